//! Linear analyses of an assembled rotor: static deflection, unbalance response,
//! complex modes and the Campbell diagram; and the analyst toolkit built on
//! them: unbalance sweeps with peaks and separation margins, bearing operating
//! points, mode-shape orbits, cross-coupling stability and the critical speed map.

pub mod alignment;
pub mod api_unbalance;
pub mod backward_crossing;
pub mod campbell;
mod campbell_point;
mod critical_refine;
mod cross_coupling_sites;
pub mod element_operating_point;
pub mod film_validity;
pub mod forced;
pub mod frequency_table;
pub mod held_equilibrium;
pub mod housing_vibration;
pub mod level_two;
pub mod linear;
pub mod linearize;
pub mod modal;
pub mod mode_tracking;
pub mod offset_stability;
pub mod operating_point;
pub mod orbit;
pub mod pad_eigen;
pub mod parallel;
mod polish;
pub mod ring_down;
pub mod shaft_loads;
pub mod shaft_orbits;
pub mod shapes;
pub mod spectrum;
pub mod speed_range;
pub mod stability;
pub mod tolerance_cases;
pub mod torsion;
mod torsion_damped;
pub mod ucs;
pub mod unbalance;
pub mod whirl_modes;
