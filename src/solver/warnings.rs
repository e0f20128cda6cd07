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

/// The warnings raised so far, and which elements have warned.
#[derive(Debug, Clone, Default)]
pub(super) struct Warnings {
    pending: Vec<SolverWarning>,
    /// Per model bearing: its coefficient table has warned.
    table_warned: Vec<bool>,
}

impl Warnings {
    pub fn new(rotor: &Rotor) -> Self {
        Self {
            pending: Vec::new(),
            table_warned: vec![false; rotor.model.bearings.len()],
        }
    }

    /// Warn (once per element) about every coefficient table of `rotor`
    /// that does not cover `speed` (rad/s) at time `time` (s).
    pub fn check_tables(&mut self, rotor: &Rotor, speed: f64, time: f64) {
        for (k, b) in rotor.model.bearings.iter().enumerate() {
            let Some(table) = b.kind.coefficient_table() else {
                continue;
            };
            if self.table_warned[k] || table.covers(speed) {
                continue;
            }
            self.table_warned[k] = true;
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
