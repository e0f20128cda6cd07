//! The repository stands alone: nothing in the product, its tests, benchmarks,
//! examples or scripts reads a folder beside the clone, and every repository
//! file the tests name is committed (so a fresh clone has it).

use std::path::{Path, PathBuf};
use std::process::Command;

/// Folders (and top-level files) whose files must not reach outside the repo.
const SCANNED: &[&str] = &[
    "src",
    "tests",
    "benches",
    "examples",
    "scripts",
    "system",
    "bench",
    ".ci",
    "build.rs",
    "fmu_pack.sh",
    "Cargo.toml",
];

/// Top-level folders holding committed inputs that tests and scripts read.
const COMMITTED_INPUTS: &[&str] = &["models/", "tests/data/", "system/", "scripts/", "bench/"];

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

fn text_files(path: &Path, out: &mut Vec<PathBuf>) {
    if path.is_dir() {
        let mut entries: Vec<_> = std::fs::read_dir(path)
            .unwrap()
            .map(|e| e.unwrap().path())
            .collect();
        entries.sort();
        for entry in entries {
            let name = entry.file_name().unwrap().to_string_lossy().into_owned();
            if name == "__pycache__" || name.ends_with(".png") {
                continue;
            }
            text_files(&entry, out);
        }
    } else if path.is_file() {
        out.push(path.to_path_buf());
    }
}

fn scanned_files() -> Vec<PathBuf> {
    let mut files = Vec::new();
    for item in SCANNED {
        text_files(&root().join(item), &mut files);
    }
    assert!(files.len() > 50, "only {} files scanned", files.len());
    files
}

/// The spellings of a path into the sibling reference folder.
fn outside_patterns() -> Vec<String> {
    // Built at run time so this file does not match itself.
    let sibling = ["..", "shared"].join("/");
    vec![
        format!("{sibling}/"),
        format!("{sibling}\""),
        ["shared", "reference"].join("/"),
    ]
}

/// Lines of `text` that name a path outside the repository.
fn outside_references(text: &str) -> Vec<(usize, String)> {
    let patterns = outside_patterns();
    text.lines()
        .enumerate()
        .filter(|(_, line)| patterns.iter().any(|p| line.contains(p.as_str())))
        .map(|(i, line)| (i + 1, line.trim().to_string()))
        .collect()
}

#[test]
fn the_scan_finds_a_reference_to_the_sibling_folder() {
    let sibling = ["..", "shared"].join("/");
    let text = format!("let p = root.join(\"{sibling}/reference/x.json\");\nok\n");
    assert_eq!(outside_references(&text).len(), 1);
    assert!(outside_references("let p = root.join(\"tests/data/x.json\");").is_empty());
}

#[test]
fn no_file_reads_the_folder_beside_the_repository() {
    let mut hits = Vec::new();
    for file in scanned_files() {
        let Ok(text) = std::fs::read_to_string(&file) else {
            continue; // binary file
        };
        for (line, content) in outside_references(&text) {
            hits.push(format!("{}:{line}: {content}", file.display()));
        }
    }
    assert!(
        hits.is_empty(),
        "files name a path outside the repository:\n{}",
        hits.join("\n")
    );
}

/// Repository-relative paths quoted in `text` under one of the committed input folders.
fn quoted_input_paths(text: &str) -> Vec<String> {
    let mut paths = Vec::new();
    for piece in text.split('"').skip(1).step_by(2) {
        let under_input = COMMITTED_INPUTS
            .iter()
            .any(|p| piece.starts_with(p) || piece == p.trim_end_matches('/'));
        if under_input
            && piece.len() < 200
            && !piece.contains(char::is_whitespace)
            && !piece.contains(['{', '\\'])
            && !piece.ends_with('/')
        {
            paths.push(piece.to_string());
        }
    }
    paths
}

fn git_tracked() -> Vec<String> {
    let out = Command::new("git")
        .args(["ls-files", "-z"])
        .current_dir(root())
        .output()
        .expect("git is needed to check that test inputs are committed");
    assert!(out.status.success(), "git ls-files failed: not a clone?");
    String::from_utf8(out.stdout)
        .unwrap()
        .split('\0')
        .filter(|s| !s.is_empty())
        .map(str::to_string)
        .collect()
}

#[test]
fn every_input_the_tests_name_is_committed() {
    let tracked = git_tracked();
    let mut named = Vec::new();
    for file in scanned_files() {
        if let Ok(text) = std::fs::read_to_string(&file) {
            named.extend(quoted_input_paths(&text));
        }
    }
    named.sort();
    named.dedup();
    assert!(
        named.iter().any(|p| p.starts_with("tests/data/")),
        "the reference data paths were not found: {named:?}"
    );
    let missing: Vec<&String> = named
        .iter()
        .filter(|p| {
            !tracked
                .iter()
                .any(|t| t == *p || t.starts_with(&format!("{p}/")))
        })
        .collect();
    assert!(
        missing.is_empty(),
        "named by a test or script but not committed (a fresh clone lacks them): {missing:?}"
    );
}

#[test]
fn every_reference_data_file_is_committed_and_described() {
    let tracked = git_tracked();
    let readme = std::fs::read_to_string(root().join("tests/data/README.md")).unwrap();
    let mut count = 0;
    for entry in std::fs::read_dir(root().join("tests/data")).unwrap() {
        let name = entry.unwrap().file_name().to_string_lossy().into_owned();
        let rel = format!("tests/data/{name}");
        // A folder counts as committed when files under it are.
        let committed =
            tracked.contains(&rel) || tracked.iter().any(|t| t.starts_with(&format!("{rel}/")));
        assert!(committed, "{rel} is not committed");
        assert!(
            readme.contains(&format!("`{name}`"))
                || readme.contains(&format!("`{name}/"))
                || name == "README.md",
            "{rel} is not described in tests/data/README.md"
        );
        count += 1;
    }
    assert!(count >= 4, "tests/data holds only {count} files");
}
