//! The assembled rotor: global assembly of a [`RotorModel`] into banded matrices.
//!
//! Layer 4 of the crate (above the element physics in [`crate::fe`] and
//! [`crate::bearing`] and the validated model in [`crate::model`], below the
//! solver and the analyses).
//!
//! Nodes along one shaft couple only to their neighbours, so with node-major DOF
//! numbering every matrix is banded with half-bandwidth 7 (less after removing
//! constrained DOFs). Storage and solves are O(n); nothing here is dense.

use crate::bearing::{BearingEval, BearingKind};
use crate::fe::{DOF_PER_NODE, DOF_X, DOF_Y};
use crate::linalg::BandMatrix;
use crate::model::RotorModel;

mod couplings;
mod dofs;
pub mod elements;
mod loads;
mod reduction;
pub mod torsion;

pub use crate::model::DEFAULT_REDUCED_MODES;
pub use couplings::{element_stiffness, flange_strain};
pub use dofs::{DOF_PER_PEDESTAL, Dof, DofMap};
pub use elements::LinearElement;
pub use reduction::{Reduction, VALIDITY_FACTOR};

/// A bearing that is not linear and is therefore kept out of the matrices (the
/// solver builds its force model from the model's bearing of the same index).
#[derive(Debug, Clone, PartialEq)]
pub struct BearingSite {
    /// Bearing name from the model.
    pub name: String,
}

/// The assembled rotor: `M q̈ + (C + Ω G) q̇ + K q = f` on the free DOFs, with the
/// linear bearings already in `K` and `C`.
#[derive(Debug)]
pub struct Rotor {
    /// The model it was built from.
    pub model: RotorModel,
    /// DOF numbering.
    pub dofs: DofMap,
    /// Mass (shaft consistent mass and disks).
    pub mass: BandMatrix<f64>,
    /// Stiffness: shaft bending and shear, axial-load geometric stiffness, linear bearings.
    pub stiffness: BandMatrix<f64>,
    /// Viscous damping of linear bearings.
    pub damping: BandMatrix<f64>,
    /// Gyroscopic matrix per rad/s of spin (skew-symmetric).
    pub gyroscopic: BandMatrix<f64>,
    /// Bearings whose force is nonlinear (kept out of the matrices).
    pub nonlinear_bearings: Vec<BearingSite>,
    /// Consistent gravity load on the free DOFs (N, N·m).
    pub gravity_load: Vec<f64>,
    /// `Some` for a [reduced](Rotor::reduced) rotor: matrices, load and
    /// coordinates are then those of the reduced system.
    pub reduction: Option<Reduction>,
    /// Linear elements of negative direct stiffness with their most negative
    /// direct entry (N/m): the statics check such a machine can hold itself.
    pub negative_stiffness: Vec<(String, f64)>,
}

/// Linear stiffness and damping of one bearing on its journal `(x, y)`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct JournalCoefficients {
    /// Index of the bearing in the model.
    pub bearing: usize,
    /// Stiffness `K_b = −∂F/∂q` (N/m), row-major `[[kxx, kxy], [kyx, kyy]]`.
    pub stiffness: [[f64; 2]; 2],
    /// Damping `C_b = −∂F/∂q̇` (N·s/m), row-major.
    pub damping: [[f64; 2]; 2],
}

/// Why a model cannot be assembled.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum AssemblyError {
    /// Every DOF is constrained.
    #[error("model {0}: every degree of freedom is fixed by supports")]
    NoFreeDofs(String),
    /// A linear bearing could not be evaluated.
    #[error("bearing {name}: {message}")]
    Bearing { name: String, message: String },
    /// The rotor cannot be reduced as asked.
    #[error("model {model}: reduction: {message}")]
    Reduction { model: String, message: String },
}

impl Rotor {
    /// Assemble the global matrices of `model`.
    ///
    /// ```
    /// use rotor_bearing::model::RotorModel;
    /// use rotor_bearing::rotor::Rotor;
    ///
    /// let path = concat!(env!("CARGO_MANIFEST_DIR"), "/models/hydro_unit.toml");
    /// let rotor = Rotor::new(RotorModel::from_file(std::path::Path::new(path))?)?;
    /// // Four DOFs per node (x, y, θx, θy) less the ones fixed by supports.
    /// assert!(rotor.dof_count() <= 4 * rotor.model.node_count());
    /// assert_eq!(rotor.mass.n(), rotor.dof_count());
    /// // The guide bearings are fluid films: kept out of K and C.
    /// assert_eq!(rotor.nonlinear_bearings.len(), 2);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn new(model: RotorModel) -> Result<Self, AssemblyError> {
        let dofs = DofMap::new(&model);
        let n = dofs.free_count();
        if n == 0 {
            return Err(AssemblyError::NoFreeDofs(model.name.clone()));
        }
        let mut linear = elements::structure(&model, &dofs);
        linear.extend(elements::point_masses(&model, &dofs));
        linear.extend(elements::pedestals(&model, &dofs));
        let mut nonlinear_bearings = Vec::new();
        let mut negative_stiffness = Vec::new();
        // Every bearing couples its journal to its housing: the band holds
        // the nonlinear ones' Jacobians too (statics, linearization).
        let mut spread = 0;
        for b in &model.bearings {
            let bearing = b.kind.build();
            spread = spread.max(elements::spread(&elements::bearing_dofs(&dofs, b)));
            if bearing.is_linear() && bearing.internal_dofs() == 0 {
                let mut eval = BearingEval::new(2);
                bearing
                    .evaluate(&[0.0; 2], &[0.0; 2], 0.0, &mut eval)
                    .map_err(|e| AssemblyError::Bearing {
                        name: b.name.clone(),
                        message: e.to_string(),
                    })?;
                let coeff = eval.journal();
                let k = [
                    [coeff.stiffness[(0, 0)], coeff.stiffness[(0, 1)]],
                    [coeff.stiffness[(1, 0)], coeff.stiffness[(1, 1)]],
                ];
                let c = [
                    [coeff.damping[(0, 0)], coeff.damping[(0, 1)]],
                    [coeff.damping[(1, 0)], coeff.damping[(1, 1)]],
                ];
                if k[0][0].min(k[1][1]) < 0.0 {
                    negative_stiffness.push((b.name.clone(), k[0][0].min(k[1][1])));
                }
                linear.push(elements::bearing_link(&dofs, b, &k, &c));
            } else {
                nonlinear_bearings.push(BearingSite {
                    name: b.name.clone(),
                });
            }
            if let Some(m) = b.kind.added_mass() {
                linear.push(elements::added_mass(&dofs, b, &m));
            }
        }
        let bw = linear
            .iter()
            .map(LinearElement::spread)
            .fold((DOF_PER_NODE - 1).max(spread), usize::max);
        let mut mass = BandMatrix::new(n, bw, bw);
        let mut stiffness = BandMatrix::new(n, bw, bw);
        let mut damping = BandMatrix::new(n, bw, bw);
        let mut gyroscopic = BandMatrix::new(n, bw, bw);
        for e in &linear {
            for (target, local) in [
                (&mut mass, &e.mass),
                (&mut stiffness, &e.stiffness),
                (&mut damping, &e.damping),
                (&mut gyroscopic, &e.gyroscopic),
            ] {
                if let Some(local) = local {
                    scatter(target, &e.dofs, |a, b| local[(a, b)]);
                }
            }
        }

        // Consistent gravity load f = M·u_g, u_g the rigid translation by the gravity vector.
        let mut u_g = vec![0.0; n];
        for (i, u) in u_g.iter_mut().enumerate() {
            if let Some(k) = dofs.kind(i).translation() {
                *u = model.gravity[k];
            }
        }
        let mut gravity_load = vec![0.0; n];
        mass.mul_vec(&u_g, &mut gravity_load);

        Ok(Self {
            model,
            dofs,
            mass,
            stiffness,
            damping,
            gyroscopic,
            nonlinear_bearings,
            gravity_load,
            reduction: None,
            negative_stiffness,
        })
    }

    /// The rotor transients run on: `model` [reduced](Rotor::reduced) to
    /// `modes` fixed-interface modes, or the full rotor for `modes = 0`.
    pub fn for_transients(model: RotorModel, modes: usize) -> Result<Self, AssemblyError> {
        let full = Self::new(model)?;
        if modes == 0 {
            Ok(full)
        } else {
            full.reduced(modes)
        }
    }

    /// Displacement `k` (0–3: x, y, θx, θy) of `node` in the coordinates `q`
    /// of this rotor (through the basis for a reduced rotor's interior nodes;
    /// 0 for a fixed DOF).
    pub fn node_value(&self, node: usize, k: usize, q: &[f64]) -> f64 {
        match (self.dofs.free(node, k), &self.reduction) {
            (Some(i), _) => q[i],
            (None, Some(r)) => r.node_value(node, k, q),
            (None, None) => 0.0,
        }
    }

    /// Translation `k` (0: `x`, 1: `y`) of pedestal `pedestal` in the
    /// coordinates `q` of this rotor (pedestals are physical coordinates of
    /// a reduced rotor too).
    pub fn pedestal_value(&self, pedestal: usize, k: usize, q: &[f64]) -> f64 {
        self.dofs.pedestal(pedestal, k).map_or(0.0, |i| q[i])
    }

    /// Which rotor this is, in one line for logs and the CLI: the reduction's
    /// [`Reduction::describe`], or `full rotor: N DOFs`.
    pub fn coordinates(&self) -> String {
        match &self.reduction {
            Some(r) => r.describe(),
            None => format!("full rotor: {} DOFs", self.dof_count()),
        }
    }

    /// Number of free DOFs (coordinates, for a reduced rotor).
    pub fn dof_count(&self) -> usize {
        self.dofs.free_count()
    }

    /// A linear copy of this rotor: every nonlinear bearing replaced by the
    /// coefficients given for it (one entry per nonlinear bearing, by model
    /// index), scattered between its journal and housing DOFs
    /// ([`elements::bearing_link`]), `K' = K + E K_b Eᵀ`, `C' = C + E C_b Eᵀ`.
    /// Mass (with the added masses of table bearings and seals), gyroscopic
    /// matrix and gravity load are copied, nothing is re-assembled; the copy's
    /// model lists those bearings as [`BearingKind::Linear`], so without added
    /// masses it equals the assembly of that model.
    pub fn with_bearing_coefficients(
        &self,
        coefficients: &[JournalCoefficients],
    ) -> Result<Self, AssemblyError> {
        if self.reduction.is_some() {
            return Err(AssemblyError::Reduction {
                model: self.model.name.clone(),
                message: "linear analyses need the full rotor".into(),
            });
        }
        let mut model = self.model.clone();
        let mut stiffness = self.stiffness.clone();
        let mut damping = self.damping.clone();
        let mut given = vec![false; model.bearings.len()];
        for c in coefficients {
            let placed =
                model
                    .bearings
                    .get_mut(c.bearing)
                    .ok_or_else(|| AssemblyError::Bearing {
                        name: format!("#{}", c.bearing),
                        message: "no such bearing in the model".into(),
                    })?;
            if !placed.kind.is_nonlinear() || given[c.bearing] {
                return Err(AssemblyError::Bearing {
                    name: placed.name.clone(),
                    message: "coefficients given for a linear bearing or twice".into(),
                });
            }
            given[c.bearing] = true;
            let link = elements::bearing_link(&self.dofs, placed, &c.stiffness, &c.damping);
            for (target, local) in [
                (&mut stiffness, &link.stiffness),
                (&mut damping, &link.damping),
            ] {
                if let Some(local) = local {
                    scatter(target, &link.dofs, |a, b| local[(a, b)]);
                }
            }
            placed.kind = BearingKind::Linear {
                stiffness: c.stiffness,
                damping: c.damping,
            };
        }
        if let Some(missing) = model.bearings.iter().find(|b| b.kind.is_nonlinear()) {
            return Err(AssemblyError::Bearing {
                name: missing.name.clone(),
                message: "nonlinear bearing without linear coefficients".into(),
            });
        }
        Ok(Self {
            model,
            dofs: self.dofs.clone(),
            mass: self.mass.clone(),
            stiffness,
            damping,
            gyroscopic: self.gyroscopic.clone(),
            nonlinear_bearings: Vec::new(),
            gravity_load: self.gravity_load.clone(),
            reduction: None,
            negative_stiffness: self.negative_stiffness.clone(),
        })
    }

    /// A freshly assembled copy (bearing objects are not clonable).
    /// (A reduced rotor is reduced again with the same mode count.)
    pub fn clone_model(&self) -> Result<Self, AssemblyError> {
        let full = Self::new(self.model.clone())?;
        match &self.reduction {
            Some(r) => full.reduced(r.requested),
            None => Ok(full),
        }
    }

    /// Unbalance force amplitude vector for synchronous excitation at unit speed²:
    /// complex `(F_x, F_y) = m e (1, −i) e^{i φ}` per plane, so that at speed `Ω`
    /// the force is `Re(Ω² F e^{iΩt})`.
    pub fn unbalance_load(&self) -> Vec<nalgebra::Complex<f64>> {
        let mut f = vec![nalgebra::Complex::new(0.0, 0.0); self.dof_count()];
        for u in &self.model.unbalances {
            let a = nalgebra::Complex::from_polar(u.magnitude, u.phase);
            if let Some(i) = self.dofs.free(u.node, DOF_X) {
                f[i] += a;
            }
            if let Some(i) = self.dofs.free(u.node, DOF_Y) {
                f[i] += a * nalgebra::Complex::new(0.0, -1.0);
            }
        }
        f
    }
}

/// Add a local matrix `value(a, b)` into `target` at the free DOFs `local`.
fn scatter(
    target: &mut BandMatrix<f64>,
    local: &[Option<usize>],
    value: impl Fn(usize, usize) -> f64,
) {
    for (a, ia) in local.iter().enumerate() {
        for (b, ib) in local.iter().enumerate() {
            if let (Some(i), Some(j)) = (ia, ib) {
                let v = value(a, b);
                if v != 0.0 {
                    target.add(*i, *j, v);
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Coefficients added to the assembled matrices give exactly the assembly
    /// of the model with those bearings written as linear bearings; a missing
    /// or misplaced entry is refused.
    #[test]
    fn bearing_coefficients_equal_the_assembled_linear_model() {
        let path = concat!(env!("CARGO_MANIFEST_DIR"), "/models/hydro_unit.toml");
        let rotor = Rotor::new(RotorModel::from_file(std::path::Path::new(path)).unwrap()).unwrap();
        let nonlinear: Vec<usize> = (0..rotor.model.bearings.len())
            .filter(|&k| rotor.model.bearings[k].kind.is_nonlinear())
            .collect();
        let coefficients: Vec<JournalCoefficients> = nonlinear
            .iter()
            .map(|&k| JournalCoefficients {
                bearing: k,
                stiffness: [[3e9 + k as f64, -2e8], [4e8, 2.5e9]],
                damping: [[1e7, 3e5], [-2e5, 2e7]],
            })
            .collect();
        let linear = rotor.with_bearing_coefficients(&coefficients).unwrap();
        let assembled = Rotor::new(linear.model.clone()).unwrap();
        assert!(linear.nonlinear_bearings.is_empty());
        assert_eq!(linear.stiffness.to_dense(), assembled.stiffness.to_dense());
        assert_eq!(linear.damping.to_dense(), assembled.damping.to_dense());
        assert_eq!(linear.mass.to_dense(), assembled.mass.to_dense());
        assert_eq!(linear.gravity_load, assembled.gravity_load);
        assert!(rotor.with_bearing_coefficients(&coefficients[1..]).is_err());
        let twice = [coefficients[0], coefficients[0]];
        assert!(rotor.with_bearing_coefficients(&twice).is_err());
    }
}
