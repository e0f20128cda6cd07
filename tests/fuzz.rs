//! Fuzzing of the shipped FMUs' C API: random call sequences (see
//! `examples/fmu_fuzz.rs` for what each sequence checks), run in child
//! processes with a timeout so that a crash or a hang fails the test with the
//! seed that caused it.
//!
//! `ROTOR_FUZZ_SEQUENCES` sets the number of sequences per shipped FMU
//! (default 2000; a tenth of it for an FMU with film tables), `ROTOR_FUZZ_INPUT_SEQUENCES` those of the FMU with every
//! input kind, `tests/data/torque_ports.toml` (default 5000),
//! `ROTOR_FUZZ_SEED` the first seed (default 1). A failing seed replays with
//! `target/debug/examples/fmu_fuzz DIR SEED 1`.

use std::io::{BufRead, BufReader};
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

fn env_u64(name: &str, default: u64) -> u64 {
    std::env::var(name)
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(default)
}

/// The FMU packed from each shipped model (`scripts/test.sh` packs them all),
/// and from `tests/data/torque_ports.toml`: a torque-driven rotor with a
/// port, a magnetic pull and forces, so that the fuzzed sequences reach the
/// torque, port, force and excitation variables.
fn shipped_fmus() -> Vec<PathBuf> {
    let mut fmus = vec![root().join("out/torque_ports.fmu")];
    assert!(
        fmus[0].exists(),
        "{} missing: scripts/test.sh packs it",
        fmus[0].display()
    );
    for entry in std::fs::read_dir(root().join("models")).unwrap() {
        let path = entry.unwrap().path();
        let stem = path.file_stem().unwrap().to_string_lossy().into_owned();
        let fmu = if stem == "hydro_unit" {
            "RotorBearing".to_string()
        } else {
            stem
        };
        let fmu = root().join("out").join(format!("{fmu}.fmu"));
        assert!(
            fmu.exists(),
            "{} missing: scripts/test.sh packs an FMU of every model",
            fmu.display()
        );
        fmus.push(fmu);
    }
    fmus.sort();
    fmus
}

/// Unpack `fmu` (a zip) into a fresh folder, as an importer does.
fn unpack(fmu: &Path) -> PathBuf {
    let name = fmu.file_stem().unwrap().to_string_lossy().into_owned();
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join(format!("fuzz_{name}"));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let python = root().join(".venv/bin/python");
    let status = Command::new(&python)
        .args(["-m", "zipfile", "-e"])
        .arg(fmu)
        .arg(&dir)
        .status()
        .unwrap_or_else(|e| panic!("{}: {e} (run scripts/python_env.sh)", python.display()));
    assert!(status.success(), "unpacking {} failed", fmu.display());
    dir
}

fn fuzzer() -> PathBuf {
    let exe = std::env::current_exe().unwrap();
    let path = exe
        .parent()
        .unwrap()
        .parent()
        .unwrap()
        .join("examples/fmu_fuzz");
    assert!(
        path.exists(),
        "{} missing: cargo build --examples",
        path.display()
    );
    path
}

/// Run seeds `first .. first + count` in one child; `Err` names the seed and why.
fn run_batch(
    dir: &Path,
    first: u64,
    count: u64,
    timeout: Duration,
    trace: bool,
) -> Result<(), String> {
    let mut command = Command::new(fuzzer());
    if trace {
        command.env("ROTOR_FUZZ_TRACE", "1");
    }
    let mut child = command
        .arg(dir)
        .arg(first.to_string())
        .arg(count.to_string())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let last_seed = Arc::new(Mutex::new(None::<u64>));
    let stdout = child.stdout.take().unwrap();
    let seen = Arc::clone(&last_seed);
    let reader = std::thread::spawn(move || {
        for line in BufReader::new(stdout).lines().map_while(Result::ok) {
            if let Some(s) = line.strip_prefix("seed ").and_then(|s| s.parse().ok()) {
                *seen.lock().unwrap() = Some(s);
            }
        }
    });
    let stderr = child.stderr.take().unwrap();
    let errors = std::thread::spawn(move || {
        let mut text = String::new();
        for line in BufReader::new(stderr).lines().map_while(Result::ok) {
            text.push_str(&line);
            text.push('\n');
        }
        text
    });
    let start = Instant::now();
    let status = loop {
        if let Some(status) = child.try_wait().unwrap() {
            break Some(status);
        }
        if start.elapsed() > timeout {
            let _ = child.kill();
            let _ = child.wait();
            break None;
        }
        std::thread::sleep(Duration::from_millis(20));
    };
    reader.join().unwrap();
    let stderr = errors.join().unwrap();
    let seed = *last_seed.lock().unwrap();
    let replay = |s: Option<u64>| {
        format!(
            "replay: {} {} {} 1",
            fuzzer().display(),
            dir.display(),
            s.map_or("?".into(), |s| s.to_string())
        )
    };
    let tail: Vec<&str> = stderr.lines().rev().take(30).collect();
    let tail: Vec<&str> = tail.into_iter().rev().collect();
    match status {
        None if !trace && seed.is_some() => {
            // Run the seed alone, printing each call, to show where it hangs.
            let seed = seed.unwrap();
            let traced = run_batch(dir, seed, 1, Duration::from_secs(10), true);
            Err(format!(
                "hang: seeds {first}..{} did not finish in {timeout:?}, stuck in seed {seed}\n{}",
                first + count,
                traced
                    .err()
                    .unwrap_or_else(|| "(the seed alone finished)".into())
            ))
        }
        None => Err(format!(
            "hang in seed {seed:?} after {timeout:?}; last calls:\n{}\n{}",
            tail.join("\n"),
            replay(seed)
        )),
        Some(s) if s.success() => Ok(()),
        Some(s) => Err(format!("{s} at seed {seed:?}\n{stderr}\n{}", replay(seed))),
    }
}

#[test]
fn random_call_sequences_on_every_shipped_fmu() {
    let shipped = env_u64("ROTOR_FUZZ_SEQUENCES", 2000);
    // The FMU with every input kind (torques, ports, forces, the pull's
    // excitation) gets more.
    let inputs = env_u64("ROTOR_FUZZ_INPUT_SEQUENCES", 5000);
    let first = env_u64("ROTOR_FUZZ_SEED", 1);
    let batch = 250;
    let mut failures = Vec::new();
    for fmu in shipped_fmus() {
        let dir = unpack(&fmu);
        // An FMU that carries finite-film force tables (the compressor)
        // prepares them at every instantiation (a library loaded afresh
        // keeps none): 400 times another FMU's sequence, nearly all of it in
        // the tables' preparation (a profile): a tenth of the sequences,
        // at least 100. Its calls and states are every FMU's; what is its
        // own, the tables in its resources, each sequence reads.
        let sequences = if fmu.ends_with("torque_ports.fmu") {
            inputs
        } else if dir.join("resources/film_tables").is_dir() {
            (shipped / 10).max(100)
        } else {
            shipped
        };
        eprintln!(
            "fuzzing {}: seeds {first}..{}",
            fmu.display(),
            first + sequences
        );
        let mut seed = first;
        while seed < first + sequences {
            let count = batch.min(first + sequences - seed);
            // Generous: a sequence takes milliseconds; a hang takes forever.
            let timeout = Duration::from_secs(30 + count / 2);
            if let Err(e) = run_batch(&dir, seed, count, timeout, false) {
                failures.push(format!("{}: {e}", fmu.display()));
                break;
            }
            seed += count;
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n\n"));
}
