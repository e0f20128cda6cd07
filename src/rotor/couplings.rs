//! The preload of misaligned couplings between the shafts of a train.
//!
//! A flexible coupling of stiffness `k = diag(k_l, k_l, k_a, k_a)` between
//! nodes `l` and `r` with the misalignment `m` (the shaft after it set off
//! from the one before, on `x, y, θx, θy`) stores `½ (q_r − q_l − m)ᵀ k
//! (q_r − q_l − m)`: besides `k` in the matrices it loads node `l` by `−k m`
//! and node `r` by `+k m`. A rigid flange keeps its shaft element `K_e`
//! between nodes `l` and `r`, whose left end belongs to the shaft after the
//! flange and so sits at `q_l + m`: it stores `½ (u_e + s)ᵀ K_e (u_e + s)`
//! with the initial strain `s = (m, 0)` over the element's eight DOFs, and
//! loads them by `−K_e s`.

use nalgebra::SVector;

use super::Rotor;
use crate::fe::DOF_PER_NODE;
use crate::model::{CouplingJoint, RotorModel};

impl Rotor {
    /// Add the misaligned couplings' preloads to `f` (free DOFs); nothing
    /// for aligned ones (models without misalignment keep their numbers bit
    /// for bit).
    pub fn add_coupling_loads(&self, f: &mut [f64]) {
        let model = &self.model;
        for c in model.couplings.iter().filter(|c| c.is_misaligned()) {
            let left = model.elements[c.element].node;
            let load: [f64; 2 * DOF_PER_NODE] = match c.joint {
                CouplingJoint::Flexible { lateral, angular } => {
                    let k = [lateral[0], lateral[0], angular[0], angular[0]];
                    std::array::from_fn(|a| {
                        let km = k[a % DOF_PER_NODE] * c.misalignment[a % DOF_PER_NODE];
                        if a < DOF_PER_NODE { -km } else { km }
                    })
                }
                CouplingJoint::Flange => {
                    let s = flange_strain(model, c.element).unwrap_or_default();
                    let k = element_stiffness(model, c.element);
                    let load = -(k * s);
                    std::array::from_fn(|a| load[a])
                }
            };
            for (a, v) in load.iter().enumerate() {
                if let Some(i) = self.dofs.free(left + a / DOF_PER_NODE, a % DOF_PER_NODE) {
                    f[i] += v;
                }
            }
        }
    }
}

/// The stiffness of shaft element `element` as assembled: bending and shear
/// plus the axial load's geometric term.
pub fn element_stiffness(model: &RotorModel, element: usize) -> nalgebra::SMatrix<f64, 8, 8> {
    let placed = &model.elements[element];
    let mats = placed.element.matrices();
    mats.stiffness + mats.axial_per_newton * placed.axial_force
}

/// The initial strain `s = (m, 0)` of shaft element `element` when a
/// misaligned rigid flange sits at it (its end forces are `K_e (u_e + s)`),
/// `None` otherwise.
pub fn flange_strain(model: &RotorModel, element: usize) -> Option<SVector<f64, 8>> {
    let c = model
        .couplings
        .iter()
        .find(|c| c.element == element && c.joint == CouplingJoint::Flange && c.is_misaligned())?;
    Some(SVector::from_fn(|a, _| {
        if a < DOF_PER_NODE {
            c.misalignment[a]
        } else {
            0.0
        }
    }))
}
