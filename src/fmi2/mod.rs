//! FMI 2.0 Co-Simulation layer: translation only, no physics.
//!
//! - [`variables`]: the variable table derived from the rotor model (value
//!   references, units, bindings) — the single source of the interface;
//! - [`xml`]: `modelDescription.xml` generated from that table, with a GUID
//!   hashed from the description;
//! - [`states`]: the FMI 2.0 Co-Simulation state machine and the one table of
//!   the states each call is allowed in;
//! - [`instance`]: one FMU instance in safe Rust (get/set dispatch, steps)
//!   driving the [`crate::solver::Simulator`];
//! - [`snapshot`]: the FMU state and its versioned, checksummed byte image;
//! - [`resources`]: instantiation from the `fmuResourceLocation` URI (decoding,
//!   loading and checking the model);
//! - `exports`: the C ABI (`fmi2*` symbols) over `instance`, types from the
//!   official headers through bindgen (`fmi-sys`).
//!
//! The FMU reads its rotor model from `resources/model.toml` at instantiation.

pub mod docs;
mod exports;
pub mod instance;
pub mod resources;
pub mod snapshot;
pub mod states;
pub mod variables;
pub mod xml;
