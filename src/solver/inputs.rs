//! The simulator's inputs: speed (or a torque-driven shaft's initial speed),
//! unbalance, load channels (forces, ports, torques), and the tunable bearing
//! parameters (viscosity, field excitation), the harmonic forces' frequencies.

use super::error::SolverError;
use super::simulator::Simulator;
use crate::model::{ForceKind, HarmonicFrequency};
use crate::units::{RAD_S_TO_RPM, Short};

impl Simulator {
    /// Set the spin speed (rad/s) now and its rate of change (rad/s²) from now on.
    pub fn set_speed(&mut self, speed: f64, rate: f64) -> Result<(), SolverError> {
        if !speed.is_finite() || !rate.is_finite() {
            return Err(SolverError::Input(format!(
                "speed {} rad/s and its rate {} rad/s² must be finite",
                Short(speed),
                Short(rate)
            )));
        }
        let max = self.rotor.model.max_speed;
        if speed.abs() > max {
            return Err(SolverError::Input(format!(
                "speed {} rad/s ({} rpm) exceeds the model's max_speed_rpm ({} rpm)",
                Short(speed),
                Short(speed * RAD_S_TO_RPM),
                Short(max * RAD_S_TO_RPM)
            )));
        }
        if self.torsion.is_some() {
            // A torque-driven shaft: the speed is its initial condition.
            if rate != 0.0 || self.state.time != 0.0 {
                return Err(SolverError::Input(format!(
                    "the shaft of {} is torque-driven: its speed comes from the torque inputs; a speed (without rate) can only be its initial condition at time 0",
                    self.rotor.model.name
                )));
            }
            self.state.twist_rate.fill(speed);
            self.state.stuck = if speed == 0.0 { 1.0 } else { 0.0 };
        }
        self.rebase_inputs();
        self.state.speed = speed;
        self.state.speed_rate = rate;
        Ok(())
    }

    /// Set the unbalance (kg·m) of plane `plane` (model order), constant from now on.
    pub fn set_unbalance(&mut self, plane: usize, magnitude: f64) -> Result<(), SolverError> {
        self.set_unbalance_ramp(plane, magnitude, 0.0)
    }

    /// Set the unbalance (kg·m) of plane `plane` now and its rate of change (kg·m/s).
    pub fn set_unbalance_ramp(
        &mut self,
        plane: usize,
        magnitude: f64,
        rate: f64,
    ) -> Result<(), SolverError> {
        if !(magnitude.is_finite() && magnitude >= 0.0 && rate.is_finite()) {
            return Err(SolverError::Input(format!(
                "unbalance {} kg·m must be finite and not negative, its rate {} kg·m/s finite",
                Short(magnitude),
                Short(rate)
            )));
        }
        self.rebase_inputs();
        *plane_slot(&mut self.state.unbalance, plane)? = magnitude;
        *plane_slot(&mut self.state.unbalance_rate, plane)? = rate;
        Ok(())
    }

    /// Change the oil viscosity (Pa·s) of fluid-film bearing `index` (model order).
    pub fn set_bearing_viscosity(
        &mut self,
        index: usize,
        viscosity: f64,
    ) -> Result<(), SolverError> {
        if !(viscosity.is_finite() && viscosity > 0.0) {
            return Err(SolverError::Input(format!(
                "viscosity {} Pa·s must be finite and positive",
                Short(viscosity)
            )));
        }
        self.change_bearing(
            index,
            |kind| kind.set_viscosity(viscosity),
            "is not a fluid-film bearing: it has no oil viscosity",
        )
    }

    /// Set the field excitation (0 off, 1 nominal; the pull goes with its
    /// square) of the magnetic pull `index` (model order of bearings, rubs,
    /// seals and pulls).
    pub fn set_excitation(&mut self, index: usize, excitation: f64) -> Result<(), SolverError> {
        if !(excitation.is_finite() && excitation >= 0.0) {
            return Err(SolverError::Input(format!(
                "field excitation {} must be finite and not negative",
                Short(excitation)
            )));
        }
        self.change_bearing(
            index,
            |kind| kind.set_excitation(excitation),
            "is not a magnetic pull: it has no field excitation",
        )
    }

    /// Set the tuned value ([`BearingKind::tuned`](crate::bearing::BearingKind::tuned))
    /// of model bearing `index`: its viscosity or its field excitation.
    pub fn set_bearing_tuned(&mut self, index: usize, value: f64) -> Result<(), SolverError> {
        let pull = self
            .rotor
            .model
            .bearings
            .get(index)
            .is_some_and(|b| b.kind.excitation().is_some());
        if pull {
            self.set_excitation(index, value)
        } else {
            self.set_bearing_viscosity(index, value)
        }
    }

    /// Change a parameter of model bearing `index` with `set` (false: the
    /// kind has no such parameter, `not_it` says why) and rebuild its force
    /// models.
    fn change_bearing(
        &mut self,
        index: usize,
        set: impl FnOnce(&mut crate::bearing::BearingKind) -> bool,
        not_it: &str,
    ) -> Result<(), SolverError> {
        let placed = self
            .rotor
            .model
            .bearings
            .get_mut(index)
            .ok_or_else(|| SolverError::Input(format!("no bearing {index}")))?;
        if !set(&mut placed.kind) {
            return Err(SolverError::Input(format!("{} {not_it}", placed.name)));
        }
        let (output, site) = &mut self.output_bearings[index];
        *output = placed.build();
        if let Some(k) = site {
            let site = &mut self.sites.list[*k];
            site.bearing = super::pad_inertia::InertialBearing::new(placed.build());
            site.memo.clear();
        }
        Ok(())
    }

    /// Set load input `input` (N; the order of
    /// [`RotorModel::load_inputs`](crate::model::RotorModel::load_inputs)) now
    /// and its rate of change (N/s) from now on.
    pub fn set_load(&mut self, input: usize, value: f64, rate: f64) -> Result<(), SolverError> {
        if !(value.is_finite() && rate.is_finite()) {
            return Err(SolverError::Input(format!(
                "load {} N and its rate {} N/s must be finite",
                Short(value),
                Short(rate)
            )));
        }
        let count = self.state.loads.len();
        if input >= count {
            return Err(SolverError::Input(format!(
                "no load input {input} (the model has {count})"
            )));
        }
        self.rebase_inputs();
        self.state.loads[input] = value;
        self.state.load_rates[input] = rate;
        Ok(())
    }

    /// Load input `input` (N) at time `t` (s).
    pub fn load_at(&self, input: usize, t: f64) -> f64 {
        let s = &self.state;
        s.loads[input] + s.load_rates[input] * (t - s.speed_time)
    }

    /// Set the angular position (rad) of plane `plane` at spin angle zero.
    pub fn set_unbalance_phase(&mut self, plane: usize, phase: f64) -> Result<(), SolverError> {
        if !phase.is_finite() {
            return Err(SolverError::Input(format!(
                "unbalance phase {} must be finite",
                Short(phase)
            )));
        }
        *plane_slot(&mut self.state.unbalance_phase, plane)? = phase;
        Ok(())
    }

    /// Set the frequency of harmonic force `index` (the order of
    /// [`RotorModel::harmonic_forces`]) from now on: its ratio to the running
    /// speed, or its angular frequency (rad/s, not negative) for a force of
    /// fixed frequency, as the model file gives it. The force's angle goes on
    /// from where it is, `θ = θ_now + ν (x − x_now)` (`x` the spin angle or
    /// the time): its phase moves by `(ν_old − ν) x_now`, so the force turns
    /// at the new frequency without a jump.
    ///
    /// [`RotorModel::harmonic_forces`]: crate::model::RotorModel::harmonic_forces
    pub fn set_force_frequency(&mut self, index: usize, frequency: f64) -> Result<(), SolverError> {
        let count = self.state.harmonic_frequency.len();
        let Some((force, _, _)) = self.rotor.model.harmonic_forces().nth(index) else {
            return Err(SolverError::Input(format!(
                "no harmonic force {index} (the model has {count})"
            )));
        };
        let f = &self.rotor.model.forces[force];
        let ratio = matches!(
            f.kind,
            ForceKind::Harmonic {
                frequency: HarmonicFrequency::Ratio(_),
                ..
            }
        );
        if !(frequency.is_finite() && (ratio || frequency >= 0.0)) {
            return Err(SolverError::Input(format!(
                "{} of harmonic force {}: {} must be finite{}",
                if ratio { "ratio" } else { "frequency" },
                f.name,
                Short(frequency),
                if ratio { "" } else { " and not negative" }
            )));
        }
        let s = &mut self.state;
        let x = if ratio { s.spin_angle } else { s.time };
        s.harmonic_phase[index] += (s.harmonic_frequency[index] - frequency) * x;
        s.harmonic_frequency[index] = frequency;
        Ok(())
    }
}

fn plane_slot(values: &mut [f64], plane: usize) -> Result<&mut f64, SolverError> {
    let count = values.len();
    values.get_mut(plane).ok_or_else(|| {
        SolverError::Input(format!(
            "no unbalance plane {plane} (the model has {count})"
        ))
    })
}
