//! The win64 binary of every packed FMU under Wine against its linux64 binary
//! (tests/python/test_wine.py): FMPy simulations through the DLL equal the
//! linux64 run to 1e-9 relative (the oil whirl to three times its own
//! round-off amplification), FMU states round-trip through both binaries
//! and between them, and the math-library differences behind the last bits.
//! Needs the two-platform FMUs in out/ (scripts/test.sh packs them) and the
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
