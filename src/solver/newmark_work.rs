//! The iterate of a Newmark step and its residual buffers
//! ([`super::newmark`]), reused by every step.

/// The iterate of a step and its residual buffers, reused by every step.
#[derive(Debug)]
pub(super) struct NewmarkWork {
    /// Rotor displacement (m, rad), velocity and acceleration at the iterate.
    pub u: Vec<f64>,
    pub ud: Vec<f64>,
    pub udd: Vec<f64>,
    /// Pad tilts (m) and their rates at the iterate.
    pub p: Vec<f64>,
    pub pd: Vec<f64>,
    pub pdd: Vec<f64>,
    /// Full residual `lin + E F_b` (N).
    pub r: Vec<f64>,
    /// Linear part of the dynamic residual, `f − M ü − D u̇ − K u` (N), or the
    /// condensed step's `A⁻¹ b`.
    pub lin: Vec<f64>,
    /// Mat-vec product, or `A⁻¹ E F_b`.
    pub mv: Vec<f64>,
    /// Newton increments of the rotor and pad coordinates.
    pub du: Vec<f64>,
    pub dp: Vec<f64>,
    /// External force: unbalance and gravity (N).
    pub f_ext: Vec<f64>,
    /// Pad residuals `Q_p` (N·m per m of pad coordinate).
    pub rp: Vec<f64>,
    /// The load inputs at the step's time (N).
    pub load_values: Vec<f64>,
    /// A torque-driven shaft's angle (rad), speed (rad/s) and acceleration
    /// (rad/s²) at each unbalance plane's node at the step's end; empty when
    /// the shaft follows the prescribed speed.
    pub plane_motion: Vec<[f64; 3]>,
}

impl NewmarkWork {
    /// Buffers for `n` rotor DOFs, `n_internal` pad DOFs and `n_loads` load inputs.
    pub fn new(n: usize, n_internal: usize, n_loads: usize) -> Self {
        let rotor = || vec![0.0; n];
        let pads = || vec![0.0; n_internal];
        Self {
            u: rotor(),
            ud: rotor(),
            udd: rotor(),
            p: pads(),
            pd: pads(),
            pdd: pads(),
            r: rotor(),
            lin: rotor(),
            mv: rotor(),
            du: rotor(),
            dp: pads(),
            f_ext: rotor(),
            rp: pads(),
            load_values: vec![0.0; n_loads],
            plane_motion: Vec::new(),
        }
    }
}
