//! The variables of the drive, appended after the loads: every model's
//! power losses (per bearing and rub, per thrust bearing with its friction
//! torque, and the total), then, for a torque-driven shaft
//! (`[torsion] drive = "torque"`), its initial speed, the torque inputs, the
//! speed and angle at each torque node and the torque in each shaft element.
//! (A torque-driven shaft's `shaft.speed` keeps its value reference and
//! becomes the output of its mean speed.)

use super::Causality::*;
use super::Kind::*;
use super::Variability::*;
use super::{Binding, OutputSpec, START_SPEED, Table};
use crate::model::Drive;

/// Append the drive's variables to `t`.
pub(super) fn add(t: &mut Table) {
    let model = t.model;
    for (k, b) in model.bearings.iter().enumerate() {
        let group = if b.kind.is_rub() {
            "rubs"
        } else if b.kind.is_bearing() {
            "bearings"
        } else {
            continue;
        };
        let specs: Vec<OutputSpec> = vec![(
            "power_loss",
            format!(
                "Power dissipated in {} {}: film shear times the journal's speed plus contact friction mu*N*|v_slip|",
                &group[..group.len() - 1],
                b.name
            ),
            Some("W"),
            None,
            Binding::BearingPowerLoss(k),
        )];
        t.outputs(group, &b.name, specs);
    }
    for (k, th) in model.thrust_bearings.iter().enumerate() {
        let node = th.node + 1;
        let specs: Vec<OutputSpec> = vec![
            (
                "friction_torque",
                format!(
                    "Friction torque of thrust bearing {} (node {node}) on the shaft, opposing the spin (at standstill the breakaway torque)",
                    th.name
                ),
                Some("N.m"),
                None,
                Binding::ThrustFriction(k),
            ),
            (
                "power_loss",
                format!("Power dissipated in thrust bearing {}", th.name),
                Some("W"),
                None,
                Binding::ThrustPowerLoss(k),
            ),
        ];
        t.outputs("thrust_bearings", &th.name, specs);
    }
    t.push(
        "power_loss".into(),
        "Sum of the power dissipated in the bearings, rubs, seals and thrust bearings (for a plant's efficiency and oil-cooler balance)".into(),
        Real,
        Output,
        Continuous,
        Some("W"),
        None,
        None,
        Binding::PowerLoss,
    );
    if model.drive != Drive::Torque {
        return;
    }
    t.push(
        "shaft.initial_speed".into(),
        "Spin speed of the torque-driven shaft at the start (every node); from there the torque inputs drive it".into(),
        Real,
        Parameter,
        Fixed,
        Some("rad/s"),
        Some("rpm"),
        Some(START_SPEED),
        Binding::InitialSpeed,
    );
    let first = model.first_torque_input();
    for (k, tq) in model.torques.iter().enumerate() {
        t.push(
            format!("torques.{}", tq.name),
            format!(
                "Torque applied to the shaft about +z at node {} (a turbine's positive, a generator's air-gap torque negative)",
                tq.node + 1
            ),
            Real,
            Input,
            Continuous,
            Some("N.m"),
            None,
            Some(0.0),
            Binding::Load(first + k),
        );
    }
    for (k, tq) in model.torques.iter().enumerate() {
        let node = tq.node + 1;
        let specs: Vec<OutputSpec> = vec![
            (
                "speed",
                format!(
                    "Rotational speed of the shaft at torque node {} (node {node})",
                    tq.name
                ),
                Some("rad/s"),
                Some("rpm"),
                Binding::TorqueSpeed(k),
            ),
            (
                "angle",
                format!(
                    "Rotation angle of the shaft at torque node {} (node {node}), its integral",
                    tq.name
                ),
                Some("rad"),
                None,
                Binding::TorqueAngle(k),
            ),
        ];
        t.outputs("torques", &tq.name, specs);
    }
    for k in 0..model.elements.len() {
        t.push(
            format!("shaft.torque[{}]", k + 1),
            format!(
                "Torque carried by shaft element {} (nodes {} to {}): stiffness times twist plus damping times twist rate",
                k + 1,
                k + 1,
                k + 2
            ),
            Real,
            Output,
            Continuous,
            Some("N.m"),
            None,
            None,
            Binding::ShaftTorque(k),
        );
    }
}
