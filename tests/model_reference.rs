//! The model reference is complete and kept complete: every key the model
//! parser accepts has a row in `docs/model_file.md` (the keys read from the
//! parser by `model::schema`, not from a list kept by hand), every row names
//! a key the parser accepts, and `rotor info` names every section of every
//! shipped model.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

use rotor_bearing::model::schema::{SchemaSection, schema};

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// A section of the reference as the parser names it: its path (`""` for
/// the top level, `"bearings"`) and the tag value of a variant (`"plain"`).
type Place = (String, Option<String>);

/// One documented section: whether its heading writes it as an array of
/// tables, and the keys of each row with the row's cells.
#[derive(Debug, Default)]
struct DocSection {
    array: bool,
    rows: Vec<(Vec<String>, Vec<String>)>,
}

/// The sections of the reference: under each heading naming a section (`##
/// Top level`, `` ## `[[magnetic_pull]]` ``, `` ### `[[bearings]]` `type =
/// "plain"` ``), the keys backticked in the first cell of each table row.
/// Other headings end a section.
fn documented(text: &str) -> BTreeMap<Place, DocSection> {
    let mut out: BTreeMap<Place, DocSection> = BTreeMap::new();
    let mut at: Option<Place> = None;
    for line in text.lines() {
        if line.starts_with('#') {
            at = heading(line);
            if let Some(place) = &at {
                let array = line.contains("`[[");
                out.entry(place.clone()).or_default().array = array;
            }
            continue;
        }
        let Some(place) = &at else { continue };
        if !line.starts_with('|') || line.starts_with("|---") || line.starts_with("| key |") {
            continue;
        }
        let cells = cells(line);
        let keys = backticked(&cells[0])
            .into_iter()
            .map(|k| k.trim_matches(['[', ']']).to_string())
            .filter(|k| {
                !k.is_empty()
                    && k.chars()
                        .all(|c| c.is_ascii_lowercase() || c.is_ascii_digit() || c == '_')
            })
            .collect();
        out.get_mut(place).unwrap().rows.push((keys, cells));
    }
    out
}

/// The section a heading names, if any.
fn heading(line: &str) -> Option<Place> {
    if line.trim_start_matches('#').trim() == "Top level" {
        return Some((String::new(), None));
    }
    let name = backticked(line)
        .into_iter()
        .find(|t| t.starts_with('['))?
        .trim_matches(['[', ']'])
        .to_string();
    // A variant: `tag = "value"`.
    let variant = line
        .split_once("= \"")
        .map(|(_, rest)| rest.split('"').next().unwrap_or_default().to_string());
    Some((name, variant))
}

/// The cells of a table row, `\|` kept inside a cell.
fn cells(line: &str) -> Vec<String> {
    let inner = line.trim().trim_start_matches('|').trim_end_matches('|');
    let mut cells = vec![String::new()];
    let mut chars = inner.chars().peekable();
    while let Some(c) = chars.next() {
        match c {
            '\\' if chars.peek() == Some(&'|') => {
                cells.last_mut().unwrap().push('|');
                chars.next();
            }
            '|' => cells.push(String::new()),
            c => cells.last_mut().unwrap().push(c),
        }
    }
    cells.into_iter().map(|c| c.trim().to_string()).collect()
}

fn backticked(text: &str) -> Vec<String> {
    text.split('`')
        .skip(1)
        .step_by(2)
        .map(str::to_string)
        .collect()
}

fn place(section: &SchemaSection) -> Place {
    (
        section.path.join("."),
        section.variant.as_ref().map(|(_, v)| v.clone()),
    )
}

/// Every way the reference falls short of the parser: a key without a row,
/// a row naming a key the parser refuses there, a section without a
/// heading or written with the wrong brackets, a row without its unit,
/// meaning, default and range.
fn problems(reference: &str, schema: &[SchemaSection]) -> Vec<String> {
    let doc = documented(reference);
    let mut problems = Vec::new();
    let rows_of = |p: &Place| -> Vec<String> {
        doc.get(p)
            .map(|s| s.rows.iter().flat_map(|(k, _)| k.clone()).collect())
            .unwrap_or_default()
    };
    for section in schema {
        let here = place(section);
        // A variant's keys may be documented in its own table or in the
        // table of the keys every variant shares.
        let common = (here.0.clone(), None);
        if !doc.contains_key(&here) {
            problems.push(format!("{}: no section", section.title()));
            continue;
        }
        if doc[&here].array != section.array && !section.path.is_empty() {
            problems.push(format!(
                "{}: heading has the wrong brackets",
                section.title()
            ));
        }
        let mut rows = rows_of(&here);
        if section.variant.is_some() {
            rows.extend(rows_of(&common));
        }
        for key in &section.keys {
            if !rows.contains(key) {
                problems.push(format!("{}: no row for `{key}`", section.title()));
            }
        }
    }
    for (here, documented) in &doc {
        let variants: Vec<&SchemaSection> = schema
            .iter()
            .filter(|s| s.path.join(".") == here.0)
            .filter(|s| here.1.is_none() || place(s) == *here)
            .collect();
        if variants.is_empty() {
            problems.push(format!(
                "{here:?}: documented, but the parser has no such section"
            ));
            continue;
        }
        for (keys, cells) in &documented.rows {
            if cells.len() != 5 || cells.iter().any(|c| c.is_empty()) {
                problems.push(format!(
                    "{here:?}: row {keys:?} needs key, unit, meaning, default and range: {cells:?}"
                ));
            }
            if keys.is_empty() {
                problems.push(format!("{here:?}: row without a key: {cells:?}"));
            }
            for key in keys {
                // A shared row must hold for every variant.
                if !variants.iter().all(|s| s.keys.contains(key)) {
                    problems.push(format!(
                        "{here:?}: row `{key}`: the parser refuses this key"
                    ));
                }
            }
        }
    }
    problems
}

fn reference() -> String {
    std::fs::read_to_string(root().join("docs/model_file.md")).unwrap()
}

/// Issue 48: `docs/model_file.md` claimed to list every key but had no row
/// for `[[magnetic_pull]]` (its `gap` named nowhere), `[[forces]]`,
/// `[[ports]]`, `[torsion]`, `[[torques]]`, `[[thrust_bearings]]` or
/// `[[couplings]]`.
#[test]
fn every_key_the_parser_accepts_has_a_row_in_the_reference() {
    let schema = schema();
    let problems = problems(&reference(), &schema);
    assert!(
        problems.is_empty(),
        "docs/model_file.md against the parser:\n{}",
        problems.join("\n")
    );
    let keys: usize = schema.iter().map(|s| s.keys.len()).sum();
    assert!(
        schema.len() >= 23 && keys > 150,
        "{} sections, {keys} keys",
        schema.len()
    );
}

/// The check is not one that cannot fail: the reference with one row cut
/// (the pull's `gap`), or with a row for a key the parser refuses, is
/// reported by name.
#[test]
fn a_missing_or_stale_row_is_reported() {
    let schema = schema();
    let text = reference();
    let gap_row = text
        .lines()
        .find(|l| l.starts_with("| `gap` | m | radial air gap"))
        .expect("the pull's gap row");
    let cut = text.replace(&format!("{gap_row}\n"), "");
    assert_eq!(
        problems(&cut, &schema),
        ["[[magnetic_pull]]: no row for `gap`"]
    );
    let stale = text.replace(
        "| `drive` |",
        "| `shaft_speed` | rpm | x | 0 | any |\n| `drive` |",
    );
    assert_eq!(
        problems(&stale, &schema),
        [r#"("torsion", None): row `shaft_speed`: the parser refuses this key"#]
    );
}

/// The files the repository ships or tests with.
fn model_files() -> Vec<PathBuf> {
    let mut files = Vec::new();
    for dir in ["models", "examples", "tests/data"] {
        for entry in std::fs::read_dir(root().join(dir)).unwrap() {
            let path = entry.unwrap().path();
            if path.extension().is_some_and(|e| e == "toml") {
                files.push(path);
            }
        }
    }
    files.sort();
    files
}

/// An independent check of the discovery: every key written in a shipped
/// model file (each read as plain TOML, whatever the parser makes of it)
/// is among the keys `model::schema` found at its place.
#[test]
fn every_key_of_the_shipped_models_is_in_the_discovered_schema() {
    let schema = schema();
    let lookup = |path: &str, variant: Option<&str>| {
        schema.iter().find(|s| {
            s.path.join(".") == path && s.variant.as_ref().map(|(_, v)| v.as_str()) == variant
        })
    };
    let mut seen = 0;
    for file in model_files() {
        let text = std::fs::read_to_string(&file).unwrap();
        let Ok(table) = text.parse::<toml::Table>() else {
            continue;
        };
        for (key, value) in &table {
            assert!(
                lookup("", None).unwrap().keys.contains(key),
                "{file:?}: {key}"
            );
            let entries: Vec<&toml::Table> = match value {
                toml::Value::Table(t) => vec![t],
                toml::Value::Array(a) => a.iter().filter_map(|v| v.as_table()).collect(),
                _ => continue,
            };
            for entry in entries {
                let variant = entry.get("type").and_then(|t| t.as_str());
                let section = lookup(key, variant)
                    .unwrap_or_else(|| panic!("{file:?}: section {key} {variant:?} not found"));
                for k in entry.keys() {
                    assert!(section.keys.contains(k), "{file:?}: {key}.{k}");
                    seen += 1;
                }
            }
        }
    }
    assert!(seen > 300, "{seen} keys checked");
}

/// What `rotor info` calls each section's entries: every line of an entry
/// starts with it. Every section the parser accepts must be here, so a new
/// section cannot be added without saying how `rotor info` shows it.
fn info_label(section: &str, entry: &toml::Table) -> String {
    match section {
        "materials" => "material".into(),
        "shaft" => "shaft section".into(),
        "disks" => "disk".into(),
        "point_masses" => "point mass".into(),
        "bearings" => "bearing".into(),
        "rubs" => "rub".into(),
        "seals" => "seal".into(),
        "magnetic_pull" => "magnetic pull".into(),
        "pedestals" => "pedestal".into(),
        "supports" => "support".into(),
        "unbalance" => "unbalance".into(),
        "forces" => "force".into(),
        "ports" => "port".into(),
        "probes" => "probe".into(),
        // `[torsion] drive = "torque"` is the `torque drive:` line.
        "torsion" => format!(
            "{} drive",
            entry
                .get("drive")
                .and_then(|d| d.as_str())
                .unwrap_or("speed")
        ),
        "torques" => "torque".into(),
        "couplings" => "coupling".into(),
        "thrust_bearings" => "thrust bearing".into(),
        "reduction" => "reduction".into(),
        "cases" => "tolerance cases".into(),
        "shaft_vibration_zones" => "shaft vibration zones".into(),
        other => panic!("no `rotor info` label for the section [{other}]"),
    }
}

#[test]
fn every_section_of_the_parser_has_an_info_label() {
    for section in schema().iter().filter(|s| !s.path.is_empty()) {
        info_label(&section.path.join("."), &toml::Table::new());
    }
}

/// Issue 48: `rotor info` did not show `[[forces]]`. For every shipped model
/// (and the torque-and-ports test model), each section the TOML file holds
/// has a line in `rotor info` starting with its label, and each named entry
/// a line with its label and name.
#[test]
fn rotor_info_names_every_section_of_every_shipped_model() {
    let mut files: Vec<PathBuf> = std::fs::read_dir(root().join("models"))
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "toml"))
        .collect();
    files.sort();
    files.push(root().join("tests/data/torque_ports.toml"));
    let mut checked = 0;
    for file in &files {
        let info = info(file);
        let table: toml::Table = std::fs::read_to_string(file).unwrap().parse().unwrap();
        for (section, value) in &table {
            let entries: Vec<&toml::Table> = match value {
                toml::Value::Table(t) => vec![t],
                toml::Value::Array(a) => a.iter().filter_map(|v| v.as_table()).collect(),
                _ => continue,
            };
            for entry in entries {
                let label = info_label(section, entry);
                let lines: Vec<&str> = info
                    .lines()
                    .map(str::trim_start)
                    .filter(|l| {
                        l.strip_prefix(label.as_str())
                            .is_some_and(|rest| rest.starts_with([' ', ':']))
                    })
                    .collect();
                assert!(
                    !lines.is_empty(),
                    "{file:?}: [{section}] has no `{label}` line in rotor info:\n{info}"
                );
                if let Some(name) = entry.get("name").and_then(|n| n.as_str()) {
                    assert!(
                        lines
                            .iter()
                            .any(|l| l.starts_with(&format!("{label} {name}"))),
                        "{file:?}: [{section}] {name}: no `{label} {name}` line in rotor info:\n{info}"
                    );
                }
                checked += 1;
            }
        }
    }
    assert!(checked > 100, "{checked} entries");
}

fn info(file: &Path) -> String {
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_rotor"))
        .arg("info")
        .arg(file)
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{file:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8(out.stdout).unwrap()
}
