//! `[[couplings]]`: the couplings between the shafts of a train — their
//! torsional stiffness and damping in the torsional chain, and laterally a
//! rigid flange or a flexible coupling with its misalignment.

use crate::model::context::{Ctx, Names, default_name};
use crate::model::error::FieldPath;
use crate::model::file::CouplingEntry;
use crate::model::limits::{
    ANGULAR_OFFSET, COUPLING_ANGULAR_STIFFNESS, COUPLING_LATERAL_STIFFNESS, OFFSET,
    TORSIONAL_STIFFNESS,
};
use crate::model::{Coupling, CouplingJoint, ModelError, PlacedElement};

/// Check each coupling: its node starts a shaft element (one coupling per
/// element); torsional stiffness within its range, damping ≥ 0; a flexible
/// coupling has both its lateral and angular stiffness, a rigid flange no
/// damping; misalignments within their ranges; a coupling does something.
pub(super) fn couplings(
    ctx: &Ctx,
    root: &FieldPath,
    entries: Vec<CouplingEntry>,
    node_z: &[f64],
    elements: &[PlacedElement],
) -> Result<Vec<Coupling>, ModelError> {
    let mut out: Vec<Coupling> = Vec::new();
    let mut names = Names::default();
    for (i, e) in entries.into_iter().enumerate() {
        let p = root.key("couplings").index(i);
        let node = ctx.location(&p, e.node, e.z, node_z)?;
        let Some(element) = elements.iter().position(|el| el.node == node) else {
            return Err(ctx.err(
                p.key("node"),
                node + 1,
                "no shaft element starts at this node (a coupling joins a node to the next)",
            ));
        };
        if out.iter().any(|c| c.element == element) {
            return Err(ctx.err(
                p.key("node"),
                node + 1,
                "a coupling is already at this element",
            ));
        }
        let stiffness = match e.torsional_stiffness {
            Some(k) => Some(ctx.within(p.key("torsional_stiffness"), k, &TORSIONAL_STIFFNESS)?),
            None => None,
        };
        if stiffness.is_none()
            && let Some(c) = e.torsional_damping
        {
            return Err(ctx.err(
                p.key("torsional_damping"),
                c,
                "needs torsional_stiffness (without it the shaft element keeps its own torsion)",
            ));
        }
        let joint = joint(ctx, &p, &e)?;
        let misalignment = misalignment(ctx, &p, &e)?;
        if stiffness.is_none() && joint == CouplingJoint::Flange && misalignment == [0.0; 4] {
            return Err(ctx.err(
                p.key("torsional_stiffness"),
                "none",
                "a coupling needs torsional_stiffness, lateral_stiffness and angular_stiffness \
                 (a flexible coupling), or a misalignment (a rigid flange set off): an aligned \
                 rigid flange is the shaft itself",
            ));
        }
        out.push(Coupling {
            name: names.claim(ctx, &p, default_name(e.name, "coupling", i), "coupling")?,
            element,
            stiffness,
            damping: ctx.non_negative(
                p.key("torsional_damping"),
                e.torsional_damping.unwrap_or(0.0),
            )?,
            joint,
            misalignment,
        });
    }
    Ok(out)
}

/// The lateral joint: flexible with both `lateral_stiffness` and
/// `angular_stiffness` (dampings default 0), else a rigid flange, which
/// takes no damping.
fn joint(ctx: &Ctx, p: &FieldPath, e: &CouplingEntry) -> Result<CouplingJoint, ModelError> {
    match (e.lateral_stiffness, e.angular_stiffness) {
        (Some(kl), Some(ka)) => Ok(CouplingJoint::Flexible {
            lateral: [
                ctx.within(p.key("lateral_stiffness"), kl, &COUPLING_LATERAL_STIFFNESS)?,
                ctx.non_negative(p.key("lateral_damping"), e.lateral_damping.unwrap_or(0.0))?,
            ],
            angular: [
                ctx.within(p.key("angular_stiffness"), ka, &COUPLING_ANGULAR_STIFFNESS)?,
                ctx.non_negative(p.key("angular_damping"), e.angular_damping.unwrap_or(0.0))?,
            ],
        }),
        (Some(k), None) => Err(ctx.err(
            p.key("lateral_stiffness"),
            k,
            "a flexible coupling needs angular_stiffness too",
        )),
        (None, Some(k)) => Err(ctx.err(
            p.key("angular_stiffness"),
            k,
            "a flexible coupling needs lateral_stiffness too",
        )),
        (None, None) => {
            for (key, v) in [
                ("lateral_damping", e.lateral_damping),
                ("angular_damping", e.angular_damping),
            ] {
                if let Some(c) = v {
                    return Err(ctx.err(
                        p.key(key),
                        c,
                        "a rigid flange has no damping: give lateral_stiffness and \
                         angular_stiffness for a flexible coupling",
                    ));
                }
            }
            Ok(CouplingJoint::Flange)
        }
    }
}

/// `parallel_offset = [x, y]` (m) and `angular_offset = [dx/dz, dy/dz]`
/// (rad) on the DOFs `[x, y, θx, θy]`: `θx = −dy/dz`, `θy = dx/dz`.
fn misalignment(ctx: &Ctx, p: &FieldPath, e: &CouplingEntry) -> Result<[f64; 4], ModelError> {
    let parallel = e.parallel_offset.unwrap_or([0.0; 2]);
    let angular = e.angular_offset.unwrap_or([0.0; 2]);
    for k in 0..2 {
        ctx.within(p.key("parallel_offset").index(k), parallel[k], &OFFSET)?;
        ctx.within(
            p.key("angular_offset").index(k),
            angular[k],
            &ANGULAR_OFFSET,
        )?;
    }
    Ok([parallel[0], parallel[1], -angular[1], angular[0]])
}
