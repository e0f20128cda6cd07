//! Linear analyses of an assembled rotor: static deflection, unbalance response,
//! complex modes and the Campbell diagram.

pub mod campbell;
pub mod linear;
pub mod linearize;
pub mod modal;
pub mod operating_point;
pub mod shapes;
pub mod spectrum;
pub mod stability;
pub mod ucs;
pub mod unbalance;
