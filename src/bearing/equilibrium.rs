//! Static equilibrium of a journal (and of a tilting-pad bearing's pads) under a
//! steady load, by Newton's method on the closed-form forces and Jacobians, and
//! the linearized coefficients there, with internal coordinates condensed.

use nalgebra::{Complex, DMatrix, DVector, Matrix2, Vector2};

use super::{Bearing, BearingError, BearingEval};

/// A converged equilibrium.
#[derive(Debug, Clone, PartialEq)]
pub struct Equilibrium {
    /// Generalized coordinates `[x, y, internal…]` (m).
    pub q: Vec<f64>,
    /// Forces and Jacobians there.
    pub eval: BearingEval,
    /// Newton iterations used.
    pub iterations: usize,
}

impl Equilibrium {
    /// Journal position (m).
    pub fn position(&self) -> Vector2<f64> {
        Vector2::new(self.q[0], self.q[1])
    }
}

/// Why no equilibrium was found.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum EquilibriumError {
    /// The bearing could not be evaluated.
    #[error(transparent)]
    Bearing(#[from] BearingError),
    /// Newton's method did not converge.
    #[error(
        "journal equilibrium: no convergence after {iterations} iterations (residual {residual:.3e} N)"
    )]
    NotConverged { iterations: usize, residual: f64 },
    /// The stiffness is singular (e.g. zero speed: a squeeze film carries no static load).
    #[error(
        "journal equilibrium: singular bearing stiffness (a film at zero speed carries no static load)"
    )]
    Singular,
}

/// Coordinates where the bearing's forces balance `load` (the steady force applied
/// to the journal, N) with all velocities zero: `Q(q) + [load, 0…] = 0`.
///
/// Newton steps `δ = K⁻¹ (Q + load)` with backtracking keep the journal inside
/// the radius `scale` and the residual decreasing; converged when
/// `|Q + load| ≤ 1e-10 |load|`. A bearing's own start
/// ([`Bearing::equilibrium_start`], none for the closed-form films) is tried
/// first. Then the start is the centred journal with each
/// internal coordinate (a pad's tilt) at the bearing's own guess
/// ([`Bearing::guess_internal`]: the tilt of zero pivot moment); when Newton
/// stalls from there, the load is applied in eight increments, each solved from
/// the previous equilibrium (continuation in load). The centre can be a
/// degenerate start — pads without preload around a centred journal have a
/// uniform film and carry nothing at any small tilt — so when that fails too,
/// the continuation starts again from the journal a tenth of its clearance
/// along the load, the pads at their zero-moment tilts there, and every
/// Newton step re-seats a pad left carrying nothing where a loaded tilt exists
/// ([`Bearing::reseat_internal`]). A heavy load at low speed can still defeat
/// that path (a pad's loaded branch folds away on the way up in load): the
/// last attempt solves the bearing at 1.25, 1.56, 1.95 or 2.44 times the speed
/// the same way and steps the speed back down in eight geometric steps, each
/// solved from the one before (continuation in speed).
pub fn journal_equilibrium(
    bearing: &dyn Bearing,
    load: Vector2<f64>,
    speed: f64,
    scale: f64,
) -> Result<Equilibrium, EquilibriumError> {
    let n = 2 + bearing.internal_dofs();
    let direct = journal_equilibrium_direct(bearing, load, speed, scale);
    if direct.is_ok() || n == 2 {
        return direct;
    }
    let mut start = vec![0.0; n];
    bearing.guess_internal([0.0, 0.0], speed, &mut start[2..]);
    let continued = continuation(bearing, load, speed, scale, start, false);
    if continued.is_ok() {
        return continued;
    }
    if load.norm() == 0.0 {
        return continued;
    }
    let off_centre = off_centre_continuation(bearing, load, speed, scale);
    if off_centre.is_ok() || speed == 0.0 {
        return off_centre.or(continued);
    }
    for k in 1..=4 {
        let higher = speed * 1.25f64.powi(k);
        let Ok(mut eq) = off_centre_continuation(bearing, load, higher, scale) else {
            continue;
        };
        let steps = 8;
        let mut walked = true;
        for i in 1..=steps {
            let at = higher * (speed / higher).powf(i as f64 / steps as f64);
            let at = if i == steps { speed } else { at };
            match newton(bearing, load, at, scale, eq.q.clone(), true) {
                Ok(next) => eq = next,
                Err(_) => {
                    walked = false;
                    break;
                }
            }
        }
        if walked {
            return Ok(eq);
        }
    }
    off_centre.or(continued)
}

/// The first attempts of [`journal_equilibrium`] alone: Newton from the
/// bearing's own start, then from the centre; for a check that must stay
/// cheap (a film solved numerically), where no equilibrium is an answer.
pub fn journal_equilibrium_direct(
    bearing: &dyn Bearing,
    load: Vector2<f64>,
    speed: f64,
    scale: f64,
) -> Result<Equilibrium, EquilibriumError> {
    let n = 2 + bearing.internal_dofs();
    if let Some(first) = bearing
        .equilibrium_start([load.x, load.y], speed)
        .filter(|q| q.len() == n)
    {
        if let Ok(eq) = newton(bearing, load, speed, scale, first, true) {
            return Ok(eq);
        }
    }
    let mut start = vec![0.0; n];
    bearing.guess_internal([0.0, 0.0], speed, &mut start[2..]);
    newton(bearing, load, speed, scale, start, false)
}

/// Continuation in load from the journal a tenth of its clearance along the
/// load, the pads at their zero-moment tilts there, re-seating pads left on
/// the unloaded branch (see [`journal_equilibrium`]).
fn off_centre_continuation(
    bearing: &dyn Bearing,
    load: Vector2<f64>,
    speed: f64,
    scale: f64,
) -> Result<Equilibrium, EquilibriumError> {
    let n = 2 + bearing.internal_dofs();
    let direction = load / load.norm();
    let reach = bearing
        .resting_contact([direction.x, direction.y])
        .map_or(scale, |(gap, _)| gap.min(scale));
    let mut offset = vec![0.0; n];
    offset[0] = 0.1 * reach * direction.x;
    offset[1] = 0.1 * reach * direction.y;
    bearing.guess_internal([offset[0], offset[1]], speed, &mut offset[2..]);
    continuation(bearing, load, speed, scale, offset, true)
}

/// The load applied in eight increments from `q`, each solved from the
/// previous equilibrium (see [`journal_equilibrium`]).
fn continuation(
    bearing: &dyn Bearing,
    load: Vector2<f64>,
    speed: f64,
    scale: f64,
    mut q: Vec<f64>,
    reseat: bool,
) -> Result<Equilibrium, EquilibriumError> {
    let steps = 8;
    let mut last = Err(EquilibriumError::Singular);
    for k in 1..=steps {
        last = newton(
            bearing,
            load * (k as f64 / steps as f64),
            speed,
            scale,
            q.clone(),
            reseat,
        );
        match &last {
            Ok(eq) => q.clone_from(&eq.q),
            Err(_) => return last,
        }
    }
    last
}

/// Newton's method with backtracking from `q` (see [`journal_equilibrium`]);
/// `reseat`: after every step, pads left on the unloaded branch are re-seated
/// ([`Bearing::reseat_internal`]) and the residual taken there.
fn newton(
    bearing: &dyn Bearing,
    load: Vector2<f64>,
    speed: f64,
    scale: f64,
    mut q: Vec<f64>,
    reseat: bool,
) -> Result<Equilibrium, EquilibriumError> {
    let n = q.len();
    let zero = vec![0.0; n];
    let residual_of = |eval: &BearingEval| -> DVector<f64> {
        DVector::from_fn(n, |i, _| {
            eval.force[i]
                + match i {
                    0 => load.x,
                    1 => load.y,
                    _ => 0.0,
                }
        })
    };
    let tol = 1e-10 * load.norm().max(f64::MIN_POSITIVE);
    let mut eval = BearingEval::new(n);
    bearing.evaluate(&q, &zero, speed, &mut eval)?;
    let mut trial_eval = eval.clone();
    let mut r = residual_of(&eval);
    for iteration in 0..200 {
        if r.norm() <= tol {
            return Ok(Equilibrium {
                q,
                eval,
                iterations: iteration,
            });
        }
        let k = DMatrix::from_row_slice(n, n, &eval.stiffness);
        let step = k.lu().solve(&r).ok_or(EquilibriumError::Singular)?;
        let mut t = 1.0;
        let mut accepted = false;
        for _ in 0..60 {
            let trial: Vec<f64> = q.iter().zip(step.iter()).map(|(a, d)| a + t * d).collect();
            if trial[0].hypot(trial[1]) < scale
                && bearing
                    .evaluate(&trial, &zero, speed, &mut trial_eval)
                    .is_ok()
            {
                let rt = residual_of(&trial_eval);
                if rt.norm() < r.norm() {
                    q = trial;
                    std::mem::swap(&mut eval, &mut trial_eval);
                    r = rt;
                    accepted = true;
                    break;
                }
            }
            t *= 0.5;
        }
        if !accepted {
            break;
        }
        if reseat && bearing.reseat_internal(&mut q, speed) {
            bearing.evaluate(&q, &zero, speed, &mut eval)?;
            r = residual_of(&eval);
        }
    }
    Err(EquilibriumError::NotConverged {
        iterations: 200,
        residual: r.norm(),
    })
}

/// Journal stiffness and damping with the internal coordinates condensed for
/// harmonic motion at `frequency` Ω (rad/s): `Z = K + iΩC`,
/// `Z_red = Z_jj − Z_jp Z_pp⁻¹ Z_pj`, `K_red = Re Z_red`, `C_red = Im Z_red / Ω`,
/// with the internal coordinates' mass in `Z_pp` (`−Ω² M_pp`, [`BearingEval::mass`]). Without internal coordinates this is the
/// journal block itself. At Ω = 0 the damping follows from the derivative
/// `dZ_red/d(iΩ)` at zero.
pub fn condensed_coefficients(eval: &BearingEval, frequency: f64) -> (Matrix2<f64>, Matrix2<f64>) {
    let n = eval.n();
    if n == 2 {
        let j = eval.journal();
        return (j.stiffness, j.damping);
    }
    let reduce = |omega: f64| -> Option<Matrix2<Complex<f64>>> {
        let mut z = DMatrix::from_fn(n, n, |i, j| {
            Complex::new(eval.k(i, j), omega * eval.c(i, j))
        });
        add_inertia(&mut z, eval, Complex::new(0.0, omega));
        let zpp = z.view((2, 2), (n - 2, n - 2)).into_owned();
        let zpj = z.view((2, 0), (n - 2, 2)).into_owned();
        let zjp = z.view((0, 2), (2, n - 2)).into_owned();
        let x = zpp.lu().solve(&zpj)?;
        let red = z.view((0, 0), (2, 2)).into_owned() - zjp * x;
        Some(Matrix2::from_fn(|i, j| red[(i, j)]))
    };
    let omega = if frequency.abs() > 0.0 {
        frequency
    } else {
        1e-6
    };
    match reduce(omega) {
        Some(red) => (red.map(|z| z.re), red.map(|z| z.im / omega)),
        None => {
            let j = eval.journal();
            (j.stiffness, j.damping)
        }
    }
}

/// Stiffness and damping of a bearing whose internal coordinates (pad
/// tilts) are condensed at the complex frequency `s` (1/s) of a
/// mode, `λ = σ + iω`: `Z(s) = K + sC + s²M` (`M` on the internal rows only), `Z_red = Z_jj − Z_jp Z_pp⁻¹ Z_pj`,
/// and the one real pair with `K_eff + s C_eff = Z_red(s)`:
/// `C_eff = Im Z_red / ω`, `K_eff = Re Z_red − σ C_eff`. A mode computed
/// with them at its own eigenvalue is a mode of the rotor with the pads as
/// coordinates (the reduction is exact at `s`); at `s = iΩ` this is
/// [`condensed_coefficients`] at `Ω`, bit for bit.
pub fn condensed_at(eval: &BearingEval, s: Complex<f64>) -> (Matrix2<f64>, Matrix2<f64>) {
    let n = eval.n();
    if n == 2 || s.im == 0.0 {
        return condensed_coefficients(eval, s.im);
    }
    let mut z = DMatrix::from_fn(n, n, |i, j| {
        Complex::new(eval.k(i, j) + s.re * eval.c(i, j), s.im * eval.c(i, j))
    });
    add_inertia(&mut z, eval, s);
    let zpp = z.view((2, 2), (n - 2, n - 2)).into_owned();
    let zpj = z.view((2, 0), (n - 2, 2)).into_owned();
    let zjp = z.view((0, 2), (2, n - 2)).into_owned();
    let Some(x) = zpp.lu().solve(&zpj) else {
        return condensed_coefficients(eval, s.im);
    };
    let red = z.view((0, 0), (2, 2)).into_owned() - zjp * x;
    let c = Matrix2::from_fn(|i, j| red[(i, j)].im / s.im);
    let k = Matrix2::from_fn(|i, j| red[(i, j)].re - s.re * c[(i, j)]);
    (k, c)
}

/// The inertia of the internal coordinates at `s`, `s² M_pp`, onto the
/// diagonal of their block of `z` (nothing for massless ones, so a bearing
/// without masses reduces bit for bit as before).
fn add_inertia(z: &mut DMatrix<Complex<f64>>, eval: &BearingEval, s: Complex<f64>) {
    for (p, &m) in eval.mass.iter().enumerate() {
        if m != 0.0 {
            z[(2 + p, 2 + p)] += s * s * m;
        }
    }
}

/// A point of a bearing's coefficient curve: equilibrium under a load along −y
/// and the linearized coefficients there (internal coordinates condensed
/// synchronously).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CoefficientPoint {
    /// Load magnitude `W` (N), applied along −y.
    pub load: f64,
    /// Eccentricity ratio at equilibrium.
    pub eccentricity: f64,
    /// Attitude angle (rad).
    pub attitude_angle: f64,
    /// Stiffness (N/m).
    pub stiffness: Matrix2<f64>,
    /// Damping (N·s/m).
    pub damping: Matrix2<f64>,
}

/// Equilibrium and coefficients at every load of `loads` (N, along −y) at spin
/// `speed`, internal coordinates (pad tilts) condensed for whirl at `whirl`
/// (rad/s; `speed` for the synchronous coefficients), each load continued
/// from the previous equilibrium (a fresh [`journal_equilibrium`] when that
/// fails). Every load is returned with its point or the reason it has none.
pub fn coefficient_points(
    bearing: &dyn Bearing,
    (speed, whirl): (f64, f64),
    scale: f64,
    loads: &[f64],
) -> Vec<(f64, Result<CoefficientPoint, EquilibriumError>)> {
    let mut previous: Option<Vec<f64>> = None;
    loads
        .iter()
        .map(|&w| {
            let load = Vector2::new(0.0, -w);
            let continued = previous
                .take()
                .map(|q| newton(bearing, load, speed, scale, q, false));
            let eq = match continued {
                Some(Ok(eq)) => Ok(eq),
                _ => journal_equilibrium(bearing, load, speed, scale),
            };
            let point = eq.map(|eq| {
                let (stiffness, damping) = condensed_coefficients(&eq.eval, whirl);
                let report = bearing.report(&eq.q, &vec![0.0; eq.q.len()], speed, &eq.eval);
                previous = Some(eq.q);
                CoefficientPoint {
                    load: w,
                    eccentricity: report.eccentricity,
                    attitude_angle: report.attitude_angle,
                    stiffness,
                    damping,
                }
            });
            (w, point)
        })
        .collect()
}
