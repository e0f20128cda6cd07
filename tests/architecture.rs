//! The layering of `docs/ARCHITECTURE.md`, checked on the sources: every
//! `crate::…` path in a library file points to its own layer's module or to a
//! lower layer, and no source file outside `tests/` grows past the size at which
//! it starts to hold a second job.

use std::collections::BTreeMap;
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
