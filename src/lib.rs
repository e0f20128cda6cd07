//! Rotor-bearing dynamics: a finite-element rotor (Timoshenko shaft elements,
//! lumped disks) on bearings, with linear analyses (static deflection, unbalance
//! response, complex modes, Campbell diagram).
//!
//! Data flow: model file ([`model`]) → validated [`model::RotorModel`] →
//! assembled [`rotor::Rotor`] (banded `M`, `K`, `C`, `G`) → analyses
//! ([`analysis`]). Physics lives in [`fe`] and [`bearing`]; [`linalg`] holds the
//! banded solver and the shift-invert eigen-solver; [`plot`] draws PNG figures.

pub mod analysis;
pub mod bearing;
pub mod fe;
pub mod fmi2;
pub mod fmi3;
pub mod fmu;
pub mod linalg;
pub mod model;
#[cfg(feature = "plot")]
pub mod plot;
pub mod report;
pub mod rotor;
pub mod solver;
pub mod units;
