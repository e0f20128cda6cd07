//! Static equilibrium of a rotor on nonlinear bearings at a spin speed:
//! `K u = f_g + E F_b(Eᵀu, 0, p, 0, Ω)`, `0 = Q_p(Eᵀu, 0, p, 0, Ω)`, by Newton
//! with backtracking on the full static Jacobian `K + E K_b Eᵀ` (pad blocks
//! through a Schur complement on the bearing DOFs). Usable without a transient
//! [`Simulator`](super::Simulator): the linearized analyses call
//! [`equilibrium`] once per speed.

use crate::bearing::Bearing;
use crate::bearing::BearingEval;
use crate::rotor::Rotor;

use super::error::SolverError;
use super::factor::make_factor;
use super::film_start::{film_start, is_offset, pushed_off_centre, reseat_pads};
use super::norm::inf_norm;
use super::options::SolverOptions;
use super::schur::SchurSolve;
use super::sites::{Sites, add_coupling};
use super::static_stability;

/// A static equilibrium (velocities and accelerations zero).
#[derive(Debug, Clone, PartialEq)]
pub struct Equilibrium {
    /// Spin speed (rad/s).
    pub speed: f64,
    /// Rotor displacement on the free DOFs (m, rad).
    pub displacement: Vec<f64>,
    /// Internal coordinates of the nonlinear bearings (pad tilts, m), bearing by
    /// bearing in model order.
    pub tilts: Vec<f64>,
    /// Every nonlinear bearing evaluated at the equilibrium with zero rates:
    /// the model index of the bearing and its forces and Jacobians there.
    pub bearings: Vec<(usize, BearingEval)>,
}

/// The static equilibrium of `rotor` under gravity (when `options.gravity`) at
/// spin `speed` (rad/s), to the relative residual `options.tolerance`.
///
/// Without `start` Newton starts from the undeflected rotor with the bearings'
/// own guess of their pad tilts; with `start` (e.g. the equilibrium at a nearby
/// speed, as in a Campbell sweep) it starts from that displacement and those
/// tilts. A fluid film at zero speed carries no load: the journals then rest
/// on their bushings or pads (the contact law carries them).
///
/// ```
/// use rotor_bearing::model::RotorModel;
/// use rotor_bearing::rotor::Rotor;
/// use rotor_bearing::solver::{SolverOptions, statics::equilibrium};
///
/// let path = concat!(env!("CARGO_MANIFEST_DIR"), "/models/jeffcott.toml");
/// let rotor = Rotor::new(RotorModel::from_file(std::path::Path::new(path))?)?;
/// let options = SolverOptions::default();
/// let at_3000 = equilibrium(&rotor, 3000.0 * std::f64::consts::PI / 30.0, &options, None)?;
/// // Continue to a nearby speed from there.
/// let at_3100 = equilibrium(&rotor, 3100.0 * std::f64::consts::PI / 30.0, &options, Some(&at_3000))?;
/// let sag = at_3100.displacement.iter().fold(0.0_f64, |a, u| a.max(u.abs()));
/// assert!(sag > 0.0 && sag < 1e-3);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn equilibrium(
    rotor: &Rotor,
    speed: f64,
    options: &SolverOptions,
    start: Option<&Equilibrium>,
) -> Result<Equilibrium, SolverError> {
    solve(rotor, speed, options, start_of(rotor, start), true)
}

/// [`equilibrium`] without refusing a statically unstable one: the
/// equilibrium Newton found, whatever the sign of its net stiffness (the
/// start of a search for the equilibria off it, `analysis::held_equilibrium`).
pub fn equilibrium_unchecked(
    rotor: &Rotor,
    speed: f64,
    options: &SolverOptions,
    start: Option<&Equilibrium>,
) -> Result<Equilibrium, SolverError> {
    solve(rotor, speed, options, start_of(rotor, start), false)
}

/// [`equilibrium`] with Newton started from the rotor displacement
/// `displacement` (m, rad, on the free DOFs) and the bearings' own guess of
/// their pad tilts there.
pub fn equilibrium_near(
    rotor: &Rotor,
    speed: f64,
    options: &SolverOptions,
    displacement: &[f64],
) -> Result<Equilibrium, SolverError> {
    if displacement.len() != rotor.dof_count() {
        return Err(SolverError::Input(
            "start displacement does not belong to this rotor (sizes differ)".into(),
        ));
    }
    solve(rotor, speed, options, (displacement.to_vec(), None), true)
}

/// The start `(u0, p0)` of Newton: `start`'s displacement and tilts, or the
/// undeflected rotor and the bearings' guess.
fn start_of(rotor: &Rotor, start: Option<&Equilibrium>) -> (Vec<f64>, Option<Vec<f64>>) {
    let u0 = match start {
        Some(e) => e.displacement.clone(),
        None => vec![0.0; rotor.dof_count()],
    };
    let p0 = start.map(|e| e.tilts.clone());
    (u0, p0)
}

/// The equilibrium from `(u0, p0)`, refused when statically unstable if
/// `check`.
fn solve(
    rotor: &Rotor,
    speed: f64,
    options: &SolverOptions,
    (u0, p0): (Vec<f64>, Option<Vec<f64>>),
    check: bool,
) -> Result<Equilibrium, SolverError> {
    let mut sites = Sites::new(rotor)?;
    if u0.len() != rotor.dof_count() || p0.as_ref().is_some_and(|p| p.len() != sites.n_internal) {
        return Err(SolverError::Input(
            "start equilibrium does not belong to this rotor (sizes differ)".into(),
        ));
    }
    let loads: Vec<f64> = rotor.model.load_inputs().iter().map(|l| l.start).collect();
    let f_ext = static_load(rotor, options, &loads);
    let (displacement, tilts) = if check {
        settle(rotor, &mut sites, speed, options, 0.0, (u0, p0), &f_ext)?
    } else {
        settle_unchecked(rotor, &mut sites, speed, options, 0.0, (u0, p0), &f_ext)?
    };
    let bearings = sites
        .list
        .into_iter()
        .map(|site| (site.index, site.eval))
        .collect();
    Ok(Equilibrium {
        speed,
        displacement,
        tilts,
        bearings,
    })
}

/// Residual buffers of the static Newton.
struct StaticWork {
    /// Gravity load or zero (N).
    f_ext: Vec<f64>,
    /// Rotor residual `f_g + E F_b − K u` (N).
    r: Vec<f64>,
    /// Pad residuals.
    rp: Vec<f64>,
    /// `K u`.
    ku: Vec<f64>,
    zero_u: Vec<f64>,
    zero_p: Vec<f64>,
}

impl StaticWork {
    /// Static residual at `u`, `p` into `r`, `rp`, relative to the largest force
    /// term; the bearings of `sites` are left evaluated there.
    fn residual(
        &mut self,
        rotor: &Rotor,
        sites: &mut Sites,
        (u, p): (&[f64], &[f64]),
        speed: f64,
        time: f64,
    ) -> Result<f64, SolverError> {
        rotor.stiffness.mul_vec(u, &mut self.ku);
        let mut scale = inf_norm(&self.ku).max(inf_norm(&self.f_ext));
        for (r, (f, k)) in self.r.iter_mut().zip(self.f_ext.iter().zip(&self.ku)) {
            *r = f - k;
        }
        let bearings = sites.add_forces(
            u,
            &self.zero_u,
            p,
            &self.zero_p,
            speed,
            time,
            &mut self.r,
            &mut self.rp,
        )?;
        scale = scale.max(bearings);
        let scale = scale.max(f64::MIN_POSITIVE);
        Ok(self.absolute() / scale)
    }

    /// Largest absolute static residual (rotor and pads) of the last evaluation.
    fn absolute(&self) -> f64 {
        inf_norm(&self.r).max(inf_norm(&self.rp))
    }
}

/// Relative size of the journal regularization of the static Jacobian: `k_r =
/// 10⁻⁹ max K_ii` on every journal DOF of a nonlinear bearing. A film at zero
/// speed has no stiffness, so a journal floating in its clearance (a vertical
/// rotor at rest) would make the Jacobian singular; the residual is left exact,
/// so a converged equilibrium does not depend on `k_r`.
const JOURNAL_REST: f64 = 1e-9;

/// The static load: gravity (when `options.gravity`) and the static and port
/// forces of the load inputs `loads`.
pub(super) fn static_load(rotor: &Rotor, options: &SolverOptions, loads: &[f64]) -> Vec<f64> {
    let mut f = if options.gravity {
        rotor.gravity_load.clone()
    } else {
        vec![0.0; rotor.dof_count()]
    };
    rotor.add_static_loads(loads, &mut f);
    f
}

/// The journal regularization `k_r` of the static Jacobian ([`JOURNAL_REST`]).
fn journal_rest(rotor: &Rotor) -> f64 {
    JOURNAL_REST
        * (0..rotor.dof_count())
            .map(|i| rotor.stiffness.get(i, i).abs())
            .fold(0.0, f64::max)
}

/// Newton with backtracking from `u0` (and `p0`, or the bearings' guess of the
/// pad tilts at the journal positions of `u0`); returns the displacement and
/// tilts. `time` (s) only labels bearing errors.
///
/// At standstill a fluid film carries nothing and the journals rest on their
/// bushings or pads: Newton then starts from [`resting_start`] (and, when
/// that fails, from the given start: journals floating in their clearance
/// off offset centres). At any other
/// speed, when Newton from the given start fails or ends with a tilting pad on
/// its unloaded branch where a loaded tilt exists ([`reseat_pads`]), a rotor
/// with tilting pads starts again from the bearings' own equilibria
/// ([`film_start`]), re-seating such pads after every step; then Newton starts
/// from [`resting_start`] (a film too weak to lift the journal off).
/// An equilibrium the machine cannot hold (negative net stiffness,
/// [`static_stability`]) is an error naming the elements.
pub(super) fn settle(
    rotor: &Rotor,
    sites: &mut Sites,
    speed: f64,
    options: &SolverOptions,
    time: f64,
    (u0, p0): (Vec<f64>, Option<Vec<f64>>),
    f_ext: &[f64],
) -> Result<(Vec<f64>, Vec<f64>), SolverError> {
    let outcome = settle_unchecked(rotor, sites, speed, options, time, (u0, p0), f_ext)?;
    static_stability::check(rotor, sites, speed, journal_rest(rotor))?;
    Ok(outcome)
}

/// Rotor displacements and pad tilts of a static equilibrium.
type RotorAndPads = (Vec<f64>, Vec<f64>);

/// Newton from the bearings' own equilibria ([`film_start`]), damped;
/// `None` when they give no start.
fn from_film_start(
    rotor: &Rotor,
    sites: &mut Sites,
    speed: f64,
    options: &SolverOptions,
    time: f64,
    f_ext: &[f64],
) -> Option<Result<RotorAndPads, SolverError>> {
    let (u, p) = film_start(rotor, sites, f_ext, speed)?;
    Some(newton_static(
        rotor,
        sites,
        speed,
        options,
        time,
        (u, Some(p)),
        f_ext,
        true,
    ))
}

/// [`settle`] without the stability check.
fn settle_unchecked(
    rotor: &Rotor,
    sites: &mut Sites,
    speed: f64,
    options: &SolverOptions,
    time: f64,
    (u0, p0): (Vec<f64>, Option<Vec<f64>>),
    f_ext: &[f64],
) -> Result<(Vec<f64>, Vec<f64>), SolverError> {
    // The resting start costs a banded factorization: build it only when used.
    if speed == 0.0 {
        if let Some(u) = resting_start(rotor, sites, f_ext) {
            let rested = newton_static(rotor, sites, speed, options, time, (u, None), f_ext, false);
            if rested.is_ok() {
                return rested;
            }
            // No journal rests after all: a bearing set off the axis within
            // its clearance with nothing pushing the journal onto it (a
            // vertical rotor at rest) floats; Newton from the given start.
            return newton_static(rotor, sites, speed, options, time, (u0, p0), f_ext, false)
                .or(rested);
        }
    }
    let direct = newton_static(rotor, sites, speed, options, time, (u0, p0), f_ext, false);
    let settled = |sites: &Sites, (u, p): &(Vec<f64>, Vec<f64>)| {
        !reseat_pads(sites, u, &mut p.clone(), speed)
    };
    let pads = sites.n_internal > 0;
    let direct = match direct {
        Ok(e) if settled(sites, &e) => {
            let (u, p) = e;
            if !pads || !pushed_off_centre(sites, &u) {
                return Ok((u, p));
            }
            // A pad bearing pushes its journal off its centre: Newton from
            // the bearings' own equilibria; when that finds no held one, the
            // direct equilibrium as before (evaluated again: the sites hold it).
            if let Some(outcome) = from_film_start(rotor, sites, speed, options, time, f_ext) {
                if outcome
                    .as_ref()
                    .is_ok_and(|e| settled(sites, e) && !pushed_off_centre(sites, &e.0))
                {
                    return outcome;
                }
            }
            return newton_static(
                rotor,
                sites,
                speed,
                options,
                time,
                (u, Some(p)),
                f_ext,
                false,
            );
        }
        other => other,
    };
    if let Some(outcome) = pads
        .then(|| from_film_start(rotor, sites, speed, options, time, f_ext))
        .flatten()
    {
        if outcome.as_ref().is_ok_and(|e| settled(sites, e)) {
            return outcome;
        }
    }
    let unsettled = || {
        SolverError::Static(
            "Newton ended with a tilting pad carrying nothing where a loaded tilt exists, and no start found the equilibrium with every pad on its loaded branch".into(),
        )
    };
    match direct {
        Err(e) => match resting_start(rotor, sites, f_ext) {
            Some(u) => {
                let outcome =
                    newton_static(rotor, sites, speed, options, time, (u, None), f_ext, false);
                match outcome {
                    Ok(found) if !pads || settled(sites, &found) => Ok(found),
                    Ok(_) => Err(unsettled()),
                    Err(_) => outcome,
                }
            }
            None => Err(e),
        },
        Ok(_) => Err(unsettled()),
    }
}

/// The rotor resting on its fluid-film bearings, as a start for Newton: each
/// journal held by its contact stiffness `k_c` at its resting gap `g` in the
/// direction `d̂` it is pushed, `(K + Σ k_c E Eᵀ) u = f + Σ k_c E (o + g d̂)`
/// (`o` a bearing's centre off the axis), with `d̂` from the same system
/// without the gaps. `None` without a bearing that can
/// rest on contact, or when no journal is pushed at all.
fn resting_start(rotor: &Rotor, sites: &Sites, f_ext: &[f64]) -> Option<Vec<f64>> {
    let mut a = rotor.stiffness.clone();
    let mut contacts = Vec::new();
    for site in &sites.list {
        if let Some((_, k)) = site.bearing.resting_contact([0.0, -1.0]) {
            for c in &site.journal {
                add_coupling(&mut a, c, c, k);
            }
            contacts.push((site, k));
        }
    }
    if contacts.is_empty() {
        return None;
    }
    let lu = a.lu().ok()?;
    let mut u = f_ext.to_vec();
    // A journal set off the axis rests about its own centre `o`.
    for &(site, k) in contacts.iter().filter(|(s, _)| is_offset(s.centre)) {
        site.journal[0].add(&mut u, k * site.centre[0]);
        site.journal[1].add(&mut u, k * site.centre[1]);
    }
    lu.solve_in_place(&mut u);
    let mut rhs = f_ext.to_vec();
    let mut pushed = false;
    for &(site, k) in &contacts {
        let [cx, cy] = site.journal;
        let o = site.centre;
        let (x, y) = if is_offset(o) {
            cx.add(&mut rhs, k * o[0]);
            cy.add(&mut rhs, k * o[1]);
            (cx.of(&u) - o[0], cy.of(&u) - o[1])
        } else {
            (cx.of(&u), cy.of(&u))
        };
        let d = x.hypot(y);
        if d > 0.0 {
            let direction = [x / d, y / d];
            let (gap, _) = site.bearing.resting_contact(direction)?;
            cx.add(&mut rhs, k * gap * direction[0]);
            cy.add(&mut rhs, k * gap * direction[1]);
            pushed = true;
        }
    }
    if !pushed {
        return None;
    }
    lu.solve_in_place(&mut rhs);
    Some(rhs)
}

/// Newton with backtracking on the static residual from `u0`, `p0`; with
/// `reseat`, pads left on their unloaded branch are re-seated after every
/// accepted step ([`reseat_pads`]) and the residual is taken there.
#[allow(clippy::too_many_arguments)]
fn newton_static(
    rotor: &Rotor,
    sites: &mut Sites,
    speed: f64,
    options: &SolverOptions,
    time: f64,
    (u0, p0): (Vec<f64>, Option<Vec<f64>>),
    f_ext: &[f64],
    reseat: bool,
) -> Result<(Vec<f64>, Vec<f64>), SolverError> {
    let n = rotor.dof_count();
    let tol = options.tolerance;
    let k_rest = journal_rest(rotor);
    let mut work = StaticWork {
        f_ext: f_ext.to_vec(),
        r: vec![0.0; n],
        rp: vec![0.0; sites.n_internal],
        ku: vec![0.0; n],
        zero_u: vec![0.0; n],
        zero_p: vec![0.0; sites.n_internal],
    };
    let mut schur = SchurSolve::new(n, sites);
    let mut column = vec![0.0; n];
    let mut u = u0;
    let mut p = match p0 {
        Some(p) => p,
        None => {
            let mut p = vec![0.0; sites.n_internal];
            for site in &sites.list {
                let journal = [site.journal[0].of(&u), site.journal[1].of(&u)];
                let range = site.offset..site.offset + site.internal;
                site.bearing.guess_internal(journal, speed, &mut p[range]);
            }
            p
        }
    };
    let mut residual = work.residual(rotor, sites, (&u, &p), speed, time)?;
    let mut absolute = work.absolute();
    for _ in 0..100 {
        if residual <= tol {
            return Ok((u, p));
        }
        // J = K + E K_b,jj Eᵀ in the band; pad blocks through the Schur step.
        let mut a = rotor.stiffness.clone();
        for site in &mut sites.list {
            site.jk.copy_from_slice(&site.eval.stiffness);
            site.jc.fill(0.0);
            let n2 = site.eval.n();
            for (i, ci) in site.journal.iter().enumerate() {
                for (j, cj) in site.journal.iter().enumerate() {
                    add_coupling(&mut a, ci, cj, site.jk[i * n2 + j]);
                }
                a.add(ci.journal, ci.journal, k_rest);
            }
        }
        let factor = make_factor(
            &a,
            rotor,
            &sites.coordinates,
            (0.0, speed),
            None,
            &mut column,
        )
        .map_err(|e| {
            SolverError::Static(format!(
                "the static stiffness is singular ({e}): is the rotor supported at this speed? (a fluid film at zero speed carries no static load)"
            ))
        })?;
        let mut du = work.r.clone();
        let mut dp = work.rp.clone();
        schur.ready = false;
        schur.solve(sites, &factor, 0.0, true, &mut du, &mut dp)?;
        let mut t = 1.0;
        let mut accepted = false;
        for _ in 0..40 {
            let trial_u: Vec<f64> = u.iter().zip(&du).map(|(a, d)| a + t * d).collect();
            let trial_p: Vec<f64> = p.iter().zip(&dp).map(|(a, d)| a + t * d).collect();
            if let Ok(r) = work.residual(rotor, sites, (&trial_u, &trial_p), speed, time) {
                let a = work.absolute();
                if a < absolute {
                    u = trial_u;
                    p = trial_p;
                    residual = r;
                    absolute = a;
                    accepted = true;
                    break;
                }
            }
            t *= 0.5;
        }
        if !accepted {
            break;
        }
        if reseat && reseat_pads(sites, &u, &mut p, speed) {
            residual = work.residual(rotor, sites, (&u, &p), speed, time)?;
            absolute = work.absolute();
        }
    }
    Err(SolverError::Static(format!(
        "Newton stalled with residual {residual:.3e} of the force scale"
    )))
}
