//! Factorization of the linear part of a step, `A = K + a1 (C + Ω G) + a0 M`
//! (Newmark `a0 = 4/h²`, `a1 = 2/h`; the static solve uses `K` plus the journal
//! stiffnesses), with the journal block of its inverse `G = Eᵀ A⁻¹ E`, and the
//! policy deciding when a step refactors.

use crate::linalg::{BandLu, BandMatrix, LinalgError};
use crate::rotor::Rotor;

use super::simulator::{Simulator, SolverError};
use super::sites::Coordinate;

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

/// Storage reused by every refactorization (no allocation when refactoring).
#[derive(Debug)]
pub(super) struct FactorWork {
    /// `A` assembled before it is factored.
    pub a: BandMatrix<f64>,
    /// Unit vector, then column of `A⁻¹`, when forming `G`.
    pub column: Vec<f64>,
}

impl FactorWork {
    /// Buffers for `rotor`.
    pub fn new(rotor: &Rotor) -> Self {
        Self {
            a: rotor.stiffness.zeroed_like(),
            column: vec![0.0; rotor.dof_count()],
        }
    }
}

/// Factor `a` and form `G = Eᵀ A⁻¹ E` (one solve per journal coordinate in
/// `coordinates`, the columns of `E`), reusing the storage of `reuse` (no
/// allocation then); `column` is workspace of length `n`.
pub(super) fn make_factor(
    a: &BandMatrix<f64>,
    rotor: &Rotor,
    coordinates: &[Coordinate],
    (step, speed): (f64, f64),
    reuse: Option<Factor>,
    column: &mut [f64],
) -> Result<Factor, LinalgError> {
    let sj = coordinates.len();
    let mut factor = match reuse {
        Some(mut f) => {
            a.lu_into(&mut f.lu)?;
            f
        }
        None => Factor {
            step,
            speed,
            lu: a.lu()?,
            g: vec![0.0; sj * sj],
            damping: rotor.stiffness.zeroed_like(),
            z: if sj <= a.kl() + a.ku() {
                vec![0.0; sj * a.n()]
            } else {
                Vec::new()
            },
        },
    };
    factor.step = step;
    factor.speed = speed;
    factor.damping.assign(&rotor.damping);
    factor.damping.scale_add(speed, &rotor.gyroscopic);
    for (c, coordinate) in coordinates.iter().enumerate() {
        column.fill(0.0);
        for (dof, sign) in coordinate.entries() {
            column[dof] = sign;
        }
        factor.lu.solve_in_place(column);
        for (r, row) in coordinates.iter().enumerate() {
            factor.g[r * sj + c] = row.of(column);
        }
        if !factor.z.is_empty() {
            let n = column.len();
            factor.z[c * n..(c + 1) * n].copy_from_slice(column);
        }
    }
    Ok(factor)
}

/// A factorization at a speed more than 2 % away from `reference` (rad/s) is
/// not reused by the stale path.
pub(super) fn speed_band_changed(reference: f64, speed: f64) -> bool {
    (speed - reference).abs() > 0.02 * reference.abs().max(1.0)
}

impl Simulator {
    /// Factor the Newmark matrix `A = K + a1 (C + Ω G) + a0 M` for step `h` at
    /// speed `speed`, reusing `reuse`'s storage.
    pub(super) fn dynamic_factor(
        &mut self,
        h: f64,
        speed: f64,
        reuse: Option<Factor>,
    ) -> Result<Factor, LinalgError> {
        let (a0, a1) = (4.0 / (h * h), 2.0 / h);
        let rotor = &self.rotor;
        let w = &mut self.factor_work;
        w.a.assign(&rotor.stiffness);
        w.a.scale_add(a1, &rotor.damping);
        w.a.scale_add(a1 * speed, &rotor.gyroscopic);
        w.a.scale_add(a0, &rotor.mass);
        let factor = make_factor(
            &w.a,
            rotor,
            &self.sites.coordinates,
            (h, speed),
            reuse,
            &mut w.column,
        )?;
        self.stats.factorizations += 1;
        Ok(factor)
    }

    /// Make `factor` exact for step `h` at speed `speed1` where that pays off;
    /// returns whether it is exact. A factorization at another step size, or
    /// more than 2 % off in speed, is always redone. Within that band a speed
    /// change is refactored when the journal DOFs are few (≤ 8): one banded LU
    /// plus one solve per journal DOF for `G`, against the stale path's
    /// mat-vecs and two solves per iteration, and 1.5× the iterations on a
    /// Jeffcott run-up (see the test in [`super::newmark`]).
    pub(super) fn prepare_factor(
        &mut self,
        h: f64,
        speed1: f64,
        factor: &mut Option<Factor>,
    ) -> Result<bool, SolverError> {
        let (exact, stale) = match factor.as_ref() {
            None => (false, true),
            Some(f) => (
                (f.step - h).abs() <= 1e-12 * h && f.speed == speed1,
                (f.step - h).abs() > 1e-9 * h || speed_band_changed(f.speed, speed1),
            ),
        };
        if exact {
            return Ok(true);
        }
        if stale || self.sites.n_journal <= self.refactor_journal_limit {
            *factor = Some(self.dynamic_factor(h, speed1, factor.take())?);
            self.schur.ready = false;
            return Ok(true);
        }
        Ok(false)
    }
}
