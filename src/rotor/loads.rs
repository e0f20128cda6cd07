//! External loads on the assembled rotor's DOFs: the model's static and
//! harmonic forces (`[[forces]]`) and the port forces (`[[ports]]`), from the
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
    /// angle `spin_angle` (rad) to `f`: static, harmonic and port forces.
    pub fn add_loads_at(&self, values: &[f64], t: f64, spin_angle: f64, f: &mut [f64]) {
        self.add_loads(values, Some((t, spin_angle)), f);
    }

    /// The loads of `values`; harmonic forces only with `at = (t, spin angle)`.
    fn add_loads(&self, values: &[f64], at: Option<(f64, f64)>, f: &mut [f64]) {
        let mut k = 0;
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
                    if let Some((t, spin)) = at {
                        let a = values[k];
                        let theta = phase
                            + match frequency {
                                HarmonicFrequency::Ratio(r) => r * spin,
                                HarmonicFrequency::Fixed(w) => w * t,
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
                }
            }
        }
        for port in &self.model.ports {
            self.add_at(f, port.node, values[k], values[k + 1]);
            k += 2;
        }
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
