//! The torsional chain of the rotor: one twist angle per node (rad, about
//! `+z`), the shaft elements' Saint-Venant torsion ([`crate::fe::torsion`]),
//! the disks' polar inertias, flexible couplings in place of their element's
//! torsional stiffness, and twist fixed where a support says `"rz"`. The
//! lateral and torsional motions of an axisymmetric rotor are uncoupled in
//! the linear matrices; they meet in the unbalance, the friction torques and
//! the spin speed (see `solver::torsion`).

use crate::fe::torsion::torsion_matrices;
use crate::linalg::BandMatrix;
use crate::model::RotorModel;

/// Tridiagonal torsional matrices on the free twist DOFs (node order).
#[derive(Debug, Clone)]
pub struct TorsionalRotor {
    /// Polar mass (kg·m²).
    pub mass: BandMatrix<f64>,
    /// Torsional stiffness (N·m/rad).
    pub stiffness: BandMatrix<f64>,
    /// Torsional damping of the couplings and shaft sections (N·m·s/rad).
    pub damping: BandMatrix<f64>,
    /// Free twist DOF of each node, `None` where a support fixes it.
    pub dofs: Vec<Option<usize>>,
    /// Lumped polar inertia of each free DOF (row sums of `mass`, kg·m²): the
    /// weights of the shaft's mean speed.
    pub inertia: Vec<f64>,
    /// Torsional stiffness (N·m/rad) and damping (N·m·s/rad) of each shaft
    /// element, from node `k` to `k + 1` (a coupling's where one is).
    pub elements: Vec<(f64, f64)>,
}

impl TorsionalRotor {
    /// The torsional chain of `model`.
    pub fn new(model: &RotorModel) -> Self {
        let nodes = model.node_count();
        let fixed: Vec<bool> = (0..nodes)
            .map(|i| model.supports.iter().any(|s| s.node == i && s.twist))
            .collect();
        let mut next = 0;
        let dofs: Vec<Option<usize>> = fixed
            .iter()
            .map(|&f| {
                (!f).then(|| {
                    next += 1;
                    next - 1
                })
            })
            .collect();
        let n = next;
        let mut mass = BandMatrix::new(n, 1, 1);
        let mut stiffness = BandMatrix::new(n, 1, 1);
        let mut damping = BandMatrix::new(n, 1, 1);
        let scatter = |target: &mut BandMatrix<f64>, nodes: [usize; 2], m: [[f64; 2]; 2]| {
            for (a, &na) in nodes.iter().enumerate() {
                for (b, &nb) in nodes.iter().enumerate() {
                    if let (Some(i), Some(j)) = (dofs[na], dofs[nb]) {
                        target.add(i, j, m[a][b]);
                    }
                }
            }
        };
        let mut elements = Vec::with_capacity(model.elements.len());
        for (k, placed) in model.elements.iter().enumerate() {
            let (mut m, mut kt) = torsion_matrices(&placed.element);
            // A flexible coupling in place of the element has no inertia of
            // its own (its hubs are disks), as laterally.
            if model.flexible_coupling_at(k) {
                m = [[0.0; 2]; 2];
            }
            let pair = [placed.node, placed.node + 1];
            // A coupling replaces the element's stiffness and damping.
            let mut c_element = placed.torsional_damping;
            if let Some(c) = model.couplings.iter().find(|c| c.element == k)
                && let Some(s) = c.stiffness
            {
                kt = [[s, -s], [-s, s]];
                c_element = c.damping;
            }
            if c_element != 0.0 {
                let ct = [[c_element, -c_element], [-c_element, c_element]];
                scatter(&mut damping, pair, ct);
            }
            elements.push((kt[0][0], c_element));
            scatter(&mut mass, pair, m);
            scatter(&mut stiffness, pair, kt);
        }
        for d in &model.disks {
            if let Some(i) = dofs[d.node] {
                mass.add(i, i, d.disk.polar_inertia);
            }
        }
        let inertia = (0..n)
            .map(|i| {
                (i.saturating_sub(1)..(i + 2).min(n))
                    .map(|j| mass.get(i, j))
                    .sum()
            })
            .collect();
        Self {
            mass,
            stiffness,
            damping,
            dofs,
            inertia,
            elements,
        }
    }

    /// Number of free twist DOFs.
    pub fn dof_count(&self) -> usize {
        self.inertia.len()
    }

    /// Total polar inertia of the free DOFs (kg·m²).
    pub fn total_inertia(&self) -> f64 {
        self.inertia.iter().sum()
    }
}
