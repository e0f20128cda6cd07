//! Model-file tests of the film bearings' plausibility: a plausible bearing
//! gives no warning; viscosity in centistokes, a radius in millimetres, a
//! diametral clearance and a clearance ratio out of range are warned or
//! refused with file, field, value and range; every shipped model is
//! plausible.

use super::RotorModel;
use super::tests::BASE;

/// The base model with a plain bearing at node 2 of the 0.05 m shaft
/// (radius 0.025 m) with the given radius, clearance and viscosity.
fn with_film_bearing(radius: f64, clearance: f64, viscosity: f64) -> RotorModel {
    let text = format!(
        "{BASE}\n[[bearings]]\nname = \"b\"\ntype = \"plain\"\nnode = 2\nradius = {radius:e}\n\
         length = 0.02\nclearance = {clearance:e}\nviscosity = {viscosity:e}\n"
    );
    RotorModel::from_toml(&text, "m.toml").unwrap()
}

#[test]
fn plausible_film_bearing_gives_no_warning() {
    assert!(
        with_film_bearing(0.025, 5e-5, 0.03)
            .plausibility_warnings()
            .is_empty()
    );
    // Within 1 % of the shaft radius, and the ends of both ranges.
    assert!(
        with_film_bearing(0.0252, 2.6e-6, 1e-4)
            .plausibility_warnings()
            .is_empty()
    );
    assert!(
        with_film_bearing(0.0248, 2.4e-4, 1.0)
            .plausibility_warnings()
            .is_empty()
    );
}

#[test]
fn viscosity_in_centistokes_is_warned_with_file_field_value_and_range() {
    for mu in [32.0, 5e-5] {
        let w = with_film_bearing(0.025, 5e-5, mu).plausibility_warnings();
        assert_eq!(w.len(), 1, "{w:?}");
        assert_eq!(
            (w[0].file.as_str(), w[0].field.as_str(), w[0].value),
            ("m.toml", "bearings[0].viscosity", mu)
        );
        let text = w[0].to_string();
        assert!(
            text.starts_with(&format!(
                "m.toml: bearings[0].viscosity = {}: ",
                crate::units::Short(mu)
            )) && text.contains("1e-4 to 1 Pa·s"),
            "{text}"
        );
    }
}

#[test]
fn bearing_radius_in_millimetres_is_refused_and_a_collar_is_declared() {
    // 25 (mm) next to the 0.025 m shaft radius: larger than the shaft, not
    // declared a collar — an error that names the key to declare it with.
    let text = |radius: f64, extra: &str| {
        format!(
            "{BASE}\n[[bearings]]\nname = \"b\"\ntype = \"plain\"\nnode = 2\nradius = {radius:e}\n\
             length = 0.02\nclearance = 5e-5\nviscosity = 0.03\n{extra}"
        )
    };
    let err = RotorModel::from_toml(&text(25.0, ""), "m.toml")
        .unwrap_err()
        .to_string();
    assert!(
        err.contains("bearings[0].radius = 25")
            && err.contains("larger than the shaft's outer radius 0.025 m at node 2")
            && err.contains("journal_collar = true"),
        "{err}"
    );
    // A declared collar of 40 mm on the 25 mm shaft: accepted, no warning.
    let m = RotorModel::from_toml(&text(0.04, "journal_collar = true\n"), "m.toml").unwrap();
    assert!(m.plausibility_warnings().is_empty());
    // Declared but not larger: refused.
    let err = RotorModel::from_toml(&text(0.025, "journal_collar = true\n"), "m.toml")
        .unwrap_err()
        .to_string();
    assert!(
        err.contains("bearings[0].journal_collar = true") && err.contains("no collar"),
        "{err}"
    );
    // 2 % larger, undeclared: refused; 2 % smaller: warned.
    assert!(RotorModel::from_toml(&text(0.0255, ""), "m.toml").is_err());
    let w = with_film_bearing(0.0245, 5e-5, 0.03).plausibility_warnings();
    assert_eq!(w.len(), 1, "{w:?}");
    assert_eq!(
        (w[0].field.as_str(), w[0].value),
        ("bearings[0].radius", 0.0245)
    );
    assert!(
        w[0].to_string()
            .contains("below the shaft radius at node 2 (0.025 m)")
            && w[0].to_string().contains("1 %"),
        "{}",
        w[0]
    );
    // The radius at a node between two sections matches either.
    let stepped = BASE.replace("length = 1.5", "length = 0.5")
        + "\n[[shaft]]\nlength = 1.0\nouter_diameter = 0.06\nmaterial = \"steel\"\nelements = 4\n\
           \n[[bearings]]\ntype = \"plain\"\nnode = 7\nradius = 0.03\nlength = 0.02\nclearance = 6e-5\nviscosity = 0.03\n";
    let m = RotorModel::from_toml(&stepped, "m.toml").unwrap();
    assert_eq!(m.elements[5].element.section.outer_diameter, 0.05);
    assert_eq!(m.elements[6].element.section.outer_diameter, 0.06);
    assert!(m.plausibility_warnings().is_empty());
}

#[test]
fn diametral_clearance_is_twice_the_radial_one() {
    let text = |keys: &str| {
        format!(
            "{BASE}\n[[bearings]]\nname = \"b\"\ntype = \"plain\"\nnode = 2\nradius = 0.025\n\
             length = 0.02\nviscosity = 0.03\n{keys}\n"
        )
    };
    let radial = RotorModel::from_toml(&text("clearance = 5e-5"), "m.toml").unwrap();
    let diametral = RotorModel::from_toml(&text("diametral_clearance = 1e-4"), "m.toml").unwrap();
    assert_eq!(radial.bearings, diametral.bearings);
    let both = RotorModel::from_toml(
        &text("clearance = 5e-5\ndiametral_clearance = 1e-4"),
        "m.toml",
    )
    .unwrap_err()
    .to_string();
    assert!(
        both.contains("bearings[0].diametral_clearance") && both.contains("not both"),
        "{both}"
    );
    let none = RotorModel::from_toml(&text(""), "m.toml")
        .unwrap_err()
        .to_string();
    assert!(
        none.contains("bearings[0].clearance = missing") && none.contains("diametral_clearance"),
        "{none}"
    );
    let bad = RotorModel::from_toml(&text("diametral_clearance = -1e-4"), "m.toml")
        .unwrap_err()
        .to_string();
    assert!(
        bad.contains("bearings[0].diametral_clearance = -0.0001"),
        "{bad}"
    );
    // Tilting pads take it too.
    let pads = |keys: &str| {
        format!(
            "{BASE}\n[[bearings]]\nname = \"t\"\ntype = \"tilting_pad\"\nnode = 2\nradius = 0.025\n\
             length = 0.02\nviscosity = 0.03\npads = 4\npad_arc_deg = 70.0\n{keys}\n"
        )
    };
    let a = RotorModel::from_toml(&pads("clearance = 5e-5"), "m.toml").unwrap();
    let b = RotorModel::from_toml(&pads("diametral_clearance = 1e-4"), "m.toml").unwrap();
    assert_eq!(a.bearings, b.bearings);
}

#[test]
fn clearance_ratio_outside_range_is_warned() {
    // Diametral clearance mistaken for radial would still pass; these do not.
    for (clearance, ratio) in [(1e-6, "4.000e-5"), (5e-4, "2.000e-2")] {
        let w = with_film_bearing(0.025, clearance, 0.03).plausibility_warnings();
        assert_eq!(w.len(), 1, "{w:?}");
        assert_eq!(
            (w[0].field.as_str(), w[0].value),
            ("bearings[0].clearance", clearance)
        );
        let text = w[0].to_string();
        assert!(
            text.contains(&format!("radial clearance / radius = {ratio}"))
                && text.contains("1e-4 to 1e-2"),
            "{text}"
        );
    }
}

#[test]
fn shipped_models_are_plausible() {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("models");
    let mut count = 0;
    for entry in std::fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        let m = RotorModel::from_file(&path).unwrap();
        assert!(
            m.plausibility_warnings().is_empty(),
            "{}: {:?}",
            path.display(),
            m.plausibility_warnings()
        );
        count += 1;
    }
    assert_eq!(count, 12);
}
