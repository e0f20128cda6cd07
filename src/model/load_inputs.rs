//! The model's load input channels ([`RotorModel::load_inputs`]): static
//! and harmonic forces, ports, magnetic pulls' dynamic eccentricities and
//! drive torques, in that order, with their physical bounds — what the FMU
//! declares as inputs and the simulator holds as `loads`.

use super::{ForceKind, HarmonicFrequency, RotorModel};
use crate::bearing::BearingKind;

/// One input channel of the loads: a component of a static force, a
/// harmonic force's amplitude or a port force component (N), or a torque
/// (N·m, torque mode), in the order of [`RotorModel::load_inputs`].
#[derive(Debug, Clone, PartialEq)]
pub struct LoadInput {
    /// Its name in the FMU: `forces.<f>.fx`, `forces.<f>.magnitude`, `ports.<p>.fy`.
    pub name: String,
    /// Value at the start (the model file's; 0 for ports).
    pub start: f64,
    /// What it is: a force component, a harmonic amplitude or a torque.
    pub channel: LoadChannel,
}

/// What a [`LoadInput`] is, for its physical range
/// ([`RotorModel::input_force_bound`], [`RotorModel::input_torque_bound`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum LoadChannel {
    /// A component of a static or port force (N), of either sign.
    Component,
    /// The amplitude of a harmonic force (N), not negative.
    Amplitude,
    /// A drive torque (N·m), of either sign.
    Torque,
    /// The dynamic eccentricity of a magnetic pull's rotor (m), in `[0, gap)`.
    Eccentricity,
}

impl LoadChannel {
    /// Whether the channel drives a periodic force (a harmonic amplitude or
    /// a pull's dynamic eccentricity), which no static equilibrium carries.
    pub fn is_periodic(self) -> bool {
        matches!(self, LoadChannel::Amplitude | LoadChannel::Eccentricity)
    }
}

impl RotorModel {
    /// The load input channels, forces, ports, magnetic pulls then torques:
    /// two per static force (`fx`, `fy`), one per harmonic force
    /// (`magnitude`), two per port, one per magnetic pull (its dynamic
    /// eccentricity, m), one per torque node (`torques.<t>`, N·m).
    pub fn load_inputs(&self) -> Vec<LoadInput> {
        let mut out = Vec::new();
        for f in &self.forces {
            match f.kind {
                ForceKind::Static([fx, fy]) => {
                    for (axis, start) in [("fx", fx), ("fy", fy)] {
                        out.push(LoadInput {
                            name: format!("forces.{}.{axis}", f.name),
                            start,
                            channel: LoadChannel::Component,
                        });
                    }
                }
                ForceKind::Harmonic { magnitude, .. } => out.push(LoadInput {
                    name: format!("forces.{}.magnitude", f.name),
                    start: magnitude,
                    channel: LoadChannel::Amplitude,
                }),
            }
        }
        for p in &self.ports {
            for axis in ["fx", "fy"] {
                out.push(LoadInput {
                    name: format!("ports.{}.{axis}", p.name),
                    start: 0.0,
                    channel: LoadChannel::Component,
                });
            }
        }
        for b in &self.bearings {
            if let BearingKind::MagneticPull(m) = &b.kind {
                out.push(LoadInput {
                    name: format!("magnetic_pull.{}.dynamic_eccentricity", b.name),
                    start: m.dynamic_eccentricity,
                    channel: LoadChannel::Eccentricity,
                });
            }
        }
        for t in &self.torques {
            out.push(LoadInput {
                name: format!("torques.{}", t.name),
                start: 0.0,
                channel: LoadChannel::Torque,
            });
        }
        out
    }

    /// The harmonic `[[forces]]` in model order: each one's force index, phase
    /// (rad) and frequency (its ratio to the running speed, or its angular
    /// frequency in rad/s), the values a simulation starts from and the FMU
    /// tunes (`forces.<f>.ratio`, `forces.<f>.frequency`).
    pub fn harmonic_forces(&self) -> impl Iterator<Item = (usize, f64, f64)> + '_ {
        self.forces
            .iter()
            .enumerate()
            .filter_map(|(i, f)| match f.kind {
                ForceKind::Harmonic {
                    phase, frequency, ..
                } => Some((
                    i,
                    phase,
                    match frequency {
                        HarmonicFrequency::Ratio(r) => r,
                        HarmonicFrequency::Fixed(w) => w,
                    },
                )),
                ForceKind::Static(_) => None,
            })
    }

    /// The channel in [`Self::load_inputs`] of model bearing `k`'s dynamic
    /// eccentricity, when it is a magnetic pull.
    pub fn pull_input(&self, k: usize) -> Option<usize> {
        if !self.bearings[k].kind.is_magnetic_pull() {
            return None;
        }
        let forces: usize = self
            .forces
            .iter()
            .map(|f| match f.kind {
                ForceKind::Static(_) => 2,
                ForceKind::Harmonic { .. } => 1,
            })
            .sum();
        let pulls_before = self.bearings[..k]
            .iter()
            .filter(|b| b.kind.is_magnetic_pull())
            .count();
        Some(forces + 2 * self.ports.len() + pulls_before)
    }

    /// Index of the first torque channel in [`Self::load_inputs`].
    pub fn first_torque_input(&self) -> usize {
        self.load_inputs().len() - self.torques.len()
    }

    /// The largest force input (N) a machine can take, `1000 g m`: the force
    /// that would accelerate the whole rotor at a thousand times gravity
    /// (short-circuit pull and hydraulic thrust stay within ten times its
    /// weight). The FMU declares `±` it on every force and port input.
    pub fn input_force_bound(&self) -> f64 {
        1000.0 * crate::units::STANDARD_GRAVITY * self.total_mass()
    }

    /// The largest torque input (N·m) a machine can take, `J Ω_max / 1 ms`:
    /// the torque that would take the shaft from rest to `max_speed_rpm` in
    /// a millisecond (a generator's short-circuit torque is a few times its
    /// rating and a unit takes seconds to run up). The FMU declares `±` it
    /// on every torque input.
    pub fn input_torque_bound(&self) -> f64 {
        self.total_polar_inertia() * self.max_speed / 1e-3
    }
}
