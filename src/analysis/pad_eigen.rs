//! Every eigenvalue of the rotor linearized with the pad tilts kept as
//! coordinates (issue 45), by a dense solve: the check on the modes that
//! [`super::whirl_modes`] iterates from the synchronous ones.
//!
//! The iteration finds the fixed points `det(λ²M + λD + K + Z_red(λ)) = 0`
//! near the synchronous modes; a root with no synchronous counterpart (a
//! slow backward whirl of a rotor held only by unpreloaded pads under
//! magnetic pull, which the synchronous condensation shows as a fast real
//! divergence) it cannot reach. Here the linearized rotor keeps the pad
//! coordinates `p` (massless, as in the transient, unless a pad has inertia:
//! then its rate is a state too, [`with_pad_inertia`]):
//!
//! `M ü + D u̇ + D_up ṗ + K u + K_up p = 0`, `D_pu u̇ + D_pp ṗ + K_pu u + K_pp p = 0`,
//!
//! (`D = C + ΩG` with the journal blocks of every bearing, the pad blocks
//! scattered through the journal–housing coordinates), written as
//! `ẋ = F x` over `x = (u, p, u̇)` (the pad rates through `D_pp⁻¹`) and
//! solved by a balanced dense Schur form: every eigenvalue, no starting
//! guess.

use nalgebra::linalg::Schur;
use nalgebra::linalg::balancing::balance_parlett_reinsch;
use nalgebra::{Complex, DMatrix};

use crate::rotor::elements::bearing_dofs;
use crate::rotor::{AssemblyError, JournalCoefficients, Rotor};
use crate::solver::Equilibrium;

type C64 = Complex<f64>;

/// Why the eigenvalues with pad coordinates could not be found.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum PadEigenError {
    /// The linear part could not be assembled.
    #[error("eigenvalues with the pad coordinates: {0}")]
    Assembly(#[from] AssemblyError),
    /// The mass matrix or a pad's damping block is singular (a pad without
    /// film).
    #[error(
        "eigenvalues with the pad coordinates: the mass or a pad's damping is singular (a pad without film)"
    )]
    Singular,
    /// The Schur iteration did not converge.
    #[error("eigenvalues with the pad coordinates: the Schur iteration did not converge")]
    NoConvergence,
}

/// Every eigenvalue (1/s) of the rotor linearized at `equilibrium`
/// (spin `speed`, rad/s) with the pad tilts of its bearings as coordinates.
pub fn eigenvalues_with_pads(
    rotor: &Rotor,
    equilibrium: &Equilibrium,
    speed: f64,
) -> Result<Vec<C64>, PadEigenError> {
    eigenvalues_of(&state_matrix_with_pads(rotor, equilibrium, speed)?)
}

/// Every eigenvalue of a state matrix `f` ([`state_matrix_with_pads`]).
pub fn eigenvalues_of(f: &DMatrix<f64>) -> Result<Vec<C64>, PadEigenError> {
    let mut f = f.clone();
    let s = f.nrows();
    balance_parlett_reinsch(&mut f);
    // A bounded Schur iteration (nalgebra's unbounded one may not return),
    // 30 sweeps an eigenvalue as LAPACK allows; its deflation test
    // `|h₍ᵢ₊₁,ᵢ₎| ≤ ε (|hᵢᵢ| + |h₍ᵢ₊₁,ᵢ₊₁₎|)` stalls at round-off on these
    // matrices (ε = 1e-14 never deflates the hydro unit's), so ε is
    // relaxed step by step from 1e-13.
    for eps in DEFLATION {
        if let Some(schur) = Schur::try_new(f.clone(), eps, 30 * s) {
            return Ok(schur.complex_eigenvalues().iter().copied().collect());
        }
    }
    Err(PadEigenError::NoConvergence)
}

/// Relative deflation thresholds of the Schur iteration, tried in turn.
const DEFLATION: [f64; 3] = [1e-13, 1e-12, 1e-11];

/// The state matrix `F` of `ẋ = F x`, `x = (u, p, u̇)`, of the rotor
/// linearized at `equilibrium` (spin `speed`, rad/s) with the pad tilts of
/// its bearings as coordinates (see the module docs).
pub fn state_matrix_with_pads(
    rotor: &Rotor,
    equilibrium: &Equilibrium,
    speed: f64,
) -> Result<DMatrix<f64>, PadEigenError> {
    state_matrix_with_pads_and(rotor, equilibrium, speed, &|_| {})
}

/// [`state_matrix_with_pads`] with `adjust` applied to the linear rotor
/// (its fluid films' coefficients zero) before the pads are added: the
/// stability studies' cross-coupled stiffness.
pub fn state_matrix_with_pads_and(
    rotor: &Rotor,
    equilibrium: &Equilibrium,
    speed: f64,
    adjust: &dyn Fn(&mut Rotor),
) -> Result<DMatrix<f64>, PadEigenError> {
    let zero: Vec<JournalCoefficients> = equilibrium
        .bearings
        .iter()
        .map(|(bearing, _)| JournalCoefficients {
            bearing: *bearing,
            stiffness: [[0.0; 2]; 2],
            damping: [[0.0; 2]; 2],
        })
        .collect();
    let mut base = rotor.with_bearing_coefficients(&zero)?;
    adjust(&mut base);
    let n = base.dof_count();
    let pads: usize = equilibrium.bearings.iter().map(|(_, e)| e.n() - 2).sum();
    let size = n + pads;
    // Second-order matrices over q = (u, p): the pad rows have no mass.
    let mut k = DMatrix::<f64>::zeros(size, size);
    let mut d = DMatrix::<f64>::zeros(size, size);
    k.view_mut((0, 0), (n, n))
        .copy_from(&base.stiffness.to_dense());
    d.view_mut((0, 0), (n, n))
        .copy_from(&(base.damping.to_dense() + base.gyroscopic.to_dense() * speed));
    let mut offset = n;
    for (bearing, eval) in &equilibrium.bearings {
        let dofs = bearing_dofs(&rotor.dofs, &rotor.model.bearings[*bearing]);
        // Each local coordinate as signed global ones: journal x, y minus
        // the housing's, then the bearing's pads.
        let local: Vec<Vec<(usize, f64)>> = (0..eval.n())
            .map(|a| {
                if a < 2 {
                    [(dofs[a], 1.0), (dofs.get(2 + a).copied().flatten(), -1.0)]
                        .into_iter()
                        .filter_map(|(g, s)| g.map(|g| (g, s)))
                        .collect()
                } else {
                    vec![(offset + a - 2, 1.0)]
                }
            })
            .collect();
        for (a, rows) in local.iter().enumerate() {
            for (b, cols) in local.iter().enumerate() {
                for &(i, si) in rows {
                    for &(j, sj) in cols {
                        k[(i, j)] += si * sj * eval.k(a, b);
                        d[(i, j)] += si * sj * eval.c(a, b);
                    }
                }
            }
        }
        offset += eval.n() - 2;
    }
    let pad_mass: Vec<f64> = equilibrium
        .bearings
        .iter()
        .flat_map(|(_, e)| e.mass.iter().copied())
        .collect();
    if pad_mass.iter().any(|&m| m != 0.0) {
        return with_pad_inertia(&k, &d, &base.mass.to_dense(), &pad_mass);
    }
    // x = (u, p, u̇), ẋ = F x: the pad rows give ṗ = −D_pp⁻¹(K_pu u + K_pp p
    // + D_pu u̇), the rotor rows M ü = −(K_uu u + K_up p + D_uu u̇ + D_up ṗ).
    let s = 2 * n + pads;
    let mut f = DMatrix::<f64>::zeros(s, s);
    f.view_mut((0, size), (n, n)).fill_with_identity();
    // Pad rows (K_pu, K_pp, D_pu) and rotor rows (K_uu, K_up, D_uu) over x.
    let rows_of = |row: usize, count: usize| {
        let mut g = DMatrix::<f64>::zeros(count, s);
        g.view_mut((0, 0), (count, size))
            .copy_from(&k.view((row, 0), (count, size)));
        g.view_mut((0, size), (count, n))
            .copy_from(&d.view((row, 0), (count, n)));
        g
    };
    let pad_rate = if pads > 0 {
        let Some(x) = d
            .view((n, n), (pads, pads))
            .into_owned()
            .lu()
            .solve(&rows_of(n, pads))
        else {
            return Err(PadEigenError::Singular);
        };
        -x
    } else {
        DMatrix::<f64>::zeros(0, s)
    };
    f.view_mut((n, 0), (pads, s)).copy_from(&pad_rate);
    let rotor_rows = rows_of(0, n) + d.view((0, n), (n, pads)) * &pad_rate;
    let Some(acceleration) = base.mass.to_dense().lu().solve(&rotor_rows) else {
        return Err(PadEigenError::Singular);
    };
    f.view_mut((size, 0), (n, s)).copy_from(&(-acceleration));
    if !f.iter().all(|x| x.is_finite()) {
        return Err(PadEigenError::Singular);
    }
    Ok(f)
}

/// The state matrix of `ẋ = F x` when some internal coordinates have mass
/// (`pad_mass`, kg, one per pad coordinate, [`crate::bearing::BearingEval::mass`]):
/// over `q = (u, p)` (stiffness `k`, damping `d`, rotor mass `m`) the
/// coordinates with mass `a` (the rotor's and the massive pads') keep their
/// rates as states, `x = (q, ȧ)`; the massless ones `b` follow from their
/// first-order rows, `ḃ = −D_bb⁻¹(K_b q + D_ba ȧ)`, and
/// `M_a ä = −(K_a q + D_aa ȧ + D_ab ḃ)`.
fn with_pad_inertia(
    k: &DMatrix<f64>,
    d: &DMatrix<f64>,
    m: &DMatrix<f64>,
    pad_mass: &[f64],
) -> Result<DMatrix<f64>, PadEigenError> {
    let n = m.nrows();
    let size = k.nrows();
    let massive: Vec<usize> = (0..n)
        .chain(
            (0..pad_mass.len())
                .filter(|&p| pad_mass[p] != 0.0)
                .map(|p| n + p),
        )
        .collect();
    let massless: Vec<usize> = (0..pad_mass.len())
        .filter(|&p| pad_mass[p] == 0.0)
        .map(|p| n + p)
        .collect();
    let na = massive.len();
    let s = size + na;
    // Rows of `set` over x: `[K_set | D_set,a]`.
    let rows = |set: &[usize]| {
        DMatrix::from_fn(set.len(), s, |r, c| {
            if c < size {
                k[(set[r], c)]
            } else {
                d[(set[r], massive[c - size])]
            }
        })
    };
    let mut f = DMatrix::<f64>::zeros(s, s);
    for (a, &i) in massive.iter().enumerate() {
        f[(i, size + a)] = 1.0;
    }
    let mut massive_rows = rows(&massive);
    if !massless.is_empty() {
        let dbb = DMatrix::from_fn(massless.len(), massless.len(), |r, c| {
            d[(massless[r], massless[c])]
        });
        let Some(x) = dbb.lu().solve(&rows(&massless)) else {
            return Err(PadEigenError::Singular);
        };
        let rate = -x;
        for (r, &i) in massless.iter().enumerate() {
            f.row_mut(i).copy_from(&rate.row(r));
        }
        let dab = DMatrix::from_fn(na, massless.len(), |r, c| d[(massive[r], massless[c])]);
        massive_rows += dab * rate;
    }
    let ma = DMatrix::from_fn(na, na, |r, c| {
        let (i, j) = (massive[r], massive[c]);
        if i < n && j < n {
            m[(i, j)]
        } else if i == j {
            pad_mass[i - n]
        } else {
            0.0
        }
    });
    let Some(acceleration) = ma.lu().solve(&massive_rows) else {
        return Err(PadEigenError::Singular);
    };
    f.view_mut((size, 0), (na, s)).copy_from(&(-acceleration));
    if !f.iter().all(|x| x.is_finite()) {
        return Err(PadEigenError::Singular);
    }
    Ok(f)
}

/// The rotor part `u` of the eigenvector of `f` ([`state_matrix_with_pads`],
/// `n` rotor DOFs) at its eigenvalue `lambda`, by two steps of inverse
/// iteration with the shift `lambda` nudged off it (1e-10 relative).
pub fn rotor_vector(f: &DMatrix<f64>, n: usize, lambda: C64) -> Option<Vec<C64>> {
    let s = f.nrows();
    let shift = lambda * (1.0 + 1e-10);
    let a = DMatrix::<C64>::from_fn(s, s, |i, j| {
        C64::new(f[(i, j)], 0.0) - if i == j { shift } else { C64::new(0.0, 0.0) }
    });
    let lu = a.lu();
    let mut x = nalgebra::DVector::<C64>::from_element(s, C64::new(1.0, 0.0));
    for _ in 0..2 {
        x = lu.solve(&x)?;
        let peak = x.iter().fold(0.0_f64, |m, z| m.max(z.norm()));
        if !(peak.is_finite() && peak > 0.0) {
            return None;
        }
        x /= C64::new(peak, 0.0);
    }
    Some(x.iter().take(n).copied().collect())
}
