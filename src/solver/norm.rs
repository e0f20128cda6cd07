//! The solver's small numerics.

/// Largest absolute entry of `v` (0 when empty).
pub(crate) fn inf_norm(v: &[f64]) -> f64 {
    v.iter().fold(0.0, |a, x| a.max(x.abs()))
}
