//! The Dask sweep tool (system/sweep.py): a 2-worker LocalCluster gives exactly
//! the serial numbers, and a failing point is reported in the table.

mod common;

#[test]
fn dask_sweep_matches_serial_and_reports_failures() {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    common::run_python(
        "system/test_sweep.py",
        &[root],
        &["out/jeffcott.fmu", "target/release/rotor"],
    );
}
