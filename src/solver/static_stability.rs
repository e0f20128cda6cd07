//! Is a static equilibrium stable? With elements of negative direct stiffness
//! (a seal or table bearing with negative `kxx`, magnetic pull) the static
//! solve can converge to an equilibrium the machine cannot hold: the tangent
//! stiffness `K_t = K + E K_c Eᵀ` (bearings condensed statically) then has a
//! real eigenvalue `λ ≤ 0` — a mode along which the net stiffness is
//! negative, so the rotor diverges (buckles sideways) from rest. The check
//! finds the eigenvalues of `K_t` nearest zero and nearest minus the
//! culprits' stiffness by shift-invert Arnoldi (a few banded solves each)
//! and refuses the equilibrium with the net
//! stiffness `λ`, where its mode is largest and the elements of negative
//! stiffness that cause it. It runs only when some element has a negative
//! direct stiffness, so every other model is untouched.

use crate::linalg::{ArnoldiOptions, largest_eigenpairs_real};
use crate::rotor::{Dof, Rotor};

use super::error::SolverError;
use super::sites::{Sites, add_coupling};

/// The elements of negative direct stiffness at the equilibrium just solved
/// (sites evaluated there) with their most negative direct entry (N/m),
/// bearings in model order.
fn negative_elements(rotor: &Rotor, sites: &Sites) -> Vec<(String, f64)> {
    // Below round-off of the rotor's own stiffness a negative entry is no
    // element's doing (an unloaded film's zero).
    let floor = -1e-9
        * (0..rotor.dof_count())
            .map(|i| rotor.stiffness.get(i, i).abs())
            .fold(0.0, f64::max);
    let mut out: Vec<(String, f64)> = rotor.negative_stiffness.clone();
    for site in &sites.list {
        let k = site.eval.k(0, 0).min(site.eval.k(1, 1));
        if k < floor {
            out.push((site.name.clone(), k));
        }
    }
    out
}

/// Refuse the equilibrium of `sites` (evaluated at it) at `speed` (rad/s) if
/// it is statically unstable; `k_rest` is the statics' journal regularization.
pub(super) fn check(
    rotor: &Rotor,
    sites: &mut Sites,
    speed: f64,
    k_rest: f64,
) -> Result<(), SolverError> {
    let culprits = negative_elements(rotor, sites);
    if culprits.is_empty() {
        return Ok(());
    }
    let n = rotor.dof_count();
    let mut a = rotor.stiffness.clone();
    for site in &mut sites.list {
        let Some((kc, _)) = site.condensation.condense(&site.eval, 0.0) else {
            continue;
        };
        for (i, ci) in site.journal.iter().enumerate() {
            for (j, cj) in site.journal.iter().enumerate() {
                add_coupling(&mut a, ci, cj, kc[2 * i + j]);
            }
            a.add(ci.journal, ci.journal, k_rest);
        }
    }
    let scale = (0..n).map(|i| a.get(i, i).abs()).fold(0.0, f64::max);
    let names = culprits
        .iter()
        .map(|(name, k)| format!("{name} ({} N/m)", short(*k)))
        .collect::<Vec<_>>()
        .join(", ");
    let rpm = speed * 30.0 / std::f64::consts::PI;
    // The eigenvalues nearest zero (a barely negative net stiffness) and
    // nearest the culprits' own stiffness (a strongly negative one, beyond
    // the small positive ones of loosely held journals).
    let strongest = culprits.iter().map(|(_, k)| k.abs()).sum::<f64>();
    let mut unstable: Option<(f64, Vec<nalgebra::Complex<f64>>)> = None;
    for shift in [0.0, -strongest] {
        let mut shifted = a.clone();
        for i in 0..n {
            shifted.add(i, i, -shift);
        }
        let Ok(lu) = shifted.lu() else {
            if shift == 0.0 {
                return Err(SolverError::StaticallyUnstable(format!(
                    "at {} rpm the machine has no net static stiffness (singular): the negative stiffness of {names} cancels what holds it",
                    short(rpm)
                )));
            }
            continue;
        };
        let mut apply = |x: &[f64], y: &mut [f64]| {
            y.copy_from_slice(x);
            lu.solve_in_place(y);
            Ok(())
        };
        let nev = n.min(8);
        let options = ArnoldiOptions {
            tol: 1e-9,
            ..ArnoldiOptions::default()
        };
        let pairs =
            largest_eigenpairs_real(n, nev, &mut apply, &options).map_err(SolverError::Linalg)?;
        for p in &pairs {
            let lambda = 1.0 / p.value.re + shift;
            let real = p.value.im.abs() <= 1e-9 * p.value.norm();
            if real && lambda < -1e-9 * scale && unstable.as_ref().is_none_or(|u| lambda < u.0) {
                unstable = Some((lambda, p.vector.clone()));
            }
        }
    }
    let Some((lambda, vector)) = unstable else {
        return Ok(());
    };
    let vector = &vector;
    let at = (0..n)
        .filter(|&i| rotor.dofs.is_displacement(i))
        .max_by(|&i, &j| vector[i].norm().total_cmp(&vector[j].norm()));
    let place = match at.map(|i| rotor.dofs.kind(i)) {
        Some(Dof::Node { node, k }) => format!(" at node {} ({})", node + 1, ["x", "y"][k]),
        Some(Dof::Pedestal { pedestal, k }) => format!(
            " at pedestal {} ({})",
            rotor.model.pedestals[pedestal].name,
            ["x", "y"][k]
        ),
        _ => String::new(),
    };
    Err(SolverError::StaticallyUnstable(format!(
        "the equilibrium at {} rpm is statically unstable: the net stiffness is {} N/m in the mode largest{place}; the negative stiffness of {names} exceeds what the shaft, bearings and supports hold",
        short(rpm),
        short(lambda)
    )))
}

/// A number to six significant digits.
fn short(x: f64) -> String {
    let v: f64 = format!("{x:.5e}").parse().unwrap_or(x);
    format!("{v}")
}
