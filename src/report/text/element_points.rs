//! The operating point of the elements that are not bearings, as `rotor
//! operating-point` prints it after the bearings (issue 48).

use std::fmt::Write;

use super::{element_kind, short};
use crate::analysis::element_operating_point::{
    ElementOperatingPoint, ForceOperatingPoint, ThrustOperatingPoint,
};
use crate::model::RotorModel;

/// One line per seal, rub and magnetic pull (its force on the rotor at the
/// equilibrium), thrust bearing (load, friction torque, power loss) and
/// external force (static, or its magnitude and frequency) at `rpm`.
pub fn element_points(
    rpm: f64,
    model: &RotorModel,
    (elements, thrusts, forces): (
        &[ElementOperatingPoint],
        &[ThrustOperatingPoint],
        &[ForceOperatingPoint],
    ),
) -> String {
    let mut s = String::new();
    for e in elements {
        let kind = element_kind(&model.bearings[e.element].kind);
        writeln!(
            s,
            "{kind} {} at {} rpm: force on the rotor {} N (Fx = {} N, Fy = {} N) at x = {} µm, y = {} µm from its centre",
            e.name,
            short(rpm),
            short(e.force[0].hypot(e.force[1])),
            short(e.force[0]),
            short(e.force[1]),
            short(e.displacement[0] * 1e6),
            short(e.displacement[1] * 1e6)
        )
        .ok();
    }
    for t in thrusts {
        writeln!(
            s,
            "thrust bearing {} at {} rpm: axial load {} N, friction torque {} N·m, power loss {} W",
            model.thrust_bearings[t.thrust].name,
            short(rpm),
            short(t.load),
            short(t.friction_torque),
            short(t.power_loss)
        )
        .ok();
    }
    for (f, point) in model.forces.iter().zip(forces) {
        let what = match point {
            ForceOperatingPoint::Static([fx, fy]) => format!(
                "static {} N (Fx = {} N, Fy = {} N)",
                short(fx.hypot(*fy)),
                short(*fx),
                short(*fy)
            ),
            ForceOperatingPoint::Harmonic {
                magnitude,
                frequency,
            } => format!(
                "harmonic {} N at {} Hz",
                short(*magnitude),
                short(frequency / std::f64::consts::TAU)
            ),
        };
        writeln!(
            s,
            "force {} at node {} at {} rpm: {what}",
            f.name,
            f.node + 1,
            short(rpm)
        )
        .ok();
    }
    s
}
