//! Where the short (Ocvirk) film stops describing a bearing (issue 47): a
//! plain bearing longer than [`PLAIN_LIMIT`] (L/D) or pads longer than
//! [`PAD_LIMIT`] (axial length over arc length, `L/(R β)`) on the short film
//! get one warning each, with the short film's stiffness and damping over
//! the finite-length film's at the bearing's operating point and the hint
//! `film = "finite"`.
//!
//! The limits are where the short film is within about 10 % of the finite
//! one at the same journal state (`tests/finite_film.rs`, Gümbel both
//! sides, `docs/bearings.md`): a plain bearing differs by 8.6 % at
//! L/D = 0.2 and 25 % at 0.4 (second order in L/D: 10 % near 0.22); pads by
//! 16 % at `L/(R β)` = 0.077, falling at first order only (10 % near 0.05).
//! The ratios are those of the coefficients at the same load, which is what
//! an analysis sees: each bearing's static load of the rotor's equilibrium
//! ([`operating_point`]), the finite film (Swift–Stieber, the default of
//! `film = "finite"`) in equilibrium under it on [`VALIDITY_MESH`] (a
//! journal without static load, on a vertical rotor, centred with the pads
//! at their zero-moment tilts), pads condensed synchronously as the
//! operating point's are; Frobenius norms.

use std::fmt;

use nalgebra::{Matrix2, Vector2};

use crate::bearing::equilibrium::{condensed_coefficients, journal_equilibrium_direct};
use crate::bearing::finite_bearing::{FiniteFilmBearing, slenderness};
use crate::bearing::reynolds::{Cavitation, ReynoldsMesh};
use crate::bearing::{Bearing, BearingEval, BearingKind};
use crate::rotor::Rotor;

use super::operating_point::{OperatingPointError, operating_point};

/// L/D beyond which a plain bearing's short film is warned about.
pub const PLAIN_LIMIT: f64 = 0.2;
/// `L/(R β)` beyond which tilting pads' short film is warned about.
pub const PAD_LIMIT: f64 = 0.05;
/// Fraction of the film's load scale `μ Ω R L (R/C)²` below which a bearing
/// is compared centred, as an unloaded one.
pub const NEARLY_UNLOADED: f64 = 1e-4;
/// The finite film's mesh for the ratios (per circle or pad): coarser than
/// the default, within about 1 % of it, so the check stays cheap.
pub const VALIDITY_MESH: ReynoldsMesh = ReynoldsMesh {
    circumferential: 72,
    axial: 8,
};

/// One bearing whose short film is outside its range.
#[derive(Debug, Clone, PartialEq)]
pub struct ShortFilmWarning {
    /// Bearing name.
    pub bearing: String,
    /// Whether it is a tilting-pad bearing (its slenderness is `L/(R β)`).
    pub pads: bool,
    /// L/D, or `L/(R β)` for pads.
    pub slenderness: f64,
    /// The speed of the operating point (rad/s).
    pub speed: f64,
    /// The bearing's static load there (N).
    pub load: f64,
    /// `|K_short| / |K_finite|` at that load (`None`: no finite-film
    /// equilibrium was found).
    pub stiffness_ratio: Option<f64>,
    /// `|C_short| / |C_finite|` at that load.
    pub damping_ratio: Option<f64>,
}

impl fmt::Display for ShortFilmWarning {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let (what, limit) = if self.pads {
            ("pad length over arc length L/(R β)", PAD_LIMIT)
        } else {
            ("L/D", PLAIN_LIMIT)
        };
        write!(
            f,
            "bearing {}: short film at {what} = {:.3}, beyond {limit} where it is within about 10 % of the finite-length film; ",
            self.bearing, self.slenderness
        )?;
        let rpm = self.speed * 30.0 / std::f64::consts::PI;
        match (self.stiffness_ratio, self.damping_ratio) {
            (Some(k), Some(c)) => write!(
                f,
                "at its operating point ({rpm:.0} rpm, {:.4e} N) its stiffness is {k:.3} and its damping {c:.3} times the finite film's",
                self.load
            )?,
            _ => write!(
                f,
                "the finite film found no equilibrium at its operating point ({rpm:.0} rpm, {:.4e} N)",
                self.load
            )?,
        }
        write!(f, ": add film = \"finite\" to its [[bearings]] entry")
    }
}

/// A warning for every plain or tilting-pad bearing of `rotor` on the short
/// film beyond [`PLAIN_LIMIT`] or [`PAD_LIMIT`], with its ratios at the
/// operating point at `speed` (rad/s); none at standstill (no film).
pub fn short_film_warnings(
    rotor: &Rotor,
    speed: f64,
) -> Result<Vec<ShortFilmWarning>, OperatingPointError> {
    let model = &rotor.model;
    let beyond = |kind: &BearingKind| match kind {
        BearingKind::Plain(_) => slenderness(kind).filter(|&s| s > PLAIN_LIMIT),
        BearingKind::TiltingPad(_) => slenderness(kind).filter(|&s| s > PAD_LIMIT),
        _ => None,
    };
    if speed == 0.0 || !model.bearings.iter().any(|b| beyond(&b.kind).is_some()) {
        return Ok(Vec::new());
    }
    let points = operating_point(rotor, speed)?;
    let mut out = Vec::new();
    for point in points {
        let kind = &model.bearings[point.bearing].kind;
        let Some(ratio) = beyond(kind) else {
            continue;
        };
        let mut finite =
            FiniteFilmBearing::of(kind, Cavitation::SwiftStieber).expect("plain or tilting pad");
        finite.mesh = VALIDITY_MESH;
        let load = -Vector2::new(point.force[0], point.force[1]);
        let scale = kind.journal_clearance().unwrap_or(1.0);
        let film = finite.film();
        // The film's load scale `μ Ω R L (R/C)²`: below NEARLY_UNLOADED of it
        // the journal moves less than about that fraction of its clearance,
        // and the centred films are the comparison (a Newton on a nearly
        // unloaded pad set is slow and may not converge).
        let load_scale = film.viscosity
            * speed.abs()
            * film.radius
            * film.length
            * (film.radius / film.clearance).powi(2);
        // The films compared with the journal centred (pads at their
        // zero-moment tilts): where a vertical rotor's journal sits.
        let centred = |b: &dyn Bearing| -> Option<(Matrix2<f64>, Matrix2<f64>)> {
            let n = 2 + b.internal_dofs();
            let mut q = vec![0.0; n];
            b.guess_internal([0.0, 0.0], speed, &mut q[2..]);
            let mut eval = BearingEval::new(n);
            b.evaluate(&q, &vec![0.0; n], speed, &mut eval).ok()?;
            Some(condensed_coefficients(&eval, speed))
        };
        let nearly_unloaded = !point.is_unloaded() && point.load < NEARLY_UNLOADED * load_scale;
        let finite_kc = if point.is_unloaded() || nearly_unloaded {
            centred(&finite)
        } else {
            journal_equilibrium_direct(&finite, load, speed, scale)
                .ok()
                .map(|eq| condensed_coefficients(&eq.eval, speed))
        };
        let matrix = |m: [[f64; 2]; 2]| Matrix2::new(m[0][0], m[0][1], m[1][0], m[1][1]);
        let short_kc = if nearly_unloaded {
            centred(kind.build().as_ref())
        } else {
            Some((matrix(point.stiffness), matrix(point.damping)))
        };
        let ratios = finite_kc
            .zip(short_kc)
            .map(|((k, c), (ks, cs))| (ks.norm() / k.norm(), cs.norm() / c.norm()));
        out.push(ShortFilmWarning {
            bearing: point.name.clone(),
            pads: matches!(kind, BearingKind::TiltingPad(_)),
            slenderness: ratio,
            speed,
            load: point.load,
            stiffness_ratio: ratios.map(|r| r.0),
            damping_ratio: ratios.map(|r| r.1),
        });
    }
    Ok(out)
}
