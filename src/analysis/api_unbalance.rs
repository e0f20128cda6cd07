//! The API 684 / API 617 unbalance cases of an API machine (`machine =
//! "compressor" | "steam_turbine" | "pump"`): where the unbalance goes, how
//! much, and what its response is judged by.
//!
//! **Amounts.** API 617 and API 684 size the unbalance of each plane by the
//! static weight `W` it acts against and the maximum continuous speed `N`:
//! `U_b = 4 W/N` oz·in with `W` in lb and `N` in rpm (the API balance
//! tolerance, also API 610's). In SI, with 1 oz·in = 28.349 523 g × 25.4 mm
//! = 720.077 9 g·mm and 1 lb = 0.453 592 37 kg,
//! `U_b = 4 · 720.0779/0.45359237 · W/N = 6350 · W/N` g·mm with `W` in kg
//! (6350.0 is the standard's rounding of 6350.03), i.e. `6.35e-3 · W/N` kg·m.
//! The analysis applies **twice** `U_b` in each plane, as API 617's lateral
//! analysis asks and ROSS `Report._unbalance_forces` does (`force = 2 *
//! force`, `6350e-6 * W / N` kg·m).
//!
//! **Cases** (API 684's placement for the first and second modes of a
//! between-bearing rotor and for an overhang; ROSS `Report._mode_shape`):
//! - *mid-span* (first mode, in phase): one plane at the node of largest
//!   modal displacement of the first forward mode at `N` that can
//!   resonate ([`RESONANT_DAMPING`]) between the bearings, `W` the sum of the
//!   static loads of the two journals adjacent to the span that holds it
//!   (on two bearings: both journals, the rotor's mass);
//! - *overhung* (each end with a disk or point mass outboard of the
//!   bearings, e.g. a coupling hub or an overhung impeller): one plane at the
//!   outermost of them,
//!   `W` the static weight of everything outboard of that bearing;
//! - *quarter-span, out of phase* (second mode): planes at the nodes nearest
//!   the quarter points of the second mode's span, 0° and 180°, each `W` the
//!   static load of the journal on its side; on two bearings the span is the
//!   bearing span, on more the span that holds the largest orbit of the
//!   second forward mode that can resonate.
//!
//! **Journal static loads.** On two bearings by two-bearing statics
//! ([`journal_static_loads`]); on three or more, a statically indeterminate
//! line, from the bearings' reactions at the line's static equilibrium under
//! gravity at `N` with the model's offsets and every bearing's stiffness
//! ([`super::alignment::alignment`]: the three-moment solution on stiff
//! supports), each along the load direction over `|g_⊥|`.
//!
//! **Judgement of each critical** (a peak of the response at the probes, or
//! at the bearings when the model has no probes or the case moves none of
//! them beyond round-off, [`NEGLIGIBLE_PEAK`]; peaks of several points
//! within [`SAME_CRITICAL`] of each other are one critical, represented by
//! the largest); clause numbers as ROSS `Report` cites them: the
//! amplification factor `AF = N_c/(N_2 − N_1)` (API 684 SP6.8.2.1,
//! half-power) and the separation margin of [`super::unbalance`] (API 684
//! SP6.8.2.10: none required for `AF < 2.5`; below the range
//! `min(16, 17 (1 − 1/(AF − 1.5)))` %, above it
//! `min(26, 10 + 17 (1 − 1/(AF − 1.5)))` %); the vibration limit
//! `A_vl = 25.4 √(12000/N)` µm pk-pk (API 684 SP6.8.2.11), at most 25.4 µm
//! (the cap of API 617's mechanical-test limit, binding below 12000 rpm;
//! ROSS leaves it out); the scale factor `S_cc = A_vl/A_1`, `A_1` the
//! peak's pk-pk amplitude, kept within `0.5 ≤ S_cc ≤ 6` (API 684 SP6.8.2.11,
//! API 617 4.8.2.11; ROSS: `Scc = min(max(A1/Amax, 0.5), 6)` with its `A1`
//! the limit); and at every close clearance (bearing, seal or rub with a
//! clearance) the response at `N_c`, the journal relative to its housing,
//! scaled by `S_cc` against 75 % of the minimum running clearance (API
//! 617): pk-pk major axis `2 S_cc r` against the diametral `0.75 · 2 C`, `C`
//! the radial clearance the journal moves in
//! ([`BearingKind::journal_clearance`](crate::bearing::BearingKind::journal_clearance)).

use nalgebra::Complex;

use crate::fe::DOF_PER_NODE;
use crate::model::{RotorModel, UnbalancePlane};
use crate::rotor::{DOF_PER_PEDESTAL, Rotor};
use crate::solver::SolverOptions;
use crate::units::RAD_S_TO_RPM;

use super::alignment::{alignment, carries_weight};
use super::linear::node_xy;
use super::modal::{ModalOptions, Mode, Whirl, modes_at};
use super::shapes::node_orbits;
use super::unbalance::{
    OperatingRange, Peak, ResponsePoint, SeparationMargin, UnbalanceError, major_semi_axis, peaks,
    refined_sweep, response_at, response_points, separation_margin, speed_grid, sweep,
};

type C64 = Complex<f64>;

/// `U_b = 4 W/N` oz·in in SI: `6350 W/N` g·mm with `W` in kg and `N` in rpm.
pub const UB_G_MM_PER_KG_RPM: f64 = 6350.0;

/// The factor on `U_b` the analysis applies in each plane (API 617; ROSS).
pub const APPLIED_FACTOR: f64 = 2.0;

/// Peaks of different points whose speeds differ by less than this fraction
/// are the same critical.
pub const SAME_CRITICAL: f64 = 0.01;

/// Bounds of the scale factor `S_cc` (API 617).
pub const SCALE_FACTOR_BOUNDS: (f64, f64) = (0.5, 6.0);

/// Peaks smaller than this fraction of a case's largest are round-off (a
/// probe on a node of the excited mode), not criticals of the case.
pub const NEGLIGIBLE_PEAK: f64 = 1e-6;

/// Fraction of the minimum running clearance the scaled response may use.
pub const CLEARANCE_FRACTION: f64 = 0.75;

/// The API residual unbalance `U_b = 6350 W/N` g·mm (= 4 W/N oz·in), in kg·m,
/// of a plane against the static weight `weight` (kg) at `mcs_rpm`.
pub fn api_unbalance_amount(weight: f64, mcs_rpm: f64) -> f64 {
    UB_G_MM_PER_KG_RPM * weight / mcs_rpm * 1e-6
}

/// The vibration limit `A_vl = 25.4 √(12000/N)` µm pk-pk, at most 25.4 µm,
/// in m, at the maximum continuous speed `mcs_rpm`.
pub fn vibration_limit(mcs_rpm: f64) -> f64 {
    (25.4 * (12000.0 / mcs_rpm).sqrt()).min(25.4) * 1e-6
}

/// The scale factor `S_cc = A_vl/A_1` within [`SCALE_FACTOR_BOUNDS`].
pub fn scale_factor(limit: f64, a1: f64) -> f64 {
    let (lo, hi) = SCALE_FACTOR_BOUNDS;
    (limit / a1).clamp(lo, hi)
}

/// Which API case.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ApiCaseKind {
    /// First mode: one plane at its largest modal displacement.
    MidSpan,
    /// Overhung mass outboard of the first (`false`) or last (`true`) bearing.
    Overhung {
        /// Whether the overhang is beyond the last bearing (else the first).
        last_end: bool,
    },
    /// Second mode: the quarter-spans, out of phase.
    QuarterSpan,
}

impl ApiCaseKind {
    /// Label for tables.
    pub fn label(self) -> &'static str {
        match self {
            ApiCaseKind::MidSpan => "mid-span (1st mode, in phase)",
            ApiCaseKind::Overhung { last_end: false } => "overhung, first end",
            ApiCaseKind::Overhung { last_end: true } => "overhung, last end",
            ApiCaseKind::QuarterSpan => "quarter-spans (2nd mode, out of phase)",
        }
    }
}

/// One unbalance plane of a case.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ApiPlane {
    /// Node (0-based).
    pub node: usize,
    /// Static weight `W` it is sized by (kg).
    pub weight: f64,
    /// `U_b = 6350 W/N` g·mm, in kg·m.
    pub amount: f64,
    /// Applied unbalance `APPLIED_FACTOR · U_b` (kg·m).
    pub applied: f64,
    /// Phase (rad).
    pub phase: f64,
}

/// A close clearance checked at one critical.
#[derive(Debug, Clone, PartialEq)]
pub struct ClearanceCheck {
    /// The point's label (`bearing NAME`, `seal NAME`, `rub NAME`).
    pub label: String,
    /// Radial clearance `C` (m).
    pub clearance: f64,
    /// Scaled response `S_cc · 2 r` (m pk-pk) at the critical.
    pub scaled: f64,
    /// `CLEARANCE_FRACTION · 2 C` (m).
    pub limit: f64,
    /// `scaled ≤ limit`.
    pub pass: bool,
}

/// One critical of one case.
#[derive(Debug, Clone, PartialEq)]
pub struct ApiCritical {
    /// The representative peak (largest amplitude of the points judged).
    pub peak: Peak,
    /// Its point's label.
    pub point: String,
    /// Separation margin (`None` without an AF).
    pub margin: Option<SeparationMargin>,
    /// `A_1`: the peak's pk-pk amplitude (m).
    pub a1: f64,
    /// `S_cc`.
    pub scale_factor: f64,
    /// The close clearances at the critical.
    pub clearances: Vec<ClearanceCheck>,
}

/// One API case and its criticals.
#[derive(Debug, Clone, PartialEq)]
pub struct ApiCase {
    /// Which case.
    pub kind: ApiCaseKind,
    /// Its unbalance planes.
    pub planes: Vec<ApiPlane>,
    /// Speeds of its refined sweep (rad/s).
    pub speeds: Vec<f64>,
    /// Its criticals, by speed.
    pub criticals: Vec<ApiCritical>,
}

/// The API unbalance cases of a machine.
#[derive(Debug, Clone, PartialEq)]
pub struct ApiUnbalance {
    /// Maximum continuous speed `N` (rad/s): the operating range's top.
    pub mcs: f64,
    /// The operating range the margins are measured from.
    pub operating: OperatingRange,
    /// `A_vl` (m pk-pk).
    pub vibration_limit: f64,
    /// Static loads of the journals (kg), by axial position.
    pub journal_loads: Vec<f64>,
    /// The cases.
    pub cases: Vec<ApiCase>,
}

/// Mass (kg) and axial position (m) of every lumped and distributed mass of
/// the rotor: each shaft element at its midpoint (flexible couplings' elements
/// excluded), disks, point masses (mean of x and y).
fn masses(model: &RotorModel) -> Vec<(f64, f64)> {
    let z = &model.node_z;
    let shaft = model
        .elements
        .iter()
        .enumerate()
        .filter(|(k, _)| !model.flexible_coupling_at(*k))
        .map(|(_, e)| (e.element.mass(), 0.5 * (z[e.node] + z[e.node + 1])));
    let disks = model.disks.iter().map(|d| (d.disk.mass, z[d.node]));
    let points = model
        .point_masses
        .iter()
        .map(|p| (0.5 * (p.mass[0] + p.mass[1]), z[p.node]));
    shaft.chain(disks).chain(points).collect()
}

/// Nodes of the supporting bearings (seals, pulls and rubs are no
/// supports), distinct, by axial position; at least two.
fn support_nodes(model: &RotorModel) -> Result<Vec<usize>, UnbalanceError> {
    let mut distinct: Vec<usize> = model
        .bearings
        .iter()
        .filter(|b| b.kind.is_bearing())
        .map(|b| b.node)
        .collect();
    distinct.sort_unstable();
    distinct.dedup();
    distinct.sort_by(|&a, &b| model.node_z[a].total_cmp(&model.node_z[b]));
    if distinct.len() < 2 {
        return Err(UnbalanceError::Options(format!(
            "the API unbalance cases need a rotor on at least two bearings (journal static loads by statics); model {} has bearings at {} node(s)",
            model.name,
            distinct.len()
        )));
    }
    Ok(distinct)
}

/// Static loads (kg) of the journals at `supports` (nodes by axial
/// position, three or more) of a statically indeterminate line: the
/// bearings' reactions along the load direction at the line's static
/// equilibrium under gravity at `speed` (rad/s) with the model's offsets
/// ([`alignment`]), summed per node and divided by `|g_⊥|`.
fn indeterminate_loads(
    rotor: &Rotor,
    supports: &[usize],
    speed: f64,
) -> Result<Vec<f64>, UnbalanceError> {
    let model = &rotor.model;
    if !carries_weight(rotor) {
        return Err(UnbalanceError::Options(format!(
            "the API unbalance cases of model {} on {} bearings need the journals' static loads, and gravity has no part across its shaft",
            model.name,
            supports.len()
        )));
    }
    let g = model.gravity[0].hypot(model.gravity[1]);
    let line = alignment(rotor, speed, &SolverOptions::default())
        .map_err(|e| UnbalanceError::Options(format!("journal static loads: {e}")))?;
    Ok(supports
        .iter()
        .map(|&node| {
            line.bearings
                .iter()
                .filter(|r| model.bearings[r.bearing].node == node)
                .map(|r| r.load / g)
                .sum()
        })
        .collect())
}

/// The span `(i, i + 1)` of `supports` (nodes by axial position) that holds
/// `node`: the journals adjacent to a mode's largest orbit.
fn span_of(model: &RotorModel, supports: &[usize], node: usize) -> usize {
    let z = model.node_z[node];
    (0..supports.len() - 1)
        .find(|&i| z <= model.node_z[supports[i + 1]])
        .unwrap_or(supports.len() - 2)
}

/// Static loads (kg) of the journals at nodes `a < b` from two-bearing
/// statics: `W_b = Σ m (z − z_a)/(z_b − z_a)`, `W_a = Σ m − W_b`.
pub fn journal_static_loads(model: &RotorModel, a: usize, b: usize) -> [f64; 2] {
    let (za, zb) = (model.node_z[a], model.node_z[b]);
    let all = masses(model);
    let total: f64 = all.iter().map(|(m, _)| m).sum();
    let wb: f64 = all.iter().map(|(m, z)| m * (z - za) / (zb - za)).sum();
    [total - wb, wb]
}

/// Mass (kg) outboard of node `bearing`: beyond it toward the first
/// (`last_end = false`) or the last end.
pub fn overhung_mass(model: &RotorModel, bearing: usize, last_end: bool) -> f64 {
    let zb = model.node_z[bearing];
    masses(model)
        .iter()
        .filter(|(_, z)| if last_end { *z > zb } else { *z < zb })
        .map(|(m, _)| m)
        .sum()
}

/// Damping ratio below which a mode can show a resonance peak (`AF = 1/(2ζ)
/// > 1`): the heavily damped film modes below it are no critical speeds.
pub const RESONANT_DAMPING: f64 = 0.5;

/// The node between `a` and `b` where the first forward mode at `speed`
/// with `ζ <` [`RESONANT_DAMPING`] (else the first forward mode, else the
/// first mode) has its largest orbit; the mid-span node when the modes
/// cannot be found.
fn first_mode_antinode(rotor: &Rotor, speed: f64, a: usize, b: usize) -> usize {
    mode_antinode(rotor, speed, (a, b), 0)
}

/// The node between `a` and `b` where the `which`-th (0-based) forward mode
/// at `speed` with `ζ <` [`RESONANT_DAMPING`] (the last such when there
/// are fewer; else the `which`-th forward mode, else the first mode) has
/// its largest orbit; the mid-span node when the modes cannot be found.
fn mode_antinode(rotor: &Rotor, speed: f64, (a, b): (usize, usize), which: usize) -> usize {
    let model = &rotor.model;
    let mid = model.nearest_node(0.5 * (model.node_z[a] + model.node_z[b]));
    let options = ModalOptions {
        modes: 8,
        target_frequency: 0.0,
    };
    let Ok(modes) = modes_at(rotor, speed, &options) else {
        return mid;
    };
    let resonant = |m: &&Mode| m.whirl == Whirl::Forward && m.damping_ratio < RESONANT_DAMPING;
    let forward = |m: &&Mode| m.whirl == Whirl::Forward;
    let Some(mode) = modes
        .iter()
        .filter(resonant)
        .take(which + 1)
        .last()
        .or(modes.iter().filter(forward).take(which + 1).last())
        .or(modes.first())
    else {
        return mid;
    };
    node_orbits(model, mode)
        .into_iter()
        .filter(|o| (a..=b).contains(&o.node))
        .max_by(|p, q| p.major.total_cmp(&q.major))
        .map_or(mid, |o| o.node)
}

/// A plane of weight `weight` (kg) at `node`, phase `phase` (rad).
fn plane(node: usize, weight: f64, mcs_rpm: f64, phase: f64) -> ApiPlane {
    let amount = api_unbalance_amount(weight, mcs_rpm);
    ApiPlane {
        node,
        weight,
        amount,
        applied: APPLIED_FACTOR * amount,
        phase,
    }
}

/// A case and its planes, before its response is computed.
pub type PlannedCase = (ApiCaseKind, Vec<ApiPlane>);

/// The planes of every API case of `rotor` at maximum continuous speed `mcs`
/// (rad/s), with the journal static loads (kg, by axial position; see the
/// module's notes).
pub fn api_cases(rotor: &Rotor, mcs: f64) -> Result<(Vec<PlannedCase>, Vec<f64>), UnbalanceError> {
    let model = &rotor.model;
    let supports = support_nodes(model)?;
    let (a, b) = (supports[0], supports[supports.len() - 1]);
    let loads = if supports.len() == 2 {
        journal_static_loads(model, a, b).to_vec()
    } else {
        indeterminate_loads(rotor, &supports, mcs)?
    };
    let n = mcs * RAD_S_TO_RPM;
    let antinode = first_mode_antinode(rotor, mcs, a, b);
    let first = span_of(model, &supports, antinode);
    let mut cases = vec![(
        ApiCaseKind::MidSpan,
        vec![plane(antinode, loads[first] + loads[first + 1], n, 0.0)],
    )];
    for (last_end, bearing) in [(false, a), (true, b)] {
        let outboard = |n: &usize| if last_end { *n > b } else { *n < a };
        let outer = model
            .disks
            .iter()
            .map(|d| d.node)
            .chain(model.point_masses.iter().map(|p| p.node))
            .filter(outboard)
            .reduce(|p, q| if last_end { p.max(q) } else { p.min(q) });
        if let Some(node) = outer {
            let w = overhung_mass(model, bearing, last_end);
            cases.push((
                ApiCaseKind::Overhung { last_end },
                vec![plane(node, w, n, 0.0)],
            ));
        }
    }
    // The second mode's span: the whole span on two bearings, else the span
    // of the second resonant forward mode's largest orbit.
    let second = if supports.len() == 2 {
        0
    } else {
        span_of(model, &supports, mode_antinode(rotor, mcs, (a, b), 1))
    };
    let (za, zb) = (
        model.node_z[supports[second]],
        model.node_z[supports[second + 1]],
    );
    let quarter = [
        model.nearest_node(za + 0.25 * (zb - za)),
        model.nearest_node(za + 0.75 * (zb - za)),
    ];
    cases.push((
        ApiCaseKind::QuarterSpan,
        vec![
            plane(quarter[0], loads[second], n, 0.0),
            plane(quarter[1], loads[second + 1], n, std::f64::consts::PI),
        ],
    ));
    Ok((cases, loads))
}

/// The rotor with its unbalance planes replaced by `planes` (applied amounts).
fn with_planes(rotor: &Rotor, planes: &[ApiPlane]) -> Result<Rotor, UnbalanceError> {
    let mut model = rotor.model.clone();
    model.unbalances = planes
        .iter()
        .enumerate()
        .map(|(k, p)| UnbalancePlane {
            name: format!("api{}", k + 1),
            node: p.node,
            magnitude: p.applied,
            phase: p.phase,
        })
        .collect();
    Ok(Rotor::new(model)?)
}

/// What the API cases sweep (rad/s).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ApiRequest {
    /// The operating range; its top is the maximum continuous speed.
    pub operating: OperatingRange,
    /// Highest speed of the sweep.
    pub max: f64,
    /// Speeds of the base grid (from 0; refined, [`refined_sweep`]).
    pub points: usize,
}

/// Run every API case of `rotor` (see the module's notes): the response of
/// each on the refined grid, its criticals with AF, separation margin, `A_1`,
/// `S_cc` and the clearance checks.
pub fn api_unbalance(rotor: &Rotor, request: &ApiRequest) -> Result<ApiUnbalance, UnbalanceError> {
    let mcs = request.operating.max;
    let n = mcs * RAD_S_TO_RPM;
    let limit = vibration_limit(n);
    let (planned, journal_loads) = api_cases(rotor, mcs)?;
    let mut cases = Vec::new();
    for (kind, planes) in planned {
        let excited = with_planes(rotor, &planes)?;
        let mut speeds = speed_grid(0.0, request.max, request.points)?;
        if !excited.nonlinear_bearings.is_empty() {
            speeds.remove(0);
        }
        // The judged points: the probes, else the bearings. A point the case
        // does not move (a probe on the excited mode's node) answers
        // round-off only, against the largest response of any point: it is
        // left out before the grid is refined on it, and when every probe
        // is such a point the bearings are judged.
        let all = response_points(&excited);
        let probes = excited.model.probes.len();
        let base = sweep(&excited, &speeds, &all)?;
        let peak_of = |p: usize| base.major(p).into_iter().fold(0.0, f64::max);
        let largest = (0..all.len()).map(peak_of).fold(0.0, f64::max);
        let moved = |p: &usize| peak_of(*p) > NEGLIGIBLE_PEAK * largest;
        let mut chosen: Vec<usize> = (0..probes).filter(moved).collect();
        if chosen.is_empty() {
            chosen = (probes..all.len())
                .filter(|&p| excited.model.bearings[p - probes].kind.is_bearing())
                .filter(moved)
                .collect();
        }
        let judged: Vec<ResponsePoint> = chosen.iter().map(|&p| all[p].clone()).collect();
        let refined = refined_sweep(&excited, &speeds, &judged)?;
        let mut found: Vec<Peak> = Vec::new();
        for p in 0..judged.len() {
            found.extend(peaks(&excited, &refined, p)?);
        }
        found.retain(|p| p.amplitude > NEGLIGIBLE_PEAK * largest);
        found.sort_by(|p, q| p.speed.total_cmp(&q.speed));
        let mut criticals = Vec::new();
        let mut k = 0;
        while k < found.len() {
            let mut j = k;
            let mut best = found[k];
            while j < found.len() && found[j].speed < found[k].speed * (1.0 + SAME_CRITICAL) {
                if found[j].amplitude > best.amplitude {
                    best = found[j];
                }
                j += 1;
            }
            k = j;
            criticals.push(judge(
                &excited,
                &judged[best.point].label,
                best,
                limit,
                &request.operating,
            )?);
        }
        cases.push(ApiCase {
            kind,
            planes,
            speeds: refined.speeds,
            criticals,
        });
    }
    Ok(ApiUnbalance {
        mcs,
        operating: request.operating,
        vibration_limit: limit,
        journal_loads,
        cases,
    })
}

/// The journal of model bearing `b` relative to its housing (its pedestal's
/// translation; the ground without one) in a response on all DOFs.
fn relative_xy(rotor: &Rotor, q: &[C64], b: usize) -> (C64, C64) {
    let placed = &rotor.model.bearings[b];
    let (x, y) = node_xy(q, placed.node);
    match placed.pedestal {
        None => (x, y),
        Some(p) => {
            let at = rotor.model.node_count() * DOF_PER_NODE + p * DOF_PER_PEDESTAL;
            (x - q[at], y - q[at + 1])
        }
    }
}

/// The judgement of one critical: margin, `A_1`, `S_cc`, and the response
/// at `N_c` scaled by `S_cc` at every close clearance (bearing, seal or rub
/// with a [`journal_clearance`](crate::bearing::BearingKind::journal_clearance);
/// a magnetic pull's air gap is no running clearance).
fn judge(
    rotor: &Rotor,
    point: &str,
    peak: Peak,
    limit: f64,
    operating: &OperatingRange,
) -> Result<ApiCritical, UnbalanceError> {
    let margin = peak
        .amplification_factor
        .map(|af| separation_margin(peak.speed, af, operating));
    let a1 = 2.0 * peak.amplitude;
    let scc = scale_factor(limit, a1);
    let q = response_at(rotor, peak.speed)?;
    let probes = rotor.model.probes.len();
    let labels = response_points(rotor);
    let clearances = rotor
        .model
        .bearings
        .iter()
        .enumerate()
        .filter(|(_, b)| !b.kind.is_magnetic_pull())
        .filter_map(|(k, b)| {
            let c = b.kind.journal_clearance()?;
            let scaled = scc * 2.0 * major_semi_axis(relative_xy(rotor, &q, k));
            let allowed = CLEARANCE_FRACTION * 2.0 * c;
            Some(ClearanceCheck {
                label: labels[probes + k].label.clone(),
                clearance: c,
                scaled,
                limit: allowed,
                pass: scaled <= allowed,
            })
        })
        .collect();
    Ok(ApiCritical {
        peak,
        point: point.to_string(),
        margin,
        a1,
        scale_factor: scc,
        clearances,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// 4 W/N oz·in against 6350 W/N g·mm: W = 1000 lb, N = 15000 rpm gives
    /// 4·1000/15000 = 0.26667 oz·in = 0.26667 · 720.0779 g·mm = 192.02 g·mm;
    /// 6350 · 453.59237/15000 = 192.02 g·mm (the constant's rounding, < 1e-4).
    #[test]
    fn si_amount_is_four_w_over_n() {
        let oz_in = 4.0 * 1000.0 / 15000.0;
        let g_mm = oz_in * 28.349_523_125 * 25.4;
        let si = api_unbalance_amount(453.592_37, 15000.0) * 1e6;
        assert!((si / g_mm - 1.0).abs() < 1e-4, "{si} vs {g_mm}");
    }

    /// A_vl: 25.4 µm up to 12000 rpm, 25.4 √(12000/N) above (N = 48000 rpm:
    /// 12.7 µm); S_cc kept within 0.5 … 6.
    #[test]
    fn vibration_limit_and_scale_factor() {
        assert!((vibration_limit(3000.0) - 25.4e-6).abs() < 1e-18);
        assert!((vibration_limit(48000.0) - 12.7e-6).abs() < 1e-18);
        assert_eq!(scale_factor(25.4e-6, 1e-6), 6.0);
        assert_eq!(scale_factor(25.4e-6, 1e-3), 0.5);
        assert!((scale_factor(25.4e-6, 10.16e-6) - 2.5).abs() < 1e-12);
    }
}
