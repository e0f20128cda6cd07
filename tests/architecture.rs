//! The layering of `docs/ARCHITECTURE.md`, checked on the sources: every
//! `crate::…` path in a library file points to its own layer's module or to a
//! lower layer, and no source file outside `tests/` grows past the size at which
//! it starts to hold a second job; and within a room (a directory under
//! `src/`), no two parts import each other: a part does not borrow from the
//! hub that uses it.

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

/// Layers from the ground up (docs/ARCHITECTURE.md). A module may use its own
/// files and any module of a strictly lower layer; modules on the same layer do
/// not import each other.
const LAYERS: &[(&str, u32)] = &[
    ("linalg", 0),
    ("units", 0),
    ("fe", 1),
    ("bearing", 1),
    ("model", 2),
    ("rotor", 3),
    ("solver", 4),
    ("analysis", 5),
    ("fmu", 5),
    ("fmi2", 6),
    ("fmi3", 6),
    ("report", 6),
    ("plot", 6),
];

/// Most lines a source file may hold, not counting its `#[cfg(test)]` module.
const MAX_LINES: usize = 720;

fn src() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("src")
}

fn rust_files(dir: &Path, out: &mut Vec<PathBuf>) {
    for entry in std::fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        if path.is_dir() {
            rust_files(&path, out);
        } else if path.extension().is_some_and(|e| e == "rs") {
            out.push(path);
        }
    }
}

/// The top-level module a file under `src/` belongs to (`None` for `lib.rs` and
/// the binaries, which stand above every layer).
fn module_of(file: &Path) -> Option<String> {
    let rel = file.strip_prefix(src()).unwrap();
    let first = rel.components().next()?.as_os_str().to_string_lossy();
    let name = first.trim_end_matches(".rs").to_string();
    (name != "lib" && name != "bin").then_some(name)
}

fn layer(module: &str) -> u32 {
    LAYERS
        .iter()
        .find(|(m, _)| *m == module)
        .unwrap_or_else(|| panic!("module {module} has no layer in tests/architecture.rs"))
        .1
}

/// Code lines of a file: comments stripped, the trailing `#[cfg(test)]` module cut.
fn code_lines(text: &str) -> Vec<&str> {
    let mut lines = Vec::new();
    for line in text.lines() {
        let trimmed = line.trim_start();
        if trimmed.starts_with("#[cfg(test)]") {
            break;
        }
        if !trimmed.starts_with("//") {
            lines.push(line);
        }
    }
    lines
}

/// The top-level modules named by `crate::` paths in `lines`.
fn imported_modules(lines: &[&str]) -> Vec<String> {
    let mut found = Vec::new();
    for line in lines {
        let mut rest = *line;
        while let Some(at) = rest.find("crate::") {
            let after = &rest[at + "crate::".len()..];
            let name: String = after
                .chars()
                .take_while(|c| c.is_ascii_alphanumeric() || *c == '_')
                .collect();
            if !name.is_empty() {
                found.push(name);
            }
            rest = after;
        }
    }
    found
}

#[test]
fn the_scan_sees_an_upward_import() {
    let text = "use crate::solver::Simulator;\n// crate::fmi2 in a comment\nfn f() {}\n";
    assert_eq!(
        imported_modules(&code_lines(text)),
        vec!["solver".to_string()]
    );
    let with_tests = "fn a() {}\n#[cfg(test)]\nmod tests { use crate::fmi2; }\n";
    assert_eq!(code_lines(with_tests).len(), 1);
}

#[test]
fn imports_only_point_down_the_layers() {
    let mut files = Vec::new();
    rust_files(&src(), &mut files);
    let mut violations = Vec::new();
    for file in &files {
        let Some(module) = module_of(file) else {
            continue;
        };
        let own = layer(&module);
        let text = std::fs::read_to_string(file).unwrap();
        for imported in imported_modules(&code_lines(&text)) {
            if imported == module {
                continue;
            }
            if layer(&imported) >= own {
                violations.push(format!(
                    "{} ({module}, layer {own}) uses crate::{imported} (layer {})",
                    file.display(),
                    layer(&imported)
                ));
            }
        }
    }
    assert!(violations.is_empty(), "{}", violations.join("\n"));
}

#[test]
fn no_source_file_outgrows_one_job() {
    let mut files = Vec::new();
    rust_files(&src(), &mut files);
    let mut sizes = BTreeMap::new();
    for file in &files {
        let text = std::fs::read_to_string(file).unwrap();
        let n = text
            .lines()
            .take_while(|l| !l.trim_start().starts_with("#[cfg(test)]"))
            .count();
        sizes.insert(file.display().to_string(), n);
    }
    let big: Vec<String> = sizes
        .iter()
        .filter(|(_, n)| **n > MAX_LINES)
        .map(|(f, n)| format!("{f}: {n} lines"))
        .collect();
    assert!(
        big.is_empty(),
        "files past {MAX_LINES} lines (split by job):\n{}",
        big.join("\n")
    );
}

/// The directories under `src/` (the rooms, `src/` itself included).
fn rooms(dir: &Path, out: &mut Vec<PathBuf>) {
    out.push(dir.to_path_buf());
    for entry in std::fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        if path.is_dir() {
            rooms(&path, out);
        }
    }
}

/// The identifier at the start of `text` (empty when none).
fn leading_ident(text: &str) -> String {
    text.trim_start()
        .chars()
        .take_while(|c| c.is_ascii_alphanumeric() || *c == '_')
        .collect()
}

/// The parts of a `{…}` group (`text` starts after its `{`), split at the
/// commas of its own level, and the length of the group up to its `}`.
fn group_parts(text: &str) -> (Vec<&str>, usize) {
    let mut parts = Vec::new();
    let (mut depth, mut start) = (0usize, 0usize);
    for (i, c) in text.char_indices() {
        match c {
            '{' => depth += 1,
            '}' if depth == 0 => {
                parts.push(&text[start..i]);
                return (parts, i);
            }
            '}' => depth -= 1,
            ',' if depth == 0 => {
                parts.push(&text[start..i]);
                start = i + 1;
            }
            _ => {}
        }
    }
    parts.push(&text[start..]);
    (parts, text.len())
}

/// The names a file's code reaches through `super::` (`use super::x…`,
/// `use super::{x, y::…}`, `super::x::…` paths), comments and its
/// `#[cfg(test)]` module left out.
fn super_names(text: &str) -> BTreeSet<String> {
    let code = code_lines(text).join("\n");
    let mut names = BTreeSet::new();
    let mut rest = code.as_str();
    while let Some(at) = rest.find("super::") {
        let after = &rest[at + "super::".len()..];
        if let Some(group) = after.strip_prefix('{') {
            let (parts, _) = group_parts(group);
            names.extend(parts.into_iter().map(leading_ident));
        } else {
            names.insert(leading_ident(after));
        }
        rest = after;
    }
    names.remove("");
    names
}

/// The pairs of parts (`(stem, text)` of each file but `mod.rs`, the room's
/// front) that import each other, each pair once, in name order.
fn circles(parts: &[(String, String)]) -> Vec<(String, String)> {
    let stems: BTreeSet<&str> = parts.iter().map(|(s, _)| s.as_str()).collect();
    let imports: BTreeMap<&str, BTreeSet<String>> = parts
        .iter()
        .map(|(stem, text)| {
            let mut names = super_names(text);
            names.retain(|n| stems.contains(n.as_str()) && n != stem);
            (stem.as_str(), names)
        })
        .collect();
    let mut found = Vec::new();
    for (a, names) in &imports {
        for b in names {
            if *a < b.as_str() && imports[b.as_str()].contains(*a) {
                found.push((a.to_string(), b.clone()));
            }
        }
    }
    found
}

#[test]
fn the_scan_sees_two_parts_importing_each_other() {
    let part = |stem: &str, text: &str| (stem.to_string(), text.to_string());
    let room = [
        part(
            "hub",
            "use super::work::Buffers;\nuse super::{error, step::Step};\n",
        ),
        part("step", "use super::{error::Error, hub::{Hub, HUB}};\n"),
        part(
            "work",
            "/// [`super::hub::Hub`] owns it.\npub struct Buffers;\n",
        ),
        part(
            "error",
            "pub struct Error;\n#[cfg(test)]\nmod tests { use super::super::hub::Hub; }\n",
        ),
        part("leaf", "fn f() { super::hub::run(); }\n"),
    ];
    assert_eq!(
        circles(&room),
        vec![("hub".to_string(), "step".to_string())]
    );
    let mut rooted = room.to_vec();
    rooted.push(part("run", "fn g() { super::leaf::f(); }\n"));
    rooted[4] = part("leaf", "fn f() { super::run::g(); }\n");
    assert_eq!(circles(&rooted).len(), 2);
}

#[test]
fn no_two_parts_of_a_room_import_each_other() {
    let mut dirs = Vec::new();
    rooms(&src(), &mut dirs);
    let mut violations = Vec::new();
    for dir in &dirs {
        let mut parts = Vec::new();
        for entry in std::fs::read_dir(dir).unwrap() {
            let path = entry.unwrap().path();
            let is_part = path.extension().is_some_and(|e| e == "rs")
                && path.file_name().is_some_and(|n| n != "mod.rs");
            if is_part {
                let stem = path.file_stem().unwrap().to_string_lossy().to_string();
                parts.push((stem, std::fs::read_to_string(&path).unwrap()));
            }
        }
        for (a, b) in circles(&parts) {
            violations.push(format!(
                "{}: {a}.rs and {b}.rs import each other (move what both need into the lower one or a file of its own)",
                dir.display()
            ));
        }
    }
    assert!(violations.is_empty(), "{}", violations.join("\n"));
}
