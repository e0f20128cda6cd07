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
mod tests;
