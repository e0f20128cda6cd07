//! The nonlinear bearings the solver integrates ("sites"): the coordinates
//! each one acts on (its journal, relative to its housing when the bearing
//! stands on a pedestal), the offset of its internal coordinates (pad tilts)
//! in `p`, its evaluation buffers and the Jacobians frozen for modified Newton.
//!
//! A site's journal coordinate is `j = Eᵀ u`: a column of `E` is `+1` at the
//! journal DOF and `−1` at the housing DOF (none for a bearing on rigid
//! ground). The bearing force `F(j, j̇)` acts on the journal and its reaction
//! on the housing, `E F`, and its Jacobian enters the rotor as `E K Eᵀ`.

use crate::bearing::{Bearing, BearingEval};
use crate::fe::{DOF_X, DOF_Y};
use crate::linalg::BandMatrix;
use crate::rotor::Rotor;

use super::condense::Condensation;
use super::error::SolverError;
use super::output_memo::OutputMemo;
use super::pad_inertia::InertialBearing;

/// One journal coordinate of a site: a journal DOF, less its housing DOF
/// when the bearing stands on a pedestal (a column of `E`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Coordinate {
    /// Free DOF of the journal.
    pub journal: usize,
    /// Free DOF of the housing, `None` on rigid ground.
    pub housing: Option<usize>,
}

impl Coordinate {
    /// The coordinate in the rotor vector `u`: `u_j − u_h` (`eᵀ u`).
    #[inline]
    pub fn of(&self, u: &[f64]) -> f64 {
        match self.housing {
            None => u[self.journal],
            Some(h) => u[self.journal] - u[h],
        }
    }

    /// Add a force `f` on the coordinate to the rotor vector `r`: `f` on the
    /// journal, its reaction `−f` on the housing (`r += e f`).
    #[inline]
    pub fn add(&self, r: &mut [f64], f: f64) {
        r[self.journal] += f;
        if let Some(h) = self.housing {
            r[h] -= f;
        }
    }

    /// The free DOFs it involves with their signs in `e`.
    pub fn entries(&self) -> impl Iterator<Item = (usize, f64)> {
        std::iter::once((self.journal, 1.0)).chain(self.housing.map(|h| (h, -1.0)))
    }
}

/// Add `k e_i e_jᵀ` to `a`: a stiffness between journal coordinates `i` and
/// `j`, which acts between journal and housing DOFs for a bearing on a pedestal.
pub(super) fn add_coupling(a: &mut BandMatrix<f64>, i: &Coordinate, j: &Coordinate, k: f64) {
    for (row, si) in i.entries() {
        for (col, sj) in j.entries() {
            a.add(row, col, si * sj * k);
        }
    }
}

/// A nonlinear bearing in the time integration or the static solve.
#[derive(Debug)]
pub(super) struct Site {
    /// Index of the bearing in the model.
    pub index: usize,
    pub name: String,
    /// The bearing as installed: about its centre [`Site::centre`]
    /// ([`crate::model::PlacedBearing::build`]), with the inertia of its
    /// internal coordinates within a step ([`super::pad_inertia`]).
    pub bearing: InertialBearing,
    /// Its housing centre off the nominal axis `o` (m): the journal
    /// coordinates `Eᵀu` are absolute, the bearing sees `Eᵀu − o`.
    pub centre: [f64; 2],
    /// The journal coordinates `x`, `y` (relative to the housing).
    pub journal: [Coordinate; 2],
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
    /// The pad block `K_pp + a1 C_pp` condensed onto the journal.
    pub condensation: Condensation,
    /// The force pass of a step that ended on its iterate.
    pub memo: OutputMemo,
}

/// All nonlinear bearings of a rotor, in model order.
#[derive(Debug)]
pub(super) struct Sites {
    pub list: Vec<Site>,
    /// Number of journal DOFs, `2 ×` the number of sites.
    pub n_journal: usize,
    /// Number of internal DOFs (length of `p`).
    pub n_internal: usize,
    /// Every journal coordinate, site by site (`x`, `y`): the columns of `E`.
    pub coordinates: Vec<Coordinate>,
    /// Every site's forces cost markedly less than its evaluation with the
    /// Jacobians ([`Bearing::cheap_forces`]), so chord iterations pay.
    pub cheap_forces: bool,
    /// Displacement scale of the convergence tests: the smallest bearing
    /// clearance (m), 1 µm without fluid-film bearings.
    pub length_scale: f64,
    /// No site stands on a pedestal: each journal coordinate is one rotor
    /// DOF, so a step can place the journals on its iterate exactly.
    pub on_ground: bool,
}

impl Sites {
    /// The nonlinear bearings of `rotor` (bearings that are linear and have no
    /// internal coordinates are in the rotor's matrices already).
    pub fn new(rotor: &Rotor) -> Result<Self, SolverError> {
        let mut list = Vec::new();
        let mut offset = 0;
        for (index, b) in rotor.model.bearings.iter().enumerate() {
            let bearing = b.build();
            if bearing.is_linear() && bearing.internal_dofs() == 0 {
                continue;
            }
            let journal = match (
                rotor.dofs.free(b.node, DOF_X),
                rotor.dofs.free(b.node, DOF_Y),
            ) {
                (Some(x), Some(y)) => {
                    let housing = |k: usize| b.pedestal.and_then(|p| rotor.dofs.pedestal(p, k));
                    [
                        Coordinate {
                            journal: x,
                            housing: housing(0),
                        },
                        Coordinate {
                            journal: y,
                            housing: housing(1),
                        },
                    ]
                }
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
                condensation: Condensation::new(internal),
                memo: OutputMemo::default(),
                centre: b.offset,
                bearing: InertialBearing::new(bearing),
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
            coordinates: list.iter().flat_map(|s| s.journal).collect(),
            cheap_forces: list.iter().all(|s| s.bearing.cheap_forces()),
            length_scale,
            on_ground: list
                .iter()
                .all(|s| s.journal.iter().all(|c| c.housing.is_none())),
            list,
        })
    }

    /// Open a Newmark step with `a1 = 2/h` from the internal rates `pd` and
    /// accelerations `pdd` at its start: the internal coordinates' inertia
    /// joins the bearings' forces ([`super::pad_inertia`]).
    pub fn begin_step(&mut self, a1: f64, pd: &[f64], pdd: &[f64]) {
        for site in &mut self.list {
            let range = site.offset..site.offset + site.internal;
            site.bearing.begin_step(a1, &pd[range.clone()], &pdd[range]);
        }
    }

    /// Close the step ([`Sites::begin_step`]).
    pub fn end_step(&mut self) {
        for site in &mut self.list {
            site.bearing.end_step();
        }
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
            for (a, c) in site.journal.iter().enumerate() {
                site.q[a] = c.of(u);
                site.qd[a] = c.of(ud);
            }
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
            site.journal[0].add(r, site.eval.force[0]);
            site.journal[1].add(r, site.eval.force[1]);
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
