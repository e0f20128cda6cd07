//! `[[supports]]`: ideal constraints (boundary conditions) on node DOFs.

use crate::model::context::Ctx;
use crate::model::error::FieldPath;
use crate::model::file::SupportEntry;
use crate::model::{ModelError, Support};

/// Check each support: node and the DOF names in `fix` (`x`, `y`, `rx`, `ry`,
/// `pinned` = x, y; `clamped` = all four; `rz`, the twist, for the torsional
/// analyses).
pub(super) fn supports(
    ctx: &Ctx,
    root: &FieldPath,
    entries: Vec<SupportEntry>,
    node_z: &[f64],
) -> Result<Vec<Support>, ModelError> {
    let mut supports = Vec::new();
    for (i, s) in entries.into_iter().enumerate() {
        let p = root.key("supports").index(i);
        let node = ctx.location(&p, s.node, s.z, node_z)?;
        let mut fixed = [false; 4];
        let mut twist = false;
        for (j, dof) in s.fix.iter().enumerate() {
            let set: &[usize] = match dof.as_str() {
                "rz" => {
                    twist = true;
                    &[]
                }
                "x" => &[0],
                "y" => &[1],
                "rx" => &[2],
                "ry" => &[3],
                "pinned" => &[0, 1],
                "clamped" => &[0, 1, 2, 3],
                _ => {
                    return Err(ctx.err(
                        p.key("fix").index(j),
                        format!("{dof:?}"),
                        "must be one of \"x\", \"y\", \"rx\", \"ry\", \"rz\", \"pinned\", \"clamped\"",
                    ));
                }
            };
            for &k in set {
                fixed[k] = true;
            }
        }
        supports.push(Support { node, fixed, twist });
    }

    Ok(supports)
}
