//! The simulator's complete dynamic state (the one field list a snapshot of
//! the solver holds) and its validation when a front end restores it.

use super::error::SolverError;
use super::newton::CHORD_PAUSE;
use crate::units::{RAD_S_TO_RPM, Short};

/// The complete dynamic state: restoring it reproduces a run bit for bit.
#[derive(Debug, Clone, PartialEq)]
pub struct SimState {
    /// Time (s).
    pub time: f64,
    /// Rotor free DOFs: displacement, velocity, acceleration.
    pub u: Vec<f64>,
    /// Velocity.
    pub ud: Vec<f64>,
    /// Acceleration.
    pub udd: Vec<f64>,
    /// Bearing internal DOFs (pad tilts, m) and their rates.
    pub p: Vec<f64>,
    /// Rates of the internal DOFs.
    pub pd: Vec<f64>,
    /// Second derivatives of the internal DOFs (Newmark bookkeeping).
    pub pdd: Vec<f64>,
    /// Spin angle (rad).
    pub spin_angle: f64,
    /// Spin speed input at `speed_time` (rad/s).
    pub speed: f64,
    /// Spin acceleration input (rad/s²): `Ω(t) = speed + speed_rate (t − speed_time)`.
    pub speed_rate: f64,
    /// Time the inputs (speed, unbalance) refer to (s).
    pub speed_time: f64,
    /// Unbalance of each plane at `speed_time` (kg·m).
    pub unbalance: Vec<f64>,
    /// Rate of change of each plane's unbalance (kg·m/s).
    pub unbalance_rate: Vec<f64>,
    /// Angular position of each unbalance plane at spin angle 0 (rad).
    pub unbalance_phase: Vec<f64>,
    /// Each load input (static force components, harmonic force amplitudes,
    /// port forces; N) at `speed_time`, in the order of
    /// [`RotorModel::load_inputs`](crate::model::RotorModel::load_inputs).
    pub loads: Vec<f64>,
    /// Rate of change of each load input (N/s).
    pub load_rates: Vec<f64>,
    /// A torque-driven shaft's twist angle of each free twist DOF (rad,
    /// absolute rotation about +z); empty when the speed is prescribed.
    pub twist: Vec<f64>,
    /// Its rate (rad/s).
    pub twist_rate: Vec<f64>,
    /// Its acceleration (rad/s²).
    pub twist_accel: Vec<f64>,
    /// The coupling torques on the twist at this time (N·m): friction and
    /// unbalance reactions, the next step's first estimate.
    pub twist_torque: Vec<f64>,
    /// 1 while static friction holds the torque-driven shaft at rest, else 0.
    pub stuck: f64,
    /// Step size the factorization in hand was made for (s); 0 for none.
    pub factor_step: f64,
    /// Spin speed the factorization in hand was made at (rad/s).
    pub factor_speed: f64,
    /// The rotor accelerations one accuracy-controlled step back (the
    /// local error estimate's); empty before the first such step.
    pub udd_previous: Vec<f64>,
    /// The next step accuracy-controlled stepping proposes (s); 0 before the
    /// first such step (then the largest step is tried).
    pub step_proposal: f64,
    /// 1 while the condensed Newton settles each pad on its own balance
    /// (`solver::pad_balance`), set by a slowly contracting step and carried
    /// to the next, else 0.
    pub pad_balancing: f64,
    /// Steps left in which the condensed Newton tries no chord iteration
    /// (a whole number from 0 to `solver::newton::CHORD_PAUSE`), set when one
    /// is refused and carried to the next steps.
    pub chord_pause: f64,
    /// For each nonlinear bearing site (site order), whether its contact has
    /// gone beyond the penetration and the force limit of its law (1) or not
    /// (0), two entries a site: a warning is raised once, and a restored
    /// state raises it again ([`super::contact_watch`]).
    pub contact_reported: Vec<f64>,
    /// For each model bearing, whether its coefficient table has warned of a
    /// speed outside its rows (1) or not (0).
    pub table_warned: Vec<f64>,
    /// The static load of each model bearing, `[fx, fy]` a bearing (N, the
    /// force of its law on the journal, a pull's rotating 1× part left out)
    /// at the equilibrium [`Simulator::settle_static`] last found: the load
    /// the bearing carries from gravity, the static loads and its offset.
    /// Zero before the first settling; kept while the run goes on (its
    /// dynamic load is the current force minus it).
    ///
    /// [`Simulator::settle_static`]: super::Simulator::settle_static
    pub static_load: Vec<f64>,
    /// Each harmonic `[[forces]]` entry's phase (rad), model order of the
    /// harmonic forces: its angle is `θ = phase + frequency × x`, `x` the
    /// spin angle (a ratio to the running speed) or the time (a fixed
    /// frequency). The model's phase, moved where its frequency is changed
    /// so that the angle goes on without a jump
    /// ([`Simulator::set_force_frequency`](super::Simulator::set_force_frequency)).
    pub harmonic_phase: Vec<f64>,
    /// Each harmonic force's frequency: its ratio to the running speed, or
    /// its angular frequency (rad/s).
    pub harmonic_frequency: Vec<f64>,
}

impl SimState {
    /// Every field finite, unbalances non-negative, `|speed| ≤ max_speed`
    /// (rad/s): a state that passes can be stepped; the error names the field.
    pub fn check(&self, max_speed: f64) -> Result<(), SolverError> {
        let scalars = [
            ("time", self.time),
            ("spin_angle", self.spin_angle),
            ("speed", self.speed),
            ("speed_rate", self.speed_rate),
            ("speed_time", self.speed_time),
            ("factor_step", self.factor_step),
            ("factor_speed", self.factor_speed),
            ("stuck", self.stuck),
            ("step_proposal", self.step_proposal),
            ("pad_balancing", self.pad_balancing),
            ("chord_pause", self.chord_pause),
        ];
        let vectors: [(&str, &[f64]); 21] = [
            ("u", &self.u),
            ("ud", &self.ud),
            ("udd", &self.udd),
            ("p", &self.p),
            ("pd", &self.pd),
            ("pdd", &self.pdd),
            ("unbalance", &self.unbalance),
            ("unbalance_rate", &self.unbalance_rate),
            ("unbalance_phase", &self.unbalance_phase),
            ("loads", &self.loads),
            ("load_rates", &self.load_rates),
            ("twist", &self.twist),
            ("twist_rate", &self.twist_rate),
            ("twist_accel", &self.twist_accel),
            ("twist_torque", &self.twist_torque),
            ("udd_previous", &self.udd_previous),
            ("contact_reported", &self.contact_reported),
            ("table_warned", &self.table_warned),
            ("static_load", &self.static_load),
            ("harmonic_phase", &self.harmonic_phase),
            ("harmonic_frequency", &self.harmonic_frequency),
        ];
        let bad = scalars
            .iter()
            .find(|(_, v)| !v.is_finite())
            .copied()
            .or_else(|| {
                vectors
                    .iter()
                    .find_map(|(name, v)| v.iter().find(|x| !x.is_finite()).map(|&x| (*name, x)))
            });
        if let Some((name, v)) = bad {
            return Err(SolverError::Input(format!(
                "state field {name} = {} is not finite",
                Short(v)
            )));
        }
        if let Some(m) = self.unbalance.iter().find(|m| **m < 0.0) {
            return Err(SolverError::Input(format!(
                "state field unbalance = {} kg·m is negative",
                Short(*m)
            )));
        }
        for (name, flags) in [
            ("contact_reported", &self.contact_reported),
            ("table_warned", &self.table_warned),
        ] {
            if let Some(v) = flags.iter().find(|v| **v != 0.0 && **v != 1.0) {
                return Err(SolverError::Input(format!(
                    "state field {name} = {} is neither 0 nor 1",
                    Short(*v)
                )));
            }
        }
        if self.step_proposal < 0.0 {
            return Err(SolverError::Input(format!(
                "state field step_proposal = {} s is negative",
                Short(self.step_proposal)
            )));
        }
        let pause = self.chord_pause;
        if pause.fract() != 0.0 || !(0.0..=f64::from(CHORD_PAUSE)).contains(&pause) {
            return Err(SolverError::Input(format!(
                "state field chord_pause = {} is not a whole number of steps from 0 to {CHORD_PAUSE}",
                Short(pause)
            )));
        }
        if self.speed.abs() > max_speed {
            return Err(SolverError::Input(format!(
                "state field speed = {} rad/s ({} rpm) exceeds the model's max_speed_rpm ({} rpm)",
                Short(self.speed),
                Short(self.speed * RAD_S_TO_RPM),
                Short(max_speed * RAD_S_TO_RPM)
            )));
        }
        Ok(())
    }
}
