//! The nonlinear bearings the solver integrates ("sites"): the journal DOFs
//! each one acts on, the offset of its internal coordinates (pad tilts) in `p`,
//! its evaluation buffers and the Jacobians frozen for modified Newton.

use crate::bearing::{Bearing, BearingEval};
use crate::fe::{DOF_X, DOF_Y};
use crate::rotor::Rotor;

use super::simulator::SolverError;

/// A nonlinear bearing in the time integration or the static solve.
#[derive(Debug)]
pub(super) struct Site {
    /// Index of the bearing in the model.
    pub index: usize,
    pub name: String,
    pub bearing: Box<dyn Bearing>,
    /// Free DOF indices of the journal (`x`, `y`).
    pub journal: [usize; 2],
    /// Offset of its internal DOFs in `p`.
    pub offset: usize,
    /// Number of internal DOFs (pads).
    pub internal: usize,
    pub eval: BearingEval,
    /// Stiffness Jacobian frozen for modified Newton–Raphson (row-major, N/m).
    pub jk: Vec<f64>,
    /// Damping Jacobian frozen for modified Newton–Raphson (row-major, N·s/m).
    pub jc: Vec<f64>,
    /// Coordinates (journal, then internal) handed to the bearing (m).
    pub q: Vec<f64>,
    /// Their rates (m/s).
    pub qd: Vec<f64>,
    /// LU of the pad block `K_pp + a1 C_pp` (row-major `m × m`) and its pivots.
    pub kpp: Vec<f64>,
    pub kpp_piv: Vec<usize>,
    /// `K_pp⁻¹ [K_pj | −F_p]`: three columns of length `m`.
    pub kpp_x: Vec<f64>,
}

/// All nonlinear bearings of a rotor, in model order.
#[derive(Debug)]
pub(super) struct Sites {
    pub list: Vec<Site>,
    /// Number of journal DOFs, `2 ×` the number of sites.
    pub n_journal: usize,
    /// Number of internal DOFs (length of `p`).
    pub n_internal: usize,
    /// Free DOF of each journal coordinate, site by site (`x`, `y`).
    pub journal_dofs: Vec<usize>,
    /// Displacement scale of the convergence tests: the smallest bearing
    /// clearance (m), 1 µm without fluid-film bearings.
    pub length_scale: f64,
}

impl Sites {
    /// The nonlinear bearings of `rotor` (bearings that are linear and have no
    /// internal coordinates are in the rotor's matrices already).
    pub fn new(rotor: &Rotor) -> Result<Self, SolverError> {
        let mut list = Vec::new();
        let mut offset = 0;
        for (index, b) in rotor.model.bearings.iter().enumerate() {
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
            list.push(Site {
                index,
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
        Ok(Self {
            n_journal: 2 * list.len(),
            n_internal: offset,
            journal_dofs: list.iter().flat_map(|s| s.journal).collect(),
            length_scale,
            list,
        })
    }

    /// Evaluate the bearings at `u`, `u̇` (rotor) and `p`, `ṗ` (internal) at
    /// spin `speed` (rad/s), adding their journal forces `E F_b` to `r` and
    /// writing the pad residuals `Q_p` to `rp`; returns the largest force term
    /// (N), each pad's film stiffness times the length scale included. `time`
    /// (s) only labels errors.
    #[allow(clippy::too_many_arguments)]
    pub fn add_forces(
        &mut self,
        u: &[f64],
        ud: &[f64],
        p: &[f64],
        pd: &[f64],
        speed: f64,
        time: f64,
        r: &mut [f64],
        rp: &mut [f64],
    ) -> Result<f64, SolverError> {
        let mut largest: f64 = 0.0;
        for site in &mut self.list {
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
            r[site.journal[0]] += site.eval.force[0];
            r[site.journal[1]] += site.eval.force[1];
            largest = largest
                .max(site.eval.force[0].abs())
                .max(site.eval.force[1].abs());
            for k in 0..site.internal {
                rp[site.offset + k] = site.eval.force[2 + k];
            }
            // Each pad's own film force sets the scale of its moment balance.
            for k in 0..site.internal {
                largest = largest.max(site.eval.k(2 + k, 2 + k).abs() * self.length_scale);
            }
        }
        Ok(largest)
    }
}
