//! The FMU binary under valgrind's memcheck: no invalid reads or writes, no use
//! of uninitialized memory, through instantiation, steps, FMU states, error
//! paths and freeing (examples/fmu_smoke.rs drives it).

use std::path::PathBuf;
use std::process::Command;

#[test]
fn fmu_runs_clean_under_valgrind() {
    let exe = std::env::current_exe().unwrap();
    let profile = exe.parent().unwrap().parent().unwrap();
    let smoke = profile.join("examples/fmu_smoke");
    let lib = profile.join("librotor_bearing.so");
    assert!(
        smoke.exists() && lib.exists(),
        "build the library and examples first (scripts/test.sh)"
    );
    let resources = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("valgrind_resources");
    std::fs::create_dir_all(&resources).unwrap();
    std::fs::copy(
        PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("models/jeffcott.toml"),
        resources.join("model.toml"),
    )
    .unwrap();
    let out = Command::new("valgrind")
        .args([
            "--error-exitcode=99",
            "--errors-for-leak-kinds=none",
            "--quiet",
        ])
        .arg(&smoke)
        .arg(&lib)
        .arg(&resources)
        .output()
        .expect("valgrind is installed by scripts/setup.sh");
    let stderr = String::from_utf8_lossy(&out.stderr);
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(
        out.status.success(),
        "valgrind reported errors (exit {:?}):\n{stderr}\n{stdout}",
        out.status.code()
    );
    assert!(stdout.contains("fmu_smoke: ok"), "{stdout}");
}
