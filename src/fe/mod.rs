//! Finite elements of the rotor: Timoshenko shaft elements, lumped disks and
//! their sections. Pure functions of their inputs; the global assembly lives in
//! the `rotor` module, one layer up (it reads the model, these files do not).
//!
//! # Coordinates, degrees of freedom and signs (stated once, used everywhere)
//!
//! The shaft axis is `z`; `x` and `y` span the cross-section and form a
//! right-handed triad `(x, y, z)`. The spin `Ω` is positive about `+z` (the
//! shaft surface moves from `+x` toward `+y`), which is the same sense in which
//! the bearing module measures the film angle `θ`.
//!
//! Every node carries four degrees of freedom, in this order:
//!
//! | index | symbol | meaning                       | unit |
//! |-------|--------|-------------------------------|------|
//! | 0     | `x`    | lateral displacement along x  | m    |
//! | 1     | `y`    | lateral displacement along y  | m    |
//! | 2     | `θx`   | rotation about the x axis     | rad  |
//! | 3     | `θy`   | rotation about the y axis     | rad  |
//!
//! With small rotations and right-handed signs, the slopes of a bent shaft are
//! `∂x/∂z = θy` and `∂y/∂z = −θx` (plus shear strain for Timoshenko beams).
//! Global DOF `4·i + k` is DOF `k` of node `i` (0-based); model files number
//! nodes from 1.
//!
//! Equations of motion of the linear part:
//! `M q̈ + (C + Ω G) q̇ + (K + K_axial) q = f`, where `M`, `K`, `K_axial` are
//! symmetric and `G` is skew-symmetric. The gyroscopic energy of a spinning
//! section is `T_g = Ω ∫ ρ I_p θ̇x θy dz` (for a disk `Ω I_p θ̇x θy`), which gives
//! `G[θx, θy] = +I_p`, `G[θy, θx] = −I_p`: forward whirl is stiffened, backward
//! whirl softened.

pub mod disk;
pub mod section;
pub mod shaft;
pub mod torsion;

/// Degrees of freedom per node.
pub const DOF_PER_NODE: usize = 4;
/// Local index of the x displacement within a node.
pub const DOF_X: usize = 0;
/// Local index of the y displacement within a node.
pub const DOF_Y: usize = 1;
/// Local index of the rotation about x within a node.
pub const DOF_RX: usize = 2;
/// Local index of the rotation about y within a node.
pub const DOF_RY: usize = 3;
