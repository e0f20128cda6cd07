//! The short-bearing (Ocvirk) film with the Gümbel π-film (half-Sommerfeld)
//! cavitation condition (paper §3, eqs. 6–18, re-derived), over the whole
//! circle (the plain bearing, [`super::plain`]) or a window of it (a pad of
//! [`super::tilting_pad`]): force, Jacobians and friction torque.
//!
//! Film `h = C − X cos θ − Y sin θ`; the short-bearing Reynolds equation gives
//! `p = (3μ/h³)(z² − L²/4) S(θ)` with the film "source"
//! `S = ω ∂h/∂θ + 2 ∂h/∂t = A sin θ − B cos θ`, `A = ωX − 2Ẏ`, `B = ωY + 2Ẋ`.
//! Pressure is positive where `S < 0`: exactly the half circle
//! `θ ∈ [α, α + π]`, `α = atan2(B, A) + π`, which moves with the journal's
//! velocity. Integrating over `z` and the arc, the force on the journal is
//!
//! `F = (μRL³/2C³) ∫_α^{α+π} S t / H³ dθ`, `t = (cos θ, sin θ)`, `H = h/C`,
//!
//! i.e. with [`FilmIntegrals`] and `c = μRL³/(4C³)`:
//! `F_x = c (A Φ_xy − B Φ_xx)`, `F_y = c (A Φ_yy − B Φ_xy)`.
//! Because `S = 0` at both arc ends, moving ends add nothing to the derivatives:
//! `C = 2c [[Φ_xx, Φ_xy], [Φ_xy, Φ_yy]]` (symmetric) and
//! `−K_x· = c [ω Φ_xy + (A Φ_xxy − B Φ_xxx)/C, −ω Φ_xx + (A Φ_xyy − B Φ_xxy)/C]`,
//! `−K_y· = c [ω Φ_yy + (A Φ_xyy − B Φ_xxy)/C, −ω Φ_xy + (A Φ_yyy − B Φ_xyy)/C]`.
//! Nothing divides by ω: at ω = 0 this is the pure squeeze film.
//!
//! **Near and in contact** (`ε → 1` and beyond) the short-bearing film grows
//! without bound (`∝ (1 − ε²)^-2`) and has no meaning at `ε ≥ 1`, where the
//! journal touches the bushing. The film is therefore evaluated at a *saturated*
//! journal position ([`film_position`]): the actual one up to
//! [`FILM_SATURATION_START`], then radially
//! `ε_f = ε_∞ − (ε_∞ − ε_a) exp(−(ε − ε_a)/(ε_∞ − ε_a))`, C¹ at `ε_a` and below
//! [`FILM_SATURATION_LIMIT`] for every `ε`, so force, Jacobians and friction stay
//! finite and continuous at and beyond contact (a film thinner than
//! `(1 − ε_∞) C` — surface roughness — carries no more than that). The bushing
//! itself acts through the contact law ([`super::contact`]) from `ε = 1` on.

use std::f64::consts::PI;

use nalgebra::{Matrix2, Vector2};

use super::film::{FilmIntegrals, Jet3};
use super::film_lanes::{ArcLanes, arc_potentials, arc_potentials2};
use super::{BearingError, BearingForce, JournalState};

/// Eccentricity ratio `ε_a` up to which the film sees the actual journal position.
pub const FILM_SATURATION_START: f64 = 0.97;
/// Eccentricity ratio `ε_∞` the saturated film position tends to as the journal
/// goes on into contact.
pub const FILM_SATURATION_LIMIT: f64 = 0.995;

/// The journal position the film is evaluated at (m) for the actual `position`
/// (m) in a clearance `clearance` (m), and its Jacobian
/// `J = ∂p_f/∂p = ρ' n nᵀ + (ρ/ε)(I − n nᵀ)` (see the module docs; the identity
/// up to [`FILM_SATURATION_START`]).
pub fn film_position(position: Vector2<f64>, clearance: f64) -> (Vector2<f64>, Matrix2<f64>) {
    // Well inside the start (the common case) without the square root; the
    // margin keeps the decision the one `ε <= ε_a` takes.
    let inside = FILM_SATURATION_START * clearance;
    if position.norm_squared() <= (1.0 - 1e-9) * inside * inside {
        return (position, Matrix2::identity());
    }
    let eps = position.norm() / clearance;
    if eps <= FILM_SATURATION_START {
        return (position, Matrix2::identity());
    }
    let span = FILM_SATURATION_LIMIT - FILM_SATURATION_START;
    let decay = (-(eps - FILM_SATURATION_START) / span).exp();
    let rho = FILM_SATURATION_LIMIT - span * decay;
    let n = position / position.norm();
    let nnt = n * n.transpose();
    let jac = nnt * decay + (Matrix2::identity() - nnt) * (rho / eps);
    (n * (rho * clearance), jac)
}

/// Short-bearing film of radius `R`, length `L`, clearance `C`, viscosity `μ`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct ShortFilm {
    pub radius: f64,
    pub length: f64,
    pub clearance: f64,
    pub viscosity: f64,
}

/// An arc `[from, to]` of the film (rad) with the sines and cosines of its ends.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct FilmWindow {
    pub from: f64,
    pub to: f64,
    pub from_sc: (f64, f64),
    pub to_sc: (f64, f64),
}

impl FilmWindow {
    pub(crate) fn new(from: f64, to: f64) -> Self {
        Self {
            from,
            to,
            from_sc: from.sin_cos(),
            to_sc: to.sin_cos(),
        }
    }
}

impl ShortFilm {
    /// Force and Jacobians of the film over the positive-pressure part of the
    /// window (`None`: the whole circle, i.e. the π-film half circle).
    pub(crate) fn force(
        &self,
        state: &JournalState,
        speed: f64,
        window: Option<&FilmWindow>,
    ) -> Result<BearingForce, BearingError> {
        let film = self.prepare(state, speed, window, Terms::WithJacobians);
        self.force_of(film, speed)
    }

    /// Force and Jacobians of a [`Film`] (its potential evaluated here if
    /// [`ShortFilm::complete`] has not).
    pub(crate) fn force_of(&self, film: Film, speed: f64) -> Result<BearingForce, BearingError> {
        let FilmAt {
            f,
            a,
            b,
            c,
            saturation,
            ..
        } = match self.completed(film, Terms::WithJacobians) {
            Film::Ready(at) => at,
            Film::Nothing | Film::Whole { .. } => {
                return Ok(BearingForce {
                    force: Vector2::zeros(),
                    stiffness: Matrix2::zeros(),
                    damping: Matrix2::zeros(),
                });
            }
        };
        let cl = self.clearance;
        let force = Vector2::new(c * (a * f.xy - b * f.xx), c * (a * f.yy - b * f.xy));
        let dfx_dx = c * (speed * f.xy + (a * f.xxy - b * f.xxx) / cl);
        let dfx_dy = c * (-speed * f.xx + (a * f.xyy - b * f.xxy) / cl);
        let dfy_dx = c * (speed * f.yy + (a * f.xyy - b * f.xxy) / cl);
        let dfy_dy = c * (-speed * f.xy + (a * f.yyy - b * f.xyy) / cl);
        let out = BearingForce {
            force,
            stiffness: -Matrix2::new(dfx_dx, dfx_dy, dfy_dx, dfy_dy) * saturation,
            damping: Matrix2::new(f.xx, f.xy, f.xy, f.yy) * (2.0 * c),
        };
        let finite = out.force.iter().all(|v| v.is_finite())
            && out.stiffness.iter().all(|v| v.is_finite())
            && out.damping.iter().all(|v| v.is_finite());
        if finite {
            Ok(out)
        } else {
            Err(BearingError::NotFinite {
                what: "film force",
                value: out.force.norm(),
            })
        }
    }

    /// The force of [`ShortFilm::force`] alone (the same number, from the
    /// potential's terms up to degree 2), and `∫ dθ/H` over the window when the
    /// pressure covers all of it (what [`ShortFilm::friction_torque`] needs, the
    /// same number too), for reports.
    pub(crate) fn force_only(
        &self,
        state: &JournalState,
        speed: f64,
        window: Option<&FilmWindow>,
    ) -> Result<(Vector2<f64>, Option<f64>), BearingError> {
        let film = self.completed(
            self.prepare(state, speed, window, Terms::ForceOnly),
            Terms::ForceOnly,
        );
        force_only_of(film)
    }

    /// `film` with its potential evaluated if it waits for one.
    fn completed(&self, film: Film, terms: Terms) -> Film {
        if !matches!(film, Film::Whole { .. }) {
            return film;
        }
        let mut one = [film];
        self.complete(&mut one, terms);
        let [film] = one;
        film
    }

    /// The film integrals at `state` over the positive-pressure part of the
    /// window, with the source coefficients `A`, `B`, the force constant
    /// `μ R L³ / (4 C³)` and the saturation Jacobian ([`Film::Nothing`] when
    /// the pressure half circle misses the window), but for the potential
    /// over a window the pressure covers wholly, which
    /// [`ShortFilm::complete`] evaluates (several films at once).
    #[inline(always)]
    pub(crate) fn prepare(
        &self,
        state: &JournalState,
        speed: f64,
        window: Option<&FilmWindow>,
        terms: Terms,
    ) -> Film {
        let cl = self.clearance;
        let (position, saturation) = film_position(state.position, cl);
        let state = &JournalState {
            position,
            velocity: state.velocity,
        };
        let (x, y) = (state.position.x / cl, state.position.y / cl);
        let (a, b) = source_coefficients(state, speed);
        let cover = window.map(|w| pressure_cover(w, a, b, state, speed));
        if cover == Some(Cover::Nothing) {
            return Film::Nothing;
        }
        let c = self.viscosity * self.radius * self.length.powi(3) / (4.0 * cl.powi(3));
        let at = FilmAt {
            f: FilmIntegrals::default(),
            a,
            b,
            c,
            saturation,
            whole: None,
        };
        match (window, cover) {
            (Some(w), Some(Cover::Whole)) => Film::Whole {
                at,
                x,
                y,
                span: w.to - w.from,
                from_sc: w.from_sc,
                to_sc: w.to_sc,
            },
            _ => Film::Ready(FilmAt {
                f: integrals_by_angles(x, y, (a, b), state, speed, window, terms),
                ..at
            }),
        }
    }

    /// Evaluate the potentials that `films` wait for ([`Film::Whole`]),
    /// making them [`Film::Ready`]: [`LANES`] at a time on the lanes of
    /// [`arc_potentials`] (with the Jacobians) or [`arc_potentials2`] (the
    /// force alone), the same numbers as one by one.
    pub(crate) fn complete(&self, films: &mut [Film], terms: Terms) {
        if films.len() == 1 {
            for film in films.iter_mut() {
                if let Film::Whole {
                    at,
                    x,
                    y,
                    span,
                    from_sc,
                    to_sc,
                } = *film
                {
                    let (f, whole) = terms.over_arc(x, y, span, from_sc, to_sc);
                    *film = Film::Ready(FilmAt { f, whole, ..at });
                }
            }
            return;
        }
        let mut waiting = [0usize; LANES];
        let mut count = 0;
        for k in 0..=films.len() {
            if k < films.len() && matches!(films[k], Film::Whole { .. }) {
                waiting[count] = k;
                count += 1;
            }
            if count == LANES || (k == films.len() && count > 0) {
                complete_lanes(films, &waiting[..count], terms);
                count = 0;
            }
        }
    }
    /// Couette (Petroff-corrected) friction torque of the film over the window
    /// (`None`: the whole circle),
    /// shear `μωR/h` on the journal surface: `T = (μωR³L/C) ∫ dθ/H` (N·m). The
    /// cavitated film is taken to carry shear too (striated oil).
    pub(crate) fn friction_torque(
        &self,
        state: &JournalState,
        speed: f64,
        window: Option<&FilmWindow>,
    ) -> f64 {
        let (position, _) = film_position(state.position, self.clearance);
        let (x, y) = (position.x / self.clearance, position.y / self.clearance);
        // Over the whole circle the antiderivative's atan terms cancel:
        // `∫₀^{2π} dθ/H = 2π/√(1 − ε²)`.
        let phi = match window {
            None => 2.0 * PI / (1.0 - x * x - y * y).sqrt(),
            Some(w) => super::film::arc_potential_value(x, y, w.to - w.from, w.from_sc, w.to_sc),
        };
        self.friction_torque_of(phi, speed)
    }

    /// The friction torque `(μωR³L/C) Φ` from `Φ = ∫ dθ/H` over the film (N·m).
    pub(crate) fn friction_torque_of(&self, phi: f64, speed: f64) -> f64 {
        self.viscosity * speed * self.radius.powi(3) * self.length / self.clearance * phi
    }
}

/// The force of a [`Film`] made complete for the force alone, and `∫ dθ/H`
/// over its window when the pressure covers all of it
/// ([`ShortFilm::force_only`]).
pub(crate) fn force_only_of(film: Film) -> Result<(Vector2<f64>, Option<f64>), BearingError> {
    let Film::Ready(FilmAt {
        f, a, b, c, whole, ..
    }) = film
    else {
        return Ok((Vector2::zeros(), None));
    };
    let force = Vector2::new(c * (a * f.xy - b * f.xx), c * (a * f.yy - b * f.xy));
    if force.iter().all(|v| v.is_finite()) {
        Ok((force, whole))
    } else {
        Err(BearingError::NotFinite {
            what: "film force",
            value: force.norm(),
        })
    }
}

/// The potentials (up to the Jacobians' terms, or the force's alone, as
/// `terms` asks) of the wholly covered `films[k]`, `k` in `which` (at most
/// [`LANES`]), on the lanes of one [`arc_potentials`] or [`arc_potentials2`];
/// unused lanes repeat the last arc.
fn complete_lanes(films: &mut [Film], which: &[usize], terms: Terms) {
    let arc_of = |film: &Film| match *film {
        Film::Whole {
            x,
            y,
            span,
            from_sc,
            to_sc,
            ..
        } => (x, y, span, from_sc, to_sc),
        _ => unreachable!("complete_lanes is given wholly covered films only"),
    };
    let arcs: [_; LANES] =
        std::array::from_fn(|lane| arc_of(&films[which[lane.min(which.len() - 1)]]));
    let lanes = ArcLanes {
        x: arcs.map(|a| a.0),
        y: arcs.map(|a| a.1),
        span: arcs.map(|a| a.2),
        from_sc: (arcs.map(|a| a.3.0), arcs.map(|a| a.3.1)),
        to_sc: (arcs.map(|a| a.4.0), arcs.map(|a| a.4.1)),
    };
    let integrals: [(FilmIntegrals, f64); LANES] = match terms {
        Terms::WithJacobians => {
            let phi = arc_potentials(&lanes);
            std::array::from_fn(|lane| {
                let jet = Jet3::from_coefficients(phi.c.map(|v| v[lane]));
                (FilmIntegrals::from_potential(jet), jet.value())
            })
        }
        Terms::ForceOnly => {
            let phi = arc_potentials2(&lanes);
            std::array::from_fn(|lane| {
                let c = phi.map(|v| v[lane]);
                (FilmIntegrals::from_potential2(c), c[0])
            })
        }
    };
    for (&k, (f, whole)) in which.iter().zip(integrals) {
        if let Film::Whole { at, .. } = films[k] {
            films[k] = Film::Ready(FilmAt {
                f,
                whole: Some(whole),
                ..at
            });
        }
    }
}

/// Which terms of the film potential a caller needs.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Terms {
    /// Up to degree 3: the force and its Jacobians.
    WithJacobians,
    /// Up to degree 2: the force alone.
    ForceOnly,
}

impl Terms {
    /// The film integrals over an arc of length `span` with the given end
    /// sines and cosines, and the potential's value `∫ dθ/H` over it.
    fn over_arc(
        self,
        x: f64,
        y: f64,
        span: f64,
        from: (f64, f64),
        to: (f64, f64),
    ) -> (FilmIntegrals, Option<f64>) {
        match self {
            Terms::WithJacobians => {
                let phi = super::film::arc_potential_sc(x, y, span, from, to);
                (FilmIntegrals::from_potential(phi), Some(phi.value()))
            }
            Terms::ForceOnly => {
                let phi = super::film::arc_potential_sc2(x, y, span, from, to);
                (FilmIntegrals::from_potential2(phi), Some(phi[0]))
            }
        }
    }
}

/// Arcs evaluated together on the lanes of [`arc_potentials`].
const LANES: usize = 2;

/// A film on its way to its force: [`ShortFilm::prepare`] leaves the
/// potential of a wholly covered window to [`ShortFilm::complete`].
#[derive(Debug, Clone, Copy)]
pub(crate) enum Film {
    /// The pressure half circle misses the window: no force.
    Nothing,
    /// The integrals are known.
    Ready(FilmAt),
    /// The pressure covers the window wholly: its potential over the arc of
    /// length `span` with the given end sines and cosines, at the film
    /// position `(x, y)` (of the clearance), is still to be evaluated.
    Whole {
        at: FilmAt,
        x: f64,
        y: f64,
        span: f64,
        from_sc: (f64, f64),
        to_sc: (f64, f64),
    },
}

/// The film integrals at a state and what the force is made of.
#[derive(Debug, Clone, Copy)]
pub(crate) struct FilmAt {
    f: FilmIntegrals,
    /// Source coefficients `A`, `B` (m/s).
    a: f64,
    b: f64,
    /// `μ R L³ / (4 C³)`.
    c: f64,
    /// Jacobian of the saturated film position.
    saturation: Matrix2<f64>,
    /// `∫ dθ/H` over the window when the pressure covers all of it.
    whole: Option<f64>,
}

/// The film integrals over the positive-pressure half circle `[α, α + π]`,
/// `α = atan2(B, A) + π`, within the window (`None`: all of it), by the angles
/// of its ends (see [`ShortFilm::force`]).
fn integrals_by_angles(
    x: f64,
    y: f64,
    (a, b): (f64, f64),
    state: &JournalState,
    speed: f64,
    window: Option<&FilmWindow>,
    terms: Terms,
) -> FilmIntegrals {
    // The positive-pressure half circle [α, α + π], α = atan2(B, A) + π, has
    // its ends' sines and cosines without trigonometry:
    // (sin α, cos α) = −(B, A)/|(A, B)|. With S ≡ 0 there is no pressure; any
    // half circle gives the one-sided limit of the Jacobian (the force is
    // not differentiable there).
    let r = a.hypot(b);
    let pressure = !source_vanishes(state, speed, r);
    let start = || {
        if pressure {
            b.atan2(a) + PI
        } else {
            y.atan2(x) + 0.5 * PI
        }
    };
    let start_sc = if pressure {
        (-b / r, -a / r)
    } else {
        start().sin_cos()
    };
    let end_sc = (-start_sc.0, -start_sc.1);
    match window {
        None => terms.over_arc(x, y, PI, start_sc, end_sc).0,
        Some(w) => {
            let start = start();
            let mut sum = FilmIntegrals::default();
            for k in -2..=1 {
                let from = start + 2.0 * PI * k as f64;
                let to = from + PI;
                let (lo, lo_sc) = if from >= w.from {
                    (from, start_sc)
                } else {
                    (w.from, w.from_sc)
                };
                let (hi, hi_sc) = if to <= w.to {
                    (to, end_sc)
                } else {
                    (w.to, w.to_sc)
                };
                if hi > lo {
                    sum = sum + terms.over_arc(x, y, hi - lo, lo_sc, hi_sc).0;
                }
            }
            sum
        }
    }
}

/// Start of the positive-pressure half circle `[α, α + π]` (rad), or `None` when
/// `S ≡ 0` (no pressure anywhere: journal centred at rest, or whirling about the
/// centre at exactly ω/2).
pub fn pressure_arc_start(state: &JournalState, speed: f64) -> Option<f64> {
    let (a, b) = source_coefficients(state, speed);
    if source_vanishes(state, speed, a.hypot(b)) {
        None
    } else {
        Some(b.atan2(a) + PI)
    }
}

/// `S ≡ 0` to round-off: `|(A, B)|` (given) below 1e-14 of its terms' size.
fn source_vanishes(state: &JournalState, speed: f64, magnitude: f64) -> bool {
    magnitude <= 1e-14 * source_scale(state, speed) || magnitude == 0.0
}

/// The size of the terms of `A` and `B` (m/s).
fn source_scale(state: &JournalState, speed: f64) -> f64 {
    (speed * state.position.x).abs()
        + (speed * state.position.y).abs()
        + 2.0 * state.velocity.x.abs()
        + 2.0 * state.velocity.y.abs()
}

/// How the positive-pressure half circle covers a film window.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Cover {
    /// Not at all: the film carries nothing.
    Nothing,
    /// The whole window.
    Whole,
    /// In part, or too close to call from the window's ends.
    Partial,
}

/// Where the pressure half circle `S < 0` lies on window `w`, from the sign of
/// `S = A sin θ − B cos θ` at its two ends: a window shorter than π is covered
/// wholly when both ends have `S < 0` and not at all when both have `S > 0`.
/// Ends within 1e-9 rad of the half circle's ends, windows of π or more and a
/// vanishing `S` are [`Cover::Partial`], which [`ShortFilm::force`] integrates
/// by the angles: the two decisions agree wherever these are taken.
fn pressure_cover(w: &FilmWindow, a: f64, b: f64, state: &JournalState, speed: f64) -> Cover {
    let size = a.abs() + b.abs();
    // |(A, B)| ≥ max(|A|, |B|) > 1e-14 · scale: `S` does not vanish.
    if w.to - w.from >= PI - 1e-6 || a.abs().max(b.abs()) <= 1e-14 * source_scale(state, speed) {
        return Cover::Partial;
    }
    let margin = 1e-9 * size;
    let s_from = a * w.from_sc.0 - b * w.from_sc.1;
    let s_to = a * w.to_sc.0 - b * w.to_sc.1;
    if s_from < -margin && s_to < -margin {
        Cover::Whole
    } else if s_from > margin && s_to > margin {
        Cover::Nothing
    } else {
        Cover::Partial
    }
}

/// `A = ωX − 2Ẏ`, `B = ωY + 2Ẋ` (m/s): `S(θ) = A sin θ − B cos θ`.
fn source_coefficients(state: &JournalState, speed: f64) -> (f64, f64) {
    let (p, v) = (state.position, state.velocity);
    (speed * p.x - 2.0 * v.y, speed * p.y + 2.0 * v.x)
}
