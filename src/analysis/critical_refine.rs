//! Refinement of a critical speed inside a bracket of the Campbell diagram,
//! used by [`super::campbell`].
//!
//! The root of `g(Ω) = ω_b(Ω) − hΩ` along a tracked branch `b` is found by
//! the Illinois method (regula falsi with halving) to `1e-8` relative. Each
//! iterate needs only the branch's own mode at the new speed: nonlinear
//! inverse iteration on the quadratic problem from the eigenvalue
//! interpolated between the two nearest speeds already evaluated and the
//! vector of the nearest ([`super::modal::mode_near`]: one to three complex
//! factorizations at 480 elements, where the whole eigen-solve builds a
//! Krylov basis of 52 to 60 vectors and polishes ten modes), converged to
//! what the quadratic problem determines as the whole eigen-solve's
//! polishing is (the refined critical speeds' modes, recomputed by whole
//! eigen-solves, lie on the 1× line to 1e-8 with the damping ratios to 1e-12).
//! The mode found is accepted when its shape continues the branch, MAC ≥
//! [`ACCEPT_MAC`] with the branch's shape at the bracket's start: modes of
//! nearly orthogonal shapes share that shape's MAC, so no other mode can
//! continue it better. Otherwise (and when the Krylov run does not converge)
//! the iterate falls back to the whole eigen-solve and the mode of largest
//! MAC, as before.

use nalgebra::Complex;

use super::campbell_point::{CampbellPoint, CriticalSpeed};
use super::linearize::linearized;
use super::modal::{
    ModalError, ModalOptions, Mode, Whirl, modal_analysis_at, mode_near, orbit_radii,
};
use super::mode_tracking::{mac, translations};
use crate::fe::{DOF_PER_NODE, DOF_X, DOF_Y};
use crate::rotor::Rotor;

type C64 = Complex<f64>;

/// Smallest MAC with the branch's shape at the bracket's start at which the
/// mode found from a neighbouring speed's vector is taken as the branch's: above 1/2 no other
/// mode of a nearly orthogonal shape can match the shape better.
pub const ACCEPT_MAC: f64 = 0.7;

/// A mode of one branch at one speed: its eigenvalue, its vector on the free
/// DOFs and its translations (for the MAC).
#[derive(Debug, Clone)]
pub(crate) struct Known {
    pub speed: f64,
    pub lambda: C64,
    pub x: Vec<C64>,
    pub shape: Vec<C64>,
}

impl Known {
    /// The known mode `m` of `rotor` at `speed`.
    pub fn of(rotor: &Rotor, speed: f64, m: &Mode) -> Self {
        let x = (0..rotor.dofs.free_count())
            .map(|i| m.shape[rotor.dofs.full(i)])
            .collect();
        Self {
            speed,
            lambda: m.eigenvalue,
            x,
            shape: translations(&m.shape),
        }
    }
}

/// A sign change of `ω_b − hΩ` between two neighbouring speeds of branch
/// `branch`.
#[derive(Debug, Clone)]
pub(crate) struct Bracket {
    pub branch: usize,
    pub start: Known,
    pub end: Known,
}

/// The share of a mode's squared amplitude `Σ (r_f² + r_b²)` that the nodes
/// whirling one way must carry for a critical speed whose nodes whirl both
/// ways to be named by that sense.
pub const DOMINANT_WHIRL_SHARE: f64 = 0.9;

/// The whirl a critical speed is named by: the mode's own when every node
/// whirls one way; otherwise (anisotropic supports — table bearings, plain
/// films — make the orbits ellipses, and the small orbits of the overhung
/// ends or of the stations near a nodal point may turn the other way) the
/// sense of the nodes that carry at least [`DOMINANT_WHIRL_SHARE`] of the
/// shape's squared amplitude, each node's orbit `r_f² + r_b²` with its
/// forward and backward radii `|X ± iY|/2` (a node within 1 % of planar
/// counts for neither sense); mixed only when neither sense dominates.
pub(crate) fn dominant_whirl(mode: &Mode, nodes: usize, speed: f64) -> Whirl {
    if mode.whirl != Whirl::Mixed || speed == 0.0 {
        return mode.whirl;
    }
    let (mut forward, mut backward, mut total) = (0.0, 0.0, 0.0);
    for k in 0..nodes {
        let node = &mode.shape[k * DOF_PER_NODE..];
        let (f, b) = orbit_radii(node[DOF_X], node[DOF_Y]);
        let size = f * f + b * b;
        total += size;
        if f > 1.01 * b {
            forward += size;
        } else if b > 1.01 * f {
            backward += size;
        }
    }
    if speed < 0.0 {
        std::mem::swap(&mut forward, &mut backward);
    }
    if forward >= DOMINANT_WHIRL_SHARE * total {
        Whirl::Forward
    } else if backward >= DOMINANT_WHIRL_SHARE * total {
        Whirl::Backward
    } else {
        Whirl::Mixed
    }
}

/// `ω − hΩ` of the mode `m` at `speed`.
fn excess(m: &Mode, speed: f64, harmonic: f64) -> f64 {
    m.damped_frequency - harmonic * speed
}

/// The mode of `modes` whose shape is nearest `shape` (largest MAC), with its
/// rank.
fn nearest(modes: &[Mode], shape: &[C64]) -> Option<(usize, Mode)> {
    modes
        .iter()
        .enumerate()
        .map(|(k, m)| (k, mac(shape, &translations(&m.shape)), m))
        .max_by(|a, b| a.1.total_cmp(&b.1))
        .map(|(k, _, m)| (k, m.clone()))
}

/// The branch's mode at `speed` from the known ones (see the module docs),
/// with its rank when it came from a whole eigen-solve.
fn follow(
    rotor: &Rotor,
    speed: f64,
    known: &[Known],
    (b, branch_shape): (usize, &[C64]),
    options: &ModalOptions,
) -> Result<(Mode, Option<usize>, Known), ModalError> {
    let linear;
    let rotor_at = if rotor.nonlinear_bearings.is_empty() {
        rotor
    } else {
        linear = linearized(rotor, speed, speed)?;
        &linear
    };
    // The two known speeds nearest `speed`: λ interpolated (or extrapolated)
    // linearly between them, the vector of the nearest.
    let mut by_distance: Vec<&Known> = known.iter().collect();
    by_distance.sort_by(|a, b| (a.speed - speed).abs().total_cmp(&(b.speed - speed).abs()));
    let (p, q) = (by_distance[0], by_distance[1]);
    let t = if q.speed != p.speed {
        (speed - p.speed) / (q.speed - p.speed)
    } else {
        0.0
    };
    let guess = p.lambda + (q.lambda - p.lambda) * t;
    if let Some((mode, x)) = mode_near(rotor_at, speed, guess, &p.x) {
        let shape = translations(&mode.shape);
        if mode.eigenvalue.im > 0.0 && mac(branch_shape, &shape) >= ACCEPT_MAC {
            let k = Known {
                speed,
                lambda: mode.eigenvalue,
                x,
                shape,
            };
            return Ok((mode, None, k));
        }
    }
    let modes = modal_analysis_at(rotor, speed, options)?.modes;
    let (rank, mode) = nearest(&modes, branch_shape).ok_or_else(|| {
        ModalError::Options(format!("branch {} vanished at {speed} rad/s", b + 1))
    })?;
    let k = Known::of(rotor, speed, &mode);
    Ok((mode, Some(rank), k))
}

/// The rank (by frequency) of branch `b` at a speed inside the bracket
/// `(start, end)` of `diagram` when the same branches lie below it at both
/// ends; `None` when that set changes inside the bracket.
fn rank_between(diagram: &[CampbellPoint], b: usize, start: f64, end: f64) -> Option<usize> {
    let below = |speed: f64| -> Option<Vec<usize>> {
        let p = diagram.iter().find(|p| p.speed == speed)?;
        let own = p.modes.iter().find(|m| m.branch == b)?.damped_frequency;
        let mut set: Vec<usize> = p
            .modes
            .iter()
            .filter(|m| m.damped_frequency < own)
            .map(|m| m.branch)
            .collect();
        set.sort_unstable();
        Some(set)
    };
    let (a, z) = (below(start)?, below(end)?);
    (a == z).then_some(a.len())
}

/// What the refinement of a bracket found.
#[derive(Debug, Clone, PartialEq)]
pub(crate) enum Refined {
    /// A crossing of the 1× line: a critical speed.
    Root(CriticalSpeed),
    /// No crossing: `g` jumps at `speed` (rad/s), where the followed mode
    /// changes (the bracket's ends are two modes, linked across a step too
    /// wide to follow one).
    Jump { speed: f64, branch: usize },
}

/// Largest `|g(c)| / (|c| max(1, |s|))` at a root, `s` the slope of `g`
/// across the bracket: the Illinois iterations stop within 1e-8 `|c|` of a
/// root of a smooth `g`, where `|g|` is about `1e-8 |c| |g'|`; Illinois on a
/// bracket where `g` jumps converges onto the jump, with `|g|` of the jump's
/// size there.
const JUMP_FRACTION: f64 = 1e-6;

/// The critical speed of `bracket`: Illinois iterations on `g(Ω) = ω_b − hΩ`
/// to `1e-8` relative, each iterate's mode followed from the known ones; a
/// [`Refined::Jump`] where they converge onto a jump of `g` instead.
pub(crate) fn refine(
    rotor: &Rotor,
    diagram: &[CampbellPoint],
    bracket: &Bracket,
    harmonic: f64,
    options: &ModalOptions,
) -> Result<Refined, ModalError> {
    let b = bracket.branch;
    let mut known = vec![bracket.start.clone(), bracket.end.clone()];
    let branch_shape = bracket.start.shape.clone();
    let g = |k: &Known| k.lambda.im.abs() - harmonic * k.speed;
    let at = |speed: f64| -> Result<(f64, (Mode, Option<usize>)), ModalError> {
        let (mode, rank, k) = follow(rotor, speed, &known, (b, &branch_shape), options)?;
        known.push(k);
        Ok((excess(&mode, speed, harmonic), (mode, rank)))
    };
    let (ga, gb) = (g(&bracket.start), g(&bracket.end));
    let (speed, (mode, rank)) = illinois(at, (bracket.start.speed, ga), (bracket.end.speed, gb))?;
    let slope = (gb - ga) / (bracket.end.speed - bracket.start.speed);
    if excess(&mode, speed, harmonic).abs() > JUMP_FRACTION * speed.abs() * slope.abs().max(1.0) {
        return Ok(Refined::Jump { speed, branch: b });
    }
    let rank =
        match rank.or_else(|| rank_between(diagram, b, bracket.start.speed, bracket.end.speed)) {
            Some(r) => r,
            // Another branch crossed this one inside the bracket: its rank at the
            // root comes from the whole eigen-solve there.
            None => {
                let modes = modal_analysis_at(rotor, speed, options)?.modes;
                nearest(&modes, &branch_shape).map_or(0, |(k, _)| k)
            }
        };
    Ok(Refined::Root(CriticalSpeed {
        speed,
        harmonic,
        rank,
        branch: b,
        whirl: dominant_whirl(&mode, rotor.dofs.node_count(), speed),
        damping_ratio: mode.damping_ratio,
    }))
}

/// Illinois regula falsi on a bracket `(a, f(a))`, `(b, f(b))` with a sign
/// change, to a root `c` within `1e-8 |c|`: the bracket has shrunk to that
/// width, or `|f(c)| ≤ 1e-9 |c| |s|` with `s` the secant slope through `c`
/// and the iterate before it (the Newton correction `f(c)/s` a tenth of the
/// tolerance; a critical speed's `f` is smooth, and each iterate after the
/// first lands one to two orders closer than this test asks at 480 elements,
/// where the frequencies themselves are determined to about 5e-11).
fn illinois<T>(
    mut f: impl FnMut(f64) -> Result<(f64, T), ModalError>,
    (mut a, mut fa): (f64, f64),
    (mut b, mut fb): (f64, f64),
) -> Result<(f64, T), ModalError> {
    let mut side = 0;
    let mut last: Option<(f64, T)> = None;
    let mut previous: Option<(f64, f64)> = None;
    for _ in 0..60 {
        let c = (a * fb - b * fa) / (fb - fa);
        let (fc, mode) = f(c)?;
        last = Some((c, mode));
        let slope = previous.map(|(p, fp)| (fc - fp) / (c - p));
        if fc == 0.0
            || (b - a).abs() <= 1e-8 * c.abs().max(1e-12)
            || slope.is_some_and(|s| fc.abs() <= 1e-9 * c.abs() * s.abs())
        {
            break;
        }
        previous = Some((c, fc));
        if fc.signum() == fb.signum() {
            b = c;
            fb = fc;
            if side == -1 {
                fa /= 2.0;
            }
            side = -1;
        } else {
            a = c;
            fa = fc;
            if side == 1 {
                fb /= 2.0;
            }
            side = 1;
        }
    }
    last.ok_or_else(|| ModalError::Options("critical speed search did not start".into()))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::analysis::campbell::{CampbellRequest, campbell_study};
    use crate::model::RotorModel;

    /// Roots of smooth functions of every scale and slope (steep, flat,
    /// curved, saturating) to 1e-8 relative, in at most 12 evaluations
    /// (measured 5 to 9); the residual test is scale-free (`f` and `1e-9 f`
    /// take as many iterates, to the same root).
    #[test]
    fn illinois_finds_roots_to_the_tolerance() {
        /// A function, its bracket and its root.
        type Case<'a> = (&'a dyn Fn(f64) -> f64, f64, f64, f64);
        let cases: [Case; 5] = [
            (&|x| x * x * x - 2.0, 1.0, 2.0, 2f64.cbrt()),
            (&|x| 1e-9 * (x * x * x - 2.0), 1.0, 2.0, 2f64.cbrt()),
            (&|x| (x - 800.0) * (1.0 + 0.01 * x), 700.0, 900.0, 800.0),
            (
                &|x| 850.0 - x + 3e-4 * (x - 800.0).powi(2),
                700.0,
                900.0,
                800.0 + (1.0 - 0.94f64.sqrt()) / 6e-4,
            ),
            (&|x| (x - 59.07).tanh(), 55.0, 110.0, 59.07),
        ];
        let mut iterates = Vec::new();
        for (k, (f, a, b, _)) in cases.iter().enumerate() {
            let mut count = 0;
            let (c, ()) = illinois(
                |x| {
                    count += 1;
                    Ok((f(x), ()))
                },
                (*a, f(*a)),
                (*b, f(*b)),
            )
            .unwrap();
            iterates.push((c, count));
            let exact = cases[k].3;
            assert!(
                (c - exact).abs() <= 1e-8 * exact,
                "case {k}: {c} vs {exact}"
            );
            assert!(count <= 12, "case {k}: {count} evaluations");
        }
        assert_eq!(iterates[0].1, iterates[1].1);
        assert!((iterates[0].0 - iterates[1].0).abs() <= 1e-15 * iterates[0].0);
    }

    /// A bracket whose ends are two modes (the lowest at 1500 rpm, the third
    /// at 1600 rpm: `g` changes sign only because the mode does) is a jump,
    /// not a critical speed; the forward mode's true crossing at 1111.46 rpm,
    /// bracketed on the same rotor, is a root.
    #[test]
    fn a_bracket_across_two_modes_is_a_jump() {
        let rotor = Rotor::new(RotorModel::default_model()).unwrap();
        let options = ModalOptions {
            modes: 8,
            ..ModalOptions::default()
        };
        let rpm = |r: f64| r * std::f64::consts::PI / 30.0;
        let known = |speed: f64, rank: usize| {
            let modes = modal_analysis_at(&rotor, speed, &options).unwrap().modes;
            Known::of(&rotor, speed, &modes[rank])
        };
        let jump = Bracket {
            branch: 0,
            start: known(rpm(1500.0), 0),
            end: known(rpm(1600.0), 2),
        };
        match refine(&rotor, &[], &jump, 1.0, &options).unwrap() {
            Refined::Jump { speed, branch } => {
                assert_eq!(branch, 0);
                assert!(speed >= rpm(1500.0) && speed <= rpm(1600.0), "{speed}");
            }
            other => panic!("{other:?}"),
        }
        let root = Bracket {
            branch: 1,
            start: known(rpm(1000.0), 1),
            end: known(rpm(1200.0), 1),
        };
        match refine(&rotor, &[], &root, 1.0, &options).unwrap() {
            Refined::Root(c) => {
                assert!(
                    (c.speed * 30.0 / std::f64::consts::PI - 1111.46).abs() < 0.005,
                    "{c:?}"
                );
                assert_eq!(c.whirl, crate::analysis::modal::Whirl::Forward);
            }
            other => panic!("{other:?}"),
        }
    }

    /// Every refined critical speed of the classic rotor (8 modes up to
    /// 20 000 rpm, crossings of both whirls) against the whole eigen-solve at
    /// that speed: the mode of the reported rank lies on the 1× line to the
    /// refinement's tolerance, with the reported whirl and damping.
    #[test]
    fn refined_criticals_are_roots_of_the_whole_eigen_solve() {
        let rotor = Rotor::new(RotorModel::default_model()).unwrap();
        let request = CampbellRequest {
            max: Some(20_000.0 * std::f64::consts::PI / 30.0),
            steps: 20,
            modes: 8,
            operating: None,
            threads: 0,
        };
        let study = campbell_study(&rotor, &request).unwrap();
        assert!(study.criticals.len() >= 4, "{:?}", study.criticals);
        let options = ModalOptions {
            modes: 8,
            ..ModalOptions::default()
        };
        for c in &study.criticals {
            let modes = modal_analysis_at(&rotor, c.speed, &options).unwrap().modes;
            let m = &modes[c.rank];
            assert!(
                (m.damped_frequency - c.speed).abs() <= 1e-8 * c.speed,
                "{c:?}: {}",
                m.damped_frequency
            );
            assert_eq!(m.whirl, c.whirl, "{c:?}");
            assert!((m.damping_ratio - c.damping_ratio).abs() <= 1e-12, "{c:?}");
        }
    }
}
