//! Appended after the losses (issue 49): the centre offset of every bearing,
//! seal, rub and magnetic pull off the nominal axis, `offset_x` and
//! `offset_y` (m), fixed parameters — a master sets them before
//! initialization (a plant study sweeping the alignment) and the statics
//! and the run take them as if the model file gave them.

use super::{Binding, Causality, Kind, Table, Variability};

/// Append the offset parameters of every model bearing to `t`.
pub(super) fn add(t: &mut Table) {
    for (k, b) in t.model.bearings.iter().enumerate() {
        let group = if b.kind.is_seal() {
            "seals"
        } else if b.kind.is_rub() {
            "rubs"
        } else if b.kind.is_magnetic_pull() {
            "magnetic_pull"
        } else {
            "bearings"
        };
        for (axis, binding) in [("x", Binding::OffsetX(k)), ("y", Binding::OffsetY(k))] {
            let start = b.offset[usize::from(axis == "y")];
            t.push(
                format!("{group}.{}.offset_{axis}", b.name),
                format!(
                    "Centre of {} (node {}) off the nominal shaft axis, {axis} (its laws see the journal relative to it; for a horizontal machine with gravity along -y, offset_y is the elevation); set before initialization",
                    b.name,
                    b.node + 1
                ),
                Kind::Real,
                Causality::Parameter,
                Variability::Fixed,
                Some("m"),
                Some("um"),
                Some(start),
                binding,
            );
        }
    }
}
