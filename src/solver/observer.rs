//! A per-internal-step observer of [`Simulator::advance_observed`]: the seam
//! through which a front end (the FMI 3.0 layer's intermediate updates) sees
//! each completed internal step of a call and may end the call there. It holds
//! no physics: it is called after the step is accepted and its time is final,
//! may read the simulator (time, outputs), and answers whether the call goes
//! on. Without an observer ([`Simulator::advance_to`]) the step loop is the
//! same loop, step for step and bit for bit.

use super::SolverError;
use super::simulator::Simulator;

/// What the observer of an internal step asks of the call.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum StepFlow {
    /// Go on to the next internal step (or end at the target).
    Continue,
    /// End the call here, at this internal step's time (ignored at the
    /// call's last step, which ends at the target anyway).
    Stop,
}

/// Called after each completed internal step of a call, with the simulator
/// at that step's time. It must leave the state as it found it (reading
/// outputs is fine).
pub type StepObserver<'a> = &'a mut dyn FnMut(&mut Simulator) -> StepFlow;

impl Simulator {
    /// [`Simulator::advance_to`] with `observer` called after every completed
    /// internal step (equal or accuracy-controlled; the halvings of a step cut
    /// are not steps of their own), the last one at `t_end`. When it answers
    /// [`StepFlow::Stop`] before the last step, the call ends at that step's
    /// time (a later call to the same target continues from there, as after
    /// a contact's onset, [`super::contact_onset`]).
    pub fn advance_observed(
        &mut self,
        t_end: f64,
        observer: StepObserver<'_>,
    ) -> Result<(), SolverError> {
        self.advance(t_end, Some(observer))
    }

    /// Ask the observer, if any, about the step just completed.
    pub(super) fn observe(&mut self, observer: &mut Option<StepObserver<'_>>) -> StepFlow {
        match observer {
            Some(o) => o(self),
            None => StepFlow::Continue,
        }
    }
}
