//! Unit tests of `linalg::band` (the parent module's `mod tests`).

use super::*;

/// Tiny deterministic generator for test data (64-bit LCG).
struct Rng(u64);

impl Rng {
    fn uniform(&mut self) -> f64 {
        self.0 = self
            .0
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        (self.0 >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
    }
}

trait Random: Scalar {
    fn random(rng: &mut Rng) -> Self;
}

impl Random for f64 {
    fn random(rng: &mut Rng) -> Self {
        rng.uniform()
    }
}

impl Random for Complex<f64> {
    fn random(rng: &mut Rng) -> Self {
        Complex::new(rng.uniform(), rng.uniform())
    }
}

/// Random band matrix, well conditioned: with `pivot` the diagonal is zero and
/// the dominant entries pair rows `(2k, 2k + 1)` so that every other column
/// needs a row interchange; otherwise the diagonal is shifted by 4.
fn random_band<T: Random>(
    rng: &mut Rng,
    n: usize,
    kl: usize,
    ku: usize,
    pivot: bool,
) -> BandMatrix<T> {
    let mut a = BandMatrix::new(n, kl, ku);
    for j in 0..n {
        for i in j.saturating_sub(ku)..=(j + kl).min(n - 1) {
            let mut v = T::random(rng);
            let partner = if j % 2 == 0 { j + 1 } else { j - 1 };
            if !pivot && i == j {
                v += T::from_real(4.0);
            } else if pivot && i == j {
                v = if j + 1 == n && n % 2 == 1 {
                    T::from_real(4.0)
                } else {
                    T::zero()
                };
            } else if pivot && i == partner {
                v += T::from_real(4.0);
            }
            a.set(i, j, v);
        }
    }
    a
}

/// `y += A x + B z` in one pass equals the dense products, for equal bands
/// (fused) and different bands (two passes).
#[test]
fn paired_mat_vec_matches_dense_products() {
    let mut rng = Rng(7);
    for (bl, bu) in [(3, 2), (1, 4)] {
        let n = 17;
        let a: BandMatrix<f64> = random_band(&mut rng, n, 3, 2, false);
        let b: BandMatrix<f64> = random_band(&mut rng, n, bl, bu, false);
        let x: Vec<f64> = (0..n).map(|_| rng.uniform()).collect();
        let z: Vec<f64> = (0..n).map(|_| rng.uniform()).collect();
        let y0: Vec<f64> = (0..n).map(|_| rng.uniform()).collect();
        let mut y = y0.clone();
        BandMatrix::mul_add_pair(&a, &b, &mut y, |j| (x[j], z[j]));
        let want = nalgebra::DVector::from_column_slice(&y0)
            + a.to_dense() * nalgebra::DVector::from_column_slice(&x)
            + b.to_dense() * nalgebra::DVector::from_column_slice(&z);
        for (got, want) in y.iter().zip(want.iter()) {
            assert!(
                (got - want).abs() < 1e-13 * want.abs().max(1.0),
                "{got} vs {want}"
            );
        }
    }
}

fn norm<T: Scalar>(v: &[T]) -> f64 {
    v.iter().map(|x| x.modulus_squared()).sum::<f64>().sqrt()
}

/// LAPACK `xGBTRS` as written: column sweeps, `U` over all `kl + ku`
/// superdiagonals.
fn column_sweeps<T: Scalar>(lu: &BandLu<T>, b: &mut [T]) {
    let (n, kl, ldab) = (lu.n, lu.kl, lu.ldab);
    let kv = kl + lu.ku;
    for j in 0..n.saturating_sub(1) {
        let l = lu.ipiv[j];
        b.swap(l, j);
        for i in j + 1..=(j + kl).min(n - 1) {
            b[i] -= lu.data[j * ldab + kv + i - j] * b[j];
        }
    }
    for j in (0..n).rev() {
        b[j] *= lu.data[j * ldab + kv];
        for i in j.saturating_sub(kv)..j {
            b[i] -= lu.data[j * ldab + kv + i - j] * b[j];
        }
    }
}

fn check_solve<T: Random>(seed: u64, n: usize, kl: usize, ku: usize, pivot: bool) {
    let mut rng = Rng(seed);
    let a: BandMatrix<T> = random_band(&mut rng, n, kl, ku, pivot);
    let b: Vec<T> = (0..n).map(|_| T::random(&mut rng)).collect();
    let lu = a.lu().expect("nonsingular");
    if pivot {
        let swaps = lu.ipiv.iter().enumerate().filter(|&(j, &p)| p != j).count();
        assert!(swaps >= (n - 1) / 2, "only {swaps} row interchanges");
    }
    let mut x = b.clone();
    lu.solve_in_place(&mut x);
    // Row by row over U's filled band, the values of LAPACK's column
    // sweeps over the whole `kl + ku` band (the same operations in the same
    // order, and products with exact zeros); without interchanges that
    // band is `ku` wide.
    assert_eq!(
        lu.interchanged,
        lu.ipiv.iter().enumerate().any(|(j, &p)| p != j)
    );
    assert!(lu.u_width <= kl + ku && (lu.interchanged || lu.u_width == ku.min(n - 1)));
    let mut swept = b.clone();
    column_sweeps(&lu, &mut swept);
    assert!(
        x.iter().zip(&swept).all(|(p, q)| p == q),
        "differs from the column sweeps"
    );
    let mut ax = vec![T::zero(); n];
    a.mul_vec(&x, &mut ax);
    let r: Vec<T> = ax.iter().zip(&b).map(|(&p, &q)| p - q).collect();
    let rel = norm(&r) / norm(&b);
    assert!(rel < 1e-12, "n={n} kl={kl} ku={ku}: residual {rel:e}");
    let dense = a.to_dense().lu();
    let xd = dense
        .solve(&nalgebra::DVector::from_column_slice(&b))
        .expect("dense nonsingular");
    let diff: Vec<T> = x.iter().zip(xd.iter()).map(|(&p, &q)| p - q).collect();
    let rel_x = norm(&diff) / norm(&x);
    assert!(
        rel_x < 1e-9,
        "n={n} kl={kl} ku={ku}: differs from dense by {rel_x:e}"
    );
}

const SHAPES: [(usize, usize, usize); 10] = [
    (1, 0, 0),
    (7, 0, 0),
    (9, 1, 1),
    (50, 3, 2),
    (60, 0, 4),
    (60, 4, 0),
    (200, 7, 7),
    (300, 15, 10),
    (120, 2, 13),
    (12, 20, 20),
];

#[test]
fn band_lu_matches_dense_real() {
    for (s, &(n, kl, ku)) in SHAPES.iter().enumerate() {
        check_solve::<f64>(11 + s as u64, n, kl, ku, false);
    }
}

#[test]
fn band_lu_matches_dense_complex() {
    for (s, &(n, kl, ku)) in SHAPES.iter().enumerate() {
        check_solve::<Complex<f64>>(101 + s as u64, n, kl, ku, false);
    }
}

#[test]
fn band_lu_requires_pivoting() {
    for (s, &(n, kl, ku)) in SHAPES.iter().enumerate() {
        if kl > 0 && ku > 0 {
            check_solve::<f64>(1001 + s as u64, n, kl, ku, true);
            check_solve::<Complex<f64>>(2001 + s as u64, n, kl, ku, true);
        }
    }
}

#[test]
fn band_lu_permutation_matrix() {
    // Anti-diagonal pairs: every pivot must come from a row interchange.
    let n = 10;
    let mut a = BandMatrix::<f64>::new(n, 1, 1);
    for k in (0..n).step_by(2) {
        a.set(k, k + 1, 2.0);
        a.set(k + 1, k, 3.0);
    }
    let lu = a.lu().expect("nonsingular");
    let mut x: Vec<f64> = (0..n).map(|i| i as f64 + 1.0).collect();
    lu.solve_in_place(&mut x);
    for k in (0..n).step_by(2) {
        assert!((x[k] - (k as f64 + 2.0) / 3.0).abs() < 1e-15);
        assert!((x[k + 1] - (k as f64 + 1.0) / 2.0).abs() < 1e-15);
    }
}

#[test]
fn singular_zero_column() {
    let mut a = BandMatrix::<f64>::new(6, 1, 1);
    for i in 0..6_usize {
        for j in i.saturating_sub(1)..=(i + 1).min(5) {
            if j != 3 {
                a.set(i, j, 1.0 + i as f64 + 2.0 * j as f64);
            }
        }
    }
    assert_eq!(a.lu().err(), Some(LinalgError::Singular { column: 3 }));
}

#[test]
fn singular_neumann_laplacian() {
    // Rows sum to zero: exactly singular, last pivot is pure round-off.
    let n = 50;
    let mut a = BandMatrix::<Complex<f64>>::new(n, 1, 1);
    for i in 0..n {
        let d = if i == 0 || i == n - 1 { 1.0 } else { 2.0 };
        a.set(i, i, Complex::new(d, 0.0));
        if i + 1 < n {
            a.set(i, i + 1, Complex::new(-1.0, 0.0));
            a.set(i + 1, i, Complex::new(-1.0, 0.0));
        }
    }
    assert_eq!(a.lu().err(), Some(LinalgError::Singular { column: n - 1 }));
    assert_eq!(
        BandMatrix::<f64>::new(3, 1, 1).lu().err(),
        Some(LinalgError::Singular { column: 0 })
    );
}

#[test]
fn non_finite_rejected() {
    let mut rng = Rng(5);
    let mut a: BandMatrix<f64> = random_band(&mut rng, 20, 2, 3, false);
    a.set(7, 9, f64::NAN);
    assert_eq!(a.lu().err(), Some(LinalgError::NotFinite));
    let mut c: BandMatrix<Complex<f64>> = random_band(&mut rng, 20, 2, 3, false);
    c.set(4, 3, Complex::new(1.0, f64::INFINITY));
    assert_eq!(c.lu().err(), Some(LinalgError::NotFinite));
}

#[test]
fn mul_vec_matches_dense() {
    let mut rng = Rng(77);
    for &(n, kl, ku) in &SHAPES {
        let a: BandMatrix<Complex<f64>> = random_band(&mut rng, n, kl, ku, false);
        let x: Vec<Complex<f64>> = (0..n).map(|_| Complex::random(&mut rng)).collect();
        let mut y = vec![Complex::new(0.0, 0.0); n];
        a.mul_vec(&x, &mut y);
        let yd = a.to_dense() * nalgebra::DVector::from_column_slice(&x);
        for (p, q) in y.iter().zip(yd.iter()) {
            assert!((p - q).norm() < 1e-13, "n={n} kl={kl} ku={ku}");
        }
    }
}

#[test]
#[should_panic(expected = "dimension mismatch")]
fn mul_vec_of_the_wrong_length_panics() {
    let a = BandMatrix::<f64>::new(4, 1, 1);
    a.mul_vec(&[1.0; 4], &mut [0.0; 3]);
}

#[test]
#[should_panic(expected = "outside the band")]
fn add_outside_the_band_panics() {
    BandMatrix::<f64>::new(5, 1, 2).add(3, 0, 1.0);
}

#[test]
#[should_panic(expected = "not contained")]
fn scale_add_of_a_wider_band_panics() {
    let a = BandMatrix::<f64>::new(5, 1, 2);
    BandMatrix::<f64>::new(5, 1, 1).scale_add(1.0, &a);
}

#[test]
fn band_access_and_scale_add() {
    let mut a = BandMatrix::<f64>::new(5, 1, 2);
    assert_eq!((a.n(), a.kl(), a.ku()), (5, 1, 2));
    a.set(1, 0, 2.0);
    a.add(1, 0, 0.5);
    a.set(0, 2, 4.0);
    assert_eq!(a.get(1, 0), 2.5);
    assert_eq!(a.get(0, 2), 4.0);
    assert_eq!(a.get(4, 0), 0.0);
    assert_eq!(a.get(9, 9), 0.0);

    let mut b = BandMatrix::<f64>::new(5, 1, 1);
    b.set(1, 0, 1.0);
    b.set(2, 2, 3.0);
    a.scale_add(2.0, &b);
    assert_eq!(a.get(1, 0), 4.5);
    assert_eq!(a.get(2, 2), 6.0);

    let z = a.zeroed_like();
    assert_eq!((z.n(), z.kl(), z.ku()), (5, 1, 2));
    assert!(z.to_dense().iter().all(|&v| v == 0.0));

    let c = map_to_complex(&a);
    assert_eq!(c.get(0, 2), Complex::new(4.0, 0.0));
    assert_eq!(c.to_dense().map(|v| v.re), a.to_dense());
}

#[test]
fn factor_real_combination_matches_complex_copies() {
    let mut rng = Rng(5);
    let n = 40;
    let k: BandMatrix<f64> = random_band(&mut rng, n, 3, 2, false);
    let d: BandMatrix<f64> = random_band(&mut rng, n, 2, 2, false);
    let m: BandMatrix<f64> = random_band(&mut rng, n, 1, 1, false);
    let (s, t) = (Complex::new(0.3, -1.2), Complex::new(-0.7, 0.4));
    let mut q = map_to_complex(&k);
    q.scale_add(s, &map_to_complex(&d));
    q.scale_add(t, &map_to_complex(&m));
    let reference = q.lu().expect("nonsingular");
    let mut lu = BandLu::default();
    for _ in 0..2 {
        lu.factor_real_combination(&[(Complex::new(1.0, 0.0), &k), (s, &d), (t, &m)])
            .expect("nonsingular");
        assert_eq!(lu.data, reference.data);
        assert_eq!(lu.ipiv, reference.ipiv);
    }
    // lu_into reuses the storage of a wider factorization.
    let narrow: BandMatrix<Complex<f64>> = map_to_complex(&m);
    narrow.lu_into(&mut lu).expect("nonsingular");
    let direct = narrow.lu().expect("nonsingular");
    assert_eq!((lu.data, lu.ipiv), (direct.data, direct.ipiv));
}
