//! fmi2DoStep of an [`Instance`]: the step's checks before anything
//! moves (state, clock, a step too short to advance the time, the stop time),
//! the step statistics for the log, the warning when a contact leaves the
//! range of its law, and on a reduced rotor the warning when the running
//! speed or the motion leaves the range it is validated for.

use super::super::states::Call;
use super::intermediate::IntermediateObserver;
use super::{Instance, Phase, STOP_SLACK, Status, category};
use crate::rotor::Rotor;
use crate::solver::SolverOptions;
use crate::solver::reduction_check::excursion_report;
use crate::units::Short;

impl Instance {
    /// fmi2DoStep.
    pub fn do_step(&mut self, current: f64, step: f64) -> Status {
        self.step_with(current, step, None)
    }

    /// fmi3DoStep with intermediate updates: [`Instance::do_step`], with
    /// `observer` told of every internal step (time and outputs), which may
    /// ask the step to return early ([`super::intermediate`]).
    pub fn do_step_observed(
        &mut self,
        current: f64,
        step: f64,
        observer: IntermediateObserver<'_>,
    ) -> Status {
        self.step_with(current, step, Some(observer))
    }

    fn step_with(
        &mut self,
        current: f64,
        step: f64,
        observer: Option<IntermediateObserver<'_>>,
    ) -> Status {
        self.early_return_at = None;
        if let Err(s) = self.check(Call::DoStep) {
            return s;
        }
        let call = Call::DoStep.name_in(self.version);
        let now = self.sim.time();
        let (t, h) = (Short(current), Short(step));
        if !(step.is_finite() && step > 0.0) {
            return self.report(
                Status::Error,
                format!("{call}: communication step {h} s must be positive"),
            );
        }
        if self.sim.align_time(current).is_err() {
            return self.report(
                Status::Error,
                format!(
                    "{call}: communication point {t} s differs from the FMU time {} s",
                    Short(now)
                ),
            );
        }
        let end = current + step;
        // The step the integrator would take: what t + h adds to t in floating point.
        let advance = end - current;
        if advance < SolverOptions::MIN_SPAN * (1.0 - 1e-6) {
            let why = if advance == 0.0 {
                format!(
                    "does not advance the time {t} s at all (below its floating-point resolution)"
                )
            } else {
                format!(
                    "is shorter than the {} s the integrator resolves (round-off in the Newmark accelerations grows as 1/h²)",
                    Short(SolverOptions::MIN_SPAN)
                )
            };
            return self.report(
                Status::Error,
                format!("{call}: the communication step {h} s from {t} s {why}"),
            );
        }
        if let Some(stop) = self
            .stop_time
            .filter(|&t| end > t + STOP_SLACK * t.abs().max(1.0))
        {
            return self.report(
                Status::Error,
                format!(
                    "{call}: the step from {t} s by {h} s ends at {} s, past the stop time {} s of {}",
                    Short(end),
                    Short(stop),
                    self.version.setup_call()
                ),
            );
        }
        self.outputs.invalidate();
        let before = self.sim.stats();
        let (result, requested) = match observer {
            None => (self.sim.advance_to(current + step), false),
            Some(o) => match self.advance_with_updates(current + step, o) {
                Ok(requested) => (Ok(()), requested),
                Err(e) => (Err(e), false),
            },
        };
        if let (Ok(()), Some((at, names))) = (&result, self.sim.contact_began_at()) {
            self.early_return_at = Some(*at);
            let text = format!(
                "{call} from {t} s by {h} s returns early at {} s: contact begins at {}",
                Short(*at),
                names.join(", ")
            );
            self.messages.push((Status::Ok, category(Status::Ok), text));
        } else if requested {
            let at = self.sim.time();
            self.early_return_at = Some(at);
            let text = format!(
                "{call} from {t} s by {h} s returns early at {} s: the importer asked for it in an intermediate update",
                Short(at)
            );
            self.messages.push((Status::Ok, category(Status::Ok), text));
        }
        for w in self.sim.take_warnings() {
            self.messages
                .push((Status::Warning, category(Status::Warning), w.to_string()));
        }
        if self.step_statistics {
            let after = self.sim.stats();
            self.messages.push((
                Status::Ok,
                category(Status::Ok),
                format!(
                    "{call} from {t} s by {h} s: {} internal steps, {} rejected by the error estimate, {} Newton iterations, {} step cuts, {} damped retries ({} Jacobian refreshes, {} factorizations)",
                    after.steps - before.steps,
                    after.rejections - before.rejections,
                    after.iterations - before.iterations,
                    after.step_cuts - before.step_cuts,
                    after.retries - before.retries,
                    after.refreshes - before.refreshes,
                    after.factorizations - before.factorizations,
                ),
            ));
        }
        // Contact beyond its law's limits: each contact and limit once per
        // episode, as fmi2Warning.
        let warnings = self.sim.take_contact_warnings();
        let warned = !warnings.is_empty();
        for w in warnings {
            self.messages
                .push((Status::Warning, category(Status::Warning), w.message));
        }
        match result {
            Ok(()) => match self.refresh_outputs() {
                Ok(_) => {
                    let status = match self.watch_reduction(call) {
                        Status::Ok if warned => Status::Warning,
                        status => status,
                    };
                    self.warn_implausible(call, status)
                }
                Err(s) => s,
            },
            Err(e) => {
                self.phase = Phase::StepFailed;
                let reached = self.sim.time();
                self.report(
                    Status::Discard,
                    format!(
                        "{call} from {t} s by {h} s discarded at {} s: {e}. Roll back with {} or reset.",
                        Short(reached),
                        self.version.set_state_call()
                    ),
                )
            }
        }
    }

    /// Whether each step stops at the first internal step at which a
    /// bearing's or rub's contact begins (FMI 3.0 early return, asked for by
    /// `earlyReturnAllowed`; off by default and for FMI 2.0).
    pub fn set_early_return(&mut self, on: bool) {
        self.early_return = on;
        self.sim.set_stop_at_contact(on);
    }

    /// Where the last step returned early because a contact began (s), if it did.
    pub fn early_return_at(&self) -> Option<f64> {
        self.early_return_at
    }

    /// fmi2GetRealStatus(fmi2LastSuccessfulTime).
    pub fn last_successful_time(&mut self) -> Result<f64, Status> {
        self.check(Call::GetRealStatus)?;
        Ok(self.sim.time())
    }

    /// After a step on a reduced rotor: fmi2Warning, once per excursion, when
    /// the running speed or the frequency of the motion at the kept nodes
    /// has left the range the rotor is validated for, with the error
    /// estimate there (against the full rotor with this instance's
    /// tuned viscosities and excitations) and the mode count that would reach it.
    fn watch_reduction(&mut self, call: &str) -> Status {
        let (t, speed) = (self.sim.time(), self.sim.speed_at(self.sim.time()));
        let Some(excursion) = self.watch.check(speed, self.sim.state()) else {
            return Status::Ok;
        };
        let mut model = self.model.clone();
        for (b, &value) in model.bearings.iter_mut().zip(&self.tuned) {
            b.kind.set_tuned(value);
        }
        let report = match Rotor::new(model) {
            Ok(full) => excursion_report(&full, self.sim.rotor(), speed, excursion),
            Err(e) => format!("no error estimate ({e})"),
        };
        let text = format!(
            "{call} at {} s: {report}; solver.reduced_modes = {} (0 runs the full rotor)",
            Short(t),
            self.params.reduced_modes
        );
        self.messages
            .push((Status::Warning, category(Status::Warning), text));
        Status::Warning
    }
}
