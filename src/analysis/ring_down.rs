//! The two halves checked against each other (issue 45): a mode of the
//! linearized rotor rung down in the nonlinear transient.
//!
//! From the static equilibrium at the speed (unbalance and harmonic forces
//! off, a torque-driven shaft held at the speed), the rotor is displaced
//! along the mode, `u = u₀ + a Re x`, `u̇ = a Re(λ x)`, with `a` a
//! ten-thousandth of the smallest bearing clearance `C` at the mode's largest
//! translation, times `Ω/ω` for a mode faster than the spin (so that its
//! squeeze velocity `a ω` stays a ten-thousandth of the film's sliding
//! velocity `C Ω`: the films' nonlinearity shifts `δ` in proportion to it,
//! 1.8 % at a thousandth on the Jeffcott rotor's 518 Hz mode, 0.2 % here;
//! 1e-7 m without a clearance), pad tilts at equilibrium; the Newmark transient
//! (equal steps of a two-hundredth of the mode's period) then runs
//! `periods` periods. The displacement of the translation that moves most
//! (a real signal, `Re(a x e^{λt})`: both exponentials of the pair carry it,
//! whichever way the mode whirls) is fitted, after its first two periods
//! (the film and pad roots decay there), by the two-exponential Prony model
//! `q_{k+2} = p₁ q_{k+1} + p₀ q_k` in least squares: its roots `e^{λΔ}` and
//! `e^{λ̄Δ}` give the decay rate and frequency of the mode the transient
//! has, `δ = −2π Re λ / Im λ`.
//!
//! On linear bearings the transient is the linear model and `δ` agrees to
//! Newmark's `(ωh)²` (`tests/verdicts.rs`); on fluid films linearized
//! exactly it agrees at small amplitude; where the linear model reduces
//! something (tilting pads condensed at the running speed) the two differ,
//! and this says by how much.

use nalgebra::{Complex, DMatrix, DVector};

use crate::fe::{DOF_X, DOF_Y};
use crate::model::Drive;
use crate::rotor::Rotor;
use crate::solver::{Simulator, SolverError, SolverOptions};

use super::held_equilibrium::held_equilibrium;
use super::modal::Mode;

type C64 = Complex<f64>;

/// Time steps per period of the mode.
const STEPS_PER_PERIOD: usize = 200;
/// Samples of the whirl per period.
const SAMPLES_PER_PERIOD: usize = 25;
/// Periods skipped before the fit (film and pad roots decay there).
const SKIPPED_PERIODS: usize = 2;
/// Initial amplitude as a fraction of the smallest bearing clearance.
const AMPLITUDE_OF_CLEARANCE: f64 = 1e-4;
/// Newton's relative tolerance in the ring-down (the default 1e-8 of the
/// displacement scale is 1e-4 of the motion).
const NEWTON_TOLERANCE: f64 = 1e-12;
/// Initial amplitude (m) of a rotor without a clearance.
const AMPLITUDE_WITHOUT_CLEARANCE: f64 = 1e-7;

/// A mode rung down in the transient.
#[derive(Debug, Clone, PartialEq)]
pub struct RingDown {
    /// The linear mode it started from.
    pub mode: Mode,
    /// The node (0-based) whose motion was fitted.
    pub node: usize,
    /// Initial amplitude there (m).
    pub amplitude: f64,
    /// Damped frequency (rad/s) of the transient's fit.
    pub frequency: f64,
    /// Log decrement of the transient's fit.
    pub log_decrement: f64,
}

impl RingDown {
    /// `δ_transient / δ_linear − 1`.
    pub fn difference(&self) -> f64 {
        self.log_decrement / self.mode.log_decrement - 1.0
    }
}

/// Why a ring-down could not be made.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum RingDownError {
    /// The transient failed.
    #[error("ring-down transient: {0}")]
    Solver(#[from] SolverError),
    /// The rotor could not be assembled for it.
    #[error("ring-down rotor: {0}")]
    Assembly(#[from] crate::rotor::AssemblyError),
    /// The mode cannot be rung down (no oscillation, no motion, no fit).
    #[error("ring-down: {0}")]
    Mode(String),
}

/// Ring `mode` (of `rotor` linearized at `speed`, rad/s) down over
/// `periods` periods in the nonlinear transient (see the module docs).
pub fn ring_down(
    rotor: &Rotor,
    speed: f64,
    mode: &Mode,
    periods: usize,
) -> Result<RingDown, RingDownError> {
    let omega = mode.damped_frequency;
    if !(omega.is_finite() && omega > 0.0) || periods <= SKIPPED_PERIODS + 1 {
        return Err(RingDownError::Mode(format!(
            "a mode of damped frequency {omega} rad/s over {periods} periods cannot be rung down"
        )));
    }
    let mut model = rotor.model.clone();
    model.drive = Drive::Speed;
    let free = Rotor::new(model)?;
    let period = std::f64::consts::TAU / omega;
    let options = SolverOptions {
        time_step: period / STEPS_PER_PERIOD as f64,
        local_error_tolerance: 0.0,
        // Newton resolves the small motion (a ten-thousandth of the clearance).
        tolerance: NEWTON_TOLERANCE,
        ..SolverOptions::default()
    };
    let mut sim = Simulator::new(free, options)?;
    sim.set_speed(speed, 0.0)?;
    for k in 0..rotor.model.unbalances.len() {
        sim.set_unbalance(k, 0.0)?;
    }
    for (i, l) in rotor.model.load_inputs().iter().enumerate() {
        if l.channel.is_periodic() {
            sim.set_load(i, 0.0, 0.0)?;
        }
    }
    // From the equilibrium the linear analyses take: the solver's own, or
    // the one off a statically unstable centre (`held_equilibrium`, to
    // 1e-11 of the load).
    match held_equilibrium(rotor, speed, None)? {
        (held, Some(_))
            if held.displacement.len() == sim.state().u.len()
                && held.tilts.len() == sim.state().p.len() =>
        {
            let mut state = sim.state().clone();
            state.u.copy_from_slice(&held.displacement);
            state.p.copy_from_slice(&held.tilts);
            sim.set_state(state)?;
            sim.consistent_acceleration()?;
        }
        _ => sim.settle_static()?,
    }
    let r = sim.rotor();
    // The translation that moves most in the mode.
    let (node, axis) = (0..r.model.node_count())
        .flat_map(|n| [(n, DOF_X), (n, DOF_Y)])
        .max_by(|&(a, i), &(b, j)| {
            mode.shape[4 * a + i]
                .norm()
                .total_cmp(&mode.shape[4 * b + j].norm())
        })
        .unwrap_or((0, DOF_X));
    let Some(index) = r.dofs.free(node, axis) else {
        return Err(RingDownError::Mode(format!(
            "node {} of the mode's largest motion is held",
            node + 1
        )));
    };
    let scale = mode.shape[4 * node + axis].norm();
    let clearance = r
        .model
        .bearings
        .iter()
        .filter_map(|b| b.kind.journal_clearance())
        .fold(f64::INFINITY, f64::min);
    // Small against the clearance, and its squeeze velocity `a ω` small
    // against the film's sliding velocity `C Ω`: a fast mode on a slow
    // journal moves less.
    let amplitude = if clearance.is_finite() {
        AMPLITUDE_OF_CLEARANCE * clearance * (speed.abs() / omega).min(1.0)
    } else {
        AMPLITUDE_WITHOUT_CLEARANCE
    };
    let a = amplitude / scale;
    let mut state = sim.state().clone();
    let u0 = state.u[index];
    for i in 0..state.u.len() {
        let x = mode.shape[r.dofs.full(i)];
        state.u[i] += a * x.re;
        state.ud[i] += a * (mode.eigenvalue * x).re;
    }
    sim.set_state(state)?;
    sim.consistent_acceleration()?;
    let dt = period / SAMPLES_PER_PERIOD as f64;
    let mut motion: Vec<f64> = Vec::with_capacity(periods * SAMPLES_PER_PERIOD);
    let t0 = sim.time();
    for k in 1..=periods * SAMPLES_PER_PERIOD {
        sim.advance_to(t0 + k as f64 * dt)?;
        if k > SKIPPED_PERIODS * SAMPLES_PER_PERIOD {
            motion.push(sim.state().u[index] - u0);
        }
    }
    let lambda = prony_pair(&motion, dt)
        .ok_or_else(|| RingDownError::Mode("the transient's motion fits no oscillation".into()))?;
    Ok(RingDown {
        mode: mode.clone(),
        node,
        amplitude,
        frequency: lambda.im,
        log_decrement: -std::f64::consts::TAU * lambda.re / lambda.im,
    })
}

/// The exponent `λ` (1/s, `Im λ > 0`) of the two-exponential Prony fit of
/// the real signal `q` sampled every `dt`: least squares
/// `q_{k+2} = p₁ q_{k+1} + p₀ q_k`, roots `w` of `w² − p₁ w − p₀` (a
/// conjugate pair for an oscillation), `λ = ln(w)/dt`.
fn prony_pair(q: &[f64], dt: f64) -> Option<C64> {
    let n = q.len().checked_sub(2)?;
    if n < 4 {
        return None;
    }
    let a = DMatrix::from_fn(n, 2, |k, j| if j == 0 { q[k + 1] } else { q[k] });
    let b = DVector::from_fn(n, |k, _| q[k + 2]);
    let p = a.svd(true, true).solve(&b, 1e-14).ok()?;
    let (p1, p0) = (C64::from(p[0]), C64::from(p[1]));
    let root = (p1 * p1 + 4.0 * p0).sqrt();
    [(p1 + root) / 2.0, (p1 - root) / 2.0]
        .into_iter()
        .map(|w| w.ln() / dt)
        .filter(|l| l.is_finite() && l.im > 0.0)
        .max_by(|a, b| a.im.total_cmp(&b.im))
}
