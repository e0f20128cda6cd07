//! Self-contained numerical linear algebra for the finite-element solver:
//! banded LU with partial pivoting ([`band`]) and an Arnoldi eigensolver for a
//! few largest-modulus eigenvalues of a linear operator ([`arnoldi`]), meant to
//! be used in shift-invert mode.

use std::fmt;

pub mod arnoldi;
pub mod band;

pub use arnoldi::{ArnoldiOptions, EigenPair, LinearOperator, largest_eigenpairs};
pub use band::{BandLu, BandMatrix, Scalar, map_to_complex};

/// Errors reported by the linear-algebra routines.
#[derive(Debug, Clone, PartialEq)]
pub enum LinalgError {
    /// Entry `(row, col)` lies outside the stored band (or outside the matrix).
    OutOfBand { row: usize, col: usize },
    /// A vector or matrix has the wrong dimension.
    DimensionMismatch { expected: usize, found: usize },
    /// The band of the second operand is not contained in the band of the first.
    IncompatibleBand,
    /// Zero or negligible pivot met while factorizing column `column` (0-based).
    Singular { column: usize },
    /// A NaN or infinite value was met in the input or produced by the operator.
    NotFinite,
    /// Only `converged` of the `wanted` eigenpairs reached the tolerance.
    NotConverged { converged: usize, wanted: usize },
    /// The dense Schur decomposition of the projected matrix failed.
    DenseEigenFailed,
    /// An argument is out of its admissible range.
    InvalidArgument(&'static str),
}

impl fmt::Display for LinalgError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::OutOfBand { row, col } => {
                write!(f, "entry ({row}, {col}) lies outside the band")
            }
            Self::DimensionMismatch { expected, found } => {
                write!(f, "dimension mismatch: expected {expected}, found {found}")
            }
            Self::IncompatibleBand => write!(f, "operand band is not contained in target band"),
            Self::Singular { column } => write!(f, "matrix is singular at column {column}"),
            Self::NotFinite => write!(f, "non-finite value (NaN or infinity) encountered"),
            Self::NotConverged { converged, wanted } => write!(
                f,
                "eigensolver did not converge: {converged} of {wanted} eigenpairs converged"
            ),
            Self::DenseEigenFailed => write!(f, "dense Schur decomposition failed to converge"),
            Self::InvalidArgument(what) => write!(f, "invalid argument: {what}"),
        }
    }
}

impl std::error::Error for LinalgError {}
