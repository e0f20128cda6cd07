//! `[[point_masses]]`: non-rotating lumped masses at nodes (coupling hubs,
//! housings, collars), the same in `x` and `y` (`mass`) or not (`mx`, `my`).

use crate::model::context::{Ctx, Names, default_name};
use crate::model::error::FieldPath;
use crate::model::file::PointMassEntry;
use crate::model::limits::SUPPORT_MASS;
use crate::model::{ModelError, PointMass};

/// Check each point mass: unique name, node, and either `mass` or both `mx`
/// and `my` (kg, > 0).
pub(super) fn point_masses(
    ctx: &Ctx,
    root: &FieldPath,
    entries: Vec<PointMassEntry>,
    node_z: &[f64],
) -> Result<Vec<PointMass>, ModelError> {
    let mut list = Vec::new();
    let mut names = Names::default();
    for (i, e) in entries.into_iter().enumerate() {
        let p = root.key("point_masses").index(i);
        let node = ctx.location(&p, e.node, e.z, node_z)?;
        let mass = match (e.mass, e.mx, e.my) {
            (Some(m), None, None) => {
                let m = ctx.within(p.key("mass"), m, &SUPPORT_MASS)?;
                [m, m]
            }
            (None, Some(mx), Some(my)) => [
                ctx.within(p.key("mx"), mx, &SUPPORT_MASS)?,
                ctx.within(p.key("my"), my, &SUPPORT_MASS)?,
            ],
            _ => {
                return Err(ctx.err(
                    p.clone(),
                    "mass / mx / my",
                    "give either mass, or both mx and my",
                ));
            }
        };
        list.push(PointMass {
            name: names.claim(ctx, &p, default_name(e.name, "point_mass", i), "point mass")?,
            node,
            mass,
        });
    }
    Ok(list)
}
