//! Stability at an operating speed and its sensitivity to destabilizing
//! cross-coupled stiffness: the API 684 / API 617 Level I screening.
//!
//! The rotor is linearized at the speed (fluid films: synchronous coefficients
//! at the static equilibrium, [`linearized`]); a cross-coupled stiffness
//! `K_Q = [[0, Q], [−Q, 0]]` (N/m, `K = −∂F/∂q` as for bearings) is added
//! where the destabilizing forces act — by default at the disks (impellers,
//! runners), split equally among them, else at the node nearest mid-span
//! between the outermost bearings ([`default_sites`]). Its force
//! `F = (−Q y, Q x)` is tangential in the spin direction, so it feeds forward
//! whirl: for a rigid disk of mass `m` on isotropic springs `k` and dampers `c`,
//! `m z̈ + c ż + (k − iQ) z = 0` (`z = x + iy`) loses stability at
//! `Q = c √(k/m)`. The threshold `Q` where the logarithmic decrement of the
//! least stable forward mode ([`least_stable_forward`]) reaches zero is found
//! by the Illinois method.
//!
//! **Level I** (API 617 8th ed. §4.8.5, API 684 2nd ed. §4.2): the anticipated
//! cross-coupling of the machine's aerodynamic or hydraulic stages,
//! `Q_A = B P (ρ_d/ρ_s) / (D H Ω)` (Wachel's formula in consistent SI units:
//! rated power `P` (W), impeller diameter `D` and restrictive flow width `H`
//! (m), speed `Ω` (rad/s); `B` = 3 for centrifugal impellers, 1.5 for axial
//! stages after Alford), equal to API 617's `q_A = B_c C P_R / (D_c H_c N)`
//! with `C` = 63 in its US units (hp, in, rpm → klbf/in) and 9.55 = 60/(2π)
//! in SI. The rotor passes the screening when the threshold `Q_0` is at least
//! [`LEVEL_I_MIN_RATIO`] × `Q_A` and the log decrement at `Q_A` is at least
//! [`LEVEL_I_MIN_LOG_DEC`]; otherwise a Level II analysis is required. (The
//! third trigger, a critical speed ratio in region B of API 617's
//! experience chart for `2 ≤ Q_0/Q_A < 10`, needs the gas density and is not
//! judged here.)

use crate::fe::{DOF_X, DOF_Y};
use crate::rotor::{AssemblyError, Rotor};
use crate::solver::Equilibrium;

type C64 = nalgebra::Complex<f64>;

pub use super::cross_coupling_sites::{
    api617_placement, default_sites, disks_and_seals, mid_span_node, site_label,
};
use super::linearize::{LinearizeError, linearized_from};
use super::modal::{
    ModalError, ModalOptions, ModalResult, Mode, OverdampedRoot, Whirl, modal_analysis, modes,
};
use super::operating_point::{OperatingPointError, operating_point};
use super::pad_eigen::PadEigenError;
use super::whirl_modes::{coefficients_at, own_frequency, reconcile, reconcile_and, with_pads};

/// Why a stability check failed.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum StabilityError {
    /// Linearizing the fluid-film bearings failed.
    #[error(transparent)]
    Linearize(#[from] LinearizeError),
    /// Copying the linear rotor failed.
    #[error(transparent)]
    Assembly(#[from] AssemblyError),
    /// The eigen-solve failed.
    #[error(transparent)]
    Modal(#[from] ModalError),
    /// The bearings' coefficients could not be found.
    #[error(transparent)]
    OperatingPoint(#[from] OperatingPointError),
    /// The eigenvalues with the pad coordinates could not be found.
    #[error(transparent)]
    PadEigen(#[from] PadEigenError),
    /// Bad input or no forward mode.
    #[error("{0}")]
    Options(String),
}

/// Wachel's stage factor `B` of centrifugal impellers (API 617 `B_c`).
pub const CENTRIFUGAL_STAGE_FACTOR: f64 = 3.0;

/// Alford's stage factor `B` of axial stages (API 617 `B_t`).
pub const AXIAL_STAGE_FACTOR: f64 = 1.5;

/// Level I: the smallest acceptable `Q_0 / Q_A`.
pub const LEVEL_I_MIN_RATIO: f64 = 2.0;

/// Level I: the smallest acceptable log decrement at `Q_A`.
pub const LEVEL_I_MIN_LOG_DEC: f64 = 0.1;

/// Level I sweeps `Q` from 0 to this multiple of `Q_A`.
pub const LEVEL_I_RANGE: f64 = 10.0;

/// The machine data of Wachel's anticipated cross-coupling (SI units).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StageData {
    /// Rated power `P` (W) of the stages together.
    pub power: f64,
    /// Impeller diameter `D` (m).
    pub diameter: f64,
    /// Restrictive flow width `H` (m): the smaller of the impeller discharge
    /// and diffuser widths (axial stages: the effective blade height).
    pub width: f64,
    /// Discharge over suction density `ρ_d/ρ_s` (1 for a liquid).
    pub density_ratio: f64,
    /// Stage factor `B` ([`CENTRIFUGAL_STAGE_FACTOR`], [`AXIAL_STAGE_FACTOR`]).
    pub stage_factor: f64,
}

impl StageData {
    /// Anticipated cross-coupling `Q_A = B P (ρ_d/ρ_s) / (D H Ω)` (N/m) at
    /// `speed` (rad/s).
    pub fn anticipated(&self, speed: f64) -> f64 {
        self.stage_factor * self.power * self.density_ratio
            / (self.diameter * self.width * speed.abs())
    }

    /// Every value finite and positive, else a message naming the option.
    pub fn check(&self) -> Result<(), StabilityError> {
        for (name, v) in [
            ("--power", self.power),
            ("--impeller-diameter", self.diameter),
            ("--flow-width", self.width),
            ("--density-ratio", self.density_ratio),
            ("--stage-factor", self.stage_factor),
        ] {
            if !(v.is_finite() && v > 0.0) {
                return Err(StabilityError::Options(format!(
                    "{name} must be a positive number, got {v}"
                )));
            }
        }
        Ok(())
    }
}

/// The stage data of one source of anticipated cross-coupling: the whole
/// machine's (`rotor stability --power …`, named `machine`) or one
/// impeller's (`[[disks]] role = "impeller"` with `stage_power`, …).
#[derive(Debug, Clone, PartialEq)]
pub struct Stage {
    /// `machine`, or the impeller disk's name.
    pub name: String,
    /// Its data.
    pub data: StageData,
}

/// The name of the one stage that stands for the whole machine.
pub const MACHINE_STAGE: &str = "machine";

/// Every impeller of the model with stage data, in file order: Wachel per
/// impeller (API 617 sums the stages' `q_A`).
pub fn impeller_stages(rotor: &Rotor) -> Vec<Stage> {
    rotor
        .model
        .disks
        .iter()
        .filter_map(|d| {
            d.stage.map(|st| Stage {
                name: d.name.clone(),
                data: StageData {
                    power: st.power,
                    diameter: st.diameter,
                    width: st.width,
                    density_ratio: st.density_ratio,
                    stage_factor: st.stage_factor,
                },
            })
        })
        .collect()
}

/// The stages of a Level I screening: the machine's data when given (one
/// stage named [`MACHINE_STAGE`]), else each impeller's of the model
/// ([`impeller_stages`]) — none for a hydro class, which API 617 does not
/// judge.
pub fn level_one_stages(rotor: &Rotor, machine: Option<StageData>) -> Vec<Stage> {
    match machine {
        Some(data) => vec![Stage {
            name: MACHINE_STAGE.to_string(),
            data,
        }],
        None if rotor.model.machine.is_hydro() => Vec::new(),
        None => impeller_stages(rotor),
    }
}

/// The anticipated cross-coupling of `stages` at `speed` (rad/s): the sum
/// of each stage's `q_A` (N/m); `None` without stages.
pub fn anticipated(stages: &[Stage], speed: f64) -> Option<f64> {
    (!stages.is_empty()).then(|| stages.iter().map(|s| s.data.anticipated(speed)).sum())
}

/// The Level I verdict.
#[derive(Debug, Clone, PartialEq)]
pub struct LevelOne {
    /// The stages whose `q_A` add up to `Q_A`: the machine's data, or each
    /// impeller's.
    pub stages: Vec<Stage>,
    /// `Q_A` (N/m).
    pub anticipated: f64,
    /// `Q_0 / Q_A`; `None` when no threshold was found up to `Q_max`
    /// (then it exceeds `Q_max / Q_A`).
    pub ratio: Option<f64>,
    /// The least stable forward mode with `Q_A` applied.
    pub mode_at_anticipated: Mode,
    /// `Q_0/Q_A ≥ 2` (or no threshold up to `Q_max ≥ 2 Q_A`).
    pub ratio_pass: bool,
    /// `δ_A ≥ 0.1`.
    pub log_dec_pass: bool,
}

impl LevelOne {
    /// Both criteria met: the rotor passes the Level I screening.
    pub fn pass(&self) -> bool {
        self.ratio_pass && self.log_dec_pass
    }
}

/// Default largest cross-coupled stiffness (N/m): a tenth of the largest
/// direct bearing stiffness at `speed` (rad/s) (thresholds are a few ζ times
/// the support stiffness), or 1e6 N/m without bearings.
pub fn default_cross_coupling_max(rotor: &Rotor, speed: f64) -> Result<f64, StabilityError> {
    let k = operating_point(rotor, speed)?
        .iter()
        .map(|p| p.stiffness[0][0].abs().max(p.stiffness[1][1].abs()))
        .fold(0.0, f64::max);
    Ok(if k > 0.0 { 0.1 * k } else { 1e6 })
}

/// A copy of the linear rotor `linear` with `[[0, q], [−q, 0]]` (N/m), split
/// equally over `sites` (0-based nodes), added to the stiffness at their x, y
/// DOFs.
pub fn with_cross_coupling(
    linear: &Rotor,
    sites: &[usize],
    q: f64,
) -> Result<Rotor, StabilityError> {
    let mut out = linear.with_bearing_coefficients(&[])?;
    add_cross_coupling(&mut out, sites, q)?;
    Ok(out)
}

/// Add `[[0, q], [−q, 0]]` (N/m), split equally over `sites` (0-based
/// nodes), to `rotor`'s stiffness at their x, y DOFs (its nonlinear
/// bearings, if any, left as they are).
pub fn add_cross_coupling(
    rotor: &mut Rotor,
    sites: &[usize],
    q: f64,
) -> Result<(), StabilityError> {
    let share = q / sites.len().max(1) as f64;
    for &node in sites {
        match (rotor.dofs.free(node, DOF_X), rotor.dofs.free(node, DOF_Y)) {
            (Some(ix), Some(iy)) => {
                rotor.stiffness.add(ix, iy, share);
                rotor.stiffness.add(iy, ix, -share);
            }
            _ => {
                return Err(StabilityError::Options(format!(
                    "node {} is fixed by a support: no cross-coupled stiffness can act there",
                    node + 1
                )));
            }
        }
    }
    Ok(())
}

/// The synchronous modes `seeds` of `rotor` linearized at `eq` (spin
/// `speed`, rad/s) with `[[0, q], [−q, 0]]` at `sites`, each iterated to its
/// own frequency (the pads condensed at its eigenvalue, [`own_frequency`])
/// and held against the exact eigenvalues with the pad coordinates and the
/// cross-coupling ([`reconcile_and`]), by damped frequency: a forward seed
/// can iterate to the backward mode beside it (the compressor's 84 Hz pair
/// with Q_A), and the forward mode would be lost.
pub(crate) fn own_modes_with_cross_coupling(
    rotor: &Rotor,
    (eq, speed): (&Equilibrium, f64),
    seeds: Vec<Mode>,
    (sites, q): (&[usize], f64),
) -> Result<Vec<Mode>, StabilityError> {
    let linear_at = |s: C64| -> Result<Rotor, StabilityError> {
        with_cross_coupling(
            &rotor.with_bearing_coefficients(&coefficients_at(eq, s))?,
            sites,
            q,
        )
    };
    let mut own: Vec<Mode> = seeds
        .into_iter()
        .map(|m| own_frequency(&linear_at, speed, m))
        .collect::<Result<_, _>>()?;
    own.sort_by(|a, b| a.damped_frequency.total_cmp(&b.damped_frequency));
    // (`linear_at` has refused `sites` a support fixes.)
    let held = reconcile_and(
        ModalResult {
            modes: own,
            overdamped: Vec::new(),
        },
        (rotor, eq, speed),
        &linear_at,
        &|r| {
            let _ = add_cross_coupling(r, sites, q);
        },
    )?;
    Ok(held.modes)
}

/// The forward mode of least logarithmic decrement among the first `count`
/// modes of the linear rotor at `speed` (rad/s): the one cross-coupling turns
/// unstable first. (On fluid films the lowest forward mode by frequency can be
/// a heavily damped rigid-body mode, so "first" is taken as "least stable".)
pub fn least_stable_forward(
    linear: &Rotor,
    speed: f64,
    count: usize,
) -> Result<Mode, StabilityError> {
    let options = ModalOptions {
        modes: count,
        ..ModalOptions::default()
    };
    modes(linear, speed, &options)?
        .into_iter()
        .filter(|m| m.whirl == Whirl::Forward)
        .min_by(|a, b| a.log_decrement.total_cmp(&b.log_decrement))
        .ok_or_else(|| {
            StabilityError::Options(format!(
                "no forward mode among the first {count} at {speed} rad/s (a spinning rotor is needed: give a speed)"
            ))
        })
}

/// Result of a stability check.
#[derive(Debug, Clone, PartialEq)]
pub struct Stability {
    /// Spin speed (rad/s).
    pub speed: f64,
    /// Nodes of the cross-coupled stiffness (0-based), `Q` split equally.
    pub sites: Vec<usize>,
    /// Why there, for the default placement ([`api617_placement`]); `None`
    /// for nodes the request named.
    pub placement: Option<String>,
    /// The first `count` modes without cross-coupling.
    pub modes: Vec<Mode>,
    /// `(Q, least stable forward mode)` over `0 … Q_max` (N/m).
    pub curve: Vec<(f64, Mode)>,
    /// The largest `Q` swept (N/m).
    pub q_max: f64,
    /// `Q` (N/m) where that mode's log decrement is zero: `Some(0)`
    /// when it is unstable already (or the rotor statically unstable,
    /// [`Stability::diverging`]), `None` when stable up to `Q_max`.
    pub threshold: Option<f64>,
    /// That mode at the threshold.
    pub threshold_mode: Option<Mode>,
    /// The Level I screening, when the machine's stage data were given.
    pub level_one: Option<LevelOne>,
    /// The growing non-oscillating roots without cross-coupling: a static
    /// divergence (then `threshold` is `Some(0)` whatever the forward modes
    /// do).
    pub diverging: Vec<OverdampedRoot>,
}

/// What a stability study is asked for.
#[derive(Debug, Clone, PartialEq)]
pub struct StabilityRequest {
    /// Spin speed (rad/s).
    pub speed: f64,
    /// Nodes of the cross-coupling (0-based); empty for [`default_sites`].
    pub sites: Vec<usize>,
    /// Largest `Q` (N/m); `None` for [`LEVEL_I_RANGE`] × `Q_A` with stage
    /// data, else [`default_cross_coupling_max`].
    pub q_max: Option<f64>,
    /// Values of `Q` from 0 to `Q_max`.
    pub points: usize,
    /// Modes listed and searched for the least stable forward one.
    pub modes: usize,
    /// The stages of the Level I screening (the machine's data, or each
    /// impeller's, [`impeller_stages`]); empty for none.
    pub stages: Vec<Stage>,
}

impl StabilityRequest {
    /// The defaults of `rotor stability` at `speed` (rad/s): the default
    /// sites and range, 21 values of `Q`, 8 modes, no stage data.
    pub fn at(speed: f64) -> Self {
        Self {
            speed,
            sites: Vec::new(),
            q_max: None,
            points: 21,
            modes: 8,
            stages: Vec::new(),
        }
    }
}

/// Stability at `speed` (rad/s) with the cross-coupling at the default
/// sites: the first `count` modes, the least stable forward mode over
/// `points` values of `Q` from 0 to `q_max` (N/m), and the threshold `Q`
/// ([`stability_study`]).
pub fn stability(
    rotor: &Rotor,
    speed: f64,
    q_max: f64,
    points: usize,
    count: usize,
) -> Result<Stability, StabilityError> {
    stability_study(
        rotor,
        &StabilityRequest {
            q_max: Some(q_max),
            points,
            modes: count,
            ..StabilityRequest::at(speed)
        },
    )
}

/// The stability study `rotor stability` and the report run: the modes at the
/// speed, the least stable forward mode against `Q` at the sites, the
/// threshold `Q_0` refined by the Illinois method until `|δ| < 1e-9` or the
/// bracket is `1e-12` of `Q`, and with stage data the Level I verdict.
pub fn stability_study(
    rotor: &Rotor,
    request: &StabilityRequest,
) -> Result<Stability, StabilityError> {
    let (speed, points, count) = (request.speed, request.points, request.modes);
    for stage in &request.stages {
        stage.data.check()?;
    }
    let anticipated = anticipated(&request.stages, speed);
    let q_max = match (request.q_max, anticipated) {
        (Some(q), _) => q,
        (None, Some(qa)) => LEVEL_I_RANGE * qa,
        (None, None) => default_cross_coupling_max(rotor, speed)?,
    };
    if !(q_max.is_finite() && q_max > 0.0) || points < 2 {
        return Err(StabilityError::Options(format!(
            "--cross-coupling-max must be positive (got {q_max} N/m) with at least 2 points (got {points})"
        )));
    }
    let (sites, placement) = if request.sites.is_empty() {
        let (sites, why) = api617_placement(rotor);
        (sites, Some(why))
    } else {
        (request.sites.clone(), None)
    };
    if let Some(&bad) = sites.iter().find(|&&n| n >= rotor.model.node_count()) {
        return Err(StabilityError::Options(format!(
            "--at: node {} is outside the model's nodes 1..{}",
            bad + 1,
            rotor.model.node_count()
        )));
    }
    let (linear, equilibrium) = linearized_from(rotor, speed, speed, None)?;
    // Tilting pads: every mode with the pads condensed at its own eigenvalue
    // (the pad tilts as coordinates of the eigenproblem, [`own_frequency`]).
    let pads = with_pads(equilibrium);
    let options = ModalOptions {
        modes: count,
        ..ModalOptions::default()
    };
    let mut analysis = modal_analysis(&linear, speed, &options)?;
    if let Some(eq) = &pads {
        let linear_at = |s: C64| -> Result<Rotor, StabilityError> {
            Ok(rotor.with_bearing_coefficients(&coefficients_at(eq, s))?)
        };
        let mut own: Vec<Mode> = analysis
            .modes
            .into_iter()
            .map(|m| own_frequency(&linear_at, speed, m))
            .collect::<Result<_, _>>()?;
        own.sort_by(|a, b| a.damped_frequency.total_cmp(&b.damped_frequency));
        analysis.modes = own;
        analysis = reconcile(analysis, (rotor, eq, speed), &linear_at)?;
    }
    let at_zero = analysis.modes;
    // A growing non-oscillating root: statically unstable without any
    // cross-coupling, whatever the forward modes' log decrements say.
    let diverging: Vec<OverdampedRoot> = analysis
        .overdamped
        .into_iter()
        .filter(OverdampedRoot::is_growing)
        .collect();
    let forward = |q: f64| -> Result<Mode, StabilityError> {
        let coupled = with_cross_coupling(&linear, &sites, q)?;
        let Some(eq) = &pads else {
            return least_stable_forward(&coupled, speed, count);
        };
        let held = own_modes_with_cross_coupling(
            rotor,
            (eq, speed),
            modes(&coupled, speed, &options)?,
            (&sites, q),
        )?;
        let least = held
            .into_iter()
            .filter(|m| m.whirl == Whirl::Forward)
            .min_by(|a, b| a.log_decrement.total_cmp(&b.log_decrement));
        least.ok_or_else(|| {
            StabilityError::Options(format!(
                "no forward mode among the first {count} at {speed} rad/s (a spinning rotor is needed: give a speed)"
            ))
        })
    };
    let mut curve = Vec::with_capacity(points);
    for k in 0..points {
        let q = q_max * k as f64 / (points - 1) as f64;
        curve.push((q, forward(q)?));
    }
    let mut threshold = None;
    let mut threshold_mode = None;
    // A growing mode at Q = 0 of any whirl (with the pad coordinates: one
    // the forward sweep's seeds may not reach) is unstable as it stands.
    let growing = at_zero
        .iter()
        .filter(|m| m.log_decrement <= 0.0)
        .min_by(|a, b| a.log_decrement.total_cmp(&b.log_decrement));
    if !diverging.is_empty() {
        threshold = Some(0.0);
    } else if let Some(m) = growing {
        threshold = Some(0.0);
        threshold_mode = Some(m.clone());
    } else if curve[0].1.log_decrement <= 0.0 {
        threshold = Some(0.0);
        threshold_mode = Some(curve[0].1.clone());
    } else if let Some(w) = curve
        .windows(2)
        .find(|w| w[0].1.log_decrement > 0.0 && w[1].1.log_decrement <= 0.0)
    {
        let (mut a, mut fa) = (w[0].0, w[0].1.log_decrement);
        let (mut b, mut fb) = (w[1].0, w[1].1.log_decrement);
        let mut best = (b, w[1].1.clone());
        let mut side = 0;
        for _ in 0..100 {
            let c = (a * fb - b * fa) / (fb - fa);
            let m = forward(c)?;
            let fc = m.log_decrement;
            best = (c, m);
            if fc.abs() < 1e-9 || (b - a).abs() <= 1e-12 * c.abs() {
                break;
            }
            if fc > 0.0 {
                a = c;
                fa = fc;
                if side == 1 {
                    fb /= 2.0;
                }
                side = 1;
            } else {
                b = c;
                fb = fc;
                if side == -1 {
                    fa /= 2.0;
                }
                side = -1;
            }
        }
        threshold = Some(best.0);
        threshold_mode = Some(best.1);
    }
    let level_one = match anticipated {
        Some(qa) => {
            let stages = request.stages.clone();
            let mode_at_anticipated = forward(qa)?;
            let ratio = threshold.map(|q0| q0 / qa);
            Some(LevelOne {
                stages,
                anticipated: qa,
                ratio,
                ratio_pass: match ratio {
                    Some(r) => r >= LEVEL_I_MIN_RATIO,
                    None => q_max >= LEVEL_I_MIN_RATIO * qa,
                },
                log_dec_pass: mode_at_anticipated.log_decrement >= LEVEL_I_MIN_LOG_DEC,
                mode_at_anticipated,
            })
        }
        None => None,
    };
    Ok(Stability {
        speed,
        sites,
        placement,
        modes: at_zero,
        curve,
        q_max,
        threshold,
        threshold_mode,
        level_one,
        diverging,
    })
}
