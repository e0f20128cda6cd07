//! The linear elements of the assembled rotor. Each is one contribution of
//! local matrices `M`, `K`, `C`, `G` (`G` per rad/s of spin) over a list of
//! free DOFs (`None`: fixed by a support, or ground); assembly adds them into
//! the banded matrices in the order they are listed:
//! shaft elements (a flexible coupling in place of one, a spring–damper
//! between its two nodes), disks, point masses, pedestals, then the bearings in
//! model order (linear bearings, added masses of table bearings and seals).
//!
//! A spring–damper between two points (a bearing between its journal and its
//! housing, a pedestal and the pedestal it stands on) is one element over the
//! DOFs of both, with the local matrices `[[K, −K], [−K, K]]`: its force on
//! the first point is `−K (q₁ − q₂)` and its reaction acts on the second.

use nalgebra::DMatrix;

use super::dofs::DofMap;
use crate::fe::{DOF_PER_NODE, DOF_X, DOF_Y};
use crate::model::{CouplingJoint, PlacedBearing, RotorModel};

/// Local matrices of one linear element over `dofs`.
#[derive(Debug, Clone, PartialEq)]
pub struct LinearElement {
    /// Free DOF of each local row and column, `None` where that DOF is fixed
    /// or is ground.
    pub dofs: Vec<Option<usize>>,
    /// Mass (kg, kg·m²).
    pub mass: Option<DMatrix<f64>>,
    /// Stiffness (N/m, N·m/rad).
    pub stiffness: Option<DMatrix<f64>>,
    /// Viscous damping (N·s/m).
    pub damping: Option<DMatrix<f64>>,
    /// Gyroscopic matrix per rad/s of spin.
    pub gyroscopic: Option<DMatrix<f64>>,
}

impl LinearElement {
    fn new(dofs: Vec<Option<usize>>) -> Self {
        Self {
            dofs,
            mass: None,
            stiffness: None,
            damping: None,
            gyroscopic: None,
        }
    }

    /// The largest distance between two of its free DOFs (0 with fewer than two).
    pub fn spread(&self) -> usize {
        spread(&self.dofs)
    }
}

/// The largest distance between two free DOFs of `dofs`.
pub(super) fn spread(dofs: &[Option<usize>]) -> usize {
    let free = dofs.iter().flatten();
    match (free.clone().min(), free.max()) {
        (Some(lo), Some(hi)) => hi - lo,
        _ => 0,
    }
}

/// The free DOFs of rotor node `node` (`x`, `y`, `θx`, `θy`).
pub(super) fn node_dofs(dofs: &DofMap, node: usize) -> [Option<usize>; DOF_PER_NODE] {
    std::array::from_fn(|k| dofs.free(node, k))
}

/// The free translations (`x`, `y`) of pedestal `pedestal`.
pub(super) fn pedestal_dofs(dofs: &DofMap, pedestal: usize) -> [Option<usize>; 2] {
    [dofs.pedestal(pedestal, 0), dofs.pedestal(pedestal, 1)]
}

/// The DOFs a bearing acts between: its journal's `x`, `y`, then its
/// housing's (none when the housing is rigid ground).
pub fn bearing_dofs(dofs: &DofMap, bearing: &PlacedBearing) -> Vec<Option<usize>> {
    let mut list = vec![
        dofs.free(bearing.node, DOF_X),
        dofs.free(bearing.node, DOF_Y),
    ];
    if let Some(p) = bearing.pedestal {
        list.extend(pedestal_dofs(dofs, p));
    }
    list
}

/// The local matrix of a 2×2 coupling `k` acting between the first point
/// and, when `to_second`, a second one: `k` itself, or `[[k, −k], [−k, k]]`.
fn link(k: &[[f64; 2]; 2], to_second: bool) -> DMatrix<f64> {
    let n = if to_second { 4 } else { 2 };
    DMatrix::from_fn(n, n, |i, j| {
        let sign = if (i < 2) == (j < 2) { 1.0 } else { -1.0 };
        sign * k[i % 2][j % 2]
    })
}

/// A linear spring–damper bearing (`K`, `C` on the journal, row-major) as an
/// element between its journal and its housing.
pub fn bearing_link(
    dofs: &DofMap,
    bearing: &PlacedBearing,
    stiffness: &[[f64; 2]; 2],
    damping: &[[f64; 2]; 2],
) -> LinearElement {
    let on_pedestal = bearing.pedestal.is_some();
    let mut e = LinearElement::new(bearing_dofs(dofs, bearing));
    e.stiffness = Some(link(stiffness, on_pedestal));
    e.damping = Some(link(damping, on_pedestal));
    e
}

/// Every linear element of `model` but its linear bearings, which depend on
/// the bearing kind (see [`bearing_link`]): shaft elements (consistent mass,
/// bending and shear stiffness plus the axial load's geometric stiffness,
/// gyroscopic matrix), then disks (mass, gyroscopic), in model order.
pub(super) fn structure(model: &RotorModel, dofs: &DofMap) -> Vec<LinearElement> {
    let mut list = Vec::new();
    for (index, placed) in model.elements.iter().enumerate() {
        let local: Vec<Option<usize>> = node_dofs(dofs, placed.node)
            .into_iter()
            .chain(node_dofs(dofs, placed.node + 1))
            .collect();
        let joint = model
            .couplings
            .iter()
            .find(|c| c.element == index)
            .map(|c| c.joint);
        if let Some(CouplingJoint::Flexible { lateral, angular }) = joint {
            list.push(flexible_coupling(local, lateral, angular));
            continue;
        }
        let mats = placed.element.matrices();
        let k_total = mats.stiffness + mats.axial_per_newton * placed.axial_force;
        let mut e = LinearElement::new(local);
        e.mass = Some(DMatrix::from_fn(8, 8, |a, b| mats.mass[(a, b)]));
        e.stiffness = Some(DMatrix::from_fn(8, 8, |a, b| k_total[(a, b)]));
        e.gyroscopic = Some(DMatrix::from_fn(8, 8, |a, b| mats.gyroscopic[(a, b)]));
        list.push(e);
    }
    for d in &model.disks {
        let (m, g) = (d.disk.mass_matrix(), d.disk.gyroscopic_matrix());
        let mut e = LinearElement::new(node_dofs(dofs, d.node).to_vec());
        e.mass = Some(DMatrix::from_fn(4, 4, |a, b| m[(a, b)]));
        e.gyroscopic = Some(DMatrix::from_fn(4, 4, |a, b| g[(a, b)]));
        list.push(e);
    }
    list
}

/// A flexible coupling in place of a shaft element over the DOFs of its two
/// nodes (`x, y, θx, θy` of each): `[[k, −k], [−k, k]]` with
/// `k = diag(k_l, k_l, k_a, k_a)` on the relative translations and rotations,
/// damping likewise; no mass or gyroscopic term (ROSS's `CouplingElement`
/// with its lateral terms, its masses left to disks at the nodes).
fn flexible_coupling(
    dofs: Vec<Option<usize>>,
    lateral: [f64; 2],
    angular: [f64; 2],
) -> LinearElement {
    let pick = |which: usize| {
        DMatrix::from_fn(2 * DOF_PER_NODE, 2 * DOF_PER_NODE, |a, b| {
            if a % DOF_PER_NODE != b % DOF_PER_NODE {
                return 0.0;
            }
            let sign = if (a < DOF_PER_NODE) == (b < DOF_PER_NODE) {
                1.0
            } else {
                -1.0
            };
            let translation = a % DOF_PER_NODE == DOF_X || a % DOF_PER_NODE == DOF_Y;
            sign * if translation {
                lateral[which]
            } else {
                angular[which]
            }
        })
    };
    let mut e = LinearElement::new(dofs);
    e.stiffness = Some(pick(0));
    e.damping = Some(pick(1));
    e
}

/// The non-rotating point masses of `model` on their nodes' translations.
pub(super) fn point_masses(model: &RotorModel, dofs: &DofMap) -> Vec<LinearElement> {
    model
        .point_masses
        .iter()
        .map(|pm| {
            let mut e =
                LinearElement::new(vec![dofs.free(pm.node, DOF_X), dofs.free(pm.node, DOF_Y)]);
            e.mass = Some(DMatrix::from_fn(2, 2, |a, b| {
                if a == b { pm.mass[a] } else { 0.0 }
            }));
            e
        })
        .collect()
}

/// The added mass `m` (kg, row-major) of a table bearing or seal, acting on
/// the journal's acceleration relative to its housing: `[[m, −m], [−m, m]]`
/// between journal and housing.
pub fn added_mass(dofs: &DofMap, bearing: &PlacedBearing, mass: &[[f64; 2]; 2]) -> LinearElement {
    let mut e = LinearElement::new(bearing_dofs(dofs, bearing));
    e.mass = Some(link(mass, bearing.pedestal.is_some()));
    e
}

/// The pedestals of `model`: each one's mass on its translations and its
/// spring–damper to ground or to the pedestal it stands on.
pub(super) fn pedestals(model: &RotorModel, dofs: &DofMap) -> Vec<LinearElement> {
    let mut list = Vec::new();
    for (p, pedestal) in model.pedestals.iter().enumerate() {
        let mut local = pedestal_dofs(dofs, p).to_vec();
        if let Some(on) = pedestal.on {
            local.extend(pedestal_dofs(dofs, on));
        }
        let to_second = pedestal.on.is_some();
        let mut e = LinearElement::new(local);
        let n = e.dofs.len();
        e.mass = Some(DMatrix::from_fn(n, n, |a, b| {
            if a == b && a < 2 { pedestal.mass } else { 0.0 }
        }));
        e.stiffness = Some(link(&pedestal.stiffness, to_second));
        e.damping = Some(link(&pedestal.damping, to_second));
        list.push(e);
    }
    list
}
