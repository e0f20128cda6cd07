//! Displacements no machine can have: a journal a whole clearance beyond its
//! bore (twice its radial clearance from the bearing centre), or, where no
//! clearance is modelled (linear and table bearings, probes, ports), a node
//! displaced by more than the shaft's own outer diameter there. The FMU
//! returns fmi2Warning with this text at every step that ends so, and the
//! CLI prints it: a force, port or torque input that large is a unit or sign
//! slip, never a machine's motion.

use crate::model::RotorModel;

use super::outputs::Outputs;

/// The largest outer diameter (m) of the shaft elements at `node`.
fn shaft_diameter_at(model: &RotorModel, node: usize) -> f64 {
    model
        .elements
        .iter()
        .filter(|e| e.node == node || e.node + 1 == node)
        .map(|e| e.element.section.outer_diameter)
        .fold(0.0, f64::max)
}

/// The first displacement of `outputs` that no machine can have, with what
/// bounds it and how many others exceed theirs; `None` when all are plausible.
pub fn implausible_displacement(model: &RotorModel, outputs: &Outputs) -> Option<String> {
    let mut found: Vec<String> = Vec::new();
    let mut check = |what: String, r: f64, limit: f64, why: &str| {
        if r > limit || r.is_nan() {
            found.push(format!(
                "{what} is {r:.3e} m from its centre, beyond {limit:.3e} m ({why})"
            ));
        }
    };
    for (b, out) in model.bearings.iter().zip(&outputs.bearings) {
        let (x, y) = out.relative();
        let r = x.hypot(y);
        match b.kind.journal_clearance() {
            Some(c) => check(
                format!("the journal of {}", b.name),
                r,
                2.0 * c,
                "twice its radial clearance",
            ),
            None => check(
                format!("the journal of {}", b.name),
                r,
                shaft_diameter_at(model, b.node),
                "the shaft's outer diameter there",
            ),
        }
    }
    for (p, out) in model.probes.iter().zip(&outputs.probes) {
        check(
            format!("probe {}", p.name),
            out.x.hypot(out.y),
            shaft_diameter_at(model, p.node),
            "the shaft's outer diameter there",
        );
    }
    for (p, out) in model.ports.iter().zip(&outputs.ports) {
        check(
            format!("port {}", p.name),
            out.x.hypot(out.y),
            shaft_diameter_at(model, p.node),
            "the shaft's outer diameter there",
        );
    }
    let first = found.first()?;
    let more = match found.len() - 1 {
        0 => String::new(),
        n => format!(" ({n} more displacements beyond their bounds)"),
    };
    Some(format!(
        "at t = {} s {first}{more}: no machine moves so; check the force, port and torque inputs (units, signs)",
        outputs.time
    ))
}
