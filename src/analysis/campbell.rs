//! Campbell diagram (damped natural frequencies against spin speed) and critical
//! speeds, where a frequency branch meets an excitation line `ω = h·Ω`.
//!
//! A crossing by a mode with damping ratio `ζ ≥` [`OVERDAMPED_DAMPING_RATIO`]
//! is not a critical speed: the resonance amplification `1/(2ζ)` is at most 1,
//! so the response has no peak there (rigid-body modes on fluid films at low
//! speed cross the 1× line with ζ ≈ 0.8).

use super::torsion::{TorsionalMode, torsional_modes};
use nalgebra::Complex;

use crate::rotor::Rotor;

/// Start of the speed grid of a model with fluid-film bearings, as a fraction
/// of the top speed: a film carries load only when turning.
pub const FILM_START_FRACTION: f64 = 0.01;

/// The `steps + 1` speeds (rad/s) of a Campbell diagram up to `top` (rad/s):
/// evenly spaced from 0 for linear bearings, from [`FILM_START_FRACTION`] ×
/// `top` when the rotor has fluid-film bearings.
pub fn speed_grid(rotor: &Rotor, top: f64, steps: usize) -> Vec<f64> {
    let first = if rotor.nonlinear_bearings.is_empty() {
        0.0
    } else {
        FILM_START_FRACTION * top
    };
    let steps = steps.max(1);
    (0..=steps)
        .map(|k| first + (top - first) * k as f64 / steps as f64)
        .collect()
}

use super::backward_crossing::unbalance_peak_at;
pub use super::campbell_point::{
    CampbellPoint, CriticalSpeed, ModeSummary, OVERDAMPED_DAMPING_RATIO,
};
use super::critical_refine::{Bracket, Known, Refined, refine};
use super::modal::{ModalError, ModalOptions, Whirl, modal_analysis_at};
use super::mode_tracking::{link, translations};
use super::parallel::map_in_order;
use super::unbalance::{OperatingRange, SeparationMargin, separation_margin};
use super::whirl_modes::modal_analysis_own;

type Complex64 = Complex<f64>;

/// A critical speed judged by API 684 (§2.6.2.10, as for unbalance response
/// peaks) with the amplification factor of its mode, `AF = 1/(2ζ)`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CriticalMargin {
    /// The critical speed.
    pub critical: CriticalSpeed,
    /// `AF = 1/(2ζ)` of the mode at the crossing (∞ for ζ ≤ 0 or round-off).
    pub amplification_factor: f64,
    /// Separation margin from the operating range, when one is known.
    pub margin: Option<SeparationMargin>,
    /// `(Nc − N_max)/N_max` from the maximum (trip or runaway) speed, when the
    /// model states one: positive when the critical lies above it.
    pub from_max_speed: Option<f64>,
    /// For a backward-whirl critical, whether the unbalance response peaks
    /// there ([`unbalance_peak_at`]); one without a peak passes its margin
    /// (API 684). `None` for forward and mixed whirl, or when not known.
    pub unbalance_peak: Option<bool>,
}

/// The critical speeds of `criticals` that are not overdamped crossings,
/// each with its separation margin from `range` (rad/s) and its distance
/// from `max_speed` (rad/s).
pub fn critical_margins(
    criticals: &[CriticalSpeed],
    range: Option<&OperatingRange>,
    max_speed: Option<f64>,
) -> Vec<CriticalMargin> {
    criticals
        .iter()
        .filter(|c| !c.is_overdamped())
        .map(|c| {
            // An undamped or unstable mode has an unbounded resonance.
            let af = if c.damping_ratio >= super::modal::ROUND_OFF_DAMPING_RATIO {
                1.0 / (2.0 * c.damping_ratio)
            } else {
                f64::INFINITY
            };
            CriticalMargin {
                critical: *c,
                amplification_factor: af,
                margin: range.map(|r| separation_margin(c.speed, af, r)),
                from_max_speed: max_speed.map(|m| (c.speed - m) / m),
                unbalance_peak: None,
            }
        })
        .collect()
}

/// Modes at every speed of `speeds` (rad/s, increasing); nonlinear bearings are
/// linearized about the static equilibrium at each speed, tilting pads
/// condensed at the running speed (synchronous coefficients;
/// [`campbell_study`] takes each mode's pads at its own frequency). The modes of each
/// speed are linked to those of the previous one by their shapes (largest
/// total MAC, [`super::mode_tracking::link`]), so a branch follows one mode
/// through crossings and veering; a mode entering the listed range starts a
/// new branch. Non-oscillating roots are kept apart and start no branch.
pub fn campbell(
    rotor: &Rotor,
    speeds: &[f64],
    options: &ModalOptions,
) -> Result<Vec<CampbellPoint>, ModalError> {
    Ok(sweep(rotor, speeds, options, None, (0, Pads::Synchronous))?.0)
}

/// How the modes of a sweep see the tilting pads.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Pads {
    /// Condensed at the running speed (the bearings' synchronous
    /// coefficients, as ROSS and vendor tables give them).
    Synchronous,
    /// Each mode's pads at its own eigenvalue and every root checked against
    /// the pad coordinates ([`modal_analysis_own`]); the same as
    /// `Synchronous` for a rotor without internal bearing coordinates.
    OwnFrequency,
}

/// [`campbell`], and with `harmonic` the brackets of its crossings of
/// `ω = harmonic·Ω`: every pair of neighbouring speeds of a branch where
/// `ω_b − harmonic·Ω` changes sign, with the branch's modes at both ends.
fn sweep(
    rotor: &Rotor,
    speeds: &[f64],
    options: &ModalOptions,
    harmonic: Option<f64>,
    (threads, pads): (usize, Pads),
) -> Result<(Vec<CampbellPoint>, Vec<Bracket>), ModalError> {
    let solves = map_in_order(speeds, threads, |&speed| match pads {
        Pads::Synchronous => modal_analysis_at(rotor, speed, options),
        Pads::OwnFrequency => modal_analysis_own(rotor, speed, options)
            .map_err(|e| ModalError::OwnFrequency(e.to_string())),
    });
    let mut diagram = Vec::with_capacity(speeds.len());
    let mut brackets = Vec::new();
    let mut previous: Vec<(usize, Vec<Complex64>)> = Vec::new();
    // The last mode seen of every branch (with `harmonic` only).
    let mut last: Vec<Option<Known>> = Vec::new();
    let mut branches = 0;
    for (&speed, result) in speeds.iter().zip(solves) {
        let result = result?;
        let shapes: Vec<Vec<Complex64>> = result
            .modes
            .iter()
            .map(|m| translations(&m.shape))
            .collect();
        let earlier: Vec<Vec<Complex64>> = previous.iter().map(|(_, s)| s.clone()).collect();
        let links = link(&earlier, &shapes);
        let mut ids = Vec::with_capacity(shapes.len());
        for l in links {
            ids.push(match l {
                Some(j) => previous[j].0,
                None => {
                    branches += 1;
                    branches - 1
                }
            });
        }
        if let Some(h) = harmonic {
            last.resize(branches, None);
            for (m, &b) in result.modes.iter().zip(&ids) {
                let now = Known::of(rotor, speed, m);
                if let Some(before) = last[b].take() {
                    let ga = before.lambda.im.abs() - h * before.speed;
                    let gb = m.damped_frequency - h * speed;
                    if ga != 0.0 && ga.signum() != gb.signum() {
                        brackets.push(Bracket {
                            branch: b,
                            start: before,
                            end: now.clone(),
                        });
                    }
                }
                last[b] = Some(now);
            }
        }
        diagram.push(CampbellPoint {
            speed,
            modes: result
                .modes
                .iter()
                .zip(&ids)
                .map(|(m, &b)| ModeSummary::of(m, b))
                .collect(),
            overdamped: result.overdamped,
        });
        previous = ids.into_iter().zip(shapes).collect();
    }
    Ok((diagram, brackets))
}

/// Number of branches of a diagram.
pub fn branch_count(diagram: &[CampbellPoint]) -> usize {
    diagram
        .iter()
        .flat_map(|p| p.modes.iter().map(|m| m.branch + 1))
        .max()
        .unwrap_or(0)
}

/// The points `(speed, mode)` of branch `b`, by increasing speed.
pub fn branch(diagram: &[CampbellPoint], b: usize) -> Vec<(f64, ModeSummary)> {
    diagram
        .iter()
        .filter_map(|p| {
            p.modes
                .iter()
                .find(|m| m.branch == b)
                .map(|m| (p.speed, *m))
        })
        .collect()
}

/// Critical speeds within the range of `diagram`: roots of `ω_b(Ω) − h Ω` along
/// every tracked branch `b`, bracketed between neighbouring speeds where the
/// branch is present and refined by the secant/bisection (Illinois) method to
/// `1e-8` relative, each iterate's mode the one that continues the branch's
/// shape at the bracket's start, found from the nearest speed already
/// evaluated by nonlinear inverse iteration (whole eigen-solves only where that mode's
/// shape does not continue the branch). The branch's modes at the bracket's
/// ends are solved anew; [`campbell_study`] keeps them from the sweep. A
/// branch that jumps across the line inside a bracket, or a critical speed
/// found on two branches ([`repeated_criticals`]), both signs of modes not
/// followed across a step of `diagram`, is an error ([`campbell_study`]
/// refines its grid instead).
pub fn critical_speeds(
    rotor: &Rotor,
    diagram: &[CampbellPoint],
    harmonic: f64,
    options: &ModalOptions,
) -> Result<Vec<CriticalSpeed>, ModalError> {
    let mut brackets = Vec::new();
    for b in 0..branch_count(diagram) {
        let points = branch(diagram, b);
        let g = |(s, m): &(f64, ModeSummary)| m.damped_frequency - harmonic * s;
        for pair in points.windows(2) {
            let (ga, gb) = (g(&pair[0]), g(&pair[1]));
            if ga == 0.0 || ga.signum() == gb.signum() {
                continue;
            }
            let mut ends = [pair[0].0, pair[1].0].into_iter().map(|speed| {
                let modes = modal_analysis_at(rotor, speed, options)?.modes;
                let rank = diagram
                    .iter()
                    .find(|p| p.speed == speed)
                    .and_then(|p| p.modes.iter().position(|m| m.branch == b))
                    .unwrap_or(0);
                Ok::<_, ModalError>(Known::of(rotor, speed, &modes[rank]))
            });
            let (start, end) = (ends.next().unwrap()?, ends.next().unwrap()?);
            brackets.push(Bracket {
                branch: b,
                start,
                end,
            });
        }
    }
    let (found, jumps) = refined(rotor, diagram, &brackets, harmonic, options, 0)?;
    if let Some((speed, b)) = jumps.first() {
        return Err(ModalError::Options(format!(
            "branch {} jumps across the {harmonic}× line at {speed} rad/s instead of crossing it: \
             its modes were not followed across a speed step; use a finer diagram",
            b + 1
        )));
    }
    if let Some((speed, a, b)) = repeated_criticals(&found).first() {
        return Err(ModalError::Options(format!(
            "the critical speed {speed} rad/s appears on branches {} and {}: \
             a mode was not followed across a speed step; use a finer diagram",
            a + 1,
            b + 1
        )));
    }
    Ok(found)
}

/// Where a branch jumps across the 1× line: `(speed, branch)`, speed in rad/s.
type Jump = (f64, usize);

/// The critical speeds of `brackets`, by speed, and the brackets where the
/// branch jumps across the line instead.
fn refined(
    rotor: &Rotor,
    diagram: &[CampbellPoint],
    brackets: &[Bracket],
    harmonic: f64,
    options: &ModalOptions,
    threads: usize,
) -> Result<(Vec<CriticalSpeed>, Vec<Jump>), ModalError> {
    let results = map_in_order(brackets, threads, |bracket| {
        refine(rotor, diagram, bracket, harmonic, options)
    });
    let (mut found, mut jumps) = (Vec::new(), Vec::new());
    for r in results {
        match r? {
            Refined::Root(c) => found.push(c),
            Refined::Jump { speed, branch } => jumps.push((speed, branch)),
        }
    }
    found.sort_by(|a, b| a.speed.total_cmp(&b.speed));
    Ok((found, jumps))
}

/// What a Campbell study sweeps (speeds in rad/s).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CampbellRequest {
    /// Top speed; `None` for the model's default
    /// ([`default_top_speed`](super::speed_range::default_top_speed) with the
    /// operating range).
    pub max: Option<f64>,
    /// Speed steps (the grid has `steps + 1` speeds, [`speed_grid`]).
    pub steps: usize,
    /// Oscillating modes per speed.
    pub modes: usize,
    /// Operating range of the separation margins.
    pub operating: Option<OperatingRange>,
    /// Threads the speeds and the critical-speed refinements are spread over
    /// (`0`: every core; the results are the same bit for bit).
    pub threads: usize,
}

impl CampbellRequest {
    /// The defaults of `rotor campbell`: the model's top speed, 40 steps, 8
    /// modes, margins from `operating`.
    pub fn default_for(operating: Option<OperatingRange>) -> Self {
        Self {
            max: None,
            steps: 40,
            modes: 8,
            operating,
            threads: 0,
        }
    }
}

/// A Campbell study: the diagram, its 1× critical speeds (overdamped
/// crossings among them, [`CriticalSpeed::is_overdamped`]) and their API 684
/// margins from the operating range and distance from the maximum speed.
#[derive(Debug, Clone, PartialEq)]
pub struct CampbellStudy {
    /// The tracked diagram.
    pub diagram: Vec<CampbellPoint>,
    /// Every crossing of the 1× line, by speed.
    pub criticals: Vec<CriticalSpeed>,
    /// The critical speeds (not overdamped) with their margins.
    pub margins: Vec<CriticalMargin>,
    /// The top speed (rad/s).
    pub top: f64,
    /// Where the top speed came from (`None` when given).
    pub top_origin: Option<super::speed_range::TopSpeedOrigin>,
    /// The operating range of the margins.
    pub operating: Option<OperatingRange>,
    /// The model's maximum speed, when the file states it (rad/s).
    pub max_speed: Option<f64>,
    /// Wall-clock time (s) of the diagram alone (the modes at every speed,
    /// tracked), without the critical speeds' refinement: what the
    /// benchmarks time.
    pub diagram_seconds: f64,
    /// The speed steps asked for; the diagram has more (twice, four or eight
    /// times as many) when a critical speed appeared on two branches with
    /// the same whirl on the grid asked for (see [`campbell_study`]).
    pub requested_steps: usize,
    /// Critical speeds still found on two branches with the same whirl after
    /// the grid was refined ([`repeated_criticals`]): `(speed, branch, branch)`.
    pub repeated: Vec<(f64, usize, usize)>,
    /// Branches that jump across the 1× line instead of crossing it (the
    /// followed mode changes inside a bracket: a mode linked to another's
    /// branch across a step), still after the grid was refined:
    /// `(speed, branch)`, the speed (rad/s) where the branch jumps.
    pub jumps: Vec<(f64, usize)>,
    /// The lowest torsional modes ([`torsional_modes`], as many as lateral
    /// ones were asked for) of a model that describes its torsion
    /// ([`RotorModel::models_torsion`](crate::model::RotorModel::models_torsion)),
    /// else none: horizontal lines, the twist having no gyroscopic coupling
    /// to the spin.
    pub torsional: Vec<TorsionalMode>,
}

impl CampbellStudy {
    /// The lowest critical speed (rad/s, not overdamped) of the diagram, the
    /// one a hydro unit's runaway speed must stay below.
    pub fn first_critical_speed(&self) -> Option<f64> {
        self.margins
            .iter()
            .map(|m| m.critical.speed)
            .min_by(f64::total_cmp)
    }
}

/// The Campbell study `rotor campbell` and the report run: the diagram with
/// each mode's tilting pads at its own eigenvalue ([`modal_analysis_own`]),
/// its 1× crossings refined on the synchronous linearization (exact there:
/// the mode whirls at the running speed).
pub fn campbell_study(
    rotor: &Rotor,
    request: &CampbellRequest,
) -> Result<CampbellStudy, ModalError> {
    let (top, top_origin) = match request.max {
        Some(m) => (m, None),
        None => {
            let (t, o) =
                super::speed_range::default_top_speed(&rotor.model, request.operating.as_ref());
            (t, Some(o))
        }
    };
    if !(top.is_finite() && top > 0.0) || request.steps == 0 {
        return Err(ModalError::Options(format!(
            "--max-rpm must be positive (got {} rpm) and --steps at least 1 (got {})",
            top * crate::units::RAD_S_TO_RPM,
            request.steps
        )));
    }
    let options = ModalOptions {
        modes: request.modes,
        ..ModalOptions::default()
    };
    // A grid step across which a mode cannot be followed links it to another
    // mode's branch: the other mode's critical speed is found twice (and the
    // mode's own is missed), or the branch jumps across the 1× line. The
    // grid is then refined.
    let mut steps = request.steps;
    let (diagram, diagram_seconds, criticals, repeated, jumps) = loop {
        let clock = std::time::Instant::now();
        let grid = speed_grid(rotor, top, steps);
        let (diagram, brackets) = sweep(
            rotor,
            &grid,
            &options,
            Some(1.0),
            (request.threads, Pads::OwnFrequency),
        )?;
        let diagram_seconds = clock.elapsed().as_secs_f64();
        let (criticals, jumps) =
            refined(rotor, &diagram, &brackets, 1.0, &options, request.threads)?;
        let repeated = repeated_criticals(&criticals);
        let tracked = repeated.is_empty() && jumps.is_empty();
        if tracked || steps >= request.steps << MAX_GRID_DOUBLINGS {
            break (diagram, diagram_seconds, criticals, repeated, jumps);
        }
        steps *= 2;
    };
    let model = &rotor.model;
    let max_speed = model.max_speed_stated.then_some(model.max_speed);
    let mut margins = critical_margins(&criticals, request.operating.as_ref(), max_speed);
    // A backward crossing that unbalance does not excite is listed, not judged.
    for m in &mut margins {
        if m.critical.whirl != Whirl::Backward {
            continue;
        }
        m.unbalance_peak = unbalance_peak_at(rotor, m.critical.speed, m.critical.damping_ratio);
        if let (Some(false), Some(sm)) = (m.unbalance_peak, m.margin.as_mut()) {
            sm.pass = true;
        }
    }
    let torsional = if model.models_torsion() {
        torsional_modes(model, request.modes)
            .map_err(|source| ModalError::Linalg { speed: 0.0, source })?
    } else {
        Vec::new()
    };
    Ok(CampbellStudy {
        torsional,
        diagram,
        criticals,
        margins,
        top,
        top_origin,
        operating: request.operating,
        max_speed,
        diagram_seconds,
        requested_steps: request.steps,
        repeated,
        jumps,
    })
}

/// How many times [`campbell_study`] doubles the speed steps while a
/// critical speed appears on two branches.
pub const MAX_GRID_DOUBLINGS: u32 = 3;

/// The critical speeds found on two branches with the same definite whirl
/// (forward or backward) within 1e-6 relative, as `(speed, branch, branch)`:
/// two modes of one whirl cross the 1× line at one speed only by accident,
/// while a mode followed onto another's branch across a coarse grid step
/// repeats that mode's crossing exactly. (Two modes of a rotor without
/// gyroscopic coupling share a speed with opposite whirls, or are planar.)
/// The lower branch comes first.
pub fn repeated_criticals(criticals: &[CriticalSpeed]) -> Vec<(f64, usize, usize)> {
    let mut out = Vec::new();
    for (i, a) in criticals.iter().enumerate() {
        for b in &criticals[i + 1..] {
            if a.whirl == b.whirl
                && a.whirl != Whirl::Mixed
                && (a.speed - b.speed).abs() <= 1e-6 * a.speed.abs().max(b.speed.abs())
            {
                out.push((a.speed, a.branch.min(b.branch), a.branch.max(b.branch)));
            }
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The classic rotor's diagram up to 20 000 rpm in 1 step gives a jump,
    /// in 2 steps a repeated critical speed: both errors naming the branch;
    /// 8 steps give its seven critical speeds.
    #[test]
    fn critical_speeds_refuses_a_diagram_too_coarse_to_follow_the_modes() {
        let rotor = Rotor::new(crate::model::RotorModel::default_model()).unwrap();
        let options = ModalOptions {
            modes: 8,
            ..ModalOptions::default()
        };
        let top = 20_000.0 * std::f64::consts::PI / 30.0;
        let found = |steps: usize| {
            let speeds: Vec<f64> = (0..=steps).map(|k| top * k as f64 / steps as f64).collect();
            let diagram = campbell(&rotor, &speeds, &options).unwrap();
            critical_speeds(&rotor, &diagram, 1.0, &options)
        };
        let error = found(1).unwrap_err().to_string();
        assert!(
            error.contains("branch 7 jumps across the 1× line at 2094.39"),
            "{error}"
        );
        let error = found(2).unwrap_err().to_string();
        assert!(error.contains("appears on branches 3 and 4"), "{error}");
        assert_eq!(found(8).unwrap().len(), 7);
    }

    /// Only a definite whirl repeated at one speed (to 1e-6) counts:
    /// opposite whirls, planar (mixed) modes and speeds 2e-6 apart do not.
    #[test]
    fn a_critical_speed_repeats_with_its_whirl() {
        let c = |speed: f64, branch: usize, whirl: Whirl| CriticalSpeed {
            speed,
            harmonic: 1.0,
            rank: branch,
            branch,
            whirl,
            damping_ratio: 0.01,
        };
        let found = [
            c(100.0, 0, Whirl::Forward),
            c(100.0, 1, Whirl::Backward),
            c(200.0, 2, Whirl::Mixed),
            c(200.0, 3, Whirl::Mixed),
            c(300.0, 4, Whirl::Forward),
            c(300.0006, 5, Whirl::Forward),
            c(492.753, 6, Whirl::Forward),
            c(492.753 * (1.0 + 5e-7), 7, Whirl::Forward),
        ];
        assert_eq!(repeated_criticals(&found), vec![(492.753, 6, 7)]);
    }
}
