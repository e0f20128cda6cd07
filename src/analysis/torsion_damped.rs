//! Damped torsional eigenvalues: the roots `s` of
//! `Q(s) x = (s² M + s C + K) x = 0` that continue the undamped modes, with
//! `C = C_v + C_ζ`:
//!
//! - `C_v`, the viscous dampers (N·m·s/rad) of the couplings and shaft
//!   sections in parallel with their stiffness (`TorsionalRotor::damping`);
//! - `C_ζ = Σ_j 2 ζ_m ω_j (M φ_j)(M φ_j)ᵀ` over the listed modes `φ_j`
//!   (`M`-normalized), the modal damping ratio `ζ_m` of `[torsion]`: alone it
//!   gives each listed mode `s = ω_j (−ζ_m + i √(1 − ζ_m²))` exactly, and no
//!   damping to the modes not listed.
//!
//! Each root comes from Rayleigh-functional iteration (Ruhe, *Algorithms for
//! the nonlinear eigenvalue problem*, SIAM J. Numer. Anal. 10, 1973): `s`
//! solves the scalar quadratic `xᵀ Q(s) x = 0` (`Q` is complex symmetric, so
//! `xᵀ` is the left vector), then `x ← Q(s)⁻¹ Q'(s) x`, from the undamped mode
//! and `s₀ = ω (−ζ₀ + i √(1 − ζ₀²))` with its proportional estimate `ζ₀`;
//! `Q(s)⁻¹` is a tridiagonal complex solve, with `C_ζ` through the
//! Sherman–Morrison–Woodbury identity. Without any damping nothing is solved:
//! `s = i ω` exactly.
//!
//! The undamped modes come in as [`Pairs`]; [`m_normalized`] and
//! [`quadratic`] are the `M`-products both this file and
//! [`super::torsion`] use.

use nalgebra::{Complex, DMatrix, DVector};

use crate::linalg::{BandLu, BandMatrix, LinalgError, map_to_complex};
use crate::model::RotorModel;
use crate::rotor::torsion::TorsionalRotor;

/// Natural frequencies (rad/s, ascending) and shapes on the free DOFs (any
/// scale: the Arnoldi ones as they come, for results unchanged to the bit).
pub(super) type Pairs = Vec<(f64, Vec<f64>)>;

/// `v / √(vᵀ M v)`.
pub(super) fn m_normalized(mass: &BandMatrix<f64>, mut v: Vec<f64>) -> Vec<f64> {
    let norm = quadratic(mass, &v, &v).sqrt();
    v.iter_mut().for_each(|x| *x /= norm);
    v
}

/// `xᵀ A y`.
pub(super) fn quadratic(a: &BandMatrix<f64>, x: &[f64], y: &[f64]) -> f64 {
    let mut ay = vec![0.0; y.len()];
    a.mul_vec(y, &mut ay);
    x.iter().zip(&ay).map(|(p, q)| p * q).sum()
}

type C64 = Complex<f64>;

/// Relative step of `s` at which the iteration stops (it converges cubically
/// near a simple root: the step after this one is far below round-off).
const STEP: f64 = 1e-12;

/// The damped eigenvalue of each undamped mode in `pairs` (ascending ω).
pub(super) fn damped_eigenvalues(
    model: &RotorModel,
    chain: &TorsionalRotor,
    pairs: &Pairs,
) -> Result<Vec<C64>, LinalgError> {
    let n = chain.dof_count();
    let zeta = model.torsional_damping_ratio;
    let viscous = (0..n).any(|i| chain.damping.get(i, i) != 0.0);
    if zeta == 0.0 && !viscous {
        return Ok(pairs.iter().map(|(w, _)| C64::new(0.0, *w)).collect());
    }
    let phis: Vec<Vec<f64>> = pairs
        .iter()
        .map(|(_, v)| m_normalized(&chain.mass, v.clone()))
        .collect();
    // C_ζ = U D Uᵀ: columns M φ_j, weights 2 ζ_m ω_j.
    let (u, d): (Vec<Vec<C64>>, Vec<f64>) = if zeta > 0.0 {
        phis.iter()
            .zip(pairs)
            .map(|(phi, (w, _))| {
                let mut mphi = vec![0.0; n];
                chain.mass.mul_vec(phi, &mut mphi);
                (real_to_complex(&mphi), 2.0 * zeta * w)
            })
            .unzip()
    } else {
        (Vec::new(), Vec::new())
    };
    let op = Quadratic {
        m: map_to_complex(&chain.mass),
        c: map_to_complex(&chain.damping),
        k: map_to_complex(&chain.stiffness),
        u,
        d,
    };
    let mut out = Vec::with_capacity(pairs.len());
    for (j, (phi, (w, _))) in phis.iter().zip(pairs).enumerate() {
        let z0 = (quadratic(&chain.damping, phi, phi) / (2.0 * w) + zeta).min(0.99);
        let start = C64::new(-z0 * w, w * (1.0 - z0 * z0).sqrt());
        match op.root(start, real_to_complex(phi))? {
            Some(s) => out.push(s),
            None => {
                return Err(LinalgError::NotConverged {
                    converged: j,
                    wanted: pairs.len(),
                });
            }
        }
    }
    Ok(out)
}

fn real_to_complex(x: &[f64]) -> Vec<C64> {
    x.iter().map(|&v| C64::new(v, 0.0)).collect()
}

/// `Q(s) = s² M + s (C + U D Uᵀ) + K` on the free twist DOFs.
struct Quadratic {
    m: BandMatrix<C64>,
    c: BandMatrix<C64>,
    k: BandMatrix<C64>,
    u: Vec<Vec<C64>>,
    d: Vec<f64>,
}

/// `xᵀ y` without conjugation.
fn dot(x: &[C64], y: &[C64]) -> C64 {
    x.iter().zip(y).map(|(a, b)| a * b).sum()
}

impl Quadratic {
    /// `A x` of a complex band matrix.
    fn mul(a: &BandMatrix<C64>, x: &[C64]) -> Vec<C64> {
        let mut y = vec![C64::new(0.0, 0.0); x.len()];
        a.mul_vec(x, &mut y);
        y
    }

    /// `(C + U D Uᵀ) x`.
    fn damp(&self, x: &[C64]) -> Vec<C64> {
        let mut y = Self::mul(&self.c, x);
        for (u, d) in self.u.iter().zip(&self.d) {
            let a = dot(u, x) * *d;
            y.iter_mut().zip(u).for_each(|(p, q)| *p += a * q);
        }
        y
    }

    /// The root of `xᵀ Q(s) x = 0` nearest `s` (the numerically stable pair
    /// of the quadratic formula).
    fn rayleigh(&self, x: &[C64], s: C64) -> C64 {
        let a = dot(x, &Self::mul(&self.m, x));
        let b = dot(x, &self.damp(x));
        let c = dot(x, &Self::mul(&self.k, x));
        let disc = (b * b - a * c * 4.0).sqrt();
        let q = if (b.conj() * disc).re >= 0.0 {
            -(b + disc) * 0.5
        } else {
            -(b - disc) * 0.5
        };
        let (r1, r2) = (q / a, c / q);
        if (r1 - s).norm() <= (r2 - s).norm() {
            r1
        } else {
            r2
        }
    }

    /// `Q(s)⁻¹ r` from the factor of `T = s² M + s C + K`: Woodbury,
    /// `Q⁻¹ = T⁻¹ − T⁻¹U (I + s D Uᵀ T⁻¹ U)⁻¹ s D Uᵀ T⁻¹`.
    fn solve(&self, lu: &BandLu<C64>, s: C64, mut r: Vec<C64>) -> Result<Vec<C64>, LinalgError> {
        lu.solve_in_place(&mut r);
        if self.u.is_empty() {
            return Ok(r);
        }
        let w: Vec<Vec<C64>> = self
            .u
            .iter()
            .map(|u| {
                let mut x = u.clone();
                lu.solve_in_place(&mut x);
                x
            })
            .collect();
        let k = self.u.len();
        let g = DMatrix::from_fn(k, k, |i, j| {
            let eye = if i == j { 1.0 } else { 0.0 };
            C64::new(eye, 0.0) + s * self.d[i] * dot(&self.u[i], &w[j])
        });
        let h = DVector::from_fn(k, |i, _| s * self.d[i] * dot(&self.u[i], &r));
        let z = g
            .lu()
            .solve(&h)
            .ok_or(LinalgError::Singular { column: 0 })?;
        for (wj, zj) in w.iter().zip(z.iter()) {
            r.iter_mut().zip(wj).for_each(|(p, q)| *p -= zj * q);
        }
        Ok(r)
    }

    /// Rayleigh-functional iteration from `(s, x)`: the root, or `None`
    /// when 60 steps do not settle it.
    fn root(&self, mut s: C64, mut x: Vec<C64>) -> Result<Option<C64>, LinalgError> {
        for iteration in 0..60 {
            let next = self.rayleigh(&x, s);
            let step = (next - s).norm();
            s = next;
            if !s.is_finite() {
                return Err(LinalgError::NotFinite);
            }
            // The first functional of the undamped mode is the start itself
            // (`s₀` is its root): only a step after a new `x` tells.
            if iteration > 0 && step <= STEP * s.norm() {
                return Ok(Some(s));
            }
            let mut t = self.k.clone();
            t.scale_add(s, &self.c);
            t.scale_add(s * s, &self.m);
            let lu = match t.lu() {
                Ok(lu) => lu,
                // `s` is a root of `det T` to round-off: without modal
                // damping (`Q = T`) that is the answer.
                Err(LinalgError::Singular { .. }) if self.u.is_empty() => return Ok(Some(s)),
                Err(e) => return Err(e),
            };
            // Q'(s) x = (2 s M + C + U D Uᵀ) x.
            let mx = Self::mul(&self.m, &x);
            let rhs: Vec<C64> = self
                .damp(&x)
                .iter()
                .zip(&mx)
                .map(|(a, b)| a + b * s * 2.0)
                .collect();
            let y = self.solve(&lu, s, rhs)?;
            let peak = y.iter().fold(0.0, |a: f64, b| a.max(b.norm()));
            if !(peak.is_finite() && peak > 0.0) {
                return Err(LinalgError::NotFinite);
            }
            x = y.iter().map(|v| v / peak).collect();
        }
        Ok(None)
    }
}
