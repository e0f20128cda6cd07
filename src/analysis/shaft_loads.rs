//! Bending moment and bending stress along the shaft at a static state, from
//! the end forces of each shaft element (issue 49: the load a misaligned
//! line puts on its shaft).
//!
//! An element in equilibrium carries at its ends the forces
//! `f = K_e u_e − f_g,e`: its stiffness (bending, shear and the axial load's
//! geometric term, as assembled) times its end displacements, less its own
//! weight as the consistent load `f_g,e = M_e u_g` the rotor's gravity load
//! is assembled from. With the exact ("interdependent") Timoshenko shape
//! functions these end forces are the beam's exact section forces at the
//! nodes. In each plane the bending moment follows `EI w'' = M` in beam
//! coordinates `(w, θ) = (x, θy)` and `(y, −θx)`: `M(z₁) = −f_θ1`,
//! `M(z₂) = f_θ2`, and the shear `V = dM/dz` is `V(z₁) = f_w1`,
//! `V(z₂) = −f_w2`. The element after a misaligned rigid flange carries
//! `K_e (u_e + s) − f_g,e` with its initial strain `s`; a flexible
//! coupling in place of an element is no shaft and is left out. The bending stress at the outer fibre is
//! `σ = |M| D_o / (2 I)`, `|M|` the resultant of the two planes.

use crate::fe::DOF_PER_NODE;
use crate::model::CouplingJoint;
use crate::rotor::{Rotor, flange_strain};

/// The section forces at one end of a shaft element.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SectionLoad {
    /// Shaft element (model order, 0-based).
    pub element: usize,
    /// Node (0-based) the end lies on.
    pub node: usize,
    /// Axial position (m).
    pub z: f64,
    /// Bending moment (N·m) in the x–z plane (`EI x'' = M`) and in the y–z
    /// plane (`EI y'' = M`): sagging positive.
    pub moment: [f64; 2],
    /// Shear force (N) in x and y, `V = dM/dz`.
    pub shear: [f64; 2],
    /// Resultant bending moment `|M|` (N·m).
    pub moment_magnitude: f64,
    /// Bending stress at the outer fibre `|M| D_o / (2 I)` (Pa).
    pub stress: f64,
}

/// Both ends of every shaft element of `rotor` at the displacement `all`
/// (on all DOFs, `4·node + k`, e.g. [`Rotor::dofs`]`.expand` of a static
/// equilibrium), with the elements' weight under gravity when `gravity`:
/// element by element, left end then right end.
pub fn section_loads(rotor: &Rotor, all: &[f64], gravity: bool) -> Vec<SectionLoad> {
    let model = &rotor.model;
    let g = if gravity { model.gravity } else { [0.0; 3] };
    let mut out = Vec::with_capacity(2 * model.elements.len());
    for (index, placed) in model.elements.iter().enumerate() {
        // A flexible coupling in place of the element is no shaft.
        if model.flexible_coupling_at(index) {
            continue;
        }
        let element = &placed.element;
        let mats = element.matrices();
        let k = mats.stiffness + mats.axial_per_newton * placed.axial_force;
        let base = placed.node * DOF_PER_NODE;
        let mut u = nalgebra::SVector::<f64, 8>::from_fn(|i, _| all[base + i]);
        // After a misaligned rigid flange the element's left end sits at the
        // misalignment from its node ([`crate::rotor::flange_strain`]).
        if let Some(s) = flange_strain(model, index) {
            u += s;
        }
        // The rigid translation by the gravity vector: x and y of both nodes.
        let u_g = nalgebra::SVector::<f64, 8>::from_fn(|i, _| match i % DOF_PER_NODE {
            0 => g[0],
            1 => g[1],
            _ => 0.0,
        });
        let f = k * u - mats.mass * u_g;
        let section = &element.section;
        let inertia = section.second_moment();
        let stress = |m: f64| m * section.outer_diameter / (2.0 * inertia);
        let z1 = model.node_z[placed.node];
        // Beam coordinates: x–z plane (x, θy) at [0, 3, 4, 7]; y–z plane
        // (y, −θx) at [1, 2, 5, 6], so its moment is conjugate to −θx.
        let ends = [
            (placed.node, z1, [-f[3], f[2]], [f[0], f[1]]),
            (
                placed.node + 1,
                z1 + element.length,
                [f[7], -f[6]],
                [-f[4], -f[5]],
            ),
        ];
        for (node, z, moment, shear) in ends {
            let magnitude = moment[0].hypot(moment[1]);
            out.push(SectionLoad {
                element: index,
                node,
                z,
                moment,
                shear,
                moment_magnitude: magnitude,
                stress: stress(magnitude),
            });
        }
    }
    out
}

/// The section of largest bending stress, `None` without shaft elements.
pub fn largest_stress(loads: &[SectionLoad]) -> Option<&SectionLoad> {
    loads.iter().max_by(|a, b| a.stress.total_cmp(&b.stress))
}

/// What a coupling transmits between the two shafts it joins, as the
/// section loads of the shaft line at it (the conventions of
/// [`SectionLoad`]: sagging moments positive, `V = dM/dz`).
#[derive(Debug, Clone, PartialEq)]
pub struct CouplingLoad {
    /// Coupling (model order, 0-based).
    pub coupling: usize,
    /// Its name.
    pub name: String,
    /// The node (0-based) of the shaft before it.
    pub node: usize,
    /// Bending moment (N·m) in the x–z and y–z planes.
    pub moment: [f64; 2],
    /// Shear force (N) in x and y.
    pub shear: [f64; 2],
}

/// The loads every coupling of `rotor` transmits at the displacement `all`
/// (on all DOFs, as for [`section_loads`]). A flexible coupling's spring
/// loads the shaft before it by `f = k (q_r − q_l − m)` in beam
/// coordinates `(w, ψ)`, so the line carries `V = −k_l (Δw − m_w)` and
/// `M = k_a (Δψ − m_ψ)` there; a rigid flange carries the section loads of
/// the shaft element after it at its left end (with its initial strain).
pub fn coupling_loads(rotor: &Rotor, all: &[f64], gravity: bool) -> Vec<CouplingLoad> {
    let model = &rotor.model;
    let sections = section_loads(rotor, all, gravity);
    model
        .couplings
        .iter()
        .enumerate()
        .map(|(index, c)| {
            let node = model.elements[c.element].node;
            let (moment, shear) = match c.joint {
                CouplingJoint::Flexible { lateral, angular } => {
                    let (l, r) = (node * DOF_PER_NODE, (node + 1) * DOF_PER_NODE);
                    let m = &c.misalignment;
                    // Beam coordinates: (x, θy) and (y, −θx).
                    let dw = [all[r] - all[l] - m[0], all[r + 1] - all[l + 1] - m[1]];
                    let dpsi = [
                        all[r + 3] - all[l + 3] - m[3],
                        -(all[r + 2] - all[l + 2] - m[2]),
                    ];
                    (
                        [angular[0] * dpsi[0], angular[0] * dpsi[1]],
                        [-lateral[0] * dw[0], -lateral[0] * dw[1]],
                    )
                }
                CouplingJoint::Flange => {
                    let s = sections
                        .iter()
                        .find(|s| s.element == c.element && s.node == node)
                        .expect("a flange's element is a shaft element");
                    (s.moment, s.shear)
                }
            };
            CouplingLoad {
                coupling: index,
                name: c.name.clone(),
                node,
                moment,
                shear,
            }
        })
        .collect()
}
