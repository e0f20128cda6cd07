//! FMI 2.0 Co-Simulation layer: translation only, no physics.
//!
//! - [`variables`]: the variable table derived from the rotor model (value
//!   references, units, bindings) — the single source of the interface;
//! - [`xml`]: `modelDescription.xml` generated from that table, with a GUID
//!   hashed from the description;
//! - [`instance`]: one FMU instance in safe Rust (state machine, get/set, steps,
//!   FMU state and its serialization) driving the [`crate::solver::Simulator`];
//! - `exports`: the C ABI (`fmi2*` symbols) over `instance`, types from the
//!   official headers through bindgen (`fmi-sys`).
//!
//! The FMU reads its rotor model from `resources/model.toml` at instantiation.

pub mod docs;
mod exports;
pub mod instance;
pub mod variables;
pub mod xml;
