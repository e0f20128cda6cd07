//! The contact law of a fluid-film bearing or rub from its model-file keys,
//! and the rub's default contact width.

use crate::bearing::contact::ContactLaw;
use crate::model::ModelError;
use crate::model::context::Ctx;
use crate::model::error::FieldPath;
use crate::model::limits::{CONTACT_STIFFNESS, DAMPING};

/// Axial width (m) of a rub's contact for its default steel stiffness.
pub(super) const RUB_WIDTH: f64 = 0.01;

/// The contact law of a fluid-film bearing: `default` (the steel law of its
/// geometry) with the model file's `contact_stiffness` (N/m, > 0),
/// `contact_damping` (N·s/m, ≥ 0) and `friction_coefficient` (≥ 0) where given;
/// `None` when none is given.
pub(super) fn contact_law(
    ctx: &Ctx,
    p: &FieldPath,
    default: ContactLaw,
    [stiffness, damping, friction]: [Option<f64>; 3],
) -> Result<Option<ContactLaw>, ModelError> {
    if stiffness.is_none() && damping.is_none() && friction.is_none() {
        return Ok(None);
    }
    let mut law = default;
    if let Some(k) = stiffness {
        law.stiffness = ctx.within(p.key("contact_stiffness"), k, &CONTACT_STIFFNESS)?;
        law.damping = ContactLaw::DAMPING_TIME * law.stiffness;
    }
    if let Some(c) = damping {
        law.damping = ctx.non_negative(p.key("contact_damping"), c)?;
        ctx.within(p.key("contact_damping"), c, &DAMPING)?;
    }
    if let Some(mu) = friction {
        law.friction = ctx.non_negative(p.key("friction_coefficient"), mu)?;
    }
    Ok(Some(law))
}
