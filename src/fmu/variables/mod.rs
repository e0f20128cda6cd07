//! The FMU's variable table, derived from the rotor model: the single source of
//! the value references, the model description and the runtime bindings.
//!
//! Order (and so value references) is fixed: parameters, inputs, outputs, each
//! in model order. The same function builds the table for `modelDescription.xml`
//! (packing) and inside the FMU (from the model file in `resources/`), so the
//! two can never drift apart; a GUID hashed from the description ties them.

use crate::model::{Drive, LoadChannel, RotorModel};
use crate::solver::SolverOptions;
pub use crate::solver::time_step::DEFAULT_LOCAL_ERROR_TOLERANCE;
use crate::solver::time_step::largest_adaptive_step;

mod bearing_loads;
mod drive;
mod loads;
mod losses;
mod machine;
mod offsets;
mod rotating_pull;
mod stepping;

/// What a variable reads or writes in the simulator.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Binding {
    /// Internal step (s).
    TimeStep,
    /// Relative solver tolerance.
    Tolerance,
    /// Newton iterations per step attempt (Integer).
    MaxIterations,
    /// Unbalance ramp time constant (s).
    RampTime,
    /// Gravity on/off (Boolean).
    Gravity,
    /// Fixed-interface modes of the reduced rotor, 0 for the full rotor (Integer).
    ReducedModes,
    /// Oil viscosity of model bearing `k` (Pa·s).
    Viscosity(usize),
    /// Angular position of unbalance plane `k` (rad).
    UnbalancePhase(usize),
    /// Spin speed input (rad/s).
    Speed,
    /// Unbalance of plane `k` (kg·m).
    Unbalance(usize),
    /// Journal x of bearing `k` (m).
    BearingX(usize),
    /// Journal y of bearing `k` (m).
    BearingY(usize),
    /// Force x of bearing `k` on the journal (N).
    BearingFx(usize),
    /// Force y of bearing `k` on the journal (N).
    BearingFy(usize),
    /// Eccentricity ratio of bearing `k`.
    BearingEccentricity(usize),
    /// Friction torque of bearing `k` (N·m).
    BearingFriction(usize),
    /// Contact normal force of bearing `k` (N).
    BearingContact(usize),
    /// Minimum film thickness of bearing `k` (m).
    BearingMinFilm(usize),
    /// Probe `k` x (m).
    ProbeX(usize),
    /// Probe `k` y (m).
    ProbeY(usize),
    /// Spin angle (rad).
    SpinAngle,
    /// Total bearing friction torque (N·m).
    FrictionTorque,
    /// Journal x of bearing `k` relative to its housing (m).
    BearingRelativeX(usize),
    /// Journal y of bearing `k` relative to its housing (m).
    BearingRelativeY(usize),
    /// Housing x of bearing `k` (m), absolute.
    HousingX(usize),
    /// Housing y of bearing `k` (m), absolute.
    HousingY(usize),
    /// Housing velocity x of bearing `k` (m/s), absolute.
    HousingVx(usize),
    /// Housing velocity y of bearing `k` (m/s), absolute.
    HousingVy(usize),
    /// Field excitation of the magnetic pull that is model bearing `k`.
    Excitation(usize),
    /// Frequency of harmonic force `h` (the order of
    /// [`RotorModel::harmonic_forces`]): its ratio to the running speed, or
    /// its fixed frequency (Hz).
    ForceFrequency(usize),
    /// Load input channel `i` (the order of
    /// [`RotorModel::load_inputs`]): a force (N), a port force (N) or a
    /// drive torque (N·m).
    Load(usize),
    /// Port `k` x (m).
    PortX(usize),
    /// Port `k` y (m).
    PortY(usize),
    /// Port `k` velocity x (m/s).
    PortVx(usize),
    /// Port `k` velocity y (m/s).
    PortVy(usize),
    /// Power dissipated in model bearing `k` (W).
    BearingPowerLoss(usize),
    /// Friction torque of thrust bearing `k` (N·m).
    ThrustFriction(usize),
    /// Power dissipated in thrust bearing `k` (W).
    ThrustPowerLoss(usize),
    /// Total power dissipated in the bearings, rubs, seals and thrust bearings (W).
    PowerLoss,
    /// Initial spin speed of a torque-driven shaft (rad/s).
    InitialSpeed,
    /// Local error tolerance of accuracy-controlled steps (–), 0 for equal steps.
    LocalErrorTolerance,
    /// Speed of torque node `k` (rad/s).
    TorqueSpeed(usize),
    /// Angle of torque node `k` (rad).
    TorqueAngle(usize),
    /// Torque carried by shaft element `k` (N·m).
    ShaftTorque(usize),
    /// Centre offset x of model bearing `k` off the nominal axis (m).
    OffsetX(usize),
    /// Centre offset y of model bearing `k` off the nominal axis (m).
    OffsetY(usize),
    /// Static load x of bearing `k`, its force on the journal at the
    /// equilibrium of initialization (N).
    StaticFx(usize),
    /// Static load y of bearing `k` (N).
    StaticFy(usize),
    /// Dynamic load x of bearing `k`, its force minus the static load (N).
    DynamicFx(usize),
    /// Dynamic load y of bearing `k` (N).
    DynamicFy(usize),
    /// Magnitude of the dynamic load of bearing `k` (N).
    DynamicLoad(usize),
}

/// FMI base type.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Kind {
    /// fmi2Real.
    Real,
    /// fmi2Integer.
    Integer,
    /// fmi2Boolean.
    Boolean,
}

/// FMI causality.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Causality {
    /// A parameter.
    Parameter,
    /// An input.
    Input,
    /// An output.
    Output,
}

/// FMI variability.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Variability {
    /// Fixed after initialization.
    Fixed,
    /// Changeable between steps.
    Tunable,
    /// Continuous in time.
    Continuous,
}

/// One scalar variable.
#[derive(Debug, Clone, PartialEq)]
pub struct Variable {
    /// Structured name, e.g. `bearings.generator_guide.x`.
    pub name: String,
    /// Value reference (its index in the table).
    pub value_reference: u32,
    /// Description with the physics and sign convention.
    pub description: String,
    /// Base type.
    pub kind: Kind,
    /// Causality.
    pub causality: Causality,
    /// Variability.
    pub variability: Variability,
    /// SI unit name (declared in `UnitDefinitions`), if any.
    pub unit: Option<&'static str>,
    /// Display unit, if any.
    pub display_unit: Option<&'static str>,
    /// Start value (parameters and inputs).
    pub start: Option<f64>,
    /// What it is bound to.
    pub binding: Binding,
    /// Output depends directly on the speed input (film forces and friction).
    pub feedthrough_speed: bool,
    /// Smallest value a master may set (declared `min`), if bounded.
    pub min: Option<f64>,
    /// Largest value a master may set (declared `max`), if bounded.
    pub max: Option<f64>,
}

/// Allowed field excitations of a magnetic pull (0 off, 1 nominal).
pub const EXCITATION_RANGE: (f64, f64) = (0.0, crate::model::limits::MAX_EXCITATION);

/// Allowed oil viscosities (Pa·s): positive, from a gas film to a heavy grease
/// (the model file's range, [`crate::model::limits::VISCOSITY`]).
/// The largest ratio of a harmonic force's frequency to the running speed
/// the FMU takes (blade passing of the largest impellers is under 100×).
pub const FORCE_RATIO_BOUND: f64 = 1000.0;

/// Whether model force `force` is harmonic with a ratio to the running speed.
pub fn force_has_ratio(model: &RotorModel, force: usize) -> bool {
    matches!(
        model.forces[force].kind,
        crate::model::ForceKind::Harmonic {
            frequency: crate::model::HarmonicFrequency::Ratio(_),
            ..
        }
    )
}

/// What the simulator's frequency of harmonic force `h` is per unit of its
/// FMU variable: 1 for a ratio, 2π for a fixed frequency (Hz to rad/s).
pub fn force_frequency_scale(model: &RotorModel, h: usize) -> f64 {
    match model.harmonic_forces().nth(h) {
        Some((force, _, _)) if !force_has_ratio(model, force) => std::f64::consts::TAU,
        _ => 1.0,
    }
}

pub const VISCOSITY_RANGE: (f64, f64) = (
    crate::model::limits::VISCOSITY.min,
    crate::model::limits::VISCOSITY.max,
);

/// The declared `[min, max]` of a settable variable: the solver's option
/// ranges, the model's largest speed, physical signs. The FMU checks every set
/// value against it, and `modelDescription.xml` declares it.
pub fn value_range(binding: Binding, model: &RotorModel) -> (Option<f64>, Option<f64>) {
    let pair = |(lo, hi): (f64, f64)| (Some(lo), Some(hi));
    let ints = |(lo, hi): (usize, usize)| (Some(lo as f64), Some(hi as f64));
    match binding {
        Binding::TimeStep => pair(SolverOptions::TIME_STEP_RANGE),
        Binding::Tolerance => pair(SolverOptions::TOLERANCE_RANGE),
        Binding::MaxIterations => ints(SolverOptions::MAX_ITERATIONS_RANGE),
        Binding::ReducedModes => ints((0, crate::model::MAX_REDUCED_MODES)),
        Binding::RampTime => pair(SolverOptions::RAMP_TIME_RANGE),
        Binding::LocalErrorTolerance => (
            Some(0.0),
            Some(SolverOptions::LOCAL_ERROR_TOLERANCE_RANGE.1),
        ),
        Binding::Viscosity(_) => pair(VISCOSITY_RANGE),
        Binding::Excitation(_) => pair(EXCITATION_RANGE),
        Binding::ForceFrequency(h) => match model.harmonic_forces().nth(h) {
            Some((force, _, _)) if force_has_ratio(model, force) => {
                pair((-FORCE_RATIO_BOUND, FORCE_RATIO_BOUND))
            }
            _ => (Some(0.0), None),
        },
        Binding::OffsetX(_) | Binding::OffsetY(_) => pair((
            crate::model::limits::OFFSET.min,
            crate::model::limits::OFFSET.max,
        )),
        Binding::Speed => (Some(-model.max_speed), Some(model.max_speed)),
        Binding::Unbalance(_) => (Some(0.0), None),
        Binding::Load(i) => match model.load_inputs().get(i).map(|l| l.channel) {
            Some(LoadChannel::Component) => {
                let f = model.input_force_bound();
                (Some(-f), Some(f))
            }
            Some(LoadChannel::Amplitude) => (Some(0.0), Some(model.input_force_bound())),
            Some(LoadChannel::Torque) => {
                let t = model.input_torque_bound();
                (Some(-t), Some(t))
            }
            Some(LoadChannel::Eccentricity) => {
                let gap = (0..model.bearings.len())
                    .find(|&k| model.pull_input(k) == Some(i))
                    .and_then(|k| match &model.bearings[k].kind {
                        crate::bearing::BearingKind::MagneticPull(m) => Some(m.gap),
                        _ => None,
                    });
                (Some(0.0), gap)
            }
            None => (None, None),
        },
        _ => (None, None),
    }
}

/// An output of a bearing: name suffix, description, unit, display unit, binding.
pub(super) type OutputSpec = (
    &'static str,
    String,
    Option<&'static str>,
    Option<&'static str>,
    Binding,
);

/// Start value of `solver.time_step` (s) of an FMU of `model`, the largest
/// internal step: the rule the CLI's `simulate` follows for
/// accuracy-controlled steps, the FMU's default
/// ([`largest_adaptive_step`]: 12 steps per revolution at the model's top
/// speed, at most 20 ms).
pub fn default_fmu_time_step(model: &RotorModel) -> f64 {
    largest_adaptive_step(model, None)
}

/// Defaults of the solver parameters.
/// Start value of `shaft.speed` (rad/s): the machine at standstill, its
/// journals resting on their bearings; a master sets another start value to
/// begin at speed.
pub const START_SPEED: f64 = 0.0;
/// Default relative tolerance.
pub const DEFAULT_TOLERANCE: f64 = 1e-8;
/// Default Newton iteration limit.
pub const DEFAULT_MAX_ITERATIONS: f64 = 50.0;

/// The variables being built: each pushed one takes the next value reference.
pub(super) struct Table<'a> {
    /// The model the variables describe.
    pub(super) model: &'a RotorModel,
    out: Vec<Variable>,
}

impl Table<'_> {
    /// Append a variable; `min`/`max` from [`value_range`].
    #[allow(clippy::too_many_arguments)]
    pub(super) fn push(
        &mut self,
        name: String,
        description: String,
        kind: Kind,
        causality: Causality,
        variability: Variability,
        unit: Option<&'static str>,
        display_unit: Option<&'static str>,
        start: Option<f64>,
        binding: Binding,
    ) {
        // A prescribed speed reaches the films, friction and losses at once;
        // a torque-driven shaft has no speed input.
        let feedthrough_speed = self.model.drive == Drive::Speed
            && matches!(
                binding,
                Binding::BearingFx(_)
                    | Binding::BearingFy(_)
                    | Binding::BearingFriction(_)
                    | Binding::FrictionTorque
                    | Binding::BearingPowerLoss(_)
                    | Binding::ThrustFriction(_)
                    | Binding::ThrustPowerLoss(_)
                    | Binding::PowerLoss
                    | Binding::DynamicFx(_)
                    | Binding::DynamicFy(_)
                    | Binding::DynamicLoad(_)
            );
        let (min, max) = value_range(binding, self.model);
        self.out.push(Variable {
            min,
            max,
            value_reference: self.out.len() as u32,
            name,
            description,
            kind,
            causality,
            variability,
            unit,
            display_unit,
            start,
            binding,
            feedthrough_speed,
        });
    }

    /// Append the continuous outputs `{group}.{name}.{suffix}` of `specs`.
    pub(super) fn outputs(
        &mut self,
        group: &str,
        name: &str,
        specs: impl IntoIterator<Item = OutputSpec>,
    ) {
        for (suffix, description, unit, display, binding) in specs {
            self.push(
                format!("{group}.{name}.{suffix}"),
                description,
                Kind::Real,
                Causality::Output,
                Variability::Continuous,
                unit,
                display,
                None,
                binding,
            );
        }
    }
}

/// The variable table of `model`: the machine's variables in their historic
/// order, then each later group appended (so a model without its elements
/// keeps every value reference).
pub fn variables(model: &RotorModel) -> Vec<Variable> {
    let mut t = Table {
        model,
        out: Vec::new(),
    };
    machine::add(&mut t);
    loads::add(&mut t);
    drive::add(&mut t);
    stepping::add(&mut t);
    losses::add(&mut t);
    offsets::add(&mut t);
    rotating_pull::add(&mut t);
    bearing_loads::add(&mut t);
    loads::add_frequencies(&mut t);
    t.out
}
