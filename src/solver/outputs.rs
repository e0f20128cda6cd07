//! What the simulator reports at the current time: per bearing the journal,
//! its force and film report and its housing's motion, per probe and port
//! the node's motion, per thrust bearing its friction, the spin, the friction
//! torque and power loss, and on a torque-driven shaft the rotation of the
//! torque nodes and the torque in each shaft element (`Simulator::outputs`).

use crate::bearing::BearingReport;
use crate::fe::{DOF_X, DOF_Y};

use super::error::SolverError;
use super::simulator::Simulator;

/// Absolute motion of a bearing's housing (zero on rigid ground): what a
/// seismic sensor on the bracket or pedestal measures.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct HousingOutput {
    /// Displacement (m).
    pub x: f64,
    /// Displacement (m).
    pub y: f64,
    /// Velocity (m/s).
    pub vx: f64,
    /// Velocity (m/s).
    pub vy: f64,
}

/// Outputs of one bearing.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct BearingOutput {
    /// Journal displacement (m), absolute; relative to the housing (what a
    /// proximity probe on the bearing measures) it is `x − housing.x`.
    pub x: f64,
    /// Journal displacement (m), absolute.
    pub y: f64,
    /// Force of the bearing on the journal (N).
    pub fx: f64,
    /// Force of the bearing on the journal (N).
    pub fy: f64,
    /// Film reports (eccentricity, friction…), from the journal's motion
    /// relative to its housing.
    pub report: BearingReport,
    /// Static load: the force of the bearing on the journal at the static
    /// equilibrium the run started from ([`SimState::static_load`], N).
    ///
    /// [`SimState::static_load`]: super::SimState::static_load
    pub static_fx: f64,
    /// Static load y (N).
    pub static_fy: f64,
    /// The housing's absolute motion (zero on rigid ground).
    pub housing: HousingOutput,
}

impl BearingOutput {
    /// Dynamic load: the force on the journal minus its static load,
    /// `(fx − static_fx, fy − static_fy)` (N).
    pub fn dynamic_load(&self) -> (f64, f64) {
        (self.fx - self.static_fx, self.fy - self.static_fy)
    }

    /// Journal displacement relative to the housing, `(x, y)` (m).
    pub fn relative(&self) -> (f64, f64) {
        (self.x - self.housing.x, self.y - self.housing.y)
    }
}

/// Displacements of one probe.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct ProbeOutput {
    /// Displacement (m).
    pub x: f64,
    /// Displacement (m).
    pub y: f64,
}

/// Motion of one force port (`[[ports]]`).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct PortOutput {
    /// Displacement (m).
    pub x: f64,
    /// Displacement (m).
    pub y: f64,
    /// Velocity (m/s).
    pub vx: f64,
    /// Velocity (m/s).
    pub vy: f64,
}

/// Friction of one thrust bearing (`[[thrust_bearings]]`).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct ThrustOutput {
    /// Friction torque opposing the spin (N·m); at standstill the breakaway torque.
    pub friction_torque: f64,
    /// Power dissipated, friction torque times the node's speed (W).
    pub power_loss: f64,
}

/// Rotation of one `[[torques]]` node of a torque-driven shaft.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct TorqueNodeOutput {
    /// Speed (rad/s).
    pub speed: f64,
    /// Angle (rad): the integral of its speed.
    pub angle: f64,
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
    /// One entry per force port, in model order.
    pub ports: Vec<PortOutput>,
    /// One entry per thrust bearing, in model order.
    pub thrust_bearings: Vec<ThrustOutput>,
    /// One entry per `[[torques]]` node, in model order (empty when the speed
    /// is prescribed).
    pub torques: Vec<TorqueNodeOutput>,
    /// Torque (N·m) in each shaft element, from node `k` to `k + 1`, of a
    /// torque-driven shaft (empty when the speed is prescribed): the twist
    /// of the far end over the near one times its stiffness, plus damping.
    pub shaft_torques: Vec<f64>,
    /// Sum of the bearings' friction torques (N·m).
    pub friction_torque: f64,
    /// Sum of the power the bearings, rubs, seals and thrust bearings
    /// dissipate (W).
    pub power_loss: f64,
}

impl Simulator {
    /// Record each bearing's force at the current state, a static
    /// equilibrium, as its static load (a magnetic pull's rotating 1× part,
    /// turning with the shaft, left out); not counted as a reported output.
    pub(super) fn take_static_load(&mut self) -> Result<(), SolverError> {
        let recalled = self.stats.outputs_recalled;
        let o = self.outputs();
        self.stats.outputs_recalled = recalled;
        let (t, angle) = (self.state.time, self.state.spin_angle);
        for (k, b) in o?.bearings.iter().enumerate() {
            let (mut fx, mut fy) = (b.fx, b.fy);
            if let Some(i) = self.rotor.model.pull_input(k) {
                let e =
                    self.state.loads[i] + self.state.load_rates[i] * (t - self.state.speed_time);
                if let Some([rx, ry]) = self.rotor.pull_rotating_force(k, e, angle) {
                    fx -= rx;
                    fy -= ry;
                }
            }
            self.state.static_load[2 * k] = fx;
            self.state.static_load[2 * k + 1] = fy;
        }
        Ok(())
    }

    /// Outputs at the current state.
    pub fn outputs(&mut self) -> Result<Outputs, SolverError> {
        let t = self.state.time;
        let speed = self.speed_at(t);
        let mut bearings = Vec::with_capacity(self.output_bearings.len());
        let mut friction_torque = 0.0;
        let mut power_loss = 0.0;
        for (k, (bearing, site)) in self.output_bearings.iter().enumerate() {
            let placed = &self.rotor.model.bearings[k];
            let node = placed.node;
            // The node's own speed: a torque-driven shaft twists.
            let speed = if self.torsion.is_some() {
                self.node_rotation(node).0
            } else {
                speed
            };
            let at = |dof: usize, v: &[f64]| self.rotor.node_value(node, dof, v);
            let (x, y) = (at(DOF_X, &self.state.u), at(DOF_Y, &self.state.u));
            let (vx, vy) = (at(DOF_X, &self.state.ud), at(DOF_Y, &self.state.ud));
            let housing = match placed.pedestal {
                None => HousingOutput::default(),
                Some(p) => {
                    let at = |k: usize, v: &[f64]| self.rotor.pedestal_value(p, k, v);
                    HousingOutput {
                        x: at(0, &self.state.u),
                        y: at(1, &self.state.u),
                        vx: at(0, &self.state.ud),
                        vy: at(1, &self.state.ud),
                    }
                }
            };
            let internal = bearing.internal_dofs();
            let eval = &mut self.output_evals[k];
            let (q, qd) = (
                &mut self.output_q[..2 + internal],
                &mut self.output_qd[..2 + internal],
            );
            (q[0], q[1], qd[0], qd[1]) = (
                x - housing.x,
                y - housing.y,
                vx - housing.vx,
                vy - housing.vy,
            );
            let mut memo = None;
            if let Some(si) = site {
                let s = &self.sites.list[*si];
                q[2..].copy_from_slice(&self.state.p[s.offset..s.offset + internal]);
                qd[2..].copy_from_slice(&self.state.pd[s.offset..s.offset + internal]);
                memo = s.memo.recall(q, qd, speed);
            }
            // The step's last bearing pass, when it was at these very inputs
            // (`output`'s bits: [`super::output_memo`]).
            let report =
                match memo {
                    Some((force, report)) => {
                        eval.force.copy_from_slice(force);
                        self.stats.outputs_recalled += 1;
                        report.unwrap_or_else(|| bearing.report(q, qd, speed, eval))
                    }
                    None => bearing.output(q, qd, speed, eval).map_err(|source| {
                        SolverError::Bearing {
                            name: self.rotor.model.bearings[k].name.clone(),
                            time: t,
                            source,
                        }
                    })?,
                };
            friction_torque += report.friction_torque;
            power_loss += report.power_loss;
            let (mut fx, mut fy) = (eval.force[0], eval.force[1]);
            // A pull's 1× rotating part (dynamic eccentricity) acts with the loads.
            if let Some(i) = self.rotor.model.pull_input(k) {
                let e =
                    self.state.loads[i] + self.state.load_rates[i] * (t - self.state.speed_time);
                if let Some([rx, ry]) = self.rotor.pull_rotating_force(k, e, self.state.spin_angle)
                {
                    fx += rx;
                    fy += ry;
                }
            }
            bearings.push(BearingOutput {
                x,
                y,
                fx,
                fy,
                report,
                housing,
                static_fx: self.state.static_load[2 * k],
                static_fy: self.state.static_load[2 * k + 1],
            });
        }
        let probes = self
            .rotor
            .model
            .probes
            .iter()
            .map(|p| {
                let (x, y) = (
                    self.rotor.node_value(p.node, DOF_X, &self.state.u),
                    self.rotor.node_value(p.node, DOF_Y, &self.state.u),
                );
                // From the installed centre of its bearing: the housing's
                // motion plus the bearing's offset.
                match p.relative_to {
                    None => ProbeOutput { x, y },
                    Some(b) => {
                        let (h, o) = (&bearings[b].housing, self.rotor.model.bearings[b].offset);
                        ProbeOutput {
                            x: x - h.x - o[0],
                            y: y - h.y - o[1],
                        }
                    }
                }
            })
            .collect();
        let thrust_bearings: Vec<ThrustOutput> = self
            .rotor
            .model
            .thrust_bearings
            .iter()
            .enumerate()
            .map(|(k, t)| {
                let torque = self.thrust_friction(k);
                ThrustOutput {
                    friction_torque: torque,
                    power_loss: torque * self.node_rotation(t.node).0,
                }
            })
            .collect();
        for t in &thrust_bearings {
            friction_torque += t.friction_torque;
            power_loss += t.power_loss;
        }
        let (torques, shaft_torques) = if self.torsion.is_some() {
            let model = &self.rotor.model;
            (
                model
                    .torques
                    .iter()
                    .map(|t| {
                        let (speed, angle) = self.node_rotation(t.node);
                        TorqueNodeOutput { speed, angle }
                    })
                    .collect(),
                (0..model.elements.len())
                    .map(|k| self.section_torque(k).unwrap_or(0.0))
                    .collect(),
            )
        } else {
            (Vec::new(), Vec::new())
        };
        let ports = self
            .rotor
            .model
            .ports
            .iter()
            .map(|p| {
                let at = |k: usize, v: &[f64]| self.rotor.node_value(p.node, k, v);
                PortOutput {
                    x: at(DOF_X, &self.state.u),
                    y: at(DOF_Y, &self.state.u),
                    vx: at(DOF_X, &self.state.ud),
                    vy: at(DOF_Y, &self.state.ud),
                }
            })
            .collect();
        Ok(Outputs {
            time: t,
            speed,
            spin_angle: self.state.spin_angle,
            bearings,
            probes,
            ports,
            thrust_bearings,
            torques,
            shaft_torques,
            friction_torque,
            power_loss,
        })
    }
}
