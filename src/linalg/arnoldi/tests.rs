//! Unit tests of `linalg::arnoldi` (the parent module's `mod tests`).

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
        let pairs =
            largest_eigenpairs(n, 6, &mut apply, &ArnoldiOptions::default()).expect("converged");
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
        let pairs = largest_eigenpairs(n, nev, &mut dense_apply(&a), &ArnoldiOptions::default())
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
    let pairs =
        largest_eigenpairs_real(n, nev, &mut apply, &ArnoldiOptions::default()).expect("converged");
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
