//! The torsional chain of a torque-driven shaft and its buffers
//! ([`super::torsion`]; nothing allocated per step).

use crate::bearing::BearingEval;
use crate::bearing::thrust::ThrustBearing;
use crate::linalg::{BandLu, BandMatrix, LinalgError};
use crate::rotor::Rotor;
use crate::rotor::torsion::TorsionalRotor;

/// The torsional chain and its buffers (nothing allocated per step).
#[derive(Debug)]
pub(super) struct Torsion {
    pub chain: TorsionalRotor,
    /// The load channel of each torque input, with its node's twist DOF.
    pub(super) inputs: Vec<(usize, Option<usize>)>,
    /// Twist DOF of each unbalance plane's node.
    pub(super) planes: Vec<Option<usize>>,
    /// Twist DOF of each site's journal node.
    pub(super) site_dofs: Vec<Option<usize>>,
    /// Thrust bearings at twist DOFs.
    pub(super) thrust: Vec<(Option<usize>, ThrustBearing)>,
    /// Newmark matrix `K + a1 C + a0 M` plus the thrust Jacobian, and its
    /// factors (storage reused).
    pub(super) a: BandMatrix<f64>,
    pub(super) lu: BandLu<f64>,
    /// `K + a1 C + a0 M` for the Newmark constants `base_for` = `(a0, a1)`
    /// (`[NaN; 2]` before the first), the part of `a` a step size fixes.
    pub(super) base: BandMatrix<f64>,
    pub(super) base_for: [f64; 2],
    /// The matrix `lu` factors: a step whose `a` has the same bits reuses it.
    pub(super) factored: BandMatrix<f64>,
    /// Iterate: twist, rate, acceleration at the step's end.
    pub theta: Vec<f64>,
    pub omega: Vec<f64>,
    pub alpha: Vec<f64>,
    /// Coupling torques at the step's end (N·m): the estimate the torsional
    /// step used, and the one the lateral step gives back.
    pub(super) coupling: Vec<f64>,
    pub(super) fresh: Vec<f64>,
    /// Work vectors.
    pub(super) rhs: Vec<f64>,
    pub(super) scratch: Vec<f64>,
    /// The torque inputs at the step's end (N·m).
    pub(super) input_values: Vec<f64>,
    /// Evaluation buffers of the sites, for their friction torques.
    pub(super) eval: Vec<BearingEval>,
}

impl Torsion {
    /// The torque-driven chain of `rotor` with `site_nodes` (each nonlinear
    /// site's node) and `site_sizes` (their coordinate counts).
    pub fn new(rotor: &Rotor, site_nodes: &[usize], site_sizes: &[usize]) -> Self {
        let model = &rotor.model;
        let chain = TorsionalRotor::new(model);
        let n = chain.dof_count();
        let first = model.first_torque_input();
        let inputs = model
            .torques
            .iter()
            .enumerate()
            .map(|(k, t)| (first + k, chain.dofs[t.node]))
            .collect();
        let planes = model
            .unbalances
            .iter()
            .map(|u| chain.dofs[u.node])
            .collect();
        let site_dofs = site_nodes.iter().map(|&node| chain.dofs[node]).collect();
        let thrust = model
            .thrust_bearings
            .iter()
            .map(|t| (chain.dofs[t.node], t.bearing))
            .collect();
        let mut a = chain.stiffness.zeroed_like();
        for i in 0..n {
            a.set(i, i, 1.0);
        }
        Self {
            lu: a.lu().expect("the identity factors"),
            base: a.zeroed_like(),
            factored: a.clone(),
            base_for: [f64::NAN; 2],
            a,
            inputs,
            planes,
            site_dofs,
            thrust,
            theta: vec![0.0; n],
            omega: vec![0.0; n],
            alpha: vec![0.0; n],
            coupling: vec![0.0; n],
            fresh: vec![0.0; n],
            rhs: vec![0.0; n],
            scratch: vec![0.0; n],
            input_values: vec![0.0; model.torques.len()],
            eval: site_sizes.iter().map(|&m| BearingEval::new(m)).collect(),
            chain,
        }
    }

    /// Factor `a` into `lu`, unless `lu` already factors a matrix with the
    /// same bits (at a steady speed the thrust friction's slope, and so `a`,
    /// stays the same to the bit over thousands of steps: the torque-driven
    /// hydro unit factored 60 times in 24 652 torsional iterations).
    pub(super) fn factor(&mut self) -> Result<(), LinalgError> {
        if self.a == self.factored {
            return Ok(());
        }
        let outcome = self.a.lu_into(&mut self.lu);
        match outcome {
            Ok(()) => self.factored.assign(&self.a),
            // Factors left half made match no matrix.
            Err(_) => self.factored.set(0, 0, f64::NAN),
        }
        outcome
    }

    /// Inertia-weighted mean of `v` over the free twist DOFs.
    pub fn mean(&self, v: &[f64]) -> f64 {
        let j = &self.chain.inertia;
        v.iter().zip(j).map(|(a, b)| a * b).sum::<f64>() / self.chain.total_inertia()
    }

    /// The breakaway torque at rest: the thrust bearings' boundary friction
    /// plus `at_rest`, the contact friction the sites report at standstill.
    pub(super) fn breakaway(&self, at_rest: f64) -> f64 {
        self.thrust
            .iter()
            .map(|(_, t)| t.breakaway_torque())
            .sum::<f64>()
            + at_rest
    }
}
