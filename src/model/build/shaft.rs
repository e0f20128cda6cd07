//! `[[shaft]]` sections: uniform tubes split into equal Timoshenko elements,
//! which also define the nodes (axial positions) everything else is placed on.

use crate::fe::section::CircularSection;
use crate::fe::shaft::{ShaftEffects, ShaftElement};

use super::materials::Materials;
use crate::model::context::Ctx;
use crate::model::error::FieldPath;
use crate::model::file::ModelFile;
use crate::model::limits::{AXIAL_FORCE, DIAMETER, LENGTH, POSITION};
use crate::model::{ModelError, PlacedElement};

/// The shaft: node positions (m, increasing) and elements in node order.
pub(super) struct Shaft {
    /// Axial position of every node (m).
    pub(super) node_z: Vec<f64>,
    /// Elements between consecutive nodes.
    pub(super) elements: Vec<PlacedElement>,
}

/// Check the shaft sections and the top-level keys that apply to them
/// (`shear_deformation`, `rotary_inertia`, `axial_force`, `start_z`).
pub(super) fn shaft(
    ctx: &Ctx,
    root: &FieldPath,
    raw: &ModelFile,
    materials: &Materials,
) -> Result<Shaft, ModelError> {
    let effects = ShaftEffects {
        shear_deformation: raw.shear_deformation.unwrap_or(true),
        rotary_inertia: raw.rotary_inertia.unwrap_or(true),
    };
    let default_axial = ctx.within(
        root.key("axial_force"),
        raw.axial_force.unwrap_or(0.0),
        &AXIAL_FORCE,
    )?;
    let start_z = ctx.within(root.key("start_z"), raw.start_z.unwrap_or(0.0), &POSITION)?;

    if raw.shaft.is_empty() {
        return Err(ctx.err(
            root.key("shaft"),
            "[]",
            "the model needs at least one [[shaft]] section",
        ));
    }
    let budget_mb = ctx.positive(
        root.key("memory_budget_mb"),
        raw.memory_budget_mb
            .unwrap_or(crate::model::DEFAULT_MEMORY_BUDGET_MB),
    )?;
    // Refuse a model too large for the budget before allocating anything for it.
    let mut total = 0usize;
    for (i, s) in raw.shaft.iter().enumerate() {
        let count = s.elements.unwrap_or(1);
        if !(1..=1_000_000).contains(&count) {
            let p = root.key("shaft").index(i);
            return Err(ctx.err(p.key("elements"), count, "must be from 1 to 1000000"));
        }
        total += count;
    }
    let dofs = 4.0 * (total as f64 + 1.0);
    let need_mb = dofs * crate::model::BYTES_PER_DOF / 1e6;
    if need_mb > budget_mb {
        return Err(ctx.err(
            root.key("shaft"),
            format!("{total} elements"),
            &format!(
                "would need about {need_mb:.0} MB ({dofs:.0} DOFs at {} bytes each), more than memory_budget_mb = {budget_mb}",
                crate::model::BYTES_PER_DOF
            ),
        ));
    }
    let mut node_z = Vec::with_capacity(total + 1);
    node_z.push(start_z);
    let mut elements = Vec::with_capacity(total);
    for (i, s) in raw.shaft.iter().enumerate() {
        let p = root.key("shaft").index(i);
        let length = ctx.within(p.key("length"), s.length, &LENGTH)?;
        let outer = ctx.within(p.key("outer_diameter"), s.outer_diameter, &DIAMETER)?;
        let inner = ctx.non_negative(p.key("inner_diameter"), s.inner_diameter)?;
        if inner >= outer {
            return Err(ctx.err(
                p.key("inner_diameter"),
                inner,
                &format!("must be smaller than outer_diameter = {outer}"),
            ));
        }
        let material = materials.find(ctx, p.key("material"), &s.material)?;
        let count = s.elements.unwrap_or(1);
        let axial_force = match s.axial_force {
            Some(f) => ctx.within(p.key("axial_force"), f, &AXIAL_FORCE)?,
            None => default_axial,
        };
        // Series dampers: `count` elements of `c · count` give the section's `c`.
        let torsional_damping = ctx.non_negative(
            p.key("torsional_damping"),
            s.torsional_damping.unwrap_or(0.0),
        )? * count as f64;
        let element = ShaftElement {
            length: length / count as f64,
            section: CircularSection {
                outer_diameter: outer,
                inner_diameter: inner,
            },
            material,
            effects,
        };
        let z0 = node_z[node_z.len() - 1];
        for k in 0..count {
            elements.push(PlacedElement {
                node: node_z.len() - 1,
                element: element.clone(),
                axial_force,
                torsional_damping,
            });
            node_z.push(z0 + length * (k + 1) as f64 / count as f64);
        }
    }
    Ok(Shaft { node_z, elements })
}
