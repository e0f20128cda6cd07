//! The coordinates of a tilting-pad bearing's pads ([`super::pad`] for the
//! equations): each pad's effective journal state from the journal, its tilt
//! and (on a pivot with a stiffness) its radial displacement, and the map of
//! its film's force and Jacobians onto the generalized coordinates
//! (`Tᵀ F`, `Tᵀ K T`, `Tᵀ C T`), its pivot's moments and springs, its masses.

use nalgebra::Vector2;

use super::tilting_pad::TiltingPadBearing;
use super::{BearingEval, BearingForce, JournalState};

impl TiltingPadBearing {
    /// Effective journal position of pad `k` with the journal at `(x, y)` and
    /// the pad tilted by `η` (on its pivot's rest position).
    pub(super) fn pad_position(&self, k: usize, x: f64, y: f64, eta: f64) -> Vector2<f64> {
        let pad = &self.pads[k];
        let (s, c) = pad.pivot_sc;
        let shift = pad.preload * self.clearance;
        Vector2::new(x + shift * c - eta * s, y + shift * s + eta * c)
    }

    /// Whether the pivots have a radial stiffness (a radial coordinate `ξ`
    /// per pad, after the tilts: `q = [x, y, η…, ξ…]`).
    pub(super) fn radial(&self) -> bool {
        self.support.pivot_stiffness.is_some()
    }

    /// The journal at `q` as pad `k`'s film sees it off the pad's radial
    /// displacement: `(x, y) − ξ_k u_k` (`(x, y)` on rigid pivots).
    pub(crate) fn journal_seen_by(&self, k: usize, q: &[f64]) -> [f64; 2] {
        if !self.radial() {
            return [q[0], q[1]];
        }
        let (s, c) = self.pads[k].pivot_sc;
        let xi = q[2 + self.pads.len() + k];
        [q[0] - xi * c, q[1] - xi * s]
    }

    /// `(sin θp, cos θp)` and the effective journal state of pad `k`.
    pub(crate) fn pad_state(&self, k: usize, q: &[f64], qdot: &[f64]) -> (f64, f64, JournalState) {
        let (s, c) = self.pads[k].pivot_sc;
        let eta_dot = qdot[2 + k];
        if self.radial() {
            let [x, y] = self.journal_seen_by(k, q);
            let xi_dot = qdot[2 + self.pads.len() + k];
            let state = JournalState {
                position: self.pad_position(k, x, y, q[2 + k]),
                velocity: Vector2::new(
                    qdot[0] - eta_dot * s - xi_dot * c,
                    qdot[1] + eta_dot * c - xi_dot * s,
                ),
            };
            return (s, c, state);
        }
        let state = JournalState {
            position: self.pad_position(k, q[0], q[1], q[2 + k]),
            velocity: Vector2::new(qdot[0] - eta_dot * s, qdot[1] + eta_dot * c),
        };
        (s, c, state)
    }

    /// Add pad `k`'s film or contact `part` at its effective journal state
    /// to `out`: `Tᵀ F`, `Tᵀ K T`, `Tᵀ C T` over the journal, its tilt and
    /// (on a pivot with a stiffness) its radial coordinate.
    pub(crate) fn add_pad_part(
        &self,
        out: &mut BearingEval,
        k: usize,
        (s, c): (f64, f64),
        part: &BearingForce,
    ) {
        if self.radial() {
            let n = self.pads.len();
            out.add_columns(part, [(2 + k, -s, c), (2 + n + k, -c, -s)]);
        } else {
            out.add_transformed(part, Some((k, -s, c)));
        }
    }

    /// The force part of [`TiltingPadBearing::add_pad_part`]: `Q += Tᵀ f`.
    pub(crate) fn add_pad_force(
        &self,
        out: &mut BearingEval,
        k: usize,
        (s, c): (f64, f64),
        f: &Vector2<f64>,
    ) {
        out.add_force(f, Some((k, -s, c)));
        if self.radial() {
            out.force[2 + self.pads.len() + k] -= c * f.x + s * f.y;
        }
    }

    /// Pad `k`'s pivot: the weak rest moment on its tilt and, with a pivot
    /// stiffness, the spring `−k_piv ξ` on its radial coordinate (with
    /// `jacobians`, their stiffness and damping too).
    pub(crate) fn add_pivot(
        &self,
        out: &mut BearingEval,
        k: usize,
        q: &[f64],
        qdot: &[f64],
        speed: f64,
        jacobians: bool,
    ) {
        let n = out.n();
        let (c_rest, k_rest) = self.pivot_rest(speed);
        let i = 2 + k;
        out.force[i] -= k_rest * q[i] + c_rest * qdot[i];
        if jacobians {
            out.stiffness[i * n + i] += k_rest;
            out.damping[i * n + i] += c_rest;
        }
        if let Some(k_piv) = self.support.pivot_stiffness {
            let r = 2 + self.pads.len() + k;
            let c_piv = self.support.pivot_damping;
            out.force[r] -= k_piv * q[r] + c_piv * qdot[r];
            if jacobians {
                out.stiffness[r * n + r] += k_piv;
                out.damping[r * n + r] += c_piv;
            }
        }
    }

    /// The internal coordinates' masses into `out.mass` ([`super::pad::PadSupport::mass`]).
    pub(crate) fn write_mass(&self, out: &mut BearingEval) {
        let pads = self.pads.len();
        for (m, v) in out.mass.iter_mut().enumerate() {
            *v = self.support.mass(m, pads, self.radius);
        }
    }
}
