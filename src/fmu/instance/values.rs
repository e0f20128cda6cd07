//! fmi2GetReal / fmi2GetInteger / fmi2GetBoolean of an [`Instance`]: the
//! parameters and inputs read where they are held, the outputs from one
//! array indexed by value reference, filled from [`Simulator::outputs`]
//! once per change of the state (after fmi2DoStep, a set, a rollback) and
//! then read in O(1) per value, without allocation or formatting unless a
//! read fails.
//!
//! [`Simulator::outputs`]: crate::solver::Simulator::outputs

use crate::solver::Outputs;
use crate::units::Short;

use super::super::states::Call;
use super::super::variables::{Binding, Causality, Kind, Variable, force_frequency_scale};
use super::{Instance, Phase, Status, category};

/// The outputs at the current state, by value reference.
#[derive(Debug, Clone)]
pub(super) struct OutputCache {
    /// Value reference and binding of each output, in table order.
    slots: Vec<(usize, Binding)>,
    /// One entry per variable of the table; those of outputs hold the value
    /// at the current state while `fresh`.
    values: Vec<f64>,
    /// Whether `values` belongs to the current state.
    fresh: bool,
}

impl OutputCache {
    /// An empty cache for the variable table `vars`.
    pub(super) fn new(vars: &[Variable]) -> Self {
        let slots = vars
            .iter()
            .enumerate()
            .filter(|(_, v)| v.causality == Causality::Output)
            .map(|(k, v)| (k, v.binding))
            .collect();
        Self {
            slots,
            values: vec![f64::NAN; vars.len()],
            fresh: false,
        }
    }

    /// The state changed: the next read evaluates the outputs again.
    pub(super) fn invalidate(&mut self) {
        self.fresh = false;
    }

    /// Whether the values belong to the current state.
    pub(super) fn is_fresh(&self) -> bool {
        self.fresh
    }

    /// Take every output's value from `o`.
    pub(super) fn fill(&mut self, o: &Outputs) {
        for &(vr, binding) in &self.slots {
            self.values[vr] = output_value(o, binding);
        }
        self.fresh = true;
    }

    /// Every variable's entry, by value reference (the outputs' after
    /// [`fill`](Self::fill)).
    pub(super) fn values(&self) -> &[f64] {
        &self.values
    }

    /// The value of output `vr` (after [`fill`](Self::fill)).
    fn value(&self, vr: usize) -> f64 {
        self.values[vr]
    }
}

/// The value of the output bound to `binding` in `o` (NaN for a binding that
/// is not an output).
fn output_value(o: &Outputs, binding: Binding) -> f64 {
    match binding {
        Binding::BearingX(k) => o.bearings[k].x,
        Binding::BearingY(k) => o.bearings[k].y,
        Binding::BearingFx(k) => o.bearings[k].fx,
        Binding::BearingFy(k) => o.bearings[k].fy,
        Binding::BearingEccentricity(k) => o.bearings[k].report.eccentricity,
        Binding::BearingFriction(k) => o.bearings[k].report.friction_torque,
        Binding::BearingContact(k) => o.bearings[k].report.contact_force,
        Binding::BearingMinFilm(k) => o.bearings[k].report.min_film_thickness,
        Binding::ProbeX(k) => o.probes[k].x,
        Binding::ProbeY(k) => o.probes[k].y,
        Binding::SpinAngle => o.spin_angle,
        Binding::FrictionTorque => o.friction_torque,
        Binding::BearingRelativeX(k) => o.bearings[k].relative().0,
        Binding::BearingRelativeY(k) => o.bearings[k].relative().1,
        Binding::HousingX(k) => o.bearings[k].housing.x,
        Binding::HousingY(k) => o.bearings[k].housing.y,
        Binding::HousingVx(k) => o.bearings[k].housing.vx,
        Binding::HousingVy(k) => o.bearings[k].housing.vy,
        Binding::PortX(k) => o.ports[k].x,
        Binding::PortY(k) => o.ports[k].y,
        Binding::PortVx(k) => o.ports[k].vx,
        Binding::PortVy(k) => o.ports[k].vy,
        Binding::BearingPowerLoss(k) => o.bearings[k].report.power_loss,
        Binding::ThrustFriction(k) => o.thrust_bearings[k].friction_torque,
        Binding::ThrustPowerLoss(k) => o.thrust_bearings[k].power_loss,
        Binding::PowerLoss => o.power_loss,
        Binding::TorqueSpeed(k) => o.torques[k].speed,
        Binding::TorqueAngle(k) => o.torques[k].angle,
        Binding::ShaftTorque(k) => o.shaft_torques[k],
        Binding::StaticFx(k) => o.bearings[k].static_fx,
        Binding::StaticFy(k) => o.bearings[k].static_fy,
        Binding::DynamicFx(k) => o.bearings[k].dynamic_load().0,
        Binding::DynamicFy(k) => o.bearings[k].dynamic_load().1,
        Binding::DynamicLoad(k) => {
            let (x, y) = o.bearings[k].dynamic_load();
            x.hypot(y)
        }
        _ => f64::NAN,
    }
}

impl Instance {
    /// Evaluate the outputs at the current state unless they are fresh
    /// (fmi2Error with a message when the evaluation fails).
    pub(super) fn refresh_outputs(&mut self) -> Result<(), Status> {
        if !self.outputs.is_fresh() {
            match self.sim.outputs() {
                Ok(o) => {
                    self.outputs.fill(&o);
                    self.implausible = self.limits.check(&o);
                }
                Err(e) => return Err(self.report(Status::Error, format!("outputs: {e}"))),
            }
        }
        Ok(())
    }

    /// `status`, or fmi2Warning with the message when the outputs hold a
    /// displacement no machine can have (after `call`).
    pub(super) fn warn_implausible(&mut self, call: &str, status: Status) -> Status {
        let Some(text) = self.implausible.clone() else {
            return status;
        };
        self.messages.push((
            Status::Warning,
            category(Status::Warning),
            format!("{call}: {text}"),
        ));
        match status {
            Status::Ok => Status::Warning,
            other => other,
        }
    }

    /// fmi2Error for a read or write of `vr` as a `kind`: unknown, or of another type.
    pub(super) fn wrong_variable(&mut self, vr: u32, kind: Kind, call: &str) -> Status {
        let text = match self.vars.get(vr as usize) {
            Some(v) => format!(
                "{call}: value reference {vr} ({}) is a {:?}, not a {kind:?}",
                v.name, v.kind
            ),
            None => format!(
                "{call}: unknown value reference {vr} (the FMU has {} variables)",
                self.vars.len()
            ),
        };
        self.report(Status::Error, text)
    }

    /// fmi2GetReal / fmi2GetInteger / fmi2GetBoolean: value of `vr` as f64.
    pub fn get(&mut self, vr: u32, kind: Kind) -> Result<f64, Status> {
        let call = match kind {
            Kind::Real => Call::GetReal,
            Kind::Integer => Call::GetInteger,
            Kind::Boolean => Call::GetBoolean,
        };
        self.check(call)?;
        let binding = match self.vars.get(vr as usize) {
            Some(v) if v.kind == kind => v.binding,
            _ => return Err(self.wrong_variable(vr, kind, call.name_in(self.version))),
        };
        let s = self.sim.state();
        let p = &self.params;
        let value = match binding {
            Binding::TimeStep => p.time_step,
            Binding::Tolerance => p.tolerance,
            Binding::MaxIterations => f64::from(p.max_iterations),
            Binding::RampTime => p.ramp_time,
            Binding::Gravity => f64::from(u8::from(p.gravity)),
            Binding::ReducedModes => f64::from(p.reduced_modes),
            Binding::Viscosity(k) | Binding::Excitation(k) => self.tuned[k],
            Binding::OffsetX(k) => self.model.bearings[k].offset[0],
            Binding::OffsetY(k) => self.model.bearings[k].offset[1],
            Binding::UnbalancePhase(k) => s.unbalance_phase[k],
            Binding::ForceFrequency(h) => {
                s.harmonic_frequency[h] / force_frequency_scale(&self.model, h)
            }
            Binding::Speed => self.sim.speed_at(s.time),
            Binding::Unbalance(k) => s.unbalance[k] + s.unbalance_rate[k] * (s.time - s.speed_time),
            Binding::Load(i) => self.sim.load_at(i, s.time),
            Binding::InitialSpeed => p.initial_speed,
            Binding::LocalErrorTolerance => p.local_error_tolerance,
            _ => {
                if self.phase == Phase::InitializationMode && !self.outputs.is_fresh() {
                    self.settle()?;
                }
                self.refresh_outputs()?;
                self.outputs.value(vr as usize)
            }
        };
        if value.is_finite() {
            Ok(value)
        } else {
            let name = &self.vars[vr as usize].name;
            let text = format!(
                "{}: {name} is not finite ({})",
                call.name_in(self.version),
                Short(value)
            );
            Err(self.report(Status::Error, text))
        }
    }
}
