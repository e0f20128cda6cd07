//! Loads and observation points: `[[unbalance]]` planes, `[[probes]]` and the
//! `gravity` vector.

use crate::model::context::{Ctx, Names, default_name};
use crate::model::error::FieldPath;
use crate::model::file::{ProbeEntry, UnbalanceEntry};
use crate::model::limits::{GRAVITY, UNBALANCE};
use crate::model::{ModelError, Probe, UnbalancePlane};

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
) -> Result<Vec<Probe>, ModelError> {
    let mut probes = Vec::new();
    let mut names = Names::default();
    for (i, pr) in entries.into_iter().enumerate() {
        let p = root.key("probes").index(i);
        let name = names.claim(ctx, &p, pr.name, "probe")?;
        let node = ctx.location(&p, pr.node, pr.z, node_z)?;
        probes.push(Probe { name, node });
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
