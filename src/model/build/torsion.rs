//! The torsional chain's parts: `[[torques]]` (where the plant applies torque), `[[thrust_bearings]]`
//! (their friction torque) and `[torsion] drive`.

use crate::bearing::thrust::ThrustBearing;
use crate::model::context::{Ctx, Names, default_name};
use crate::model::error::FieldPath;
use crate::model::file::{ThrustBearingEntry, TorqueEntry, TorsionEntry};
use crate::model::{Drive, ModelError, PlacedThrustBearing, TorqueNode};

/// Check each torque node: unique name and node.
pub(super) fn torques(
    ctx: &Ctx,
    root: &FieldPath,
    entries: Vec<TorqueEntry>,
    node_z: &[f64],
) -> Result<Vec<TorqueNode>, ModelError> {
    let mut out = Vec::new();
    let mut names = Names::default();
    for (i, e) in entries.into_iter().enumerate() {
        let p = root.key("torques").index(i);
        let name = names.claim(ctx, &p, e.name, "torque")?;
        out.push(TorqueNode {
            name,
            node: ctx.location(&p, e.node, e.z, node_z)?,
        });
    }
    Ok(out)
}

/// Check each thrust bearing; the load defaults to the weight along the
/// shaft axis, `weight` (N; 0 on a horizontal rotor, which the plausibility
/// warnings point out).
pub(super) fn thrust_bearings(
    ctx: &Ctx,
    root: &FieldPath,
    entries: Vec<ThrustBearingEntry>,
    node_z: &[f64],
    weight: f64,
) -> Result<Vec<PlacedThrustBearing>, ModelError> {
    let mut out = Vec::new();
    let mut names = Names::default();
    for (i, e) in entries.into_iter().enumerate() {
        let p = root.key("thrust_bearings").index(i);
        let node = ctx.location(&p, e.node, e.z, node_z)?;
        // Without a load the bearing carries the weight along the axis (none
        // on a horizontal rotor: a plausibility warning says so).
        let load = match e.load {
            Some(w) => ctx.non_negative(p.key("load"), w)?,
            None => weight,
        };
        let inner = ctx.non_negative(p.key("inner_radius"), e.inner_radius)?;
        let outer = ctx.positive(p.key("outer_radius"), e.outer_radius)?;
        if outer <= inner {
            return Err(ctx.err(
                p.key("outer_radius"),
                outer,
                &format!("must exceed inner_radius = {inner}"),
            ));
        }
        let coverage = e.pad_coverage.unwrap_or(0.8);
        if !(coverage > 0.0 && coverage <= 1.0) {
            return Err(ctx.err(p.key("pad_coverage"), coverage, "must lie in (0, 1]"));
        }
        let lift_rpm = ctx.positive(p.key("lift_off_rpm"), e.lift_off_rpm.unwrap_or(5.0))?;
        out.push(PlacedThrustBearing {
            name: names.claim(ctx, &p, default_name(e.name, "thrust", i), "thrust bearing")?,
            node,
            bearing: ThrustBearing {
                load,
                inner_radius: inner,
                outer_radius: outer,
                coverage,
                film_thickness: ctx.positive(p.key("film_thickness"), e.film_thickness)?,
                viscosity: ctx.positive(p.key("viscosity"), e.viscosity)?,
                boundary_friction: ctx.non_negative(
                    p.key("friction_coefficient"),
                    e.friction_coefficient.unwrap_or(0.15),
                )?,
                lift_off_speed: lift_rpm * std::f64::consts::PI / 30.0,
                oil_lift: e.oil_lift.unwrap_or(false),
            },
        });
    }
    Ok(out)
}

/// `[torsion] damping_ratio`: the modal damping ratio of the listed
/// torsional modes, in `[0, 1)` (1 is critical damping: no mode left).
pub(super) fn damping_ratio(
    ctx: &Ctx,
    root: &FieldPath,
    entry: Option<&TorsionEntry>,
) -> Result<f64, ModelError> {
    let Some(z) = entry.and_then(|e| e.damping_ratio) else {
        return Ok(0.0);
    };
    let z = ctx.non_negative(root.key("torsion").key("damping_ratio"), z)?;
    if z >= 1.0 {
        return Err(ctx.err(
            root.key("torsion").key("damping_ratio"),
            z,
            "must be less than 1 (a modal damping ratio of 1 or more leaves no oscillating mode)",
        ));
    }
    Ok(z)
}

/// The drive: `"speed"` (default) or `"torque"`, which needs `[[torques]]`.
pub(super) fn drive(
    ctx: &Ctx,
    root: &FieldPath,
    entry: Option<TorsionEntry>,
    torques: &[TorqueNode],
) -> Result<Drive, ModelError> {
    let given = entry.and_then(|e| e.drive);
    match given.as_deref().unwrap_or("speed") {
        "speed" => Ok(Drive::Speed),
        "torque" if torques.is_empty() => Err(ctx.err(
            root.key("torsion").key("drive"),
            "\"torque\"",
            "a torque-driven shaft needs [[torques]] nodes to apply the torques at",
        )),
        "torque" => Ok(Drive::Torque),
        other => Err(ctx.err(
            root.key("torsion").key("drive"),
            format!("{other:?}"),
            "must be \"speed\" or \"torque\"",
        )),
    }
}
