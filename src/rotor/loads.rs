//! External loads on the assembled rotor's DOFs: the model's static and
//! harmonic forces (`[[forces]]`), the port forces (`[[ports]]`) and the
//! rotating pull of each magnetic pull's dynamic eccentricity, from the
//! values of their input channels ([`RotorModel::load_inputs`] order).
//!
//! A harmonic force of amplitude `A` has the angle
//! `θ = phase + r φ_spin` (a ratio `r` to the running speed, so it follows
//! any speed history) or `θ = phase + ω t` (a fixed frequency), and acts as
//! `A (cos θ, sin θ)` (forward), `A (cos θ, −sin θ)` (backward) or
//! `A cos θ (cos α, sin α)` (a fixed line of action). Its complex amplitude
//! for a steady response `Re(F̂ e^{iωt})` is `A e^{i phase}` times `(1, −i)`,
//! `(1, i)` or `(cos α, sin α)`.
//!
//! [`RotorModel::load_inputs`]: crate::model::RotorModel::load_inputs

use nalgebra::Complex;

use super::Rotor;
use crate::bearing::BearingKind;
use crate::fe::{DOF_X, DOF_Y};
use crate::model::{ForceKind, HarmonicDirection, HarmonicFrequency};

impl Rotor {
    /// Add the force `(fx, fy)` at `node` to `f` (free DOFs).
    fn add_at(&self, f: &mut [f64], node: usize, fx: f64, fy: f64) {
        if let Some(i) = self.dofs.free(node, DOF_X) {
            f[i] += fx;
        }
        if let Some(i) = self.dofs.free(node, DOF_Y) {
            f[i] += fy;
        }
    }

    /// Add the constant loads — static forces and port forces — of the
    /// input values `values` to `f`.
    pub fn add_static_loads(&self, values: &[f64], f: &mut [f64]) {
        self.add_loads(values, None, f);
    }

    /// Add every load of the input values `values` at time `t` (s) and spin
    /// angle `spin_angle` (rad) to `f`: static, harmonic and port forces, the
    /// harmonic ones at the phases and frequencies `harmonic` (one
    /// `(phase, frequency)` each, [`RotorModel::harmonic_forces`] order;
    /// the model's when `None`).
    ///
    /// [`RotorModel::harmonic_forces`]: crate::model::RotorModel::harmonic_forces
    pub fn add_loads_at(
        &self,
        values: &[f64],
        harmonic: Option<(&[f64], &[f64])>,
        t: f64,
        spin_angle: f64,
        f: &mut [f64],
    ) {
        self.add_loads(values, Some((t, spin_angle, harmonic)), f);
    }

    /// The loads of `values`; harmonic forces only with `at = (t, spin
    /// angle, their phases and frequencies)`.
    #[allow(clippy::type_complexity)]
    fn add_loads(
        &self,
        values: &[f64],
        at: Option<(f64, f64, Option<(&[f64], &[f64])>)>,
        f: &mut [f64],
    ) {
        let mut k = 0;
        let mut h = 0;
        for force in &self.model.forces {
            match force.kind {
                ForceKind::Static(_) => {
                    self.add_at(f, force.node, values[k], values[k + 1]);
                    k += 2;
                }
                ForceKind::Harmonic {
                    phase,
                    frequency,
                    direction,
                    ..
                } => {
                    if let Some((t, spin, harmonic)) = at {
                        let a = values[k];
                        let (phase, value) = match harmonic {
                            Some((phases, frequencies)) => (phases[h], frequencies[h]),
                            None => match frequency {
                                HarmonicFrequency::Ratio(r) | HarmonicFrequency::Fixed(r) => {
                                    (phase, r)
                                }
                            },
                        };
                        let theta = phase
                            + match frequency {
                                HarmonicFrequency::Ratio(_) => value * spin,
                                HarmonicFrequency::Fixed(_) => value * t,
                            };
                        let (s, c) = theta.sin_cos();
                        let (fx, fy) = match direction {
                            HarmonicDirection::Forward => (a * c, a * s),
                            HarmonicDirection::Backward => (a * c, -a * s),
                            HarmonicDirection::Fixed(alpha) => {
                                (a * c * alpha.cos(), a * c * alpha.sin())
                            }
                        };
                        self.add_at(f, force.node, fx, fy);
                    }
                    k += 1;
                    h += 1;
                }
            }
        }
        for port in &self.model.ports {
            self.add_at(f, port.node, values[k], values[k + 1]);
            k += 2;
        }
        for (b, placed) in self.model.bearings.iter().enumerate() {
            if !placed.kind.is_magnetic_pull() {
                continue;
            }
            if let Some((_, spin, _)) = at {
                if let Some([fx, fy]) = self.pull_rotating_force(b, values[k], spin) {
                    self.add_at(f, placed.node, fx, fy);
                    if let Some(p) = placed.pedestal {
                        self.add_on_pedestal(f, p, [-fx, -fy]);
                    }
                }
            }
            k += 1;
        }
        self.add_offset_loads(f);
    }

    /// The 1× rotating pull (N, on the rotor) of model bearing `bearing`, a
    /// magnetic pull, with dynamic eccentricity `eccentricity` (m) at spin
    /// angle `spin_angle` (rad) ([`MagneticPull::rotating_pull`]); `None`
    /// for another kind or no eccentricity.
    ///
    /// [`MagneticPull::rotating_pull`]: crate::bearing::MagneticPull::rotating_pull
    pub fn pull_rotating_force(
        &self,
        bearing: usize,
        eccentricity: f64,
        spin_angle: f64,
    ) -> Option<[f64; 2]> {
        match &self.model.bearings[bearing].kind {
            BearingKind::MagneticPull(m) if eccentricity != 0.0 => {
                Some(m.rotating_pull(eccentricity, spin_angle))
            }
            _ => None,
        }
    }

    /// Add `load` (N, x and y) to the DOFs of pedestal `p` in `f`.
    fn add_on_pedestal(&self, f: &mut [f64], p: usize, load: [f64; 2]) {
        for (k, v) in load.iter().enumerate() {
            if let Some(i) = self.dofs.pedestal(p, k) {
                f[i] += v;
            }
        }
    }

    /// Add the preload of the elements in the matrices whose centres are set
    /// off the nominal axis to `f`: a linear bearing's `K (q − q_h − o)` is
    /// `K q − K q_h` (in `K`) less the constant `K o`, so the journal carries
    /// `+K o` and its housing `−K o`; a pedestal's spring anchored at `o`
    /// likewise loads the pedestal by `+K o` and what it stands on by `−K o`.
    /// Nothing is added for elements on the axis (models without offsets keep
    /// their numbers bit for bit). The fluid films, seals and stators see
    /// their offsets in their own laws ([`crate::bearing::offset`]).
    /// Misaligned couplings add theirs ([`Rotor::add_coupling_loads`]).
    pub fn add_offset_loads(&self, f: &mut [f64]) {
        let preload = |k: &[[f64; 2]; 2], o: &[f64; 2]| {
            [
                k[0][0] * o[0] + k[0][1] * o[1],
                k[1][0] * o[0] + k[1][1] * o[1],
            ]
        };
        let on_pedestal = |f: &mut [f64], p: usize, load: [f64; 2], sign: f64| {
            self.add_on_pedestal(f, p, [sign * load[0], sign * load[1]]);
        };
        for b in &self.model.bearings {
            let BearingKind::Linear { stiffness, .. } = &b.kind else {
                continue;
            };
            if !b.is_offset() {
                continue;
            }
            let load = preload(stiffness, &b.offset);
            self.add_at(f, b.node, load[0], load[1]);
            if let Some(p) = b.pedestal {
                on_pedestal(f, p, load, -1.0);
            }
        }
        for (p, pedestal) in self.model.pedestals.iter().enumerate() {
            if pedestal.offset == [0.0, 0.0] {
                continue;
            }
            let load = preload(&pedestal.stiffness, &pedestal.offset);
            on_pedestal(f, p, load, 1.0);
            if let Some(on) = pedestal.on {
                on_pedestal(f, on, load, -1.0);
            }
        }
        self.add_coupling_loads(f);
    }

    /// Whether the model has any load that acts in a static equilibrium (a
    /// static force or a port).
    pub fn has_static_loads(&self) -> bool {
        !self.model.ports.is_empty()
            || self
                .model
                .forces
                .iter()
                .any(|f| matches!(f.kind, ForceKind::Static(_)))
    }

    /// The frequency (rad/s) at spin `speed` (rad/s) and the complex
    /// amplitude vector (free DOFs) of harmonic force `index` (model order
    /// of `[[forces]]`) of amplitude `magnitude` (N): the steady force is
    /// `Re(F̂ e^{iωt})`. `None` for a static force.
    pub fn harmonic_load(
        &self,
        index: usize,
        magnitude: f64,
        speed: f64,
    ) -> Option<(f64, Vec<Complex<f64>>)> {
        let force = &self.model.forces[index];
        let ForceKind::Harmonic {
            phase,
            frequency,
            direction,
            ..
        } = force.kind
        else {
            return None;
        };
        let omega = match frequency {
            HarmonicFrequency::Ratio(r) => r * speed,
            HarmonicFrequency::Fixed(w) => w,
        };
        let a = Complex::from_polar(magnitude, phase);
        let (x, y) = match direction {
            HarmonicDirection::Forward => (a, a * Complex::new(0.0, -1.0)),
            HarmonicDirection::Backward => (a, a * Complex::new(0.0, 1.0)),
            HarmonicDirection::Fixed(alpha) => (a * alpha.cos(), a * alpha.sin()),
        };
        let mut f = vec![Complex::new(0.0, 0.0); self.dof_count()];
        if let Some(i) = self.dofs.free(force.node, DOF_X) {
            f[i] += x;
        }
        if let Some(i) = self.dofs.free(force.node, DOF_Y) {
            f[i] += y;
        }
        Some((omega, f))
    }
}
