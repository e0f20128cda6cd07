//! `[[disks]]`: rigid disks on nodes, given by mass and inertias or by
//! geometry and material.

use crate::fe::disk::Disk;

use super::materials::Materials;
use crate::model::context::{Ctx, Names, default_name};
use crate::model::error::FieldPath;
use crate::model::file::DiskEntry;
use crate::model::impeller_stage::{DEFAULT_DENSITY_RATIO, DEFAULT_STAGE_FACTOR, ImpellerStage};
use crate::model::limits::{
    DENSITY_RATIO, DIAMETER, INERTIA, LENGTH, MASS, STAGE_FACTOR, STAGE_POWER,
};
use crate::model::{ModelError, PlacedDisk};

/// Check each disk: unique name, its node, and either `mass`, `polar_inertia`,
/// `diametral_inertia` (kg > 0, kg·m² ≥ 0: zero inertias make a point mass
/// that spins with the rotor) or `material`, `outer_diameter`,
/// `inner_diameter`, `width` (m) — not a mix; `role` `"impeller"` or
/// `"other"`.
pub(super) fn disks(
    ctx: &Ctx,
    root: &FieldPath,
    entries: Vec<DiskEntry>,
    node_z: &[f64],
    materials: &Materials,
) -> Result<Vec<PlacedDisk>, ModelError> {
    let mut disks = Vec::new();
    let mut names = Names::default();
    for (i, d) in entries.into_iter().enumerate() {
        let p = root.key("disks").index(i);
        let node = ctx.location(&p, d.node, d.z, node_z)?;
        let by_inertia =
            d.mass.is_some() || d.polar_inertia.is_some() || d.diametral_inertia.is_some();
        let by_geometry = d.material.is_some()
            || d.outer_diameter.is_some()
            || d.inner_diameter.is_some()
            || d.width.is_some();
        let disk = match (by_inertia, by_geometry) {
            (true, false) => {
                let need = |key: &'static str, v: Option<f64>| {
                    v.ok_or_else(|| {
                        ctx.err(
                            p.key(key),
                            "(missing)",
                            "needed with mass-and-inertia disks",
                        )
                    })
                };
                let mass = ctx.within(p.key("mass"), need("mass", d.mass)?, &MASS)?;
                // Zero inertias make a point mass on the rotor (no gyroscopic
                // effect); others lie in the physical range.
                let inertia = |key: &'static str, v: Option<f64>| {
                    let v = ctx.non_negative(p.key(key), need(key, v)?)?;
                    if v == 0.0 {
                        Ok(0.0)
                    } else {
                        ctx.within(p.key(key), v, &INERTIA)
                    }
                };
                let polar_inertia = inertia("polar_inertia", d.polar_inertia)?;
                let diametral_inertia = inertia("diametral_inertia", d.diametral_inertia)?;
                Disk {
                    mass,
                    polar_inertia,
                    diametral_inertia,
                }
            }
            (false, true) => {
                let material = match &d.material {
                    Some(name) => materials.find(ctx, p.key("material"), name)?,
                    None => {
                        return Err(ctx.err(
                            p.key("material"),
                            "(missing)",
                            "needed with disk geometry",
                        ));
                    }
                };
                let outer = match d.outer_diameter {
                    Some(v) => ctx.within(p.key("outer_diameter"), v, &DIAMETER)?,
                    None => {
                        return Err(ctx.err(
                            p.key("outer_diameter"),
                            "(missing)",
                            "needed with disk geometry",
                        ));
                    }
                };
                let inner =
                    ctx.non_negative(p.key("inner_diameter"), d.inner_diameter.unwrap_or(0.0))?;
                if inner >= outer {
                    return Err(ctx.err(
                        p.key("inner_diameter"),
                        inner,
                        &format!("must be smaller than outer_diameter = {outer}"),
                    ));
                }
                let width = match d.width {
                    Some(v) => ctx.within(p.key("width"), v, &LENGTH)?,
                    None => {
                        return Err(ctx.err(
                            p.key("width"),
                            "(missing)",
                            "needed with disk geometry",
                        ));
                    }
                };
                Disk::from_geometry(material.density, outer, inner, width)
            }
            (true, true) => {
                return Err(ctx.err(
                    p.clone(),
                    "mass/inertia and geometry",
                    "give either mass, polar_inertia, diametral_inertia or material, outer_diameter, inner_diameter, width — not both",
                ));
            }
            (false, false) => {
                return Err(ctx.err(
                    p.clone(),
                    "(empty)",
                    "give mass, polar_inertia, diametral_inertia or material, outer_diameter, inner_diameter, width",
                ));
            }
        };
        let impeller = match d.role.as_deref().unwrap_or("other") {
            "impeller" => true,
            "other" => false,
            other => {
                return Err(ctx.err(
                    p.key("role"),
                    format!("{other:?}"),
                    "must be \"impeller\" (a stage or runner) or \"other\"",
                ));
            }
        };
        let stage = stage(ctx, &p, &d, impeller)?;
        disks.push(PlacedDisk {
            name: names.claim(ctx, &p, default_name(d.name, "disk", i), "disk")?,
            node,
            disk,
            impeller,
            stage,
        });
    }

    Ok(disks)
}

/// An impeller's stage data: `stage_power`, `impeller_diameter` and
/// `flow_width` together (or none of them), with `density_ratio` (default
/// 1) and `stage_factor` (default 3); only on `role = "impeller"`.
fn stage(
    ctx: &Ctx,
    p: &FieldPath,
    d: &DiskEntry,
    impeller: bool,
) -> Result<Option<ImpellerStage>, ModelError> {
    let given = [
        ("stage_power", d.stage_power),
        ("impeller_diameter", d.impeller_diameter),
        ("flow_width", d.flow_width),
        ("density_ratio", d.density_ratio),
        ("stage_factor", d.stage_factor),
    ];
    let Some((first, Some(value))) = given.iter().find(|(_, v)| v.is_some()) else {
        return Ok(None);
    };
    if !impeller {
        return Err(ctx.err(
            p.key(first),
            value.to_string(),
            "stage data belong to an impeller: add role = \"impeller\"",
        ));
    }
    // A missing key is named at the entry (it has no line of its own).
    let need = |key: &'static str, v: Option<f64>| {
        v.ok_or_else(|| {
            ctx.err(
                p.clone(),
                format!("{key} missing"),
                "a stage needs stage_power, impeller_diameter and flow_width together",
            )
        })
    };
    Ok(Some(ImpellerStage {
        power: ctx.within(
            p.key("stage_power"),
            need("stage_power", d.stage_power)?,
            &STAGE_POWER,
        )?,
        diameter: ctx.within(
            p.key("impeller_diameter"),
            need("impeller_diameter", d.impeller_diameter)?,
            &DIAMETER,
        )?,
        width: ctx.within(
            p.key("flow_width"),
            need("flow_width", d.flow_width)?,
            &LENGTH,
        )?,
        density_ratio: ctx.within(
            p.key("density_ratio"),
            d.density_ratio.unwrap_or(DEFAULT_DENSITY_RATIO),
            &DENSITY_RATIO,
        )?,
        stage_factor: ctx.within(
            p.key("stage_factor"),
            d.stage_factor.unwrap_or(DEFAULT_STAGE_FACTOR),
            &STAGE_FACTOR,
        )?,
    }))
}
