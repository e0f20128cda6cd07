//! The FMI Cross-Check layout (issue 50): `scripts/cross_check.sh` writes the
//! FMI 2.0 and FMI 3.0 layout of one shipped model (FMU, input file, reference
//! at a finer step, options) and FMPy's cross-check validator accepts both and
//! passes FMPy's result against the reference by the rule (fewer than 10 % of
//! the samples outside ±10 % of the reference's range). The validator is live:
//! a reference scaled by 1.5 fails the rule, an options file without `RelTol`
//! is reported. Needs out/jeffcott.fmu and out/jeffcott_fmi3.fmu
//! (scripts/test.sh packs them).

use std::path::PathBuf;
use std::process::Command;

#[test]
fn the_cross_check_layout_validates_and_passes_for_fmi2_and_fmi3() {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    for need in [
        "out/jeffcott.fmu",
        "out/jeffcott_fmi3.fmu",
        ".venv/bin/python",
    ] {
        assert!(
            root.join(need).exists(),
            "{need} missing: scripts/test.sh builds it"
        );
    }
    let dest = std::env::temp_dir().join(format!("rotor_cross_check_{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dest);
    let out = Command::new("bash")
        .arg(root.join("scripts/cross_check.sh"))
        .arg(&dest)
        .arg("jeffcott")
        .current_dir(&root)
        .output()
        .unwrap();
    let text = String::from_utf8_lossy(&out.stdout).into_owned();
    assert!(
        out.status.success(),
        "{text}{}",
        String::from_utf8_lossy(&out.stderr)
    );
    for (version, platform) in [("2.0", "linux64"), ("3.0", "x86_64-linux")] {
        assert!(
            text.contains(&format!(
                "jeffcott FMI {version}: {}",
                dest.join(format!("fmus/{version}/cs/{platform}/RotorBearing"))
                    .display()
            )),
            "{text}"
        );
        let dir = dest.join(format!(
            "fmus/{version}/cs/{platform}/RotorBearing/{}/jeffcott",
            env!("CARGO_PKG_VERSION")
        ));
        for file in [
            "jeffcott.fmu",
            "jeffcott_in.csv",
            "jeffcott_ref.csv",
            "jeffcott_ref.opt",
        ] {
            assert!(dir.join(file).exists(), "{}", dir.join(file).display());
        }
    }
    assert_eq!(
        text.matches("layout valid, FMPy result passes the cross-check rule")
            .count(),
        2,
        "{text}"
    );

    // The validator is live: a reference 1.5 times the result fails the
    // rule, an options file without RelTol is a problem.
    let dir = dest.join(format!(
        "fmus/3.0/cs/x86_64-linux/RotorBearing/{}/jeffcott",
        env!("CARGO_PKG_VERSION")
    ));
    let probe = r#"
import sys, numpy as np
from fmpy.cross_check import validate_result
from fmpy.cross_check.validate_vendor_repo import read_csv, validate_test_fmu
d = sys.argv[1]
ref = read_csv(d + "/jeffcott_ref.csv")
res = ref.copy()
name = "bearings.left.fy"
res[name] = 1.5 * ref[name]
print("scaled:", validate_result(res, ref, 0.0, 0.5))
print("same:", validate_result(ref, ref, 0.0, 0.5))
open(d + "/jeffcott_ref.opt", "w").write("StartTime, 0.0\nStopTime, 0.5\nStepSize, 0.01\n")
print("opt:", validate_test_fmu(d))
"#;
    let out = Command::new(root.join(".venv/bin/python"))
        .args(["-W", "ignore", "-c", probe])
        .arg(&dir)
        .output()
        .unwrap();
    let text = String::from_utf8_lossy(&out.stdout).into_owned();
    assert!(
        out.status.success(),
        "{text}{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(
        text.contains("scaled: More than 10% of the samples outside epsilon band for variable \"bearings.left.fy\""),
        "{text}"
    );
    assert!(text.contains("same: None"), "{text}");
    assert!(text.contains("Missing element 'RelTol'"), "{text}");
    let _ = std::fs::remove_dir_all(&dest);
}
