//! `modelDescription.xml` generated from the variable table (quick-xml writer).

use quick_xml::Writer;
use quick_xml::events::{BytesDecl, BytesEnd, BytesStart, Event};

use crate::fmu::description::{
    GUID_PLACEHOLDER, fmt_real, guid_of, log_category_events, model_text, unit_events,
};
pub use crate::fmu::description::{LOG_CATEGORIES, MODEL_IDENTIFIER};
use crate::fmu::variables::{Binding, Causality, Kind, Variability, Variable, variables};
use crate::model::RotorModel;

/// The model description of `model` and its GUID.
pub fn model_description(model: &RotorModel) -> (String, String) {
    let vars = variables(model);
    let text = render(model, &vars, GUID_PLACEHOLDER);
    let guid = guid_of(&text);
    (text.replace(GUID_PLACEHOLDER, &guid), guid)
}

fn render(model: &RotorModel, vars: &[Variable], guid: &str) -> String {
    let mut w = Writer::new_with_indent(Vec::new(), b' ', 2);
    let mut emit = |e: Event| {
        // Writing into a Vec cannot fail.
        let _ = w.write_event(e);
    };
    emit(Event::Decl(BytesDecl::new("1.0", Some("UTF-8"), None)));
    let description = model_text(model);
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

    for e in unit_events(vars).into_iter().chain(log_category_events()) {
        emit(e);
    }

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
        .position(|v| v.binding == Binding::Speed)
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
