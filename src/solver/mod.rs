//! Nonlinear transient solver: Newmark average acceleration (β = 1/4, γ = 1/2)
//! with modified Newton–Raphson on the bearing nonlinearity, and the
//! [`Simulator`] API that front ends (CLI, FMI layer) drive.
//!
//! # Equations
//! Rotor DOFs `u` (free DOFs of [`crate::rotor::Rotor`]) and the internal
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
//! Newmark gives `ü = a0 (u − uₙ) − a2 u̇ₙ − üₙ`, `u̇ = a1 (u − uₙ) − u̇ₙ`
//! (`a0 = 4/h²`, `a1 = 2/h`, `a2 = 4/h`), so the rotor equations of a step are
//! `A u = b + E F_b` with `A = K + a1 (C + Ω G) + a0 M` (banded LU, O(n)) and the
//! effective load `b = f + M (a0 uₙ + a2 u̇ₙ + üₙ) + (C + Ω G)(a1 uₙ + u̇ₙ)`.
//!
//! **Exact factorization** (the usual case): `u = A⁻¹ b + A⁻¹ E F_b`, so Newton
//! runs on the journal coordinates `j = Eᵀu` and pad tilts alone,
//! `j = Eᵀ A⁻¹ b + G F_b(j, p)`, `Q_p(j, p) = 0`, `G = Eᵀ A⁻¹ E` kept with the
//! factorization. Full Newton: the bearing Jacobians (`K_b + a1 C_b`) are fresh
//! at every iterate, the pads are condensed bearing by bearing, and the dense
//! system has the size of the journal DOFs. A step costs two banded mat-vecs,
//! one banded solve, and `A⁻¹ E F_b` (a stored `Z = A⁻¹E` when there are few
//! journals, else a second solve), whatever the number of iterations.
//! `A` is refactored (into the same storage) when the step size changes, and at
//! every speed change when the journal DOFs are few (≤ 8); sub-steps that differ
//! from the factored step by time-grid round-off take the factored step.
//!
//! **Stale factorization** (many journals, speed within ±2 % of the factored
//! one): modified Newton on the full residual with `J = A + E (K_b + a1 C_b) Eᵀ`
//! (plus pad blocks) through a Schur complement on the bearing DOFs.
//!
//! # Convergence and failure
//! Exact path: a step has converged when the Newton correction of the journal
//! and pad coordinates is below `tolerance` times the displacement scale (their
//! largest value, at least the smallest bearing clearance); the journal forces at
//! the corrected point are taken to first order, which satisfies the condensed
//! equations exactly. Stale path: the residual is below `tolerance` times the
//! largest force term and the increment below `tolerance` times the displacement
//! scale; the bearing Jacobian is refreshed when the residual stops contracting
//! (ratio > 0.7). Plain Newton gives up early on a step whose increments keep
//! failing to shrink (a cycle). A step it fails is solved again from the
//! predictor by the damped Newton (`line_search.rs`: Armijo backtracking on the
//! condensed residual, on a factorization exact for the step); a step that
//! fails that too (or takes a journal beyond the clearance) is cut in half,
//! down to `2^-max_step_cuts` (16 by default) and never below
//! [`SolverOptions::MIN_SPAN`]. A step that still fails is an error: an
//! unconverged state is never returned. Every accepted step is checked against
//! the limits of the contact law ([`contact_watch`]).

mod adaptive;
mod condense;
mod condensed_work;
pub mod contact_onset;
mod contact_records;
pub mod contact_watch;
mod dense;
mod error;
mod factor;
mod factor_work;
mod film_start;
mod floor;
mod gyroscopic_correction;
mod inputs;
mod line_search;
mod newmark;
mod newmark_work;
mod newton;
mod norm;
mod observed;
pub mod observer;
pub mod offset_continuation;
mod options;
mod output_memo;
mod outputs;
mod pad_balance;
mod pad_inertia;
pub mod plausible;
pub mod reduction_check;
pub mod run;
mod schur;
mod simulator;
mod sites;
mod slow_pads;
mod state;
mod static_stability;
pub mod statics;
mod stats;
mod torsion;
mod torsion_work;
mod warnings;

pub mod time_step;

pub use contact_watch::{ContactLimit, ContactWarning};
pub use error::SolverError;
pub use observer::{StepFlow, StepObserver};
pub use offset_continuation::line_equilibrium;
pub use options::SolverOptions;
pub use outputs::{
    BearingOutput, HousingOutput, Outputs, PortOutput, ProbeOutput, ThrustOutput, TorqueNodeOutput,
};
pub use run::{SpeedProfile, record, record_into};
pub use simulator::Simulator;
pub use state::SimState;
pub use statics::{Equilibrium, equilibrium, equilibrium_near, equilibrium_unchecked};
pub use stats::StepStats;
pub use warnings::SolverWarning;
