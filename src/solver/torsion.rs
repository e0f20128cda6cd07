//! A torque-driven shaft (`[torsion] drive = "torque"`): the twist of every
//! node is a state, driven by the torques at the `[[torques]]` nodes, and the
//! lateral motion and the twist are stepped together.
//!
//! Torsional equations: `M_t φ̈ + C_t φ̇ + K_t φ = T_in(t) + T_c`, Newmark
//! average acceleration like the lateral ones, with the coupling torques
//! `T_c` on the shaft at each node:
//! - the friction torque of every bearing, rub, seal and pull there,
//!   `−T_f` (film shear and contact friction, [`Bearing::report`]), and of
//!   every thrust bearing, `−T(φ̇)` ([`ThrustBearing`], implicit in the
//!   torsional Newton with its derivative);
//! - the reaction of each unbalance `m e` at angle `φ`: the torque the shaft
//!   spends carrying the unbalance mass along the node's lateral
//!   acceleration, `−m e (ÿ cos φ − ẍ sin φ)` (the lateral unbalance force
//!   uses the node's own `φ` and `φ̇` at the step's end and its `φ̈` over the
//!   step, as a prescribed speed profile gives it, so the pair exchanges
//!   energy and a torsionally rigid shaft repeats the speed-driven run).
//!
//! The lateral step runs at the shaft's mean speed `Ω = Σ J_i φ̇_i / Σ J_i`
//! (gyroscopic moments and films; the node speeds differ from it only by the
//! torsional vibration), linear within the step as Newmark's velocity is.
//! Within each step the two are iterated (block Gauss–Seidel) until the
//! coupling torques agree to the solver tolerance, or until their change
//! calls for a twist correction the lateral step would not see, which the
//! torsional step then takes ([`absorb_coupling_change`]); so the coupled
//! step solves the coupled equations.
//!
//! At rest the shaft sticks: while the net input torque is within the
//! breakaway torque (the thrust bearings' `μ_b W R_m` plus the journals'
//! contact friction at standstill, `μ N R`) every node stays at exactly zero
//! speed; past it the shaft breaks away, and a mean speed that reaches zero
//! with the input torque within the breakaway torque sticks again. A stuck
//! shaft takes the static wind-up of its inputs against the friction that
//! holds it ([`Simulator::static_wind_up`]), so its section torques are
//! what a coupling carries at start.
//!
//! [`Bearing::report`]: crate::bearing::Bearing::report
//! [`ThrustBearing`]: crate::bearing::thrust::ThrustBearing

use crate::bearing::Bearing;
use crate::bearing::thrust::ThrustBearing;
use crate::fe::{DOF_X, DOF_Y};
use crate::units::{RAD_S_TO_RPM, Short};

use super::error::SolverError;
use super::simulator::Simulator;
use super::state::SimState;
use super::torsion_work::Torsion;

/// Coupled iterations allowed per step before it is cut.
const MAX_COUPLING_ITERATIONS: usize = 50;

/// Newton iterations allowed for the torsional step (thrust friction).
const MAX_TORSION_ITERATIONS: usize = 50;

impl Simulator {
    /// The torque (N·m) in shaft element `element` (from node `element` to
    /// the next), the twist of the far end over the near one times its
    /// torsional stiffness plus damping (a coupling's where one is; a twist
    /// a support holds is zero); `None` when the speed is prescribed or there
    /// is no such element.
    pub fn section_torque(&self, element: usize) -> Option<f64> {
        let tors = self.torsion.as_ref()?;
        let &(k, c) = tors.chain.elements.get(element)?;
        let s = &self.state;
        let at = |node: usize| {
            tors.chain.dofs[node].map_or((0.0, 0.0), |i| (s.twist[i], s.twist_rate[i]))
        };
        let (near, far) = (at(element), at(element + 1));
        Some(k * (far.0 - near.0) + c * (far.1 - near.1))
    }

    /// The speed (rad/s) and angle (rad) of `node` (0-based): its twist of a
    /// torque-driven shaft, else the prescribed speed and spin angle.
    pub fn node_rotation(&self, node: usize) -> (f64, f64) {
        let s = &self.state;
        match self.torsion.as_ref().and_then(|t| t.chain.dofs[node]) {
            Some(i) => (s.twist_rate[i], s.twist[i]),
            None if self.torsion.is_some() => (0.0, 0.0),
            None => (self.speed_at(s.time), s.spin_angle),
        }
    }

    /// The friction torque (N·m, opposing the spin) of thrust bearing `k`
    /// (model order) at its node's speed; at standstill its breakaway
    /// torque, as the journals' contact friction reports `μ N R` there.
    pub fn thrust_friction(&self, k: usize) -> f64 {
        let t = &self.rotor.model.thrust_bearings[k];
        let (speed, _) = self.node_rotation(t.node);
        if speed == 0.0 {
            return t.bearing.breakaway_torque();
        }
        t.bearing.friction_torque(speed).0
    }

    /// The net input torque (N·m) of the `[[torques]]` at time `t`.
    fn input_torque(&self, t: f64) -> f64 {
        let Some(tors) = &self.torsion else {
            return 0.0;
        };
        tors.inputs.iter().map(|&(k, _)| self.load_at(k, t)).sum()
    }

    /// Friction torques of the sites at the lateral iterate (`newmark.u`,
    /// `ud`, `p`, `pd`, or the state with `at_state`) at spin `speed`, added
    /// (as torques on the shaft, `−T_f`) into `torsion.fresh` when `add`;
    /// returns the sum of their magnitudes (at rest: their breakaway torque).
    fn site_friction(&mut self, speed: f64, at_state: bool, add: bool) -> Result<f64, SolverError> {
        let Some(tors) = self.torsion.as_mut() else {
            return Ok(0.0);
        };
        let (u, ud, p, pd) = if at_state {
            (&self.state.u, &self.state.ud, &self.state.p, &self.state.pd)
        } else {
            (
                &self.newmark.u,
                &self.newmark.ud,
                &self.newmark.p,
                &self.newmark.pd,
            )
        };
        let mut total = 0.0;
        for (k, site) in self.sites.list.iter_mut().enumerate() {
            for (a, c) in site.journal.iter().enumerate() {
                site.q[a] = c.of(u);
                site.qd[a] = c.of(ud);
            }
            let range = site.offset..site.offset + site.internal;
            site.q[2..].copy_from_slice(&p[range.clone()]);
            site.qd[2..].copy_from_slice(&pd[range]);
            // The report's numbers without the Jacobians (`Bearing::output`).
            let torque = site
                .bearing
                .output(&site.q, &site.qd, speed, &mut tors.eval[k])
                .map_err(|source| SolverError::Bearing {
                    name: site.name.clone(),
                    time: self.state.time,
                    source,
                })?
                .friction_torque;
            total += torque.abs();
            if let (true, Some(i)) = (add, tors.site_dofs[k]) {
                tors.fresh[i] -= torque;
            }
        }
        Ok(total)
    }

    /// The unbalance reaction torques `−m e (ÿ cos φ − ẍ sin φ)` at the step's
    /// end (lateral accelerations from `newmark.udd`), added into
    /// `torsion.fresh`.
    fn unbalance_reaction(&mut self, t: f64) {
        let Some(tors) = self.torsion.as_mut() else {
            return;
        };
        let s = &self.state;
        let ramp = if self.options.unbalance_ramp_time > 0.0 {
            1.0 - (-t / self.options.unbalance_ramp_time).exp()
        } else {
            1.0
        };
        for (k, plane) in self.rotor.model.unbalances.iter().enumerate() {
            let Some(i) = tors.planes[k] else { continue };
            let me = (s.unbalance[k] + s.unbalance_rate[k] * (t - s.speed_time)).max(0.0) * ramp;
            let phi = tors.theta[i] + s.unbalance_phase[k];
            let ax = self.rotor.node_value(plane.node, DOF_X, &self.newmark.udd);
            let ay = self.rotor.node_value(plane.node, DOF_Y, &self.newmark.udd);
            tors.fresh[i] -= me * (ay * phi.cos() - ax * phi.sin());
        }
    }

    /// The torsional Newmark step of size `h` with the coupling torques in
    /// `torsion.coupling` and the inputs at `t1`, into `torsion.theta`,
    /// `omega`, `alpha`.
    fn torsional_step(&mut self, h: f64, t1: f64) -> Result<(), SolverError> {
        let Some(mut tors) = self.torsion.take() else {
            return Ok(());
        };
        for (v, &(k, _)) in tors.input_values.iter_mut().zip(&tors.inputs) {
            *v = self.load_at(k, t1);
        }
        let outcome = torsional_newton(&mut tors, &self.state, h);
        let speed = tors.mean(&tors.omega);
        self.torsion = Some(tors);
        outcome?;
        self.check_overspeed(speed, t1)
    }

    /// A torque-driven shaft whose mean speed `speed` (rad/s) at `t1` (s)
    /// would exceed the model's `max_speed_rpm` fails its step: the state
    /// stays at or below the limit (so it can be saved and restored), and a
    /// step that cannot be cut below the crossing is the call's error,
    /// named in the torque and in rpm.
    fn check_overspeed(&self, speed: f64, t1: f64) -> Result<(), SolverError> {
        let max = self.rotor.model.max_speed;
        if speed.abs() <= max {
            return Ok(());
        }
        Err(SolverError::Budget(format!(
            "the torque inputs (net {} N·m) would accelerate the shaft to {:.1} rpm by t = {:.6} s, beyond the model's max_speed_rpm ({:.0} rpm): the state is kept at or below it",
            Short(self.input_torque(t1)),
            speed * RAD_S_TO_RPM,
            t1,
            max * RAD_S_TO_RPM
        )))
    }

    /// Point the lateral step at the speed profile of the torsional iterate:
    /// the mean speed from the state's to the iterate's, and each unbalance
    /// plane's node angle and speed at the step's end and acceleration over
    /// the step.
    fn drive_lateral(&mut self, h: f64) {
        let Some(tors) = &self.torsion else { return };
        let w0 = tors.mean(&self.state.twist_rate);
        let w1 = tors.mean(&tors.omega);
        let s = &mut self.state;
        s.speed = w0;
        s.speed_rate = (w1 - w0) / h;
        s.speed_time = s.time;
        // The unbalance takes the node's acceleration over the step, as a
        // prescribed speed profile does (its rate, linear within the step).
        let motion = &mut self.newmark.plane_motion;
        motion.clear();
        for dof in &tors.planes {
            motion.push(match *dof {
                Some(i) => [
                    tors.theta[i],
                    tors.omega[i],
                    (tors.omega[i] - s.twist_rate[i]) / h,
                ],
                None => [0.0; 3],
            });
        }
    }

    /// One coupled step of a torque-driven shaft (see the module docs).
    pub(super) fn try_coupled_step(&mut self, h: f64) -> Result<Option<f64>, SolverError> {
        let t1 = self.state.time + h;
        // Re-base every input to the step's start: the lateral speed profile
        // is then set from the twist.
        self.rebase_inputs();
        let drive = self.input_torque(t1);
        if self.state.stuck != 0.0 {
            let at_rest = self.site_friction(0.0, true, false)?;
            let capacity = self.torsion.as_ref().map_or(0.0, |t| t.breakaway(at_rest));
            if drive.abs() <= capacity {
                return self.hold_at_rest(h, t1);
            }
            self.state.stuck = 0.0;
            self.breakaway_acceleration(drive)?;
        }
        if let Some(t) = self.torsion.as_mut() {
            t.coupling.copy_from_slice(&self.state.twist_torque);
        }
        let mut last = f64::INFINITY;
        for _ in 0..MAX_COUPLING_ITERATIONS {
            self.torsional_step(h, t1)?;
            self.drive_lateral(h);
            if let Some(residual) = self.solve_lateral_step(h)? {
                return Ok(Some(residual));
            }
            let speed1 = self.speed_at(t1);
            if let Some(t) = self.torsion.as_mut() {
                t.fresh.fill(0.0);
            }
            self.site_friction(speed1, false, true)?;
            self.unbalance_reaction(t1);
            let Some(tors) = self.torsion.as_mut() else {
                break;
            };
            let size = tors
                .fresh
                .iter()
                .chain(tors.coupling.iter())
                .fold(0.0_f64, |m, v| m.max(v.abs()))
                .max(drive.abs())
                .max(f64::MIN_POSITIVE);
            let change = tors
                .fresh
                .iter()
                .zip(&tors.coupling)
                .fold(0.0_f64, |m, (a, b)| m.max((a - b).abs()));
            let absorbed = change > self.options.tolerance * size
                && absorb_coupling_change(tors, h, self.options.tolerance);
            std::mem::swap(&mut tors.coupling, &mut tors.fresh);
            if change <= self.options.tolerance * size || absorbed {
                // The sites' breakaway torque matters only where the mean
                // speed reaches or crosses zero (`commit_coupled_step`).
                let w1 = tors.mean(&tors.omega);
                let w0 = self.speed_at(self.state.time);
                let at_rest = if w1 == 0.0 || w0 * w1 < 0.0 {
                    self.site_friction(0.0, false, false)?
                } else {
                    0.0
                };
                self.commit_coupled_step(h, drive, at_rest);
                return Ok(None);
            }
            last = change / size;
        }
        Ok(Some(last))
    }

    /// Take the converged coupled step: twist, coupling torques, lateral
    /// state; a mean speed that reaches or crosses zero with the input torque
    /// within the breakaway torque (`at_rest`: the sites' part, needed only
    /// then) sticks.
    fn commit_coupled_step(&mut self, h: f64, drive: f64, at_rest: f64) {
        let w0 = self.speed_at(self.state.time);
        self.commit_lateral_step(h);
        let Some(tors) = self.torsion.as_mut() else {
            return;
        };
        let capacity = tors.breakaway(at_rest);
        let s = &mut self.state;
        s.twist.copy_from_slice(&tors.theta);
        s.twist_rate.copy_from_slice(&tors.omega);
        s.twist_accel.copy_from_slice(&tors.alpha);
        s.twist_torque.copy_from_slice(&tors.coupling);
        let w1 = tors.mean(&tors.omega);
        if (w1 == 0.0 || w0 * w1 < 0.0) && drive.abs() <= capacity {
            s.stuck = 1.0;
            s.twist_rate.fill(0.0);
            s.twist_accel.fill(0.0);
        }
        // The speed profile stays the step's (from its start, where every
        // input was re-based); a stuck shaft is at rest.
        if s.stuck != 0.0 {
            s.speed = 0.0;
            s.speed_rate = 0.0;
        }
    }

    /// At breakaway the shaft accelerates at once: the twist accelerations
    /// consistent with the inputs at the step's start and the friction at
    /// the onset of sliding (each bearing's breakaway torque, opposing the
    /// net input `drive`), `M_t φ̈ = T_in − T_f − K_t φ − C_t φ̇`, so that
    /// Newmark's first step neither lags nor breaks the energy balance.
    fn breakaway_acceleration(&mut self, drive: f64) -> Result<(), SolverError> {
        let sign = drive.signum();
        // The sites' contact friction at rest, as if sliding the way the drive pushes.
        self.consistent_twist_acceleration(0.0, sign, |t, _| sign * t.breakaway_torque())
    }

    /// The twist accelerations consistent with the state of a turning shaft
    /// and the inputs now, `M_t φ̈ = T_in − T_f − T_thrust(φ̇) − K_t φ − C_t φ̇`
    /// (the sites' friction at the mean speed, each thrust bearing's at its
    /// node's speed): a run that starts at speed under a torque starts
    /// Newmark from the acceleration it has (a zero one is a lag of
    /// `h/2 · φ̈` in the speed that never decays).
    pub(super) fn running_acceleration(&mut self) -> Result<(), SolverError> {
        if self.torsion.is_none() || self.state.stuck != 0.0 {
            return Ok(());
        }
        let speed = self.speed_at(self.state.time);
        self.consistent_twist_acceleration(speed, 1.0, |t, rate| t.friction_torque(rate).0)
    }

    /// `M_t φ̈ = sign · T_sites + T_in − Σ T_thrust − K_t φ − C_t φ̇` at the
    /// state into its twist accelerations: the sites' friction torques taken
    /// at spin `speed` (as torques on the shaft), each thrust bearing's
    /// `thrust(bearing, φ̇ of its node)`.
    fn consistent_twist_acceleration(
        &mut self,
        speed: f64,
        sign: f64,
        thrust: impl Fn(&ThrustBearing, f64) -> f64,
    ) -> Result<(), SolverError> {
        if let Some(t) = self.torsion.as_mut() {
            t.fresh.fill(0.0);
        }
        self.site_friction(speed, true, true)?;
        let t0 = self.state.time;
        let Some(mut tors) = self.torsion.take() else {
            return Ok(());
        };
        let s = &self.state;
        for (r, f) in tors.rhs.iter_mut().zip(&tors.fresh) {
            *r = sign * f;
        }
        for &(k, dof) in &tors.inputs {
            if let Some(i) = dof {
                tors.rhs[i] += self.load_at(k, t0);
            }
        }
        for (dof, t) in &tors.thrust {
            if let Some(i) = *dof {
                tors.rhs[i] -= thrust(t, s.twist_rate[i]);
            }
        }
        for (m, x) in [
            (&tors.chain.stiffness, &s.twist),
            (&tors.chain.damping, &s.twist_rate),
        ] {
            m.mul_vec(x, &mut tors.scratch);
            for (r, v) in tors.rhs.iter_mut().zip(&tors.scratch) {
                *r -= v;
            }
        }
        let outcome = tors.chain.mass.lu().map(|lu| {
            lu.solve_in_place(&mut tors.rhs);
            self.state.twist_accel.copy_from_slice(&tors.rhs);
        });
        self.torsion = Some(tors);
        Ok(outcome?)
    }

    /// A step of the shaft held at rest by static friction: no twist motion
    /// but its static wind-up under the inputs at the step's end `t1`
    /// ([`Simulator::static_wind_up`]), the lateral step at zero speed.
    fn hold_at_rest(&mut self, h: f64, t1: f64) -> Result<Option<f64>, SolverError> {
        let s = &mut self.state;
        s.speed = 0.0;
        s.speed_rate = 0.0;
        s.speed_time = s.time;
        self.static_wind_up(t1)?;
        self.drive_lateral(h);
        let outcome = self.solve_lateral_step(h)?;
        if outcome.is_none() {
            self.commit_lateral_step(h);
            if let Some(tors) = self.torsion.as_ref() {
                let s = &mut self.state;
                s.twist.copy_from_slice(&tors.theta);
                s.twist_rate.fill(0.0);
                s.twist_accel.fill(0.0);
            }
        }
        Ok(outcome)
    }

    /// The twist of a shaft that static friction holds at rest, into
    /// `torsion.theta` (rates zero): `K_t φ = T_in(t1) + T_r`, where the
    /// reactions `T_r` of the elements that hold it (each thrust bearing and
    /// each bearing, rub, seal or pull in contact at rest) balance the net
    /// input torque in proportion to each one's breakaway torque; a chain
    /// that no support fixes keeps its inertia-weighted mean twist (the shaft
    /// does not turn). Opposing torques at the two ends of a stuck shaft so
    /// twist it by `T L / (G J)` (tests/reliability.rs).
    fn static_wind_up(&mut self, t1: f64) -> Result<(), SolverError> {
        if let Some(t) = self.torsion.as_mut() {
            t.fresh.fill(0.0);
        }
        // The sites' friction at rest, as torques on the shaft at their DOFs:
        // their magnitudes are the capacities.
        self.site_friction(0.0, true, true)?;
        let Some(mut tors) = self.torsion.take() else {
            return Ok(());
        };
        let n = tors.chain.dof_count();
        for c in tors.fresh.iter_mut() {
            *c = c.abs();
        }
        for (dof, t) in &tors.thrust {
            if let Some(i) = *dof {
                tors.fresh[i] += t.breakaway_torque();
            }
        }
        tors.rhs.fill(0.0);
        for &(k, dof) in &tors.inputs {
            if let Some(i) = dof {
                tors.rhs[i] += self.load_at(k, t1);
            }
        }
        let free = tors.chain.dofs.iter().all(Option::is_some);
        let net: f64 = tors.rhs.iter().sum();
        let capacity: f64 = tors.fresh.iter().sum();
        if free && capacity > 0.0 {
            for (r, c) in tors.rhs.iter_mut().zip(&tors.fresh) {
                *r -= net * c / capacity;
            }
        }
        tors.a.assign(&tors.chain.stiffness);
        if free && n > 0 {
            // The rigid-body rotation: pin the first twist, then shift.
            tors.a.set(0, 0, 1.0);
            if n > 1 {
                tors.a.set(0, 1, 0.0);
                tors.a.set(1, 0, 0.0);
            }
            tors.rhs[0] = 0.0;
        }
        let outcome = tors.factor();
        if outcome.is_ok() {
            tors.lu.solve_in_place(&mut tors.rhs);
            if free {
                let shift = tors.mean(&self.state.twist) - tors.mean(&tors.rhs);
                for (theta, r) in tors.theta.iter_mut().zip(&tors.rhs) {
                    *theta = r + shift;
                }
            } else {
                tors.theta.copy_from_slice(&tors.rhs);
            }
            tors.omega.fill(0.0);
            tors.alpha.fill(0.0);
        }
        self.torsion = Some(tors);
        Ok(outcome?)
    }
}

/// Newton on the torsional Newmark step from state `s` (step `h`):
/// Take the coupling torques' change over the iteration, `ΔT = T_fresh −
/// T_c` (in `fresh` and `coupling`), into the torsional step by its linear
/// correction when the lateral step would not see it; returns whether it
/// did. The correction `Δφ = A_t⁻¹ ΔT`, with the torsional step's Newmark
/// matrix (the factor of its last Newton iteration, thrust slope included),
/// is one Newton step of the torsional equations at the fresh torques. When
/// it is within the Newton tolerance `tol` in rad (the unbalance force's
/// direction moves by less than `tol` of its size) and its rate `(2/h) Δφ`
/// within `tol` of the mean speed (at least 1 rad/s; the films and the
/// gyroscopic moments take the speed), the lateral step stands as solved and
/// the twist, its rates and the section torques take the correction: the
/// coupled equations hold to the tolerance with one lateral solve instead of
/// two (issue 51: the torque-driven hydro unit's coupling change after the
/// first iteration calls for about 3e-13 rad).
fn absorb_coupling_change(tors: &mut Torsion, h: f64, tol: f64) -> bool {
    for ((d, fresh), used) in tors.scratch.iter_mut().zip(&tors.fresh).zip(&tors.coupling) {
        *d = fresh - used;
    }
    tors.lu.solve_in_place(&mut tors.scratch);
    let twist = tors.scratch.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
    let speed = tors.mean(&tors.omega).abs().max(1.0);
    if !(twist <= tol && 2.0 / h * twist <= tol * speed) {
        return false;
    }
    // The Newmark rates are linear in the step's end twist.
    let (a0, a1) = (4.0 / (h * h), 2.0 / h);
    for (((theta, omega), alpha), d) in tors
        .theta
        .iter_mut()
        .zip(tors.omega.iter_mut())
        .zip(tors.alpha.iter_mut())
        .zip(&tors.scratch)
    {
        *theta += d;
        *omega += a1 * d;
        *alpha += a0 * d;
    }
    true
}

/// `M α + C ω + K θ = T_in + T_c − T_thrust(ω)` with the Newmark rates of
/// `θ`, with backtracking on the residual (the thrust friction turns over
/// sharply near rest).
fn torsional_newton(tors: &mut Torsion, s: &SimState, h: f64) -> Result<(), SolverError> {
    let (a0, a1, a2) = (4.0 / (h * h), 2.0 / h, 4.0 / h);
    let n = tors.chain.dof_count();
    // Predictor.
    for i in 0..n {
        tors.theta[i] = s.twist[i] + h * s.twist_rate[i] + 0.5 * h * h * s.twist_accel[i];
    }
    let mut residual = torsional_residual(tors, s, (a0, a1, a2), true);
    for _ in 0..MAX_TORSION_ITERATIONS {
        tors.factor()?;
        tors.scratch.copy_from_slice(&tors.rhs);
        tors.lu.solve_in_place(&mut tors.scratch);
        let step = tors.scratch.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
        let scale = tors
            .theta
            .iter()
            .fold(0.0_f64, |m, v| m.max(v.abs()))
            .max(1.0);
        // The Newton direction, then backtracking along it.
        tors.fresh.copy_from_slice(&tors.scratch);
        let mut t = 1.0;
        loop {
            for (theta, d) in tors.theta.iter_mut().zip(&tors.fresh) {
                *theta += t * d;
            }
            let trial = torsional_residual(tors, s, (a0, a1, a2), true);
            if trial <= residual || t < 1e-8 {
                residual = trial;
                break;
            }
            for (theta, d) in tors.theta.iter_mut().zip(&tors.fresh) {
                *theta -= t * d;
            }
            t *= 0.5;
        }
        if step <= 1e-14 * scale || residual == 0.0 {
            return Ok(());
        }
    }
    Err(SolverError::Input(
        "the torsional step did not converge (thrust bearing friction)".into(),
    ))
}

/// The torsional residual `T_in + T_c − T_thrust − M α − C ω − K θ` at
/// `torsion.theta` into `torsion.rhs` (rates updated), and with `jacobian`
/// its Jacobian into `torsion.a`; returns its largest entry.
fn torsional_residual(
    tors: &mut Torsion,
    s: &SimState,
    (a0, a1, a2): (f64, f64, f64),
    jacobian: bool,
) -> f64 {
    for i in 0..tors.theta.len() {
        let d = tors.theta[i] - s.twist[i];
        tors.omega[i] = a1 * d - s.twist_rate[i];
        tors.alpha[i] = a0 * d - a2 * s.twist_rate[i] - s.twist_accel[i];
    }
    tors.rhs.copy_from_slice(&tors.coupling);
    for (&(_, dof), t) in tors.inputs.iter().zip(&tors.input_values) {
        if let Some(i) = dof {
            tors.rhs[i] += t;
        }
    }
    if jacobian {
        // Formed once a step size, in the same order: the same bits.
        if tors.base_for != [a0, a1] {
            tors.base.assign(&tors.chain.stiffness);
            tors.base.scale_add(a1, &tors.chain.damping);
            tors.base.scale_add(a0, &tors.chain.mass);
            tors.base_for = [a0, a1];
        }
        tors.a.assign(&tors.base);
    }
    for (dof, t) in &tors.thrust {
        if let Some(i) = *dof {
            let (torque, slope) = t.friction_torque(tors.omega[i]);
            tors.rhs[i] -= torque;
            if jacobian {
                tors.a.add(i, i, a1 * slope);
            }
        }
    }
    for (m, x) in [
        (&tors.chain.mass, &tors.alpha),
        (&tors.chain.damping, &tors.omega),
        (&tors.chain.stiffness, &tors.theta),
    ] {
        m.mul_vec(x, &mut tors.scratch);
        for (r, v) in tors.rhs.iter_mut().zip(&tors.scratch) {
            *r -= v;
        }
    }
    tors.rhs.iter().fold(0.0_f64, |m, v| m.max(v.abs()))
}
