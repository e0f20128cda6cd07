//! The rotor-bearing FMU coupled to a governor/turbine/generator FMU (pythonfmu)
//! by libcosim (libcosimpy): start-up and load rejection checked for physics.
//! Needs the venv and out/HydroPlant.fmu (scripts/test.sh builds them).

use std::path::PathBuf;
use std::process::Command;

#[test]
fn coupled_plant_and_rotor_behave_physically() {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    let python = root.join(".venv/bin/python");
    assert!(
        python.exists(),
        "{} missing: run scripts/python_env.sh",
        python.display()
    );
    assert!(
        root.join("out/HydroPlant.fmu").exists(),
        "out/HydroPlant.fmu missing: scripts/test.sh builds it"
    );
    let out = Command::new(python)
        .arg(root.join("system/test_coupled.py"))
        .arg(&root)
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&out.stdout);
    eprintln!("{stdout}");
    assert!(
        out.status.success(),
        "coupled-system checks failed:\n{stdout}\n{}",
        String::from_utf8_lossy(&out.stderr)
            .lines()
            .filter(|l| !l.contains("[debug]") && !l.contains("[info]"))
            .collect::<Vec<_>>()
            .join("\n")
    );
}
