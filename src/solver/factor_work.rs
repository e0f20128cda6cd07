//! A factorization of the linear part of a step (its LU and Schur data,
//! [`super::factor`]) and the storage every refactorization reuses, with the
//! factorizations set aside for the steps and speeds that come back.

use crate::linalg::{BandLu, BandMatrix};
use crate::rotor::Rotor;

/// Factorized linear part and its Schur data.
#[derive(Debug)]
pub(super) struct Factor {
    /// Step size `h` it was formed for (s); 0 for the static stiffness.
    pub step: f64,
    /// Spin speed `Ω` it was formed at (rad/s).
    pub speed: f64,
    pub lu: BandLu<f64>,
    /// `G = Eᵀ A⁻¹ E`, row-major `s_j × s_j` (the journal block of the inverse).
    pub g: Vec<f64>,
    /// `C + Ω G` at the factor's speed (for the Newmark effective load).
    pub damping: BandMatrix<f64>,
    /// `Z = A⁻¹ E` column by column (`n` per journal coordinate) when applying it costs
    /// less than a banded solve (few journal DOFs); empty otherwise.
    pub z: Vec<f64>,
}

/// Storage reused by every refactorization (no allocation when refactoring
/// once the set-aside factorizations are made).
#[derive(Debug)]
pub(super) struct FactorWork {
    /// `A` assembled before it is factored.
    pub a: BandMatrix<f64>,
    /// Unit vector, then column of `A⁻¹`, when forming `G`.
    pub column: Vec<f64>,
    /// Factorizations replaced by another, oldest first, at most `capacity`:
    /// `A` depends on nothing but the step and the speed (the rotor's
    /// matrices never change), so one set aside for exactly (bit for bit)
    /// the step and speed a step asks for is the factorization it would
    /// form, and is taken instead. Accuracy-controlled steps come back to
    /// the same few sizes (a communication interval split into 2, 3, 4 …
    /// equal steps).
    pub(super) set_aside: Vec<Factor>,
    /// [`SET_ASIDE_BYTES`] over the storage of one factorization, at most
    /// [`SET_ASIDE_COUNT`].
    pub(super) capacity: usize,
    /// [`GYROSCOPIC_PHASE_BAND`], the band within which a factorization at
    /// another speed is kept (`Simulator::prepare_factor`).
    pub(super) phase_band: f64,
}

/// Gyroscopic phase `|ΔΩ| h` (rad) between a step's speed and that of a
/// factorization of its step size within which the condensed step keeps the
/// factorization and corrects for the gyroscopic term instead
/// (`Simulator::gyroscopic_correction`). The term left out of `A` is
/// `(2/h) ΔΩ G` against `(4/h²) M`, so `ΔΩ h` measures it: what the
/// correction leaves is of that order relative to a correction already
/// within the Newton tolerance (a larger one refactors). Against the relative
/// band of 1e-4 it replaces (`|ΔΩ| ≤ 1e-4 |Ω|`, which refactored every step
/// of a start-up, its speed 0 at first), at 1e-3 a linear run-up from rest
/// to the rated speed in 10 s (first 4 s, equal steps of a quarter of the
/// FMU's largest; `docs/solver.md`) makes 0.006–0.04 factorizations a step
/// instead of 1.0, and the torque-driven hydro unit's coast from 150 rpm
/// 0.007 instead of 0.043 (0.009 at 1e-4; its displacements within 3.1e-8
/// of their range of a run at a Newton tolerance of 1e-12, 2.0e-8 at 1e-4,
/// 3.7e-9 with the relative band, 2.4e-9 refactoring every step).
pub(super) const GYROSCOPIC_PHASE_BAND: f64 = 1e-3;

/// Largest number of factorizations set aside.
const SET_ASIDE_COUNT: usize = 8;

/// Memory the set-aside factorizations may take together (bytes).
const SET_ASIDE_BYTES: usize = 8 << 20;

impl FactorWork {
    /// Buffers for `rotor`.
    pub fn new(rotor: &Rotor) -> Self {
        let a = rotor.stiffness.zeroed_like();
        let n = rotor.dof_count();
        // The LU (2 kl + ku + 1 rows, and its rows copied for the
        // substitutions, kl + ku), `C + Ω G` (kl + ku + 1) and `Z` (at most
        // kl + ku columns) of one factorization.
        let rows = 5 * (a.kl() + a.ku()) + 2;
        let bytes = (rows * n * std::mem::size_of::<f64>()).max(1);
        Self {
            a,
            column: vec![0.0; n],
            set_aside: Vec::new(),
            capacity: (SET_ASIDE_BYTES / bytes).min(SET_ASIDE_COUNT),
            phase_band: GYROSCOPIC_PHASE_BAND,
        }
    }

    /// Take the factorization set aside for exactly `step` and `speed`.
    pub(super) fn recall(&mut self, step: f64, speed: f64) -> Option<Factor> {
        let i = self.set_aside.iter().position(|f| {
            f.step.to_bits() == step.to_bits() && f.speed.to_bits() == speed.to_bits()
        })?;
        Some(self.set_aside.remove(i))
    }

    /// Set `factor` aside; returns the storage of the one it displaces
    /// (the oldest, when `capacity` are set aside), or `factor` itself when
    /// none may be kept.
    pub(super) fn set_aside(&mut self, factor: Factor) -> Option<Factor> {
        if self.capacity == 0 {
            return Some(factor);
        }
        let displaced = (self.set_aside.len() == self.capacity).then(|| self.set_aside.remove(0));
        self.set_aside.push(factor);
        displaced
    }
}
