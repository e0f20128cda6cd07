//! General banded matrices in LAPACK band storage and their LU factorization
//! with partial pivoting (the unblocked algorithm of LAPACK `xGBTF2`/`xGBTRS`;
//! like LAPACK's `izamax`, pivots and the singularity threshold measure a
//! complex entry by `|re| + |im|`, which needs no square root).

use nalgebra::{Complex, ComplexField, DMatrix};

use super::LinalgError;

/// Scalars supported by the banded routines: `f64` and `Complex<f64>`.
pub trait Scalar: ComplexField<RealField = f64> + Copy {}

impl Scalar for f64 {}
impl Scalar for Complex<f64> {}

/// Square `n × n` matrix with `kl` sub- and `ku` super-diagonals.
///
/// Column-major LAPACK band storage with leading dimension `ldab = kl + ku + 1`:
/// entry `(i, j)` lives at `data[(ku + i - j) + j * ldab]`. Only the band is
/// stored (mat-vecs stream no padding); [`BandMatrix::lu`] copies it into
/// factor storage with `kl` extra rows for the fill-in of row pivoting.
#[derive(Debug, Clone, PartialEq)]
pub struct BandMatrix<T> {
    n: usize,
    kl: usize,
    ku: usize,
    ldab: usize,
    data: Vec<T>,
}

impl<T: Scalar> BandMatrix<T> {
    /// Zero `n × n` matrix with `kl` sub- and `ku` super-diagonals
    /// (both are clamped to `n - 1`).
    pub fn new(n: usize, kl: usize, ku: usize) -> Self {
        let kl = kl.min(n.saturating_sub(1));
        let ku = ku.min(n.saturating_sub(1));
        let ldab = kl + ku + 1;
        Self {
            n,
            kl,
            ku,
            ldab,
            data: vec![T::zero(); ldab * n],
        }
    }

    /// Zero matrix with the same dimension and band as `self`.
    pub fn zeroed_like(&self) -> Self {
        Self::new(self.n, self.kl, self.ku)
    }

    /// Matrix dimension.
    pub fn n(&self) -> usize {
        self.n
    }

    /// Number of sub-diagonals.
    pub fn kl(&self) -> usize {
        self.kl
    }

    /// Number of super-diagonals.
    pub fn ku(&self) -> usize {
        self.ku
    }

    /// Storage index of `(i, j)`, or `None` outside the matrix or the band.
    #[inline]
    fn index(&self, i: usize, j: usize) -> Option<usize> {
        if i < self.n && j < self.n && i + self.ku >= j && i <= j + self.kl {
            Some(self.ku + i - j + j * self.ldab)
        } else {
            None
        }
    }

    /// Entry `(i, j)`; zero outside the band or the matrix.
    pub fn get(&self, i: usize, j: usize) -> T {
        self.index(i, j).map_or_else(T::zero, |k| self.data[k])
    }

    /// `A[i, j] += v`.
    ///
    /// # Panics
    /// If `(i, j)` lies outside the stored band (a programming error).
    pub fn add(&mut self, i: usize, j: usize, v: T) {
        let k = self.band_index(i, j);
        self.data[k] += v;
    }

    /// `A[i, j] = v`.
    ///
    /// # Panics
    /// If `(i, j)` lies outside the stored band (a programming error).
    pub fn set(&mut self, i: usize, j: usize, v: T) {
        let k = self.band_index(i, j);
        self.data[k] = v;
    }

    /// Storage index of `(i, j)`, asserting that it lies in the band.
    fn band_index(&self, i: usize, j: usize) -> usize {
        match self.index(i, j) {
            Some(k) => k,
            None => panic!(
                "entry ({i}, {j}) lies outside the band (n = {}, kl = {}, ku = {})",
                self.n, self.kl, self.ku
            ),
        }
    }

    /// `y = A x` without allocation.
    ///
    /// # Panics
    /// If `x` or `y` does not have length `n`.
    pub fn mul_vec(&self, x: &[T], y: &mut [T]) {
        check_len("y of mul_vec", self.n, y.len());
        y.fill(T::zero());
        self.mul_add_vec(T::one(), x, y);
    }

    /// `y += alpha A x` without allocation.
    ///
    /// # Panics
    /// If `x` or `y` does not have length `n`.
    pub fn mul_add_vec(&self, alpha: T, x: &[T], y: &mut [T]) {
        check_len("x of mul_add_vec", self.n, x.len());
        check_len("y of mul_add_vec", self.n, y.len());
        for (j, &xj) in x.iter().enumerate() {
            self.add_column(j, alpha * xj, y);
        }
    }

    /// `y += A x + B z` in one pass over the columns of both bands, with
    /// `(x_j, z_j)` given per column by `xz(j)` (so the operands need not be
    /// stored). Equal bands share one loop per column (5 % faster Newmark steps
    /// than two column updates).
    pub fn mul_add_pair(
        a: &BandMatrix<T>,
        b: &BandMatrix<T>,
        y: &mut [T],
        xz: impl Fn(usize) -> (T, T),
    ) {
        check_len("y of mul_add_pair", a.n, y.len());
        check_len("y of mul_add_pair", b.n, y.len());
        let (n, kl, ku, ldab) = (a.n, a.kl, a.ku, a.ldab);
        let same_band = b.kl == kl && b.ku == ku;
        for j in 0..n {
            let (xj, zj) = xz(j);
            if !same_band {
                a.add_column(j, xj, y);
                b.add_column(j, zj, y);
                continue;
            }
            let i0 = j.saturating_sub(ku);
            let i1 = (j + kl).min(n - 1);
            let base = j * ldab + ku - j;
            let ca = &a.data[base + i0..=base + i1];
            let cb = &b.data[base + i0..=base + i1];
            for ((yi, &p), &q) in y[i0..=i1].iter_mut().zip(ca).zip(cb) {
                *yi += p * xj + q * zj;
            }
        }
    }

    /// `y += A[:, j] x_j`.
    fn add_column(&self, j: usize, xj: T, y: &mut [T]) {
        let i0 = j.saturating_sub(self.ku);
        let i1 = (j + self.kl).min(self.n - 1);
        let base = j * self.ldab + self.ku - j;
        for (yi, &a) in y[i0..=i1].iter_mut().zip(&self.data[base + i0..=base + i1]) {
            *yi += a * xj;
        }
    }

    /// `self = other` without allocation; the band of `other` must lie within
    /// the band of `self` (panics otherwise).
    pub fn assign(&mut self, other: &BandMatrix<T>) {
        self.data.fill(T::zero());
        self.scale_add(T::one(), other);
    }

    /// Dense copy (for tests and small problems).
    pub fn to_dense(&self) -> DMatrix<T> {
        DMatrix::from_fn(self.n, self.n, |i, j| self.get(i, j))
    }

    /// `self += alpha * other`.
    ///
    /// # Panics
    /// If the dimensions differ or the band of `other` is not contained in the
    /// band of `self` (programming errors).
    pub fn scale_add(&mut self, alpha: T, other: &BandMatrix<T>) {
        check_len("operand of scale_add", self.n, other.n);
        assert!(
            other.kl <= self.kl && other.ku <= self.ku,
            "scale_add: operand band (kl = {}, ku = {}) is not contained in the target band (kl = {}, ku = {})",
            other.kl,
            other.ku,
            self.kl,
            self.ku
        );
        let (kv, okv) = (self.ku, other.ku);
        for j in 0..self.n {
            let i0 = j.saturating_sub(other.ku);
            let i1 = (j + other.kl).min(self.n - 1);
            let sb = j * self.ldab + kv - j;
            let ob = j * other.ldab + okv - j;
            let dst = &mut self.data[sb + i0..=sb + i1];
            let src = &other.data[ob + i0..=ob + i1];
            for (d, &s) in dst.iter_mut().zip(src) {
                *d += alpha * s;
            }
        }
    }

    /// LU factorization with partial pivoting, `P A = L U`, of a copy of `self`.
    ///
    /// LAPACK `xGBTF2`: `U` gets `kl + ku` super-diagonals, `L` is unit lower
    /// banded with `kl` sub-diagonals. Cost `O(n kl (kl + ku))`. A pivot that is
    /// zero or whose modulus is below `n * EPSILON * max|a_ij|` is reported as
    /// [`LinalgError::Singular`].
    pub fn lu(&self) -> Result<BandLu<T>, LinalgError> {
        let mut lu = BandLu::default();
        self.lu_into(&mut lu)?;
        Ok(lu)
    }

    /// [`BandMatrix::lu`] into the storage of an earlier factorization (no
    /// allocation when the sizes match, as in a time stepper refactoring at a
    /// new speed).
    pub fn lu_into(&self, lu: &mut BandLu<T>) -> Result<(), LinalgError> {
        lu.shape(self.n, self.kl, self.ku);
        for (dst, src) in lu
            .data
            .chunks_exact_mut(lu.ldab)
            .zip(self.data.chunks_exact(self.ldab))
        {
            dst[..self.kl].fill(T::zero());
            dst[self.kl..].copy_from_slice(src);
        }
        lu.factor()
    }
}

impl<T: Scalar> BandLu<T> {
    /// Sets the dimensions of the factor storage (contents unspecified).
    fn shape(&mut self, n: usize, kl: usize, ku: usize) {
        self.n = n;
        self.kl = kl;
        self.ku = ku;
        self.ldab = 2 * kl + ku + 1;
        self.data.resize(self.ldab * n, T::zero());
    }

    /// Factors in place the matrix stored in the last `kl + ku + 1` rows of
    /// `data` (the first `kl` rows zero), as described at [`BandMatrix::lu`].
    fn factor(&mut self) -> Result<(), LinalgError> {
        let (n, kl, ku, ldab) = (self.n, self.kl, self.ku, self.ldab);
        let kv = kl + ku;
        let mut amax = 0.0_f64;
        for col in self.data.chunks_exact(ldab) {
            for a in &col[kl..] {
                if !a.is_finite() {
                    return Err(LinalgError::NotFinite);
                }
                amax = amax.max(a.norm1());
            }
        }
        let thresh = n as f64 * f64::EPSILON * amax;
        let lu = self;
        lu.u_width = kv;
        lu.interchanged = true;
        lu.ipiv.clear();
        lu.ipiv.resize(n, 0);
        let (a, ipiv) = (&mut lu.data, &mut lu.ipiv);
        let (mut ju, mut u_width) = (0usize, 0usize);
        for (j, piv) in ipiv.iter_mut().enumerate() {
            let km = kl.min(n - 1 - j);
            let diag = j * ldab + kv;
            let mut p = 0usize;
            let mut pmax = -1.0_f64;
            for (r, v) in a[diag..=diag + km].iter().enumerate() {
                let m = v.norm1();
                if m > pmax {
                    pmax = m;
                    p = r;
                }
            }
            if pmax == 0.0 || pmax < thresh {
                return Err(LinalgError::Singular { column: j });
            }
            *piv = j + p;
            ju = ju.max((j + ku + p).min(n - 1));
            u_width = u_width.max(ju - j);
            if p != 0 {
                for c in j..=ju {
                    let k = c * ldab + kv + j - c;
                    a.swap(k, k + p);
                }
            }
            if km > 0 {
                let (left, right) = a.split_at_mut((j + 1) * ldab);
                let inv = T::one() / left[diag];
                let l = &mut left[diag + 1..=diag + km];
                for x in l.iter_mut() {
                    *x *= inv;
                }
                for c in j + 1..=ju {
                    let k = (c - j - 1) * ldab + kv + j - c;
                    let u = right[k];
                    if u != T::zero() {
                        for (dst, &lr) in right[k + 1..=k + km].iter_mut().zip(l.iter()) {
                            *dst -= lr * u;
                        }
                    }
                }
            }
        }
        // Back substitution multiplies by the inverse pivots: a division on the
        // critical path of every column costs more than the column's update.
        for j in 0..n {
            let d = &mut a[j * ldab + kv];
            *d = T::one() / *d;
        }
        lu.u_width = u_width;
        lu.interchanged = lu.ipiv.iter().enumerate().any(|(j, &p)| p != j);
        lu.copy_rows();
        Ok(())
    }

    /// Fill [`BandLu::l_rows`] and [`BandLu::u_rows`] from the factors
    /// (empty when rows were interchanged: the column sweeps read `data`).
    fn copy_rows(&mut self) {
        let (n, kl, w) = (self.n, self.kl, self.u_width);
        let kv = kl + self.ku;
        let stride = self.ldab.saturating_sub(1);
        self.l_rows.clear();
        self.u_rows.clear();
        if self.interchanged {
            return;
        }
        self.l_rows.resize(n * kl, T::zero());
        self.u_rows.resize(n * w, T::zero());
        for i in 0..n {
            let j0 = i.saturating_sub(kl);
            let row = &mut self.l_rows[i * kl..(i + 1) * kl];
            for (dst, j) in row[kl - (i - j0)..].iter_mut().zip(j0..i) {
                *dst = self.data[j * stride + kv + i];
            }
            let j1 = (i + w).min(n - 1);
            let row = &mut self.u_rows[i * w..(i + 1) * w];
            for (dst, j) in row.iter_mut().zip(i + 1..=j1) {
                *dst = self.data[j * stride + kv + i];
            }
        }
    }
}

impl BandLu<Complex<f64>> {
    /// Factors `Σ cᵢ Aᵢ` for real `Aᵢ` into `self` (as [`BandMatrix::lu_into`]),
    /// with the band of the first term, which must contain the bands of the
    /// others; the sum is formed term by term in the given order (the value
    /// of [`map_to_complex`] of the first term followed by
    /// [`BandMatrix::scale_add`] of the others) directly in the factor
    /// storage, without complex copies of the operands (no allocation when
    /// the sizes match).
    ///
    /// # Panics
    /// If `terms` is empty, a dimension differs or a band is not contained in
    /// the band of the first term.
    pub fn factor_real_combination(
        &mut self,
        terms: &[(Complex<f64>, &BandMatrix<f64>)],
    ) -> Result<(), LinalgError> {
        let first = terms.first().expect("at least one term").1;
        let (n, kl, ku) = (first.n, first.kl, first.ku);
        self.shape(n, kl, ku);
        self.data.fill(Complex::new(0.0, 0.0));
        let ldab = self.ldab;
        for &(_, other) in terms {
            check_len("operand of factor_real_combination", n, other.n);
            assert!(
                other.kl <= kl && other.ku <= ku,
                "factor_real_combination: operand band (kl = {}, ku = {}) is not contained in the band (kl = {kl}, ku = {ku})",
                other.kl,
                other.ku,
            );
        }
        for (j, col) in self.data.chunks_exact_mut(ldab).enumerate() {
            // Row i of column j: `kl + ku + i - j` in the factor storage
            // (`i ≥ j - ku`, so the index is never negative).
            for &(alpha, other) in terms {
                let i0 = j.saturating_sub(other.ku);
                let i1 = (j + other.kl).min(n - 1);
                let ob = j * other.ldab + other.ku - j;
                let dst = &mut col[kl + ku + i0 - j..=kl + ku + i1 - j];
                let src = &other.data[ob + i0..=ob + i1];
                for (d, &s) in dst.iter_mut().zip(src) {
                    *d += Complex::new(alpha.re * s, alpha.im * s);
                }
            }
        }
        self.factor()
    }
}

impl<T: Scalar> Default for BandLu<T> {
    /// Empty factors (`n = 0`), storage for [`BandMatrix::lu_into`].
    fn default() -> Self {
        Self {
            n: 0,
            kl: 0,
            ku: 0,
            ldab: 0,
            u_width: 0,
            interchanged: false,
            data: Vec::new(),
            ipiv: Vec::new(),
            l_rows: Vec::new(),
            u_rows: Vec::new(),
        }
    }
}

/// `BandMatrix<f64>` → `BandMatrix<Complex<f64>>` with the same band.
pub fn map_to_complex(a: &BandMatrix<f64>) -> BandMatrix<Complex<f64>> {
    BandMatrix {
        n: a.n,
        kl: a.kl,
        ku: a.ku,
        ldab: a.ldab,
        data: a.data.iter().map(|&x| Complex::new(x, 0.0)).collect(),
    }
}

/// Assert that `what` has the dimension `expected` (a programming error otherwise).
fn check_len(what: &str, expected: usize, found: usize) {
    assert!(
        expected == found,
        "dimension mismatch: {what} has length {found}, expected {expected}"
    );
}

/// Banded LU factors `P A = L U` produced by [`BandMatrix::lu`] (LAPACK layout,
/// except that the diagonal of `U` is stored inverted).
#[derive(Debug, Clone)]
pub struct BandLu<T> {
    n: usize,
    kl: usize,
    ku: usize,
    ldab: usize,
    /// Upper bandwidth of `U` as filled by the row interchanges,
    /// `max_j (ju_j − j) ≤ kl + ku` (`ju_j` the last column row `j` reaches in
    /// the elimination, as in LAPACK `xGBTF2`): `ku` when no row is
    /// interchanged. Entries of `U` farther from the diagonal are exactly zero.
    u_width: usize,
    /// Whether any row was interchanged (`ipiv[j] ≠ j` for some `j`).
    interchanged: bool,
    data: Vec<T>,
    ipiv: Vec<usize>,
    /// Without interchanges, row `i` of `L` (`L[i, i − kl … i − 1]`, fewer
    /// in the first rows) in `l_rows[i kl ..][.. kl]`, right-aligned: the
    /// forward sweep reads each row as one contiguous slice.
    l_rows: Vec<T>,
    /// Without interchanges, row `i` of `U` right of the diagonal
    /// (`U[i, i + 1 … i + u_width]`, fewer in the last rows) in
    /// `u_rows[i u_width ..]`, left-aligned, for the back substitution.
    u_rows: Vec<T>,
}

impl<T: Scalar> BandLu<T> {
    /// Matrix dimension.
    pub fn n(&self) -> usize {
        self.n
    }

    /// Solves `A x = b` in place (LAPACK `xGBTRS`, no transpose), no allocation.
    /// Cost `O(n (kl + w))`, `w` the upper bandwidth of `U` (`ku` without
    /// row interchanges, at most `kl + ku`): the back substitution skips the
    /// entries beyond it, which are exactly zero.
    ///
    /// # Panics
    /// If `b` does not have length `n`.
    pub fn solve_in_place(&self, b: &mut [T]) {
        let (n, kl, ldab) = (self.n, self.kl, self.ldab);
        check_len("right-hand side", n, b.len());
        let kv = kl + self.ku;
        // `L[i, j]` and `U[i, j]` sit at `j (ldab − 1) + kv + i`.
        let stride = ldab.saturating_sub(1);
        if kl > 0 && self.interchanged {
            for j in 0..n.saturating_sub(1) {
                let lm = kl.min(n - 1 - j);
                let l = self.ipiv[j];
                if l != j {
                    b.swap(l, j);
                }
                let bj = b[j];
                let diag = j * ldab + kv;
                let col = &self.data[diag + 1..=diag + lm];
                for (bi, &lr) in b[j + 1..=j + lm].iter_mut().zip(col) {
                    *bi -= lr * bj;
                }
            }
        } else if kl > 0 {
            // Without interchanges, row by row: row `i` takes the updates of
            // columns `i − kl … i − 1` in the order the column sweep above
            // gives them (the same bits), but only its last one waits for
            // the row before; each row is read as one contiguous slice of
            // `l_rows` (the columns' entries are `ldab − 1` apart in `data`).
            for i in 1..n {
                let j0 = i.saturating_sub(kl);
                let row = &self.l_rows[(i + 1) * kl - (i - j0)..(i + 1) * kl];
                let (done, rest) = b.split_at_mut(i);
                let mut acc = rest[0];
                for (l, bj) in row.iter().zip(&done[j0..]) {
                    acc -= *l * *bj;
                }
                rest[0] = acc;
            }
        }
        // Back substitution row by row, the columns of row `i` from the last
        // down, as a column sweep from the last column gives them.
        let w = self.u_width;
        for i in (0..n).rev() {
            let j1 = (i + w).min(n - 1);
            let (head, solved) = b.split_at_mut(i + 1);
            let mut acc = head[i];
            if self.interchanged {
                for j in (i + 1..=j1).rev() {
                    acc -= self.data[j * stride + kv + i] * solved[j - i - 1];
                }
            } else {
                let row = &self.u_rows[i * w..i * w + (j1 - i)];
                for (u, bj) in row.iter().zip(&solved[..j1 - i]).rev() {
                    acc -= *u * *bj;
                }
            }
            head[i] = acc * self.data[i * ldab + kv];
        }
    }
}

#[cfg(test)]
mod tests;
