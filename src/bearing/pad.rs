//! One pad of a tilting-pad bearing: its geometry ([`Pad`]) and how it is
//! held ([`PadSupport`]: its pivot's radial stiffness, its inertia), the
//! coordinates that gives it and their map to the effective journal
//! position its film sees ([`super::tilting_pad`]).
//!
//! A pad has its tilt `η = ψ R` (ψ its rotation about the pivot, `R` the
//! journal radius) and, on a pivot of radial stiffness `k_piv`, its radial
//! displacement `ξ` outward along the pivot direction `u = (cos θp, sin θp)`:
//! `X_e = X + mC cos θp − η sin θp − ξ cos θp`,
//! `Y_e = Y + mC sin θp + η cos θp − ξ sin θp`, so the columns of
//! `T = ∂(X_e, Y_e)/∂(X, Y, η, ξ)` are the unit vectors, `t = (−sin θp, cos θp)`
//! and `−u`. The pivot spring adds `−k_piv ξ − c_piv ξ̇` to `Q_ξ = −u·F`; the pad's
//! moment of inertia `I` about its pivot gives its tilt the mass `I/R²`
//! (kinetic energy `½ I ψ̇² = ½ (I/R²) η̇²`), its mass `m_p` its radial
//! coordinate the mass `m_p`.

use std::f64::consts::PI;

use super::short_film::FilmWindow;

/// One pad of a tilting-pad bearing, with its fixed geometry's trigonometry
/// worked out once ([`Pad::new`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Pad {
    pivot: f64,
    pub(super) arc: f64,
    offset: f64,
    pub(super) preload: f64,
    /// `(sin θp, cos θp)`.
    pub(super) pivot_sc: (f64, f64),
    /// The pad's arc from the leading edge, normalized to start in `[0, 2π)`.
    pub(super) window: FilmWindow,
}

impl Pad {
    /// Pad with pivot angle `θp` from +x toward +y (rad), arc extent (rad),
    /// pivot `offset` as a fraction of the arc from the leading edge (0.5 =
    /// centred) and preload `m = 1 − C_b/C` (0 = pad curvature centred on the
    /// bearing).
    pub fn new(pivot: f64, arc: f64, offset: f64, preload: f64) -> Self {
        let lead = (pivot - offset * arc).rem_euclid(2.0 * PI);
        Self {
            pivot,
            arc,
            offset,
            preload,
            pivot_sc: pivot.sin_cos(),
            window: FilmWindow::new(lead, lead + arc),
        }
    }

    /// Pivot angle `θp` (rad).
    pub fn pivot(&self) -> f64 {
        self.pivot
    }

    /// Arc extent (rad).
    pub fn arc(&self) -> f64 {
        self.arc
    }

    /// Pivot position as a fraction of the arc from the leading edge.
    pub fn offset(&self) -> f64 {
        self.offset
    }

    /// Preload `m` (–).
    pub fn preload(&self) -> f64 {
        self.preload
    }

    /// The pad's arc `(from, to)` (rad), normalized to start in `[0, 2π)`:
    /// the window of its film.
    pub fn film_arc(&self) -> (f64, f64) {
        (self.window.from, self.window.to)
    }

    /// Leading and trailing edge angles (rad); the spin carries oil from leading to trailing.
    pub fn edges(&self) -> (f64, f64) {
        let lead = self.pivot - self.offset * self.arc;
        (lead, lead + self.arc)
    }
}

/// How the pads of a bearing are held: their pivots' radial stiffness and
/// their inertia (the defaults: rigid pivots, massless pads).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct PadSupport {
    /// Radial stiffness `k_piv` of each pivot (N/m); `None`: rigid (no
    /// radial coordinate).
    pub pivot_stiffness: Option<f64>,
    /// Each pad's moment of inertia `I` about its pivot (kg·m²): mass
    /// `I/R²` on its tilt `η = ψR` (`R` the journal radius).
    pub pad_inertia: f64,
    /// Each pad's mass `m_p` (kg) on its radial coordinate `ξ` (only with a
    /// pivot stiffness).
    pub pad_mass: f64,
    /// Radial damping `c_piv` of each pivot (N·s/m), in parallel with its
    /// stiffness (only with a pivot stiffness).
    pub pivot_damping: f64,
}

impl PadSupport {
    /// Internal coordinates per pad: the tilt, and the radial displacement
    /// on a pivot with a stiffness.
    pub fn coordinates_per_pad(&self) -> usize {
        if self.pivot_stiffness.is_some() { 2 } else { 1 }
    }

    /// The mass of internal coordinate `m` of a bearing with `pads` pads
    /// and journal radius `radius` (m): `I/R²` on the tilts `0..pads`, `m_p`
    /// on the radial coordinates `pads..2 pads` (kg).
    pub fn mass(&self, m: usize, pads: usize, radius: f64) -> f64 {
        if m < pads {
            if self.pad_inertia == 0.0 {
                0.0
            } else {
                self.pad_inertia / (radius * radius)
            }
        } else {
            self.pad_mass
        }
    }
}
