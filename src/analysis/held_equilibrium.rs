//! The equilibrium the linear analyses linearize about: one the bearings
//! hold (issue 45).
//!
//! A magnetic pull stiffer than the unloaded films (or a seal of negative
//! stiffness) makes the centred equilibrium of a vertical machine on
//! unpreloaded pads statically unstable: the rotor linearized there with the
//! pad tilts as coordinates ([`super::pad_eigen`]) has a real root `λ > 0`
//! (divergence), and the transient leaves the centre for a point where the
//! films, stiffening with eccentricity, balance the pull. The statics
//! follow the machine there, as the machine does: from the centre displaced
//! along the divergence mode `v` of the largest root (its rotor part, made
//! real, largest entry positive) until the journal moved most relative to its
//! clearance sits at 5 % of its resting gap, the nonlinear transient at the
//! speed (unbalance and harmonic loads off; the CLI's accuracy-controlled
//! steps) runs in windows of two e-foldings of the slowest divergence root
//! (0.05–5 s, at most 12 windows); after each, Newton starts from the
//! window's mean displacement (the rest point of a settled transient, the
//! centre of a limit cycle). The first equilibrium reached away from the centre
//! that the static check accepts and at which no non-oscillating root grows is
//! taken; its own whirl stability is what the analyses then judge. For an
//! axisymmetric machine such equilibria form a ring: the divergence root is
//! then repeated, and the one the transient along `v` reaches is taken, the
//! same on every run (the note says so). With none reached the statics say
//! so and name the elements of negative stiffness.
//!
//! Only a rotor with an element of negative direct stiffness is examined (a
//! dense eigensolve per equilibrium): every other rotor's equilibrium, and
//! every stable one, comes back as the solver found it, bit for bit.

use nalgebra::Complex;

use crate::model::Drive;
use crate::rotor::Rotor;
use crate::rotor::elements::bearing_dofs;
use crate::solver::{
    Equilibrium, Simulator, SolverError, SolverOptions, equilibrium, equilibrium_near,
    equilibrium_unchecked, line_equilibrium,
};

use crate::solver::time_step::{DEFAULT_LOCAL_ERROR_TOLERANCE, largest_adaptive_step};

use super::modal::NON_OSCILLATING_DAMPING_RATIO;
use super::pad_eigen::{eigenvalues_of, rotor_vector, state_matrix_with_pads};

type C64 = Complex<f64>;

/// Fraction of the resting gap the most displaced journal starts at.
const START_FRACTION: f64 = 0.05;
/// Windows of the transient, each `WINDOW_GROWTHS` e-foldings of the slowest
/// divergence long (within `MIN_WINDOW`, `MAX_WINDOW` s), sampled `SAMPLES`
/// times.
const WINDOWS: usize = 12;
const WINDOW_GROWTHS: f64 = 2.0;
const MIN_WINDOW: f64 = 0.05;
const MAX_WINDOW: f64 = 5.0;
const SAMPLES: usize = 20;
/// Newton's relative residual at the equilibrium taken (the analyses' default
/// is 1e-8).
const POLISH_TOLERANCE: f64 = 1e-11;

/// How the statics left a statically unstable equilibrium.
#[derive(Debug, Clone, PartialEq)]
pub struct OffCentre {
    /// Spin speed (rad/s).
    pub speed: f64,
    /// Growth rates (1/s) of the real roots of the equilibrium left, largest
    /// first.
    pub divergence: Vec<f64>,
    /// Elements of negative direct stiffness and that stiffness (N/m).
    pub culprits: Vec<(String, f64)>,
    /// Whether the largest divergence root is repeated (an axisymmetric
    /// machine: a ring of equilibria, one taken).
    pub ring: bool,
    /// Every nonlinear bearing with contact at the equilibrium taken: name, journal
    /// displacement relative to the housing `(x, y)` (m) and its ratio to
    /// the resting gap in that direction (`e/C`).
    pub journals: Vec<(String, [f64; 2], f64)>,
}

impl OffCentre {
    /// One line for every command that linearizes.
    pub fn describe(&self) -> String {
        let rpm = self.speed * 30.0 / std::f64::consts::PI;
        let rates = self
            .divergence
            .iter()
            .map(|r| format!("{r:.4}"))
            .collect::<Vec<_>>()
            .join(", ");
        let culprits = self
            .culprits
            .iter()
            .map(|(name, k)| format!("{name} ({k:.4e} N/m)"))
            .collect::<Vec<_>>()
            .join(", ");
        let journals = self
            .journals
            .iter()
            .map(|(name, d, ratio)| {
                format!(
                    "{name} e/C = {ratio:.4} at {:.1}°",
                    d[1].atan2(d[0]).to_degrees()
                )
            })
            .collect::<Vec<_>>()
            .join(", ");
        let ring = if self.ring {
            " (the machine is axisymmetric: the equilibria form a ring, the one along the divergence mode is taken)"
        } else {
            ""
        };
        format!(
            "at {rpm:.6} rpm the centred equilibrium is statically unstable (it diverges at {rates} 1/s: the negative stiffness of {culprits}); linearized about the equilibrium off it where the bearings hold the rotor{ring}: {journals} (angles from x toward y)"
        )
    }
}

/// The static equilibrium of `rotor` at `speed` (rad/s), started from
/// `start` (or the undeflected rotor), that the bearings hold: the solver's
/// own when it is stable, else the one off it (see the module docs) and how
/// it was reached.
pub fn held_equilibrium(
    rotor: &Rotor,
    speed: f64,
    start: Option<&Equilibrium>,
) -> Result<(Equilibrium, Option<OffCentre>), SolverError> {
    let options = SolverOptions::default();
    let (first, refused) = match line_equilibrium(rotor, speed, &options, start) {
        Ok(eq) => (eq, None),
        Err(SolverError::StaticallyUnstable(why)) => (
            equilibrium_unchecked(rotor, speed, &options, start)?,
            Some(why),
        ),
        Err(e) => return Err(e),
    };
    let culprits = negative_elements(rotor, &first);
    // The solver's verdict stands where nothing can be followed: no
    // element of negative stiffness, no divergence (or no dense solve).
    let unchanged = |first: Equilibrium, refused: Option<String>| match refused {
        None => Ok((first, None)),
        Some(why) => Err(SolverError::StaticallyUnstable(why)),
    };
    if culprits.is_empty() {
        return unchanged(first, refused);
    }
    let Ok((divergence, f)) = divergence_roots(rotor, &first, speed) else {
        return unchanged(first, refused);
    };
    if divergence.is_empty() {
        return unchanged(first, refused);
    }
    match follow(rotor, speed, &first, (&divergence, &f)) {
        Some(found) => {
            let ring = divergence
                .get(1)
                .is_some_and(|r| (r - divergence[0]).abs() <= 1e-6 * divergence[0]);
            let journals = journals(rotor, &found);
            Ok((
                found,
                Some(OffCentre {
                    speed,
                    divergence,
                    culprits,
                    ring,
                    journals,
                }),
            ))
        }
        None => match refused {
            Some(why) => Err(SolverError::StaticallyUnstable(why)),
            None => {
                let rpm = speed * 30.0 / std::f64::consts::PI;
                let names = culprits
                    .iter()
                    .map(|(name, k)| format!("{name} ({k:.4e} N/m)"))
                    .collect::<Vec<_>>()
                    .join(", ");
                Err(SolverError::StaticallyUnstable(format!(
                    "the equilibrium at {rpm:.6} rpm is statically unstable (it diverges at {:.4} 1/s) and the transient from it along the divergence mode reached no equilibrium the bearings hold: the negative stiffness of {names} exceeds what the films hold",
                    divergence[0]
                )))
            }
        },
    }
}

/// The equilibrium off `first` (statically unstable: growth rates
/// `divergence`, largest first, of the state matrix `f`) that the
/// transient along the divergence mode reaches (see the module docs),
/// polished; `None` when the mode moves no journal in a bearing with a
/// clearance, the transient fails or no window reaches one.
fn follow(
    rotor: &Rotor,
    speed: f64,
    first: &Equilibrium,
    (divergence, f): (&[f64], &nalgebra::DMatrix<f64>),
) -> Option<Equilibrium> {
    let options = SolverOptions::default();
    let largest = *divergence.first()?;
    let slowest = *divergence.last()?;
    let mode = real_mode(&rotor_vector(f, rotor.dof_count(), C64::new(largest, 0.0))?);
    let bearings: Vec<usize> = first.bearings.iter().map(|(b, _)| *b).collect();
    let worst = gap_ratio(rotor, &bearings, &mode).filter(|r| *r > 0.0)?;
    let start = START_FRACTION / worst;
    let mut sim = transient(rotor, speed).ok()?;
    let mut state = sim.state().clone();
    for ((u, u_first), v) in state.u.iter_mut().zip(&first.displacement).zip(&mode) {
        *u = u_first + start * v;
    }
    state.ud.fill(0.0);
    sim.set_state(state).ok()?;
    sim.consistent_acceleration().ok()?;
    let window = (WINDOW_GROWTHS / slowest).clamp(MIN_WINDOW, MAX_WINDOW);
    let reach = mode.iter().fold(0.0_f64, |m, v| m.max((start * v).abs()));
    for _ in 0..WINDOWS {
        // The mean displacement over a window: the point a settled
        // transient rests at, the centre of a limit cycle.
        let t0 = sim.time();
        let mut mean = vec![0.0; first.displacement.len()];
        for k in 1..=SAMPLES {
            sim.advance_to(t0 + window * k as f64 / SAMPLES as f64)
                .ok()?;
            for (m, u) in mean.iter_mut().zip(&sim.state().u) {
                *m += u / SAMPLES as f64;
            }
        }
        let Ok(found) = equilibrium_near(rotor, speed, &options, &mean) else {
            continue;
        };
        let moved = distance(&found, first);
        let diverges = divergence_roots(rotor, &found, speed).map_or(true, |(d, _)| !d.is_empty());
        if moved <= reach || diverges {
            continue;
        }
        // Polished: the force balance to round-off of the load.
        let polish = SolverOptions {
            tolerance: POLISH_TOLERANCE,
            ..options
        };
        return Some(match equilibrium(rotor, speed, &polish, Some(&found)) {
            Ok(polished) if distance(&polished, &found) <= 1e-6 * moved => polished,
            _ => found,
        });
    }
    None
}

/// The largest difference of two equilibria's displacements (m, rad).
fn distance(a: &Equilibrium, b: &Equilibrium) -> f64 {
    a.displacement
        .iter()
        .zip(&b.displacement)
        .fold(0.0_f64, |m, (x, y)| m.max((x - y).abs()))
}

/// A simulator of `rotor` held at `speed` (rad/s) with unbalance and
/// harmonic loads off, from its start.
fn transient(rotor: &Rotor, speed: f64) -> Result<Simulator, SolverError> {
    let mut model = rotor.model.clone();
    model.drive = Drive::Speed;
    let free = Rotor::new(model).map_err(|e| SolverError::Input(e.to_string()))?;
    // The CLI's and the FMU's accuracy-controlled steps.
    let options = SolverOptions {
        time_step: largest_adaptive_step(&free.model, Some(speed.abs())),
        local_error_tolerance: DEFAULT_LOCAL_ERROR_TOLERANCE,
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
    Ok(sim)
}

/// The elements of negative direct stiffness at `eq`: linear ones (a
/// magnetic pull, a seal or table of negative stiffness) and nonlinear
/// bearings whose direct stiffness is negative there, beyond round-off of the
/// rotor's own stiffness.
fn negative_elements(rotor: &Rotor, eq: &Equilibrium) -> Vec<(String, f64)> {
    let floor = -1e-9
        * (0..rotor.dof_count())
            .map(|i| rotor.stiffness.get(i, i).abs())
            .fold(0.0, f64::max);
    let mut out = rotor.negative_stiffness.clone();
    for (bearing, eval) in &eq.bearings {
        let k = eval.k(0, 0).min(eval.k(1, 1));
        if k < floor {
            out.push((rotor.model.bearings[*bearing].name.clone(), k));
        }
    }
    out
}

/// The growth rates (1/s) of the non-oscillating roots of the rotor
/// linearized at `eq` with the pad coordinates that grow (largest first;
/// a pair of a near-zero frequency counted once), and its state matrix.
fn divergence_roots(
    rotor: &Rotor,
    eq: &Equilibrium,
    speed: f64,
) -> Result<(Vec<f64>, nalgebra::DMatrix<f64>), SolverError> {
    let eigen = |e: super::pad_eigen::PadEigenError| SolverError::Static(e.to_string());
    let f = state_matrix_with_pads(rotor, eq, speed).map_err(eigen)?;
    let roots = eigenvalues_of(&f).map_err(eigen)?;
    let scale = roots.iter().fold(0.0_f64, |a, l| a.max(l.norm()));
    // Non-oscillating as `rotor modes` lists them (damping ratio ≥ 0.999,
    // one of a conjugate pair) and growing.
    let real_part = (1.0 - NON_OSCILLATING_DAMPING_RATIO.powi(2)).sqrt();
    let mut growing: Vec<f64> = roots
        .iter()
        .filter(|l| {
            l.im.abs() <= real_part * l.norm() + 1e-12 * scale && l.im >= 0.0 && l.re > 1e-9 * scale
        })
        .map(|l| l.re)
        .collect();
    growing.sort_by(|a, b| b.total_cmp(a));
    Ok((growing, f))
}

/// A real vector spanning the eigenvector `v` of a real root: `v` turned so
/// that its largest entry is real and positive, its real part.
fn real_mode(v: &[C64]) -> Vec<f64> {
    let peak = v
        .iter()
        .copied()
        .max_by(|a, b| a.norm().total_cmp(&b.norm()))
        .unwrap_or(C64::new(1.0, 0.0));
    let turn = if peak.norm() > 0.0 {
        peak.conj() / peak.norm()
    } else {
        C64::new(1.0, 0.0)
    };
    v.iter().map(|z| (z * turn).re).collect()
}

/// The journal displacement relative to the housing of every nonlinear
/// bearing in `u` (rotor DOFs), with the bearing's model index.
fn journal_displacements(rotor: &Rotor, bearings: &[usize], u: &[f64]) -> Vec<(usize, [f64; 2])> {
    bearings
        .iter()
        .map(|&b| {
            let dofs = bearing_dofs(&rotor.dofs, &rotor.model.bearings[b]);
            let at = |k: usize| -> f64 {
                let journal = dofs[k].map_or(0.0, |i| u[i]);
                let housing = dofs.get(2 + k).copied().flatten().map_or(0.0, |i| u[i]);
                journal - housing
            };
            (b, [at(0), at(1)])
        })
        .collect()
}

/// The ratio of a journal displacement `d` (m) to bearing `b`'s resting gap
/// in its direction; `None` for a bearing without contact.
fn ratio_to_gap(rotor: &Rotor, b: usize, d: [f64; 2]) -> Option<f64> {
    let norm = d[0].hypot(d[1]);
    if norm == 0.0 {
        return Some(0.0);
    }
    let bearing = rotor.model.bearings[b].kind.build();
    let (gap, _) = bearing.resting_contact([d[0] / norm, d[1] / norm])?;
    (gap > 0.0).then_some(norm / gap)
}

/// The largest ratio of journal displacement to resting gap that the
/// displacement `u` gives over `bearings` (model indices).
fn gap_ratio(rotor: &Rotor, bearings: &[usize], u: &[f64]) -> Option<f64> {
    journal_displacements(rotor, bearings, u)
        .into_iter()
        .filter_map(|(b, d)| ratio_to_gap(rotor, b, d))
        .reduce(f64::max)
}

/// Every nonlinear bearing at `eq`: name, journal displacement and `e/C`.
fn journals(rotor: &Rotor, eq: &Equilibrium) -> Vec<(String, [f64; 2], f64)> {
    let bearings: Vec<usize> = eq.bearings.iter().map(|(b, _)| *b).collect();
    journal_displacements(rotor, &bearings, &eq.displacement)
        .into_iter()
        .filter_map(|(b, d)| {
            let ratio = ratio_to_gap(rotor, b, d)?;
            Some((rotor.model.bearings[b].name.clone(), d, ratio))
        })
        .collect()
}
