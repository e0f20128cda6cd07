//! The buffers and iteration memory of the condensed Newton on the journal
//! coordinates ([`super::newton`]), reused by every step.

use super::line_search::Backtrack;
use super::sites::Sites;
use super::slow_pads::SlowPads;

/// Buffers of the condensed Newton on the journal coordinates: the iterate
/// `j` (set to the predictor before the first iteration), bearing forces `F_j`,
/// pad terms `K_jp K_pp⁻¹ (−F_p)`, condensed 2×2 stiffnesses (4 per bearing),
/// the matrix `I + G K_c` with its pivots, and the right-hand side / increment.
#[derive(Debug)]
pub(super) struct CondensedWork {
    /// The journal coordinates `j = Eᵀ u` of the iterate.
    pub j: Vec<f64>,
    pub(super) fj: Vec<f64>,
    pub(super) wv: Vec<f64>,
    pub(super) kc: Vec<f64>,
    pub(super) cj: Vec<f64>,
    pub(super) cj_piv: Vec<usize>,
    pub(super) cj_rhs: Vec<f64>,
    /// The last increment, its line search and the stall count.
    pub(super) search: Backtrack,
    /// The pads' previous increments, for the slow-contraction rule.
    pub(super) slow: SlowPads,
    /// Whether the next step settles each pad on its own balance in every
    /// iteration ([`super::pad_balance`]): set when an iteration contracts
    /// slowly, cleared after a step whose pads all balanced within
    /// [`BALANCED_EVALUATIONS`](crate::solver::newton::BALANCED_EVALUATIONS) film evaluations each.
    pub(super) balancing: bool,
    /// Whether the last step ended on its iterate: the next step's first
    /// chord iteration then also makes the bearings' reports
    /// (`Bearing::output`), which such a step's outputs take. Either pass gives
    /// the same bits, so this choice of work changes no result.
    pub(super) last_on_iterate: bool,
    /// Steps left in which the condensed Newton tries no chord iteration,
    /// set to [`CHORD_PAUSE`](crate::solver::newton::CHORD_PAUSE) when one is refused.
    pub(super) chord_pause: u32,
    /// Set by a step whose gyroscopic correction moved a journal by more
    /// than the Newton tolerance: the step is taken again on a factorization
    /// at its own speed (`Simulator::gyroscopic_correction`).
    pub(super) gyroscopic_excess: bool,
}

impl CondensedWork {
    /// Buffers for the journal and pad DOFs of `sites`.
    pub fn new(sites: &Sites) -> Self {
        let n_journal = sites.n_journal;
        Self {
            j: vec![0.0; n_journal],
            search: Backtrack::new(n_journal, sites.n_internal),
            slow: SlowPads::new(sites.n_internal),
            fj: vec![0.0; n_journal],
            wv: vec![0.0; n_journal],
            kc: vec![0.0; 2 * n_journal],
            cj: vec![0.0; n_journal * n_journal],
            cj_piv: vec![0; n_journal],
            cj_rhs: vec![0.0; n_journal],
            balancing: false,
            last_on_iterate: false,
            chord_pause: 0,
            gyroscopic_excess: false,
        }
    }
}

impl CondensedWork {
    /// Whether the next step settles each pad on its own balance.
    pub fn balancing(&self) -> bool {
        self.balancing
    }

    /// Restore [`CondensedWork::balancing`] with a state (`SimState::pad_balancing`).
    pub fn set_balancing(&mut self, on: bool) {
        self.balancing = on;
    }

    /// Steps left without chord iterations ([`CondensedWork::chord_pause`]).
    pub fn chord_pause(&self) -> u32 {
        self.chord_pause
    }

    /// Restore [`CondensedWork::chord_pause`] with a state (`SimState::chord_pause`).
    pub fn set_chord_pause(&mut self, steps: u32) {
        self.chord_pause = steps;
    }
}
