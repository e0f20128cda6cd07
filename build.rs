//! Build script: tells Cargo which inputs outside `src/` the crate embeds.
//! The FMI interface is generated the other way round — `modelDescription.xml`
//! comes from the variable table in `src/fmi2/variables.rs`, and the test
//! `tests/fmu.rs` proves the file at the repo root is exactly that output.

fn main() {
    println!("cargo:rerun-if-changed=models/classic_disk_rotor.toml");
    println!("cargo:rerun-if-changed=modelDescription.xml");
}
