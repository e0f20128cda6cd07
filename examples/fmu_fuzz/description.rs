//! The importer's view of an FMU's variables: its own `modelDescription.xml`
//! read with quick-xml (GUID, and each scalar variable's reference,
//! causality, variability, type, start and declared range).

use std::path::Path;

use quick_xml::Reader;
use quick_xml::events::Event;

/// A scalar variable as the model description declares it.
#[derive(Debug, Clone)]
pub struct Var {
    pub name: String,
    pub vr: u32,
    pub causality: String,
    pub variability: String,
    pub kind: &'static str,
    pub start: Option<f64>,
    /// The declared range of a Real (`min`, `max`).
    pub min: Option<f64>,
    pub max: Option<f64>,
}

fn attr(e: &quick_xml::events::BytesStart, key: &[u8]) -> Option<String> {
    e.attributes()
        .flatten()
        .find(|a| a.key.as_ref() == key)
        .map(|a| String::from_utf8_lossy(&a.value).into_owned())
}

/// GUID and scalar variables of a model description.
pub fn read_description(path: &Path) -> Result<(String, Vec<Var>), String> {
    let text = std::fs::read_to_string(path).map_err(|e| format!("{}: {e}", path.display()))?;
    let mut reader = Reader::from_str(&text);
    let mut guid = String::new();
    let mut vars = Vec::new();
    let mut current: Option<Var> = None;
    loop {
        match reader.read_event().map_err(|e| e.to_string())? {
            Event::Start(e) | Event::Empty(e) => match e.name().as_ref() {
                b"fmiModelDescription" => guid = attr(&e, b"guid").unwrap_or_default(),
                b"ScalarVariable" => {
                    current = Some(Var {
                        name: attr(&e, b"name").unwrap_or_default(),
                        vr: attr(&e, b"valueReference")
                            .and_then(|v| v.parse().ok())
                            .ok_or("valueReference")?,
                        causality: attr(&e, b"causality").unwrap_or("local".into()),
                        variability: attr(&e, b"variability").unwrap_or("continuous".into()),
                        kind: "Real",
                        start: None,
                        min: None,
                        max: None,
                    })
                }
                tag @ (b"Real" | b"Integer" | b"Boolean") => {
                    if let Some(v) = current.as_mut() {
                        v.kind = match tag {
                            b"Real" => "Real",
                            b"Integer" => "Integer",
                            _ => "Boolean",
                        };
                        v.min = attr(&e, b"min").and_then(|s| s.parse().ok());
                        v.max = attr(&e, b"max").and_then(|s| s.parse().ok());
                        v.start = attr(&e, b"start").and_then(|s| match s.as_str() {
                            "true" => Some(1.0),
                            "false" => Some(0.0),
                            other => other.parse().ok(),
                        });
                    }
                }
                _ => {}
            },
            Event::End(e) if e.name().as_ref() == b"ScalarVariable" => {
                vars.extend(current.take());
            }
            Event::Eof => break,
            _ => {}
        }
    }
    Ok((guid, vars))
}
