//! Build script. The FMI layer (FMU issue) will generate its value-reference
//! table from `modelDescription.xml` here; for now it only tells Cargo which
//! inputs outside `src/` the crate embeds.

fn main() {
    println!("cargo:rerun-if-changed=models/classic_disk_rotor.toml");
    println!("cargo:rerun-if-changed=modelDescription.xml");
}
