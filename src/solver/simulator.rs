//! The time-domain simulator (see the module docs of [`crate::solver`]).

use crate::bearing::{Bearing, BearingError, BearingEval, BearingReport};
use crate::fe::{DOF_PER_NODE, DOF_X, DOF_Y};
use crate::linalg::{BandLu, BandMatrix, LinalgError};
use crate::rotor::Rotor;

use super::dense::{lu_in_place, lu_solve};

/// Solver settings.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SolverOptions {
    /// Largest internal time step (s).
    pub time_step: f64,
    /// Relative tolerance on residual and increment (–).
    pub tolerance: f64,
    /// Newton iterations per attempt of a step.
    pub max_iterations: usize,
    /// Largest number of step halvings before giving up.
    pub max_step_cuts: usize,
    /// Time constant τ of the unbalance ramp `1 − e^{−t/τ}` (s); 0 for none.
    pub unbalance_ramp_time: f64,
    /// Apply gravity.
    pub gravity: bool,
}

impl Default for SolverOptions {
    fn default() -> Self {
        Self {
            time_step: 1e-4,
            tolerance: 1e-8,
            max_iterations: 50,
            max_step_cuts: 10,
            unbalance_ramp_time: 0.0,
            gravity: true,
        }
    }
}

/// The complete dynamic state: restoring it reproduces a run bit for bit.
#[derive(Debug, Clone, PartialEq)]
pub struct SimState {
    /// Time (s).
    pub time: f64,
    /// Rotor free DOFs: displacement, velocity, acceleration.
    pub u: Vec<f64>,
    /// Velocity.
    pub ud: Vec<f64>,
    /// Acceleration.
    pub udd: Vec<f64>,
    /// Bearing internal DOFs (pad tilts, m) and their rates.
    pub p: Vec<f64>,
    /// Rates of the internal DOFs.
    pub pd: Vec<f64>,
    /// Second derivatives of the internal DOFs (Newmark bookkeeping).
    pub pdd: Vec<f64>,
    /// Spin angle (rad).
    pub spin_angle: f64,
    /// Spin speed input at `speed_time` (rad/s).
    pub speed: f64,
    /// Spin acceleration input (rad/s²): `Ω(t) = speed + speed_rate (t − speed_time)`.
    pub speed_rate: f64,
    /// Time the inputs (speed, unbalance) refer to (s).
    pub speed_time: f64,
    /// Unbalance of each plane at `speed_time` (kg·m).
    pub unbalance: Vec<f64>,
    /// Rate of change of each plane's unbalance (kg·m/s).
    pub unbalance_rate: Vec<f64>,
    /// Angular position of each unbalance plane at spin angle 0 (rad).
    pub unbalance_phase: Vec<f64>,
}

/// Counters of the work done, for reports.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct StepStats {
    /// Accepted steps.
    pub steps: usize,
    /// Newton iterations.
    pub iterations: usize,
    /// Bearing-Jacobian refreshes after a stall.
    pub refreshes: usize,
    /// Step halvings.
    pub step_cuts: usize,
    /// Factorizations of the linear part.
    pub factorizations: usize,
}

/// Why the solver stopped.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum SolverError {
    /// Newton did not converge even with the smallest allowed step.
    #[error(
        "Newton–Raphson did not converge at t = {time:.6} s (step {step:.3e} s after {cuts} halvings; last relative residual or correction {residual:.3e})"
    )]
    NotConverged {
        time: f64,
        step: f64,
        cuts: usize,
        residual: f64,
    },
    /// A bearing could not give a force (e.g. the journal reached the clearance).
    #[error("bearing {name} at t = {time:.6} s: {source}")]
    Bearing {
        name: String,
        time: f64,
        source: BearingError,
    },
    /// The linear part could not be factored.
    #[error("linear algebra: {0}")]
    Linalg(#[from] LinalgError),
    /// Bad input or option.
    #[error("{0}")]
    Input(String),
    /// No static equilibrium was found.
    #[error("static equilibrium: {0}")]
    Static(String),
}

/// Outputs of one bearing.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct BearingOutput {
    /// Journal displacement (m).
    pub x: f64,
    /// Journal displacement (m).
    pub y: f64,
    /// Force of the bearing on the journal (N).
    pub fx: f64,
    /// Force of the bearing on the journal (N).
    pub fy: f64,
    /// Film reports (eccentricity, friction…).
    pub report: BearingReport,
}

/// Displacements of one probe.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct ProbeOutput {
    /// Displacement (m).
    pub x: f64,
    /// Displacement (m).
    pub y: f64,
}

/// Everything a front end reports at the current time.
#[derive(Debug, Clone, PartialEq)]
pub struct Outputs {
    /// Time (s).
    pub time: f64,
    /// Spin speed (rad/s).
    pub speed: f64,
    /// Spin angle (rad).
    pub spin_angle: f64,
    /// One entry per model bearing, in model order.
    pub bearings: Vec<BearingOutput>,
    /// One entry per probe, in model order.
    pub probes: Vec<ProbeOutput>,
    /// Sum of the bearings' friction torques (N·m).
    pub friction_torque: f64,
}

/// A nonlinear bearing in the time integration.
#[derive(Debug)]
struct Site {
    name: String,
    bearing: Box<dyn Bearing>,
    /// Free DOF indices of the journal.
    journal: [usize; 2],
    /// Offset of its internal DOFs in `p`.
    offset: usize,
    internal: usize,
    eval: BearingEval,
    /// Jacobians frozen for modified Newton–Raphson (row-major).
    jk: Vec<f64>,
    jc: Vec<f64>,
    q: Vec<f64>,
    qd: Vec<f64>,
    /// LU of the pad block `K_pp + a1 C_pp` (row-major `m × m`) and its pivots.
    kpp: Vec<f64>,
    kpp_piv: Vec<usize>,
    /// `K_pp⁻¹ [K_pj | −F_p]`: three columns of length `m`.
    kpp_x: Vec<f64>,
}

/// Factorized linear part and its Schur data.
#[derive(Debug)]
struct Factor {
    step: f64,
    speed: f64,
    lu: BandLu<f64>,
    /// `G = Eᵀ A⁻¹ E`, row-major `s_j × s_j` (the journal block of the inverse).
    g: Vec<f64>,
    /// `C + Ω G` at the factor's speed (for the Newmark effective load).
    damping: BandMatrix<f64>,
    /// `Z = A⁻¹ E` column by column (`n` per journal DOF) when applying it costs
    /// less than a banded solve (few journal DOFs); empty otherwise.
    z: Vec<f64>,
}

/// Where the displacement of a step comes from when its rates are formed.
#[derive(Debug, Clone, Copy)]
enum Displacement {
    /// `work.u` as it stands (the Newton iterate).
    Iterate,
    /// `work.lin` (the condensed step's `A⁻¹ b`, corrected in place).
    Linear,
    /// `work.lin + work.mv` (`A⁻¹ b + A⁻¹ E F_b` by a second solve).
    LinearPlusCorrection,
}

/// Work vectors reused by every step.
#[derive(Debug, Default)]
struct Work {
    u: Vec<f64>,
    ud: Vec<f64>,
    udd: Vec<f64>,
    p: Vec<f64>,
    pd: Vec<f64>,
    pdd: Vec<f64>,
    r: Vec<f64>,
    /// Linear part of the dynamic residual, `f − M ü − D u̇ − K u`.
    lin: Vec<f64>,
    mv: Vec<f64>,
    du: Vec<f64>,
    dp: Vec<f64>,
    f_ext: Vec<f64>,
    rp: Vec<f64>,
    small: Vec<f64>,
    /// `small` holds the LU factors for the current Jacobians and factorization.
    small_ready: bool,
    small_rhs: Vec<f64>,
    pivots: Vec<usize>,
    ey: Vec<f64>,
    /// Unit vector / column of `A⁻¹` when forming `G`.
    column: Vec<f64>,
    /// Condensed Newton on the journal DOFs: bearing forces `F_j`, pad terms
    /// `K_jp K_pp⁻¹ (−F_p)`, condensed 2×2 stiffnesses (4 per bearing), the
    /// matrix `I + G K_c` with its pivots, and the right-hand side / increment.
    fj: Vec<f64>,
    wv: Vec<f64>,
    kc: Vec<f64>,
    cj: Vec<f64>,
    cj_piv: Vec<usize>,
    cj_rhs: Vec<f64>,
}

/// Newmark/Newton–Raphson simulator of a rotor on nonlinear bearings.
#[derive(Debug)]
pub struct Simulator {
    rotor: Rotor,
    options: SolverOptions,
    state: SimState,
    sites: Vec<Site>,
    /// All model bearings (for outputs), with the site index of nonlinear ones.
    output_bearings: Vec<(Box<dyn Bearing>, Option<usize>)>,
    n_journal: usize,
    /// Free DOF of each journal coordinate, bearing by bearing (`x`, `y`).
    journal_dofs: Vec<usize>,
    n_internal: usize,
    length_scale: f64,
    factor: Option<Factor>,
    /// Storage for assembling `A` before factoring it.
    a_work: BandMatrix<f64>,
    /// Evaluation buffers of every model bearing for [`Simulator::outputs`].
    output_evals: Vec<BearingEval>,
    output_q: Vec<f64>,
    output_qd: Vec<f64>,
    /// Up to this many journal DOFs a speed change is refactored exactly (see
    /// [`Simulator::prepare_factor`]).
    refactor_journal_limit: usize,
    work: Work,
    stats: StepStats,
}

impl Simulator {
    /// A simulator at rest (zero state, zero speed) for `rotor`.
    pub fn new(rotor: Rotor, options: SolverOptions) -> Result<Self, SolverError> {
        check_options(&options)?;
        let n = rotor.dof_count();
        let mut sites = Vec::new();
        let mut offset = 0;
        for b in &rotor.model.bearings {
            let bearing = b.kind.build();
            if bearing.is_linear() && bearing.internal_dofs() == 0 {
                continue;
            }
            let journal = match (
                rotor.dofs.free(b.node, DOF_X),
                rotor.dofs.free(b.node, DOF_Y),
            ) {
                (Some(x), Some(y)) => [x, y],
                _ => {
                    return Err(SolverError::Input(format!(
                        "bearing {} sits on node {} whose x or y is fixed by a support",
                        b.name,
                        b.node + 1
                    )));
                }
            };
            let internal = bearing.internal_dofs();
            sites.push(Site {
                name: b.name.clone(),
                journal,
                offset,
                internal,
                eval: BearingEval::new(2 + internal),
                jk: vec![0.0; (2 + internal) * (2 + internal)],
                jc: vec![0.0; (2 + internal) * (2 + internal)],
                q: vec![0.0; 2 + internal],
                qd: vec![0.0; 2 + internal],
                kpp: vec![0.0; internal * internal],
                kpp_piv: vec![0; internal],
                kpp_x: vec![0.0; 3 * internal],
                bearing,
            });
            offset += internal;
        }
        let mut site_of = sites.iter().enumerate();
        let output_bearings: Vec<(Box<dyn Bearing>, Option<usize>)> = rotor
            .model
            .bearings
            .iter()
            .map(|b| {
                let bearing = b.kind.build();
                let site = if bearing.is_linear() && bearing.internal_dofs() == 0 {
                    None
                } else {
                    site_of.next().map(|(k, _)| k)
                };
                (bearing, site)
            })
            .collect();
        let length_scale = rotor
            .model
            .bearings
            .iter()
            .filter_map(|b| b.kind.journal_clearance())
            .fold(f64::INFINITY, f64::min);
        let length_scale = if length_scale.is_finite() {
            length_scale
        } else {
            1e-6
        };
        let n_journal = 2 * sites.len();
        let n_internal = offset;
        let s = n_journal + n_internal;
        let state = SimState {
            time: 0.0,
            u: vec![0.0; n],
            ud: vec![0.0; n],
            udd: vec![0.0; n],
            p: vec![0.0; n_internal],
            pd: vec![0.0; n_internal],
            pdd: vec![0.0; n_internal],
            spin_angle: 0.0,
            speed: 0.0,
            speed_rate: 0.0,
            speed_time: 0.0,
            unbalance: rotor.model.unbalances.iter().map(|u| u.magnitude).collect(),
            unbalance_rate: vec![0.0; rotor.model.unbalances.len()],
            unbalance_phase: rotor.model.unbalances.iter().map(|u| u.phase).collect(),
        };
        let work = Work {
            u: vec![0.0; n],
            ud: vec![0.0; n],
            udd: vec![0.0; n],
            p: vec![0.0; n_internal],
            pd: vec![0.0; n_internal],
            pdd: vec![0.0; n_internal],
            r: vec![0.0; n],
            lin: vec![0.0; n],
            mv: vec![0.0; n],
            du: vec![0.0; n],
            dp: vec![0.0; n_internal],
            f_ext: vec![0.0; n],
            rp: vec![0.0; n_internal],
            small: vec![0.0; s * s],
            small_ready: false,
            small_rhs: vec![0.0; s],
            pivots: vec![0; s],
            ey: vec![0.0; n_journal],
            column: vec![0.0; n],
            fj: vec![0.0; n_journal],
            wv: vec![0.0; n_journal],
            kc: vec![0.0; 2 * n_journal],
            cj: vec![0.0; n_journal * n_journal],
            cj_piv: vec![0; n_journal],
            cj_rhs: vec![0.0; n_journal],
        };
        let journal_dofs = sites.iter().flat_map(|s| s.journal).collect();
        let output_evals: Vec<BearingEval> = output_bearings
            .iter()
            .map(|(b, _)| BearingEval::new(2 + b.internal_dofs()))
            .collect();
        let widest = output_evals.iter().map(BearingEval::n).max().unwrap_or(2);
        let a_work = rotor.stiffness.zeroed_like();
        Ok(Self {
            rotor,
            options,
            state,
            sites,
            output_bearings,
            n_journal,
            journal_dofs,
            n_internal,
            length_scale,
            factor: None,
            a_work,
            output_evals,
            output_q: vec![0.0; widest],
            output_qd: vec![0.0; widest],
            refactor_journal_limit: 8,
            work,
            stats: StepStats::default(),
        })
    }

    /// The assembled rotor.
    pub fn rotor(&self) -> &Rotor {
        &self.rotor
    }

    /// Solver options.
    pub fn options(&self) -> &SolverOptions {
        &self.options
    }

    /// Change solver options (takes effect at the next step).
    pub fn set_options(&mut self, options: SolverOptions) -> Result<(), SolverError> {
        check_options(&options)?;
        self.options = options;
        self.factor = None;
        Ok(())
    }

    /// Work counters since creation.
    pub fn stats(&self) -> StepStats {
        self.stats
    }

    /// The complete state (for rollback and serialization).
    pub fn state(&self) -> &SimState {
        &self.state
    }

    /// Restore a state obtained from [`Simulator::state`] of a simulator of the same rotor.
    pub fn set_state(&mut self, state: SimState) -> Result<(), SolverError> {
        let s = &self.state;
        if state.u.len() != s.u.len()
            || state.ud.len() != s.ud.len()
            || state.udd.len() != s.udd.len()
            || state.p.len() != s.p.len()
            || state.pd.len() != s.pd.len()
            || state.pdd.len() != s.pdd.len()
            || state.unbalance.len() != s.unbalance.len()
            || state.unbalance_rate.len() != s.unbalance_rate.len()
            || state.unbalance_phase.len() != s.unbalance_phase.len()
        {
            return Err(SolverError::Input(
                "state does not belong to this rotor (sizes differ)".into(),
            ));
        }
        self.state = state;
        Ok(())
    }

    /// Current time (s).
    pub fn time(&self) -> f64 {
        self.state.time
    }

    /// Adopt a master's clock `t` that differs from the current time only by
    /// rounding (≤ 1e-9 relative), so that repeated `t + h` sums cannot drift.
    pub fn align_time(&mut self, t: f64) -> Result<(), SolverError> {
        let now = self.state.time;
        if !(t.is_finite() && (t - now).abs() <= 1e-9 * now.abs().max(1.0)) {
            return Err(SolverError::Input(format!(
                "time {t} s is not the simulator's time {now} s"
            )));
        }
        self.state.time = t;
        Ok(())
    }

    /// Spin speed at time `t` (rad/s).
    pub fn speed_at(&self, t: f64) -> f64 {
        self.state.speed + self.state.speed_rate * (t - self.state.speed_time)
    }

    /// Re-base the linearly extrapolated inputs to the current time.
    fn rebase_inputs(&mut self) {
        let s = &mut self.state;
        let dt = s.time - s.speed_time;
        s.speed += s.speed_rate * dt;
        for (u, r) in s.unbalance.iter_mut().zip(&s.unbalance_rate) {
            *u = (*u + r * dt).max(0.0);
        }
        s.speed_time = s.time;
    }

    /// Set the spin speed (rad/s) now and its rate of change (rad/s²) from now on.
    pub fn set_speed(&mut self, speed: f64, rate: f64) -> Result<(), SolverError> {
        if !speed.is_finite() || !rate.is_finite() {
            return Err(SolverError::Input(format!(
                "speed {speed} rad/s and its rate {rate} rad/s² must be finite"
            )));
        }
        self.rebase_inputs();
        self.state.speed = speed;
        self.state.speed_rate = rate;
        Ok(())
    }

    /// Set the unbalance (kg·m) of plane `plane` (model order), constant from now on.
    pub fn set_unbalance(&mut self, plane: usize, magnitude: f64) -> Result<(), SolverError> {
        self.set_unbalance_ramp(plane, magnitude, 0.0)
    }

    /// Set the unbalance (kg·m) of plane `plane` now and its rate of change (kg·m/s).
    pub fn set_unbalance_ramp(
        &mut self,
        plane: usize,
        magnitude: f64,
        rate: f64,
    ) -> Result<(), SolverError> {
        if !(magnitude.is_finite() && magnitude >= 0.0 && rate.is_finite()) {
            return Err(SolverError::Input(format!(
                "unbalance {magnitude} kg·m must be finite and not negative, its rate {rate} kg·m/s finite"
            )));
        }
        self.rebase_inputs();
        *plane_slot(&mut self.state.unbalance, plane)? = magnitude;
        *plane_slot(&mut self.state.unbalance_rate, plane)? = rate;
        Ok(())
    }

    /// Change the oil viscosity (Pa·s) of fluid-film bearing `index` (model order).
    pub fn set_bearing_viscosity(
        &mut self,
        index: usize,
        viscosity: f64,
    ) -> Result<(), SolverError> {
        if !(viscosity.is_finite() && viscosity > 0.0) {
            return Err(SolverError::Input(format!(
                "viscosity {viscosity} Pa·s must be finite and positive"
            )));
        }
        let placed = self
            .rotor
            .model
            .bearings
            .get_mut(index)
            .ok_or_else(|| SolverError::Input(format!("no bearing {index}")))?;
        if !placed.kind.set_viscosity(viscosity) {
            return Err(SolverError::Input(format!(
                "bearing {} is linear: it has no oil viscosity",
                placed.name
            )));
        }
        let (output, site) = &mut self.output_bearings[index];
        *output = placed.kind.build();
        if let Some(k) = site {
            self.sites[*k].bearing = placed.kind.build();
        }
        Ok(())
    }

    /// Set the angular position (rad) of plane `plane` at spin angle zero.
    pub fn set_unbalance_phase(&mut self, plane: usize, phase: f64) -> Result<(), SolverError> {
        if !phase.is_finite() {
            return Err(SolverError::Input(format!(
                "unbalance phase {phase} must be finite"
            )));
        }
        *plane_slot(&mut self.state.unbalance_phase, plane)? = phase;
        Ok(())
    }

    /// Put the rotor in static equilibrium under gravity at the current speed
    /// (velocities and accelerations zero, nonlinear bearings included), by
    /// Newton with backtracking on the full static Jacobian.
    pub fn settle_static(&mut self) -> Result<(), SolverError> {
        let speed = self.speed_at(self.state.time);
        let tol = self.options.tolerance;
        self.work.f_ext.fill(0.0);
        if self.options.gravity {
            self.work.f_ext.copy_from_slice(&self.rotor.gravity_load);
        }
        let mut u = self.state.u.clone();
        let mut p = self.state.p.clone();
        for site in &self.sites {
            let journal = [u[site.journal[0]], u[site.journal[1]]];
            let range = site.offset..site.offset + site.internal;
            site.bearing.guess_internal(journal, speed, &mut p[range]);
        }
        let mut residual = self.static_residual(&u, &p, speed)?;
        let mut absolute = self.static_absolute();
        for _ in 0..100 {
            if residual <= tol {
                self.state.u = u;
                self.state.p = p;
                self.state.ud.fill(0.0);
                self.state.udd.fill(0.0);
                self.state.pd.fill(0.0);
                self.state.pdd.fill(0.0);
                self.factor = None;
                return Ok(());
            }
            // J = K + E K_b,jj Eᵀ in the band; pad blocks through the Schur step.
            let mut a = self.rotor.stiffness.clone();
            for site in &mut self.sites {
                site.jk.copy_from_slice(&site.eval.stiffness);
                site.jc.fill(0.0);
                let n2 = site.eval.n();
                for (i, &gi) in site.journal.iter().enumerate() {
                    for (j, &gj) in site.journal.iter().enumerate() {
                        a.add(gi, gj, site.jk[i * n2 + j])?;
                    }
                }
            }
            let factor = self.make_factor(&a, 0.0, speed, None).map_err(|e| {
                SolverError::Static(format!(
                    "the static stiffness is singular ({e}): is the rotor supported at this speed? (a fluid film at zero speed carries no static load)"
                ))
            })?;
            let mut du = self.work.r.clone();
            let mut dp = self.work.rp.clone();
            self.work.small_ready = false;
            self.small_solve(&factor, 0.0, true, &mut du, &mut dp)?;
            let mut t = 1.0;
            let mut accepted = false;
            for _ in 0..40 {
                let trial_u: Vec<f64> = u.iter().zip(&du).map(|(a, d)| a + t * d).collect();
                let trial_p: Vec<f64> = p.iter().zip(&dp).map(|(a, d)| a + t * d).collect();
                if let Ok(r) = self.static_residual(&trial_u, &trial_p, speed) {
                    let a = self.static_absolute();
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
        }
        // Leave the bearings' evaluations consistent with the state.
        let (su, sp) = (self.state.u.clone(), self.state.p.clone());
        let _ = self.static_residual(&su, &sp, speed);
        Err(SolverError::Static(format!(
            "Newton stalled with residual {residual:.3e} of the force scale"
        )))
    }

    /// Evaluate the bearings at `u`, `u̇` (rotor) and `p`, `ṗ` (internal), adding
    /// their journal forces to `work.r`, writing pad residuals to `work.rp`;
    /// returns the largest bearing force.
    fn add_bearing_forces(
        &mut self,
        u: &[f64],
        ud: &[f64],
        p: &[f64],
        pd: &[f64],
        speed: f64,
        time: f64,
    ) -> Result<f64, SolverError> {
        let mut largest: f64 = 0.0;
        for site in &mut self.sites {
            site.q[0] = u[site.journal[0]];
            site.q[1] = u[site.journal[1]];
            site.qd[0] = ud[site.journal[0]];
            site.qd[1] = ud[site.journal[1]];
            let range = site.offset..site.offset + site.internal;
            site.q[2..].copy_from_slice(&p[range.clone()]);
            site.qd[2..].copy_from_slice(&pd[range]);
            site.bearing
                .evaluate(&site.q, &site.qd, speed, &mut site.eval)
                .map_err(|source| SolverError::Bearing {
                    name: site.name.clone(),
                    time,
                    source,
                })?;
            self.work.r[site.journal[0]] += site.eval.force[0];
            self.work.r[site.journal[1]] += site.eval.force[1];
            largest = largest
                .max(site.eval.force[0].abs())
                .max(site.eval.force[1].abs());
            for k in 0..site.internal {
                self.work.rp[site.offset + k] = site.eval.force[2 + k];
            }
            // Each pad's own film force sets the scale of its moment balance.
            for k in 0..site.internal {
                largest = largest.max(site.eval.k(2 + k, 2 + k).abs() * self.length_scale);
            }
        }
        Ok(largest)
    }

    /// Static residual `f_g + E F_b − K u` (into `work.r`) and pad residual (into
    /// `work.rp`), relative to the largest force term.
    /// Largest absolute static residual (rotor and pads) of the last evaluation.
    fn static_absolute(&self) -> f64 {
        inf_norm(&self.work.r).max(inf_norm(&self.work.rp))
    }

    fn static_residual(&mut self, u: &[f64], p: &[f64], speed: f64) -> Result<f64, SolverError> {
        self.rotor.stiffness.mul_vec(u, &mut self.work.mv)?;
        let mut scale = inf_norm(&self.work.mv).max(inf_norm(&self.work.f_ext));
        for (r, (f, k)) in self
            .work
            .r
            .iter_mut()
            .zip(self.work.f_ext.iter().zip(&self.work.mv))
        {
            *r = f - k;
        }
        let zero_u = vec![0.0; u.len()];
        let zero_p = vec![0.0; p.len()];
        scale =
            scale.max(self.add_bearing_forces(u, &zero_u, p, &zero_p, speed, self.state.time)?);
        let scale = scale.max(f64::MIN_POSITIVE);
        Ok(inf_norm(&self.work.r).max(inf_norm(&self.work.rp)) / scale)
    }

    /// Newmark rates at the iterate `work.u`, `work.p` of a step of size `h`.
    fn update_rates(&mut self, h: f64) {
        self.set_displacement_and_rates(h, Displacement::Iterate);
    }

    /// Set `work.u` from `from` and form the Newmark rates of the step, rotor and
    /// pads, in one pass.
    fn set_displacement_and_rates(&mut self, h: f64, from: Displacement) {
        let (a0, a1, a2) = (4.0 / (h * h), 2.0 / h, 4.0 / h);
        let (s, w) = (&self.state, &mut self.work);
        for i in 0..s.u.len() {
            let u = match from {
                Displacement::Iterate => w.u[i],
                Displacement::Linear => w.lin[i],
                Displacement::LinearPlusCorrection => w.lin[i] + w.mv[i],
            };
            w.u[i] = u;
            let d = u - s.u[i];
            w.ud[i] = a1 * d - s.ud[i];
            w.udd[i] = a0 * d - a2 * s.ud[i] - s.udd[i];
        }
        for i in 0..s.p.len() {
            let d = w.p[i] - s.p[i];
            w.pd[i] = a1 * d - s.pd[i];
            w.pdd[i] = a0 * d - a2 * s.pd[i] - s.pdd[i];
        }
    }

    /// Linear part of the dynamic residual at the iterate, `work.lin = f − M ü −
    /// (C + Ω G) u̇ − K u` (rates updated first); returns the largest force term.
    fn linear_residual(&mut self, h: f64, speed1: f64) -> Result<f64, SolverError> {
        self.update_rates(h);
        self.work.lin.copy_from_slice(&self.work.f_ext);
        let mut scale = inf_norm(&self.work.f_ext);
        let terms: [(&BandMatrix<f64>, f64, u8); 4] = [
            (&self.rotor.mass, 1.0, 2),
            (&self.rotor.damping, 1.0, 1),
            (&self.rotor.gyroscopic, speed1, 1),
            (&self.rotor.stiffness, 1.0, 0),
        ];
        for (matrix, coef, which) in terms {
            if coef == 0.0 {
                continue;
            }
            let x = match which {
                2 => &self.work.udd,
                1 => &self.work.ud,
                _ => &self.work.u,
            };
            matrix.mul_vec(x, &mut self.work.mv)?;
            let mut norm: f64 = 0.0;
            for (r, m) in self.work.lin.iter_mut().zip(&self.work.mv) {
                *r -= coef * m;
                norm = norm.max((coef * m).abs());
            }
            scale = scale.max(norm);
        }
        Ok(scale)
    }

    /// Full residual `work.r = work.lin + E F_b` and pad residual `work.rp` with the
    /// bearings evaluated at the iterate; returns it relative to the force scale
    /// (`scale` grows with the bearing forces).
    fn residual_with_bearings(
        &mut self,
        t1: f64,
        speed1: f64,
        scale: &mut f64,
    ) -> Result<f64, SolverError> {
        self.work.r.copy_from_slice(&self.work.lin);
        let (u, ud, p, pd) = (
            std::mem::take(&mut self.work.u),
            std::mem::take(&mut self.work.ud),
            std::mem::take(&mut self.work.p),
            std::mem::take(&mut self.work.pd),
        );
        let bearings = self.add_bearing_forces(&u, &ud, &p, &pd, speed1, t1);
        self.work.u = u;
        self.work.ud = ud;
        self.work.p = p;
        self.work.pd = pd;
        *scale = scale.max(bearings?).max(f64::MIN_POSITIVE);
        Ok(inf_norm(&self.work.r).max(inf_norm(&self.work.rp)) / *scale)
    }

    /// Factor `a` and form `G = Eᵀ A⁻¹ E` (one solve per journal DOF), reusing the
    /// storage of `reuse` (no allocation when refactoring).
    fn make_factor(
        &mut self,
        a: &BandMatrix<f64>,
        step: f64,
        speed: f64,
        reuse: Option<Factor>,
    ) -> Result<Factor, LinalgError> {
        let mut factor = match reuse {
            Some(mut f) => {
                a.lu_into(&mut f.lu)?;
                f
            }
            None => Factor {
                step,
                speed,
                lu: a.lu()?,
                g: vec![0.0; self.n_journal * self.n_journal],
                damping: self.rotor.stiffness.zeroed_like(),
                z: if self.n_journal <= a.kl() + a.ku() {
                    vec![0.0; self.n_journal * a.n()]
                } else {
                    Vec::new()
                },
            },
        };
        factor.step = step;
        factor.speed = speed;
        factor.damping.assign(&self.rotor.damping)?;
        factor.damping.scale_add(speed, &self.rotor.gyroscopic)?;
        self.stats.factorizations += 1;
        let sj = self.n_journal;
        let column = &mut self.work.column;
        for (c, &dof) in self.journal_dofs.iter().enumerate() {
            column.fill(0.0);
            column[dof] = 1.0;
            factor.lu.solve_in_place(column)?;
            for (r, &row_dof) in self.journal_dofs.iter().enumerate() {
                factor.g[r * sj + c] = column[row_dof];
            }
            if !factor.z.is_empty() {
                let n = column.len();
                factor.z[c * n..(c + 1) * n].copy_from_slice(column);
            }
        }
        Ok(factor)
    }

    /// Factor the Newmark matrix `A = K + a1 (C + Ω G) + a0 M` for step `h` at
    /// speed `speed`, reusing `reuse`'s storage.
    fn dynamic_factor(
        &mut self,
        h: f64,
        speed: f64,
        reuse: Option<Factor>,
    ) -> Result<Factor, LinalgError> {
        let (a0, a1) = (4.0 / (h * h), 2.0 / h);
        let mut a = std::mem::replace(&mut self.a_work, BandMatrix::new(0, 0, 0));
        let assembled = (|| {
            a.assign(&self.rotor.stiffness)?;
            a.scale_add(a1, &self.rotor.damping)?;
            a.scale_add(a1 * speed, &self.rotor.gyroscopic)?;
            a.scale_add(a0, &self.rotor.mass)
        })();
        let factor = assembled.and_then(|()| self.make_factor(&a, h, speed, reuse));
        self.a_work = a;
        factor
    }

    /// Schur solve of `J [δu; δp] = [y; dp]` in place, `J` = factored `A` plus the
    /// frozen bearing blocks `(K_b + a1 C_b)`; with `journal_in_a` only the pad
    /// blocks are added (the journal blocks are already in `A`).
    fn small_solve(
        &mut self,
        factor: &Factor,
        a1: f64,
        journal_in_a: bool,
        y: &mut [f64],
        dp: &mut [f64],
    ) -> Result<(), SolverError> {
        let sj = self.n_journal;
        let s = sj + self.n_internal;
        factor.lu.solve_in_place(y)?;
        if s == 0 {
            return Ok(());
        }
        let w = &mut self.work;
        for (k, site) in self.sites.iter().enumerate() {
            w.ey[2 * k] = y[site.journal[0]];
            w.ey[2 * k + 1] = y[site.journal[1]];
        }
        // The matrix depends only on the frozen Jacobians and G: factor it once per
        // refresh (modified Newton), then only the right-hand side changes.
        if !w.small_ready {
            w.small.fill(0.0);
            for (k, site) in self.sites.iter().enumerate() {
                let n2 = site.eval.n();
                let jac = |i: usize, j: usize| site.jk[i * n2 + j] + a1 * site.jc[i * n2 + j];
                let jr = 2 * k;
                let pr = sj + site.offset;
                for i in 0..2 {
                    // Rows of f: f + ΔK_jj G f − K_jp δp = ΔK_jj Eᵀy.
                    w.small[(jr + i) * s + jr + i] += 1.0;
                    if !journal_in_a {
                        for a in 0..2 {
                            let kia = jac(i, a);
                            for c in 0..sj {
                                w.small[(jr + i) * s + c] += kia * factor.g[(jr + a) * sj + c];
                            }
                        }
                    }
                    for m in 0..site.internal {
                        w.small[(jr + i) * s + pr + m] -= jac(i, 2 + m);
                    }
                }
                for m in 0..site.internal {
                    // Rows of δp: −K_pj G f + K_pp δp = r_p − K_pj Eᵀy.
                    let row = pr + m;
                    for a in 0..2 {
                        let kma = jac(2 + m, a);
                        for c in 0..sj {
                            w.small[row * s + c] -= kma * factor.g[(jr + a) * sj + c];
                        }
                    }
                    for l in 0..site.internal {
                        w.small[row * s + pr + l] += jac(2 + m, 2 + l);
                    }
                }
            }
            if !lu_in_place(&mut w.small, s, &mut w.pivots) {
                return Err(SolverError::Linalg(LinalgError::Singular { column: 0 }));
            }
            w.small_ready = true;
        }
        w.small_rhs.fill(0.0);
        for (k, site) in self.sites.iter().enumerate() {
            let n2 = site.eval.n();
            let jac = |i: usize, j: usize| site.jk[i * n2 + j] + a1 * site.jc[i * n2 + j];
            let jr = 2 * k;
            if !journal_in_a {
                for i in 0..2 {
                    for a in 0..2 {
                        w.small_rhs[jr + i] += jac(i, a) * w.ey[jr + a];
                    }
                }
            }
            for m in 0..site.internal {
                let row = sj + site.offset + m;
                for a in 0..2 {
                    w.small_rhs[row] -= jac(2 + m, a) * w.ey[jr + a];
                }
                w.small_rhs[row] += dp[site.offset + m];
            }
        }
        lu_solve(&w.small, s, &w.pivots, &mut w.small_rhs);
        // δu = A⁻¹ r − A⁻¹ E f: a second solve with the journal forces f.
        if sj > 0 {
            w.mv.fill(0.0);
            for (k, site) in self.sites.iter().enumerate() {
                w.mv[site.journal[0]] += w.small_rhs[2 * k];
                w.mv[site.journal[1]] += w.small_rhs[2 * k + 1];
            }
            factor.lu.solve_in_place(&mut w.mv)?;
            for (yi, zi) in y.iter_mut().zip(&w.mv) {
                *yi -= zi;
            }
        }
        dp.copy_from_slice(&w.small_rhs[sj..]);
        Ok(())
    }

    /// External force at time `t` (unbalance with ramp, gravity) into `work.f_ext`.
    fn external_force(&mut self, t: f64, spin_angle: f64) {
        let w = &mut self.work;
        w.f_ext.fill(0.0);
        if self.options.gravity {
            w.f_ext.copy_from_slice(&self.rotor.gravity_load);
        }
        let speed = self.state.speed + self.state.speed_rate * (t - self.state.speed_time);
        let rate = self.state.speed_rate;
        let ramp = if self.options.unbalance_ramp_time > 0.0 {
            1.0 - (-t / self.options.unbalance_ramp_time).exp()
        } else {
            1.0
        };
        let since = t - self.state.speed_time;
        for (k, plane) in self.rotor.model.unbalances.iter().enumerate() {
            let me =
                (self.state.unbalance[k] + self.state.unbalance_rate[k] * since).max(0.0) * ramp;
            let (s, c) = (spin_angle + self.state.unbalance_phase[k]).sin_cos();
            let fx = me * (speed * speed * c + rate * s);
            let fy = me * (speed * speed * s - rate * c);
            if let Some(i) = self.rotor.dofs.free(plane.node, DOF_X) {
                w.f_ext[i] += fx;
            }
            if let Some(i) = self.rotor.dofs.free(plane.node, DOF_Y) {
                w.f_ext[i] += fy;
            }
        }
    }

    /// Advance to time `t_end` in equal internal steps no longer than the
    /// configured time step.
    pub fn advance_to(&mut self, t_end: f64) -> Result<(), SolverError> {
        if !t_end.is_finite() {
            return Err(SolverError::Input(format!(
                "target time {t_end} is not finite"
            )));
        }
        let span = t_end - self.state.time;
        if span < 0.0 {
            return Err(SolverError::Input(format!(
                "cannot step backwards from {} s to {t_end} s",
                self.state.time
            )));
        }
        if span == 0.0 {
            return Ok(());
        }
        let count = (span / self.options.time_step - 1e-9).ceil().max(1.0) as usize;
        let h = span / count as f64;
        for k in 0..count {
            self.step_with_cuts(h, 0)?;
            if k + 1 == count {
                self.state.time = t_end;
            }
        }
        Ok(())
    }

    fn step_with_cuts(&mut self, h: f64, depth: usize) -> Result<(), SolverError> {
        match self.try_step(h)? {
            None => Ok(()),
            Some(residual) => {
                if depth >= self.options.max_step_cuts {
                    return Err(SolverError::NotConverged {
                        time: self.state.time,
                        step: h,
                        cuts: depth,
                        residual,
                    });
                }
                self.stats.step_cuts += 1;
                self.step_with_cuts(h / 2.0, depth + 1)?;
                self.step_with_cuts(h / 2.0, depth + 1)
            }
        }
    }

    /// One Newmark step of size `h`. `Ok(None)`: converged, state advanced;
    /// `Ok(Some(residual))`: Newton failed, state untouched. A bearing error
    /// (journal beyond the clearance) at an iterate counts as a failure of the
    /// step, so a smaller step is tried before giving up.
    fn try_step(&mut self, h: f64) -> Result<Option<f64>, SolverError> {
        // Sub-steps of communication intervals differ from the factored step by
        // the round-off of the time grid (1e-11 relative at t = 20 s): take the
        // factored step itself (the grid moves by ~1e-15 s, and `advance_to`
        // ends exactly on the communication point).
        let h = match self.factor.as_ref() {
            Some(f) if (f.step - h).abs() <= 1e-9 * h => f.step,
            _ => h,
        };
        let t1 = self.state.time + h;
        let speed0 = self.speed_at(self.state.time);
        let speed1 = self.speed_at(t1);
        let spin1 = self.state.spin_angle + 0.5 * (speed0 + speed1) * h;
        self.external_force(t1, spin1);
        let mut factor = self.factor.take();
        let exact = self.prepare_factor(h, speed1, &mut factor);
        // Predictor `u + h u̇ + h²/2 ü`: the condensed Newton only needs it on the
        // journal and pad coordinates.
        {
            let (s, w) = (&self.state, &mut self.work);
            let predict = |i: usize| s.u[i] + h * s.ud[i] + 0.5 * h * h * s.udd[i];
            if matches!(exact, Ok(true)) {
                for &i in &self.journal_dofs {
                    w.u[i] = predict(i);
                }
            } else {
                for (i, u) in w.u.iter_mut().enumerate() {
                    *u = predict(i);
                }
            }
            for i in 0..s.p.len() {
                w.p[i] = s.p[i] + h * s.pd[i] + 0.5 * h * h * s.pdd[i];
            }
        }
        let outcome = match exact {
            Ok(true) => match factor.as_ref() {
                Some(f) => self.newton_condensed(h, t1, speed1, f),
                None => Err(SolverError::Input("internal: no factorization".into())),
            },
            Ok(false) => self.newton(h, t1, speed1, &mut factor),
            Err(e) => Err(e),
        };
        self.factor = factor;
        let outcome = match outcome {
            Err(SolverError::Bearing {
                source: BearingError::ClearanceExceeded { .. },
                ..
            }) if h > self.options.time_step * 0.5f64.powi(self.options.max_step_cuts as i32) => {
                Some(f64::INFINITY)
            }
            other => other?,
        };
        if outcome.is_none() {
            let (s, w) = (&mut self.state, &mut self.work);
            std::mem::swap(&mut s.u, &mut w.u);
            std::mem::swap(&mut s.ud, &mut w.ud);
            std::mem::swap(&mut s.udd, &mut w.udd);
            std::mem::swap(&mut s.p, &mut w.p);
            std::mem::swap(&mut s.pd, &mut w.pd);
            std::mem::swap(&mut s.pdd, &mut w.pdd);
            s.time = t1;
            s.spin_angle = spin1;
            self.stats.steps += 1;
        }
        Ok(outcome)
    }

    /// Make `factor` exact for step `h` at speed `speed1` where that pays off;
    /// returns whether it is exact. A factorization at another step size, or
    /// more than 2 % off in speed, is always redone. Within that band a speed
    /// change is refactored when the journal DOFs are few (≤ 8): one banded LU
    /// plus one solve per journal DOF for `G`, against the stale path's
    /// mat-vecs and two solves per iteration, and 1.5× the iterations on a
    /// Jeffcott run-up (see the test below).
    fn prepare_factor(
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
        if stale || self.n_journal <= self.refactor_journal_limit {
            *factor = Some(self.dynamic_factor(h, speed1, factor.take())?);
            self.work.small_ready = false;
            return Ok(true);
        }
        Ok(false)
    }

    /// Newton–Raphson on the bearing coordinates alone, with an exact
    /// factorization of `A = K + a1 (C + Ω G) + a0 M`. The rotor equations of
    /// the step are `A u = b + E F` with the Newmark effective load
    /// `b = f + M (a0 u_n + a2 u̇_n + ü_n) + (C + Ω G)(a1 u_n + u̇_n)`, so
    /// `u = u_lin + A⁻¹ E F` with `u_lin = A⁻¹ b`: the journal coordinates
    /// `j = Eᵀ u` and the pad tilts `p` solve the small system
    /// `j − j_lin − G F_j(j, p) = 0`, `F_p(j, p) = 0` (`G = Eᵀ A⁻¹ E`).
    ///
    /// Full Newton on it: pads are condensed bearing by bearing,
    /// `K_c = K_jj − K_jp K_pp⁻¹ K_pj` (all `K` here are `K + a1 C`), leaving
    /// `(I + G K_c) δj = j_lin − j + G (F_j + K_jp K_pp⁻¹ (−F_p))`. The step stops
    /// when the correction is below the tolerance; the journal forces there are
    /// taken to first order, `F_j − K_c δj + K_jp K_pp⁻¹ (−F_p)`, which satisfies
    /// the condensed equation exactly. A step costs two banded mat-vecs and two
    /// banded solves whatever the number of iterations.
    fn newton_condensed(
        &mut self,
        h: f64,
        t1: f64,
        speed1: f64,
        f: &Factor,
    ) -> Result<Option<f64>, SolverError> {
        let (a0, a1, a2) = (4.0 / (h * h), 2.0 / h, 4.0 / h);
        let sj = self.n_journal;
        {
            let (s, w) = (&self.state, &mut self.work);
            w.lin.copy_from_slice(&w.f_ext);
            BandMatrix::mul_add_pair(&self.rotor.mass, &f.damping, &mut w.lin, |j| {
                (a0 * s.u[j] + a2 * s.ud[j] + s.udd[j], a1 * s.u[j] + s.ud[j])
            })?;
            f.lu.solve_in_place(&mut w.lin)?;
        }
        if sj == 0 {
            self.stats.iterations += 1;
            self.set_displacement_and_rates(h, Displacement::Linear);
            return Ok(None);
        }
        let tol = self.options.tolerance;
        let singular = || SolverError::Linalg(LinalgError::Singular { column: 0 });
        let mut last = f64::INFINITY;
        for _ in 0..self.options.max_iterations {
            self.stats.iterations += 1;
            let (s, w) = (&self.state, &mut self.work);
            for (k, site) in self.sites.iter_mut().enumerate() {
                for (a, &dof) in site.journal.iter().enumerate() {
                    site.q[a] = w.u[dof];
                    site.qd[a] = a1 * (w.u[dof] - s.u[dof]) - s.ud[dof];
                }
                for m in 0..site.internal {
                    let i = site.offset + m;
                    site.q[2 + m] = w.p[i];
                    site.qd[2 + m] = a1 * (w.p[i] - s.p[i]) - s.pd[i];
                }
                site.bearing
                    .evaluate(&site.q, &site.qd, speed1, &mut site.eval)
                    .map_err(|source| SolverError::Bearing {
                        name: site.name.clone(),
                        time: t1,
                        source,
                    })?;
                let ev = &site.eval;
                let (kc, wv) =
                    condense_internal(ev, a1, &mut site.kpp, &mut site.kpp_piv, &mut site.kpp_x)
                        .ok_or_else(singular)?;
                w.kc[4 * k..4 * k + 4].copy_from_slice(&kc);
                w.fj[2 * k..2 * k + 2].copy_from_slice(&ev.force[..2]);
                w.wv[2 * k..2 * k + 2].copy_from_slice(&wv);
            }
            for (r, &dof) in self.journal_dofs.iter().enumerate() {
                let g = &f.g[r * sj..(r + 1) * sj];
                let mut rhs = w.lin[dof] - w.u[dof];
                for (gc, (fc, wc)) in g.iter().zip(w.fj.iter().zip(&w.wv)) {
                    rhs += gc * (fc + wc);
                }
                w.cj_rhs[r] = rhs;
                for k in 0..sj / 2 {
                    for i in 0..2 {
                        let mut v = if r == 2 * k + i { 1.0 } else { 0.0 };
                        for a in 0..2 {
                            v += g[2 * k + a] * w.kc[4 * k + 2 * a + i];
                        }
                        w.cj[r * sj + 2 * k + i] = v;
                    }
                }
            }
            if !lu_in_place(&mut w.cj, sj, &mut w.cj_piv) {
                return Err(singular());
            }
            lu_solve(&w.cj, sj, &w.cj_piv, &mut w.cj_rhs);
            let (mut inc, mut mag): (f64, f64) = (0.0, 0.0);
            for (&dof, d) in self.journal_dofs.iter().zip(&w.cj_rhs) {
                inc = inc.max(d.abs());
                mag = mag.max(w.u[dof].abs());
                w.u[dof] += d;
            }
            for (k, site) in self.sites.iter().enumerate() {
                let mi = site.internal;
                let (dx, dy) = (w.cj_rhs[2 * k], w.cj_rhs[2 * k + 1]);
                for m in 0..mi {
                    let x = &site.kpp_x;
                    let d = -x[2 * mi + m] - x[m] * dx - x[mi + m] * dy;
                    let p = &mut w.p[site.offset + m];
                    inc = inc.max(d.abs());
                    mag = mag.max(p.abs());
                    *p += d;
                }
            }
            let scale = mag.max(self.length_scale);
            if inc <= tol * scale {
                // u = u_lin + A⁻¹ E F_j with the first-order journal forces.
                for (k, fk) in w.fj.iter_mut().enumerate() {
                    let (b, i) = (k / 2, k % 2);
                    let kc = &w.kc[4 * b + 2 * i..4 * b + 2 * i + 2];
                    *fk += w.wv[k] - kc[0] * w.cj_rhs[2 * b] - kc[1] * w.cj_rhs[2 * b + 1];
                }
                if f.z.is_empty() {
                    w.mv.fill(0.0);
                    for (&dof, fk) in self.journal_dofs.iter().zip(&w.fj) {
                        w.mv[dof] = *fk;
                    }
                    f.lu.solve_in_place(&mut w.mv)?;
                    self.set_displacement_and_rates(h, Displacement::LinearPlusCorrection);
                } else {
                    for (zc, fk) in f.z.chunks_exact(w.lin.len()).zip(&w.fj) {
                        for (l, z) in w.lin.iter_mut().zip(zc) {
                            *l += z * fk;
                        }
                    }
                    self.set_displacement_and_rates(h, Displacement::Linear);
                }
                return Ok(None);
            }
            last = inc / scale;
        }
        Ok(Some(last))
    }

    fn newton(
        &mut self,
        h: f64,
        t1: f64,
        speed1: f64,
        factor: &mut Option<Factor>,
    ) -> Result<Option<f64>, SolverError> {
        let a1 = 2.0 / h;
        let tol = self.options.tolerance;
        let mut last = f64::INFINITY;
        let mut refreshed = false;
        let mut jacobian_current = false;
        let mut increment_ok = false;
        let mut scale = self.linear_residual(h, speed1)?;
        let mut residual = self.residual_with_bearings(t1, speed1, &mut scale)?;
        for iteration in 0..self.options.max_iterations {
            self.stats.iterations += 1;
            if residual <= tol && increment_ok {
                return Ok(None);
            }
            let stalled = iteration > 0 && residual > 0.7 * last;
            last = residual;
            // The predictor can be far from the solution: take the Jacobian once more
            // at the first corrected iterate, then keep it (modified Newton).
            if iteration == 1 {
                jacobian_current = false;
            }
            // A stalled modified Newton gets the current bearing Jacobian (cheap: it
            // lives on the few bearing DOFs) and, once per step, `A` at the current speed.
            let mut refresh_now = false;
            if stalled {
                refresh_now = !refreshed;
                refreshed = true;
                jacobian_current = false;
                self.stats.refreshes += 1;
            }
            // `prepare_factor` has refactored for a new step size or speed band;
            // here only a refresh moves `A` to the exact speed.
            let rebuild = factor
                .as_ref()
                .is_none_or(|f| refresh_now && f.speed != speed1);
            if rebuild {
                *factor = Some(self.dynamic_factor(h, speed1, factor.take())?);
                self.work.small_ready = false;
            }
            if !jacobian_current {
                self.work.small_ready = false;
                for site in &mut self.sites {
                    site.jk.copy_from_slice(&site.eval.stiffness);
                    site.jc.copy_from_slice(&site.eval.damping);
                }
                jacobian_current = true;
            }
            let Some(f) = factor.as_ref() else {
                return Err(SolverError::Input("internal: no factorization".into()));
            };
            // Step sizes that differ by rounding only count as exact (the error is
            // of the order of the round-off of the solve itself).
            let exact = (f.step - h).abs() <= 1e-12 * h && f.speed == speed1;
            let mut du = std::mem::take(&mut self.work.du);
            let mut dp = std::mem::take(&mut self.work.dp);
            du.copy_from_slice(&self.work.r);
            dp.copy_from_slice(&self.work.rp);
            let solved = self.small_solve(f, a1, false, &mut du, &mut dp);
            if let Err(e) = solved {
                self.work.du = du;
                self.work.dp = dp;
                return Err(e);
            }
            let mut inc: f64 = 0.0;
            let mut mag: f64 = 0.0;
            for (i, d) in du.iter().enumerate() {
                if self.rotor.dofs.full(i) % DOF_PER_NODE < 2 {
                    inc = inc.max(d.abs());
                    mag = mag.max(self.work.u[i].abs());
                }
            }
            for (d, v) in dp.iter().zip(&self.work.p) {
                inc = inc.max(d.abs());
                mag = mag.max(v.abs());
            }
            increment_ok = inc <= tol * mag.max(self.length_scale);
            for (u, d) in self.work.u.iter_mut().zip(&du) {
                *u += d;
            }
            for (p, d) in self.work.p.iter_mut().zip(&dp) {
                *p += d;
            }
            self.work.du = du;
            self.work.dp = dp;
            if exact {
                // With the exact A, A δu = r − E f and r = lin + E F_b, so the new
                // linear residual is E (f − F_b): it lives on the journal DOFs only.
                self.update_rates(h);
                self.work.lin.fill(0.0);
                for (k, site) in self.sites.iter().enumerate() {
                    for (a, &dof) in site.journal.iter().enumerate() {
                        self.work.lin[dof] = self.work.small_rhs[2 * k + a] - site.eval.force[a];
                    }
                }
            } else {
                scale = scale.max(self.linear_residual(h, speed1)?);
            }
            residual = self.residual_with_bearings(t1, speed1, &mut scale)?;
        }
        Ok(Some(last))
    }

    /// Make the accelerations consistent with the equations of motion at the
    /// current displacements and velocities: `M ü = f(t) + E F_b − (C + ΩG) u̇ − K u`
    /// (pad rates are left as they are). Call after setting an arbitrary state.
    pub fn consistent_acceleration(&mut self) -> Result<(), SolverError> {
        let t = self.state.time;
        let speed = self.speed_at(t);
        self.external_force(t, self.state.spin_angle);
        let w = &mut self.work;
        w.r.copy_from_slice(&w.f_ext);
        for (matrix, coef, x) in [
            (&self.rotor.damping, 1.0, &self.state.ud),
            (&self.rotor.gyroscopic, speed, &self.state.ud),
            (&self.rotor.stiffness, 1.0, &self.state.u),
        ] {
            matrix.mul_vec(x, &mut w.mv)?;
            for (r, m) in w.r.iter_mut().zip(&w.mv) {
                *r -= coef * m;
            }
        }
        let (u, ud, p, pd) = (
            self.state.u.clone(),
            self.state.ud.clone(),
            self.state.p.clone(),
            self.state.pd.clone(),
        );
        self.add_bearing_forces(&u, &ud, &p, &pd, speed, t)?;
        let lu = self.rotor.mass.lu()?;
        let mut acc = self.work.r.clone();
        lu.solve_in_place(&mut acc)?;
        self.state.udd = acc;
        Ok(())
    }

    /// Outputs at the current state.
    pub fn outputs(&mut self) -> Result<Outputs, SolverError> {
        let t = self.state.time;
        let speed = self.speed_at(t);
        let mut bearings = Vec::with_capacity(self.output_bearings.len());
        let mut friction_torque = 0.0;
        for (k, (bearing, site)) in self.output_bearings.iter().enumerate() {
            let node = self.rotor.model.bearings[k].node;
            let at = |dof: usize, v: &[f64]| self.rotor.dofs.free(node, dof).map_or(0.0, |i| v[i]);
            let (x, y) = (at(DOF_X, &self.state.u), at(DOF_Y, &self.state.u));
            let (vx, vy) = (at(DOF_X, &self.state.ud), at(DOF_Y, &self.state.ud));
            let internal = bearing.internal_dofs();
            let eval = &mut self.output_evals[k];
            let (q, qd) = (
                &mut self.output_q[..2 + internal],
                &mut self.output_qd[..2 + internal],
            );
            (q[0], q[1], qd[0], qd[1]) = (x, y, vx, vy);
            if let Some(si) = site {
                let s = &self.sites[*si];
                q[2..].copy_from_slice(&self.state.p[s.offset..s.offset + internal]);
                qd[2..].copy_from_slice(&self.state.pd[s.offset..s.offset + internal]);
            }
            bearing
                .evaluate(q, qd, speed, eval)
                .map_err(|source| SolverError::Bearing {
                    name: self.rotor.model.bearings[k].name.clone(),
                    time: t,
                    source,
                })?;
            let report = bearing.report(q, speed, eval);
            friction_torque += report.friction_torque;
            bearings.push(BearingOutput {
                x,
                y,
                fx: eval.force[0],
                fy: eval.force[1],
                report,
            });
        }
        let probes = self
            .rotor
            .model
            .probes
            .iter()
            .map(|p| ProbeOutput {
                x: self
                    .rotor
                    .dofs
                    .free(p.node, DOF_X)
                    .map_or(0.0, |i| self.state.u[i]),
                y: self
                    .rotor
                    .dofs
                    .free(p.node, DOF_Y)
                    .map_or(0.0, |i| self.state.u[i]),
            })
            .collect();
        Ok(Outputs {
            time: t,
            speed,
            spin_angle: self.state.spin_angle,
            bearings,
            probes,
            friction_torque,
        })
    }
}

/// Condense a bearing's internal coordinates (pad tilts) onto its journal: with
/// `K = K_b + a1 C_b` from `ev` (journal first, then `m` internal), returns
/// `K_c = K_jj − K_jp K_pp⁻¹ K_pj` (row-major 2×2) and `w = K_jp K_pp⁻¹ (−F_p)`;
/// `x` receives the three columns `K_pp⁻¹ [K_pj | −F_p]` and `kpp`, `piv` are
/// workspace. A diagonal `K_pp` (pads acting on the journal only) is divided
/// directly. `None` when `K_pp` is singular.
fn condense_internal(
    ev: &BearingEval,
    a1: f64,
    kpp: &mut [f64],
    piv: &mut [usize],
    x: &mut [f64],
) -> Option<([f64; 4], [f64; 2])> {
    let n2 = ev.n();
    let mi = n2 - 2;
    let keff = |i: usize, j: usize| ev.stiffness[i * n2 + j] + a1 * ev.damping[i * n2 + j];
    let mut kc = [keff(0, 0), keff(0, 1), keff(1, 0), keff(1, 1)];
    let mut wv = [0.0; 2];
    if mi == 0 {
        return Some((kc, wv));
    }
    let mut uncoupled = true;
    for r in 0..mi {
        for c in 0..mi {
            let v = keff(2 + r, 2 + c);
            kpp[r * mi + c] = v;
            uncoupled &= r == c || v == 0.0;
        }
        x[r] = keff(2 + r, 0);
        x[mi + r] = keff(2 + r, 1);
        x[2 * mi + r] = -ev.force[2 + r];
    }
    if uncoupled {
        for r in 0..mi {
            let d = kpp[r * mi + r];
            if d == 0.0 || !d.is_finite() {
                return None;
            }
            for column in 0..3 {
                x[column * mi + r] /= d;
            }
        }
    } else {
        if !lu_in_place(kpp, mi, piv) {
            return None;
        }
        for column in x.chunks_exact_mut(mi) {
            lu_solve(kpp, mi, piv, column);
        }
    }
    for i in 0..2 {
        for r in 0..mi {
            let kjp = keff(i, 2 + r);
            kc[2 * i] -= kjp * x[r];
            kc[2 * i + 1] -= kjp * x[mi + r];
            wv[i] += kjp * x[2 * mi + r];
        }
    }
    Some((kc, wv))
}

fn plane_slot(values: &mut [f64], plane: usize) -> Result<&mut f64, SolverError> {
    let count = values.len();
    values.get_mut(plane).ok_or_else(|| {
        SolverError::Input(format!(
            "no unbalance plane {plane} (the model has {count})"
        ))
    })
}

fn speed_band_changed(reference: f64, speed: f64) -> bool {
    (speed - reference).abs() > 0.02 * reference.abs().max(1.0)
}

fn inf_norm(v: &[f64]) -> f64 {
    v.iter().fold(0.0, |a, x| a.max(x.abs()))
}

fn check_options(o: &SolverOptions) -> Result<(), SolverError> {
    let bad = |what: &str, v: f64| {
        SolverError::Input(format!("solver option {what} = {v} is out of range"))
    };
    if !(o.time_step.is_finite() && o.time_step > 0.0) {
        return Err(bad("time_step", o.time_step));
    }
    if !(o.tolerance.is_finite() && o.tolerance > 0.0 && o.tolerance < 1.0) {
        return Err(bad("tolerance", o.tolerance));
    }
    if o.max_iterations == 0 {
        return Err(bad("max_iterations", 0.0));
    }
    if !(o.unbalance_ramp_time.is_finite() && o.unbalance_ramp_time >= 0.0) {
        return Err(bad("unbalance_ramp_time", o.unbalance_ramp_time));
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::RotorModel;

    fn jeffcott() -> Simulator {
        let path = concat!(env!("CARGO_MANIFEST_DIR"), "/models/jeffcott.toml");
        let model = RotorModel::from_file(std::path::Path::new(path)).unwrap();
        let speed = model.nominal_speed;
        let mut sim = Simulator::new(Rotor::new(model).unwrap(), SolverOptions::default()).unwrap();
        sim.set_speed(speed, 0.0).unwrap();
        sim.settle_static().unwrap();
        sim.set_speed(speed, 200.0).unwrap();
        sim
    }

    /// The condensed 2×2 stiffness and load of a bearing with internal
    /// coordinates equal the dense Schur complement, for coupled (LU) and
    /// uncoupled (diagonal) internal blocks.
    #[test]
    fn internal_coordinates_condense_to_the_schur_complement() {
        let mut seed = 11u64;
        let mut rand = || {
            seed = seed
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            (seed >> 11) as f64 / (1u64 << 53) as f64 - 0.5
        };
        for coupled in [true, false] {
            let (m, a1) = (3, 7.0);
            let n2 = 2 + m;
            let mut ev = BearingEval::new(n2);
            for i in 0..n2 {
                ev.force[i] = rand();
                for j in 0..n2 {
                    let internal_pair = i >= 2 && j >= 2 && i != j;
                    let (k, c) = if internal_pair && !coupled {
                        (0.0, 0.0)
                    } else {
                        (rand() + if i == j { 3.0 } else { 0.0 }, rand())
                    };
                    ev.stiffness[i * n2 + j] = k;
                    ev.damping[i * n2 + j] = c;
                }
            }
            let (mut kpp, mut piv, mut x) = (vec![0.0; m * m], vec![0; m], vec![0.0; 3 * m]);
            let (kc, wv) = condense_internal(&ev, a1, &mut kpp, &mut piv, &mut x).unwrap();
            let k = nalgebra::DMatrix::from_fn(n2, n2, |i, j| {
                ev.stiffness[i * n2 + j] + a1 * ev.damping[i * n2 + j]
            });
            let kjj = k.view((0, 0), (2, 2));
            let kjp = k.view((0, 2), (2, m));
            let kpp_inv = k.view((2, 2), (m, m)).into_owned().try_inverse().unwrap();
            let schur = kjj - kjp * &kpp_inv * k.view((2, 0), (m, 2));
            let fp = nalgebra::DVector::from_fn(m, |r, _| -ev.force[2 + r]);
            let load = kjp * &kpp_inv * fp;
            for i in 0..2 {
                for j in 0..2 {
                    assert!(
                        (kc[2 * i + j] - schur[(i, j)]).abs() < 1e-12,
                        "coupled {coupled}"
                    );
                }
                assert!((wv[i] - load[i]).abs() < 1e-12, "coupled {coupled}");
            }
        }
    }

    /// During a run-up the speed changes every step. The condensed Newton on an
    /// exact refactorization and the full-residual Newton on a factorization
    /// held within the ±2 % speed band solve the same equations: their orbits
    /// agree to the Newton tolerance (1e-8 of the clearance) over the run.
    #[test]
    fn condensed_and_full_residual_newton_agree_on_a_run_up() {
        let mut exact = jeffcott();
        let mut banded = jeffcott();
        banded.refactor_journal_limit = 0;
        let clearance = exact.length_scale;
        let mut worst: f64 = 0.0;
        for k in 1..=200 {
            let t = k as f64 * 2.5e-4;
            exact.advance_to(t).unwrap();
            banded.advance_to(t).unwrap();
            for &dof in &exact.journal_dofs {
                worst = worst.max((exact.state.u[dof] - banded.state.u[dof]).abs());
            }
        }
        assert!(worst < 1e-8 * clearance, "orbits differ by {worst:e} m");
        // The paths really differ: one factorization per step against a few.
        assert!(exact.stats().factorizations >= 400, "{:?}", exact.stats());
        assert!(banded.stats().factorizations < 10, "{:?}", banded.stats());
        assert!(banded.stats().iterations > exact.stats().iterations);
    }
}
