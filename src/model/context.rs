//! What every section of a model file is checked with: the source text (for
//! line numbers), range checks that name the field path and value, and the
//! lookup of a node by `node` (1-based) or axial position `z` (m).

use std::collections::HashSet;

use super::ModelError;
use super::error::FieldPath;
use super::limits::Limit;
use super::source_map::line_of_field;
use crate::units::Short;

/// The model text and its name, for error messages.
pub(crate) struct Ctx<'a> {
    /// The TOML text (for line numbers).
    pub(crate) text: &'a str,
    /// File name shown in messages.
    pub(crate) source: &'a str,
    /// Where finite films' force tables (plain films' and pads') are cached (`film_tables = true`).
    pub(crate) film_cache: Option<&'a std::path::Path>,
}

impl Ctx<'_> {
    /// An [`ModelError::Invalid`] for the field at `path` holding `value`.
    pub(crate) fn err(
        &self,
        path: FieldPath,
        value: impl std::fmt::Display,
        problem: &str,
    ) -> ModelError {
        ModelError::Invalid {
            file: self.source.to_string(),
            line: line_of_field(self.text, &path),
            field: path.to_string(),
            value: value.to_string(),
            problem: problem.to_string(),
        }
    }

    /// `v` if finite.
    pub(crate) fn finite(&self, path: FieldPath, v: f64) -> Result<f64, ModelError> {
        if v.is_finite() {
            Ok(v)
        } else {
            Err(self.err(path, Short(v), "must be a finite number"))
        }
    }

    /// `v` if finite and > 0.
    pub(crate) fn positive(&self, path: FieldPath, v: f64) -> Result<f64, ModelError> {
        if v.is_finite() && v > 0.0 {
            Ok(v)
        } else {
            Err(self.err(path, Short(v), "must be a finite number greater than zero"))
        }
    }

    /// `v` if finite and ≥ 0.
    pub(crate) fn non_negative(&self, path: FieldPath, v: f64) -> Result<f64, ModelError> {
        if v.is_finite() && v >= 0.0 {
            Ok(v)
        } else {
            Err(self.err(path, Short(v), "must be a finite number not less than zero"))
        }
    }

    /// `v` if finite and within `limit` (its range and the reason in the
    /// message); a value of the wrong sign gets the sign's message first.
    pub(crate) fn within(&self, path: FieldPath, v: f64, limit: &Limit) -> Result<f64, ModelError> {
        if limit.min > 0.0 {
            self.positive(path.clone(), v)?;
        } else if limit.min == 0.0 {
            self.non_negative(path.clone(), v)?;
        } else {
            self.finite(path.clone(), v)?;
        }
        if limit.holds(v) {
            Ok(v)
        } else {
            Err(self.err(
                path,
                Short(v),
                &format!(
                    "must lie in [{}, {}] {} ({})",
                    Short(limit.min),
                    Short(limit.max),
                    limit.unit,
                    limit.why
                ),
            ))
        }
    }

    /// Resolve `node` (1-based) or `z` (m) to a node index.
    pub(crate) fn location(
        &self,
        path: &FieldPath,
        node: Option<i64>,
        z: Option<f64>,
        node_z: &[f64],
    ) -> Result<usize, ModelError> {
        match (node, z) {
            (Some(n), None) => {
                if n >= 1 && (n as usize) <= node_z.len() {
                    Ok(n as usize - 1)
                } else {
                    Err(self.err(
                        path.key("node"),
                        n,
                        &format!("must be a node number from 1 to {}", node_z.len()),
                    ))
                }
            }
            (None, Some(z)) => {
                let z = self.finite(path.key("z"), z)?;
                let span = node_z[node_z.len() - 1] - node_z[0];
                let best = super::nodes::nearest(node_z, z);
                if (node_z[best] - z).abs() <= 1e-9 * span.max(1.0) {
                    Ok(best)
                } else {
                    Err(self.err(
                        path.key("z"),
                        z,
                        &format!(
                            "no node there; the nearest is node {} at z = {} m (split the shaft section so that a node falls at this position)",
                            best + 1,
                            node_z[best]
                        ),
                    ))
                }
            }
            (Some(n), Some(z)) => Err(self.err(
                path.key("node"),
                format!("{n} (and z = {z})"),
                "give either node or z, not both",
            )),
            (None, None) => Err(self.err(path.clone(), "(missing)", "needs node or z")),
        }
    }
}

/// The name given, else `prefix` and the 1-based entry number.
pub(crate) fn default_name(given: Option<String>, prefix: &str, k: usize) -> String {
    given.unwrap_or_else(|| format!("{prefix}{}", k + 1))
}

/// Names already taken in one section of a model, to reject duplicates.
#[derive(Default)]
pub(crate) struct Names(HashSet<String>);

impl Names {
    /// `name` if no earlier entry of the section took it, else an error at
    /// `entry.name`; `what` names the kind of entry (`"bearing"`, …).
    pub(crate) fn claim(
        &mut self,
        ctx: &Ctx,
        entry: &FieldPath,
        name: String,
        what: &str,
    ) -> Result<String, ModelError> {
        if self.0.insert(name.clone()) {
            Ok(name)
        } else {
            Err(ctx.err(entry.key("name"), &name, &format!("duplicate {what} name")))
        }
    }
}
