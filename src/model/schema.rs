//! The keys the model-file parser accepts, discovered from the parser itself.
//!
//! Every struct of [`super::file`] denies unknown keys, and serde's refusal
//! of one names every key the struct accepts (`unknown field `x`, expected
//! one of `a`, `b`, …`). [`schema`] feeds [`super::file::ModelFile`] small
//! documents holding an unknown key at each place a key can go — the top
//! level, every section it names, every variant of a section chosen by a tag
//! (`[[bearings]] type`), every table nested in an entry — and reads the
//! accepted keys from the refusals. A field added to any of the serde
//! structs therefore appears here without anyone listing it, which is what
//! the model reference's completeness test (`tests/model_reference.rs`)
//! rests on.

use super::file::ModelFile;

/// A key no struct of the model file accepts, used to make the parser name
/// the keys it does accept.
const PROBE: &str = "__probe__";

/// Deepest nesting of tables the discovery follows (the file nests none
/// below a section's entries today; a deeper one would be found up to here).
const MAX_DEPTH: usize = 4;

/// One place of the model file keys go: the top level, a section, a
/// variant of a tagged section, or a table nested in an entry.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct SchemaSection {
    /// Keys from the top level down: empty for the top level, `["bearings"]`
    /// for `[[bearings]]`.
    pub path: Vec<String>,
    /// Whether the section is an array of tables (`[[name]]`) rather than one
    /// table (`[name]`).
    pub array: bool,
    /// For a section whose entries are chosen by a tag: the tag key and the
    /// value of this variant (`("type", "plain")`).
    pub variant: Option<(String, String)>,
    /// Every key the parser accepts here, in the order the parser lists them
    /// (the tag key included for a variant).
    pub keys: Vec<String>,
}

impl SchemaSection {
    /// How the section is written in a model file: `top level`,
    /// `[[bearings]] type = "plain"`, `[torsion]`.
    pub fn title(&self) -> String {
        if self.path.is_empty() {
            return "top level".to_string();
        }
        let name = self.path.join(".");
        let mut title = if self.array {
            format!("[[{name}]]")
        } else {
            format!("[{name}]")
        };
        if let Some((tag, value)) = &self.variant {
            title.push_str(&format!(" {tag} = \"{value}\""));
        }
        title
    }
}

/// What the parser said about a probe document.
#[derive(Debug, PartialEq)]
enum Answer {
    /// The probe key is unknown here; these are the keys that are known.
    Keys(Vec<String>),
    /// A tagged entry without its tag: `missing field `type``.
    MissingTag(String),
    /// An unknown tag value; these are the variants.
    Variants(Vec<String>),
    /// Anything else: the place holds a value, not a table.
    Other,
}

/// Parse `doc` as a model file and classify the refusal.
fn ask(doc: &str) -> Answer {
    let Err(e) = toml::from_str::<ModelFile>(doc) else {
        return Answer::Other;
    };
    let message = e.message();
    if let Some(rest) = message.strip_prefix(&format!("unknown field `{PROBE}`, expected ")) {
        return Answer::Keys(backticked(rest));
    }
    if let Some(rest) = message.strip_prefix(&format!("unknown variant `{PROBE}`, expected ")) {
        return Answer::Variants(backticked(rest));
    }
    if let Some(rest) = message.strip_prefix("missing field `") {
        if let Some(tag) = rest.strip_suffix('`') {
            return Answer::MissingTag(tag.to_string());
        }
    }
    Answer::Other
}

/// The names between backticks in serde's list of expected names
/// (`` `a` ``, `` `a` or `b` ``, `` one of `a`, `b`, `c` ``; `there are no
/// fields` gives none).
fn backticked(list: &str) -> Vec<String> {
    list.split('`')
        .skip(1)
        .step_by(2)
        .map(str::to_string)
        .collect()
}

/// Every place keys go in a model file and the keys the parser accepts
/// there, discovered by probing [`ModelFile`]'s deserializer (see the
/// module's documentation). The top level comes first, then each section in
/// the order the parser lists it, each variant of a tagged section apart.
pub fn schema() -> Vec<SchemaSection> {
    let Answer::Keys(top) = ask(&format!("{PROBE} = 1")) else {
        unreachable!("the model file's top level denies unknown keys");
    };
    let mut out = vec![SchemaSection {
        path: Vec::new(),
        array: false,
        variant: None,
        keys: top.clone(),
    }];
    for key in &top {
        let wrap = |value: &str| format!("{key} = {value}");
        discover(&wrap, vec![key.clone()], &mut out);
    }
    out
}

/// Probe the value at `path` (whose document `wrap` builds around an inline
/// value) as an array of tables and as a table; record what it holds and
/// recurse into its keys.
fn discover(wrap: &dyn Fn(&str) -> String, path: Vec<String>, out: &mut Vec<SchemaSection>) {
    if path.len() > MAX_DEPTH {
        return;
    }
    for array in [true, false] {
        // An entry holding `items` (and the probe), as written at `path`.
        let entry = |items: &str| {
            let table = format!("{{ {items} }}");
            wrap(&if array { format!("[{table}]") } else { table })
        };
        match ask(&entry(&format!("{PROBE} = 1"))) {
            Answer::Keys(keys) => {
                let sub = keys.clone();
                out.push(SchemaSection {
                    path: path.clone(),
                    array,
                    variant: None,
                    keys,
                });
                nested(&entry, "", &sub, &path, out);
                return;
            }
            Answer::MissingTag(tag) => {
                let Answer::Variants(variants) = ask(&entry(&format!("{tag} = \"{PROBE}\"")))
                else {
                    continue;
                };
                for v in variants {
                    let given = format!("{tag} = \"{v}\", ");
                    let Answer::Keys(mut keys) = ask(&entry(&format!("{given}{PROBE} = 1"))) else {
                        continue;
                    };
                    let sub = keys.clone();
                    keys.insert(0, tag.clone());
                    out.push(SchemaSection {
                        path: path.clone(),
                        array,
                        variant: Some((tag.clone(), v.clone())),
                        keys,
                    });
                    nested(&entry, &given, &sub, &path, out);
                }
                return;
            }
            Answer::Variants(_) | Answer::Other => {}
        }
    }
}

/// Recurse into each key of an entry (written by `entry`, after the items
/// `given`) that may hold a table.
fn nested(
    entry: &dyn Fn(&str) -> String,
    given: &str,
    keys: &[String],
    path: &[String],
    out: &mut Vec<SchemaSection>,
) {
    for key in keys {
        let wrap = |value: &str| entry(&format!("{given}{key} = {value}"));
        let mut sub = path.to_vec();
        sub.push(key.clone());
        discover(&wrap, sub, out);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn serde_lists_are_read_whole() {
        assert_eq!(backticked("`a`"), ["a"]);
        assert_eq!(backticked("`a` or `b`"), ["a", "b"]);
        assert_eq!(backticked("one of `a`, `b`, `c`"), ["a", "b", "c"]);
        assert!(backticked("there are no fields").is_empty());
    }

    #[test]
    fn the_probe_finds_sections_variants_and_plain_keys() {
        let schema = schema();
        let find = |path: &str, variant: Option<&str>| {
            schema
                .iter()
                .find(|s| {
                    s.path.join(".") == path
                        && s.variant.as_ref().map(|(_, v)| v.as_str()) == variant
                })
                .unwrap_or_else(|| panic!("no section {path} {variant:?}"))
        };
        // Read off `file.rs` by hand: a key of each kind of place.
        assert!(find("", None).keys.contains(&"max_speed_rpm".to_string()));
        let pull = find("magnetic_pull", None);
        assert!(pull.array && pull.keys.contains(&"gap".to_string()));
        let torsion = find("torsion", None);
        assert!(!torsion.array && torsion.keys == ["drive", "damping_ratio"]);
        let pads = find("bearings", Some("tilting_pad"));
        assert_eq!(pads.keys[0], "type");
        assert!(pads.keys.contains(&"preload".to_string()));
        let bearings: Vec<_> = schema.iter().filter(|s| s.path == ["bearings"]).collect();
        assert_eq!(bearings.len(), 4, "linear, plain, table, tilting_pad");
        assert!(bearings.iter().all(|s| s.variant.is_some()));
        // Values are not sections: the gravity vector, a table coefficient.
        assert!(!schema.iter().any(|s| s.path == ["gravity"]));
        assert!(!schema.iter().any(|s| s.path.len() > 1));
    }
}
