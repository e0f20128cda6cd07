//! The lowest eigenpairs of a symmetric definite banded pencil `(K, M)` by
//! subspace iteration with a Sturm-sequence check (the fixed-interface modes
//! of a reduced rotor, [`crate::rotor::Rotor::reduced`]).

use nalgebra::{DMatrix, SymmetricEigen};

use super::{BandLu, BandMatrix, LinalgError, eigenvalues_below};

/// Relative change of the kept eigenvalues at which subspace iteration stops.
const EIGEN_TOL: f64 = 1e-12;
/// Subspace iterations allowed (each costs one banded solve per vector).
const MAX_SUBSPACE_ITERATIONS: usize = 200;

/// The `m` lowest eigenpairs of `K φ = ω² M φ` (`K`, `M` symmetric positive
/// definite), by subspace iteration with Rayleigh–Ritz (Bathe, *Finite Element
/// Procedures*, §11.6): a block of `p = max(2m, m + 8)` vectors (all DOFs when
/// fewer, which makes it one exact dense solve), `Y = K⁻¹ M X`, then the
/// `p × p` pencil `(Yᵀ M X, Yᵀ M Y)` (`K Y = M X`, so `K` itself, badly
/// conditioned, is never multiplied). Vectors come M-orthonormal.
///
/// Converged Ritz values need not be the *lowest* eigenvalues: a mode the
/// start block (nearly) misses, such as the second plane of a degenerate pair,
/// may emerge only long after the others stopped changing. So every result is
/// checked by a Sturm sequence count ([`eigenvalues_below`]) at
/// `σ = (1 + CLUSTER) ω_m²`: when the pencil has more eigenvalues below `σ`
/// than converged Ritz values, the iteration restarts from its Ritz vectors
/// and pseudo-random vectors in a block enlarged by twice the missing count
/// plus 8 (bounded: at `p = n` the solution is exact).
pub fn lowest_eigenpairs(
    k: &BandMatrix<f64>,
    mass: &BandMatrix<f64>,
    lu: &BandLu<f64>,
    m: usize,
) -> Result<(Vec<f64>, DMatrix<f64>), String> {
    let n = k.n();
    if m == 0 {
        return Ok((Vec::new(), DMatrix::zeros(n, 0)));
    }
    let mut p = (2 * m).max(m + 8).min(n);
    let mut x = start_block(k, mass, p);
    let mut random = PseudoRandom(0x2545_f491_4f6c_dd1d);
    loop {
        let (values, ritz) = subspace_iteration(mass, lu, m, x)?;
        if p == n {
            return Ok((values[..m].to_vec(), ritz.columns(0, m).into_owned()));
        }
        let (below, found) = sturm_check(k, mass, &values, values[m - 1] * (1.0 + CLUSTER))?;
        if below <= found {
            return Ok((values[..m].to_vec(), ritz.columns(0, m).into_owned()));
        }
        let old = p;
        p = (p + 2 * (below - found) + 8).min(n);
        x = DMatrix::zeros(n, p);
        x.columns_mut(0, old).copy_from(&ritz);
        for c in old..p {
            for j in 0..n {
                x[(j, c)] = random.next();
            }
        }
    }
}

/// Relative width of a cluster of eigenvalues kept together: converged
/// together, and counted together by the Sturm check.
const CLUSTER: f64 = 1e-6;

/// Bathe's start block: unit vectors on the DOFs of largest `M_jj / K_jj`,
/// plus a spread vector so no mode starts orthogonal to the block (the
/// identity when `p` is the order).
fn start_block(k: &BandMatrix<f64>, mass: &BandMatrix<f64>, p: usize) -> DMatrix<f64> {
    let n = k.n();
    let mut x = DMatrix::zeros(n, p);
    if p == n {
        x.fill_with_identity();
        return x;
    }
    let mut ratio: Vec<(f64, usize)> = (0..n)
        .map(|j| (mass.get(j, j) / k.get(j, j).abs().max(f64::MIN_POSITIVE), j))
        .collect();
    ratio.sort_by(|a, b| b.0.total_cmp(&a.0));
    for c in 1..p {
        x[(ratio[c - 1].1, c)] = 1.0;
    }
    for j in 0..n {
        x[(j, 0)] = 1.0 + (j % 7) as f64 * 0.1;
    }
    x
}

/// Subspace iteration from the block `x` until the `m` lowest Ritz values and
/// those within [`CLUSTER`] of the highest of them change by less than
/// [`EIGEN_TOL`], or stop improving below 1e-9 (their round-off floor): all
/// Ritz values (ascending) and their vectors.
fn subspace_iteration(
    mass: &BandMatrix<f64>,
    lu: &BandLu<f64>,
    m: usize,
    mut x: DMatrix<f64>,
) -> Result<(Vec<f64>, DMatrix<f64>), String> {
    let (n, p) = x.shape();
    let mut previous: Vec<f64> = vec![f64::INFINITY; p];
    let mut last_change = f64::INFINITY;
    let (mut y, mut mx) = (DMatrix::zeros(n, p), DMatrix::zeros(n, p));
    let mut work = vec![0.0; n];
    for _ in 0..MAX_SUBSPACE_ITERATIONS {
        for c in 0..p {
            mass.mul_vec(x.column(c).as_slice(), &mut work);
            mx.column_mut(c).copy_from_slice(&work);
            lu.solve_in_place(&mut work);
            y.column_mut(c).copy_from_slice(&work);
        }
        let kr = y.transpose() * &mx;
        let mut my = DMatrix::zeros(n, p);
        for c in 0..p {
            mass.mul_vec(y.column(c).as_slice(), &mut work);
            my.column_mut(c).copy_from_slice(&work);
        }
        let mr = y.transpose() * my;
        let (values, vectors) = rayleigh_ritz(kr, mr)?;
        x = &y * vectors;
        let edge = values[m - 1] * (1.0 + CLUSTER);
        let wanted = values.iter().take_while(|&&v| v < edge).count().max(m);
        let change = values[..wanted]
            .iter()
            .zip(&previous)
            .map(|(v, p)| ((v - p) / v).abs())
            .fold(0.0, f64::max);
        previous = values;
        if p == n || change <= EIGEN_TOL || (change <= 1e-9 && change >= last_change) {
            return Ok((previous, x));
        }
        last_change = change;
    }
    Err(format!(
        "the lowest eigenpairs did not converge in {MAX_SUBSPACE_ITERATIONS} subspace iterations"
    ))
}

/// Eigenvalues of `(k, mass)` below `shift` by their Sturm count, and Ritz
/// `values` below it; `shift` moves up by a little when it is an eigenvalue to
/// round-off (a zero pivot).
fn sturm_check(
    k: &BandMatrix<f64>,
    mass: &BandMatrix<f64>,
    values: &[f64],
    shift: f64,
) -> Result<(usize, usize), String> {
    let mut sigma = shift;
    for _ in 0..8 {
        match eigenvalues_below(k, mass, sigma) {
            Ok(below) => return Ok((below, values.iter().filter(|&&v| v < sigma).count())),
            Err(LinalgError::Singular { .. }) => sigma *= 1.0 + 1e-7,
            Err(e) => return Err(format!("Sturm check of the fixed-interface modes: {e}")),
        }
    }
    Err(format!(
        "Sturm check of the fixed-interface modes: every shift near {shift} is an eigenvalue"
    ))
}

/// Deterministic uniform numbers in [−1, 1) (xorshift64*, Vigna 2016) for
/// restart vectors: no structure a mode could be orthogonal to.
struct PseudoRandom(u64);

impl PseudoRandom {
    fn next(&mut self) -> f64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        let bits = self.0.wrapping_mul(0x2545_f491_4f6c_dd1d) >> 11;
        bits as f64 / (1u64 << 52) as f64 - 1.0
    }
}

/// Eigenpairs of the pencil `(kr, mr)` (symmetrized), ascending, vectors
/// `mr`-orthonormal.
fn rayleigh_ritz(kr: DMatrix<f64>, mr: DMatrix<f64>) -> Result<(Vec<f64>, DMatrix<f64>), String> {
    let p = kr.nrows();
    let kr = (&kr + kr.transpose()) * 0.5;
    let mr = (&mr + mr.transpose()) * 0.5;
    let chol = mr
        .cholesky()
        .ok_or("the interior mass matrix is not positive definite")?;
    let l = chol.l();
    let linv_k = l
        .solve_lower_triangular(&kr)
        .ok_or("singular Rayleigh–Ritz mass")?;
    let c = l
        .solve_lower_triangular(&linv_k.transpose())
        .ok_or("singular Rayleigh–Ritz mass")?;
    let eig = SymmetricEigen::new((&c + c.transpose()) * 0.5);
    let mut order: Vec<usize> = (0..p).collect();
    order.sort_by(|&a, &b| eig.eigenvalues[a].total_cmp(&eig.eigenvalues[b]));
    let values: Vec<f64> = order.iter().map(|&j| eig.eigenvalues[j]).collect();
    let sorted = DMatrix::from_fn(p, p, |i, j| eig.eigenvectors[(i, order[j])]);
    let vectors = l
        .transpose()
        .solve_upper_triangular(&sorted)
        .ok_or("singular Rayleigh–Ritz mass")?;
    Ok((values, vectors))
}
