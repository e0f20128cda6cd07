//! Appended after the offsets (issue 48): the dynamic (rotating, 1×)
//! eccentricity of each magnetic pull's rotor, a continuous input in metres
//! (the model file's `dynamic_eccentricity` its start), so a plant study can
//! switch it on, sweep it or drive it from another model during the run like
//! the field excitation. Its force, `k s² e_d` turning with the shaft, is in
//! the pull's `fx`, `fy` outputs.

use super::{Binding, Causality, Kind, Table, Variability};

/// Append the dynamic-eccentricity input of every magnetic pull to `t`.
pub(super) fn add(t: &mut Table) {
    for (k, b) in t.model.bearings.iter().enumerate() {
        let Some(channel) = t.model.pull_input(k) else {
            continue;
        };
        let crate::bearing::BearingKind::MagneticPull(m) = &b.kind else {
            continue;
        };
        t.push(
            format!("magnetic_pull.{}.dynamic_eccentricity", b.name),
            format!(
                "Dynamic (rotating) eccentricity of the rotor in the stator of {} (node {}): its geometric centre off the axis of rotation, turning with the shaft; adds the 1x pull k s^2 e_d (0 to the air gap {} m)",
                b.name,
                b.node + 1,
                m.gap
            ),
            Kind::Real,
            Causality::Input,
            Variability::Continuous,
            Some("m"),
            Some("um"),
            Some(m.dynamic_eccentricity),
            Binding::Load(channel),
        );
    }
}
