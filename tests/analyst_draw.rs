//! `rotor draw`: a side view of every shipped model; slender rotors are drawn
//! with a stated radial exaggeration.

use std::path::PathBuf;
use std::process::Command;

use rotor_bearing::model::RotorModel;
use rotor_bearing::plot::radial_exaggeration;

fn png_size(bytes: &[u8]) -> (u32, u32) {
    assert_eq!(&bytes[..8], b"\x89PNG\r\n\x1a\n");
    let be = |i: usize| u32::from_be_bytes([bytes[i], bytes[i + 1], bytes[i + 2], bytes[i + 3]]);
    (be(16), be(20))
}

#[test]
fn every_shipped_model_is_drawn() {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("draw");
    std::fs::create_dir_all(&dir).unwrap();
    let models = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("models");
    for entry in std::fs::read_dir(models).unwrap() {
        let path = entry.unwrap().path();
        let png = dir.join(path.file_stem().unwrap()).with_extension("png");
        let out = Command::new(env!("CARGO_BIN_EXE_rotor"))
            .arg("draw")
            .arg(&path)
            .arg("--png")
            .arg(&png)
            .output()
            .unwrap();
        assert!(
            out.status.success(),
            "{}: {}",
            path.display(),
            String::from_utf8_lossy(&out.stderr)
        );
        let bytes = std::fs::read(&png).unwrap();
        let (w, h) = png_size(&bytes);
        assert_eq!(w, 1400);
        assert!((300..=1400).contains(&h), "{}: height {h}", path.display());
        assert!(
            bytes.len() > 15_000,
            "{}: {} bytes",
            path.display(),
            bytes.len()
        );
    }
}

#[test]
fn slender_rotors_are_exaggerated_radially_and_say_so() {
    // The classic rotor: a 280 mm disk on 1.5 m, thicker than a tenth: to scale.
    assert_eq!(radial_exaggeration(&RotorModel::default_model()), 1.0);
    // A 10 mm shaft of 1 m: drawn ten times thicker (to a tenth of its length).
    let text = r#"name = "needle"
[[materials]]
name = "steel"
youngs_modulus = 2e11
poisson_ratio = 0.3
density = 7800.0
[[shaft]]
length = 1.0
outer_diameter = 0.01
material = "steel"
elements = 4
[[bearings]]
type = "linear"
node = 1
kxx = 1e6
kyy = 1e6
"#;
    let model = RotorModel::from_toml(text, "needle.toml").unwrap();
    assert!((radial_exaggeration(&model) - 10.0).abs() < 1e-12);
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("draw_needle");
    std::fs::create_dir_all(&dir).unwrap();
    let (path, png) = (dir.join("needle.toml"), dir.join("needle.png"));
    std::fs::write(&path, text).unwrap();
    let out = Command::new(env!("CARGO_BIN_EXE_rotor"))
        .arg("draw")
        .arg(&path)
        .arg("--png")
        .arg(&png)
        .output()
        .unwrap();
    assert!(String::from_utf8_lossy(&out.stdout).contains("radial scale exaggerated ×10.0"));
}

/// A rub element is drawn (as a stator ring), so the picture of a model with a
/// `[[rubs]]` entry differs from the same model without it.
#[test]
fn rub_elements_are_drawn() {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("draw_rub");
    std::fs::create_dir_all(&dir).unwrap();
    let base = std::fs::read_to_string(
        PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("models/jeffcott.toml"),
    )
    .unwrap();
    let with_rub = format!("{base}\n[[rubs]]\nname = \"seal\"\nnode = 3\ngap = 2e-4\n");
    let mut pictures = Vec::new();
    for (stem, text) in [("plain", base), ("rub", with_rub)] {
        let (toml, png) = (
            dir.join(format!("{stem}.toml")),
            dir.join(format!("{stem}.png")),
        );
        std::fs::write(&toml, text).unwrap();
        let out = Command::new(env!("CARGO_BIN_EXE_rotor"))
            .arg("draw")
            .arg(&toml)
            .arg("--png")
            .arg(&png)
            .output()
            .unwrap();
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        pictures.push(std::fs::read(&png).unwrap());
    }
    assert_ne!(pictures[0], pictures[1]);
}
