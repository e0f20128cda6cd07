//! Warnings a transient raises while it runs: results that are computed but
//! rest on data outside its validity, reported once per element so a long
//! run does not flood its log. Today: a coefficient table (table bearing or
//! seal) asked for a speed outside its rows, where its end values are held.

use std::fmt;

use crate::rotor::Rotor;

/// One warning of a running simulation.
#[derive(Debug, Clone, PartialEq)]
pub struct SolverWarning {
    /// Simulation time it was first met (s).
    pub time: f64,
    /// The model element it concerns (bearing, rub or seal name).
    pub element: String,
    /// What is wrong and what the solver does about it.
    pub message: String,
}

impl fmt::Display for SolverWarning {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "t = {} s: {}: {}", self.time, self.element, self.message)
    }
}

/// The warnings raised and not yet taken. Which elements have warned is
/// part of the state ([`SimState::table_warned`]), so a restored state warns
/// again.
///
/// [`SimState::table_warned`]: super::SimState::table_warned
#[derive(Debug, Clone, Default)]
pub(super) struct Warnings {
    pending: Vec<SolverWarning>,
}

impl Warnings {
    /// Warn (once per element) about every coefficient table of `rotor`
    /// that does not cover `speed` (rad/s) at time `time` (s).
    /// `warned` holds, per model bearing, 1 once its table has warned.
    pub fn check_tables(&mut self, rotor: &Rotor, warned: &mut [f64], speed: f64, time: f64) {
        for (k, b) in rotor.model.bearings.iter().enumerate() {
            let Some(table) = b.kind.coefficient_table() else {
                continue;
            };
            if warned[k] != 0.0 || table.covers(speed) {
                continue;
            }
            warned[k] = 1.0;
            self.pending.push(SolverWarning {
                time,
                element: b.name.clone(),
                message: table.outside_message(speed),
            });
        }
    }

    /// The warnings raised since the last call.
    pub fn take(&mut self) -> Vec<SolverWarning> {
        std::mem::take(&mut self.pending)
    }
}
