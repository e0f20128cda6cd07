//! Condensation of a bearing's internal coordinates (pad tilts, massless) onto
//! its journal: the Schur complement `K_c = K_jj − K_jp K_pp⁻¹ K_pj` of the
//! bearing's effective Jacobian `K = K_b + a1 C_b` (Newmark `a1 = 2/h`).

use crate::bearing::BearingEval;

use super::dense::{lu_in_place, lu_solve};

/// Condense a bearing's internal coordinates (pad tilts) onto its journal: with
/// `K = K_b + a1 C_b` from `ev` (journal first, then `m` internal), returns
/// `K_c = K_jj − K_jp K_pp⁻¹ K_pj` (row-major 2×2) and `w = K_jp K_pp⁻¹ (−F_p)`;
/// `x` receives the three columns `K_pp⁻¹ [K_pj | −F_p]` and `kpp`, `piv` are
/// workspace. A diagonal `K_pp` (pads acting on the journal only) is divided
/// directly. `None` when `K_pp` is singular.
pub(super) fn condense_internal(
    ev: &BearingEval,
    a1: f64,
    kpp: &mut [f64],
    piv: &mut [usize],
    x: &mut [f64],
) -> Option<([f64; 4], [f64; 2])> {
    let n2 = ev.n();
    let mi = n2 - 2;
    let keff = |i: usize, j: usize| ev.stiffness[i * n2 + j] + a1 * ev.damping[i * n2 + j];
    let mut kc = [keff(0, 0), keff(0, 1), keff(1, 0), keff(1, 1)];
    let mut wv = [0.0; 2];
    if mi == 0 {
        return Some((kc, wv));
    }
    // Pads that act on the journal only leave the off-diagonal pad block zero:
    // found without forming the block (the scan stops at the first coupling).
    let uncoupled = (0..mi).all(|r| (0..mi).all(|c| r == c || keff(2 + r, 2 + c) == 0.0));
    for r in 0..mi {
        x[r] = keff(2 + r, 0);
        x[mi + r] = keff(2 + r, 1);
        x[2 * mi + r] = -ev.force[2 + r];
    }
    if uncoupled {
        for r in 0..mi {
            let d = keff(2 + r, 2 + r);
            if d == 0.0 || !d.is_finite() {
                return None;
            }
            for column in 0..3 {
                x[column * mi + r] /= d;
            }
        }
    } else {
        for r in 0..mi {
            for c in 0..mi {
                kpp[r * mi + c] = keff(2 + r, 2 + c);
            }
        }
        if !lu_in_place(kpp, mi, piv) {
            return None;
        }
        for column in x.chunks_exact_mut(mi) {
            lu_solve(kpp, mi, piv, column);
        }
    }
    for i in 0..2 {
        for r in 0..mi {
            let kjp = keff(i, 2 + r);
            kc[2 * i] -= kjp * x[r];
            kc[2 * i + 1] -= kjp * x[mi + r];
            wv[i] += kjp * x[2 * mi + r];
        }
    }
    Some((kc, wv))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The condensed 2×2 stiffness and load of a bearing with internal
    /// coordinates equal the dense Schur complement, for coupled (LU) and
    /// uncoupled (diagonal) internal blocks.
    #[test]
    fn internal_coordinates_condense_to_the_schur_complement() {
        let mut seed = 11u64;
        let mut rand = || {
            seed = seed
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            (seed >> 11) as f64 / (1u64 << 53) as f64 - 0.5
        };
        for coupled in [true, false] {
            let (m, a1) = (3, 7.0);
            let n2 = 2 + m;
            let mut ev = BearingEval::new(n2);
            for i in 0..n2 {
                ev.force[i] = rand();
                for j in 0..n2 {
                    let internal_pair = i >= 2 && j >= 2 && i != j;
                    let (k, c) = if internal_pair && !coupled {
                        (0.0, 0.0)
                    } else {
                        (rand() + if i == j { 3.0 } else { 0.0 }, rand())
                    };
                    ev.stiffness[i * n2 + j] = k;
                    ev.damping[i * n2 + j] = c;
                }
            }
            let (mut kpp, mut piv, mut x) = (vec![0.0; m * m], vec![0; m], vec![0.0; 3 * m]);
            let (kc, wv) = condense_internal(&ev, a1, &mut kpp, &mut piv, &mut x).unwrap();
            let k = nalgebra::DMatrix::from_fn(n2, n2, |i, j| {
                ev.stiffness[i * n2 + j] + a1 * ev.damping[i * n2 + j]
            });
            let kjj = k.view((0, 0), (2, 2));
            let kjp = k.view((0, 2), (2, m));
            let kpp_inv = k.view((2, 2), (m, m)).into_owned().try_inverse().unwrap();
            let schur = kjj - kjp * &kpp_inv * k.view((2, 0), (m, 2));
            let fp = nalgebra::DVector::from_fn(m, |r, _| -ev.force[2 + r]);
            let load = kjp * &kpp_inv * fp;
            for i in 0..2 {
                for j in 0..2 {
                    assert!(
                        (kc[2 * i + j] - schur[(i, j)]).abs() < 1e-12,
                        "coupled {coupled}"
                    );
                }
                assert!((wv[i] - load[i]).abs() < 1e-12, "coupled {coupled}");
            }
        }
    }
}
