//! Intermediate updates of a step (FMI 3.0's Intermediate Update Mode, asked
//! for by an importer's `intermediateUpdate` callback): after each completed
//! internal step of the simulator ([`crate::solver::observer`]) the outputs at
//! that step are evaluated and handed to the version layer's observer with the
//! step's time; the observer may ask the step to return early at a time.
//! Version-neutral and physics-free: the simulator steps as it would without
//! an observer, and the outputs are those a read at that time would give.

use crate::solver::{Simulator, SolverError, SolverOptions, StepFlow};

use super::Instance;

/// What the version layer's observer asks after an internal step.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Intermediate {
    /// Go on with the step.
    Continue,
    /// Return early at this time (s): at the internal step just completed
    /// when the time is not later than it (by less than
    /// [`SolverOptions::MIN_SPAN`]), else at that time, reached by a shorter
    /// last step (a time at or past the step's end lets it end as usual).
    ReturnAt(f64),
}

/// The version layer's observer: the time of an internal step (s) and the
/// table's values there, indexed by value reference (outputs only; `None`
/// when the outputs could not be evaluated).
pub type IntermediateObserver<'a> = &'a mut dyn FnMut(f64, Option<&[f64]>) -> Intermediate;

impl Instance {
    /// Advance the simulator to `end` with `observer` told of every internal
    /// step; returns whether an early return the observer asked for ended
    /// the advance before `end`.
    pub(super) fn advance_with_updates(
        &mut self,
        end: f64,
        observer: IntermediateObserver<'_>,
    ) -> Result<bool, SolverError> {
        let mut target = end;
        let mut requested = false;
        loop {
            let mut next = None;
            let result = {
                let outputs = &mut self.outputs;
                let mut watch = |sim: &mut Simulator| {
                    let t = sim.time();
                    let values = match sim.outputs() {
                        Ok(o) => {
                            outputs.fill(&o);
                            Some(outputs.values())
                        }
                        Err(_) => None,
                    };
                    match observer(t, values) {
                        Intermediate::Continue => StepFlow::Continue,
                        Intermediate::ReturnAt(at) if at >= target => StepFlow::Continue,
                        Intermediate::ReturnAt(at) => {
                            requested = true;
                            if at - t >= SolverOptions::MIN_SPAN {
                                next = Some(at);
                            }
                            StepFlow::Stop
                        }
                    }
                };
                self.sim.advance_observed(target, &mut watch)
            };
            self.outputs.invalidate();
            result?;
            match next {
                Some(at) if self.sim.contact_began_at().is_none() => target = at,
                _ => break,
            }
        }
        Ok(requested && self.sim.time() < end)
    }
}
