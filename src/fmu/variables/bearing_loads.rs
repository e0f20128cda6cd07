//! Appended after the pulls' dynamic eccentricity (issue 49): each journal
//! bearing's static load — its force on the journal at the static
//! equilibrium the FMU settles in at initialization (gravity, static loads
//! and its offset; [`SimState::static_load`]) — and its dynamic load, the
//! current force minus the static load, with the dynamic load's magnitude.
//!
//! [`SimState::static_load`]: crate::solver::SimState::static_load

use super::{Binding, OutputSpec, Table};

/// Append the static and dynamic loads of every journal bearing to `t`.
pub(super) fn add(t: &mut Table) {
    for (k, b) in t.model.bearings.iter().enumerate() {
        if !b.kind.is_bearing() {
            continue;
        }
        let n = &b.name;
        let outputs: [OutputSpec; 5] = [
            (
                "static_fx",
                format!(
                    "Static load x of bearing {n}: its force on the journal at the static equilibrium of initialization (gravity, static loads, offsets), held while the run goes on"
                ),
                Some("N"),
                None,
                Binding::StaticFx(k),
            ),
            (
                "static_fy",
                format!("Static load y of bearing {n} (force on the journal at initialization)"),
                Some("N"),
                None,
                Binding::StaticFy(k),
            ),
            (
                "dynamic_fx",
                format!("Dynamic load x of bearing {n}: fx - static_fx"),
                Some("N"),
                None,
                Binding::DynamicFx(k),
            ),
            (
                "dynamic_fy",
                format!("Dynamic load y of bearing {n}: fy - static_fy"),
                Some("N"),
                None,
                Binding::DynamicFy(k),
            ),
            (
                "dynamic_load",
                format!(
                    "Magnitude of the dynamic load of bearing {n}, sqrt(dynamic_fx^2 + dynamic_fy^2)"
                ),
                Some("N"),
                None,
                Binding::DynamicLoad(k),
            ),
        ];
        t.outputs("bearings", n, outputs);
    }
}
