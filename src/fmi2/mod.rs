//! FMI 2.0 Co-Simulation layer: translation only, no physics, over the
//! version-neutral FMU of [`crate::fmu`].
//!
//! - [`xml`]: the FMI 2.0 `modelDescription.xml` generated from the variable
//!   table, with a GUID hashed from the description;
//! - [`resources`]: an FMI 2.0 instance (`Instance::new`) and the
//!   instantiation from the `fmuResourceLocation` URI, checked against the GUID;
//! - `exports`: the C ABI (`fmi2*` symbols) over the instance, types from the
//!   official headers through bindgen (`fmi-sys`).
//!
//! [`variables`], [`instance`], [`states`], [`snapshot`] and [`docs`] are
//! [`crate::fmu`]'s, named here as before.
//!
//! The FMU reads its rotor model from `resources/model.toml` at instantiation.

mod exports;
pub mod resources;
pub mod xml;

pub use crate::fmu::{docs, instance, snapshot, states, variables};
