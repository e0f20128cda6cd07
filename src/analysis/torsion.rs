//! Torsional modes: `K_t φ = ω² M_t φ` on the rotor's torsional chain
//! ([`TorsionalRotor`]), then the damped eigenvalues of
//! `(s² M_t + s C_t + K_t) x = 0` ([`super::torsion_damped`]). A chain whose
//! twist no support fixes has a rigid-body rotation at 0 Hz, which is not a
//! vibration mode and is left out.
//!
//! The undamped eigenvalues come first from shift-invert Arnoldi on
//! `(K − σ M)⁻¹ M` with a small negative shift (so the singular free–free `K`
//! factors), a few banded solves of the tridiagonal system. That shift and
//! the rigid-body filter scale with the stiffest element, so on their own
//! they can miss modes far below it (heavy inertias on a fine mesh, light
//! shafts). The result is therefore checked by a Sturm count (Sylvester's law
//! of inertia, [`eigenvalues_below`]): below the first reported `ω²` lie
//! exactly the rigid-body rotations (`r`, 1 free–free, 0 otherwise), between
//! the `i`-th and the next exactly `r + i` eigenvalues, and just above the last
//! `r + m`. Where any count disagrees (or Arnoldi fails), every wanted
//! eigenvalue is computed again by bisection on the Sturm count of the
//! tridiagonal pencil ([`tridiagonal_eigenvalues_below`], never refusing a
//! shift), which cannot miss one: the `k`-th eigenvalue is the point where the
//! count steps from `k − 1` to `k`, found to the last bit; its shape follows
//! from inverse iteration, orthogonal in `M` to the rigid rotation. The
//! rigid-body rotation is thus identified by its index, not by a threshold on
//! `ω²`. Where the check passes, the Arnoldi results are kept bit for bit.

use super::torsion_damped::{Pairs, damped_eigenvalues, m_normalized, quadratic};
use crate::linalg::{
    ArnoldiOptions, LinalgError, eigenvalues_below, largest_eigenpairs_real,
    tridiagonal_eigenvalues_below,
};
use crate::model::RotorModel;
use crate::rotor::torsion::TorsionalRotor;
use nalgebra::Complex;

/// One torsional mode.
#[derive(Debug, Clone, PartialEq)]
pub struct TorsionalMode {
    /// Undamped natural frequency `ω` (rad/s).
    pub natural_frequency: f64,
    /// Damping ratio `ζ = −Re s/|s|` of the damped eigenvalue (–): 0 without
    /// torsional damping.
    pub damping_ratio: f64,
    /// Damped eigenvalue `s = −ζ ω_n + i ω_d` (1/s) of `s² M + s C + K`, the
    /// root that continues this undamped mode (`i ω` without damping).
    pub eigenvalue: Complex<f64>,
    /// Twist of every node (rad; 0 where fixed), scaled to a largest twist of 1.
    pub shape: Vec<f64>,
}

impl TorsionalMode {
    /// Damped natural frequency `ω_d = Im s` (rad/s).
    pub fn damped_frequency(&self) -> f64 {
        self.eigenvalue.im
    }
}

/// The lowest `count` elastic torsional modes of `model`, ascending: none
/// missing (checked by a Sturm count), each with its damped eigenvalue.
///
/// ```
/// use rotor_bearing::analysis::torsion::torsional_modes;
/// use rotor_bearing::model::RotorModel;
///
/// let path = concat!(env!("CARGO_MANIFEST_DIR"), "/models/hydro_unit.toml");
/// let model = RotorModel::from_file(std::path::Path::new(path))?;
/// let modes = torsional_modes(&model, 2)?;
/// // Generator and runner twisting against each other through the shaft.
/// assert!(modes[0].natural_frequency > 0.0);
/// assert!(modes[0].shape[4] * modes[0].shape[19] < 0.0);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn torsional_modes(
    model: &RotorModel,
    count: usize,
) -> Result<Vec<TorsionalMode>, LinalgError> {
    let chain = TorsionalRotor::new(model);
    let n = chain.dof_count();
    if n == 0 || count == 0 {
        return Ok(Vec::new());
    }
    let rigid = usize::from(n == model.node_count());
    let wanted = count.min(n - rigid);
    let pairs = match arnoldi(&chain, count, rigid == 1) {
        Ok((pairs, next)) if verified(&chain, rigid, wanted, &pairs, next) => pairs,
        _ => bisection(&chain, rigid, wanted)?,
    };
    if pairs.len() != wanted {
        return Err(LinalgError::NotConverged {
            converged: pairs.len(),
            wanted,
        });
    }
    let eigenvalues = damped_eigenvalues(model, &chain, &pairs)?;
    Ok(pairs
        .iter()
        .zip(eigenvalues)
        .map(|((w, v), s)| {
            let peak = v
                .iter()
                .copied()
                .fold(0.0, |a: f64, b| if b.abs() > a.abs() { b } else { a });
            let shape = chain
                .dofs
                .iter()
                .map(|d| d.map_or(0.0, |i| v[i] / peak))
                .collect();
            TorsionalMode {
                natural_frequency: *w,
                damping_ratio: if s.re == 0.0 { 0.0 } else { -s.re / s.norm() },
                eigenvalue: s,
                shape,
            }
        })
        .collect())
}

/// Every elastic torsional mode of `model` with a natural frequency up to
/// `omega` (rad/s) and the first above it (where the chain has one),
/// ascending: how many lie below is a Sturm count of the tridiagonal pencil,
/// so none is missed.
///
/// ```
/// use rotor_bearing::analysis::torsion::torsional_modes_up_to;
/// use rotor_bearing::model::RotorModel;
///
/// let path = concat!(env!("CARGO_MANIFEST_DIR"), "/models/hydro_unit.toml");
/// let model = RotorModel::from_file(std::path::Path::new(path))?;
/// let modes = torsional_modes_up_to(&model, 2.0 * std::f64::consts::TAU * 60.0)?;
/// let last = modes.last().unwrap().natural_frequency;
/// assert!(last > 2.0 * std::f64::consts::TAU * 60.0);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn torsional_modes_up_to(
    model: &RotorModel,
    omega: f64,
) -> Result<Vec<TorsionalMode>, LinalgError> {
    let chain = TorsionalRotor::new(model);
    let n = chain.dof_count();
    if n == 0 {
        return Ok(Vec::new());
    }
    let rigid = usize::from(n == model.node_count());
    let below = tridiagonal_eigenvalues_below(&chain.stiffness, &chain.mass, omega * omega);
    torsional_modes(model, below.saturating_sub(rigid) + 1)
}

/// Shift-invert Arnoldi with the shift and rigid-body filter scaled by the
/// stiffest element (fast; its result is checked by [`verified`]): the
/// lowest `count` modes it finds and the next frequency it found, if any.
fn arnoldi(
    chain: &TorsionalRotor,
    count: usize,
    free_free: bool,
) -> Result<(Pairs, Option<f64>), LinalgError> {
    let n = chain.dof_count();
    // Shift below zero by a fraction of the stiffest element's frequency
    // scale, so that K − σM factors even with the rigid-body mode.
    let scale = element_scale(chain);
    let sigma = -1e-6 * scale;
    let mut shifted = chain.stiffness.clone();
    shifted.scale_add(-sigma, &chain.mass);
    let lu = shifted.lu()?;
    let mut apply = |x: &[f64], y: &mut [f64]| {
        chain.mass.mul_vec(x, y);
        lu.solve_in_place(y);
        Ok(())
    };
    let wanted = (count + usize::from(free_free)).min(n);
    let nev = (2 * wanted + 4).min(n);
    let options = ArnoldiOptions {
        tol: 1e-12,
        ..ArnoldiOptions::default()
    };
    let pairs = largest_eigenpairs_real(n, nev, &mut apply, &options)?;
    let mut modes: Pairs = pairs
        .iter()
        .filter(|p| p.value.re > 0.0)
        .map(|p| {
            let omega2 = 1.0 / p.value.re + sigma;
            let v: Vec<f64> = p.vector.iter().map(|z| z.re).collect();
            (omega2.max(0.0).sqrt(), v)
        })
        // The rigid-body rotation: ω² at round-off of the shift.
        .filter(|(w, _)| *w * *w > 1e-9 * scale)
        .collect();
    modes.sort_by(|a, b| a.0.total_cmp(&b.0));
    let next = modes.get(count).map(|p| p.0);
    modes.truncate(count);
    Ok((modes, next))
}

/// `max K_ii / M_ii` (rad²/s²): the stiffest element's frequency scale.
fn element_scale(chain: &TorsionalRotor) -> f64 {
    (0..chain.dof_count())
        .map(|i| chain.stiffness.get(i, i) / chain.mass.get(i, i).max(f64::MIN_POSITIVE))
        .fold(0.0, f64::max)
}

/// True when the `wanted` reported modes are the lowest elastic ones: the
/// Sturm count of `K − λ M` is `rigid` below half the first `ω²`, `rigid + i`
/// midway between the `i`-th and the next, `rigid + m` midway between the last
/// and the next frequency Arnoldi found (`next`; without one, 1e-6 above the
/// last). A shift that falls on an eigenvalue fails the check.
fn verified(
    chain: &TorsionalRotor,
    rigid: usize,
    wanted: usize,
    pairs: &Pairs,
    next: Option<f64>,
) -> bool {
    if pairs.len() != wanted {
        return false;
    }
    let l: Vec<f64> = pairs.iter().map(|(w, _)| w * w).collect();
    let below = |shift: f64| eigenvalues_below(&chain.stiffness, &chain.mass, shift).ok();
    let mut checks = vec![(0.5 * l[0], rigid)];
    checks.extend((1..l.len()).map(|i| (0.5 * (l[i - 1] + l[i]), rigid + i)));
    let last = l[l.len() - 1];
    let above = next.map_or(last * (1.0 + 1e-6), |w| 0.5 * (last + w * w));
    checks.push((above, rigid + l.len()));
    checks.iter().all(|&(shift, n)| below(shift) == Some(n))
}

/// The elastic eigenvalues `rigid + 1 … rigid + wanted` by bisection on the
/// tridiagonal Sturm count (to adjacent doubles), shapes by inverse iteration.
fn bisection(chain: &TorsionalRotor, rigid: usize, wanted: usize) -> Result<Pairs, LinalgError> {
    let count = |shift: f64| tridiagonal_eigenvalues_below(&chain.stiffness, &chain.mass, shift);
    let mut hi = element_scale(chain).max(1.0);
    while count(hi) < rigid + wanted {
        hi *= 2.0;
        if !hi.is_finite() {
            return Err(LinalgError::NotFinite);
        }
    }
    let mut lo = 0.0;
    let mut pairs: Pairs = Vec::with_capacity(wanted);
    for k in rigid + 1..=rigid + wanted {
        // Invariant: count(lo) < k ≤ count(top); lo starts at the previous
        // eigenvalue's lower end (0 below the first: K is semi-definite).
        let mut top = hi;
        loop {
            let mid = 0.5 * (lo + top);
            if mid <= lo || mid >= top {
                break;
            }
            if count(mid) >= k {
                top = mid;
            } else {
                lo = mid;
            }
        }
        let previous: Vec<&[f64]> = pairs.iter().map(|(_, v)| v.as_slice()).collect();
        let v = inverse_iteration(chain, top, rigid == 1, &previous)?;
        pairs.push((top.sqrt(), v));
    }
    Ok(pairs)
}

/// The `M`-normalized eigenvector at the eigenvalue `lambda` (to round-off):
/// four solves `(K − λ' M) x ← M x` at `λ'` a hair below it (moved further
/// while the factor is singular), orthogonal in `M` to the rigid rotation
/// (free–free) and to the earlier vectors.
fn inverse_iteration(
    chain: &TorsionalRotor,
    lambda: f64,
    free_free: bool,
    previous: &[&[f64]],
) -> Result<Vec<f64>, LinalgError> {
    let n = chain.dof_count();
    let mut offset = 1e-10;
    let lu = loop {
        let mut a = chain.stiffness.clone();
        a.scale_add(-lambda * (1.0 - offset), &chain.mass);
        match a.lu() {
            Ok(lu) => break lu,
            Err(LinalgError::Singular { .. }) if offset < 1e-4 => offset *= 100.0,
            Err(e) => return Err(e),
        }
    };
    let ones = vec![1.0; n];
    let deflate = |x: &mut Vec<f64>| {
        let rigid = free_free.then_some(ones.as_slice());
        for u in rigid.into_iter().chain(previous.iter().copied()) {
            let c = quadratic(&chain.mass, u, x) / quadratic(&chain.mass, u, u);
            x.iter_mut().zip(u).for_each(|(a, b)| *a -= c * b);
        }
    };
    // A start with a part along every mode: no symmetry of the chain hides one.
    let mut x: Vec<f64> = (0..n).map(|i| 1.0 + (1.7 * i as f64).sin()).collect();
    for _ in 0..4 {
        deflate(&mut x);
        let mut y = vec![0.0; n];
        chain.mass.mul_vec(&x, &mut y);
        lu.solve_in_place(&mut y);
        let peak = y.iter().fold(0.0, |a: f64, b| a.max(b.abs()));
        if !(peak.is_finite() && peak > 0.0) {
            return Err(LinalgError::NotFinite);
        }
        x = y.iter().map(|v| v / peak).collect();
    }
    deflate(&mut x);
    Ok(m_normalized(&chain.mass, x))
}
