//! Arnoldi eigensolver for a few largest-modulus eigenvalues of a complex,
//! generally non-Hermitian linear operator (use it on `(A - σB)⁻¹B` for
//! shift-invert), and of a real one ([`largest_eigenpairs_real`]: a real shift
//! of a real pencil), whose Krylov basis is real: a quarter of the flops and
//! half the memory traffic of the complex process, with the Ritz values of the
//! real Hessenberg matrix in conjugate pairs of which one member is returned.
//!
//! Arnoldi process with full re-orthogonalization by classical Gram–Schmidt
//! applied twice with the Daniel–Gragg–Kaufman–Stewart (DGKS) criterion,
//! Ritz pairs from the complex Schur form of the projected Hessenberg matrix
//! (Saad, *Numerical Methods for Large Eigenvalue Problems*, 2nd ed., ch. 6),
//! the factorization grown in place (convergence checked every 8 steps) up to
//! a dimension that doubles at each explicit restart. An invariant subspace
//! ("lucky breakdown") is continued with a fresh vector orthogonal to the
//! basis, as in ARPACK's `getv0`.

use nalgebra::{Complex, DMatrix, Schur};

use super::LinalgError;

type C = Complex<f64>;

const ZERO: C = Complex::new(0.0, 0.0);

/// A linear operator `y = A x` on `C^n`, given as a closure `(x, y)`.
pub type LinearOperator<'a> = dyn FnMut(&[C], &mut [C]) -> Result<(), LinalgError> + 'a;

/// A real linear operator `y = A x` on `R^n`, given as a closure `(x, y)`.
pub type RealOperator<'a> = dyn FnMut(&[f64], &mut [f64]) -> Result<(), LinalgError> + 'a;

/// A linear operator on `T^n` (either field).
type Operator<'a, T> = dyn FnMut(&[T], &mut [T]) -> Result<(), LinalgError> + 'a;

/// Scalars of a Krylov basis: `f64` for real operators, `Complex<f64>` otherwise.
trait KrylovScalar: super::Scalar {
    /// A pseudo-random value (real and imaginary parts uniform on [−1, 1)).
    fn draw(rng: &mut Lcg) -> Self;
    /// `c · self`.
    fn times(self, c: C) -> C;
    /// `self` as a complex number.
    fn complex(self) -> C;
    /// The value of `c` in this field (the real part for `f64`).
    fn from_complex(c: C) -> Self;
}

impl KrylovScalar for f64 {
    fn draw(rng: &mut Lcg) -> Self {
        rng.uniform()
    }
    fn times(self, c: C) -> C {
        c * self
    }
    fn complex(self) -> C {
        Complex::new(self, 0.0)
    }
    fn from_complex(c: C) -> Self {
        c.re
    }
}

impl KrylovScalar for C {
    fn draw(rng: &mut Lcg) -> Self {
        let re = rng.uniform();
        Complex::new(re, rng.uniform())
    }
    fn times(self, c: C) -> C {
        c * self
    }
    fn complex(self) -> C {
        self
    }
    fn from_complex(c: C) -> Self {
        c
    }
}

/// Options of [`largest_eigenpairs`].
#[derive(Debug, Clone, PartialEq)]
pub struct ArnoldiOptions {
    /// Relative tolerance on the Ritz residual `‖A u − θ u‖ / |θ|`.
    pub tol: f64,
    /// Upper bound on the Krylov dimension.
    pub max_krylov: usize,
    /// Maximum number of explicit restarts.
    pub max_restarts: usize,
    /// Start vector (length `n`); a fixed pseudo-random vector if `None`.
    pub start: Option<Vec<C>>,
}

impl Default for ArnoldiOptions {
    fn default() -> Self {
        Self {
            tol: 1e-10,
            max_krylov: 600,
            max_restarts: 25,
            start: None,
        }
    }
}

/// Eigenvalue, unit-norm eigenvector and true relative residual
/// `‖A v − value·v‖ / |value|` (absolute if `value == 0`).
#[derive(Debug, Clone, PartialEq)]
pub struct EigenPair {
    pub value: C,
    pub vector: Vec<C>,
    pub residual: f64,
}

/// The `nev` eigenpairs of the `n × n` operator `apply` (`y = A x`) that are
/// largest in modulus, sorted by decreasing modulus.
///
/// Eigenvectors are scaled to unit 2-norm with their largest component real
/// and positive. Results are reproducible bit for bit for a given operator.
pub fn largest_eigenpairs(
    n: usize,
    nev: usize,
    apply: &mut LinearOperator<'_>,
    opts: &ArnoldiOptions,
) -> Result<Vec<EigenPair>, LinalgError> {
    if nev == 0 {
        return Ok(Vec::new());
    }
    check_arguments(n, nev, opts)?;
    let start = match &opts.start {
        Some(s) => checked_start(s, n)?,
        None => Vec::new(),
    };
    let (ritz, vectors) = converged_ritz(n, nev, apply, opts, start, |_| true)?;
    finish(ritz, vectors, opts.tol, Some(apply))
}

/// [`largest_eigenpairs`] of a real operator, with a real Krylov basis: of the
/// `nev` eigenvalues largest in modulus, the real ones and the members of the
/// conjugate pairs with non-negative imaginary part (within `tol` of the
/// modulus), sorted by decreasing modulus; the other members are their complex
/// conjugates, with conjugate eigenvectors. A start vector in `opts` gives its
/// real part. Residuals are the Ritz estimates `|h_{k+1,k}| |y_k| / |θ|` (the
/// true residual in exact arithmetic; computing it would cost two more
/// operator applications per pair).
pub fn largest_eigenpairs_real(
    n: usize,
    nev: usize,
    apply: &mut RealOperator<'_>,
    opts: &ArnoldiOptions,
) -> Result<Vec<EigenPair>, LinalgError> {
    if nev == 0 {
        return Ok(Vec::new());
    }
    check_arguments(n, nev, opts)?;
    let start: Vec<f64> = match &opts.start {
        Some(s) => checked_start(s, n)?.iter().map(|z| z.re).collect(),
        None => Vec::new(),
    };
    let tol = opts.tol;
    let (ritz, vectors) =
        converged_ritz(n, nev, apply, opts, start, |v: &C| v.im >= -tol * v.norm())?;
    finish(ritz, vectors, tol, None)
}

/// Checks the arguments shared by both entry points (`nev > 0`).
fn check_arguments(n: usize, nev: usize, opts: &ArnoldiOptions) -> Result<(), LinalgError> {
    if nev > n {
        return Err(LinalgError::InvalidArgument("nev exceeds the dimension"));
    }
    if !(opts.tol.is_finite() && opts.tol > 0.0) {
        return Err(LinalgError::InvalidArgument("tol must be positive"));
    }
    if n.min(opts.max_krylov) < nev {
        return Err(LinalgError::InvalidArgument(
            "max_krylov is smaller than nev",
        ));
    }
    Ok(())
}

/// The given start vector, checked for length (panics) and finiteness.
fn checked_start(s: &[C], n: usize) -> Result<Vec<C>, LinalgError> {
    assert!(
        s.len() == n,
        "dimension mismatch: start vector has length {}, expected {n}",
        s.len()
    );
    if !s.iter().all(|z| z.re.is_finite() && z.im.is_finite()) {
        return Err(LinalgError::NotFinite);
    }
    Ok(s.to_vec())
}

/// Arnoldi until the `nev` Ritz values largest in
/// modulus have converged; returns the `nev` largest for which `keep` holds,
/// with their (not yet normalized) Ritz vectors.
///
/// Each round grows one Arnoldi factorization in place, checking convergence
/// at dimensions `m₀, m₀ + 8, …` up to the round's dimension `m`: the basis is
/// extended, never rebuilt, so a round that needs all of `m` computes the same
/// factorization as building `m` steps at once, and a round that converges
/// earlier stops with fewer steps (the orthogonalization costs `O(n m²)`).
/// Rounds are explicitly restarted from the sum of the wanted Ritz vectors
/// with a doubled `m`.
fn converged_ritz<T: KrylovScalar>(
    n: usize,
    nev: usize,
    apply: &mut Operator<'_, T>,
    opts: &ArnoldiOptions,
    mut start: Vec<T>,
    keep: impl Fn(&C) -> bool,
) -> Result<(Vec<Ritz>, Vec<Vec<C>>), LinalgError> {
    let cap = n.min(opts.max_krylov);
    let mut m = cap.min((2 * nev + 20).max(40));
    let wanted = nev;
    let mut rng = Lcg::new();
    if norm(&start) == 0.0 {
        start.resize(n, T::zero());
        rng.fill(&mut start);
    }

    let mut basis = Vec::new();
    let mut h = DMatrix::from_element(0, 0, T::zero());
    let mut w = vec![T::zero(); n];
    let mut converged = 0;
    for _ in 0..=opts.max_restarts {
        let s = norm(&start);
        basis.clear();
        basis.extend(start.iter().map(|&x| x.unscale(s)));
        let mut size = m.min((2 * wanted + 12).max(nev + 4)).max(nev);
        let (mut from, mut beta) = (0, 0.0);
        loop {
            let k;
            (k, beta) = build_krylov(
                size, from, beta, apply, &mut basis, &mut h, &mut w, &mut rng,
            )?;
            let ritz = wanted_ritz(&h.view((0, 0), (k, k)).map(T::complex), beta, nev)?;
            if ritz.len() < nev {
                return Err(LinalgError::NotConverged {
                    converged: 0,
                    wanted: nev,
                });
            }
            converged = ritz
                .iter()
                .take(wanted)
                .filter(|r| r.estimate <= opts.tol * r.value.norm())
                .count();
            let last = converged == wanted || k < size || size == m;
            if !last {
                (from, size) = (size, (size + 8).min(m));
                continue;
            }
            let ritz: Vec<Ritz> = ritz.into_iter().filter(|r| keep(&r.value)).collect();
            let vectors: Vec<Vec<C>> = ritz.iter().map(|r| combine(&basis, n, k, &r.y)).collect();
            if converged == wanted {
                return Ok((ritz, vectors));
            }
            start.fill(T::zero());
            for u in &vectors {
                for (s, &x) in start.iter_mut().zip(u) {
                    *s += T::from_complex(x);
                }
            }
            if norm(&start) < 1e-8 {
                rng.fill(&mut start);
            }
            break;
        }
        m = (2 * m).min(cap);
    }
    Err(LinalgError::NotConverged { converged, wanted })
}

/// Tiny deterministic 64-bit LCG (Knuth's MMIX constants) for start vectors.
struct Lcg(u64);

impl Lcg {
    fn new() -> Self {
        Self(0x853c_49e6_748f_ea9b)
    }

    fn uniform(&mut self) -> f64 {
        self.0 = self
            .0
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        (self.0 >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
    }

    fn fill<T: KrylovScalar>(&mut self, v: &mut [T]) {
        for z in v {
            *z = T::draw(self);
        }
    }
}

/// `aᴴ b`, summed in eight interleaved partial sums (independent chains that
/// the compiler can keep in vector registers).
fn dot<T: super::Scalar>(a: &[T], b: &[T]) -> T {
    let mut acc = [T::zero(); 8];
    let (ca, cb) = (a.chunks_exact(8), b.chunks_exact(8));
    let mut s = ca
        .remainder()
        .iter()
        .zip(cb.remainder())
        .fold(T::zero(), |s, (x, y)| s + x.conjugate() * *y);
    for (x, y) in ca.zip(cb) {
        for k in 0..8 {
            acc[k] += x[k].conjugate() * y[k];
        }
    }
    for a in acc {
        s += a;
    }
    s
}

fn norm<T: super::Scalar>(a: &[T]) -> f64 {
    a.iter().map(|z| z.modulus_squared()).sum::<f64>().sqrt()
}

fn all_finite<T: super::Scalar>(a: &[T]) -> bool {
    a.iter().all(|z| z.is_finite())
}

/// Orthogonalizes `w` against the `count` orthonormal columns of `basis`
/// (classical Gram–Schmidt, twice, a third pass if the DGKS test
/// `‖w_new‖ > 0.717 ‖w_old‖` fails; CGS2 keeps the basis orthogonal to working
/// precision as MGS2 does, L. Giraud et al., Numer. Math. 101, 2005). Each pass
/// forms all projections `h = Vᴴ w` from the same `w`, then `w −= V h`, four
/// columns per sweep over `w` (a fourth of the loads of one column at a
/// time). Accumulates the projection coefficients in `coeffs` and returns
/// `‖w‖`, or `None` when `w` lies numerically in the span.
fn orthogonalize<T: super::Scalar>(
    basis: &[T],
    count: usize,
    w: &mut [T],
    coeffs: &mut [T],
) -> Option<f64> {
    let n = w.len();
    coeffs[..count].fill(T::zero());
    let mut h = vec![T::zero(); count];
    let mut prev = norm(w);
    for pass in 0..3 {
        if prev == 0.0 {
            return None;
        }
        project(&basis[..count * n], w, &mut h);
        subtract(&basis[..count * n], &h, w);
        for (c, &p) in coeffs.iter_mut().zip(&h) {
            *c += p;
        }
        let now = norm(w);
        if pass > 0 && now > 0.717 * prev {
            return Some(now);
        }
        prev = now;
    }
    None
}

/// `h = Vᴴ w` for the columns of `basis` (length `w.len()` each), four
/// columns per sweep over `w`, each product summed in four interleaved
/// partial sums.
fn project<T: super::Scalar>(basis: &[T], w: &[T], h: &mut [T]) {
    let n = w.len();
    for (block, hb) in basis.chunks(4 * n).zip(h.chunks_mut(4)) {
        if hb.len() < 4 {
            for (v, hi) in block.chunks_exact(n).zip(hb.iter_mut()) {
                *hi = dot(v, w);
            }
            continue;
        }
        let cols: [&[T]; 4] = std::array::from_fn(|c| &block[c * n..(c + 1) * n]);
        let mut acc = [[T::zero(); 4]; 4];
        let chunks = n / 4 * 4;
        for k in (0..chunks).step_by(4) {
            let wk = &w[k..k + 4];
            for (a, v) in acc.iter_mut().zip(&cols) {
                let vk = &v[k..k + 4];
                for l in 0..4 {
                    a[l] += vk[l].conjugate() * wk[l];
                }
            }
        }
        for ((hi, a), v) in hb.iter_mut().zip(&acc).zip(&cols) {
            let tail = v[chunks..]
                .iter()
                .zip(&w[chunks..])
                .fold(T::zero(), |s, (x, y)| s + x.conjugate() * *y);
            *hi = (a[0] + a[1]) + (a[2] + a[3]) + tail;
        }
    }
}

/// `w −= V h` for the columns of `basis`, four columns per sweep over `w`.
fn subtract<T: super::Scalar>(basis: &[T], h: &[T], w: &mut [T]) {
    let n = w.len();
    for (block, hb) in basis.chunks(4 * n).zip(h.chunks(4)) {
        if let [h0, h1, h2, h3] = *hb {
            let (v0, rest) = block.split_at(n);
            let (v1, rest) = rest.split_at(n);
            let (v2, v3) = rest.split_at(n);
            for k in 0..n {
                w[k] -= (h0 * v0[k] + h1 * v1[k]) + (h2 * v2[k] + h3 * v3[k]);
            }
        } else {
            for (v, &p) in block.chunks_exact(n).zip(hb) {
                for (wk, &vk) in w.iter_mut().zip(v) {
                    *wk -= p * vk;
                }
            }
        }
    }
}

/// Arnoldi steps `from..m`: extends the factorization whose first `from + 1`
/// basis columns (of length `n`, the first one the normalized start vector)
/// are in `basis` and whose `from × from` Hessenberg matrix is in `h`, with
/// residual norm `beta` (ignored when `from == 0`). On return `basis` holds
/// `k + 1` columns and `h` the `k × k` Hessenberg matrix in its top-left
/// corner (`k = m` unless the whole space is exhausted); returns `k` and the
/// norm of the final residual `h_{k+1,k}`.
#[allow(clippy::too_many_arguments)]
fn build_krylov<T: KrylovScalar>(
    m: usize,
    from: usize,
    beta: f64,
    apply: &mut Operator<'_, T>,
    basis: &mut Vec<T>,
    h: &mut DMatrix<T>,
    w: &mut [T],
    rng: &mut Lcg,
) -> Result<(usize, f64), LinalgError> {
    let n = w.len();
    basis.resize(n * (m + 1), T::zero());
    if from == 0 {
        *h = DMatrix::from_element(m, m, T::zero());
    } else {
        h.resize_mut(m, m, T::zero());
        h[(from, from - 1)] = T::from_real(beta);
    }
    let mut coeffs = vec![T::zero(); m + 1];
    for j in from..m {
        let (done, next) = basis.split_at_mut((j + 1) * n);
        apply(&done[j * n..], w)?;
        if !all_finite(w) {
            return Err(LinalgError::NotFinite);
        }
        let beta = orthogonalize(done, j + 1, w, &mut coeffs);
        for (i, &c) in coeffs[..=j].iter().enumerate() {
            h[(i, j)] = c;
        }
        let beta = match beta {
            Some(b) => b,
            None if j + 1 == m => 0.0,
            None => {
                // Invariant subspace: continue with a random vector orthogonal to it.
                let mut fresh = None;
                for _ in 0..3 {
                    rng.fill(w);
                    fresh = orthogonalize(done, j + 1, w, &mut coeffs);
                    if fresh.is_some() {
                        break;
                    }
                }
                match fresh {
                    Some(b) => {
                        for (x, &y) in next[..n].iter_mut().zip(w.iter()) {
                            *x = y.unscale(b);
                        }
                        continue;
                    }
                    None => return Ok((j + 1, 0.0)),
                }
            }
        };
        if j + 1 < m {
            h[(j + 1, j)] = T::from_real(beta);
        }
        if beta == 0.0 {
            return Ok((m, 0.0));
        }
        for (x, &y) in next[..n].iter_mut().zip(w.iter()) {
            *x = y.unscale(beta);
        }
        if j + 1 == m {
            return Ok((m, beta));
        }
    }
    Ok((m, 0.0))
}

/// A wanted Ritz pair in coordinates of the Krylov basis.
struct Ritz {
    value: C,
    /// Unit-norm eigenvector of `H`.
    y: Vec<C>,
    /// Residual estimate `|h_{k+1,k}| |y_k|`.
    estimate: f64,
}

/// Complex Schur form `H = Q T Q^H` via nalgebra, verified; on failure retried
/// after a pseudo-random Householder similarity `W H W`.
fn schur(h: &DMatrix<C>) -> Result<(DMatrix<C>, DMatrix<C>), LinalgError> {
    let k = h.nrows();
    let hnorm = h.norm();
    let max_iter = 100 * k.max(10);
    let accept = |q: &DMatrix<C>, t: &DMatrix<C>| -> bool {
        if !(all_finite(q.as_slice()) && all_finite(t.as_slice())) {
            return false;
        }
        let sub = (1..k).map(|i| t[(i, i - 1)].norm()).fold(0.0, f64::max);
        let res = (h * q - q * t).norm();
        let tol = 1e3 * f64::EPSILON * (k as f64) * hnorm.max(f64::MIN_POSITIVE);
        sub <= tol && res <= tol
    };
    if let Some(s) = Schur::try_new(h.clone(), f64::EPSILON, max_iter) {
        let (q, t) = s.unpack();
        if accept(&q, &t) {
            return Ok((q, t));
        }
    }
    let mut rng = Lcg::new();
    for _ in 0..3 {
        let mut v = vec![ZERO; k];
        rng.fill(&mut v);
        let vn = norm(&v);
        let v = nalgebra::DVector::from_iterator(k, v.into_iter().map(|z| z / vn));
        let refl = DMatrix::identity(k, k) - (&v * v.adjoint()) * Complex::new(2.0, 0.0);
        let rotated = &refl * h * &refl;
        if let Some(s) = Schur::try_new(rotated, f64::EPSILON, max_iter) {
            let (q, t) = s.unpack();
            let q = &refl * q;
            if accept(&q, &t) {
                return Ok((q, t));
            }
        }
    }
    Err(LinalgError::DenseEigenFailed)
}

/// Eigenvector of the upper-triangular `t` for eigenvalue `t[p, p]` by
/// back-substitution (LAPACK `ztrevc`: tiny divisors are perturbed to `smin`).
fn triangular_eigenvector(t: &DMatrix<C>, p: usize, smin: f64) -> Vec<C> {
    let mut x = vec![ZERO; t.nrows()];
    x[p] = Complex::new(1.0, 0.0);
    let lambda = t[(p, p)];
    for i in (0..p).rev() {
        let s = (i + 1..=p).fold(ZERO, |s, l| s + t[(i, l)] * x[l]);
        let d = t[(i, i)] - lambda;
        let dn = d.norm();
        x[i] = if dn < smin {
            -s.unscale(smin)
        } else {
            -(s * d.conj().unscale(dn)).unscale(dn)
        };
        let xi = x[i].norm();
        if xi > 1e150 {
            for z in &mut x[i..=p] {
                *z /= xi;
            }
        }
    }
    x
}

/// The `nev` Ritz pairs of largest modulus of the `k × k` Hessenberg `h`.
fn wanted_ritz(h: &DMatrix<C>, beta: f64, nev: usize) -> Result<Vec<Ritz>, LinalgError> {
    if !all_finite(h.as_slice()) {
        return Err(LinalgError::NotFinite);
    }
    let k = h.nrows();
    let (q, t) = schur(h)?;
    let mut order: Vec<usize> = (0..k).collect();
    order.sort_by(|&a, &b| {
        let (za, zb) = (t[(a, a)], t[(b, b)]);
        zb.norm()
            .total_cmp(&za.norm())
            .then(zb.im.total_cmp(&za.im))
            .then(zb.re.total_cmp(&za.re))
    });
    let smin = (f64::EPSILON * t.norm()).max(f64::MIN_POSITIVE * k as f64 / f64::EPSILON);
    let ritz = order
        .into_iter()
        .take(nev)
        .map(|p| {
            let x = nalgebra::DVector::from_vec(triangular_eigenvector(&t, p, smin));
            let y = &q * x;
            let y = &y / Complex::new(y.norm(), 0.0);
            Ritz {
                value: t[(p, p)],
                estimate: beta * y[k - 1].norm(),
                y: y.as_slice().to_vec(),
            }
        })
        .collect();
    Ok(ritz)
}

/// `u = V y` for the first `k` basis columns.
fn combine<T: KrylovScalar>(basis: &[T], n: usize, k: usize, y: &[C]) -> Vec<C> {
    let mut u = vec![ZERO; n];
    for (i, &c) in y.iter().enumerate().take(k) {
        for (uk, &vk) in u.iter_mut().zip(&basis[i * n..(i + 1) * n]) {
            *uk += vk.times(c);
        }
    }
    u
}

/// Normalizes the converged vectors and computes their true residuals with
/// `apply`, or without it gives the Ritz estimates `|h_{k+1,k}| |y_k| / |θ|`.
///
/// Vectors of Ritz values equal to within `tol` (a multiple eigenvalue) are
/// orthonormalized among themselves, so that they form a well-conditioned basis
/// of the eigenspace.
fn finish(
    ritz: Vec<Ritz>,
    vectors: Vec<Vec<C>>,
    tol: f64,
    mut apply: Option<&mut LinearOperator<'_>>,
) -> Result<Vec<EigenPair>, LinalgError> {
    let mut w = vec![ZERO; vectors.first().map_or(0, Vec::len)];
    let mut out: Vec<EigenPair> = Vec::with_capacity(ritz.len());
    for (r, mut u) in ritz.into_iter().zip(vectors) {
        let un = norm(&u);
        for z in &mut u {
            *z = z.unscale(un);
        }
        let mut projected = u.clone();
        for _ in 0..2 {
            for prev in &out {
                let scale = r.value.norm().max(prev.value.norm());
                if (r.value - prev.value).norm() <= tol * scale {
                    let p = dot(&prev.vector, &projected);
                    for (x, &v) in projected.iter_mut().zip(&prev.vector) {
                        *x -= p * v;
                    }
                }
            }
        }
        if norm(&projected) >= 0.1 {
            u = projected;
        }
        let big = u
            .iter()
            .copied()
            .fold(ZERO, |b, z| if z.norm_sqr() > b.norm_sqr() { z } else { b });
        let scale = big.conj() / (big.norm() * norm(&u));
        for z in &mut u {
            *z *= scale;
        }
        let res = match apply.as_mut() {
            Some(apply) => {
                apply(&u, &mut w)?;
                w.iter()
                    .zip(&u)
                    .map(|(&a, &b)| (a - r.value * b).norm_sqr())
                    .sum::<f64>()
                    .sqrt()
            }
            None => r.estimate,
        };
        let mu = r.value.norm();
        out.push(EigenPair {
            value: r.value,
            vector: u,
            residual: if mu > 0.0 { res / mu } else { res },
        });
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::linalg::band::{BandMatrix, map_to_complex};

    fn c(re: f64, im: f64) -> C {
        Complex::new(re, im)
    }

    /// Dense operator `y = A x`.
    fn dense_apply(a: &DMatrix<C>) -> impl FnMut(&[C], &mut [C]) -> Result<(), LinalgError> + '_ {
        move |x: &[C], y: &mut [C]| {
            for (i, yi) in y.iter_mut().enumerate() {
                *yi = x
                    .iter()
                    .enumerate()
                    .fold(ZERO, |s, (j, &xj)| s + a[(i, j)] * xj);
            }
            Ok(())
        }
    }

    fn dense_eigenvalues(a: &DMatrix<C>) -> Vec<C> {
        let (_, t) = Schur::try_new(a.clone(), f64::EPSILON, 10_000)
            .expect("dense Schur")
            .unpack();
        (0..a.nrows()).map(|i| t[(i, i)]).collect()
    }

    /// Every found value is matched to a distinct reference value within `tol * scale`.
    fn assert_matches(found: &[C], reference: &[C], tol: f64) {
        let mut pool = reference.to_vec();
        for f in found {
            let (idx, d) = pool
                .iter()
                .enumerate()
                .map(|(i, r)| (i, (r - f).norm()))
                .min_by(|a, b| a.1.total_cmp(&b.1))
                .expect("reference not exhausted");
            assert!(
                d <= tol * f.norm().max(1.0),
                "{f} has no match: nearest off by {d:e} in {reference:?}"
            );
            pool.swap_remove(idx);
        }
    }

    fn largest(values: &[C], nev: usize) -> Vec<C> {
        let mut v = values.to_vec();
        v.sort_by(|a, b| b.norm().total_cmp(&a.norm()));
        v.truncate(nev);
        v
    }

    fn check_pairs(pairs: &[EigenPair], nev: usize, tol: f64) {
        assert_eq!(pairs.len(), nev);
        for w in pairs.windows(2) {
            assert!(w[0].value.norm() >= w[1].value.norm() * (1.0 - 1e-12));
        }
        for p in pairs {
            assert!((norm(&p.vector) - 1.0).abs() < 1e-12);
            assert!(p.residual < tol, "true residual {:e}", p.residual);
        }
    }

    fn random_dense(n: usize, seed: u64) -> DMatrix<C> {
        let mut rng = Lcg(seed);
        DMatrix::from_fn(n, n, |_, _| c(rng.uniform(), rng.uniform()))
    }

    #[test]
    fn diagonal_operator() {
        let n = 2000;
        for phase in [0.0, 0.7] {
            let d: Vec<C> = (0..n)
                .map(|k| Complex::from_polar(1.0 / (k as f64 + 1.0), phase * k as f64))
                .collect();
            let mut apply = |x: &[C], y: &mut [C]| {
                for ((yi, xi), di) in y.iter_mut().zip(x).zip(&d) {
                    *yi = xi * di;
                }
                Ok(())
            };
            let pairs = largest_eigenpairs(n, 6, &mut apply, &ArnoldiOptions::default())
                .expect("converged");
            check_pairs(&pairs, 6, 1e-9);
            for (k, p) in pairs.iter().enumerate() {
                assert!(
                    (p.value - d[k]).norm() < 1e-10 * d[k].norm(),
                    "{k}: {}",
                    p.value
                );
                assert!((p.vector[k].norm() - 1.0).abs() < 1e-10);
            }
        }
    }

    #[test]
    fn double_eigenvalue_is_found_twice() {
        let n = 500;
        let d: Vec<f64> = (0..n)
            .map(|k| if k < 2 { 1.0 } else { 0.8 / (k as f64 - 1.0) })
            .collect();
        let mut apply = |x: &[C], y: &mut [C]| {
            for ((yi, xi), di) in y.iter_mut().zip(x).zip(&d) {
                *yi = xi * di;
            }
            Ok(())
        };
        let pairs =
            largest_eigenpairs(n, 3, &mut apply, &ArnoldiOptions::default()).expect("converged");
        check_pairs(&pairs, 3, 1e-9);
        assert_matches(
            &pairs.iter().map(|p| p.value).collect::<Vec<_>>(),
            &[c(1.0, 0.0), c(1.0, 0.0), c(0.8, 0.0)],
            1e-10,
        );
        let overlap = dot(&pairs[0].vector[..2], &pairs[1].vector[..2]).norm();
        assert!(
            overlap < 1e-8,
            "the two copies are not independent: {overlap}"
        );
    }

    #[test]
    fn shift_invert_laplacian() {
        let n = 1000;
        let mut a = BandMatrix::<f64>::new(n, 1, 1);
        for i in 0..n {
            a.set(i, i, 2.0);
            if i + 1 < n {
                a.set(i, i + 1, -1.0);
                a.set(i + 1, i, -1.0);
            }
        }
        let sigma = 0.0;
        let mut shifted = map_to_complex(&a);
        let mut id = BandMatrix::<C>::new(n, 0, 0);
        for i in 0..n {
            id.set(i, i, c(1.0, 0.0));
        }
        shifted.scale_add(c(-sigma, 0.0), &id);
        let lu = shifted.lu().expect("nonsingular");
        let mut apply = |x: &[C], y: &mut [C]| {
            y.copy_from_slice(x);
            lu.solve_in_place(y);
            Ok::<(), LinalgError>(())
        };
        let pairs =
            largest_eigenpairs(n, 5, &mut apply, &ArnoldiOptions::default()).expect("converged");
        check_pairs(&pairs, 5, 1e-9);
        for (k, p) in pairs.iter().enumerate() {
            let lambda = sigma + 1.0 / p.value;
            let x = (k + 1) as f64 * std::f64::consts::PI / (2.0 * (n + 1) as f64);
            let exact = 4.0 * x.sin() * x.sin();
            assert!(
                (lambda - exact).norm() < 1e-9 * exact,
                "k={k}: {lambda} vs {exact}"
            );
            assert!(lambda.im.abs() < 1e-9 * exact);
        }
    }

    #[test]
    fn complex_non_hermitian_dense() {
        let a = random_dense(30, 42);
        let reference = dense_eigenvalues(&a);
        let pairs = largest_eigenpairs(30, 4, &mut dense_apply(&a), &ArnoldiOptions::default())
            .expect("converged");
        check_pairs(&pairs, 4, 1e-9);
        let found: Vec<C> = pairs.iter().map(|p| p.value).collect();
        assert_matches(&found, &largest(&reference, 4), 1e-10);
    }

    #[test]
    fn complex_non_hermitian_with_restarts() {
        let n = 300;
        let mut a = random_dense(n, 7) * c(0.02, 0.0);
        let dominant = [c(5.0, 0.0), c(0.0, 4.0), c(-3.0, 1.0), c(2.0, 2.0)];
        for (k, &d) in dominant.iter().enumerate() {
            a[(k, k)] += d;
        }
        let reference = dense_eigenvalues(&a);
        let opts = ArnoldiOptions {
            max_krylov: 12,
            ..ArnoldiOptions::default()
        };
        let pairs = largest_eigenpairs(n, 4, &mut dense_apply(&a), &opts).expect("converged");
        check_pairs(&pairs, 4, 1e-9);
        let found: Vec<C> = pairs.iter().map(|p| p.value).collect();
        assert_matches(&found, &largest(&reference, 4), 1e-10);
    }

    #[test]
    fn krylov_space_exhausted() {
        let n = 8;
        let a = random_dense(n, 3);
        let reference = dense_eigenvalues(&a);
        for nev in [1, 3, 8] {
            let pairs =
                largest_eigenpairs(n, nev, &mut dense_apply(&a), &ArnoldiOptions::default())
                    .expect("converged");
            check_pairs(&pairs, nev, 1e-10);
            let found: Vec<C> = pairs.iter().map(|p| p.value).collect();
            assert_matches(&found, &largest(&reference, nev), 1e-12);
        }
        // Cyclic shift: all eigenvalues are 8th roots of unity (equal modulus).
        let mut shift = |x: &[C], y: &mut [C]| {
            for (i, yi) in y.iter_mut().enumerate() {
                *yi = x[(i + 1) % n];
            }
            Ok(())
        };
        let pairs =
            largest_eigenpairs(n, n, &mut shift, &ArnoldiOptions::default()).expect("converged");
        check_pairs(&pairs, n, 1e-10);
        let roots: Vec<C> = (0..n)
            .map(|k| Complex::from_polar(1.0, 2.0 * std::f64::consts::PI * k as f64 / n as f64))
            .collect();
        let found: Vec<C> = pairs.iter().map(|p| p.value).collect();
        assert_matches(&found, &roots, 1e-12);
        // Start vector inside a 2-dimensional invariant subspace.
        let mut diag = |x: &[C], y: &mut [C]| {
            for (k, (yi, xi)) in y.iter_mut().zip(x).enumerate() {
                *yi = xi * (k as f64 + 1.0);
            }
            Ok(())
        };
        let mut start = vec![ZERO; n];
        start[0] = c(1.0, 0.0);
        start[1] = c(0.0, 1.0);
        let opts = ArnoldiOptions {
            start: Some(start),
            ..ArnoldiOptions::default()
        };
        let pairs = largest_eigenpairs(n, 4, &mut diag, &opts).expect("converged");
        check_pairs(&pairs, 4, 1e-12);
        for (p, exact) in pairs.iter().zip([8.0, 7.0, 6.0, 5.0]) {
            assert!((p.value - c(exact, 0.0)).norm() < 1e-12);
        }
    }

    #[test]
    fn gyroscopic_state_space() {
        // M q'' + Ω G q' + K q = 0 with M = I, K = diag(1, 1, 4, 4), G skew 2x2 blocks,
        // as x' = A x with x = [q; q'] and A = [[0, I], [-K, -Ω G]].
        let omega = 0.7;
        let k = [1.0, 1.0, 4.0, 4.0];
        let mut a = BandMatrix::<C>::new(8, 4, 4);
        for (i, &ki) in k.iter().enumerate() {
            a.set(i, i + 4, c(1.0, 0.0));
            a.set(i + 4, i, c(-ki, 0.0));
        }
        for b in [4, 6] {
            a.set(b, b + 1, c(-omega, 0.0));
            a.set(b + 1, b, c(omega, 0.0));
        }
        let dense = a.to_dense();
        let reference = dense_eigenvalues(&dense);
        for z in &reference {
            assert!(
                z.re.abs() < 1e-12,
                "undamped gyroscopic system is conservative"
            );
        }

        let mut direct = |x: &[C], y: &mut [C]| {
            a.mul_vec(x, y);
            Ok::<(), LinalgError>(())
        };
        let pairs =
            largest_eigenpairs(8, 8, &mut direct, &ArnoldiOptions::default()).expect("converged");
        check_pairs(&pairs, 8, 1e-10);
        let found: Vec<C> = pairs.iter().map(|p| p.value).collect();
        assert_matches(&found, &reference, 1e-12);

        let sigma = c(0.0, 0.5);
        let mut shifted = a.clone();
        for i in 0..8 {
            shifted.add(i, i, -sigma);
        }
        let lu = shifted.lu().expect("nonsingular");
        let mut inverse = |x: &[C], y: &mut [C]| {
            y.copy_from_slice(x);
            lu.solve_in_place(y);
            Ok::<(), LinalgError>(())
        };
        let pairs =
            largest_eigenpairs(8, 4, &mut inverse, &ArnoldiOptions::default()).expect("converged");
        check_pairs(&pairs, 4, 1e-10);
        let found: Vec<C> = pairs.iter().map(|p| sigma + p.value.inv()).collect();
        let mut nearest = reference.clone();
        nearest.sort_by(|x, y| (x - sigma).norm().total_cmp(&(y - sigma).norm()));
        nearest.truncate(4);
        assert_matches(&found, &nearest, 1e-12);
        for (p, lambda) in pairs.iter().zip(&found) {
            let mut ax = vec![ZERO; 8];
            a.mul_vec(&p.vector, &mut ax);
            let r: Vec<C> = ax
                .iter()
                .zip(&p.vector)
                .map(|(y, v)| y - lambda * v)
                .collect();
            assert!(norm(&r) < 1e-10 * lambda.norm());
        }
    }

    #[test]
    fn errors() {
        let mut id = |x: &[C], y: &mut [C]| {
            y.copy_from_slice(x);
            Ok(())
        };
        let opts = ArnoldiOptions::default();
        assert!(
            largest_eigenpairs(5, 0, &mut id, &opts)
                .expect("trivial")
                .is_empty()
        );
        assert!(matches!(
            largest_eigenpairs(5, 6, &mut id, &opts),
            Err(LinalgError::InvalidArgument(_))
        ));
        let mut nan = |_: &[C], y: &mut [C]| {
            y.fill(c(f64::NAN, 0.0));
            Ok(())
        };
        assert_eq!(
            largest_eigenpairs(5, 1, &mut nan, &opts),
            Err(LinalgError::NotFinite)
        );
        let mut failing = |_: &[C], _: &mut [C]| Err(LinalgError::Singular { column: 2 });
        assert_eq!(
            largest_eigenpairs(5, 1, &mut failing, &opts),
            Err(LinalgError::Singular { column: 2 })
        );
        // Equal-modulus spectrum ±1 with a tiny Krylov space cannot converge.
        let n = 400;
        let mut hard = |x: &[C], y: &mut [C]| {
            for (k, (yi, xi)) in y.iter_mut().zip(x).enumerate() {
                *yi = xi * (1.0 - 1e-6 * k as f64);
            }
            Ok(())
        };
        let tight = ArnoldiOptions {
            max_krylov: 4,
            max_restarts: 2,
            ..ArnoldiOptions::default()
        };
        assert!(matches!(
            largest_eigenpairs(n, 2, &mut hard, &tight),
            Err(LinalgError::NotConverged { wanted: 2, .. })
        ));
        // Zero operator: exact zero eigenvalues.
        let mut zero = |_: &[C], y: &mut [C]| {
            y.fill(ZERO);
            Ok(())
        };
        let pairs = largest_eigenpairs(6, 2, &mut zero, &opts).expect("converged");
        assert!(pairs.iter().all(|p| p.value == ZERO && p.residual == 0.0));
    }

    /// Classical Gram–Schmidt twice, four columns at a time, on lengths and
    /// counts that are not multiples of four, real and complex: the basis
    /// stays orthonormal to 1e-14, the coefficients reproduce each vector
    /// (`w = V h + w⊥`) to 1e-14, and a vector in the span leaves at most
    /// 1e-14 of its norm.
    fn check_orthogonalize<T: KrylovScalar>() {
        let (n, count) = (1003, 37);
        let mut rng = Lcg::new();
        let mut basis: Vec<T> = Vec::new();
        let mut coeffs = vec![T::zero(); count + 1];
        for j in 0..count {
            let mut w = vec![T::zero(); n];
            rng.fill(&mut w);
            if j % 3 == 0 && j > 0 {
                // Nearly in the span: forces the reorthogonalization passes.
                for (i, wi) in w.iter_mut().enumerate() {
                    *wi = basis[i] + basis[(j - 1) * n + i] + wi.unscale(1e8);
                }
            }
            let original = w.clone();
            let beta = orthogonalize(&basis, j, &mut w, &mut coeffs).unwrap();
            let mut rebuilt = w.clone();
            for (c, &h) in coeffs[..j].iter().enumerate() {
                for (r, &v) in rebuilt.iter_mut().zip(&basis[c * n..(c + 1) * n]) {
                    *r += h * v;
                }
            }
            let gap: Vec<T> = rebuilt
                .iter()
                .zip(&original)
                .map(|(a, b)| *a - *b)
                .collect();
            assert!(norm(&gap) <= 1e-14 * norm(&original), "column {j}");
            basis.extend(w.iter().map(|x| x.unscale(beta)));
        }
        for a in 0..count {
            for b in 0..count {
                let p = dot(&basis[a * n..(a + 1) * n], &basis[b * n..(b + 1) * n]);
                let expected = if a == b { 1.0 } else { 0.0 };
                assert!(
                    (p - T::from_real(expected)).modulus() <= 1e-14,
                    "({a}, {b})"
                );
            }
        }
        let mut inside = vec![T::zero(); n];
        for c in 0..count {
            for (x, &v) in inside.iter_mut().zip(&basis[c * n..(c + 1) * n]) {
                *x += v.scale(1.0 + c as f64);
            }
        }
        let size = norm(&inside);
        let left = orthogonalize(&basis, count, &mut inside, &mut coeffs);
        assert!(left.unwrap_or(0.0) <= 1e-14 * size, "{left:?} of {size}");
    }

    #[test]
    fn gram_schmidt_keeps_the_basis_orthonormal() {
        check_orthogonalize::<f64>();
        check_orthogonalize::<C>();
    }

    #[test]
    fn real_operator_one_of_each_conjugate_pair() {
        let n = 60;
        let mut rng = Lcg(11);
        let a = DMatrix::from_fn(n, n, |_, _| rng.uniform());
        let ac = a.map(|x| c(x, 0.0));
        let reference = dense_eigenvalues(&ac);
        let mut apply = |x: &[f64], y: &mut [f64]| {
            for (i, yi) in y.iter_mut().enumerate() {
                *yi = x.iter().enumerate().map(|(j, &xj)| a[(i, j)] * xj).sum();
            }
            Ok(())
        };
        // A count that does not split a conjugate pair.
        let mut sorted = reference.clone();
        sorted.sort_by(|a, b| b.norm().total_cmp(&a.norm()));
        let nev = (6..12)
            .find(|&k| sorted[k - 1].norm() - sorted[k].norm() > 1e-6)
            .expect("a gap in the moduli");
        let pairs = largest_eigenpairs_real(n, nev, &mut apply, &ArnoldiOptions::default())
            .expect("converged");
        let wanted: Vec<C> = largest(&reference, nev)
            .into_iter()
            .filter(|z| z.im >= -1e-10 * z.norm())
            .collect();
        assert_eq!(pairs.len(), wanted.len());
        let found: Vec<C> = pairs.iter().map(|p| p.value).collect();
        assert_matches(&found, &wanted, 1e-10);
        let complex = largest_eigenpairs(n, nev, &mut dense_apply(&ac), &ArnoldiOptions::default())
            .expect("converged");
        for p in &pairs {
            assert!(p.residual < 1e-9, "true residual {:e}", p.residual);
            assert!((norm(&p.vector) - 1.0).abs() < 1e-12);
            let twin = complex
                .iter()
                .find(|q| (q.value - p.value).norm() < 1e-10 * p.value.norm())
                .expect("the complex process finds it too");
            assert!(
                dot(&twin.vector, &p.vector).norm() > 1.0 - 1e-9,
                "same eigenvector up to phase"
            );
        }
    }

    /// From a start vector near one eigenvector (the 12th largest of 2000),
    /// the Ritz pair nearest the target converges to it, not to the dominant
    /// ones; a target between two eigenvalues gets the one the start holds.
    #[test]
    fn reproducible() {
        let a = random_dense(40, 9);
        let run = || {
            let opts = ArnoldiOptions {
                max_krylov: 20,
                ..ArnoldiOptions::default()
            };
            largest_eigenpairs(40, 3, &mut dense_apply(&a), &opts)
        };
        let first = run().expect("converged after restarts");
        assert_eq!(first.len(), 3);
        assert_eq!(Ok(first), run());
    }

    #[test]
    fn slowly_separating_values_all_converge() {
        // Eigenvalues 1/(k+1): the fifth converges long after the leading ones.
        let n = 3000;
        let d: Vec<f64> = (0..n).map(|k| 1.0 / (k as f64 + 1.0)).collect();
        let mut apply = |x: &[f64], y: &mut [f64]| {
            for ((yi, xi), di) in y.iter_mut().zip(x).zip(&d) {
                *yi = xi * di;
            }
            Ok(())
        };
        let opts = ArnoldiOptions {
            tol: 1e-12,
            ..ArnoldiOptions::default()
        };
        let all = largest_eigenpairs_real(n, 5, &mut apply, &opts).expect("converged");
        assert_eq!(all.len(), 5);
        for (k, p) in all.iter().enumerate() {
            assert!(p.residual <= 1e-12, "{k}: {:e}", p.residual);
            assert!((p.value - c(d[k], 0.0)).norm() < 1e-11 * d[k]);
        }
    }
}
