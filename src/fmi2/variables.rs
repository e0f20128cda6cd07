//! The FMU's variable table, derived from the rotor model: the single source of
//! the value references, the model description and the runtime bindings.
//!
//! Order (and so value references) is fixed: parameters, inputs, outputs, each
//! in model order. The same function builds the table for `modelDescription.xml`
//! (packing) and inside the FMU (from the model file in `resources/`), so the
//! two can never drift apart; a GUID hashed from the description ties them.

use crate::model::{DEFAULT_REDUCED_MODES, RotorModel};
use crate::solver::SolverOptions;
use crate::solver::time_step::default_time_step;

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

/// Allowed oil viscosities (Pa·s): positive, from a gas film to a heavy grease
/// (the model file's range, [`crate::model::limits::VISCOSITY`]).
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
        Binding::Viscosity(_) => pair(VISCOSITY_RANGE),
        Binding::Speed => (Some(-model.max_speed), Some(model.max_speed)),
        Binding::Unbalance(_) => (Some(0.0), None),
        _ => (None, None),
    }
}

/// An output of a bearing: name suffix, description, unit, display unit, binding.
type OutputSpec = (
    &'static str,
    String,
    Option<&'static str>,
    Option<&'static str>,
    Binding,
);

/// Start value of `solver.time_step` (s) of an FMU of `model`: the rule the
/// CLI's `simulate` follows ([`default_time_step`]: 60 steps per revolution
/// at the model's top speed, at most 1 ms).
pub fn default_fmu_time_step(model: &RotorModel) -> f64 {
    default_time_step(model, None)
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

/// The variable table of `model`.
pub fn variables(model: &RotorModel) -> Vec<Variable> {
    let mut out: Vec<Variable> = Vec::new();
    let mut push = |name: String,
                    description: String,
                    kind: Kind,
                    causality: Causality,
                    variability: Variability,
                    unit: Option<&'static str>,
                    display_unit: Option<&'static str>,
                    start: Option<f64>,
                    binding: Binding| {
        let feedthrough_speed = matches!(
            binding,
            Binding::BearingFx(_)
                | Binding::BearingFy(_)
                | Binding::BearingFriction(_)
                | Binding::FrictionTorque
        );
        let (min, max) = value_range(binding, model);
        out.push(Variable {
            min,
            max,
            value_reference: out.len() as u32,
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
    };
    use Causality::*;
    use Kind::*;
    use Variability::*;
    push(
        "solver.time_step".into(),
        "Largest internal Newmark time step; each fmi2DoStep is split into equal sub-steps no longer than this".into(),
        Real,
        Parameter,
        Fixed,
        Some("s"),
        None,
        Some(default_fmu_time_step(model)),
        Binding::TimeStep,
    );
    push(
        "solver.tolerance".into(),
        "Relative tolerance of the Newton-Raphson iterations on residual and increment".into(),
        Real,
        Parameter,
        Fixed,
        Some("1"),
        None,
        Some(DEFAULT_TOLERANCE),
        Binding::Tolerance,
    );
    push(
        "solver.max_iterations".into(),
        "Newton-Raphson iterations per step attempt before the step is halved".into(),
        Integer,
        Parameter,
        Fixed,
        None,
        None,
        Some(DEFAULT_MAX_ITERATIONS),
        Binding::MaxIterations,
    );
    push(
        "unbalance_ramp_time".into(),
        "Time constant of the unbalance ramp-in 1 - exp(-t/tau); 0 applies the unbalance at once"
            .into(),
        Real,
        Parameter,
        Fixed,
        Some("s"),
        None,
        Some(0.0),
        Binding::RampTime,
    );
    push(
        "gravity".into(),
        "Apply the model's gravity vector".into(),
        Boolean,
        Parameter,
        Fixed,
        None,
        None,
        Some(1.0),
        Binding::Gravity,
    );
    for (k, b) in model.bearings.iter().enumerate() {
        let Some(mu) = b.kind.viscosity() else {
            continue;
        };
        push(
            format!("bearings.{}.viscosity", b.name),
            format!(
                "Oil dynamic viscosity of bearing {} (node {})",
                b.name,
                b.node + 1
            ),
            Real,
            Parameter,
            Tunable,
            Some("Pa.s"),
            None,
            Some(mu),
            Binding::Viscosity(k),
        );
    }
    for (k, u) in model.unbalances.iter().enumerate() {
        push(
            format!("unbalance.{}.phase", u.name),
            format!(
                "Angular position of unbalance plane {} (node {}) at spin angle 0, from +x toward +y",
                u.name,
                u.node + 1
            ),
            Real,
            Parameter,
            Tunable,
            Some("rad"),
            Some("deg"),
            Some(u.phase),
            Binding::UnbalancePhase(k),
        );
    }
    push(
        "shaft.speed".into(),
        "Spin speed of the shaft about +z (input; a first-order input derivative gives a ramp within a step)".into(),
        Real,
        Input,
        Continuous,
        Some("rad/s"),
        Some("rpm"),
        Some(START_SPEED),
        Binding::Speed,
    );
    for (k, u) in model.unbalances.iter().enumerate() {
        push(
            format!("unbalance.{}", u.name),
            format!("Unbalance m*e of plane {} (node {})", u.name, u.node + 1),
            Real,
            Input,
            Continuous,
            Some("kg.m"),
            None,
            Some(u.magnitude),
            Binding::Unbalance(k),
        );
    }
    for (k, b) in model.bearings.iter().enumerate() {
        if b.kind.is_rub() {
            continue;
        }
        let node = b.node + 1;
        let n = &b.name;
        let outputs: [OutputSpec; 6] = [
            (
                "x",
                format!("Journal displacement x at bearing {n} (node {node})"),
                Some("m"),
                Some("um"),
                Binding::BearingX(k),
            ),
            (
                "y",
                format!("Journal displacement y at bearing {n} (node {node})"),
                Some("m"),
                Some("um"),
                Binding::BearingY(k),
            ),
            (
                "fx",
                format!("Force x of bearing {n} on the journal"),
                Some("N"),
                None,
                Binding::BearingFx(k),
            ),
            (
                "fy",
                format!("Force y of bearing {n} on the journal"),
                Some("N"),
                None,
                Binding::BearingFy(k),
            ),
            (
                "eccentricity",
                format!("Eccentricity ratio e/C of bearing {n} (0 for linear bearings)"),
                Some("1"),
                None,
                Binding::BearingEccentricity(k),
            ),
            (
                "friction_torque",
                format!(
                    "Friction torque of bearing {n} on the journal, opposing the spin: film shear plus contact friction mu*N*R (at standstill the breakaway torque)"
                ),
                Some("N.m"),
                None,
                Binding::BearingFriction(k),
            ),
        ];
        for (suffix, description, unit, display, binding) in outputs {
            push(
                format!("bearings.{n}.{suffix}"),
                description,
                Real,
                Output,
                Continuous,
                unit,
                display,
                None,
                binding,
            );
        }
    }
    for (k, p) in model.probes.iter().enumerate() {
        let node = p.node + 1;
        push(
            format!("probes.{}.x", p.name),
            format!("Displacement x at probe {} (node {node})", p.name),
            Real,
            Output,
            Continuous,
            Some("m"),
            Some("um"),
            None,
            Binding::ProbeX(k),
        );
        push(
            format!("probes.{}.y", p.name),
            format!("Displacement y at probe {} (node {node})", p.name),
            Real,
            Output,
            Continuous,
            Some("m"),
            Some("um"),
            None,
            Binding::ProbeY(k),
        );
    }
    push(
        "shaft.spin_angle".into(),
        "Spin angle of the shaft (integral of the speed)".into(),
        Real,
        Output,
        Continuous,
        Some("rad"),
        Some("deg"),
        None,
        Binding::SpinAngle,
    );
    push(
        "friction_torque".into(),
        "Sum of the bearings' friction torques on the shaft (for a generator torque balance)"
            .into(),
        Real,
        Output,
        Continuous,
        Some("N.m"),
        None,
        None,
        Binding::FrictionTorque,
    );
    // Contact outputs come last, so the value references above stay as they were.
    for (k, b) in model.bearings.iter().enumerate() {
        let n = &b.name;
        if b.kind.is_rub() {
            push(
                format!("rubs.{n}.contact_force"),
                format!(
                    "Normal force of rub {n} (node {}) on the rotor (0 while clear of the stator)",
                    b.node + 1
                ),
                Real,
                Output,
                Continuous,
                Some("N"),
                None,
                None,
                Binding::BearingContact(k),
            );
            push(
                format!("rubs.{n}.friction_torque"),
                format!("Friction torque mu*N*R of rub {n} on the rotor, opposing the spin"),
                Real,
                Output,
                Continuous,
                Some("N.m"),
                None,
                None,
                Binding::BearingFriction(k),
            );
            continue;
        }
        push(
            format!("bearings.{n}.contact_force"),
            format!(
                "Normal force of the metal-to-metal contact of the journal in bearing {n} (0 while it floats on its film)"
            ),
            Real,
            Output,
            Continuous,
            Some("N"),
            None,
            None,
            Binding::BearingContact(k),
        );
        push(
            format!("bearings.{n}.min_film_thickness"),
            format!(
                "Minimum oil-film thickness of bearing {n} (0 in contact and for linear bearings)"
            ),
            Real,
            Output,
            Continuous,
            Some("m"),
            Some("um"),
            None,
            Binding::BearingMinFilm(k),
        );
    }
    // Appended after the contact outputs, so earlier value references stay.
    push(
        "solver.reduced_modes".into(),
        "Fixed-interface modes of the Craig-Bampton reduced rotor the transient runs on (nonlinear bearings, rubs, probes and unbalance planes kept physical); 0 runs the full rotor".into(),
        Integer,
        Parameter,
        Fixed,
        None,
        None,
        Some(crate::rotor::Rotor::transient_modes(model).unwrap_or(DEFAULT_REDUCED_MODES) as f64),
        Binding::ReducedModes,
    );
    out
}
