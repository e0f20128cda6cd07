//! Craig–Bampton reduction of the assembled rotor for long transients.
//!
//! The free DOFs split into **physical** ones `b` (all free DOFs of the kept
//! nodes: nonlinear bearings and rubs, probes, unbalance planes; and every
//! pedestal's translations) and
//! **interior** ones `i`. The interior moves with the boundary statically plus
//! `m` fixed-interface modes (Craig & Bampton, AIAA J. 6(7), 1968):
//!
//! `u = T q`, `T = [[I, 0], [Ψ, Φ]]`, `Ψ = −K_ii⁻¹ K_ib`,
//! `K_ii φ_k = ω_k² M_ii φ_k` for the `m` lowest `ω_k`,
//!
//! and every matrix becomes `Tᵀ X T` (`X` = M, K, C, G; dense, of order
//! `r = n_b + m`), the gravity load `Tᵀ f_g`. Forces on kept nodes (bearing,
//! rub and unbalance forces) enter `q` unchanged, because the boundary rows
//! of `T` are the identity: the nonlinear forces act exactly where they do in
//! the full model, and the static response to them is exact (Ψ). The modes
//! carry the interior's dynamics up to `ω_m`; each is scaled to a largest
//! translation of 1, so its coordinate is the peak interior displacement (m).
//! The gyroscopic matrix is projected on the same basis, so one reduction
//! serves every speed.

use nalgebra::DMatrix;

use super::dofs::DOF_PER_PEDESTAL;
use super::{AssemblyError, Dof, DofMap, Rotor};
use crate::fe::DOF_PER_NODE;
use crate::linalg::{BandMatrix, lowest_eigenpairs};
use crate::model::{DEFAULT_REDUCED_MODES, MAX_REDUCED_MODES, ReductionRequest, RotorModel};

/// The kept fixed-interface modes must reach this multiple of the highest
/// frequency of the motion (running speed, whirl): then the receptance at
/// the kept nodes is within 1 % of the full rotor's (measured on every
/// shipped model with 1 to 24 modes, worst 7.1e-3 at a tenth of the highest
/// mode; `tests/reduction.rs`); at a fifth it reaches 8 %, at half 150 %.
pub const VALIDITY_FACTOR: f64 = 10.0;

/// What a reduced rotor keeps, and its basis.
#[derive(Debug, Clone, PartialEq)]
pub struct Reduction {
    /// Nodes kept as physical coordinates (0-based, ascending).
    pub kept_nodes: Vec<usize>,
    /// Physical coordinates (the free DOFs of the kept nodes), first in `q`.
    pub physical: usize,
    /// Fixed-interface modes kept, after the physical coordinates.
    pub modes: usize,
    /// Modes asked for (clamped to the interior's DOF count).
    pub requested: usize,
    /// Natural frequencies of the kept fixed-interface modes (rad/s), ascending.
    pub mode_frequencies: Vec<f64>,
    /// The full rotor's DOF numbering (the rows of `T`).
    pub full_map: DofMap,
    /// `T` (full free DOFs × reduced coordinates, `u = T q`) row by row,
    /// so that a node's row is one contiguous slice.
    rows: Vec<f64>,
}

impl Reduction {
    /// Displacement `k` (0–3: x, y, θx, θy) of `node` for reduced
    /// coordinates `q`: row `(node, k)` of `T` times `q` (0 for a fixed DOF).
    pub fn node_value(&self, node: usize, k: usize, q: &[f64]) -> f64 {
        let r = self.physical + self.modes;
        self.full_map.free(node, k).map_or(0.0, |i| {
            let row = &self.rows[i * r..(i + 1) * r];
            row.iter().zip(q).fold(0.0, |sum, (t, x)| sum + t * x)
        })
    }

    /// Highest kept fixed-interface frequency (rad/s), 0 without modes.
    pub fn highest_frequency(&self) -> f64 {
        self.mode_frequencies.last().copied().unwrap_or(0.0)
    }

    /// Highest frequency of motion (rad/s) the reduction is valid for: the
    /// highest kept mode over [`VALIDITY_FACTOR`] (0 without modes).
    pub fn validated_frequency(&self) -> f64 {
        self.highest_frequency() / VALIDITY_FACTOR
    }

    /// One line for logs and the CLI: what is kept and how far the modes reach.
    pub fn describe(&self) -> String {
        let nodes: Vec<String> = self
            .kept_nodes
            .iter()
            .map(|n| (n + 1).to_string())
            .collect();
        let clamped = if self.requested > self.modes {
            format!(" ({} asked, all the interior has)", self.requested)
        } else {
            String::new()
        };
        let pedestals = (self.full_map.full_count() - self.full_map.node_count() * DOF_PER_NODE)
            / DOF_PER_PEDESTAL;
        let housings = match pedestals {
            0 => String::new(),
            1 => " and 1 pedestal".to_string(),
            n => format!(" and {n} pedestals"),
        };
        format!(
            "reduced rotor (Craig–Bampton): {} coordinates for {} DOFs — {} physical at nodes {}{housings} + {} fixed-interface modes{clamped} up to {:.1} Hz, valid for motion up to {:.1} Hz ({} rpm)",
            self.physical + self.modes,
            self.full_map.free_count(),
            self.physical,
            nodes.join(", "),
            self.modes,
            self.highest_frequency() / std::f64::consts::TAU,
            self.validated_frequency() / std::f64::consts::TAU,
            (self.validated_frequency() * 30.0 / std::f64::consts::PI).round(),
        )
    }
}

impl Rotor {
    /// Nodes a reduced rotor keeps physical: every bearing kept out of the
    /// matrices (nonlinear bearings, rubs, seals, magnetic pulls), every
    /// probe, unbalance plane, external force and port.
    /// (Linear bearings stay in the matrices; their journals are read
    /// through the basis.)
    pub fn kept_nodes(&self) -> Vec<usize> {
        let m = &self.model;
        // A linear bearing set off the axis is loaded by its preload at
        // its journal ([`Rotor::add_offset_loads`]): kept physical too.
        let bearings = m.bearings.iter().filter(|b| {
            let bearing = b.kind.build();
            !(bearing.is_linear() && bearing.internal_dofs() == 0) || b.is_offset()
        });
        let mut nodes: Vec<usize> = bearings
            .map(|b| b.node)
            .chain(m.probes.iter().map(|p| p.node))
            .chain(m.unbalances.iter().map(|u| u.node))
            .chain(m.forces.iter().map(|f| f.node))
            .chain(m.ports.iter().map(|p| p.node))
            // A misaligned coupling loads both its nodes by its preload.
            .chain(
                m.couplings
                    .iter()
                    .filter(|c| c.is_misaligned())
                    .flat_map(|c| {
                        let node = m.elements[c.element].node;
                        [node, node + 1]
                    }),
            )
            .collect();
        nodes.sort_unstable();
        nodes.dedup();
        nodes
    }

    /// Coordinates of the rotor [`Rotor::for_transients`] builds from this
    /// one's model with `modes` fixed-interface modes, without building it:
    /// every free DOF for 0 (the full rotor), else the free DOFs of the kept
    /// nodes and of the pedestals plus `min(modes, interior DOFs)`; `None` when the model has no
    /// node to keep. Two counts build the same rotor exactly when both or
    /// neither are 0 and their coordinates agree (999 and 1000 modes on a rotor
    /// with fewer interior DOFs are both all of them).
    pub fn transient_coordinates(&self, modes: usize) -> Option<usize> {
        let kept = self.kept_nodes();
        let (free, physical) = match &self.reduction {
            Some(r) => (r.full_map.free_count(), r.physical),
            None => {
                let at_kept = |&node: &usize| {
                    (0..DOF_PER_NODE)
                        .filter(|&k| self.dofs.free(node, k).is_some())
                        .count()
                };
                // The pedestals stay physical too (see `interior`).
                let pedestals = (0..self.dof_count())
                    .filter(|&i| matches!(self.dofs.kind(i), Dof::Pedestal { .. }))
                    .count();
                (
                    self.dof_count(),
                    kept.iter().map(at_kept).sum::<usize>() + pedestals,
                )
            }
        };
        match modes {
            0 => Some(free),
            _ if kept.is_empty() => None,
            _ => Some(physical + modes.min(free - physical)),
        }
    }

    /// An [`AssemblyError::Reduction`] of this model.
    fn reduction_error(&self, message: String) -> AssemblyError {
        AssemblyError::Reduction {
            model: self.model.name.clone(),
            message,
        }
    }

    /// The free DOFs split into the kept nodes' and the interior, and the
    /// interior's stiffness (factored) and mass.
    fn interior(&self) -> Result<Interior, AssemblyError> {
        if self.reduction.is_some() {
            return Err(self.reduction_error("the rotor is already reduced".into()));
        }
        let kept_nodes = self.kept_nodes();
        if kept_nodes.is_empty() {
            return Err(self.reduction_error(
                "no node to keep: the model has no nonlinear bearing, rub, probe or unbalance"
                    .into(),
            ));
        }
        let n = self.dof_count();
        let mut is_kept = vec![false; n];
        for &node in &kept_nodes {
            for k in 0..DOF_PER_NODE {
                if let Some(i) = self.dofs.free(node, k) {
                    is_kept[i] = true;
                }
            }
        }
        // Pedestals carry bearing reactions: they stay physical too.
        for (i, kept) in is_kept.iter_mut().enumerate() {
            if matches!(self.dofs.kind(i), Dof::Pedestal { .. }) {
                *kept = true;
            }
        }
        let boundary: Vec<usize> = (0..n).filter(|&i| is_kept[i]).collect();
        let interior: Vec<usize> = (0..n).filter(|&i| !is_kept[i]).collect();
        let k_ii = sub_band(&self.stiffness, &interior);
        let m_ii = sub_band(&self.mass, &interior);
        let lu = k_ii.lu().map_err(|e| {
            self.reduction_error(format!(
                "the interior is not held by the kept nodes and linear bearings (K_ii: {e})"
            ))
        })?;
        Ok(Interior {
            kept_nodes,
            boundary,
            interior,
            k_ii,
            m_ii,
            lu,
        })
    }

    /// The `count` lowest fixed-interface natural frequencies (rad/s,
    /// ascending; fewer when the interior has fewer DOFs), those a reduction
    /// with `count` modes keeps.
    pub fn fixed_interface_frequencies(&self, count: usize) -> Result<Vec<f64>, AssemblyError> {
        let i = self.interior()?;
        let m = count.min(i.interior.len());
        let (omega_sq, _) =
            lowest_eigenpairs(&i.k_ii, &i.m_ii, &i.lu, m).map_err(|e| self.reduction_error(e))?;
        Ok(omega_sq.iter().map(|w2| w2.sqrt()).collect())
    }

    /// Fixed-interface modes a reduced rotor needs to be valid for motion
    /// up to `frequency` (rad/s): the smallest count whose highest mode
    /// reaches [`VALIDITY_FACTOR`] × `frequency`, with the partner of a
    /// degenerate pair (the x and y modes of a round shaft) kept together;
    /// every mode the interior has when none reaches it (at most
    /// [`MAX_REDUCED_MODES`]).
    pub fn modes_for(&self, frequency: f64) -> Result<usize, AssemblyError> {
        let target = VALIDITY_FACTOR * frequency.abs();
        let interior = self.interior()?.interior.len();
        let cap = interior.clamp(1, MAX_REDUCED_MODES);
        let mut count = 8.min(cap);
        let frequencies = loop {
            let f = self.fixed_interface_frequencies(count)?;
            if f.last().is_some_and(|&w| w >= target) || count >= cap {
                break f;
            }
            count = (2 * count).min(cap);
        };
        let Some(k) = frequencies.iter().position(|&w| w >= target) else {
            return Ok(cap);
        };
        let pair = frequencies[k + 1..]
            .iter()
            .take_while(|&&w| w <= frequencies[k] * (1.0 + 1e-6))
            .count();
        Ok((k + 1 + pair).clamp(1, cap))
    }

    /// The mode count transients of `model` run with: 0 (the full rotor)
    /// without `[reduction]`, its `modes`, or without them as many as the
    /// speed range needs ([`Rotor::modes_for`] the model's `max_speed_rpm`
    /// if it states one, else its `speed_rpm`; [`DEFAULT_REDUCED_MODES`]
    /// when it states neither).
    pub fn transient_modes(model: &RotorModel) -> Result<usize, AssemblyError> {
        match model.reduction {
            None => Ok(0),
            Some(ReductionRequest::Modes(m)) => Ok(m),
            Some(ReductionRequest::FromSpeedRange) => match model.transient_top_speed() {
                Some(top) => Rotor::new(model.clone())?.modes_for(top),
                None => Ok(DEFAULT_REDUCED_MODES),
            },
        }
    }

    /// This rotor reduced to its [kept nodes](Rotor::kept_nodes) and `modes`
    /// fixed-interface modes (clamped to the interior DOF count), for the
    /// transient [`Simulator`](crate::solver::Simulator).
    ///
    /// ```
    /// use rotor_bearing::model::RotorModel;
    /// use rotor_bearing::rotor::Rotor;
    ///
    /// let path = concat!(env!("CARGO_MANIFEST_DIR"), "/models/hydro_unit.toml");
    /// let rotor = Rotor::new(RotorModel::from_file(std::path::Path::new(path))?)?;
    /// let reduced = rotor.reduced(10)?;
    /// let r = reduced.reduction.as_ref().unwrap();
    /// // Two guide bearings, the probes and the unbalance planes stay physical.
    /// assert_eq!(r.physical + r.modes, reduced.dof_count());
    /// assert!(reduced.dof_count() < rotor.dof_count());
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn reduced(&self, modes: usize) -> Result<Rotor, AssemblyError> {
        if modes == 0 {
            return Err(self.reduction_error("reduced_modes = 0: ask for at least one mode".into()));
        }
        let Interior {
            kept_nodes,
            boundary,
            interior,
            k_ii,
            m_ii,
            lu,
        } = self.interior()?;
        let n = self.dof_count();
        let (nb, ni) = (boundary.len(), interior.len());
        let m = modes.min(ni);
        let (omega_sq, phi) =
            lowest_eigenpairs(&k_ii, &m_ii, &lu, m).map_err(|e| self.reduction_error(e))?;

        // T = [[I, 0], [Ψ, Φ]] in the full free numbering.
        let r = nb + m;
        let mut basis = DMatrix::zeros(n, r);
        let mut column = vec![0.0; ni];
        for (c, &b) in boundary.iter().enumerate() {
            basis[(b, c)] = 1.0;
            for (x, &i) in column.iter_mut().zip(&interior) {
                *x = -self.stiffness.get(i, b);
            }
            lu.solve_in_place(&mut column);
            for (x, &i) in column.iter().zip(&interior) {
                basis[(i, c)] = *x;
            }
        }
        for k in 0..m {
            let mut v: Vec<f64> = phi.column(k).iter().copied().collect();
            normalize_to_peak_translation(&mut v, &interior, &self.dofs);
            for (x, &i) in v.iter().zip(&interior) {
                basis[(i, nb + k)] = *x;
            }
        }

        let project = |x: &BandMatrix<f64>| -> BandMatrix<f64> {
            let mut xt = DMatrix::zeros(n, r);
            let mut y = vec![0.0; n];
            for c in 0..r {
                x.mul_vec(basis.column(c).as_slice(), &mut y);
                xt.column_mut(c).copy_from_slice(&y);
            }
            let dense = basis.transpose() * xt;
            let mut out = BandMatrix::new(r, r - 1, r - 1);
            for j in 0..r {
                for i in 0..r {
                    out.set(i, j, dense[(i, j)]);
                }
            }
            out
        };
        let gravity = basis.transpose() * nalgebra::DVector::from_column_slice(&self.gravity_load);

        let mut dofs = DofMap {
            full_to_free: vec![None; self.dofs.full_count()],
            free_to_full: boundary.iter().map(|&b| self.dofs.full(b)).collect(),
            modal: m,
            nodes: self.dofs.nodes,
        };
        for (c, &b) in boundary.iter().enumerate() {
            dofs.full_to_free[self.dofs.full(b)] = Some(c);
        }
        Ok(Rotor {
            model: self.model.clone(),
            dofs,
            mass: project(&self.mass),
            stiffness: project(&self.stiffness),
            damping: project(&self.damping),
            gyroscopic: project(&self.gyroscopic),
            nonlinear_bearings: self.nonlinear_bearings.clone(),
            negative_stiffness: self.negative_stiffness.clone(),
            gravity_load: gravity.as_slice().to_vec(),
            reduction: Some(Reduction {
                kept_nodes,
                physical: nb,
                modes: m,
                requested: modes,
                mode_frequencies: omega_sq.iter().map(|w2| w2.sqrt()).collect(),
                rows: basis.transpose().as_slice().to_vec(),
                full_map: self.dofs.clone(),
            }),
        })
    }
}

/// The free DOFs of a rotor split for its reduction, and the interior's matrices.
struct Interior {
    kept_nodes: Vec<usize>,
    boundary: Vec<usize>,
    interior: Vec<usize>,
    k_ii: BandMatrix<f64>,
    m_ii: BandMatrix<f64>,
    lu: crate::linalg::BandLu<f64>,
}

/// The rows and columns `keep` (ascending) of a banded matrix, as a banded
/// matrix of the same half-bandwidths (dropping DOFs never widens the band).
fn sub_band(a: &BandMatrix<f64>, keep: &[usize]) -> BandMatrix<f64> {
    let n = keep.len();
    let mut out = BandMatrix::new(n, a.kl(), a.ku());
    for j in 0..n {
        for i in j.saturating_sub(out.ku())..(j + out.kl() + 1).min(n) {
            let v = a.get(keep[i], keep[j]);
            if v != 0.0 {
                out.set(i, j, v);
            }
        }
    }
    out
}

/// Scale an interior mode to a largest translation of 1 (its largest entry
/// when it has no translation), the largest entry positive.
fn normalize_to_peak_translation(v: &mut [f64], interior: &[usize], dofs: &DofMap) {
    let translation = |j: usize| dofs.kind(interior[j]).translation().is_some();
    let peak = |only_translation: bool| {
        (0..v.len())
            .filter(|&j| !only_translation || translation(j))
            .max_by(|&a, &b| v[a].abs().total_cmp(&v[b].abs()))
    };
    let largest = peak(false).map_or(0.0, |j| v[j].abs());
    let j = match peak(true) {
        Some(j) if v[j].abs() > 1e-9 * largest => j,
        _ => match peak(false) {
            Some(j) => j,
            None => return,
        },
    };
    let scale = 1.0 / v[j];
    for x in v.iter_mut() {
        *x *= scale;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::fe::{DOF_X, DOF_Y};
    use crate::model::RotorModel;
    use nalgebra::SymmetricEigen;

    /// An Euler–Bernoulli shaft (no shear, no rotary inertia) of 1 m, 50 mm,
    /// in `elements` elements, probes at both ends and no bearings.
    fn clamped_interior(elements: usize) -> Rotor {
        let text = format!(
            r#"
name = "beam"
shear_deformation = false
rotary_inertia = false
[[materials]]
name = "steel"
youngs_modulus = 211e9
shear_modulus = 81.2e9
density = 7810.0
[[shaft]]
length = 1.0
outer_diameter = 0.05
material = "steel"
elements = {elements}
[[probes]]
name = "a"
node = 1
[[probes]]
name = "b"
node = {}
"#,
            elements + 1
        );
        Rotor::new(RotorModel::from_toml(&text, "beam.toml").unwrap()).unwrap()
    }

    /// With both ends kept, the interior is a clamped–clamped beam:
    /// `ω_k = (β_k L)² √(EI / (ρ A L⁴))`, `β₁L = 4.730041`, `β₂L = 7.853205`,
    /// each twice (the two planes). 80 cubic elements are within 1e-6 of it
    /// (the discretization error falls as `h⁴`: 1e-6 for mode 2 at 40).
    #[test]
    fn fixed_interface_modes_are_those_of_the_clamped_interior() {
        let rotor = clamped_interior(80);
        let reduced = rotor.reduced(4).unwrap();
        let r = reduced.reduction.as_ref().unwrap();
        assert_eq!(
            (r.kept_nodes.clone(), r.physical, r.modes),
            (vec![0, 80], 8, 4)
        );
        let d: f64 = 0.05;
        let (e, rho) = (211e9, 7810.0);
        let (area, inertia) = (
            std::f64::consts::PI * d * d / 4.0,
            std::f64::consts::PI * d.powi(4) / 64.0,
        );
        let unit = (e * inertia / (rho * area)).sqrt();
        for (k, bl) in [4.730_040_745, 4.730_040_745, 7.853_204_624, 7.853_204_624]
            .iter()
            .enumerate()
        {
            let exact = bl * bl * unit;
            let rel = (r.mode_frequencies[k] / exact - 1.0).abs();
            assert!(
                rel < 1e-6,
                "mode {k}: {} against {exact} rad/s ({rel:.1e})",
                r.mode_frequencies[k]
            );
        }
    }

    /// The generalized eigenvalues of `(k, m)` by a dense solution, ascending:
    /// the inverse problem `L⁻¹ M L⁻ᵀ y = (1/ω²) y`, `K = L Lᵀ`, whose largest
    /// eigenvalues (the lowest modes) a dense solver gets to round-off.
    fn dense_eigenvalues(k: &BandMatrix<f64>, m: &BandMatrix<f64>) -> Vec<f64> {
        let l = k.to_dense().cholesky().unwrap().l();
        let a = l.solve_lower_triangular(&m.to_dense()).unwrap();
        let a = l.solve_lower_triangular(&a.transpose()).unwrap();
        let mut dense: Vec<f64> = SymmetricEigen::new((&a + a.transpose()) * 0.5)
            .eigenvalues
            .iter()
            .map(|mu| 1.0 / mu)
            .collect();
        dense.sort_by(f64::total_cmp);
        dense
    }

    /// Every count from 1 to `up_to` gives exactly the lowest eigenvalues of
    /// the rotor's interior, with their multiplicity, to 1e-10 (the dense
    /// solution's round-off on `ω²`), and M-orthonormal vectors.
    fn assert_lowest_eigenvalues(rotor: &Rotor, up_to: usize) {
        let i = rotor.interior().unwrap();
        let dense = dense_eigenvalues(&i.k_ii, &i.m_ii);
        let md = i.m_ii.to_dense();
        for count in 1..=up_to {
            let (values, vectors) = lowest_eigenpairs(&i.k_ii, &i.m_ii, &i.lu, count).unwrap();
            assert_eq!(values.len(), count);
            for (j, (v, d)) in values.iter().zip(&dense).enumerate() {
                assert!(
                    (v / d - 1.0).abs() < 1e-10,
                    "{}, {count} modes, mode {j}: ω = {} against {} rad/s",
                    rotor.model.name,
                    v.sqrt(),
                    d.sqrt()
                );
            }
            let gram = vectors.transpose() * &md * &vectors;
            assert!((gram - DMatrix::identity(count, count)).amax() < 1e-10);
        }
    }

    /// Subspace iteration (block smaller than the interior) gives the
    /// eigenvalues of a dense generalized solution of `(K_ii, M_ii)` to 1e-10,
    /// repeated pairs included.
    #[test]
    fn subspace_iteration_matches_a_dense_eigensolution() {
        let rotor = clamped_interior(30);
        assert!(2 * 12 < rotor.dof_count() - 8);
        assert_lowest_eigenvalues(&rotor, 12);
    }

    /// Two identical clamped spans (the middle node kept too), each in two
    /// planes: every eigenvalue is fourfold, and every count, cutting a
    /// cluster or not, gets the lowest ones.
    #[test]
    fn fourfold_eigenvalues_of_two_identical_spans_are_all_found() {
        let mut rotor = clamped_interior(40);
        let mut model = rotor.model.clone();
        let mut probe = model.probes[0].clone();
        probe.node = 20;
        probe.name = "mid".into();
        model.probes.push(probe);
        rotor = Rotor::new(model).unwrap();
        assert_eq!(rotor.kept_nodes(), vec![0, 20, 40]);
        let i = rotor.interior().unwrap();
        let dense = dense_eigenvalues(&i.k_ii, &i.m_ii);
        assert!((dense[3] / dense[0] - 1.0) < 1e-9 && dense[4] / dense[3] > 2.0);
        assert_lowest_eigenvalues(&rotor, 12);
    }

    /// The coordinates counted without building the reduced rotor (what the
    /// FMU checks a restored state against) are those of the rotor built,
    /// for every shipped model and 1, 4 and 10 modes — pedestals included
    /// (the unit on brackets keeps its three pedestals physical: 27
    /// coordinates with one mode, where the count once said 21).
    #[test]
    fn the_counted_coordinates_are_the_built_ones() {
        let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/models");
        for entry in std::fs::read_dir(dir).unwrap() {
            let path = entry.unwrap().path();
            if path.extension().is_none_or(|e| e != "toml") {
                continue;
            }
            let model = RotorModel::from_file(&path).unwrap();
            let full = Rotor::new(model.clone()).unwrap();
            for modes in [1, 4, 10] {
                let Ok(built) = Rotor::for_transients(model.clone(), modes) else {
                    continue;
                };
                assert_eq!(
                    full.transient_coordinates(modes),
                    Some(built.dof_count()),
                    "{}, {modes} modes",
                    path.display()
                );
            }
            if model.name == "hydro_unit_brackets" {
                assert_eq!(full.transient_coordinates(1), Some(27));
            }
        }
    }

    /// The unit with three guide bearings (24 elements, kept nodes 1, 5, 9,
    /// 22, 25): its long span 9–22 has degenerate pairs (697.5 and 1734.4
    /// rad/s) that a start block of unit vectors misses without the Sturm check.
    #[test]
    fn the_three_guide_unit_gets_its_lowest_lowest_eigenpairs() {
        let path = concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/models/hydro_unit_three_guide.toml"
        );
        let rotor = Rotor::new(RotorModel::from_file(std::path::Path::new(path)).unwrap()).unwrap();
        assert_eq!(rotor.kept_nodes(), vec![0, 4, 8, 21, 24]);
        assert_lowest_eigenvalues(&rotor, 24);
        let f = rotor.fixed_interface_frequencies(6).unwrap();
        assert!((f[1] / f[0] - 1.0).abs() < 1e-9 && (f[3] / f[2] - 1.0).abs() < 1e-9);
        assert!(f[2] > 1.5 * f[0] && f[4] > 1.5 * f[2], "{f:?}");
    }

    /// The reduced matrices are `Tᵀ X T` with `T` identity on the kept DOFs:
    /// a static load on a kept DOF gives the full model's displacement there.
    #[test]
    fn static_condensation_is_exact_at_the_kept_nodes() {
        let path = concat!(env!("CARGO_MANIFEST_DIR"), "/models/hydro_unit.toml");
        let model = RotorModel::from_file(std::path::Path::new(path)).unwrap();
        let mut full = Rotor::new(model).unwrap();
        // Hold the journals (the guide bearings are kept out of K) with springs.
        for b in full.model.bearings.clone() {
            for k in [DOF_X, DOF_Y] {
                let i = full.dofs.free(b.node, k).unwrap();
                full.stiffness.add(i, i, 1e9);
            }
        }
        let reduced = full.reduced(3).unwrap();
        let node = reduced.reduction.as_ref().unwrap().kept_nodes[1];
        let (i_full, i_red) = (
            full.dofs.free(node, DOF_Y).unwrap(),
            reduced.dofs.free(node, DOF_Y).unwrap(),
        );
        let mut f = vec![0.0; full.dof_count()];
        f[i_full] = 1e6;
        full.stiffness.lu().unwrap().solve_in_place(&mut f);
        let mut g = vec![0.0; reduced.dof_count()];
        g[i_red] = 1e6;
        reduced.stiffness.lu().unwrap().solve_in_place(&mut g);
        for &n in &reduced.reduction.as_ref().unwrap().kept_nodes {
            for k in 0..DOF_PER_NODE {
                let (a, b) = (
                    f[full.dofs.free(n, k).unwrap()],
                    reduced.node_value(n, k, &g),
                );
                assert!(
                    (a - b).abs() <= 1e-12 * f[i_full].abs(),
                    "node {n} dof {k}: {a} against {b}"
                );
            }
        }
    }
}
