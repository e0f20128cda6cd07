//! Sturm sequence count of a symmetric definite banded pencil: the number of
//! eigenvalues of `K φ = λ M φ` below a shift `σ` is the number of negative
//! pivots of `K − σ M = L D Lᵀ` (Sylvester's law of inertia; Bathe, *Finite
//! Element Procedures*, §11.4.3). The factorization is banded and without
//! pivoting, as inertia requires a congruence.

use super::{BandMatrix, LinalgError};

/// A pivot `d_j = a_jj − Σ L_jc² d_c` below this fraction of
/// `|a_jj| + Σ |L_jc² d_c|` (the cancellation that forms it) is treated as
/// zero: its sign is not known to round-off, because `σ` is (numerically) an
/// eigenvalue of a leading block; move it. Above it, `d_j` is known to about
/// `ε / 1e-9 ≈ 2e-7` of itself, its sign for sure.
const ZERO_PIVOT: f64 = 1e-9;

/// Number of eigenvalues of the pencil `(k, mass)` (symmetric, `mass`
/// positive definite, both banded; only their lower bands are read) below
/// `shift`: the negative pivots of `L D Lᵀ = k − shift · mass`.
/// [`LinalgError::Singular`] when a pivot is (numerically) zero — `shift` is
/// an eigenvalue to round-off or the factorization broke down: move it.
pub fn eigenvalues_below(
    k: &BandMatrix<f64>,
    mass: &BandMatrix<f64>,
    shift: f64,
) -> Result<usize, LinalgError> {
    let n = k.n();
    assert_eq!(mass.n(), n, "Sturm count: K and M of different orders");
    let b = k.kl().max(mass.kl());
    if !shift.is_finite() {
        return Err(LinalgError::NotFinite);
    }
    // l[j * (b + 1) + d] = L(j + d, j) for d = 1..=b; d = 0 holds D_j.
    let w = b + 1;
    let mut l = vec![0.0; n * w];
    let entry = |i: usize, j: usize| k.get(i, j) - shift * mass.get(i, j);
    let mut negative = 0;
    for j in 0..n {
        let first = j.saturating_sub(b);
        let mut d = entry(j, j);
        let mut scale = d.abs();
        for c in first..j {
            let ljc = l[c * w + (j - c)];
            let term = ljc * ljc * l[c * w];
            d -= term;
            scale += term.abs();
        }
        if !d.is_finite() {
            return Err(LinalgError::NotFinite);
        }
        if d.abs() <= ZERO_PIVOT * scale {
            return Err(LinalgError::Singular { column: j });
        }
        if d < 0.0 {
            negative += 1;
        }
        l[j * w] = d;
        for i in j + 1..(j + w).min(n) {
            let mut v = entry(i, j);
            for c in i.saturating_sub(b).max(first)..j {
                v -= l[c * w + (i - c)] * l[c * w + (j - c)] * l[c * w];
            }
            l[j * w + (i - j)] = v / d;
        }
    }
    Ok(negative)
}

/// Number of eigenvalues of a symmetric tridiagonal pencil `(k, mass)`
/// (`mass` positive definite; only the diagonal and first sub-diagonal are
/// read) below `shift`, for bisection: the negative pivots of
/// `d_j = a_jj − e_j²/d_{j−1}` with `a = k − shift · mass`, a pivot of
/// magnitude below `pivmin` taken as `−pivmin` (Kahan's count as in LAPACK's
/// `dstebz`; backward stable, so it never refuses a shift: a shift on an
/// eigenvalue counts it on one side or the other).
pub fn tridiagonal_eigenvalues_below(
    k: &BandMatrix<f64>,
    mass: &BandMatrix<f64>,
    shift: f64,
) -> usize {
    let n = k.n();
    assert_eq!(mass.n(), n, "Sturm count: K and M of different orders");
    let e = |j: usize| k.get(j, j - 1) - shift * mass.get(j, j - 1);
    let largest = (1..n).map(|j| e(j) * e(j)).fold(1.0, f64::max);
    let pivmin = f64::MIN_POSITIVE * largest;
    let mut negative = 0;
    let mut d = 1.0;
    for j in 0..n {
        let a = k.get(j, j) - shift * mass.get(j, j);
        d = if j == 0 { a } else { a - e(j) * e(j) / d };
        if d.abs() < pivmin || d.is_nan() {
            d = -pivmin;
        }
        if d < 0.0 {
            negative += 1;
        }
    }
    negative
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Tridiagonal `K` (the fixed–fixed string, `2, −1`) and `M = I`:
    /// eigenvalues `2 − 2 cos(kπ/(n+1))`; the count between any two of them
    /// and outside them is exact.
    #[test]
    fn counts_the_eigenvalues_of_the_discrete_string() {
        let n = 12;
        let mut k = BandMatrix::new(n, 1, 1);
        let mut m = BandMatrix::new(n, 1, 1);
        for i in 0..n {
            k.set(i, i, 2.0);
            m.set(i, i, 1.0);
            if i + 1 < n {
                k.set(i, i + 1, -1.0);
                k.set(i + 1, i, -1.0);
            }
        }
        let exact: Vec<f64> = (1..=n)
            .map(|j| 2.0 - 2.0 * (j as f64 * std::f64::consts::PI / (n + 1) as f64).cos())
            .collect();
        assert_eq!(eigenvalues_below(&k, &m, 0.5 * exact[0]), Ok(0));
        for j in 1..n {
            // Off the midpoint: the middle one, 2, zeroes the first pivot.
            let mid = 0.4 * exact[j - 1] + 0.6 * exact[j];
            assert_eq!(eigenvalues_below(&k, &m, mid), Ok(j), "below {mid}");
        }
        assert_eq!(eigenvalues_below(&k, &m, 5.0), Ok(n));
    }

    /// A shift on an eigenvalue (here the double eigenvalue 1 of a diagonal
    /// pencil) is refused, not miscounted.
    #[test]
    fn a_shift_on_an_eigenvalue_is_refused() {
        let mut k = BandMatrix::new(3, 0, 0);
        let mut m = BandMatrix::new(3, 0, 0);
        for (i, v) in [1.0, 1.0, 4.0].iter().enumerate() {
            k.set(i, i, *v);
            m.set(i, i, 1.0);
        }
        assert!(matches!(
            eigenvalues_below(&k, &m, 1.0),
            Err(LinalgError::Singular { .. })
        ));
        assert_eq!(eigenvalues_below(&k, &m, 1.0 + 1e-7), Ok(2));
        assert_eq!(eigenvalues_below(&k, &m, 1.0 - 1e-7), Ok(0));
    }
    /// The tridiagonal count agrees with the refusing one off the
    /// eigenvalues, and on an eigenvalue counts it on one side: never fails.
    #[test]
    fn the_tridiagonal_count_brackets_every_eigenvalue() {
        let n = 9;
        let mut k = BandMatrix::new(n, 1, 1);
        let mut m = BandMatrix::new(n, 1, 1);
        for i in 0..n {
            k.set(i, i, 2.0);
            m.set(i, i, 1.0);
            if i + 1 < n {
                k.set(i, i + 1, -1.0);
                k.set(i + 1, i, -1.0);
            }
        }
        for j in 1..=n {
            let exact = 2.0 - 2.0 * (j as f64 * std::f64::consts::PI / (n + 1) as f64).cos();
            let below = tridiagonal_eigenvalues_below(&k, &m, exact * (1.0 - 1e-12));
            let above = tridiagonal_eigenvalues_below(&k, &m, exact * (1.0 + 1e-12));
            assert_eq!((below, above), (j - 1, j), "eigenvalue {j}");
            let on = tridiagonal_eigenvalues_below(&k, &m, exact);
            assert!(on == j - 1 || on == j, "on eigenvalue {j}: {on}");
            let off = exact * 1.01;
            if let Ok(c) = eigenvalues_below(&k, &m, off) {
                assert_eq!(tridiagonal_eigenvalues_below(&k, &m, off), c);
            }
        }
    }
}
