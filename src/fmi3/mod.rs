//! FMI 3.0 Co-Simulation layer: translation only, no physics, over the same
//! version-neutral FMU ([`crate::fmu`]) and the same variable table as FMI 2.0.
//!
//! - [`xml`]: the FMI 3.0 `modelDescription.xml` generated from the variable
//!   table, with an instantiation token hashed from the description;
//! - [`arrays`]: `fmi3Float64` arrays over the table's per-bearing, per-probe
//!   and per-port inputs and outputs (`bearings.x`, `ports.fx`, ...);
//! - [`resources`]: an FMI 3.0 instance (`Instance::new_fmi3`) and the
//!   instantiation from the `resourcePath` folder, checked against the token;
//! - `exports`: the C ABI (`fmi3*` symbols, every function of
//!   `fmi3Functions.h`) over the instance, types from the official FMI 3.0
//!   headers (2-Clause BSD, Modelica Association) through bindgen (`fmi-sys`
//!   with its `fmi3` feature).
//!
//! Both versions live in one shared library: the `fmi2*` and `fmi3*` names
//! differ, so the FMI 2.0 and the FMI 3.0 FMU ship the same binary.
//!
//! Inputs: FMI 3.0 has no input derivatives, so a value set before
//! `fmi3DoStep` is held over the whole step (zero-order hold), exactly as an
//! FMI 2.0 input set without `fmi2SetRealInputDerivatives`.

pub mod arrays;
mod exports;
pub mod resources;
pub mod xml;
