//! Packing: `fmu_pack.sh --platforms` packs what it is asked for and says so,
//! refuses an unknown platform by name, `--fmi 3` packs an FMI 3.0 FMU (the
//! FMI 3.0 platform folder and model description) and an unknown FMI version
//! is refused by name, and `scripts/fmu_binary_check.sh` (the
//! export and import checks of both binaries) passes a complete binary and
//! fails, naming the culprit, on a missing export or a non-system DLL. The
//! two-platform default FMUs are checked by tests/wine.rs.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

#[path = "common/fmi2_functions.rs"]
mod fmi2_functions;
use fmi2_functions::FMI2_CS_FUNCTIONS as FMI2_CS;

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("rotor_fmu_pack_{name}_{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

fn run(cmd: &mut Command) -> (Output, String) {
    let out = cmd.current_dir(root()).output().unwrap();
    let text = format!(
        "{}{}",
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    );
    (out, text)
}

fn check(lib: &Path) -> (Output, String) {
    run(Command::new("bash")
        .arg("scripts/fmu_binary_check.sh")
        .arg(lib))
}

/// A stub library exporting `names` (plus `extra` C code), built by `cc`.
fn stub(cc: &str, dir: &Path, file: &str, names: &[&str], extra: &str, libs: &[&str]) -> PathBuf {
    let mut c = String::new();
    for n in names {
        c.push_str(&format!("int {n}(void) {{ return 0; }}\n"));
    }
    c.push_str(extra);
    let src = dir.join(format!("{file}.c"));
    std::fs::write(&src, c).unwrap();
    let lib = dir.join(file);
    let (out, text) = run(Command::new(cc)
        .args(["-shared", "-fPIC", "-o"])
        .arg(&lib)
        .arg(&src)
        .args(libs));
    assert!(out.status.success(), "{cc}: {text}");
    lib
}

#[test]
fn the_binary_check_passes_complete_binaries_and_names_what_is_wrong() {
    let dir = scratch("check");
    let so = stub("cc", &dir, "full.so", &FMI2_CS, "", &[]);
    let (out, text) = check(&so);
    assert!(out.status.success(), "{text}");
    assert!(text.contains("34 fmi2 functions exported"), "{text}");

    // Each of the 34 is required: without it the check fails and names it.
    for (i, left_out) in FMI2_CS.iter().enumerate() {
        let names: Vec<&str> = [&FMI2_CS[..i], &FMI2_CS[i + 1..]].concat();
        let short = stub("cc", &dir, "short.so", &names, "", &[]);
        let (out, text) = check(&short);
        assert_eq!(out.status.code(), Some(1), "{text}");
        assert!(
            text.trim_end()
                .ends_with(&format!("does not export {left_out}")),
            "{text}"
        );
    }

    let mingw = "x86_64-w64-mingw32-gcc-posix";
    let dll = stub(mingw, &dir, "full.dll", &FMI2_CS, "", &[]);
    let (out, text) = check(&dll);
    assert!(out.status.success(), "{text}");
    assert!(
        text.contains("system DLLs imported only (KERNEL32.dll"),
        "{text}"
    );

    // The MinGW runtime's pthread DLL is on no user's Windows.
    let pthread = "#include <pthread.h>\nunsigned long long self_id(void) { return (unsigned long long)pthread_self(); }\n";
    let foreign = stub(
        mingw,
        &dir,
        "foreign.dll",
        &FMI2_CS,
        pthread,
        &["-l:libwinpthread.dll.a"],
    );
    let (out, text) = check(&foreign);
    assert_eq!(out.status.code(), Some(1), "{text}");
    assert!(
        text.contains("imports DLLs that are not part of Windows: libwinpthread-1.dll"),
        "{text}"
    );
    // With --fmi 3 the 75 functions of fmi3Functions.h are required: the
    // FMI 2.0 stub lacks them.
    let (out, text) = run(Command::new("bash")
        .args(["scripts/fmu_binary_check.sh", "--fmi", "3"])
        .arg(&so));
    assert_eq!(out.status.code(), Some(1), "{text}");
    assert!(text.contains("does not export fmi3"), "{text}");
    let (out, text) = check(&dir.join("full.c"));
    assert_eq!(out.status.code(), Some(2), "{text}");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn platforms_packs_what_it_is_asked_for_and_refuses_unknown_ones() {
    let dir = scratch("platforms");
    let fmu = dir.join("jeffcott_linux64.fmu");
    let (out, text) = run(Command::new("bash").args([
        "fmu_pack.sh",
        "--model",
        "models/jeffcott.toml",
        "--platforms",
        "linux64",
        "--out",
        fmu.to_str().unwrap(),
    ]));
    assert!(out.status.success(), "{text}");
    assert!(
        text.contains("for linux64 only (--platforms linux64), FMPy validation passed"),
        "{text}"
    );
    let (out, list) = run(Command::new("unzip").arg("-l").arg(&fmu));
    assert!(out.status.success(), "{list}");
    assert!(list.contains("binaries/linux64/RotorBearing.so"), "{list}");
    assert!(!list.contains("binaries/win64"), "{list}");

    // FMI 3.0: the same library under the FMI 3.0 platform folder, with the
    // FMI 3.0 model description; an unknown version is refused by name.
    let fmu3 = dir.join("jeffcott_3.fmu");
    let (out, text) = run(Command::new("bash").args([
        "fmu_pack.sh",
        "--model",
        "models/jeffcott.toml",
        "--platforms",
        "linux64",
        "--fmi",
        "3",
        "--out",
        fmu3.to_str().unwrap(),
    ]));
    assert!(out.status.success(), "{text}");
    assert!(text.contains("FMI 3.0, instantiationToken {"), "{text}");
    assert!(text.contains("75 fmi3 functions exported"), "{text}");
    let (out, list) = run(Command::new("unzip").arg("-l").arg(&fmu3));
    assert!(out.status.success(), "{list}");
    assert!(
        list.contains("binaries/x86_64-linux/RotorBearing.so"),
        "{list}"
    );
    assert!(!list.contains("binaries/linux64"), "{list}");
    let (out, xml) = run(Command::new("unzip")
        .args(["-p"])
        .arg(&fmu3)
        .arg("modelDescription.xml"));
    assert!(out.status.success(), "{xml}");
    assert!(xml.contains("fmiVersion=\"3.0\""), "{xml}");
    let (out, text) = run(Command::new("bash").args([
        "fmu_pack.sh",
        "--fmi",
        "2,4",
        "--out",
        dir.join("x.fmu").to_str().unwrap(),
    ]));
    assert_eq!(out.status.code(), Some(2), "{text}");
    assert!(text.contains("unknown FMI version \"4\""), "{text}");

    for (platforms, named) in [("linux64,mac64", "\"mac64\""), ("", "no platform")] {
        let (out, text) = run(Command::new("bash").args([
            "fmu_pack.sh",
            "--platforms",
            platforms,
            "--out",
            dir.join("x.fmu").to_str().unwrap(),
        ]));
        assert_eq!(out.status.code(), Some(2), "{platforms}: {text}");
        assert!(text.contains(named), "{platforms}: {text}");
        assert!(!dir.join("x.fmu").exists());
    }
    let _ = std::fs::remove_dir_all(&dir);
}
