//! Loads and observation points: `[[unbalance]]` planes, `[[forces]]`,
//! `[[ports]]`, `[[probes]]` and the `gravity` vector.

use crate::model::context::{Ctx, Names, default_name};
use crate::model::error::FieldPath;
use crate::model::file::{ForceEntry, PortEntry, ProbeEntry, UnbalanceEntry};
use crate::model::limits::{GRAVITY, UNBALANCE};
use crate::model::{
    ExternalForce, ForceKind, HarmonicDirection, HarmonicFrequency, ModelError, PlacedBearing,
    Port, Probe, UnbalancePlane,
};

/// Check each unbalance plane: unique name, node, `m·e ≥ 0` (kg·m), finite
/// phase (° → rad).
pub(super) fn unbalances(
    ctx: &Ctx,
    root: &FieldPath,
    entries: Vec<UnbalanceEntry>,
    node_z: &[f64],
) -> Result<Vec<UnbalancePlane>, ModelError> {
    let mut unbalances = Vec::new();
    let mut names = Names::default();
    for (i, u) in entries.into_iter().enumerate() {
        let p = root.key("unbalance").index(i);
        let node = ctx.location(&p, u.node, u.z, node_z)?;
        let magnitude = ctx.within(p.key("magnitude"), u.magnitude, &UNBALANCE)?;
        let phase = ctx.finite(p.key("phase_deg"), u.phase_deg)?.to_radians();
        unbalances.push(UnbalancePlane {
            name: names.claim(ctx, &p, default_name(u.name, "unbalance", i), "unbalance")?,
            node,
            magnitude,
            phase,
        });
    }

    Ok(unbalances)
}

/// Check each probe: unique name and node.
pub(super) fn probes(
    ctx: &Ctx,
    root: &FieldPath,
    entries: Vec<ProbeEntry>,
    node_z: &[f64],
    bearings: &[PlacedBearing],
) -> Result<Vec<Probe>, ModelError> {
    let mut probes = Vec::new();
    let mut names = Names::default();
    for (i, pr) in entries.into_iter().enumerate() {
        let p = root.key("probes").index(i);
        let name = names.claim(ctx, &p, pr.name, "probe")?;
        let node = ctx.location(&p, pr.node, pr.z, node_z)?;
        let relative_to = match &pr.relative_to {
            None => None,
            Some(b) => Some(
                bearings
                    .iter()
                    .position(|placed| &placed.name == b && placed.kind.is_bearing())
                    .ok_or_else(|| {
                        let known: Vec<&str> = bearings
                            .iter()
                            .filter(|placed| placed.kind.is_bearing())
                            .map(|placed| placed.name.as_str())
                            .collect();
                        ctx.err(
                            p.key("relative_to"),
                            format!("{b:?}"),
                            &format!(
                                "is not a bearing of the model (its bearings: {})",
                                known.join(", ")
                            ),
                        )
                    })?,
            ),
        };
        probes.push(Probe {
            name,
            node,
            relative_to,
        });
    }
    Ok(probes)
}

/// The gravity vector (m/s², `z` along the shaft), zero when not given.
pub(super) fn gravity(
    ctx: &Ctx,
    root: &FieldPath,
    given: Option<[f64; 3]>,
) -> Result<[f64; 3], ModelError> {
    let gravity = given.unwrap_or([0.0; 3]);
    for (k, g) in gravity.iter().enumerate() {
        ctx.within(root.key("gravity").index(k), *g, &GRAVITY)?;
    }

    Ok(gravity)
}

/// Check each external force: unique name, node, and either a static force
/// (`fx` and/or `fy`, N) or a harmonic one (`magnitude` ≥ 0, N; `ratio` to
/// the running speed or `frequency_hz` ≥ 0; `direction` forward, backward
/// or fixed with `angle_deg`; `phase_deg`).
pub(super) fn forces(
    ctx: &Ctx,
    root: &FieldPath,
    entries: Vec<ForceEntry>,
    node_z: &[f64],
) -> Result<Vec<ExternalForce>, ModelError> {
    let mut out = Vec::new();
    let mut names = Names::default();
    for (i, f) in entries.into_iter().enumerate() {
        let p = root.key("forces").index(i);
        let node = ctx.location(&p, f.node, f.z, node_z)?;
        let is_static = f.fx.is_some() || f.fy.is_some();
        let harmonic_keys = [
            ("magnitude", f.magnitude.is_some()),
            ("phase_deg", f.phase_deg.is_some()),
            ("ratio", f.ratio.is_some()),
            ("frequency_hz", f.frequency_hz.is_some()),
            ("direction", f.direction.is_some()),
            ("angle_deg", f.angle_deg.is_some()),
        ];
        let kind = if is_static {
            if let Some((key, _)) = harmonic_keys.iter().find(|(_, given)| *given) {
                return Err(ctx.err(
                    p.key(key),
                    "(given)",
                    "a force is static (fx, fy) or harmonic (magnitude …), not both: give two entries",
                ));
            }
            ForceKind::Static([
                ctx.finite(p.key("fx"), f.fx.unwrap_or(0.0))?,
                ctx.finite(p.key("fy"), f.fy.unwrap_or(0.0))?,
            ])
        } else {
            let magnitude = match f.magnitude {
                Some(m) => ctx.non_negative(p.key("magnitude"), m)?,
                None => {
                    return Err(ctx.err(
                        p.clone(),
                        "(no force)",
                        "give fx and/or fy (a static force) or magnitude (a harmonic force)",
                    ));
                }
            };
            let frequency = match (f.ratio, f.frequency_hz) {
                (Some(r), None) => HarmonicFrequency::Ratio(ctx.finite(p.key("ratio"), r)?),
                (None, Some(hz)) => HarmonicFrequency::Fixed(
                    ctx.non_negative(p.key("frequency_hz"), hz)? * std::f64::consts::TAU,
                ),
                _ => {
                    return Err(ctx.err(
                        p.clone(),
                        "ratio / frequency_hz",
                        "a harmonic force needs either ratio (to the running speed) or frequency_hz",
                    ));
                }
            };
            let direction = match f.direction.as_deref().unwrap_or("forward") {
                "forward" | "backward" if f.angle_deg.is_some() => {
                    return Err(ctx.err(
                        p.key("angle_deg"),
                        f.angle_deg.unwrap_or_default(),
                        "only a fixed-direction force has a line of action angle",
                    ));
                }
                "forward" => HarmonicDirection::Forward,
                "backward" => HarmonicDirection::Backward,
                "fixed" => HarmonicDirection::Fixed(
                    ctx.finite(p.key("angle_deg"), f.angle_deg.unwrap_or(0.0))?
                        .to_radians(),
                ),
                other => {
                    return Err(ctx.err(
                        p.key("direction"),
                        format!("{other:?}"),
                        "must be \"forward\", \"backward\" or \"fixed\"",
                    ));
                }
            };
            ForceKind::Harmonic {
                magnitude,
                phase: ctx
                    .finite(p.key("phase_deg"), f.phase_deg.unwrap_or(0.0))?
                    .to_radians(),
                frequency,
                direction,
            }
        };
        out.push(ExternalForce {
            name: names.claim(ctx, &p, default_name(f.name, "force", i), "force")?,
            node,
            kind,
        });
    }
    Ok(out)
}

/// Check each port: unique name and node.
pub(super) fn ports(
    ctx: &Ctx,
    root: &FieldPath,
    entries: Vec<PortEntry>,
    node_z: &[f64],
) -> Result<Vec<Port>, ModelError> {
    let mut out = Vec::new();
    let mut names = Names::default();
    for (i, e) in entries.into_iter().enumerate() {
        let p = root.key("ports").index(i);
        let name = names.claim(ctx, &p, e.name, "port")?;
        let node = ctx.location(&p, e.node, e.z, node_z)?;
        out.push(Port { name, node });
    }
    Ok(out)
}

/// Every force of `model` within the range the FMU declares for its inputs,
/// `±` [`RotorModel::input_force_bound`](crate::model::RotorModel::input_force_bound)
/// (a thousand times the rotor's weight): a larger one is a unit slip.
pub(super) fn check_force_bounds(
    ctx: &Ctx,
    root: &FieldPath,
    model: &crate::model::RotorModel,
) -> Result<(), ModelError> {
    let bound = model.input_force_bound();
    for (i, f) in model.forces.iter().enumerate() {
        let p = root.key("forces").index(i);
        let values: Vec<(&str, f64)> = match f.kind {
            ForceKind::Static([fx, fy]) => vec![("fx", fx), ("fy", fy)],
            ForceKind::Harmonic { magnitude, .. } => vec![("magnitude", magnitude)],
        };
        for (key, v) in values {
            if v.abs() > bound {
                return Err(ctx.err(
                    p.key(key),
                    v,
                    &format!(
                        "exceeds {bound:.4e} N, the force that would accelerate the whole rotor ({:.4e} kg) at 1000 g: no machine carries it (a unit slip?)",
                        model.total_mass()
                    ),
                ));
            }
        }
    }
    Ok(())
}
