//! Appended after the step control: the power dissipated by the seals and
//! magnetic pulls (their stator contact: `μ N |v_slip|`), so that every part
//! of the total `power_loss` has an output of its own (the bearings', rubs' and thrust bearings' come with the
//! drive's variables).

use super::{Binding, OutputSpec, Table};

/// Append the seals' and pulls' power losses to `t`.
pub(super) fn add(t: &mut Table) {
    for (k, b) in t.model.bearings.iter().enumerate() {
        let (n, node) = (&b.name, b.node + 1);
        if b.kind.is_seal() {
            let specs: [OutputSpec; 1] = [(
                "power_loss",
                format!(
                    "Power dissipated by seal {n} (node {node}) rubbing on its stator, mu*N*|v_slip| (0 while clear)"
                ),
                Some("W"),
                None,
                Binding::BearingPowerLoss(k),
            )];
            t.outputs("seals", n, specs);
        } else if b.kind.is_magnetic_pull() {
            let specs: [OutputSpec; 1] = [(
                "power_loss",
                format!(
                    "Power dissipated by the rotor of magnetic pull {n} (node {node}) rubbing on its stator, mu*N*|v_slip| (0 while the air gap is open)"
                ),
                Some("W"),
                None,
                Binding::BearingPowerLoss(k),
            )];
            t.outputs("magnetic_pull", n, specs);
        }
    }
}
