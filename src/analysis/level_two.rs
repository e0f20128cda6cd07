//! API 617 Level II stability of an API machine (`machine = "compressor" |
//! "steam_turbine" | "pump"`): the log decrement of the full model at the
//! maximum continuous speed.
//!
//! When the Level I screening ([`super::stability`]) fails, API 617 (7th
//! ed. §2.6.6, 8th ed. §4.8.6; API 684 2nd ed. §4.3) asks for a Level II
//! analysis: the rotor's damped eigenvalues at the maximum continuous speed
//! `N_mc` with every element that contributes stiffness, damping and
//! cross-coupling — the bearings, and the seals with their cross-coupled
//! coefficients (they are in the linearized rotor already:
//! `tests/seal_cross_coupling.rs`) — and the log decrement of the first
//! forward mode at least [`LEVEL_II_MIN_LOG_DEC`] (the same 0.1 as Level I's
//! `δ_A`; ROSS `Report.stability_level_2` takes the first non-backward mode
//! of the full rotor at the maximum speed). The standard's text is not
//! public; the clause numbers are those the literature and ROSS cite.
//!
//! Which modes are judged: the first forward mode (the lowest forward
//! damped frequency; overdamped roots are no modes) and every forward mode
//! whose damped frequency lies below the running frequency of `N_mc`
//! ([`LEVEL_II_FREQUENCY_LIMIT`] × `N_mc`): a subsynchronous forward whirl
//! is what destabilizing cross-coupling drives. The verdict is on the least
//! log decrement among them; a growing non-oscillating root (static
//! divergence) fails.
//!
//! **With the anticipated cross-coupling**: the same eigenproblem with the
//! Level I `Q_A` (the sum of each stage's Wachel `q_A`, now at `N_mc`) added
//! as `[[0, Q_A], [−Q_A, 0]]` where Level I places it
//! ([`api617_placement`]: mid-span, or the overhung impellers), split
//! equally. It answers what Level I would, but with the seals in the model.
//!
//! `N_mc` is the top of the operating range, as for the API unbalance cases
//! ([`super::api_unbalance::ApiUnbalance::mcs`]).

use crate::rotor::Rotor;

use super::linearize::linearized_from;
use super::modal::{ModalOptions, Mode, OverdampedRoot, Whirl, modal_analysis};
use super::stability::{
    StabilityError, Stage, anticipated, api617_placement, own_modes_with_cross_coupling,
    with_cross_coupling,
};
use super::whirl_modes::with_pads;

/// Level II: the smallest acceptable log decrement of the judged modes.
pub const LEVEL_II_MIN_LOG_DEC: f64 = 0.1;

/// Forward modes below this multiple of the maximum continuous speed's
/// running frequency are judged beside the first forward mode.
pub const LEVEL_II_FREQUENCY_LIMIT: f64 = 1.0;

/// The most modes asked of the eigen-solver to reach the frequency limit.
const MAX_MODES: usize = 64;

/// The judged forward modes of one Level II eigenproblem.
#[derive(Debug, Clone, PartialEq)]
pub struct LevelTwoCase {
    /// Added cross-coupled stiffness (N/m), 0 for the model as built.
    pub cross_coupling: f64,
    /// Its nodes (0-based), empty without.
    pub sites: Vec<usize>,
    /// The first forward mode and every forward mode below the limit, by
    /// damped frequency.
    pub modes: Vec<Mode>,
    /// Growing non-oscillating roots (static divergence).
    pub diverging: Vec<OverdampedRoot>,
}

impl LevelTwoCase {
    /// The judged mode of least log decrement.
    pub fn governing(&self) -> Option<&Mode> {
        self.modes
            .iter()
            .min_by(|a, b| a.log_decrement.total_cmp(&b.log_decrement))
    }

    /// Every judged mode has `δ ≥ 0.1` and nothing diverges.
    pub fn pass(&self) -> bool {
        self.diverging.is_empty()
            && self
                .governing()
                .is_some_and(|m| !m.is_undamped() && m.log_decrement >= LEVEL_II_MIN_LOG_DEC)
    }
}

/// The Level II analysis.
#[derive(Debug, Clone, PartialEq)]
pub struct LevelTwo {
    /// Maximum continuous speed (rad/s).
    pub speed: f64,
    /// Forward modes below this damped frequency (rad/s) are judged.
    pub frequency_limit: f64,
    /// The model as built (bearings and seals with their cross-coupling).
    pub as_built: LevelTwoCase,
    /// With the stages' anticipated cross-coupling `Q_A` at `N_mc` added at
    /// API 617's placement, and the placement's reason; `None` without
    /// stage data.
    pub anticipated: Option<(Vec<Stage>, String, LevelTwoCase)>,
}

/// Forward modes of `coupled` (the linear rotor with `q` at `sites`) at
/// `speed`, each with its pads at its own eigenvalue when the equilibrium
/// has pads, by damped frequency, and the growing overdamped roots.
fn forward_modes(
    rotor: &Rotor,
    linear: &Rotor,
    pads: Option<&crate::solver::Equilibrium>,
    speed: f64,
    (sites, q): (&[usize], f64),
    count: usize,
) -> Result<(Vec<Mode>, Vec<OverdampedRoot>), StabilityError> {
    let coupled = with_cross_coupling(linear, sites, q)?;
    let options = ModalOptions {
        modes: count,
        ..ModalOptions::default()
    };
    let analysis = modal_analysis(&coupled, speed, &options)?;
    let diverging: Vec<OverdampedRoot> = analysis
        .overdamped
        .into_iter()
        .filter(OverdampedRoot::is_growing)
        .collect();
    let modes = match pads {
        None => analysis.modes,
        Some(eq) => own_modes_with_cross_coupling(rotor, (eq, speed), analysis.modes, (sites, q))?,
    };
    let mut out: Vec<Mode> = modes
        .into_iter()
        .filter(|m| m.whirl == Whirl::Forward)
        .collect();
    out.sort_by(|a, b| a.damped_frequency.total_cmp(&b.damped_frequency));
    Ok((out, diverging))
}

/// The judged modes of one eigenproblem: asks for `count` modes, doubling
/// until one lies above the limit (or [`MAX_MODES`]), and keeps the first
/// forward mode and every forward mode below `limit` (rad/s).
fn judged_case(
    rotor: &Rotor,
    linear: &Rotor,
    pads: Option<&crate::solver::Equilibrium>,
    speed: f64,
    (sites, q): (&[usize], f64),
    (count, limit): (usize, f64),
) -> Result<LevelTwoCase, StabilityError> {
    let mut count = count.max(2);
    let (all, diverging) = loop {
        let (all, diverging) = forward_modes(rotor, linear, pads, speed, (sites, q), count)?;
        let reached = all.last().is_some_and(|m| m.damped_frequency > limit);
        if reached || count >= MAX_MODES {
            break (all, diverging);
        }
        count *= 2;
    };
    let modes: Vec<Mode> = all
        .into_iter()
        .enumerate()
        .filter(|(k, m)| *k == 0 || m.damped_frequency < limit)
        .map(|(_, m)| m)
        .collect();
    if modes.is_empty() {
        return Err(StabilityError::Options(format!(
            "Level II: no forward mode at {speed} rad/s among the first {count}"
        )));
    }
    Ok(LevelTwoCase {
        cross_coupling: q,
        sites: sites.to_vec(),
        modes,
        diverging,
    })
}

/// The Level II analysis of `rotor` at its maximum continuous speed `mcs`
/// (rad/s): the model as built and, with `stages`, with their `Q_A` at
/// `mcs` added at API 617's placement (see the module's notes); `count`
/// modes asked of the eigen-solver at first.
pub fn level_two(
    rotor: &Rotor,
    mcs: f64,
    stages: &[Stage],
    count: usize,
) -> Result<LevelTwo, StabilityError> {
    if !(mcs.is_finite() && mcs != 0.0) {
        return Err(StabilityError::Options(format!(
            "Level II needs a nonzero maximum continuous speed, got {mcs} rad/s"
        )));
    }
    for stage in stages {
        stage.data.check()?;
    }
    let limit = LEVEL_II_FREQUENCY_LIMIT * mcs.abs();
    let (linear, equilibrium) = linearized_from(rotor, mcs, mcs, None)?;
    let pads = with_pads(equilibrium);
    let as_built = judged_case(
        rotor,
        &linear,
        pads.as_ref(),
        mcs,
        (&[], 0.0),
        (count, limit),
    )?;
    let anticipated = match anticipated(stages, mcs) {
        Some(qa) => {
            let (sites, why) = api617_placement(rotor);
            let case = judged_case(
                rotor,
                &linear,
                pads.as_ref(),
                mcs,
                (&sites, qa),
                (count, limit),
            )?;
            Some((stages.to_vec(), why, case))
        }
        None => None,
    };
    Ok(LevelTwo {
        speed: mcs,
        frequency_limit: limit,
        as_built,
        anticipated,
    })
}
