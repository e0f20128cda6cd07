//! Tilting-pad journal bearing (paper §3, eqs. 19–25): short-bearing film on each
//! pad, Gümbel cavitation, massless rigid pads on rigid pivots.
//!
//! Pad `k` with pivot angle `θp`, preload `m` and tilt `η = ψ R` (ψ the pad
//! rotation about its pivot, counter-clockwise) has the film
//! `h = C − m C cos(θ − θp) − X cos θ − Y sin θ − η sin(θ − θp)`
//! `  = C − X_e cos θ − Y_e sin θ`, with the *effective journal position*
//! `X_e = X + mC cos θp − η sin θp`, `Y_e = Y + mC sin θp + η cos θp`
//! (and `Ẋ_e = Ẋ − η̇ sin θp`, `Ẏ_e = Ẏ + η̇ cos θp`). So each pad is the plain
//! short-bearing film ([`super::plain`]) at the effective position, restricted to
//! the pad's arc (positive pressure only). With `T = ∂(X_e, Y_e)/∂(X, Y, η)
//! = [[1, 0, −sin θp], [0, 1, cos θp]]` the generalized forces are `Tᵀ F_pad`
//! (the third, `Q_η`, is the pivot moment divided by the pad radius) and the
//! Jacobians `Tᵀ K_pad T`, `Tᵀ C_pad T`, exact because `T` is constant.
//!
//! **Pad tilts are extra unknowns** ([`Bearing::internal_dofs`]), not an inner
//! solve: a massless pad's moment balance `Q_η(X, Y, Ẋ, Ẏ, η, η̇) = 0` contains
//! `η̇` (the pad's own squeeze film), so the tilt has first-order dynamics of its
//! own. Solving it inside Newton–Raphson with the journal keeps that dynamics;
//! a quasi-static inner solve (η̇ = 0) would invent cross-coupled damping
//! (`tests/data/tilting_pad_reference.json`, `quasi_static_reduced`).
//!
//! **Unloaded pads.** A pad the journal moves away from has no zero-moment
//! tilt that carries load in short-bearing/Gümbel theory: its film force
//! vanishes for a whole range of tilts, and its equation would be `0 = 0`. Every
//! pivot therefore has a weak restoring moment `Q_rest = −k_r η − c_r η̇` with
//! `c_r = 10⁻⁹ μRL³/C³` and `k_r = c_r · max(|ω|, 1 rad/s)`: nine orders of
//! magnitude below the film of a loaded pad (loaded pads' tilts and the
//! coefficients move by ~10⁻⁸ relative), it parks an unloaded pad where its film
//! just stops carrying load and keeps the system non-singular.

use std::f64::consts::PI;

use nalgebra::Vector2;

pub use super::pad::{Pad, PadSupport};

use super::BearingForce;
use super::contact::{ContactExtent, ContactLaw, ContactReport};
use super::pad_tally::PadTally;
use super::short_film::{Film, ShortFilm, Terms, force_only_of};
use super::{Bearing, BearingError, BearingEval, BearingReport, JournalState, check_state};

/// Relative size of the pivot's restoring moment (see the module docs).
const PIVOT_REST: f64 = 1e-9;

/// `|p_e|² / C²` below which a pad's contact is not evaluated (it is zero
/// there; the margin covers the rounding of `n·p_e` against `|p_e|`).
const CONTACT_FREE: f64 = 1.0 - 1e-9;

/// Tilting-pad journal bearing (SI units).
#[derive(Debug, Clone, PartialEq)]
pub struct TiltingPadBearing {
    /// Journal radius `R` (m).
    pub radius: f64,
    /// Pad length `L` (m).
    pub length: f64,
    /// Pad (machined) radial clearance `C` (m).
    pub clearance: f64,
    /// Oil dynamic viscosity `μ` (Pa·s).
    pub viscosity: f64,
    /// The pads.
    pub pads: Vec<Pad>,
    /// Journal–pad contact; `None`: the steel default [`ContactLaw::steel`] for
    /// this geometry (gap = the pad clearance, on each pad's effective position).
    pub contact: Option<ContactLaw>,
    /// The pads' pivot stiffness and inertia ([`PadSupport`]; default rigid
    /// pivots, massless pads).
    pub support: PadSupport,
}

impl TiltingPadBearing {
    fn film(&self) -> ShortFilm {
        ShortFilm {
            radius: self.radius,
            length: self.length,
            clearance: self.clearance,
            viscosity: self.viscosity,
        }
    }

    /// The journal–pad contact law (gap = the pad clearance `C`).
    pub fn contact_law(&self) -> ContactLaw {
        self.contact
            .unwrap_or_else(|| ContactLaw::steel(self.clearance, self.radius, self.length))
    }

    /// Contact of the journal with pad `k` at the pad's effective journal state:
    /// with the pad's circular surface (`|p_e| = C`) when the closest approach
    /// lies on the pad's arc, else with its nearer edge (a flat contact of
    /// normal `(cos θ_e, sin θ_e)`). Both give the same penetration and normal at
    /// the arc's ends, so the force is continuous. `None` within the gap
    /// (`|p_e| < C`), where neither the surface nor the edges touch
    /// (`n·p_e ≤ |p_e|`): no force, no contact to report.
    pub(crate) fn pad_contact(
        &self,
        law: &ContactLaw,
        k: usize,
        state: &JournalState,
        speed: f64,
    ) -> Option<(BearingForce, ContactReport)> {
        let p = state.position;
        if p.norm_squared() < CONTACT_FREE * law.gap * law.gap {
            return None;
        }
        let pad = &self.pads[k];
        let window = &pad.window;
        let phi = p.y.atan2(p.x);
        if (phi - window.from).rem_euclid(2.0 * PI) <= pad.arc {
            return Some(law.evaluate(p, state.velocity, speed));
        }
        let lead = Vector2::new(window.from_sc.1, window.from_sc.0);
        let trail = Vector2::new(window.to_sc.1, window.to_sc.0);
        let normal = if p.dot(&lead) >= p.dot(&trail) {
            lead
        } else {
            trail
        };
        Some(law.evaluate_edge(normal, p, state.velocity, speed))
    }

    /// Assembled (bearing) clearance `C_b = C (1 − m)`, the smallest over the pads (m).
    pub fn assembled_clearance(&self) -> f64 {
        self.pads
            .iter()
            .map(|p| self.clearance * (1.0 - p.preload))
            .fold(self.clearance, f64::min)
    }

    /// Minimum film thickness (m) on pad `k` at `q = [x, y, η…]`: the film
    /// `h = C − X_e cos θ − Y_e sin θ` at the effective journal position `p_e`
    /// is thinnest, `C − |p_e|`, at `θ = atan2(Y_e, X_e)` when that lies on the
    /// pad's arc (for arcs under π: `p_e` between the ends' directions by the
    /// signs of two cross products), else at the nearer edge.
    pub fn pad_min_film_thickness(&self, k: usize, q: &[f64]) -> f64 {
        let [x, y] = self.journal_seen_by(k, q);
        self.min_film_at(k, self.pad_position(k, x, y, q[2 + k]))
    }

    /// [`TiltingPadBearing::pad_min_film_thickness`] at the effective journal
    /// position `p` of pad `k`.
    fn min_film_at(&self, k: usize, p: Vector2<f64>) -> f64 {
        let pad = &self.pads[k];
        let window = &pad.window;
        let lead = Vector2::new(window.from_sc.1, window.from_sc.0);
        let trail = Vector2::new(window.to_sc.1, window.to_sc.0);
        let inside = if pad.arc < PI {
            lead.perp(&p) >= 0.0 && p.perp(&trail) >= 0.0
        } else {
            (p.y.atan2(p.x) - window.from).rem_euclid(2.0 * PI) <= pad.arc
        };
        let thinnest = if inside {
            self.clearance - p.norm()
        } else {
            (self.clearance - p.dot(&lead)).min(self.clearance - p.dot(&trail))
        };
        thinnest.max(0.0)
    }

    /// Pivot rest damping `c_r` (N·s/m) and stiffness `k_r` (N/m) at spin
    /// `speed` (see the module docs).
    pub(crate) fn pivot_rest(&self, speed: f64) -> (f64, f64) {
        let c_rest = PIVOT_REST * self.viscosity * self.radius * self.length.powi(3)
            / self.clearance.powi(3);
        (c_rest, c_rest * speed.abs().max(1.0))
    }

    /// The stable zero-moment tilt of pad `k` with the journal held at
    /// `journal` (m), no rates: the first sign change of the film's pivot
    /// moment from + to − on a scan of 65 tilts over ±0.98 C, refined by
    /// bisection; `None` when the film's moment never changes sign that way
    /// (a pad that carries nothing at any tilt).
    pub fn stable_tilt(&self, k: usize, journal: [f64; 2], speed: f64) -> Option<f64> {
        let pad = &self.pads[k];
        let film = self.film();
        let (s, c) = pad.pivot_sc;
        let moment = |eta: f64| -> Option<f64> {
            let state = JournalState {
                position: self.pad_position(k, journal[0], journal[1], eta),
                velocity: Vector2::zeros(),
            };
            let f = film.force(&state, speed, Some(&pad.window)).ok()?.force;
            Some(c * f.y - s * f.x)
        };
        let reach = self.clearance * 0.98;
        let samples = 64;
        let mut prev: Option<(f64, f64)> = None;
        for i in 0..=samples {
            let eta = -reach + 2.0 * reach * i as f64 / samples as f64;
            let Some(m) = moment(eta) else {
                prev = None;
                continue;
            };
            if let Some((e0, m0)) = prev {
                if m0 > 0.0 && m <= 0.0 {
                    let (mut lo, mut hi) = (e0, eta);
                    for _ in 0..60 {
                        let mid = 0.5 * (lo + hi);
                        match moment(mid) {
                            Some(v) if v > 0.0 => lo = mid,
                            _ => hi = mid,
                        }
                    }
                    return Some(0.5 * (lo + hi));
                }
            }
            prev = Some((eta, m));
        }
        None
    }

    /// Pad `k`'s moment balance `Q_η` (N) and `K_ηη`, `C_ηη` at `q`, `q̇`
    /// ([`Bearing::internal_balance`]).
    fn pad_balance(
        &self,
        k: usize,
        q: &[f64],
        qdot: &[f64],
        speed: f64,
    ) -> Result<[f64; 3], BearingError> {
        let film = self.film();
        // (A pad `k` beyond the bearing's is refused by `pad_balance_of`.)
        let window = self.pads.get(k).map(|p| p.window);
        self.pad_balance_of(k, q, qdot, speed, &|state| {
            film.force(state, speed, window.as_ref())
        })
    }

    /// [`Self::pad_balance`] with pad `k`'s film force and Jacobians at its
    /// effective journal state given by `film` (the short film's, or a
    /// finite film's: `super::finite_bearing`).
    pub(crate) fn pad_balance_of(
        &self,
        k: usize,
        q: &[f64],
        qdot: &[f64],
        speed: f64,
        film: &dyn Fn(&JournalState) -> Result<BearingForce, BearingError>,
    ) -> Result<[f64; 3], BearingError> {
        let n = 2 + self.internal_dofs();
        if q.len() != n || qdot.len() != n || k >= self.pads.len() {
            return Err(BearingError::Dimension {
                expected: n,
                found: q.len(),
            });
        }
        let (s, c, state) = self.pad_state(k, q, qdot);
        // t = (−sin θp, cos θp), the third column of T.
        let t = [-s, c];
        let mut out = [0.0; 3];
        let mut add = |part: &BearingForce| {
            out[0] += t[0] * part.force.x + t[1] * part.force.y;
            for (slot, mat) in [(1, &part.stiffness), (2, &part.damping)] {
                let col = [
                    mat[(0, 0)] * t[0] + mat[(0, 1)] * t[1],
                    mat[(1, 0)] * t[0] + mat[(1, 1)] * t[1],
                ];
                out[slot] += t[0] * col[0] + t[1] * col[1];
            }
        };
        add(&film(&state)?);
        if let Some((contact, _)) = self.pad_contact(&self.contact_law(), k, &state, speed) {
            add(&contact);
        }
        let (c_rest, k_rest) = self.pivot_rest(speed);
        let i = 2 + k;
        out[0] -= k_rest * q[i] + c_rest * qdot[i];
        out[1] += k_rest;
        out[2] += c_rest;
        Ok(out)
    }

    /// Film force on pad `k` alone at `q`, `q̇`: the force on the journal (N).
    pub fn pad_force(
        &self,
        k: usize,
        q: &[f64],
        qdot: &[f64],
        speed: f64,
    ) -> Result<Vector2<f64>, BearingError> {
        let (_, _, state) = self.pad_state(k, q, qdot);
        Ok(self
            .film()
            .force(&state, speed, Some(&self.pads[k].window))?
            .force)
    }
}

/// Pads whose films are prepared, then evaluated together, at a time.
const PAD_BATCH: usize = 8;

/// A batch of pads: each pad's `(sin, cos)` of its pivot angle and its
/// effective journal state ([`TiltingPadBearing::pad_state`]), and its film.
struct PadBatch {
    states: [(f64, f64, JournalState); PAD_BATCH],
    films: [Film; PAD_BATCH],
}

impl PadBatch {
    fn new() -> Self {
        Self {
            states: [(0.0, 0.0, JournalState::default()); PAD_BATCH],
            films: [Film::Nothing; PAD_BATCH],
        }
    }
}

impl Bearing for TiltingPadBearing {
    fn internal_dofs(&self) -> usize {
        self.support.coordinates_per_pad() * self.pads.len()
    }

    fn internal_mass(&self, m: usize) -> f64 {
        self.support.mass(m, self.pads.len(), self.radius)
    }

    fn evaluate(
        &self,
        q: &[f64],
        qdot: &[f64],
        speed: f64,
        out: &mut BearingEval,
    ) -> Result<(), BearingError> {
        let n = 2 + self.internal_dofs();
        check_state(n, q, qdot, speed, out)?;
        out.clear();
        self.write_mass(out);
        let film = self.film();
        let law = self.contact_law();
        // Pads in batches: their films' potentials evaluated together
        // (`ShortFilm::complete`), then each pad's force in pad order.
        let mut pads = PadBatch::new();
        for first in (0..self.pads.len()).step_by(PAD_BATCH) {
            let batch = first..(first + PAD_BATCH).min(self.pads.len());
            self.prepare_films(
                batch.clone(),
                q,
                qdot,
                speed,
                Terms::WithJacobians,
                &mut pads,
            );
            for (i, k) in batch.enumerate() {
                let (s, c, state) = &pads.states[i];
                let part = film.force_of(pads.films[i], speed)?;
                self.add_pad_part(out, k, (*s, *c), &part);
                if let Some((contact, _)) = self.pad_contact(&law, k, state, speed) {
                    self.add_pad_part(out, k, (*s, *c), &contact);
                }
                self.add_pivot(out, k, q, qdot, speed, true);
            }
        }
        Ok(())
    }

    fn is_linear(&self) -> bool {
        false
    }

    fn contact_extent(&self, q: &[f64], qdot: &[f64], speed: f64) -> Option<ContactExtent> {
        let law = self.contact_law();
        (0..self.pads.len())
            .filter_map(|k| {
                let (_, _, state) = self.pad_state(k, q, qdot);
                law.extent(&self.pad_contact(&law, k, &state, speed)?.1)
            })
            .reduce(ContactExtent::worst)
    }

    /// Pads free to tilt carry a journal where it reaches a pad's pivot:
    /// `p·u_k = C (1 − m)` with `u_k` the pivot direction, first along
    /// `direction` for `d·u_k > 0`; the assembled clearance when no pad faces it.
    fn resting_contact(&self, direction: [f64; 2]) -> Option<(f64, f64)> {
        let reach = self
            .pads
            .iter()
            .filter_map(|pad| {
                let (s, c) = pad.pivot_sc;
                let facing = direction[0] * c + direction[1] * s;
                (facing > 1e-9).then(|| self.clearance * (1.0 - pad.preload) / facing)
            })
            .fold(f64::INFINITY, f64::min);
        let gap = if reach.is_finite() {
            reach
        } else {
            self.assembled_clearance()
        };
        Some((gap, self.contact_law().stiffness))
    }

    /// Each pad's stable zero-moment tilt with the journal held (pads alone, no
    /// rates): the first sign change of `Q_η` from + to − on a scan of tilts that
    /// keep the pad film open, refined by bisection ([`TiltingPadBearing::stable_tilt`]).
    /// A pad with none (unloaded) starts at zero. Newton from zero tilts can
    /// otherwise run to the unloaded root, where the film vanishes.
    ///
    /// On pivots with a stiffness, each pad's radial displacement `ξ` is
    /// where its pivot spring carries its film's radial force with the pad
    /// on its stable tilt, `k_piv ξ = −u·F(ξ)`, by bisection on
    /// `[0, −u·F(0)/k_piv]` (the film's push falls as the pad recedes).
    fn guess_internal(&self, journal: [f64; 2], speed: f64, internal: &mut [f64]) {
        for (k, tilt) in internal.iter_mut().take(self.pads.len()).enumerate() {
            *tilt = self.seated_tilt(k, journal, speed);
        }
        let Some(k_piv) = self.support.pivot_stiffness else {
            return;
        };
        let n = self.pads.len();
        for k in 0..n {
            let (s, c) = self.pads[k].pivot_sc;
            // The pad's radial push on its pivot, `−u·F`, at `ξ`, with its tilt.
            let push = |xi: f64| -> (f64, f64) {
                let seen = [journal[0] - xi * c, journal[1] - xi * s];
                let eta = self.seated_tilt(k, seen, speed);
                let state = JournalState {
                    position: self.pad_position(k, seen[0], seen[1], eta),
                    velocity: Vector2::zeros(),
                };
                let f = self
                    .film()
                    .force(&state, speed, Some(&self.pads[k].window))
                    .map(|f| f.force)
                    .unwrap_or_else(|_| Vector2::zeros());
                (-(c * f.x + s * f.y), eta)
            };
            let (first, eta0) = push(0.0);
            internal[n + k] = 0.0;
            internal[k] = eta0;
            if first.is_nan() || first <= 0.0 {
                continue;
            }
            let (mut lo, mut hi) = (0.0, first / k_piv);
            for _ in 0..40 {
                let mid = 0.5 * (lo + hi);
                if push(mid).0 > k_piv * mid {
                    lo = mid;
                } else {
                    hi = mid;
                }
            }
            let xi = 0.5 * (lo + hi);
            internal[n + k] = xi;
            internal[k] = push(xi).1;
        }
    }

    /// A pad on the unloaded branch — its film carries nothing (less than the
    /// pivot's rest moment makes at one clearance, `k_r C`) although a stable
    /// zero-moment tilt where it carries load exists at this journal position —
    /// is set to that tilt: the pad the journal moves towards takes up load, as
    /// a free pad does. Loaded pads, and unloaded pads without a loaded tilt,
    /// are left alone. On pivots with a stiffness the journal is the one the
    /// pad's film sees off its radial displacement.
    fn reseat_internal(&self, q: &mut [f64], speed: f64) -> bool {
        let film = self.film();
        let unloaded = self.pivot_rest(speed).1 * self.clearance;
        let rest = vec![0.0; q.len()];
        let mut changed = false;
        for k in 0..self.pads.len() {
            let force = |q: &[f64]| -> Option<f64> {
                let (_, _, state) = self.pad_state(k, q, &rest);
                Some(
                    film.force(&state, speed, Some(&self.pads[k].window))
                        .ok()?
                        .force
                        .norm(),
                )
            };
            if force(q).is_none_or(|f| f > unloaded) {
                continue;
            }
            let Some(tilt) = self.stable_tilt(k, self.journal_seen_by(k, q), speed) else {
                continue;
            };
            let previous = q[2 + k];
            q[2 + k] = tilt;
            if force(q).is_some_and(|f| f > unloaded) {
                changed = true;
            } else {
                q[2 + k] = previous;
            }
        }
        changed
    }

    fn report(&self, q: &[f64], qdot: &[f64], speed: f64, eval: &BearingEval) -> BearingReport {
        let film = self.film();
        let law = self.contact_law();
        let mut tally = PadTally::default();
        for (k, pad) in self.pads.iter().enumerate() {
            let (_, _, state) = self.pad_state(k, q, qdot);
            let film_torque = film.friction_torque(&state, speed, Some(&pad.window));
            let contact = self.pad_contact(&law, k, &state, speed);
            tally.add(&law, film_torque, contact.as_ref(), speed);
            tally.min_film = tally.min_film.min(self.min_film_at(k, state.position));
        }
        tally.report(q, eval, self.assembled_clearance())
    }

    /// One pass over the pads: each pad's state once, its film force without
    /// the Jacobians ([`ShortFilm::force_only`]), whose potential also gives the
    /// friction of a pad the pressure covers wholly; the same numbers as
    /// `evaluate` then `report`.
    fn output(
        &self,
        q: &[f64],
        qdot: &[f64],
        speed: f64,
        out: &mut BearingEval,
    ) -> Result<BearingReport, BearingError> {
        let film = self.film();
        let law = self.contact_law();
        let mut tally = PadTally::default();
        self.pad_forces(q, qdot, speed, out, |k, state, whole, contact| {
            let film_torque = match whole {
                Some(phi) => film.friction_torque_of(phi, speed),
                None => film.friction_torque(state, speed, Some(&self.pads[k].window)),
            };
            tally.add(&law, film_torque, contact, speed);
            tally.min_film = tally.min_film.min(self.min_film_at(k, state.position));
        })?;
        Ok(tally.report(q, out, self.assembled_clearance()))
    }

    /// The film force without its Jacobians is about half the work.
    fn cheap_forces(&self) -> bool {
        true
    }

    /// Pad `m`'s moment balance alone: the third row of `Tᵀ F_pad` and the
    /// diagonal of `Tᵀ K_pad T`, `Tᵀ C_pad T` (module docs), with its contact
    /// and its pivot's rest moment, as [`Bearing::evaluate`] adds them.
    fn internal_balance(
        &self,
        m: usize,
        q: &[f64],
        qdot: &[f64],
        speed: f64,
    ) -> Option<Result<[f64; 3], BearingError>> {
        // On pivots with a stiffness a pad's tilt and radial displacement
        // balance together: no balance of one coordinate alone.
        if self.radial() {
            return None;
        }
        Some(self.pad_balance(m, q, qdot, speed))
    }

    /// The forces of [`Bearing::output`] alone.
    fn forces(
        &self,
        q: &[f64],
        qdot: &[f64],
        speed: f64,
        out: &mut BearingEval,
    ) -> Result<(), BearingError> {
        self.pad_forces(q, qdot, speed, out, |_, _, _, _| {})
    }
}

impl TiltingPadBearing {
    /// Pad `k`'s starting tilt with the journal seen at `journal` (m): its
    /// stable zero-moment tilt ([`TiltingPadBearing::stable_tilt`]), else,
    /// with the journal pressed onto the pad's pivot line (at rest on the
    /// pad), the tilt that puts the contact at the pivot, `η = −p·t_k`,
    /// else zero.
    fn seated_tilt(&self, k: usize, journal: [f64; 2], speed: f64) -> f64 {
        let pad = &self.pads[k];
        let (s, c) = pad.pivot_sc;
        let pressed = journal[0] * c + journal[1] * s >= self.clearance * (1.0 - pad.preload);
        let resting = if pressed {
            journal[0] * s - journal[1] * c
        } else {
            0.0
        };
        self.stable_tilt(k, journal, speed).unwrap_or(resting)
    }

    /// One pass over the pads for the generalized forces in `out.force`, each
    /// pad's film force without its Jacobians (the numbers of
    /// [`ShortFilm::force_only`], a batch of pads' potentials evaluated
    /// together as in `evaluate`); `each_pad` sees pad `k`'s effective
    /// journal state, `∫ dθ/H` over the pad when the pressure covers all of
    /// it, and its contact.
    fn pad_forces(
        &self,
        q: &[f64],
        qdot: &[f64],
        speed: f64,
        out: &mut BearingEval,
        mut each_pad: impl FnMut(
            usize,
            &JournalState,
            Option<f64>,
            Option<&(BearingForce, ContactReport)>,
        ),
    ) -> Result<(), BearingError> {
        let n = 2 + self.internal_dofs();
        check_state(n, q, qdot, speed, out)?;
        out.force.fill(0.0);
        let law = self.contact_law();
        let mut pads = PadBatch::new();
        for first in (0..self.pads.len()).step_by(PAD_BATCH) {
            let batch = first..(first + PAD_BATCH).min(self.pads.len());
            self.prepare_films(batch.clone(), q, qdot, speed, Terms::ForceOnly, &mut pads);
            for (i, k) in batch.enumerate() {
                let (s, c, state) = &pads.states[i];
                let (force, whole) = force_only_of(pads.films[i])?;
                self.add_pad_force(out, k, (*s, *c), &force);
                let contact = self.pad_contact(&law, k, state, speed);
                if let Some((contact, _)) = &contact {
                    self.add_pad_force(out, k, (*s, *c), &contact.force);
                }
                self.add_pivot(out, k, q, qdot, speed, false);
                each_pad(k, state, whole, contact.as_ref());
            }
        }
        Ok(())
    }

    /// The states of the pads `batch` (at most [`PAD_BATCH`]) and their films
    /// with the potentials (up to the Jacobians' terms, or the force's alone,
    /// as `terms` asks) evaluated together ([`ShortFilm::complete`]), into
    /// the first `batch.len()` entries of `pads` (the caller's, so that
    /// nothing is copied back).
    fn prepare_films(
        &self,
        batch: std::ops::Range<usize>,
        q: &[f64],
        qdot: &[f64],
        speed: f64,
        terms: Terms,
        pads: &mut PadBatch,
    ) {
        let film = self.film();
        for (i, k) in batch.clone().enumerate() {
            pads.states[i] = self.pad_state(k, q, qdot);
            pads.films[i] =
                film.prepare(&pads.states[i].2, speed, Some(&self.pads[k].window), terms);
        }
        film.complete(&mut pads.films[..batch.len()], terms);
    }
}

#[cfg(test)]
mod tests;
