//! Fuzzing of the FMI 3.0 FMUs' C API (issue 50): random call sequences (see
//! `examples/fmu3_fuzz.rs` for what each checks) of the Jeffcott rotor (whose
//! rub sequences return early), the hydro unit and the torque-driven hydro
//! unit, run in a child process with a timeout so that a crash or a hang fails
//! the test. `ROTOR_FUZZ3_SEQUENCES` sets the sequences per FMU (default
//! 2000). A failing seed replays with
//! `target/debug/examples/fmu3_fuzz DIR SEED 1` (`ROTOR_FUZZ_TRACE=1` prints
//! the calls).

use std::io::Read;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// Unpack `fmu` (a zip) into a fresh folder, as an importer does.
fn unpack(fmu: &Path) -> PathBuf {
    let name = fmu.file_stem().unwrap().to_string_lossy().into_owned();
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join(format!("fuzz3_{name}"));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let status = Command::new(root().join(".venv/bin/python"))
        .args(["-m", "zipfile", "-e"])
        .arg(fmu)
        .arg(&dir)
        .status()
        .expect(".venv/bin/python (run scripts/python_env.sh)");
    assert!(status.success(), "unpacking {} failed", fmu.display());
    dir
}

#[test]
fn random_fmi3_call_sequences_neither_crash_nor_break_the_rules() {
    let exe = std::env::current_exe().unwrap();
    let fuzzer = exe
        .parent()
        .unwrap()
        .parent()
        .unwrap()
        .join("examples/fmu3_fuzz");
    assert!(
        fuzzer.exists(),
        "{}: cargo build --examples",
        fuzzer.display()
    );
    let count: u64 = std::env::var("ROTOR_FUZZ3_SEQUENCES")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(2000);
    for stem in ["jeffcott", "RotorBearing", "hydro_unit_torque"] {
        let fmu = root().join(format!("out/{stem}_fmi3.fmu"));
        assert!(fmu.exists(), "{}: scripts/test.sh packs it", fmu.display());
        let dir = unpack(&fmu);
        let mut child = Command::new(&fuzzer)
            .arg(&dir)
            .arg("1")
            .arg(count.to_string())
            .stdout(Stdio::piped())
            .stderr(Stdio::piped())
            .spawn()
            .unwrap();
        // Read both pipes while the child runs: a child that fills a pipe
        // the parent does not drain blocks (2000 sequences print ~80 kB).
        let drain = |pipe: Option<Box<dyn Read + Send>>| {
            std::thread::spawn(move || {
                let mut text = String::new();
                if let Some(mut pipe) = pipe {
                    let _ = pipe.read_to_string(&mut text);
                }
                text
            })
        };
        let stdout = drain(child.stdout.take().map(|p| Box::new(p) as _));
        let stderr = drain(child.stderr.take().map(|p| Box::new(p) as _));
        let start = Instant::now();
        let status = loop {
            if let Some(status) = child.try_wait().unwrap() {
                break status;
            }
            if start.elapsed() > Duration::from_secs(600) {
                let _ = child.kill();
                let _ = child.wait();
                panic!("{stem}: the fuzzer hangs (over 600 s)");
            }
            std::thread::sleep(Duration::from_millis(20));
        };
        let (stdout, stderr) = (stdout.join().unwrap(), stderr.join().unwrap());
        assert!(
            status.success(),
            "{stem}: {} (last: {:?})\n{stderr}",
            status,
            stdout.lines().rev().find(|l| l.starts_with("seed"))
        );
        let (mut steps, mut early, mut updates) = (0usize, 0usize, 0usize);
        for line in stdout.lines() {
            let words: Vec<&str> = line.split_whitespace().collect();
            if let ["steps", s, "early", e, "updates", u] = words.as_slice() {
                steps += s.parse::<usize>().unwrap();
                early += e.parse::<usize>().unwrap();
                updates += u.parse::<usize>().unwrap();
            }
        }
        eprintln!(
            "{stem}: {count} sequences, {steps} steps, {early} early returns, {updates} intermediate updates, no violation"
        );
        // The sequences reach Step Mode and step, half of them with
        // intermediate updates; the Jeffcott rub returns early.
        assert!(steps > count as usize, "{stem}: only {steps} steps");
        assert!(
            updates > count as usize,
            "{stem}: only {updates} intermediate updates"
        );
        if stem == "jeffcott" {
            assert!(early > 0, "no early return among the Jeffcott rubs");
        }
    }
}
