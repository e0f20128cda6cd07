//! `[[pedestals]]`: bearing supports in series with bearings — a mass on a
//! spring–damper to ground or to another pedestal (a bracket on a
//! foundation) — and the lookup of the pedestal a bearing stands on.

use crate::model::context::{Ctx, Names};
use crate::model::error::FieldPath;
use crate::model::file::PedestalEntry;
use crate::model::limits::{DAMPING, STIFFNESS, SUPPORT_MASS};
use crate::model::{ModelError, Pedestal, PlacedBearing};

/// Check each pedestal: unique name, positive mass, positive direct
/// stiffness (it must hold its mass), non-negative direct damping, finite
/// cross terms, and `on` naming another pedestal with no loop in the chain.
pub(super) fn pedestals(
    ctx: &Ctx,
    root: &FieldPath,
    entries: &[PedestalEntry],
) -> Result<Vec<Pedestal>, ModelError> {
    let mut names = Names::default();
    let mut list = Vec::with_capacity(entries.len());
    for (i, e) in entries.iter().enumerate() {
        let p = root.key("pedestals").index(i);
        let name = names.claim(ctx, &p, e.name.clone(), "pedestal")?;
        let k = |key: &str, v: f64| ctx.within(p.key(key), v, &STIFFNESS);
        let c = |key: &str, v: f64| ctx.within(p.key(key), v, &DAMPING);
        let stiffness = [
            [
                ctx.positive(p.key("kxx"), k("kxx", e.kxx)?)?,
                k("kxy", e.kxy)?,
            ],
            [
                k("kyx", e.kyx)?,
                ctx.positive(p.key("kyy"), k("kyy", e.kyy)?)?,
            ],
        ];
        let damping = [
            [
                ctx.non_negative(p.key("cxx"), c("cxx", e.cxx)?)?,
                c("cxy", e.cxy)?,
            ],
            [
                c("cyx", e.cyx)?,
                ctx.non_negative(p.key("cyy"), c("cyy", e.cyy)?)?,
            ],
        ];
        list.push(Pedestal {
            name,
            mass: ctx.within(p.key("mass"), e.mass, &SUPPORT_MASS)?,
            stiffness,
            damping,
            on: None,
            offset: super::placement::centre_offset(ctx, &p, (e.offset_x, e.offset_y))?,
            on_stator: e.on_stator,
        });
    }
    for (i, e) in entries.iter().enumerate() {
        let Some(on) = &e.on else { continue };
        let path = root.key("pedestals").index(i).key("on");
        let target = lookup(ctx, &path, &list, on)?;
        if target == i {
            return Err(ctx.err(path, format!("{on:?}"), "a pedestal cannot stand on itself"));
        }
        list[i].on = Some(target);
    }
    // A chain longer than the list has a loop.
    for (i, e) in entries.iter().enumerate() {
        let mut at = list[i].on;
        let mut steps = 0;
        while let Some(p) = at {
            steps += 1;
            if steps > list.len() {
                return Err(ctx.err(
                    root.key("pedestals").index(i).key("on"),
                    format!("{:?}", e.on.as_deref().unwrap_or_default()),
                    "the pedestals stand on each other in a loop: one of them must stand on ground",
                ));
            }
            at = list[p].on;
        }
    }
    Ok(list)
}

/// The index of the pedestal named `name`, or an error at `path`.
pub(super) fn lookup(
    ctx: &Ctx,
    path: &FieldPath,
    pedestals: &[Pedestal],
    name: &str,
) -> Result<usize, ModelError> {
    pedestals
        .iter()
        .position(|p| p.name == name)
        .ok_or_else(|| {
            let known: Vec<&str> = pedestals.iter().map(|p| p.name.as_str()).collect();
            ctx.err(
                path.clone(),
                format!("{name:?}"),
                &if known.is_empty() {
                    "no [[pedestals]] entry has this name (the model defines none)".to_string()
                } else {
                    format!("no pedestal has this name (defined: {})", known.join(", "))
                },
            )
        })
}

/// Every pedestal must carry a bearing, rub, seal or pull stator, directly or through the pedestals
/// standing on it: one that carries nothing is a mass on a spring that no
/// force reaches, almost certainly a misspelt or forgotten `pedestal` key.
pub(super) fn check_carried(
    ctx: &Ctx,
    root: &FieldPath,
    pedestals: &[Pedestal],
    bearings: &[PlacedBearing],
) -> Result<(), ModelError> {
    let mut carries = vec![false; pedestals.len()];
    for b in bearings {
        let mut at = b.pedestal;
        while let Some(p) = at {
            carries[p] = true;
            at = pedestals[p].on;
        }
    }
    match carries.iter().position(|c| !c) {
        None => Ok(()),
        Some(i) => Err(ctx.err(
            root.key("pedestals").index(i).key("name"),
            format!("{:?}", pedestals[i].name),
            "no bearing, rub, seal or magnetic pull stands on this pedestal (give it as pedestal = \"<name>\" in their entries)",
        )),
    }
}
