//! What the model descriptions of both FMI versions declare alike: the model
//! identifier, the log categories, the units, the number format, and the
//! token (FMI 2 `guid`, FMI 3 `instantiationToken`) hashed from a
//! description text.

use quick_xml::events::{BytesEnd, BytesStart, Event};

use super::variables::Variable;

/// `modelIdentifier`: the shared library name inside the FMU.
pub const MODEL_IDENTIFIER: &str = "RotorBearing";
/// Log categories the FMU may use (declared in the model description).
pub const LOG_CATEGORIES: [(&str, &str); 5] = [
    ("logStatusWarning", "Warnings"),
    (
        "logStatusDiscard",
        "Discarded steps (solver failures the master may retry)",
    ),
    (
        "logStatusError",
        "Errors: wrong calls, bad values, broken models",
    ),
    ("logStatusFatal", "Fatal errors"),
    ("logAll", "Everything, including step statistics"),
];
/// The token written while the description is hashed (FMI 2 `guid`, FMI 3
/// `instantiationToken`), replaced by the hash.
pub const GUID_PLACEHOLDER: &str = "{00000000-0000-0000-0000-000000000000}";

/// SI units used, with their base-unit exponents (kg, m, s, rad) and display units
/// `(name, factor)` so that `display = factor · value`.
/// A unit: name, exponents of (kg, m, s, rad), display units.
pub type UnitSpec = (&'static str, [i32; 4], &'static [(&'static str, f64)]);

pub const UNITS: [UnitSpec; 9] = [
    ("s", [0, 0, 1, 0], &[]),
    ("1", [0, 0, 0, 0], &[]),
    ("rad", [0, 0, 0, 1], &[("deg", 57.295_779_513_082_32)]),
    ("rad/s", [0, 0, -1, 1], &[("rpm", 9.549_296_585_513_72)]),
    ("m", [0, 1, 0, 0], &[("um", 1e6)]),
    ("N", [1, 1, -2, 0], &[]),
    ("N.m", [1, 2, -2, 0], &[]),
    ("Pa.s", [1, -1, -1, 0], &[]),
    ("kg.m", [1, 1, 0, 0], &[]),
];

/// Units declared only when a variable uses one (so that a model without
/// such variables keeps its description, and GUID, as it was).
pub const UNITS_WHEN_USED: [UnitSpec; 3] = [
    ("m/s", [0, 1, -1, 0], &[("mm/s", 1e3)]),
    ("W", [1, 2, -3, 0], &[("kW", 1e-3)]),
    ("Hz", [0, 0, -1, 0], &[]),
];

/// GUID of a description text (placeholder GUID inside): two FNV-1a 64-bit hashes.
pub fn guid_of(text: &str) -> String {
    let fnv = |seed: u64| {
        text.bytes().fold(seed, |h, b| {
            (h ^ u64::from(b)).wrapping_mul(0x0000_0100_0000_01b3)
        })
    };
    let (a, b) = (fnv(0xcbf2_9ce4_8422_2325), fnv(0x6c62_272e_07bb_0142));
    format!(
        "{{{:08x}-{:04x}-{:04x}-{:04x}-{:012x}}}",
        a >> 32,
        (a >> 16) & 0xffff,
        a & 0xffff,
        b >> 48,
        b & 0xffff_ffff_ffff
    )
}

/// A real as FMI writes it.
pub fn fmt_real(v: f64) -> String {
    // Round-trip exact, as FMI requires for start values.
    format!("{v:?}")
}

/// The `<UnitDefinitions>` of `vars` (the same elements in FMI 2.0 and 3.0).
pub fn unit_events(vars: &[Variable]) -> Vec<Event<'static>> {
    let mut out = vec![Event::Start(BytesStart::new("UnitDefinitions"))];
    let used = UNITS_WHEN_USED
        .into_iter()
        .filter(|(name, ..)| vars.iter().any(|v| v.unit == Some(*name)));
    for (name, exp, displays) in UNITS.into_iter().chain(used) {
        let mut unit = BytesStart::new("Unit");
        unit.push_attribute(("name", name));
        out.push(Event::Start(unit));
        let mut base = BytesStart::new("BaseUnit");
        for (key, e) in ["kg", "m", "s", "rad"].iter().zip(exp) {
            if e != 0 {
                base.push_attribute((*key, e.to_string().as_str()));
            }
        }
        out.push(Event::Empty(base));
        for (d, factor) in displays {
            let mut du = BytesStart::new("DisplayUnit");
            du.push_attribute(("name", *d));
            du.push_attribute(("factor", fmt_real(*factor).as_str()));
            out.push(Event::Empty(du));
        }
        out.push(Event::End(BytesEnd::new("Unit")));
    }
    out.push(Event::End(BytesEnd::new("UnitDefinitions")));
    out
}

/// The `<LogCategories>` (the same elements in FMI 2.0 and 3.0).
pub fn log_category_events() -> Vec<Event<'static>> {
    let mut out = vec![Event::Start(BytesStart::new("LogCategories"))];
    for (name, text) in LOG_CATEGORIES {
        let mut c = BytesStart::new("Category");
        c.push_attribute(("name", name));
        c.push_attribute(("description", text));
        out.push(Event::Empty(c));
    }
    out.push(Event::End(BytesEnd::new("LogCategories")));
    out
}

/// The model's description text (`description` attribute).
pub fn model_text(model: &crate::model::RotorModel) -> String {
    if model.description.is_empty() {
        format!("Rotor-bearing dynamics of {}", model.name)
    } else {
        model.description.clone()
    }
}
