//! Absurd sizes (issue 22): every length, diameter, mass, inertia, modulus and
//! stiffness of a model file lies in a stated physical range, and a value
//! outside is refused with the file, line, field, value and range; a model
//! whose every size is valid but that as a whole looks drawn in millimetres is
//! warned about; the FMU refuses such a model at instantiation.

use rotor_bearing::model::limits::{self, Limit};
use rotor_bearing::model::{DEFAULT_MODEL_TOML, RotorModel};

/// The Jeffcott rotor with a rub and a disk given by its geometry, so that
/// every bounded key appears once.
fn base() -> String {
    let text =
        std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/models/jeffcott.toml"))
            .unwrap();
    format!(
        "{text}\n[[disks]]\nname = \"ring\"\nnode = 3\nmaterial = \"steel\"\nouter_diameter = 0.3\n\
         inner_diameter = 0.04\nwidth = 0.02\n[[rubs]]\nname = \"seal\"\nnode = 4\ngap = 2e-4\n\
         radius = 0.02\ncontact_stiffness = 1e9\ncontact_damping = 1e4\n"
    )
}

/// `text` with the `n`-th (0-based) line `key = …` set to `value`.
fn with(text: &str, key: &str, n: usize, value: &str) -> (String, usize) {
    let mut seen = 0;
    let mut line = 0;
    let out: Vec<String> = text
        .lines()
        .enumerate()
        .map(|(i, l)| {
            let is_key = l.split('=').next().is_some_and(|k| k.trim() == key);
            if is_key {
                seen += 1;
                if seen == n + 1 {
                    line = i + 1;
                    return format!("{key} = {value}");
                }
            }
            l.to_string()
        })
        .collect();
    assert!(line > 0, "no line {key} #{n}");
    (out.join("\n"), line)
}

/// Each bounded field: its key, which occurrence in [`base`], its field path and range.
const FIELDS: [(&str, usize, &str, Limit); 18] = [
    (
        "youngs_modulus",
        0,
        "materials[0].youngs_modulus",
        limits::MODULUS,
    ),
    ("density", 0, "materials[0].density", limits::DENSITY),
    ("length", 0, "shaft[0].length", limits::LENGTH),
    (
        "outer_diameter",
        0,
        "shaft[0].outer_diameter",
        limits::DIAMETER,
    ),
    ("mass", 0, "disks[0].mass", limits::MASS),
    (
        "polar_inertia",
        0,
        "disks[0].polar_inertia",
        limits::INERTIA,
    ),
    (
        "diametral_inertia",
        0,
        "disks[0].diametral_inertia",
        limits::INERTIA,
    ),
    (
        "outer_diameter",
        1,
        "disks[1].outer_diameter",
        limits::DIAMETER,
    ),
    ("width", 0, "disks[1].width", limits::LENGTH),
    ("radius", 0, "bearings[0].radius", limits::RADIUS),
    ("length", 1, "bearings[0].length", limits::LENGTH),
    ("clearance", 0, "bearings[0].clearance", limits::CLEARANCE),
    ("viscosity", 0, "bearings[0].viscosity", limits::VISCOSITY),
    ("gap", 0, "rubs[0].gap", limits::CLEARANCE),
    ("radius", 2, "rubs[0].radius", limits::RADIUS),
    (
        "contact_stiffness",
        0,
        "rubs[0].contact_stiffness",
        limits::CONTACT_STIFFNESS,
    ),
    (
        "contact_damping",
        0,
        "rubs[0].contact_damping",
        limits::DAMPING,
    ),
    ("magnitude", 0, "unbalance[0].magnitude", limits::UNBALANCE),
];

/// Every bounded field refuses a value just beyond each end of its range (and
/// 1e300) with file, line, field, value and the range; the ends themselves
/// pass that check. (Issue 22: a shaft diameter or disk width of 1e300 m was
/// accepted and `rotor static` printed NaN.)
#[test]
fn every_size_is_bounded_with_field_file_line_value_and_range() {
    let text = base();
    assert!(RotorModel::from_toml(&text, "m.toml").is_ok());
    for (key, n, field, limit) in FIELDS {
        for value in [limit.max * 1.01, 1e300, limit.min * 0.99 - 1e-300] {
            if value <= 0.0 && limit.min <= 0.0 {
                continue;
            }
            let shown = format!("{value:e}");
            let (mutant, line) = with(&text, key, n, &shown);
            let e = RotorModel::from_toml(&mutant, "m.toml")
                .err()
                .unwrap_or_else(|| panic!("{field} = {shown} accepted"))
                .to_string();
            let short = rotor_bearing::units::Short(value).to_string();
            assert!(
                e.starts_with(&format!("m.toml:{line}: {field} = {short}: must lie in [")),
                "{field} = {shown}: {e}"
            );
            assert!(e.contains(limit.unit) && e.len() < 300, "{e}");
        }
    }
    // Gravity and the largest speed, on the default model.
    for (key, value, field) in [
        (
            "gravity",
            "[0.0, -1e4, 0.0]",
            "gravity[1] = -10000: must lie in [-1000, 1000] m/s²",
        ),
        (
            "max_speed_rpm",
            "1e300",
            "max_speed_rpm = 1e300: must lie in [0.001, 10000000] rpm",
        ),
    ] {
        let default = DEFAULT_MODEL_TOML.replace("gravity =", "# gravity =");
        let mutant = format!("{key} = {value}\n{default}");
        let e = RotorModel::from_toml(&mutant, "d.toml")
            .unwrap_err()
            .to_string();
        assert!(e.starts_with(&format!("d.toml:1: {field}")), "{e}");
    }
}

/// A bearing's `diametral_clearance` (issue 27) lies in twice the radial
/// clearance's range: just beyond either end, and 1e300, refused with file,
/// line, field, value and range; the ends themselves pass that check.
#[test]
fn the_diametral_clearance_is_bounded_like_the_radial_one() {
    let (text, _) = with(&base(), "clearance", 0, "100e-6");
    let text = text.replacen("clearance = 100e-6", "diametral_clearance = 200e-6", 1);
    assert!(RotorModel::from_toml(&text, "m.toml").is_ok());
    let limit = limits::DIAMETRAL_CLEARANCE;
    assert_eq!(
        (limit.min, limit.max),
        (2.0 * limits::CLEARANCE.min, 2.0 * limits::CLEARANCE.max)
    );
    for value in [limit.max * 1.01, 1e300, limit.min * 0.99] {
        let shown = format!("{value:e}");
        let (mutant, line) = with(&text, "diametral_clearance", 0, &shown);
        let e = RotorModel::from_toml(&mutant, "m.toml")
            .err()
            .unwrap_or_else(|| panic!("diametral_clearance = {shown} accepted"))
            .to_string();
        let short = rotor_bearing::units::Short(value).to_string();
        assert!(
            e.starts_with(&format!(
                "m.toml:{line}: bearings[0].diametral_clearance = {short}: must lie in [2e-7, 2] m"
            )),
            "{e}"
        );
    }
}

/// Idealizations the test suite and users rely on stay inside the ranges: a
/// "rigid" shaft (E = 2e15 Pa), a "massless" one (1e-6 kg/m³), a 4 000 t
/// generator rotor with 4.5e6 kg·m² of polar inertia, a 1 µm gas-bearing
/// clearance.
#[test]
fn idealizations_and_large_machines_fit() {
    let text = base();
    for (key, n, value) in [
        ("youngs_modulus", 0, "2e15"),
        ("density", 0, "1e-6"),
        ("mass", 0, "4e6"),
        ("polar_inertia", 0, "4.5e6"),
        ("clearance", 0, "1e-6"),
    ] {
        let (mutant, _) = with(&text, key, n, value);
        RotorModel::from_toml(&mutant, "m.toml").unwrap_or_else(|e| panic!("{key} = {value}: {e}"));
    }
}

/// A model whose every length is in millimetres passes field by field, but
/// its rotating mass, shaft length and shaft diameter are no machine: one
/// warning each, naming the file and the value (issue 22: 25 524 681.9 kg
/// were accepted silently). The shipped models get none.
#[test]
fn a_model_in_millimetres_is_warned_about() {
    let text =
        std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/models/jeffcott.toml"))
            .unwrap();
    let mm: String = text
        .lines()
        .map(|l| {
            let key = l.split('=').next().unwrap_or("").trim();
            match ["length", "outer_diameter", "radius", "clearance"].contains(&key) {
                true => {
                    let v: f64 = l
                        .split('=')
                        .nth(1)
                        .unwrap()
                        .split('#')
                        .next()
                        .unwrap()
                        .trim()
                        .parse()
                        .unwrap();
                    format!("{key} = {}", v * 1000.0)
                }
                false => l.to_string(),
            }
        })
        .collect::<Vec<_>>()
        .join("\n");
    let m = RotorModel::from_toml(&mm, "mm.toml").unwrap();
    let warnings: Vec<String> = m
        .plausibility_warnings()
        .iter()
        .map(|w| w.to_string())
        .collect();
    let mass = m.total_mass();
    assert!(mass > 1e9, "{mass}");
    for expected in [
        format!("mm.toml: rotating mass (shaft and disks, kg) = {mass}: above the 10000000 kg"),
        "mm.toml: shaft length (sum of shaft[*].length, m) = 500: longer than the 200 m"
            .to_string(),
        "mm.toml: shaft outer_diameter (element 1) = 40: thicker than the 10 m".to_string(),
    ] {
        assert!(
            warnings
                .iter()
                .any(|w| w.starts_with(&expected) && w.contains("millimetres")),
            "{expected}\n{warnings:#?}"
        );
    }
    assert_eq!(warnings.len(), 3, "{warnings:#?}");
    // The largest shipped machine stays below all three.
    let hydro = RotorModel::from_file(std::path::Path::new(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/models/hydro_unit.toml"
    )))
    .unwrap();
    assert!(hydro.plausibility_warnings().is_empty());
}

/// The FMU refuses a model with an absurd size at instantiation, naming the
/// field, instead of initializing and failing at the first output.
#[test]
fn the_fmu_refuses_an_absurd_model_at_instantiation() {
    let dir = std::env::temp_dir().join(format!("rotor_limits_{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let (mutant, line) = with(&base(), "width", 0, "1e300");
    std::fs::write(dir.join("model.toml"), mutant).unwrap();
    let uri = format!("file://{}", dir.display());
    let e = rotor_bearing::fmi2::resources::instantiate("i", "{any}", &uri).unwrap_err();
    assert!(
        e.contains(&format!(
            "model.toml:{line}: disks[1].width = 1e300: must lie in"
        )),
        "{e}"
    );
    std::fs::remove_dir_all(&dir).unwrap();
}
