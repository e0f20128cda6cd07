//! The FMU behind both FMI versions: translation only, no physics, and nothing
//! here is particular to FMI 2.0 or FMI 3.0 beyond the names of the calls
//! ([`states::Version`]).
//!
//! - [`variables`]: the variable table derived from the rotor model (value
//!   references, units, bindings) — the single source of the interface of
//!   both FMI versions;
//! - [`description`]: what both model descriptions declare alike (units, log
//!   categories, the model identifier) and the token hashed from a description;
//! - [`states`]: the Co-Simulation state machine and the one table of the
//!   states each call is allowed in, with each call's name in either version;
//! - [`instance`]: one FMU instance in safe Rust (get/set dispatch, steps)
//!   driving the [`crate::solver::Simulator`];
//! - [`snapshot`]: the FMU state and its versioned, checksummed byte image;
//! - [`resources`]: the model in the FMU's resources folder, named by a
//!   `file` URI (decoding, loading, checking the token);
//! - [`docs`]: `documentation/index.html`, from the same table;
//! - `c_abi`: what the two C ABIs share (pointer helpers, the FMU-state
//!   exports written once for both versions' names).
//!
//! The version layers translate: `crate::fmi2` (FMI 2.0: its model description
//! and the `fmi2*` C exports) and `crate::fmi3` (FMI 3.0: the same for
//! `fmi3*`), each building its [`instance::Instance`] with its own token.

pub(crate) mod c_abi;
pub mod description;
pub mod docs;
pub mod instance;
pub mod resources;
pub mod snapshot;
pub mod states;
pub mod variables;
