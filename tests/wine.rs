//! The win64 binary of every packed FMU under Wine against its linux64 binary
//! (tests/python/test_wine.py): FMPy simulations through the DLL equal the
//! linux64 run to 1e-9 relative (the oil whirl to three times its own
//! round-off amplification), FMU states round-trip through both binaries
//! and between them, and the math-library differences behind the last bits;
//! the FMI 3.0 FMUs' win64 binary equals their linux64 binary to the same
//! policy (tests/python/test_wine_fmi3.py). Needs the two-platform FMUs in out/ (scripts/test.sh packs them) and the
//! cross toolchain and Wine prefix of scripts/setup.sh.

mod common;

#[test]
fn the_win64_binary_under_wine_equals_linux64() {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    common::run_python(
        "tests/python/test_wine.py",
        &[root],
        &["out/RotorBearing.fmu"],
    );
}

/// The FMI 3.0 FMUs' win64 binary under Wine against their linux64 binary
/// (tests/python/test_wine_fmi3.py): FMPy's remoting serves FMI 2.0 only, so
/// one C importer (tests/wine/fmi3_run.c) built for both platforms runs the
/// same runs as the FMI 2.0 test, to the same tolerance policy.
#[test]
fn the_win64_fmi3_binary_under_wine_equals_linux64() {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    common::run_python(
        "tests/python/test_wine_fmi3.py",
        &[root],
        &["out/RotorBearing_fmi3.fmu"],
    );
}
