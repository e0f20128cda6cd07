//! Errors of model files, and the field paths that name the culprit.

use std::fmt;

/// One step of a field path: a table key or an array index.
#[derive(Debug, Clone, PartialEq)]
pub(crate) enum Seg {
    Key(String),
    Index(usize),
}

/// A path to a field, displayed as `shaft[2].outer_diameter`.
#[derive(Debug, Clone, Default, PartialEq)]
pub(crate) struct FieldPath(pub(crate) Vec<Seg>);

impl FieldPath {
    pub(crate) fn key(&self, k: &str) -> Self {
        let mut p = self.clone();
        p.0.push(Seg::Key(k.to_string()));
        p
    }

    pub(crate) fn index(&self, i: usize) -> Self {
        let mut p = self.clone();
        p.0.push(Seg::Index(i));
        p
    }

    /// The path one step up, `None` at the root.
    pub(crate) fn parent(&self) -> Option<Self> {
        let (_, rest) = self.0.split_last()?;
        Some(Self(rest.to_vec()))
    }
}

impl fmt::Display for FieldPath {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        for (n, seg) in self.0.iter().enumerate() {
            match seg {
                Seg::Key(k) if n == 0 => write!(f, "{k}")?,
                Seg::Key(k) => write!(f, ".{k}")?,
                Seg::Index(i) => write!(f, "[{i}]")?,
            }
        }
        if self.0.is_empty() {
            write!(f, "(top level)")?;
        }
        Ok(())
    }
}

/// A model file that cannot be used, with enough detail to fix it.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ModelError {
    /// The file could not be read.
    #[error("{file}: cannot read the model file: {message}")]
    Io { file: String, message: String },
    /// The text is not valid TOML or does not fit the model-file schema.
    #[error("{file}{}: {message}", line_suffix(*line))]
    Syntax {
        file: String,
        line: Option<usize>,
        message: String,
    },
    /// A value is out of range or inconsistent with the rest of the model.
    #[error("{file}{}: {field} = {value}: {problem}", line_suffix(*line))]
    Invalid {
        file: String,
        line: Option<usize>,
        field: String,
        value: String,
        problem: String,
    },
}

fn line_suffix(line: Option<usize>) -> String {
    line.map(|l| format!(":{l}")).unwrap_or_default()
}
