//! Model-file mutation fuzzer: mutants of every shipped model are loaded and
//! assembled by `rotor info`, and solved by `rotor static`, in child processes
//! with a timeout. A mutant may be accepted or refused, but the run fails on a
//! panic, a crash, a hang, a refusal that does not name the file, a NaN or
//! infinity printed by a command that succeeds, or nonsense accepted silently:
//! a non-finite number anywhere, a non-positive size or property where physics
//! needs a positive one, a size or mass absurd by twenty orders of magnitude
//! (issue 22: a diameter of 1e300 m passed), a duplicated name. Centre
//! offsets (`offset_x`, `offset_y`, issue 49) are inserted into the entries
//! that take them, with the same values, and so are the couplings'
//! misalignments (`parallel_offset`, `angular_offset`, as `[value, 0.0]`);
//! the couplings' stiffnesses and dampings are mutated where the shipped
//! train (`models/turbine_generator_train.toml`) gives them. Tilting-pad
//! entries get `pivot_stiffness`, `pad_inertia`, `pad_mass` or `pivot_damping` inserted
//! (issue 47) with the same values.
//!
//! `ROTOR_MODEL_FUZZ_MUTANTS` sets the mutants per model (default 100),
//! `ROTOR_FUZZ_SEED` the first seed (default 1); each failure prints its seed
//! and the mutant is left in the test's temporary folder.

use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

#[path = "common/rng.rs"]
mod rng;
use rng::Rng;

/// Keys whose value must be a positive number (SI sizes and properties).
const POSITIVE: &[&str] = &[
    "length",
    "outer_diameter",
    "youngs_modulus",
    "shear_modulus",
    "density",
    "mass",
    "width",
    "radius",
    "clearance",
    "viscosity",
    "pad_arc_deg",
    "elements",
    "pads",
    "pivot_stiffness",
    "lateral_stiffness",
    "angular_stiffness",
    "torsional_stiffness",
];

/// Keys whose value must not be negative (zero disk inertias make a point mass).
const NON_NEGATIVE: &[&str] = &[
    "pad_inertia",
    "pad_mass",
    "pivot_damping",
    "polar_inertia",
    "diametral_inertia",
    "lateral_damping",
    "angular_damping",
    "torsional_damping",
];

/// Keys of sizes and masses: a value of 1e20 or 1e-20 (in SI units) is no
/// machine and must be refused, naming the field.
const SIZES: &[&str] = &[
    "length",
    "outer_diameter",
    "width",
    "radius",
    "clearance",
    "gap",
    "mass",
    "polar_inertia",
    "diametral_inertia",
    "density",
];

/// Keys of centre offsets (m, issue 49), inserted into the entries that take
/// them: beyond a metre off the axis is no machine and must be refused.
const OFFSETS: &[&str] = &["offset_x", "offset_y"];

/// A tilting-pad bearing's pivot stiffness and pad inertia (issue 47),
/// inserted into the tilting-pad entries.
const PAD_SUPPORT: &[&str] = &[
    "pivot_stiffness",
    "pad_inertia",
    "pad_mass",
    "pivot_damping",
];

/// Sections whose entries take `offset_x`, `offset_y`.
const OFFSET_SECTIONS: &[&str] = &[
    "[[bearings]]",
    "[[rubs]]",
    "[[seals]]",
    "[[magnetic_pull]]",
    "[[pedestals]]",
];

/// A coupling's misalignments (issue 49) and the largest magnitude each
/// takes: 1 m of parallel offset, 0.1 rad of angular offset.
const COUPLING_OFFSETS: &[(&str, f64)] = &[("parallel_offset", 1.0), ("angular_offset", 0.1)];

/// Replacement values: nonsense, edge cases and wrong types.
const VALUES: &[&str] = &[
    "0",
    "0.0",
    "-1",
    "-1e-3",
    "1e308",
    "1e-300",
    "1e300",
    "1e20",
    "1e-20",
    "1e-200",
    "nan",
    "inf",
    "-inf",
    "1e12",
    "999999999",
    "\"text\"",
    "true",
    "[]",
    "[1, 2]",
    "{}",
];

/// What a mutation did, for judging the outcome.
#[derive(Debug)]
enum Mutation {
    /// `key = value` set on line `line`.
    Value {
        key: String,
        value: &'static str,
        line: usize,
    },
    /// A named `[[section]]` block repeated verbatim (its name twice).
    DuplicateSection { name: String },
    /// Anything else (deleted or garbled lines, truncation): must not crash.
    Other(String),
}

impl Mutation {
    fn describe(&self) -> String {
        match self {
            Mutation::Value { key, value, line } => format!("line {line}: {key} = {value}"),
            Mutation::DuplicateSection { name } => format!("section {name} repeated"),
            Mutation::Other(what) => what.clone(),
        }
    }

    /// `Some(reason)` when the mutant is nonsense that must be refused.
    fn must_refuse(&self) -> Option<String> {
        match self {
            Mutation::Value { key, value, .. } => {
                let number: Option<f64> = value.parse().ok();
                match number {
                    Some(x) if !x.is_finite() => Some(format!("{key} = {value} is not finite")),
                    Some(x) if x <= 0.0 && POSITIVE.contains(&key.as_str()) => {
                        Some(format!("{key} = {value} must be positive"))
                    }
                    Some(x) if x < 0.0 && NON_NEGATIVE.contains(&key.as_str()) => {
                        Some(format!("{key} = {value} must not be negative"))
                    }
                    Some(x) if OFFSETS.contains(&key.as_str()) && x.abs() > 1.0 => {
                        Some(format!("{key} = {value} is no offset (beyond 1 m)"))
                    }
                    Some(x)
                        if COUPLING_OFFSETS
                            .iter()
                            .any(|(k, most)| k == key && x.abs() > *most) =>
                    {
                        Some(format!("{key} = [{value}, 0.0] is no misalignment"))
                    }
                    Some(x)
                        if SIZES.contains(&key.as_str())
                            && !((1e-20..1e20).contains(&x)
                                || x == 0.0 && NON_NEGATIVE.contains(&key.as_str())) =>
                    {
                        Some(format!("{key} = {value} is no machine"))
                    }
                    _ => None,
                }
            }
            Mutation::DuplicateSection { name } => Some(format!("name {name} appears twice")),
            Mutation::Other(_) => None,
        }
    }
}

/// Whether the entry under the header on line `header` is a tilting-pad bearing.
fn tilting_pad_block(lines: &[&str], header: usize) -> bool {
    lines[header + 1..]
        .iter()
        .take_while(|l| !l.trim_start().starts_with('['))
        .any(|l| l.replace(' ', "").starts_with("type=\"tilting_pad\""))
}

/// `key = number` lines (`key` and the byte range of the number).
fn numeric_assignments(lines: &[&str]) -> Vec<(usize, String)> {
    lines
        .iter()
        .enumerate()
        .filter_map(|(i, line)| {
            let (key, value) = line.split_once('=')?;
            let key = key.trim();
            let value = value.split('#').next()?.trim();
            let is_key =
                !key.is_empty() && key.chars().all(|c| c.is_ascii_alphanumeric() || c == '_');
            (is_key && value.parse::<f64>().is_ok()).then(|| (i, key.to_string()))
        })
        .collect()
}

/// Blocks `[[table]]` … up to the next header that carry a `name = "…"`.
fn named_blocks(lines: &[&str]) -> Vec<(usize, usize, String)> {
    let mut blocks = Vec::new();
    let mut start = None;
    for (i, line) in lines.iter().enumerate().chain([(lines.len(), &"[[end]]")]) {
        if line.trim_start().starts_with('[') {
            if let Some(s) = start {
                let name = lines[s..i].iter().find_map(|l| {
                    let (k, v) = l.split_once('=')?;
                    (k.trim() == "name").then(|| v.trim().trim_matches('"').to_string())
                });
                if let Some(name) = name
                    && lines[s].trim_start().starts_with("[[")
                {
                    blocks.push((s, i, name));
                }
            }
            start = Some(i);
        }
    }
    blocks
}

fn mutate(text: &str, rng: &mut Rng) -> (String, Mutation) {
    let lines: Vec<&str> = text.lines().collect();
    let numeric = numeric_assignments(&lines);
    let blocks = named_blocks(&lines);
    let headers: Vec<usize> = lines
        .iter()
        .enumerate()
        .filter(|(_, l)| OFFSET_SECTIONS.contains(&l.trim()) || l.trim() == "[[couplings]]")
        .map(|(i, _)| i)
        .collect();
    match rng.below(10) {
        5 if !headers.is_empty() => {
            // A centre offset (a coupling's misalignment) inserted into an
            // entry that takes one.
            let header = headers[rng.below(headers.len())];
            let at = header + 1;
            let value = VALUES[rng.below(VALUES.len())];
            let (key, assignment) = if lines[header].trim() == "[[couplings]]" {
                let key = COUPLING_OFFSETS[rng.below(COUPLING_OFFSETS.len())].0;
                (key.to_string(), format!("{key} = [{value}, 0.0]"))
            } else if rng.below(2) == 0 && tilting_pad_block(&lines, header) {
                let key = PAD_SUPPORT[rng.below(PAD_SUPPORT.len())];
                (key.to_string(), format!("{key} = {value}"))
            } else {
                let key = OFFSETS[rng.below(OFFSETS.len())];
                (key.to_string(), format!("{key} = {value}"))
            };
            let mut out: Vec<String> = lines.iter().map(|l| l.to_string()).collect();
            out.insert(at, assignment);
            (
                out.join("\n"),
                Mutation::Value {
                    key,
                    value,
                    line: at + 1,
                },
            )
        }
        0..=5 if !numeric.is_empty() => {
            let (line, key) = numeric[rng.below(numeric.len())].clone();
            let value = VALUES[rng.below(VALUES.len())];
            let mut out: Vec<String> = lines.iter().map(|l| l.to_string()).collect();
            out[line] = format!("{key} = {value}");
            (
                out.join("\n"),
                Mutation::Value {
                    key,
                    value,
                    line: line + 1,
                },
            )
        }
        6 if !blocks.is_empty() => {
            let (s, e, name) = blocks[rng.below(blocks.len())].clone();
            let mut out: Vec<&str> = lines.clone();
            let copy: Vec<&str> = lines[s..e].to_vec();
            for (k, l) in copy.into_iter().enumerate() {
                out.insert(e + k, l);
            }
            (out.join("\n"), Mutation::DuplicateSection { name })
        }
        7 => {
            let k = rng.below(lines.len());
            let mut out = lines.clone();
            out.remove(k);
            (
                out.join("\n"),
                Mutation::Other(format!("line {} deleted", k + 1)),
            )
        }
        8 => {
            let cut = rng.below(text.len());
            let cut = (0..=cut)
                .rev()
                .find(|&c| text.is_char_boundary(c))
                .unwrap_or(0);
            (
                text[..cut].to_string(),
                Mutation::Other(format!("truncated at byte {cut}")),
            )
        }
        _ => {
            let garbage = [
                "= =",
                "[[",
                "unknown_key = 1",
                "name = ",
                "[[shaft]]",
                "\u{0}",
            ];
            let g = garbage[rng.below(garbage.len())];
            let k = rng.below(lines.len() + 1);
            let mut out = lines.clone();
            out.insert(k, g);
            (
                out.join("\n"),
                Mutation::Other(format!("{g:?} inserted at line {}", k + 1)),
            )
        }
    }
}

/// Run `rotor COMMAND FILE` with a timeout: `None` on a hang, else exit code
/// and stderr, or the first line of stdout with a NaN or infinity.
fn rotor(command: &str, file: &Path, timeout: Duration) -> Option<(Option<i32>, String)> {
    // Film tables (the compressor's) built once into the test's own cache,
    // not the user's.
    let cache = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("model_fuzz_cache");
    let mut child = Command::new(env!("CARGO_BIN_EXE_rotor"))
        .env("ROTOR_CACHE_DIR", cache)
        .arg(command)
        .arg(file)
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let start = Instant::now();
    loop {
        if child.try_wait().unwrap().is_some() {
            let out = child.wait_with_output().unwrap();
            let stdout = String::from_utf8_lossy(&out.stdout);
            let not_finite = stdout.lines().find(|l| {
                l.split(|c: char| !c.is_ascii_alphanumeric())
                    .any(|w| w.eq_ignore_ascii_case("nan") || w.eq_ignore_ascii_case("inf"))
            });
            return Some(match (out.status.code(), not_finite) {
                (Some(0), Some(line)) => (Some(-1), format!("printed {line:?}")),
                (code, _) => (code, String::from_utf8_lossy(&out.stderr).into_owned()),
            });
        }
        if start.elapsed() > timeout {
            let _ = child.kill();
            let _ = child.wait();
            return None;
        }
        std::thread::sleep(Duration::from_millis(5));
    }
}

fn env_u64(name: &str, default: u64) -> u64 {
    std::env::var(name)
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(default)
}

#[test]
fn mutated_models_are_refused_cleanly_or_accepted_sensibly() {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("model_fuzz");
    std::fs::create_dir_all(&dir).unwrap();
    let per_model = env_u64("ROTOR_MODEL_FUZZ_MUTANTS", 100);
    let first = env_u64("ROTOR_FUZZ_SEED", 1);
    let mut models: Vec<PathBuf> = std::fs::read_dir(root.join("models"))
        .unwrap()
        .map(|e| e.unwrap().path())
        .collect();
    models.sort();
    let mut failures = Vec::new();
    let mut tried = 0;
    for (m, model) in models.iter().enumerate() {
        let text = std::fs::read_to_string(model).unwrap();
        for seed in first..first + per_model {
            let mut rng = Rng(seed ^ ((m as u64 + 1) << 40));
            let (mutant, mutation) = mutate(&text, &mut rng);
            let stem = model.file_stem().unwrap().to_string_lossy();
            let file = dir.join(format!("{stem}_{seed}.toml"));
            std::fs::write(&file, &mutant).unwrap();
            tried += 1;
            let what = format!("{} seed {seed} ({})", file.display(), mutation.describe());
            let outcome = rotor("info", &file, Duration::from_secs(20));
            // An accepted model is solved too: a success must print no NaN.
            let outcome = match outcome {
                // (`static` may refuse what `info` accepts, e.g. a rotor with no support.)
                Some((Some(0), _)) => {
                    rotor("static", &file, Duration::from_secs(20)).map(|(code, err)| match code {
                        Some(1) => (Some(0), err),
                        other => (other, err),
                    })
                }
                other => other,
            };
            match outcome {
                None => failures.push(format!("hang: {what}")),
                Some((Some(-1), line)) => failures.push(format!("NaN printed: {what}: {line}")),
                Some((None, err)) => failures.push(format!("killed by a signal: {what}\n{err}")),
                Some((Some(101), err)) => failures.push(format!("panic: {what}\n{err}")),
                Some((Some(0), _)) => {
                    if let Some(why) = mutation.must_refuse() {
                        failures.push(format!("accepted nonsense ({why}): {what}"));
                    }
                    continue;
                }
                Some((Some(_), err)) => {
                    let name = file.file_name().unwrap().to_string_lossy().into_owned();
                    if !err.contains(&name) {
                        failures.push(format!("refusal does not name the file: {what}\n{err}"));
                    } else if let Mutation::Value { key, .. } = &mutation
                        && mutation.must_refuse().is_some()
                        && !err.contains(key.as_str())
                    {
                        failures.push(format!(
                            "refusal does not name the field {key}: {what}\n{err}"
                        ));
                    }
                    continue;
                }
            }
        }
    }
    assert!(tried >= 500, "only {tried} mutants");
    assert!(
        failures.is_empty(),
        "{} of {tried} mutants failed:\n{}",
        failures.len(),
        failures.join("\n\n")
    );
}
