//! Nonlinear transient solver: Newmark average acceleration (β = 1/4, γ = 1/2)
//! with modified Newton–Raphson on the bearing nonlinearity, and the
//! [`Simulator`] API that front ends (CLI, FMI layer) drive.
//!
//! # Equations
//! Rotor DOFs `u` (free DOFs of [`crate::fe::assembly::Rotor`]) and the internal
//! DOFs `p` of the bearings (pad tilts, massless):
//!
//! `M ü + (C + Ω G) u̇ + K u = f_unb(t) + f_g + E F_b(Eᵀu, Eᵀu̇, p, ṗ, Ω)`,
//! `0 = Q_p(Eᵀu, Eᵀu̇, p, ṗ, Ω)`,
//!
//! `E` selecting the journal DOFs. The unbalance of a plane `m e` at angle
//! `φ = φ_spin + phase` is `m e (Ω² cos φ + Ω̇ sin φ, Ω² sin φ − Ω̇ cos φ)`,
//! centrifugal plus angular-acceleration terms, times an optional ramp
//! `1 − e^{−t/τ}`.
//!
//! # Step
//! Newmark gives `ü = a0 (u − uₙ) − a2 u̇ₙ − a3 üₙ`, `u̇ = a1 (u − uₙ) − a4 u̇ₙ − a5 üₙ`
//! (`a0 = 4/h²`, `a1 = 2/h`, `a2 = 4/h`, `a3 = a4 = 1`, `a5 = 0`). Newton on the
//! residual uses `J = A + E (K_b + a1 C_b) Eᵀ` (plus the pad blocks) with the
//! linear part `A = K + a1 (C + Ω_ref G) + a0 M` factored once per step size and
//! speed band (banded LU, O(n)). The bearing part enters through a Schur
//! complement on the few journal and pad DOFs: with `Z = A⁻¹E` kept with the
//! factorization, one Newton iteration costs one banded solve, `O(n·s)` for
//! `Z f`, and a dense solve of size `s = 2·bearings + pads`. Cost per step grows
//! linearly with the rotor size.
//!
//! # Convergence and failure
//! A step has converged when the residual is below `tolerance` times the largest
//! force term, and the increment is below `tolerance` times the displacement scale
//! (largest translational displacement, at least the smallest bearing clearance).
//! *Modified* Newton keeps the bearing Jacobian of the first iteration; when the
//! residual stops contracting (ratio > 0.7) it is refreshed (and `A` refactored at
//! the current speed); when that fails within `max_iterations` the step is cut in
//! half, down to `2^-max_step_cuts`. A step that still fails is an error: an
//! unconverged state is never returned.

mod dense;
pub mod run;
mod simulator;

pub use run::{SpeedProfile, record};
pub use simulator::{
    BearingOutput, Outputs, ProbeOutput, SimState, Simulator, SolverError, SolverOptions, StepStats,
};
