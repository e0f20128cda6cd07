//! Torsional modes: `K_t φ = ω² M_t φ` on the rotor's torsional chain
//! ([`TorsionalRotor`]), undamped (the couplings' damping gives each mode a
//! damping ratio from its modal damping, `ζ = φᵀ C φ / (2 ω φᵀ M φ)`). A
//! chain whose twist no support fixes has a rigid-body rotation at 0 Hz,
//! which is not a vibration mode and is left out. The eigenvalues come from
//! shift-invert Arnoldi on `(K − σ M)⁻¹ M` with a small negative shift
//! (so the singular free–free `K` factors), a few banded solves of the
//! tridiagonal system: O(n) for any rotor size.

use crate::linalg::{ArnoldiOptions, LinalgError, largest_eigenpairs_real};
use crate::model::RotorModel;
use crate::rotor::torsion::TorsionalRotor;

/// One torsional mode.
#[derive(Debug, Clone, PartialEq)]
pub struct TorsionalMode {
    /// Natural frequency (rad/s).
    pub natural_frequency: f64,
    /// Modal damping ratio from the couplings' damping (–).
    pub damping_ratio: f64,
    /// Twist of every node (rad; 0 where fixed), scaled to a largest twist of 1.
    pub shape: Vec<f64>,
}

/// The lowest `count` elastic torsional modes of `model`, ascending.
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
    let free_free = n == model.node_count();
    // Shift below zero by a fraction of the stiffest element's frequency
    // scale, so that K − σM factors even with the rigid-body mode.
    let scale = (0..n)
        .map(|i| chain.stiffness.get(i, i) / chain.mass.get(i, i).max(f64::MIN_POSITIVE))
        .fold(0.0, f64::max);
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
    let mut modes: Vec<TorsionalMode> = pairs
        .iter()
        .filter(|p| p.value.re > 0.0)
        .map(|p| {
            let omega2 = 1.0 / p.value.re + sigma;
            let v: Vec<f64> = p.vector.iter().map(|z| z.re).collect();
            (omega2.max(0.0).sqrt(), v)
        })
        // The rigid-body rotation: ω² at round-off of the shift.
        .filter(|(w, _)| *w * *w > 1e-9 * scale)
        .map(|(w, v)| {
            let mut mv = vec![0.0; n];
            chain.mass.mul_vec(&v, &mut mv);
            let mass: f64 = v.iter().zip(&mv).map(|(a, b)| a * b).sum();
            chain.damping.mul_vec(&v, &mut mv);
            let damping: f64 = v.iter().zip(&mv).map(|(a, b)| a * b).sum();
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
                natural_frequency: w,
                damping_ratio: damping / (2.0 * w * mass),
                shape,
            }
        })
        .collect();
    modes.sort_by(|a, b| a.natural_frequency.total_cmp(&b.natural_frequency));
    modes.truncate(count);
    Ok(modes)
}
