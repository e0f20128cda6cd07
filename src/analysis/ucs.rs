//! Undamped critical speed map: the forward synchronous critical speeds of the
//! rotor against an isotropic support stiffness, with the bearings' own
//! stiffness over a speed range to read the map with.
//!
//! Every bearing is replaced by an isotropic spring `k` (N/m) without damping,
//! in series with the bearing's pedestal where it stands on one (so the map
//! holds the real supports); a magnetic pull keeps its negative stiffness;
//! rubs and seals are left out.
//! At a synchronous critical speed the whirl frequency equals the spin `Ω`:
//! with `λ = iΩ` the quadratic eigenproblem `(λ²M + λΩG + K) x = 0` becomes
//! `K x = Ω² (M − iG) x`, a generalized problem with `K` symmetric and
//! `M − iG` Hermitian (`G` real skew-symmetric). It is solved by shift-invert
//! Arnoldi on `K⁻¹(M − iG)` (one banded complex solve per step); each positive
//! eigenvalue `ν = 1/Ω²` is a synchronous critical speed, kept when its shape
//! whirls forward (more forward than backward orbit, [`orbit_radii`]). Gyroscopic
//! stiffening is thereby included exactly (a disk with `Ip > Id` has no forward
//! rocking critical: `ν < 0`).

use nalgebra::Complex;

use crate::bearing::BearingKind;
use crate::fe::{DOF_PER_NODE, DOF_X, DOF_Y};
use crate::linalg::sturm::eigenvalues_below;
use crate::linalg::{ArnoldiOptions, LinalgError, largest_eigenpairs, map_to_complex};
use crate::rotor::{AssemblyError, Rotor};

use super::modal::orbit_radii;
use super::operating_point::{OperatingPointError, operating_point};

type C64 = Complex<f64>;

/// Why a critical speed map could not be made.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum UcsError {
    /// The rotor with springs could not be assembled.
    #[error(transparent)]
    Assembly(#[from] AssemblyError),
    /// The eigen-solve failed (e.g. a rotor without bearings or supports).
    #[error("critical speeds at support stiffness {stiffness} N/m: {source}")]
    Linalg { stiffness: f64, source: LinalgError },
    /// The bearings' coefficients at a speed could not be found.
    #[error(transparent)]
    OperatingPoint(#[from] OperatingPointError),
    /// Bad input, naming the option and value.
    #[error("{0}")]
    Options(String),
}

/// The rotor with every bearing replaced by an isotropic spring of `stiffness`
/// (N/m) and no damping, in series with its pedestal where it stands on one;
/// a magnetic pull becomes its negative stiffness at the centred rotor,
/// `−k s²` (it acts on the rotor whatever holds it); rubs and seals are left
/// out (they support nothing).
pub fn with_isotropic_supports(rotor: &Rotor, stiffness: f64) -> Result<Rotor, UcsError> {
    let mut model = rotor.model.clone();
    model
        .bearings
        .retain(|b| b.kind.is_bearing() || b.kind.is_magnetic_pull());
    for b in &mut model.bearings {
        let k = match &b.kind {
            BearingKind::MagneticPull(m) => -m.stiffness * m.excitation * m.excitation,
            _ => stiffness,
        };
        b.kind = BearingKind::Linear {
            stiffness: [[k, 0.0], [0.0, k]],
            damping: [[0.0; 2]; 2],
        };
    }
    Ok(Rotor::new(model)?)
}

/// The lowest `count` forward synchronous critical speeds (rad/s, increasing)
/// of a rotor with linear bearings (damping ignored), from `K x = Ω²(M − iG) x`.
pub fn synchronous_critical_speeds(rotor: &Rotor, count: usize) -> Result<Vec<f64>, LinalgError> {
    let n = rotor.dof_count();
    let factor = map_to_complex(&rotor.stiffness).lu()?;
    let mut b = map_to_complex(&rotor.mass);
    b.scale_add(C64::new(0.0, -1.0), &map_to_complex(&rotor.gyroscopic));
    let mut apply = |x: &[C64], y: &mut [C64]| -> Result<(), LinalgError> {
        b.mul_vec(x, y);
        factor.solve_in_place(y);
        Ok(())
    };
    let options = ArnoldiOptions {
        tol: 1e-13,
        ..ArnoldiOptions::default()
    };
    let mut nev = (2 * count + 4).min(n);
    loop {
        let pairs = largest_eigenpairs(n, nev, &mut apply, &options)?;
        let mut forward: Vec<f64> = pairs
            .iter()
            .filter(|p| p.value.re > 0.0 && is_forward(rotor, &p.vector))
            .map(|p| 1.0 / p.value.re.sqrt())
            .collect();
        if forward.len() >= count || nev == n {
            forward.sort_by(f64::total_cmp);
            forward.truncate(count);
            return Ok(forward);
        }
        nev = (nev + 2 * (count - forward.len()) + 4).min(n);
    }
}

/// More forward than backward whirl over the nodes: `Σ r_f² > Σ r_b²`.
fn is_forward(rotor: &Rotor, free: &[C64]) -> bool {
    let all = rotor.dofs.expand(free);
    let (mut f, mut b) = (0.0, 0.0);
    for node in 0..rotor.dofs.node_count() {
        let (rf, rb) = orbit_radii(
            all[node * DOF_PER_NODE + DOF_X],
            all[node * DOF_PER_NODE + DOF_Y],
        );
        f += rf * rf;
        b += rb * rb;
    }
    f > b
}

/// One bearing's direct stiffness over speed.
#[derive(Debug, Clone, PartialEq)]
pub struct BearingStiffness {
    /// Bearing name.
    pub name: String,
    /// `(speed rad/s, kxx N/m, kyy N/m)`, synchronous coefficients at the
    /// static equilibrium at each speed ([`operating_point`]).
    pub points: Vec<(f64, f64, f64)>,
}

/// A critical speed map.
#[derive(Debug, Clone, PartialEq)]
pub struct CriticalSpeedMap {
    /// Support stiffnesses (N/m).
    pub stiffness: Vec<f64>,
    /// `speeds[i]`: the forward critical speeds (rad/s) at `stiffness[i]`;
    /// none where the rotor is statically unstable.
    pub speeds: Vec<Vec<f64>>,
    /// `unstable[i]`: the number of modes of negative net static stiffness
    /// at `stiffness[i]` (a magnetic pull stiffer than the supports): the
    /// rotor diverges from the centre there and has no critical speed.
    pub unstable: Vec<usize>,
    /// The model's bearings over the speed range.
    pub bearings: Vec<BearingStiffness>,
}

/// `points` stiffnesses spaced geometrically from `min` to `max` (N/m).
pub fn stiffness_grid(min: f64, max: f64, points: usize) -> Result<Vec<f64>, UcsError> {
    if !(min.is_finite() && max.is_finite() && min > 0.0 && max > min) || points < 2 {
        return Err(UcsError::Options(format!(
            "the stiffness range needs 0 < --min-stiffness < --max-stiffness and --points ≥ 2 (got {min} … {max} N/m, {points} points)"
        )));
    }
    let ratio = (max / min).ln();
    Ok((0..points)
        .map(|k| min * (ratio * k as f64 / (points - 1) as f64).exp())
        .collect())
}

/// The defaults of `rotor ucs`: support stiffness from 1e5 to 1e10 N/m.
pub const DEFAULT_STIFFNESS_RANGE: (f64, f64) = (1e5, 1e10);

/// The defaults of `rotor ucs`: 31 stiffnesses, 4 critical speeds each, the
/// bearings at 20 speeds.
pub const DEFAULT_POINTS: usize = 31;

/// See [`DEFAULT_POINTS`].
pub const DEFAULT_CRITICALS: usize = 4;

/// See [`DEFAULT_POINTS`].
pub const DEFAULT_BEARING_SPEEDS: usize = 20;

/// The `count` speeds (rad/s) the bearings' stiffness is drawn at: `top/count`
/// … `top` (no film at standstill).
pub fn bearing_speeds(top: f64, count: usize) -> Vec<f64> {
    (1..=count).map(|k| top * k as f64 / count as f64).collect()
}

/// The map: the lowest `count` forward critical speeds at every stiffness of
/// `stiffness` (N/m), and each bearing's kxx, kyy at every speed of `speeds`
/// (rad/s; skip 0 for fluid films).
pub fn critical_speed_map(
    rotor: &Rotor,
    stiffness: &[f64],
    count: usize,
    speeds: &[f64],
) -> Result<CriticalSpeedMap, UcsError> {
    if rotor.model.bearings.is_empty() {
        return Err(UcsError::Options(format!(
            "model {} has no bearings to replace by springs",
            rotor.model.name
        )));
    }
    let mut map = Vec::with_capacity(stiffness.len());
    let mut unstable = Vec::with_capacity(stiffness.len());
    for &k in stiffness {
        let sprung = with_isotropic_supports(rotor, k)?;
        let linalg = |source| UcsError::Linalg {
            stiffness: k,
            source,
        };
        // Negative eigenvalues of the (symmetric) sprung stiffness: the
        // negative pivots of K = L D Lᵀ (Sylvester's inertia).
        let negative = eigenvalues_below(&sprung.stiffness, &sprung.mass, 0.0).map_err(linalg)?;
        unstable.push(negative);
        if negative > 0 {
            map.push(Vec::new());
            continue;
        }
        map.push(synchronous_critical_speeds(&sprung, count).map_err(linalg)?);
    }
    let mut bearings: Vec<BearingStiffness> = rotor
        .model
        .bearings
        .iter()
        .filter(|b| b.kind.is_bearing())
        .map(|b| BearingStiffness {
            name: b.name.clone(),
            points: Vec::with_capacity(speeds.len()),
        })
        .collect();
    for &s in speeds {
        for (curve, p) in bearings.iter_mut().zip(operating_point(rotor, s)?) {
            curve.points.push((s, p.stiffness[0][0], p.stiffness[1][1]));
        }
    }
    Ok(CriticalSpeedMap {
        stiffness: stiffness.to_vec(),
        speeds: map,
        unstable,
        bearings,
    })
}
