//! The tolerance cases of an API machine (`[cases]`): the bearings' oil
//! supply temperature (through the oil's ASTM D341 viscosity law,
//! [`crate::bearing::oil`]), their clearance and the tilting pads' preload,
//! each at the ends of its stated range. [`ToleranceCases::cases`] lists the
//! nominal model and every combination of the ends (2^k corners of the k
//! ranges given, 8 with all three); [`RotorModel::with_case`] is the model of
//! one case: the nominal one with every fluid-film bearing's viscosity,
//! clearance and preload replaced.

use serde::Deserialize;

use super::context::Ctx;
use super::error::FieldPath;
use super::{ModelError, RotorModel};
use crate::bearing::BearingKind;
use crate::bearing::contact::ContactLaw;
use crate::bearing::finite_bearing::FilmSupport;
use crate::bearing::oil::{CELSIUS_ZERO, DEFAULT_DENSITY_15, ISO_VG, Oil};
use crate::bearing::plain::PlainBearing;
use crate::bearing::tilting_pad::{Pad, TiltingPadBearing};
use crate::units::Short;

/// The oil supply temperatures `[cases]` accepts (°C): a mineral oil's
/// liquid range, where its viscosity and density laws hold.
pub const OIL_TEMPERATURE_C: [f64; 2] = [-50.0, 200.0];

/// `[cases]` as written.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CasesEntry {
    /// ISO VG grade of the oil (22, 32, 46 or 68: the constants of
    /// [`crate::bearing::oil::ISO_VG`]), or give `nu_40` and `nu_100`.
    pub iso_vg: Option<i64>,
    /// The oil's kinematic viscosity at 40 °C (mm²/s), with `nu_100`.
    pub nu_40: Option<f64>,
    /// The oil's kinematic viscosity at 100 °C (mm²/s), with `nu_40`.
    pub nu_100: Option<f64>,
    /// The oil's density at 15 °C (kg/m³); default 870.
    pub density_15: Option<f64>,
    /// Oil supply temperature `[min, max]` (°C): each film's viscosity from the law.
    pub oil_temperature_c: Option<Vec<f64>>,
    /// Factor on every film bearing's clearance `[min, max]` (–), e.g. `[0.9, 1.1]`.
    pub clearance_factor: Option<Vec<f64>>,
    /// Tilting pads' preload `[min, max]` (–), each in `[0, 1)`.
    pub preload: Option<Vec<f64>>,
}

/// The validated `[cases]`: the oil and the ranges given.
#[derive(Debug, Clone, PartialEq)]
pub struct ToleranceCases {
    /// The oil, when a temperature range is given.
    pub oil: Option<Oil>,
    /// Oil supply temperature `[min, max]` (K).
    pub temperature: Option<[f64; 2]>,
    /// Factor on the film bearings' clearances `[min, max]`.
    pub clearance_factor: Option<[f64; 2]>,
    /// Tilting pads' preload `[min, max]`.
    pub preload: Option<[f64; 2]>,
}

/// One case: what replaces the nominal bearings' data (`None`: nominal).
#[derive(Debug, Clone, PartialEq)]
pub struct CaseSettings {
    /// `nominal`, or the ends taken (`T min, C max, m min`).
    pub label: String,
    /// Oil supply temperature (K) and the dynamic viscosity (Pa·s) the law gives there.
    pub temperature: Option<(f64, f64)>,
    /// Factor on every film bearing's clearance.
    pub clearance_factor: Option<f64>,
    /// Every tilting pad's preload.
    pub preload: Option<f64>,
}

impl ToleranceCases {
    /// The nominal case first, then every combination of the ranges' ends
    /// (temperature outermost, then clearance, then preload; min before max).
    pub fn cases(&self) -> Vec<CaseSettings> {
        let mut out = vec![CaseSettings {
            label: "nominal".into(),
            temperature: None,
            clearance_factor: None,
            preload: None,
        }];
        let ends = |r: Option<[f64; 2]>| -> Vec<Option<(f64, &'static str)>> {
            match r {
                Some([lo, hi]) => vec![Some((lo, "min")), Some((hi, "max"))],
                None => vec![None],
            }
        };
        for t in ends(self.temperature) {
            for c in ends(self.clearance_factor) {
                for m in ends(self.preload) {
                    let mut label = Vec::new();
                    let temperature = t.map(|(t, end)| {
                        label.push(format!("T {end}"));
                        let oil = self.oil.expect("a temperature range comes with its oil");
                        let mu = oil
                            .dynamic_viscosity(t)
                            .expect("temperatures are checked above absolute zero");
                        (t, mu)
                    });
                    let clearance_factor = c.map(|(c, end)| {
                        label.push(format!("C {end}"));
                        c
                    });
                    let preload = m.map(|(m, end)| {
                        label.push(format!("m {end}"));
                        m
                    });
                    out.push(CaseSettings {
                        label: label.join(", "),
                        temperature,
                        clearance_factor,
                        preload,
                    });
                }
            }
        }
        out
    }
}

impl CaseSettings {
    /// The case's values as text: `T = 35 °C (μ = 0.0273 Pa·s), C × 0.9, m = 0.2`.
    pub fn describe(&self) -> String {
        let mut parts = Vec::new();
        if let Some((t, mu)) = self.temperature {
            parts.push(format!(
                "T = {} °C (μ = {:.5} Pa·s)",
                Short(t - CELSIUS_ZERO),
                mu
            ));
        }
        if let Some(c) = self.clearance_factor {
            parts.push(format!("C × {}", Short(c)));
        }
        if let Some(m) = self.preload {
            parts.push(format!("m = {}", Short(m)));
        }
        if parts.is_empty() {
            "the model as written".into()
        } else {
            parts.join(", ")
        }
    }
}

/// A film's viscosity, clearance and stated contact law in the case (the
/// contact gap follows the clearance).
fn film_case(
    viscosity: &mut f64,
    clearance: &mut f64,
    contact: &mut Option<ContactLaw>,
    case: &CaseSettings,
) {
    if let Some((_, mu)) = case.temperature {
        *viscosity = mu;
    }
    if let Some(f) = case.clearance_factor {
        *clearance *= f;
        if let Some(law) = contact {
            regap(law, *clearance);
        }
    }
}

/// A plain film in the case.
fn plain_case(b: &mut PlainBearing, case: &CaseSettings) {
    film_case(&mut b.viscosity, &mut b.clearance, &mut b.contact, case);
}

/// Tilting pads in the case, with its preload.
fn pads_case(b: &mut TiltingPadBearing, case: &CaseSettings) {
    film_case(&mut b.viscosity, &mut b.clearance, &mut b.contact, case);
    if let Some(m) = case.preload {
        for pad in &mut b.pads {
            *pad = Pad::new(pad.pivot(), pad.arc(), pad.offset(), m);
        }
    }
}

/// A stated contact law at a new clearance: the gap and the fade-in length
/// [`ContactLaw::steel`] scales with it.
fn regap(law: &mut ContactLaw, clearance: f64) {
    law.gap = clearance;
    law.smoothing = ContactLaw::SMOOTHING_PER_GAP * clearance;
}

impl RotorModel {
    /// The model of one tolerance case: every plain and tilting-pad bearing
    /// (short or finite film) with the case's viscosity and clearance, every
    /// tilting pad with its preload; linear and table bearings, seals, rubs
    /// and pulls as written. The nominal case is the model itself.
    pub fn with_case(&self, case: &CaseSettings) -> RotorModel {
        let mut model = self.clone();
        for b in &mut model.bearings {
            match &mut b.kind {
                BearingKind::Plain(p) => plain_case(p, case),
                BearingKind::TiltingPad(t) => pads_case(t, case),
                BearingKind::FiniteFilm(f) => match &mut f.support {
                    FilmSupport::Plain(p) => plain_case(p, case),
                    FilmSupport::TiltingPad(t) => pads_case(t, case),
                },
                _ => {}
            }
        }
        model
    }
}

/// `[a, b]` of a range key: two finite numbers, `a ≤ b`.
fn range(ctx: &Ctx, path: FieldPath, v: &[f64]) -> Result<[f64; 2], ModelError> {
    let shown = format!("{v:?}");
    if v.len() != 2 {
        return Err(ctx.err(path, shown, "must be [min, max]"));
    }
    let a = ctx.finite(path.index(0), v[0])?;
    let b = ctx.finite(path.index(1), v[1])?;
    if a > b {
        return Err(ctx.err(path, shown, "must be [min, max] with min ≤ max"));
    }
    Ok([a, b])
}

/// Check `[cases]` against the model's bearings.
pub(super) fn validate(
    ctx: &Ctx,
    root: &FieldPath,
    raw: Option<CasesEntry>,
    bearings: &[super::PlacedBearing],
) -> Result<Option<ToleranceCases>, ModelError> {
    let Some(raw) = raw else {
        return Ok(None);
    };
    let p = root.key("cases");
    let oil = match (raw.iso_vg, raw.nu_40, raw.nu_100) {
        (None, None, None) => None,
        (Some(g), None, None) => {
            let grades: Vec<String> = ISO_VG.iter().map(|(g, _, _)| g.to_string()).collect();
            let oil = u32::try_from(g).ok().and_then(Oil::iso_vg).ok_or_else(|| {
                ctx.err(
                    p.key("iso_vg"),
                    g,
                    &format!(
                        "must be an ISO VG grade with stated constants: {} (or give nu_40 and nu_100)",
                        grades.join(", ")
                    ),
                )
            })?;
            Some(oil)
        }
        (None, Some(n40), Some(n100)) => Some(
            Oil::new(n40, n100, DEFAULT_DENSITY_15)
                .map_err(|e| ctx.err(p.key("nu_100"), Short(n100), &e.to_string()))?,
        ),
        (Some(g), _, _) => {
            return Err(ctx.err(
                p.key("iso_vg"),
                g,
                "give iso_vg or nu_40 and nu_100, not both",
            ));
        }
        (None, n40, _) => {
            let (key, shown) = match n40 {
                Some(v) => ("nu_40", Short(v).to_string()),
                None => ("nu_100", "given alone".to_string()),
            };
            return Err(ctx.err(
                p.key(key),
                shown,
                "give both nu_40 and nu_100 (mm²/s), the viscosities at 40 and 100 °C",
            ));
        }
    };
    let oil = match (oil, raw.density_15) {
        (Some(o), Some(rho)) => Some(
            Oil::new(o.nu_40, o.nu_100, rho)
                .map_err(|e| ctx.err(p.key("density_15"), Short(rho), &e.to_string()))?,
        ),
        (None, Some(rho)) => {
            return Err(ctx.err(
                p.key("density_15"),
                Short(rho),
                "is the oil's density: give it with iso_vg or nu_40 and nu_100",
            ));
        }
        (o, None) => o,
    };
    let temperature = match &raw.oil_temperature_c {
        None => None,
        Some(v) => {
            let path = p.key("oil_temperature_c");
            let [lo, hi] = range(ctx, path.clone(), v)?;
            for (i, c) in [lo, hi].into_iter().enumerate() {
                let kelvin = c + CELSIUS_ZERO;
                if kelvin <= 0.0 {
                    return Err(ctx.err(
                        path.index(i),
                        Short(c),
                        &format!(
                            "is {} K, below absolute zero: give the oil temperature in °C",
                            Short(kelvin)
                        ),
                    ));
                }
                if !(OIL_TEMPERATURE_C[0]..=OIL_TEMPERATURE_C[1]).contains(&c) {
                    return Err(ctx.err(
                        path.index(i),
                        Short(c),
                        &format!(
                            "must lie in [{}, {}] °C, where a mineral oil is a liquid the ASTM D341 law describes",
                            OIL_TEMPERATURE_C[0], OIL_TEMPERATURE_C[1]
                        ),
                    ));
                }
            }
            if oil.is_none() {
                return Err(ctx.err(
                    path,
                    format!("{v:?}"),
                    "needs the oil: give iso_vg or nu_40 and nu_100",
                ));
            }
            Some([lo + CELSIUS_ZERO, hi + CELSIUS_ZERO])
        }
    };
    let clearance_factor = match &raw.clearance_factor {
        None => None,
        Some(v) => {
            let path = p.key("clearance_factor");
            let r = range(ctx, path.clone(), v)?;
            for (i, f) in r.into_iter().enumerate() {
                if !(f > 0.0 && f <= 2.0) {
                    return Err(ctx.err(path.index(i), Short(f), "must lie in (0, 2]"));
                }
            }
            Some(r)
        }
    };
    let preload = match &raw.preload {
        None => None,
        Some(v) => {
            let path = p.key("preload");
            let r = range(ctx, path.clone(), v)?;
            for (i, m) in r.into_iter().enumerate() {
                if !(0.0..1.0).contains(&m) {
                    return Err(ctx.err(path.index(i), Short(m), "must lie in [0, 1)"));
                }
            }
            let pads = bearings.iter().any(|b| match &b.kind {
                BearingKind::TiltingPad(_) => true,
                BearingKind::FiniteFilm(f) => matches!(f.support, FilmSupport::TiltingPad(_)),
                _ => false,
            });
            if !pads {
                return Err(ctx.err(
                    path,
                    format!("{v:?}"),
                    "is the tilting pads' preload: the model has no tilting-pad bearing",
                ));
            }
            Some(r)
        }
    };
    if temperature.is_none() && clearance_factor.is_none() && preload.is_none() {
        return Err(ctx.err(
            p,
            "no range",
            "give at least one of oil_temperature_c, clearance_factor, preload",
        ));
    }
    Ok(Some(ToleranceCases {
        oil,
        temperature,
        clearance_factor,
        preload,
    }))
}
