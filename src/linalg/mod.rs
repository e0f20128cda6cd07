//! Self-contained numerical linear algebra for the finite-element solver:
//! banded LU with partial pivoting ([`band`]), an Arnoldi eigensolver for a
//! few largest-modulus eigenvalues of a linear operator ([`arnoldi`]), meant to
//! be used in shift-invert mode, and monotone cubic interpolation of tables
//! ([`pchip`]), the Sturm sequence count of a symmetric definite banded
//! pencil ([`sturm`]) and its lowest eigenpairs by subspace iteration
//! ([`subspace`]).

use std::fmt;

pub mod arnoldi;
pub mod band;
pub mod pchip;
pub mod sturm;
pub mod subspace;

pub use arnoldi::{
    ArnoldiOptions, EigenPair, LinearOperator, RealOperator, largest_eigenpairs,
    largest_eigenpairs_real,
};
pub use band::{BandLu, BandMatrix, Scalar, map_to_complex};
pub use sturm::{eigenvalues_below, tridiagonal_eigenvalues_below};
pub use subspace::lowest_eigenpairs;

/// Numerical failures of the linear-algebra routines. Programming errors (an
/// entry outside the band, operands of the wrong dimension or band) are not
/// values: the routines panic on them with a message naming the operands.
#[derive(Debug, Clone, PartialEq)]
pub enum LinalgError {
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
