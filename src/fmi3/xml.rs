//! The FMI 3.0 `modelDescription.xml`, generated from the same variable table
//! as the FMI 2.0 one (quick-xml writer): every table entry under its own
//! value reference, as `<Float64>`, `<Int32>` or `<Boolean>`, plus the
//! independent variable `time` FMI 3.0 requires (§2.4.7.4), under
//! [`TIME_VALUE_REFERENCE`]. Causality, variability and `initial` are FMI
//! 2.0's (they mean the same in FMI 3.0); `<ModelStructure>` names unknowns by
//! value reference (`<Output>`, `<InitialUnknown>`). Every output (and output
//! array) has `intermediateUpdate = "true"`: the importer may read it in
//! Intermediate Update Mode (`providesIntermediateUpdate`).

use quick_xml::Writer;
use quick_xml::events::{BytesDecl, BytesEnd, BytesStart, Event};

use super::arrays::{Array, arrays};
use crate::fmu::description::{
    GUID_PLACEHOLDER, MODEL_IDENTIFIER, fmt_real, guid_of, log_category_events, model_text,
    unit_events,
};
use crate::fmu::variables::{Binding, Causality, Kind, Variability, Variable, variables};
use crate::model::RotorModel;

/// The value reference of the independent variable `time` (s), outside the
/// table's range so that appending variables never moves it.
pub const TIME_VALUE_REFERENCE: u32 = 999_999_999;

/// The FMI 3.0 model description of `model` and its instantiation token.
pub fn model_description(model: &RotorModel) -> (String, String) {
    let vars = variables(model);
    let text = render(model, &vars, GUID_PLACEHOLDER);
    let token = guid_of(&text);
    (text.replace(GUID_PLACEHOLDER, &token), token)
}

/// The FMI 3.0 element name of a table type.
pub fn type_name(kind: Kind) -> &'static str {
    match kind {
        Kind::Real => "Float64",
        Kind::Integer => "Int32",
        Kind::Boolean => "Boolean",
    }
}

/// The `<CoSimulation>` capabilities.
const CO_SIMULATION: [(&str, &str); 16] = [
    ("modelIdentifier", MODEL_IDENTIFIER),
    ("needsExecutionTool", "false"),
    ("canBeInstantiatedOnlyOncePerProcess", "false"),
    ("canGetAndSetFMUState", "true"),
    ("canSerializeFMUState", "true"),
    ("providesDirectionalDerivatives", "false"),
    ("providesAdjointDerivatives", "false"),
    ("providesPerElementDependencies", "false"),
    ("canHandleVariableCommunicationStepSize", "true"),
    ("maxOutputDerivativeOrder", "0"),
    ("recommendedIntermediateInputSmoothness", "0"),
    ("providesIntermediateUpdate", "true"),
    ("mightReturnEarlyFromDoStep", "true"),
    ("canReturnEarlyAfterIntermediateUpdate", "true"),
    ("hasEventMode", "false"),
    ("providesEvaluateDiscreteStates", "false"),
];

fn render(model: &RotorModel, vars: &[Variable], token: &str) -> String {
    let mut w = Writer::new_with_indent(Vec::new(), b' ', 2);
    let mut emit = |e: Event| {
        // Writing into a Vec cannot fail.
        let _ = w.write_event(e);
    };
    emit(Event::Decl(BytesDecl::new("1.0", Some("UTF-8"), None)));
    let description = model_text(model);
    let mut root = BytesStart::new("fmiModelDescription");
    root.push_attribute(("fmiVersion", "3.0"));
    root.push_attribute(("modelName", model.name.as_str()));
    root.push_attribute(("instantiationToken", token));
    root.push_attribute(("description", description.as_str()));
    root.push_attribute((
        "generationTool",
        concat!("rotor_bearing ", env!("CARGO_PKG_VERSION")),
    ));
    root.push_attribute(("variableNamingConvention", "structured"));
    emit(Event::Start(root));

    let mut cs = BytesStart::new("CoSimulation");
    for kv in CO_SIMULATION {
        cs.push_attribute(kv);
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
    let mut time = BytesStart::new("Float64");
    time.push_attribute(("name", "time"));
    time.push_attribute(("valueReference", TIME_VALUE_REFERENCE.to_string().as_str()));
    time.push_attribute(("description", "Simulation time"));
    time.push_attribute(("causality", "independent"));
    time.push_attribute(("variability", "continuous"));
    time.push_attribute(("unit", "s"));
    emit(Event::Empty(time));
    for v in vars {
        emit(Event::Empty(variable(v)));
    }
    let arrays = arrays(vars);
    for a in &arrays {
        emit(Event::Start(array(a, vars)));
        let mut dim = BytesStart::new("Dimension");
        dim.push_attribute(("start", a.elements.len().to_string().as_str()));
        emit(Event::Empty(dim));
        emit(Event::End(BytesEnd::new("Float64")));
    }
    emit(Event::End(BytesEnd::new("ModelVariables")));

    let speed = vars
        .iter()
        .find(|v| v.binding == Binding::Speed)
        .map(|v| v.value_reference.to_string());
    // Each output, then each output array (fed through from the speed when
    // any element is).
    let outputs: Vec<(u32, bool)> = vars
        .iter()
        .filter(|v| v.causality == Causality::Output)
        .map(|v| (v.value_reference, v.feedthrough_speed))
        .chain(
            arrays
                .iter()
                .filter(|a| a.causality == Causality::Output)
                .map(|a| {
                    let through = a
                        .elements
                        .iter()
                        .any(|&e| vars[e as usize].feedthrough_speed);
                    (a.value_reference, through)
                }),
        )
        .collect();
    emit(Event::Start(BytesStart::new("ModelStructure")));
    for section in ["Output", "InitialUnknown"] {
        for &(vr, feedthrough) in &outputs {
            let mut u = BytesStart::new(section);
            u.push_attribute(("valueReference", vr.to_string().as_str()));
            if section == "Output" {
                // Outputs follow the state; film forces and friction also the speed directly.
                match (&speed, feedthrough) {
                    (Some(vr), true) => {
                        u.push_attribute(("dependencies", vr.as_str()));
                        u.push_attribute(("dependenciesKind", "dependent"));
                    }
                    _ => u.push_attribute(("dependencies", "")),
                }
            }
            emit(Event::Empty(u));
        }
    }
    emit(Event::End(BytesEnd::new("ModelStructure")));
    emit(Event::End(BytesEnd::new("fmiModelDescription")));
    let mut text = String::from_utf8(w.into_inner()).unwrap_or_default();
    text.push('\n');
    text
}

/// The `<Float64>` start element of an array (its `<Dimension>` follows).
fn array(a: &Array, vars: &[Variable]) -> BytesStart<'static> {
    let mut t = BytesStart::new("Float64");
    t.push_attribute(("name", a.name.as_str()));
    t.push_attribute(("valueReference", a.value_reference.to_string().as_str()));
    let names: Vec<&str> = a
        .elements
        .iter()
        .map(|&e| vars[e as usize].name.as_str())
        .collect();
    let description = format!("Array of {}", names.join(", "));
    t.push_attribute(("description", description.as_str()));
    let inputs = a.causality == Causality::Input;
    t.push_attribute(("causality", if inputs { "input" } else { "output" }));
    t.push_attribute((
        "variability",
        match a.variability {
            Variability::Fixed => "fixed",
            Variability::Tunable => "tunable",
            Variability::Continuous => "continuous",
        },
    ));
    if !inputs {
        t.push_attribute(("initial", "calculated"));
        // Readable in Intermediate Update Mode (outputs only: inputs are held
        // over a step).
        t.push_attribute(("intermediateUpdate", "true"));
    }
    if let Some(u) = a.unit {
        t.push_attribute(("unit", u));
    }
    if let Some(d) = a.display_unit {
        t.push_attribute(("displayUnit", d));
    }
    if inputs {
        let starts: Vec<String> = a
            .elements
            .iter()
            .map(|&e| fmt_real(vars[e as usize].start.unwrap_or(0.0)))
            .collect();
        t.push_attribute(("start", starts.join(" ").as_str()));
    }
    t
}

/// The element of one table variable (`<Float64>`, `<Int32>`, `<Boolean>`).
fn variable(v: &Variable) -> BytesStart<'static> {
    let mut t = BytesStart::new(type_name(v.kind));
    t.push_attribute(("name", v.name.as_str()));
    t.push_attribute(("valueReference", v.value_reference.to_string().as_str()));
    // The descriptions speak of the FMI 2 step call; FMI 3's is fmi3DoStep.
    let description = v.description.replace("fmi2DoStep", "fmi3DoStep");
    t.push_attribute(("description", description.as_str()));
    t.push_attribute((
        "causality",
        match v.causality {
            Causality::Parameter => "parameter",
            Causality::Input => "input",
            Causality::Output => "output",
        },
    ));
    t.push_attribute((
        "variability",
        match v.variability {
            Variability::Fixed => "fixed",
            Variability::Tunable => "tunable",
            Variability::Continuous => "continuous",
        },
    ));
    match v.causality {
        Causality::Parameter => t.push_attribute(("initial", "exact")),
        Causality::Output => {
            t.push_attribute(("initial", "calculated"));
            // Readable in Intermediate Update Mode (outputs only: inputs are
            // held over a step).
            t.push_attribute(("intermediateUpdate", "true"));
        }
        Causality::Input => {}
    }
    // Units belong to floats in FMI 3.0 (`<Int32>` and `<Boolean>` have none).
    if v.kind == Kind::Real {
        if let Some(u) = v.unit {
            t.push_attribute(("unit", u));
        }
        if let Some(d) = v.display_unit {
            t.push_attribute(("displayUnit", d));
        }
    }
    let number = |x: f64| match v.kind {
        Kind::Integer => format!("{}", x as i64),
        _ => fmt_real(x),
    };
    if v.kind != Kind::Boolean {
        if let Some(m) = v.min {
            t.push_attribute(("min", number(m).as_str()));
        }
        if let Some(m) = v.max {
            t.push_attribute(("max", number(m).as_str()));
        }
    }
    if let Some(s) = v.start {
        let start = match v.kind {
            Kind::Boolean => (if s != 0.0 { "true" } else { "false" }).to_string(),
            _ => number(s),
        };
        t.push_attribute(("start", start.as_str()));
    }
    t
}
