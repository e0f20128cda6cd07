//! `[[materials]]`: elastic constants and density, looked up by name from the
//! shaft and disk sections.

use crate::fe::section::Material;

use crate::model::ModelError;
use crate::model::context::Ctx;
use crate::model::error::FieldPath;
use crate::model::file::MaterialEntry;
use crate::model::limits::{DENSITY, MODULUS};

/// The checked materials of a model, in file order.
pub(super) struct Materials(Vec<Material>);

impl Materials {
    /// The material called `name`, or an error at `path` listing the defined ones.
    pub(super) fn find(
        &self,
        ctx: &Ctx,
        path: FieldPath,
        name: &str,
    ) -> Result<Material, ModelError> {
        self.0
            .iter()
            .find(|m| m.name == name)
            .cloned()
            .ok_or_else(|| {
                let known: Vec<&str> = self.0.iter().map(|m| m.name.as_str()).collect();
                ctx.err(
                    path,
                    format!("{name:?}"),
                    &format!("unknown material (defined: {known:?})"),
                )
            })
    }
}

/// Check each material: unique name, `E > 0`, `ρ > 0` and exactly one of `G` or
/// `ν`, with Poisson's ratio `ν = E/(2G) − 1` in (−1, 0.5).
pub(super) fn materials(
    ctx: &Ctx,
    root: &FieldPath,
    entries: &[MaterialEntry],
) -> Result<Materials, ModelError> {
    let mut materials: Vec<Material> = Vec::new();
    for (i, m) in entries.iter().enumerate() {
        let p = root.key("materials").index(i);
        if materials.iter().any(|x| x.name == m.name) {
            return Err(ctx.err(p.key("name"), &m.name, "duplicate material name"));
        }
        let youngs_modulus = ctx.within(p.key("youngs_modulus"), m.youngs_modulus, &MODULUS)?;
        let density = ctx.within(p.key("density"), m.density, &DENSITY)?;
        let shear_modulus = match (m.shear_modulus, m.poisson_ratio) {
            (Some(g), None) => {
                let g = ctx.within(p.key("shear_modulus"), g, &MODULUS)?;
                let nu = youngs_modulus / (2.0 * g) - 1.0;
                if !(-1.0..0.5).contains(&nu) {
                    return Err(ctx.err(
                        p.key("shear_modulus"),
                        g,
                        &format!("gives Poisson's ratio E/(2G) − 1 = {nu:.4}, outside (−1, 0.5)"),
                    ));
                }
                g
            }
            (None, Some(nu)) => {
                if !(nu > -1.0 && nu < 0.5) {
                    return Err(ctx.err(p.key("poisson_ratio"), nu, "must lie in (−1, 0.5)"));
                }
                youngs_modulus / (2.0 * (1.0 + nu))
            }
            (Some(g), Some(_)) => {
                return Err(ctx.err(
                    p.key("shear_modulus"),
                    g,
                    "give shear_modulus or poisson_ratio, not both",
                ));
            }
            (None, None) => {
                return Err(ctx.err(p.clone(), &m.name, "needs shear_modulus or poisson_ratio"));
            }
        };
        materials.push(Material {
            name: m.name.clone(),
            youngs_modulus,
            shear_modulus,
            density,
        });
    }
    Ok(Materials(materials))
}
