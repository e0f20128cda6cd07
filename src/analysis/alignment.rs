//! Alignment of a shaft line on its bearings (issue 49): the bearing
//! reactions at the model's offsets, the reaction influence matrix (how each
//! reaction changes with each bearing's offset) and the offsets that give a
//! target load sharing.
//!
//! The reactions are those of the static equilibrium of the whole line
//! ([`line_equilibrium`]: gravity, loads, offsets, nonlinear films). At the
//! equilibrium the line's tangent stiffness is `K_t = K + Σ E K_b Eᵀ` (`K`
//! holding the linear bearings, `K_b` each other element's static stiffness,
//! pad tilts condensed statically). An offset `o_j` enters the force of
//! bearing `j` as `F_j(Eⱼᵀu − o_j)`, so `∂r/∂o_j = E_j K_j` and
//! `du/do_j = K_t⁻¹ E_j K_j`; a reaction `R_i = F_i(E_iᵀu − o_i)` then moves by
//! `∂R_i/∂o_j = −K_i (E_iᵀ du/do_j − δ_ij I)`. For linear bearings this is the
//! exact (constant) influence matrix; for films the tangent at the
//! equilibrium.
//!
//! The load a bearing carries is its reaction along the load direction
//! `d = −g_⊥/|g_⊥|` (up, for gravity along −y; for a vertical machine the
//! plane of its largest offset, [`load_direction`]), and its elevation is
//! its offset along `d`. The offsets for a target sharing are found by Newton
//! on the elevations with the least-norm (pseudo-inverse) step: the rigid
//! lift and tilt of the whole line change no reaction and are left alone, and
//! a target that no alignment reaches (the reactions must balance the line's
//! weight and its moment) is met in the least-squares sense.

use nalgebra::{DMatrix, DVector, Matrix2};

use crate::bearing::BearingEval;
use crate::fe::{DOF_X, DOF_Y};
use crate::rotor::Rotor;
use crate::solver::{Equilibrium, SolverError, SolverOptions, line_equilibrium};

/// Why an alignment could not be computed.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum AlignmentError {
    /// No static equilibrium.
    #[error("alignment at {speed} rad/s: {source}")]
    Solver { speed: f64, source: SolverError },
    /// The model cannot be aligned as asked.
    #[error("alignment: {0}")]
    Input(String),
}

/// One bearing of the line at its static equilibrium.
#[derive(Debug, Clone, PartialEq)]
pub struct BearingReaction {
    /// Bearing index in the model.
    pub bearing: usize,
    /// Bearing name.
    pub name: String,
    /// Its offset `(o_x, o_y)` (m).
    pub offset: [f64; 2],
    /// Force of the bearing on the journal `(F_x, F_y)` (N).
    pub reaction: [f64; 2],
    /// The load it carries: the reaction along the load direction (N).
    pub load: f64,
    /// Projected area `L·D` of a fluid-film bearing (m²), `None` otherwise.
    pub area: Option<f64>,
}

/// The bearing reactions of a line and their influence matrix.
#[derive(Debug, Clone, PartialEq)]
pub struct Alignment {
    /// Spin speed (rad/s).
    pub speed: f64,
    /// Unit load direction `d` in the x–y plane (opposite gravity; for a
    /// vertical machine the plane of its largest offset, [`load_direction`]).
    pub direction: [f64; 2],
    /// The bearings (rubs, seals and magnetic pulls act on the line but are
    /// not listed), in model order.
    pub bearings: Vec<BearingReaction>,
    /// `∂R/∂o` (N/m), `2n × 2n` over the bearings' `(x, y)`: row `2i + a` is
    /// `R_i,a`, column `2j + b` the offset `o_j,b`.
    pub influence: DMatrix<f64>,
    /// The static equilibrium the reactions belong to.
    pub equilibrium: Equilibrium,
}

impl Alignment {
    /// The loads the bearings carry (N), along [`Self::direction`].
    pub fn loads(&self) -> Vec<f64> {
        self.bearings.iter().map(|b| b.load).collect()
    }

    /// The influence of the elevations on the loads, `S_ij = dᵀ (∂R_i/∂o_j) d`
    /// (N/m), `n × n`.
    pub fn load_influence(&self) -> DMatrix<f64> {
        let n = self.bearings.len();
        let d = self.direction;
        DMatrix::from_fn(n, n, |i, j| {
            let mut s = 0.0;
            for a in 0..2 {
                for b in 0..2 {
                    s += d[a] * self.influence[(2 * i + a, 2 * j + b)] * d[b];
                }
            }
            s
        })
    }
}

/// The journal stiffness of an element evaluated at rest, internal
/// coordinates condensed statically: `K_jj − K_jp K_pp⁻¹ K_pj` (N/m).
fn static_stiffness(eval: &BearingEval) -> Matrix2<f64> {
    let n = eval.n();
    let j = eval.journal().stiffness;
    if n == 2 {
        return j;
    }
    let k = DMatrix::from_fn(n, n, |a, b| eval.k(a, b));
    let kpp = k.view((2, 2), (n - 2, n - 2)).into_owned();
    let kpj = k.view((2, 0), (n - 2, 2)).into_owned();
    let kjp = k.view((0, 2), (2, n - 2)).into_owned();
    match kpp.lu().solve(&kpj) {
        Some(x) => {
            let red = kjp * x;
            j - Matrix2::from_fn(|a, b| red[(a, b)])
        }
        None => j,
    }
}

/// The unit load direction of `rotor`'s model: `−g_⊥/|g_⊥|` against
/// gravity across the shaft. A vertical machine (no gravity across the
/// shaft) carries no weight on its guide bearings: its loads come from the
/// offsets, and are taken in the plane of the largest offset of a journal
/// bearing (the plane a plumb-line survey measures it in), `+x` when no
/// bearing is offset.
pub fn load_direction(rotor: &Rotor) -> [f64; 2] {
    let g = rotor.model.gravity;
    let norm = g[0].hypot(g[1]);
    if norm > 0.0 {
        return [-g[0] / norm, -g[1] / norm];
    }
    let largest = rotor
        .model
        .bearings
        .iter()
        .filter(|b| b.kind.is_bearing())
        .map(|b| b.offset)
        .max_by(|a, b| a[0].hypot(a[1]).total_cmp(&b[0].hypot(b[1])))
        .filter(|o| o[0].hypot(o[1]) > 0.0);
    match largest {
        Some(o) => {
            let r = o[0].hypot(o[1]);
            [o[0] / r, o[1] / r]
        }
        None => [1.0, 0.0],
    }
}

/// Whether gravity has a part across the shaft of `rotor` (a horizontal or
/// inclined machine whose bearings share its weight); `false` for a
/// vertical machine.
pub fn carries_weight(rotor: &Rotor) -> bool {
    let g = rotor.model.gravity;
    g[0].hypot(g[1]) > 0.0
}

/// The free DOFs of the journal and housing of model bearing `b` in
/// direction `k` (0: x, 1: y).
fn coordinate(rotor: &Rotor, b: usize, k: usize) -> (Option<usize>, Option<usize>) {
    let placed = &rotor.model.bearings[b];
    let journal = rotor.dofs.free(placed.node, [DOF_X, DOF_Y][k]);
    let housing = placed.pedestal.and_then(|p| rotor.dofs.pedestal(p, k));
    (journal, housing)
}

/// `Eᵀ u` of model bearing `b` in direction `k`.
fn relative(rotor: &Rotor, u: &[f64], b: usize, k: usize) -> f64 {
    let (j, h) = coordinate(rotor, b, k);
    j.map_or(0.0, |j| u[j]) - h.map_or(0.0, |h| u[h])
}

/// The bearing reactions of `rotor` at its offsets at spin `speed` (rad/s)
/// and their influence matrix ([module](self)).
pub fn alignment(
    rotor: &Rotor,
    speed: f64,
    options: &SolverOptions,
) -> Result<Alignment, AlignmentError> {
    let direction = load_direction(rotor);
    let model = &rotor.model;
    let solver = |source| AlignmentError::Solver { speed, source };
    let eq = line_equilibrium(rotor, speed, options, None).map_err(solver)?;
    let u = &eq.displacement;
    // The static stiffness of every element outside K, by model index.
    let mut stiffness: Vec<Option<Matrix2<f64>>> = vec![None; model.bearings.len()];
    let mut force: Vec<Option<[f64; 2]>> = vec![None; model.bearings.len()];
    for (index, eval) in &eq.bearings {
        stiffness[*index] = Some(static_stiffness(eval));
        force[*index] = Some([eval.force[0], eval.force[1]]);
    }
    let mut tangent = rotor.stiffness.clone();
    for (b, k) in stiffness.iter().enumerate() {
        let Some(k) = k else { continue };
        for a in 0..2 {
            for c in 0..2 {
                let (ja, ha) = coordinate(rotor, b, a);
                let (jc, hc) = coordinate(rotor, b, c);
                for (row, sr) in [(ja, 1.0), (ha, -1.0)] {
                    for (col, sc) in [(jc, 1.0), (hc, -1.0)] {
                        if let (Some(row), Some(col)) = (row, col) {
                            tangent.add(row, col, sr * sc * k[(a, c)]);
                        }
                    }
                }
            }
        }
    }
    let lu = tangent.lu().map_err(|e| {
        AlignmentError::Input(format!("the line's static stiffness is singular ({e})"))
    })?;
    let listed: Vec<usize> = (0..model.bearings.len())
        .filter(|&b| model.bearings[b].kind.is_bearing())
        .collect();
    let mut bearings = Vec::with_capacity(listed.len());
    let mut own = Vec::with_capacity(listed.len());
    for &b in &listed {
        let placed = &model.bearings[b];
        let (k, reaction) = match (&placed.kind, stiffness[b], force[b]) {
            (crate::bearing::BearingKind::Linear { stiffness: k, .. }, _, _) => {
                let k = Matrix2::new(k[0][0], k[0][1], k[1][0], k[1][1]);
                let q = [
                    relative(rotor, u, b, 0) - placed.offset[0],
                    relative(rotor, u, b, 1) - placed.offset[1],
                ];
                let f = -(k * nalgebra::Vector2::new(q[0], q[1]));
                (k, [f.x, f.y])
            }
            (_, Some(k), Some(f)) => (k, f),
            _ => {
                return Err(AlignmentError::Input(format!(
                    "bearing {} has no static stiffness at the equilibrium",
                    placed.name
                )));
            }
        };
        own.push(k);
        bearings.push(BearingReaction {
            bearing: b,
            name: placed.name.clone(),
            offset: placed.offset,
            reaction,
            load: reaction[0] * direction[0] + reaction[1] * direction[1],
            area: placed
                .kind
                .film_geometry()
                .map(|g| g.length * 2.0 * g.radius),
        });
    }
    let n = listed.len();
    let mut influence = DMatrix::zeros(2 * n, 2 * n);
    let mut du = vec![0.0; rotor.dof_count()];
    for (j, &bj) in listed.iter().enumerate() {
        for c in 0..2 {
            // du/do_j,c = K_t⁻¹ E_j K_j e_c.
            du.fill(0.0);
            for a in 0..2 {
                let (ja, ha) = coordinate(rotor, bj, a);
                let v = own[j][(a, c)];
                if let Some(i) = ja {
                    du[i] += v;
                }
                if let Some(i) = ha {
                    du[i] -= v;
                }
            }
            lu.solve_in_place(&mut du);
            for (i, &bi) in listed.iter().enumerate() {
                let mut moved = [relative(rotor, &du, bi, 0), relative(rotor, &du, bi, 1)];
                if i == j {
                    moved[c] -= 1.0;
                }
                for a in 0..2 {
                    influence[(2 * i + a, 2 * j + c)] =
                        -(own[i][(a, 0)] * moved[0] + own[i][(a, 1)] * moved[1]);
                }
            }
        }
    }
    Ok(Alignment {
        speed,
        direction,
        bearings,
        influence,
        equilibrium: eq,
    })
}

/// The loads of equal specific load `W/(L·D)` over the bearings of
/// `alignment` (`W` the total load they carry); equal loads `W/n` when a
/// bearing has no film area (linear and table bearings).
pub fn equal_specific_loads(alignment: &Alignment) -> Vec<f64> {
    let total: f64 = alignment.loads().iter().sum();
    let areas: Option<Vec<f64>> = alignment.bearings.iter().map(|b| b.area).collect();
    match areas {
        Some(areas) => {
            let sum: f64 = areas.iter().sum();
            areas.iter().map(|a| total * a / sum).collect()
        }
        None => {
            let n = alignment.bearings.len() as f64;
            vec![total / n; alignment.bearings.len()]
        }
    }
}

/// Offsets that give a target load sharing.
#[derive(Debug, Clone, PartialEq)]
pub struct TargetAlignment {
    /// The target loads (N), one per bearing of the alignment.
    pub target: Vec<f64>,
    /// The offsets found `(o_x, o_y)` (m), one per bearing: the model's
    /// offsets moved along the load direction.
    pub offsets: Vec<[f64; 2]>,
    /// The alignment at those offsets (its loads are the achieved ones).
    pub achieved: Alignment,
    /// Newton steps taken.
    pub iterations: usize,
    /// The part of the target no alignment reaches (N): the least-squares
    /// residual `|(I − S S⁺)(target − achieved)|`, zero for a reachable target.
    pub unreachable: f64,
}

/// Relative singular value below which a direction of the load influence
/// matrix is taken as null (the rigid lift and tilt of the line).
const NULL_DIRECTION: f64 = 1e-9;

/// The offsets, the model's moved along the load direction by the least-norm
/// change, that make the bearings of `rotor` carry `target` (N, one per
/// bearing in the order of [`alignment`]) at `speed`: Newton with the
/// pseudo-inverse of the load influence matrix, until the step changes the
/// reachable part of the loads by less than `tolerance` (N), at most
/// `max_iterations` steps. Linear bearings converge in one step.
pub fn offsets_for_loads(
    rotor: &Rotor,
    speed: f64,
    options: &SolverOptions,
    target: &[f64],
    tolerance: f64,
    max_iterations: usize,
) -> Result<TargetAlignment, AlignmentError> {
    let mut current = alignment(rotor, speed, options)?;
    let n = current.bearings.len();
    if target.len() != n {
        return Err(AlignmentError::Input(format!(
            "{} target loads given for {n} bearings",
            target.len()
        )));
    }
    if let Some(t) = target.iter().find(|t| !t.is_finite()) {
        return Err(AlignmentError::Input(format!(
            "target load {t} is not finite"
        )));
    }
    let d = current.direction;
    let mut model = rotor.model.clone();
    let mut iterations = 0;
    loop {
        let s = current.load_influence();
        let residual =
            DVector::from_iterator(n, target.iter().zip(current.loads()).map(|(t, l)| t - l));
        let pinv = s
            .clone()
            .pseudo_inverse(NULL_DIRECTION * s.amax())
            .map_err(|e| AlignmentError::Input(e.to_string()))?;
        let step = &pinv * &residual;
        let reachable = &s * &step;
        let unreachable = (&residual - &reachable).norm();
        if reachable.amax() <= tolerance || iterations >= max_iterations {
            if reachable.amax() > tolerance {
                return Err(AlignmentError::Input(format!(
                    "no alignment found after {iterations} steps: the loads still miss their reachable target by {:.3e} N",
                    reachable.amax()
                )));
            }
            return Ok(TargetAlignment {
                target: target.to_vec(),
                offsets: current.bearings.iter().map(|b| b.offset).collect(),
                achieved: current,
                iterations,
                unreachable,
            });
        }
        for (k, b) in current.bearings.iter().enumerate() {
            let o = &mut model.bearings[b.bearing].offset;
            o[0] += step[k] * d[0];
            o[1] += step[k] * d[1];
        }
        let moved = Rotor::new(model.clone()).map_err(|e| AlignmentError::Input(e.to_string()))?;
        current = alignment(&moved, speed, options)?;
        iterations += 1;
    }
}
