//! Where an entry sits: the centre offset of a bearing, stator or pedestal
//! and the shaft's radius at a node.

use crate::model::context::Ctx;
use crate::model::error::FieldPath;
use crate::model::limits::OFFSET;
use crate::model::{ModelError, PlacedElement};

/// The centre offset `(offset_x, offset_y)` (m) of a bearing, seal, stator
/// or pedestal entry at `p`: each finite and within [`OFFSET`], default 0.
pub(super) fn centre_offset(
    ctx: &Ctx,
    p: &FieldPath,
    (x, y): (Option<f64>, Option<f64>),
) -> Result<[f64; 2], ModelError> {
    Ok([
        ctx.within(p.key("offset_x"), x.unwrap_or(0.0), &OFFSET)?,
        ctx.within(p.key("offset_y"), y.unwrap_or(0.0), &OFFSET)?,
    ])
}

/// The shaft's outer radius at `node`: the larger of its elements'.
pub(super) fn shaft_radius_at(elements: &[PlacedElement], node: usize) -> f64 {
    elements
        .iter()
        .filter(|e| e.node == node || e.node + 1 == node)
        .map(|e| 0.5 * e.element.section.outer_diameter)
        .fold(0.0, f64::max)
}
