//! Factorization of the linear part of a step, `A = K + a1 (C + Ω G) + a0 M`
//! (Newmark `a0 = 4/h²`, `a1 = 2/h`; the static solve uses `K` plus the journal
//! stiffnesses), with the journal block of its inverse `G = Eᵀ A⁻¹ E`, and the
//! policy deciding when a step refactors.

use crate::linalg::{BandMatrix, LinalgError};
use crate::rotor::Rotor;

use super::error::SolverError;
use super::factor_work::Factor;
use super::simulator::Simulator;
use super::sites::Coordinate;

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
    /// speed `speed`, or recall the one set aside for exactly them
    /// ([`FactorWork`](super::factor_work::FactorWork)); `reuse`, the factorization it replaces, is set aside,
    /// and the storage of the one that displaces is reused.
    pub(super) fn dynamic_factor(
        &mut self,
        h: f64,
        speed: f64,
        reuse: Option<Factor>,
    ) -> Result<Factor, LinalgError> {
        let w = &mut self.factor_work;
        let recalled = w.recall(h, speed);
        let reuse = reuse.and_then(|f| w.set_aside(f));
        if let Some(factor) = recalled {
            self.stats.factors_recalled += 1;
            return Ok(factor);
        }
        let (a0, a1) = (4.0 / (h * h), 2.0 / h);
        let rotor = &self.rotor;
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
    /// returns whether it is exact. A factorization of the same step within
    /// [`GYROSCOPIC_PHASE_BAND`](super::factor_work::GYROSCOPIC_PHASE_BAND)
    /// of the speed counts as exact: the condensed step
    /// corrects it for the gyroscopic term of the difference. Beyond it, a
    /// factorization at another step size, or more than 2 % off in speed, is
    /// always redone; within 2 % a speed change is refactored when the
    /// journal DOFs are few (≤ 8): one banded LU
    /// plus one solve per journal DOF for `G`, against the stale path's
    /// mat-vecs and two solves per iteration, and 1.5× the iterations on a
    /// Jeffcott run-up (see the test in [`super::newmark`]). It is refactored
    /// too when the bearings have pads: only the exact (condensed) path
    /// settles each pad on its own balance ([`super::pad_balance`]); on the
    /// stale path the unit on brackets (10 journal DOFs, 24 unpreloaded pads)
    /// took 26.6 iterations a step over a 10 s run-up from rest to 300 rpm,
    /// with 37 step halvings, and takes 2.17 with none, in a quarter of the
    /// wall-clock time (`tests/newton_iterations.rs`). And it is refactored
    /// where the new factorization will be kept long enough to pay
    /// ([`Simulator::refactor_pays`]).
    pub(super) fn prepare_factor(
        &mut self,
        h: f64,
        speed1: f64,
        factor: &mut Option<Factor>,
    ) -> Result<bool, SolverError> {
        let (exact, stale) = match factor.as_ref() {
            None => (false, true),
            Some(f) => (
                (f.step - h).abs() <= 1e-12 * h
                    && (speed1 - f.speed).abs() * h <= self.factor_work.phase_band,
                (f.step - h).abs() > 1e-9 * h || speed_band_changed(f.speed, speed1),
            ),
        };
        if exact {
            return Ok(true);
        }
        if stale
            || self.sites.n_journal <= self.refactor_journal_limit
            || self.sites.n_internal > 0
            || self.refactor_pays(h, speed1)
        {
            *factor = Some(self.dynamic_factor(h, speed1, factor.take())?);
            self.schur.ready = false;
            return Ok(true);
        }
        Ok(false)
    }

    /// Whether a factorization at `speed1` pays against the full residual on
    /// the one in hand: it is kept while the speed stays within the phase
    /// band, `band / (|Ω̇ h| h)` steps at this step's speed change, and costs
    /// an LU and a solve per journal DOF (about `n_j + 3` solves), against
    /// at least two solves a step more on the stale path. So a speed that
    /// has settled (no change: kept for good) or moves slowly refactors
    /// once and goes on exactly; a fast run-up of a large rotor keeps the
    /// stale path. (Before the band every speed change refactored, and a
    /// unit with more than 8 journal DOFs and no pads stayed on the stale
    /// path after any speed change within 2 %.)
    fn refactor_pays(&self, h: f64, speed1: f64) -> bool {
        let drift = (speed1 - self.speed_at(self.state.time)).abs() * h;
        self.factor_work.phase_band / drift >= 0.5 * (self.sites.n_journal as f64 + 3.0)
    }

    /// Make `factor` a factorization for exactly step `h` at speed `speed1`
    /// (the damped retry's, and a step whose gyroscopic correction was too
    /// large), refactoring the one in hand if it is not.
    pub(super) fn exact_factor(
        &mut self,
        h: f64,
        speed1: f64,
        factor: &mut Option<Factor>,
    ) -> Result<(), SolverError> {
        let exact = factor
            .as_ref()
            .is_some_and(|f| (f.step - h).abs() <= 1e-12 * h && f.speed == speed1);
        if !exact {
            *factor = Some(self.dynamic_factor(h, speed1, factor.take())?);
            self.schur.ready = false;
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use crate::model::RotorModel;
    use crate::rotor::Rotor;
    use crate::solver::{Simulator, SolverOptions};

    /// The three-guide-bearing unit started from its settled state with the
    /// unbalance at once, accuracy-controlled steps, communication every
    /// 5 ms for 0.3 s: its steps come back to the same sizes (21 of the 53
    /// factorizations recalled, measured), and the factorizations recalled
    /// for them give the run that forms every one anew, bit for bit.
    #[test]
    fn recalled_factorizations_are_the_ones_formed_anew() {
        let run = |capacity: Option<usize>| {
            let path = concat!(
                env!("CARGO_MANIFEST_DIR"),
                "/models/hydro_unit_three_guide.toml"
            );
            let model = RotorModel::from_file(std::path::Path::new(path)).unwrap();
            let options = SolverOptions {
                time_step: 1.0 / 120.0,
                local_error_tolerance: 3e-3,
                ..SolverOptions::default()
            };
            let mut sim = Simulator::new(Rotor::new(model.clone()).unwrap(), options).unwrap();
            if let Some(c) = capacity {
                sim.factor_work.capacity = c;
            }
            sim.set_speed(model.nominal_speed, 0.0).unwrap();
            sim.settle_static().unwrap();
            let mut trace = Vec::new();
            for k in 1..=60 {
                sim.advance_to(k as f64 * 5e-3).unwrap();
                trace.extend(sim.state().u.iter().map(|v| v.to_bits()));
            }
            (trace, sim.stats())
        };
        let (recalled, with) = run(None);
        let (formed, without) = run(Some(0));
        assert_eq!(with.steps, without.steps);
        assert_eq!(without.factors_recalled, 0);
        assert!(with.factors_recalled >= 15, "{with:?}");
        assert_eq!(
            with.factorizations + with.factors_recalled,
            without.factorizations
        );
        assert!(recalled == formed, "the recalled run differs");
    }

    /// A simulator of shipped model `name` driven by its speed, in equal
    /// steps of a quarter of the FMU's largest, keeping a factorization
    /// within the phase band `band`; and its rated speed.
    fn at_quarter_steps(name: &str, band: f64) -> (Simulator, f64) {
        let path = format!("{}/models/{name}.toml", env!("CARGO_MANIFEST_DIR"));
        let mut model = RotorModel::from_file(std::path::Path::new(&path)).unwrap();
        model.drive = crate::model::Drive::Speed;
        let options = SolverOptions {
            time_step: crate::solver::time_step::largest_adaptive_step(&model, None) / 4.0,
            local_error_tolerance: 0.0,
            ..SolverOptions::default()
        };
        let rated = model.nominal_speed;
        let mut sim = Simulator::new(Rotor::new(model).unwrap(), options).unwrap();
        sim.factor_work.phase_band = band;
        (sim, rated)
    }

    /// Start-ups from rest (the static equilibrium at standstill, then a
    /// linear run-up to the rated speed in 10 s, its first 2 s in equal
    /// steps of a quarter of the FMU's largest), on a factorization kept
    /// within `GYROSCOPIC_PHASE_BAND` and corrected for the gyroscopic term,
    /// against one formed at every step's own speed: the hydro unit on plain
    /// bearings (4 journal DOFs) and the train (10, more than the 8 up to
    /// which a speed change within ±2 % refactors: the full residual on the
    /// stale matrix before). The journals agree within the Newton tolerance
    /// (1e-8 of the displacement scale) at every 5 ms (measured 8.2e-3 and
    /// 1.7e-2 of it), and the kept factorizations are at most one in twenty
    /// steps (0.040 and 0.006 a step; 1.0 with the relative band of 1e-4).
    #[test]
    fn start_ups_keep_their_factorization_within_the_newton_tolerance() {
        let run = |name: &str, band: f64| {
            let (mut sim, rated) = at_quarter_steps(name, band);
            if band == 0.0 {
                sim.refactor_journal_limit = usize::MAX;
            }
            sim.set_speed(0.0, 0.0).unwrap();
            sim.settle_static().unwrap();
            sim.set_speed(0.0, rated / 10.0).unwrap();
            let mut trace = Vec::new();
            for k in 1..=400 {
                sim.advance_to(k as f64 * 5e-3).unwrap();
                trace.extend(sim.sites.coordinates.iter().map(|c| c.of(&sim.state.u)));
            }
            let scale = sim.options.tolerance * sim.sites.length_scale;
            (trace, sim.stats(), scale, sim.sites.n_journal)
        };
        for name in ["hydro_unit_plain", "turbine_generator_train"] {
            let (kept, stats, tolerance, n_journal) =
                run(name, crate::solver::factor_work::GYROSCOPIC_PHASE_BAND);
            let (formed, every, _, _) = run(name, 0.0);
            let worst = kept
                .iter()
                .zip(&formed)
                .fold(0.0_f64, |m, (a, b)| m.max((a - b).abs()));
            let per_step = |s: &crate::solver::StepStats| s.factorizations as f64 / s.steps as f64;
            println!(
                "{name} ({n_journal} journal DOFs): {:.3} factorizations a step against {:.3}, journals within {:.2e} of the tolerance",
                per_step(&stats),
                per_step(&every),
                worst / tolerance
            );
            assert!(worst <= tolerance, "{name}: {worst:e} m");
            assert!(per_step(&stats) <= 0.05, "{name}: {stats:?}");
            assert!(per_step(&every) >= 1.0, "{name}: {every:?}");
        }
    }

    /// A speed step of 1 % on the train (10 journal DOFs, no pads, at its
    /// rated speed in equal steps of a quarter of the FMU's largest): the
    /// factorization at the new speed pays for itself (the speed settled,
    /// it is kept for good), so the unit refactors once and goes on with
    /// the condensed Newton, instead of the full residual on the stale
    /// factorization at every step after (what a speed change within 2 %
    /// did before the phase band; its band set to zero here). The two agree
    /// within the Newton tolerance, and the refactored run takes fewer
    /// iterations.
    #[test]
    fn a_speed_step_on_a_large_unit_refactors_once() {
        let run = |band: f64| {
            let (mut sim, rated) = at_quarter_steps("turbine_generator_train", band);
            sim.set_speed(rated, 0.0).unwrap();
            sim.settle_static().unwrap();
            sim.advance_to(0.05).unwrap();
            sim.set_speed(1.01 * rated, 0.0).unwrap();
            let before = sim.stats();
            let mut trace = Vec::new();
            for k in 1..=100 {
                sim.advance_to(0.05 + k as f64 * 5e-3).unwrap();
                trace.extend(sim.sites.coordinates.iter().map(|c| c.of(&sim.state.u)));
            }
            let after = sim.stats();
            let tolerance = sim.options.tolerance * sim.sites.length_scale;
            (
                trace,
                after.factorizations - before.factorizations,
                (after.iterations - before.iterations) as f64 / (after.steps - before.steps) as f64,
                tolerance,
            )
        };
        let (kept, factored, iterations, tolerance) =
            run(crate::solver::factor_work::GYROSCOPIC_PHASE_BAND);
        let (stale, stale_factored, stale_iterations, _) = run(0.0);
        let worst = kept
            .iter()
            .zip(&stale)
            .fold(0.0_f64, |m, (a, b)| m.max((a - b).abs()));
        println!(
            "refactored {factored}× at {iterations:.2} iterations a step; stale {stale_factored}× at {stale_iterations:.2}; journals within {:.2e} of the tolerance",
            worst / tolerance
        );
        assert_eq!(factored, 1);
        assert_eq!(stale_factored, 0);
        assert!(
            iterations < stale_iterations,
            "{iterations} {stale_iterations}"
        );
        assert!(worst <= tolerance, "{worst:e} m");
    }
}
