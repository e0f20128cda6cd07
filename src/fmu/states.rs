//! The Co-Simulation state machine: the states an instance can be in and one
//! table of the states each call is allowed in (FMI 2.0.4 §4.2.4, "state
//! machine of calling sequence from master to slave"), as bit masks like the
//! `MASK_fmi2*` defines of the FMI Reference FMUs. [`Call::check`] is the only
//! place the table is consulted. An FMI 3.0 instance follows the same table
//! under its own call names ([`Call::name_in`]): FMI 3.0 §4.3's Co-Simulation
//! states without event mode map one to one (*Step Mode* is *stepComplete*;
//! after an `fmi3Discard` only `fmi3Terminate`, `fmi3Reset`, `fmi3SetFMUState`
//! and the reads help, as after an FMI 2 discarded step).
//!
//! The standard's states map onto [`Phase`] as follows: *instantiated*,
//! *initialization mode*, *stepComplete*, *stepFailed*, *terminated* and
//! *error* one to one; *stepInProgress* and *stepCanceled* never occur (every
//! `fmi2DoStep` completes synchronously, `canRunAsynchronuously = false`);
//! *fatal* and *start/end* have no live instance to call.

/// The FMI version an instance speaks: it names the calls in messages.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Version {
    /// FMI 2.0 (`fmi2*`).
    Fmi2,
    /// FMI 3.0 (`fmi3*`).
    Fmi3,
}

impl Version {
    /// What the model description calls its token: `GUID` (FMI 2.0) or
    /// `instantiationToken` (FMI 3.0).
    pub const fn token_name(self) -> &'static str {
        match self {
            Version::Fmi2 => "GUID",
            Version::Fmi3 => "instantiationToken",
        }
    }

    /// The name of the call that rolls an instance back to a saved state.
    pub const fn set_state_call(self) -> &'static str {
        match self {
            Version::Fmi2 => "fmi2SetFMUstate",
            Version::Fmi3 => "fmi3SetFMUState",
        }
    }

    /// The call that gives the start and stop times.
    pub const fn setup_call(self) -> &'static str {
        match self {
            Version::Fmi2 => "fmi2SetupExperiment",
            Version::Fmi3 => "fmi3EnterInitializationMode",
        }
    }
}

/// Where the instance is in the Co-Simulation state machine.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Phase {
    /// After fmi2Instantiate (and fmi2Reset).
    Instantiated,
    /// Between fmi2EnterInitializationMode and fmi2ExitInitializationMode.
    InitializationMode,
    /// Initialized; the last step (if any) completed.
    StepComplete,
    /// The last fmi2DoStep was discarded; only rollback, reset or terminate help.
    StepFailed,
    /// After fmi2Terminate.
    Terminated,
    /// After an fmi2Error: only reset, rollback, debug reads or free.
    Error,
}

impl Phase {
    /// Every phase, in bit order.
    pub const ALL: [Phase; 6] = [
        Phase::Instantiated,
        Phase::InitializationMode,
        Phase::StepComplete,
        Phase::StepFailed,
        Phase::Terminated,
        Phase::Error,
    ];

    /// This phase's bit in a [`Mask`].
    pub const fn bit(self) -> Mask {
        Mask(1 << self as u8)
    }
}

/// A set of phases, one bit per [`Phase`].
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Mask(u8);

impl Mask {
    /// No phase.
    pub const NONE: Mask = Mask(0);

    /// The union of two sets.
    pub const fn or(self, other: Mask) -> Mask {
        Mask(self.0 | other.0)
    }

    /// Whether `phase` is in the set.
    pub const fn contains(self, phase: Phase) -> bool {
        self.0 & phase.bit().0 != 0
    }

    /// The phases in the set, in bit order.
    pub fn phases(self) -> impl Iterator<Item = Phase> {
        Phase::ALL.into_iter().filter(move |p| self.contains(*p))
    }
}

const INSTANTIATED: Mask = Phase::Instantiated.bit();
const INITIALIZATION: Mask = Phase::InitializationMode.bit();
const STEP_COMPLETE: Mask = Phase::StepComplete.bit();
const STEP_FAILED: Mask = Phase::StepFailed.bit();
const TERMINATED: Mask = Phase::Terminated.bit();
const ERROR: Mask = Phase::Error.bit();

/// Every state with a live instance (fmi2FreeInstance, fmi2Reset, the FMU state
/// functions, fmi2SetDebugLogging).
const ANY: Mask = INSTANTIATED
    .or(INITIALIZATION)
    .or(STEP_COMPLETE)
    .or(STEP_FAILED)
    .or(TERMINATED)
    .or(ERROR);
/// Where values can be read (in *error* for debugging only).
const READABLE: Mask = INITIALIZATION
    .or(STEP_COMPLETE)
    .or(STEP_FAILED)
    .or(TERMINATED)
    .or(ERROR);
/// Where inputs and tunable parameters can be set.
const SETTABLE: Mask = INSTANTIATED.or(INITIALIZATION).or(STEP_COMPLETE);
/// Where the status queries answer (the standard adds *stepInProgress*).
const STATUS: Mask = STEP_COMPLETE.or(STEP_FAILED).or(TERMINATED);

/// The FMI calls whose allowed states the table fixes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Call {
    /// fmi2SetDebugLogging.
    SetDebugLogging,
    /// fmi2SetupExperiment.
    SetupExperiment,
    /// fmi2EnterInitializationMode.
    EnterInitializationMode,
    /// fmi2ExitInitializationMode.
    ExitInitializationMode,
    /// fmi2Terminate.
    Terminate,
    /// fmi2Reset.
    Reset,
    /// fmi2GetReal.
    GetReal,
    /// fmi2GetInteger.
    GetInteger,
    /// fmi2GetBoolean.
    GetBoolean,
    /// fmi2GetString.
    GetString,
    /// fmi2SetReal.
    SetReal,
    /// fmi2SetInteger.
    SetInteger,
    /// fmi2SetBoolean.
    SetBoolean,
    /// fmi2SetString.
    SetString,
    /// Any fmi2Set* of a parameter with `variability = "fixed"` (the standard's
    /// footnote: only before the end of Initialization Mode).
    SetFixedParameter,
    /// fmi2GetFMUstate.
    GetFmuState,
    /// fmi2SetFMUstate.
    SetFmuState,
    /// fmi2FreeFMUstate.
    FreeFmuState,
    /// fmi2SerializedFMUstateSize.
    SerializedFmuStateSize,
    /// fmi2SerializeFMUstate.
    SerializeFmuState,
    /// fmi2DeSerializeFMUstate.
    DeSerializeFmuState,
    /// fmi2GetDirectionalDerivative.
    GetDirectionalDerivative,
    /// fmi2SetRealInputDerivatives.
    SetRealInputDerivatives,
    /// fmi2GetRealOutputDerivatives.
    GetRealOutputDerivatives,
    /// fmi2DoStep.
    DoStep,
    /// fmi2CancelStep (allowed in *stepInProgress* only, which this FMU never
    /// enters).
    CancelStep,
    /// fmi2GetStatus.
    GetStatus,
    /// fmi2GetRealStatus.
    GetRealStatus,
    /// fmi2GetIntegerStatus.
    GetIntegerStatus,
    /// fmi2GetBooleanStatus.
    GetBooleanStatus,
    /// fmi2GetStringStatus.
    GetStringStatus,
}

impl Call {
    /// The table: the C name of each call and the phases it is allowed in.
    pub const fn rule(self) -> (&'static str, Mask) {
        match self {
            Call::SetDebugLogging => ("fmi2SetDebugLogging", ANY),
            Call::SetupExperiment => ("fmi2SetupExperiment", INSTANTIATED),
            Call::EnterInitializationMode => ("fmi2EnterInitializationMode", INSTANTIATED),
            Call::ExitInitializationMode => ("fmi2ExitInitializationMode", INITIALIZATION),
            Call::Terminate => ("fmi2Terminate", STEP_COMPLETE.or(STEP_FAILED)),
            Call::Reset => ("fmi2Reset", ANY),
            Call::GetReal => ("fmi2GetReal", READABLE),
            Call::GetInteger => ("fmi2GetInteger", READABLE),
            Call::GetBoolean => ("fmi2GetBoolean", READABLE),
            Call::GetString => ("fmi2GetString", READABLE),
            Call::SetReal => ("fmi2SetReal", SETTABLE),
            Call::SetInteger => ("fmi2SetInteger", SETTABLE),
            Call::SetBoolean => ("fmi2SetBoolean", SETTABLE),
            Call::SetString => ("fmi2SetString", SETTABLE),
            Call::SetFixedParameter => (
                "fmi2Set of a fixed parameter",
                INSTANTIATED.or(INITIALIZATION),
            ),
            Call::GetFmuState => ("fmi2GetFMUstate", ANY),
            Call::SetFmuState => ("fmi2SetFMUstate", ANY),
            Call::FreeFmuState => ("fmi2FreeFMUstate", ANY),
            Call::SerializedFmuStateSize => ("fmi2SerializedFMUstateSize", ANY),
            Call::SerializeFmuState => ("fmi2SerializeFMUstate", ANY),
            Call::DeSerializeFmuState => ("fmi2DeSerializeFMUstate", ANY),
            Call::GetDirectionalDerivative => ("fmi2GetDirectionalDerivative", READABLE),
            Call::SetRealInputDerivatives => ("fmi2SetRealInputDerivatives", SETTABLE),
            Call::GetRealOutputDerivatives => (
                "fmi2GetRealOutputDerivatives",
                STEP_COMPLETE.or(STEP_FAILED).or(TERMINATED).or(ERROR),
            ),
            Call::DoStep => ("fmi2DoStep", STEP_COMPLETE),
            Call::CancelStep => ("fmi2CancelStep", Mask::NONE),
            Call::GetStatus => ("fmi2GetStatus", STATUS),
            Call::GetRealStatus => ("fmi2GetRealStatus", STATUS),
            Call::GetIntegerStatus => ("fmi2GetIntegerStatus", STATUS),
            Call::GetBooleanStatus => ("fmi2GetBooleanStatus", STATUS),
            Call::GetStringStatus => ("fmi2GetStringStatus", STATUS),
        }
    }

    /// The C name of the call (FMI 2.0).
    pub const fn name(self) -> &'static str {
        self.rule().0
    }

    /// The C name of the call in FMI `version` (FMI 3.0 folds
    /// fmi2SetupExperiment into fmi3EnterInitializationMode, names the types
    /// by their size and spells `FMUState`; the FMI 2 status queries, input
    /// derivatives and step cancelling have no FMI 3 call and keep a
    /// descriptive name).
    pub const fn name_in(self, version: Version) -> &'static str {
        match version {
            Version::Fmi2 => self.name(),
            Version::Fmi3 => match self {
                Call::SetDebugLogging => "fmi3SetDebugLogging",
                Call::SetupExperiment | Call::EnterInitializationMode => {
                    "fmi3EnterInitializationMode"
                }
                Call::ExitInitializationMode => "fmi3ExitInitializationMode",
                Call::Terminate => "fmi3Terminate",
                Call::Reset => "fmi3Reset",
                Call::GetReal => "fmi3GetFloat64",
                Call::GetInteger => "fmi3GetInt32",
                Call::GetBoolean => "fmi3GetBoolean",
                Call::GetString => "fmi3GetString",
                Call::SetReal => "fmi3SetFloat64",
                Call::SetInteger => "fmi3SetInt32",
                Call::SetBoolean => "fmi3SetBoolean",
                Call::SetString => "fmi3SetString",
                Call::SetFixedParameter => "fmi3Set of a fixed parameter",
                Call::GetFmuState => "fmi3GetFMUState",
                Call::SetFmuState => "fmi3SetFMUState",
                Call::FreeFmuState => "fmi3FreeFMUState",
                Call::SerializedFmuStateSize => "fmi3SerializedFMUStateSize",
                Call::SerializeFmuState => "fmi3SerializeFMUState",
                Call::DeSerializeFmuState => "fmi3DeserializeFMUState",
                Call::GetDirectionalDerivative => "fmi3GetDirectionalDerivative",
                Call::SetRealInputDerivatives => "input derivatives (none in FMI 3.0)",
                Call::GetRealOutputDerivatives => "fmi3GetOutputDerivatives",
                Call::DoStep => "fmi3DoStep",
                Call::CancelStep => "step cancelling (none in FMI 3.0)",
                Call::GetStatus
                | Call::GetRealStatus
                | Call::GetIntegerStatus
                | Call::GetBooleanStatus
                | Call::GetStringStatus => "status queries (none in FMI 3.0)",
            },
        }
    }

    /// The phases the call is allowed in.
    pub const fn allowed(self) -> Mask {
        self.rule().1
    }

    /// `Ok` if the call is allowed in `phase`, else the message explaining why not.
    pub fn check(self, phase: Phase) -> Result<(), String> {
        self.check_in(phase, Version::Fmi2)
    }

    /// [`check`](Self::check) naming the call as FMI `version` does.
    pub fn check_in(self, phase: Phase, version: Version) -> Result<(), String> {
        let (name, allowed) = (self.name_in(version), self.allowed());
        if allowed.contains(phase) {
            return Ok(());
        }
        let list: Vec<String> = allowed.phases().map(|p| format!("{p:?}")).collect();
        let list = if list.is_empty() {
            "only while an asynchronous step is in progress; this FMU runs no asynchronous \
             step (canRunAsynchronuously = false)"
                .to_string()
        } else {
            list.join(", ")
        };
        Err(format!(
            "{name} is not allowed in state {phase:?} (allowed: {list})"
        ))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The standard's table (FMI 2.0.4, Co-Simulation state table of §4.2.4),
    /// written out by hand, column per state in [`Phase::ALL`] order:
    /// instantiated, initializationMode, stepComplete, stepFailed, terminated,
    /// error.
    const STANDARD: [(Call, [bool; 6]); 31] = {
        const X: bool = true;
        const O: bool = false;
        [
            (Call::SetDebugLogging, [X, X, X, X, X, X]),
            (Call::SetupExperiment, [X, O, O, O, O, O]),
            (Call::EnterInitializationMode, [X, O, O, O, O, O]),
            (Call::ExitInitializationMode, [O, X, O, O, O, O]),
            (Call::Terminate, [O, O, X, X, O, O]),
            (Call::Reset, [X, X, X, X, X, X]),
            (Call::GetReal, [O, X, X, X, X, X]),
            (Call::GetInteger, [O, X, X, X, X, X]),
            (Call::GetBoolean, [O, X, X, X, X, X]),
            (Call::GetString, [O, X, X, X, X, X]),
            (Call::SetReal, [X, X, X, O, O, O]),
            (Call::SetInteger, [X, X, X, O, O, O]),
            (Call::SetBoolean, [X, X, X, O, O, O]),
            (Call::SetString, [X, X, X, O, O, O]),
            (Call::SetFixedParameter, [X, X, O, O, O, O]),
            (Call::GetFmuState, [X, X, X, X, X, X]),
            (Call::SetFmuState, [X, X, X, X, X, X]),
            (Call::FreeFmuState, [X, X, X, X, X, X]),
            (Call::SerializedFmuStateSize, [X, X, X, X, X, X]),
            (Call::SerializeFmuState, [X, X, X, X, X, X]),
            (Call::DeSerializeFmuState, [X, X, X, X, X, X]),
            (Call::GetDirectionalDerivative, [O, X, X, X, X, X]),
            (Call::SetRealInputDerivatives, [X, X, X, O, O, O]),
            (Call::GetRealOutputDerivatives, [O, O, X, X, X, X]),
            (Call::DoStep, [O, O, X, O, O, O]),
            (Call::CancelStep, [O, O, O, O, O, O]),
            (Call::GetStatus, [O, O, X, X, X, O]),
            (Call::GetRealStatus, [O, O, X, X, X, O]),
            (Call::GetIntegerStatus, [O, O, X, X, X, O]),
            (Call::GetBooleanStatus, [O, O, X, X, X, O]),
            (Call::GetStringStatus, [O, O, X, X, X, O]),
        ]
    };

    #[test]
    fn table_is_the_standards() {
        for (call, row) in STANDARD {
            for (phase, allowed) in Phase::ALL.into_iter().zip(row) {
                assert_eq!(
                    call.check(phase).is_ok(),
                    allowed,
                    "{} in {phase:?}",
                    call.name()
                );
            }
        }
    }

    #[test]
    fn refusals_name_the_call_the_state_and_the_allowed_states() {
        let e = Call::DoStep.check(Phase::Instantiated).unwrap_err();
        assert_eq!(
            e,
            "fmi2DoStep is not allowed in state Instantiated (allowed: StepComplete)"
        );
        let e = Call::CancelStep.check(Phase::StepComplete).unwrap_err();
        assert!(e.contains("no asynchronous step"), "{e}");
    }

    #[test]
    fn an_fmi3_instance_hears_fmi3_names() {
        let e = Call::DoStep
            .check_in(Phase::Instantiated, Version::Fmi3)
            .unwrap_err();
        assert_eq!(
            e,
            "fmi3DoStep is not allowed in state Instantiated (allowed: StepComplete)"
        );
        assert_eq!(
            Call::DeSerializeFmuState.name_in(Version::Fmi3),
            "fmi3DeserializeFMUState"
        );
        assert_eq!(Call::GetReal.name_in(Version::Fmi2), "fmi2GetReal");
    }

    #[test]
    fn masks_hold_their_phases() {
        assert_eq!(ANY.phases().count(), Phase::ALL.len());
        assert_eq!(Mask::NONE.phases().count(), 0);
        assert!(SETTABLE.contains(Phase::StepComplete));
        assert!(!SETTABLE.contains(Phase::StepFailed));
    }
}
