//! `modelDescription.xml` generated from the variable table (quick-xml writer).

use quick_xml::Writer;
use quick_xml::events::{BytesDecl, BytesEnd, BytesStart, Event};

use super::variables::{Causality, Kind, Variability, Variable, variables};
use crate::model::RotorModel;

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
const GUID_PLACEHOLDER: &str = "{00000000-0000-0000-0000-000000000000}";

/// SI units used, with their base-unit exponents (kg, m, s, rad) and display units
/// `(name, factor)` so that `display = factor · value`.
/// A unit: name, exponents of (kg, m, s, rad), display units.
type UnitSpec = (&'static str, [i32; 4], &'static [(&'static str, f64)]);

const UNITS: [UnitSpec; 9] = [
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
const UNITS_WHEN_USED: [UnitSpec; 2] = [
    ("m/s", [0, 1, -1, 0], &[("mm/s", 1e3)]),
    ("W", [1, 2, -3, 0], &[("kW", 1e-3)]),
];

/// The model description of `model` and its GUID.
pub fn model_description(model: &RotorModel) -> (String, String) {
    let vars = variables(model);
    let text = render(model, &vars, GUID_PLACEHOLDER);
    let guid = guid_of(&text);
    (text.replace(GUID_PLACEHOLDER, &guid), guid)
}

/// GUID of a description text (placeholder GUID inside): two FNV-1a 64-bit hashes.
fn guid_of(text: &str) -> String {
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

fn fmt_real(v: f64) -> String {
    // Round-trip exact, as FMI requires for start values.
    format!("{v:?}")
}

fn render(model: &RotorModel, vars: &[Variable], guid: &str) -> String {
    let mut w = Writer::new_with_indent(Vec::new(), b' ', 2);
    let mut emit = |e: Event| {
        // Writing into a Vec cannot fail.
        let _ = w.write_event(e);
    };
    emit(Event::Decl(BytesDecl::new("1.0", Some("UTF-8"), None)));
    let description = if model.description.is_empty() {
        format!("Rotor-bearing dynamics of {}", model.name)
    } else {
        model.description.clone()
    };
    let mut root = BytesStart::new("fmiModelDescription");
    root.push_attribute(("fmiVersion", "2.0"));
    root.push_attribute(("modelName", model.name.as_str()));
    root.push_attribute(("guid", guid));
    root.push_attribute(("description", description.as_str()));
    root.push_attribute((
        "generationTool",
        concat!("rotor_bearing ", env!("CARGO_PKG_VERSION")),
    ));
    root.push_attribute(("variableNamingConvention", "structured"));
    root.push_attribute(("numberOfEventIndicators", "0"));
    emit(Event::Start(root));

    let mut cs = BytesStart::new("CoSimulation");
    for (k, v) in [
        ("modelIdentifier", MODEL_IDENTIFIER),
        ("needsExecutionTool", "false"),
        ("canHandleVariableCommunicationStepSize", "true"),
        ("canInterpolateInputs", "true"),
        ("maxOutputDerivativeOrder", "0"),
        ("canRunAsynchronuously", "false"),
        ("canBeInstantiatedOnlyOncePerProcess", "false"),
        ("canNotUseMemoryManagementFunctions", "true"),
        ("canGetAndSetFMUstate", "true"),
        ("canSerializeFMUstate", "true"),
        ("providesDirectionalDerivative", "false"),
    ] {
        cs.push_attribute((k, v));
    }
    emit(Event::Empty(cs));

    emit(Event::Start(BytesStart::new("UnitDefinitions")));
    let used = UNITS_WHEN_USED
        .into_iter()
        .filter(|(name, ..)| vars.iter().any(|v| v.unit == Some(*name)));
    for (name, exp, displays) in UNITS.into_iter().chain(used) {
        let mut unit = BytesStart::new("Unit");
        unit.push_attribute(("name", name));
        emit(Event::Start(unit));
        let mut base = BytesStart::new("BaseUnit");
        for (key, e) in ["kg", "m", "s", "rad"].iter().zip(exp) {
            if e != 0 {
                base.push_attribute((*key, e.to_string().as_str()));
            }
        }
        emit(Event::Empty(base));
        for (d, factor) in displays {
            let mut du = BytesStart::new("DisplayUnit");
            du.push_attribute(("name", *d));
            du.push_attribute(("factor", fmt_real(*factor).as_str()));
            emit(Event::Empty(du));
        }
        emit(Event::End(BytesEnd::new("Unit")));
    }
    emit(Event::End(BytesEnd::new("UnitDefinitions")));

    emit(Event::Start(BytesStart::new("LogCategories")));
    for (name, text) in LOG_CATEGORIES {
        let mut c = BytesStart::new("Category");
        c.push_attribute(("name", name));
        c.push_attribute(("description", text));
        emit(Event::Empty(c));
    }
    emit(Event::End(BytesEnd::new("LogCategories")));

    let mut de = BytesStart::new("DefaultExperiment");
    de.push_attribute(("startTime", "0.0"));
    de.push_attribute(("stopTime", "10.0"));
    de.push_attribute(("stepSize", "0.01"));
    emit(Event::Empty(de));

    emit(Event::Start(BytesStart::new("ModelVariables")));
    for v in vars {
        let mut sv = BytesStart::new("ScalarVariable");
        sv.push_attribute(("name", v.name.as_str()));
        sv.push_attribute(("valueReference", v.value_reference.to_string().as_str()));
        sv.push_attribute(("description", v.description.as_str()));
        sv.push_attribute((
            "causality",
            match v.causality {
                Causality::Parameter => "parameter",
                Causality::Input => "input",
                Causality::Output => "output",
            },
        ));
        sv.push_attribute((
            "variability",
            match v.variability {
                Variability::Fixed => "fixed",
                Variability::Tunable => "tunable",
                Variability::Continuous => "continuous",
            },
        ));
        match v.causality {
            Causality::Parameter => sv.push_attribute(("initial", "exact")),
            Causality::Output => sv.push_attribute(("initial", "calculated")),
            Causality::Input => {}
        }
        emit(Event::Start(sv));
        let (tag, start) = match v.kind {
            Kind::Real => ("Real", v.start.map(fmt_real)),
            Kind::Integer => ("Integer", v.start.map(|s| format!("{}", s as i64))),
            Kind::Boolean => (
                "Boolean",
                v.start
                    .map(|s| (if s != 0.0 { "true" } else { "false" }).to_string()),
            ),
        };
        let mut t = BytesStart::new(tag);
        if let Some(u) = v.unit {
            t.push_attribute(("unit", u));
        }
        if let Some(d) = v.display_unit {
            t.push_attribute(("displayUnit", d));
        }
        let bound = |x: f64| match v.kind {
            Kind::Integer => format!("{}", x as i64),
            _ => fmt_real(x),
        };
        let (min, max) = (v.min.map(bound), v.max.map(bound));
        if let Some(m) = &min {
            t.push_attribute(("min", m.as_str()));
        }
        if let Some(m) = &max {
            t.push_attribute(("max", m.as_str()));
        }
        if let Some(s) = &start {
            t.push_attribute(("start", s.as_str()));
        }
        emit(Event::Empty(t));
        emit(Event::End(BytesEnd::new("ScalarVariable")));
    }
    emit(Event::End(BytesEnd::new("ModelVariables")));

    let speed_index = vars
        .iter()
        .position(|v| v.binding == super::variables::Binding::Speed)
        .map_or(0, |i| i + 1);
    emit(Event::Start(BytesStart::new("ModelStructure")));
    for section in ["Outputs", "InitialUnknowns"] {
        emit(Event::Start(BytesStart::new(section)));
        for (i, v) in vars.iter().enumerate() {
            if v.causality != Causality::Output {
                continue;
            }
            let mut u = BytesStart::new("Unknown");
            u.push_attribute(("index", (i + 1).to_string().as_str()));
            if section == "Outputs" {
                // Outputs follow the state; film forces and friction also the speed directly.
                let deps = if v.feedthrough_speed {
                    speed_index.to_string()
                } else {
                    String::new()
                };
                u.push_attribute(("dependencies", deps.as_str()));
                if v.feedthrough_speed {
                    u.push_attribute(("dependenciesKind", "dependent"));
                }
            }
            emit(Event::Empty(u));
        }
        emit(Event::End(BytesEnd::new(section)));
    }
    emit(Event::End(BytesEnd::new("ModelStructure")));
    emit(Event::End(BytesEnd::new("fmiModelDescription")));
    let mut text = String::from_utf8(w.into_inner()).unwrap_or_default();
    text.push('\n');
    text
}
