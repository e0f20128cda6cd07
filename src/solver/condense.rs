//! Condensation of a bearing's internal coordinates (pad tilts, massless) onto
//! its journal: the Schur complement `K_c = K_jj − K_jp K_pp⁻¹ K_pj` of the
//! bearing's effective Jacobian `K = K_b + a1 C_b` (Newmark `a1 = 2/h`).

use crate::bearing::BearingEval;

use super::dense::{lu_in_place, lu_solve};

/// A bearing's internal coordinates (pad tilts) condensed onto its journal,
/// with the factors kept so that a later Newton iteration on the same
/// Jacobians condenses new forces alone ([`Condensation::load`]).
#[derive(Debug, Clone)]
pub(super) struct Condensation {
    /// LU of the pad block `K_pp` (row-major `m × m`, `coupled`), or its
    /// diagonal on the diagonal of this matrix (pads acting on the journal only).
    kpp: Vec<f64>,
    piv: Vec<usize>,
    coupled: bool,
    /// `K_jp`: two rows of `m`.
    kjp: Vec<f64>,
    /// `K_pp⁻¹ [K_pj | −F_p]`: three columns of length `m`.
    pub x: Vec<f64>,
}

impl Condensation {
    /// Buffers for `m` internal coordinates.
    pub fn new(m: usize) -> Self {
        Self {
            kpp: vec![0.0; m * m],
            piv: vec![0; m],
            coupled: false,
            kjp: vec![0.0; 2 * m],
            x: vec![0.0; 3 * m],
        }
    }

    /// Condense a bearing's internal coordinates onto its journal: with
    /// `K = K_b + a1 C_b` from `ev` (journal first, then `m` internal),
    /// returns `K_c = K_jj − K_jp K_pp⁻¹ K_pj` (row-major 2×2) and
    /// `w = K_jp K_pp⁻¹ (−F_p)`, keeping `K_pp`'s factors and `K_jp`. A
    /// diagonal `K_pp` is divided directly. `None` when `K_pp` is singular.
    pub fn condense(&mut self, ev: &BearingEval, a1: f64) -> Option<([f64; 4], [f64; 2])> {
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
        self.coupled = !(0..mi).all(|r| (0..mi).all(|c| r == c || keff(2 + r, 2 + c) == 0.0));
        let x = &mut self.x;
        for r in 0..mi {
            x[r] = keff(2 + r, 0);
            x[mi + r] = keff(2 + r, 1);
            x[2 * mi + r] = -ev.force[2 + r];
        }
        if self.coupled {
            for r in 0..mi {
                for c in 0..mi {
                    self.kpp[r * mi + c] = keff(2 + r, 2 + c);
                }
            }
            if !lu_in_place(&mut self.kpp, mi, &mut self.piv) {
                return None;
            }
            for column in x.chunks_exact_mut(mi) {
                lu_solve(&self.kpp, mi, &self.piv, column);
            }
        } else {
            for r in 0..mi {
                let d = keff(2 + r, 2 + r);
                if d == 0.0 || !d.is_finite() {
                    return None;
                }
                self.kpp[r * mi + r] = d;
                for column in 0..3 {
                    x[column * mi + r] /= d;
                }
            }
        }
        for i in 0..2 {
            for r in 0..mi {
                let kjp = keff(i, 2 + r);
                self.kjp[i * mi + r] = kjp;
                kc[2 * i] -= kjp * x[r];
                kc[2 * i + 1] -= kjp * x[mi + r];
                wv[i] += kjp * x[2 * mi + r];
            }
        }
        Some((kc, wv))
    }

    /// `w = K_jp K_pp⁻¹ (−F_p)` for the generalized forces `force` (journal,
    /// then internal) on the Jacobians of the last [`Condensation::condense`],
    /// whose `K_pp⁻¹ K_pj` columns stay; the `−F_p` column of `x` is replaced.
    pub fn load(&mut self, force: &[f64]) -> [f64; 2] {
        let mi = self.piv.len();
        let mut wv = [0.0; 2];
        if mi == 0 {
            return wv;
        }
        let column = &mut self.x[2 * mi..];
        for (x, f) in column.iter_mut().zip(&force[2..]) {
            *x = -f;
        }
        if self.coupled {
            lu_solve(&self.kpp, mi, &self.piv, column);
        } else {
            for (r, x) in column.iter_mut().enumerate() {
                *x /= self.kpp[r * mi + r];
            }
        }
        for (i, w) in wv.iter_mut().enumerate() {
            for (kjp, x) in self.kjp[i * mi..(i + 1) * mi].iter().zip(column.iter()) {
                *w += kjp * x;
            }
        }
        wv
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The condensed 2×2 stiffness and load of a bearing with internal
    /// coordinates equal the dense Schur complement, for coupled (LU) and
    /// uncoupled (diagonal) internal blocks, and the load of new forces on
    /// the kept factors equals the Schur complement's load on the old `K`.
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
            let mut condensation = Condensation::new(m);
            let (kc, wv) = condensation.condense(&ev, a1).unwrap();
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
            // New forces on the kept Jacobians: the load and the `−F_p` column
            // for them, `K_pp⁻¹ K_pj` unchanged, whatever `ev`'s Jacobians now hold.
            let kept: Vec<f64> = condensation.x[..2 * m].to_vec();
            let force: Vec<f64> = (0..n2).map(|_| rand()).collect();
            ev.stiffness.fill(f64::NAN);
            let wv = condensation.load(&force);
            let fp = nalgebra::DVector::from_fn(m, |r, _| -force[2 + r]);
            let column = &kpp_inv * &fp;
            let load = kjp * column.clone();
            for i in 0..2 {
                assert!((wv[i] - load[i]).abs() < 1e-12, "coupled {coupled}");
            }
            for r in 0..m {
                assert!((condensation.x[2 * m + r] - column[r]).abs() < 1e-12);
            }
            assert_eq!(condensation.x[..2 * m], kept[..]);
        }
    }
}
