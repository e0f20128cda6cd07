//! Displacements no machine can have: a journal a whole clearance beyond its
//! bore (twice its radial clearance from the bearing centre), or, where no
//! clearance is modelled (linear and table bearings, probes, ports), a node
//! displaced by more than the shaft's own outer diameter there. The FMU
//! returns fmi2Warning with this text at every step that ends so (the bounds
//! found once per instance, [`DisplacementLimits`]): a force, port or torque
//! input that large is a unit or sign slip, never a machine's motion.

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

/// The bound of each displacement of a model's outputs, found once (the
/// check runs after every FMU step: a pass over the outputs, no search of
/// the shaft).
#[derive(Debug, Clone, PartialEq)]
pub struct DisplacementLimits {
    /// Per bearing: its name, bound (m), what sets it, and its centre's
    /// offset off the axis (m; the bound is about the displaced centre).
    bearings: Vec<(String, f64, &'static str, [f64; 2])>,
    /// Per probe, then per port: name and bound (m).
    probes: Vec<(String, f64)>,
    ports: Vec<(String, f64)>,
}

const DIAMETER: &str = "the shaft's outer diameter there";

impl DisplacementLimits {
    /// The bounds of `model`'s journals, probes and ports.
    pub fn new(model: &RotorModel) -> Self {
        let bearings = model
            .bearings
            .iter()
            .map(|b| match b.kind.journal_clearance() {
                Some(c) => (
                    b.name.clone(),
                    2.0 * c,
                    "twice its radial clearance",
                    b.offset,
                ),
                None => (
                    b.name.clone(),
                    shaft_diameter_at(model, b.node),
                    DIAMETER,
                    b.offset,
                ),
            })
            .collect();
        let at = |name: &str, node: usize| (name.to_string(), shaft_diameter_at(model, node));
        Self {
            bearings,
            probes: model.probes.iter().map(|p| at(&p.name, p.node)).collect(),
            ports: model.ports.iter().map(|p| at(&p.name, p.node)).collect(),
        }
    }

    /// The first displacement of `outputs` that no machine can have, with
    /// what bounds it and how many others exceed theirs; `None` when all are
    /// plausible.
    pub fn check(&self, outputs: &Outputs) -> Option<String> {
        let mut found: Vec<String> = Vec::new();
        let mut check = |what: String, r: f64, limit: f64, why: &str| {
            if r > limit || r.is_nan() {
                found.push(format!(
                    "{what} is {r:.3e} m from its centre, beyond {limit:.3e} m ({why})"
                ));
            }
        };
        for ((name, limit, why, o), out) in self.bearings.iter().zip(&outputs.bearings) {
            let (x, y) = out.relative();
            let (x, y) = (x - o[0], y - o[1]);
            check(format!("the journal of {name}"), x.hypot(y), *limit, why);
        }
        for ((name, limit), out) in self.probes.iter().zip(&outputs.probes) {
            check(
                format!("probe {name}"),
                out.x.hypot(out.y),
                *limit,
                DIAMETER,
            );
        }
        for ((name, limit), out) in self.ports.iter().zip(&outputs.ports) {
            check(format!("port {name}"), out.x.hypot(out.y), *limit, DIAMETER);
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
}
