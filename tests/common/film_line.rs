//! The rotor on three plain (short-film) bearings of `tests/alignment.rs`,
//! shared by the alignment stability tests.

use rotor_bearing::model::RotorModel;
use rotor_bearing::rotor::Rotor;

/// The line of `tests/alignment.rs` (`film_line_with`, disks 30 and 45 kg):
/// 1.2 m × 60 mm steel shaft in 12 elements, disks at 0.3 and 0.9 m, three
/// plain bearings R = L = 30 mm, C = 80 µm, 0.02 Pa·s at 0, 0.6 and 1.2 m,
/// the middle one at elevation `middle` (m): its model text.
#[allow(dead_code)] // each test takes what it needs
pub fn text(middle: f64) -> String {
    let bearing = |name: &str, node: usize, o: f64| {
        format!(
            "[[bearings]]\nname = \"{name}\"\ntype = \"plain\"\nnode = {node}\nradius = 0.03\nlength = 0.03\nclearance = 80e-6\nviscosity = 0.02\noffset_y = {o:e}\n"
        )
    };
    let disk = |node: usize, mass: f64| {
        format!(
            "[[disks]]\nnode = {node}\nmass = {mass:?}\npolar_inertia = 0.2\ndiametral_inertia = 0.1\n"
        )
    };
    format!(
        "name = \"film3\"\ngravity = [0.0, -9.81, 0.0]\n[[materials]]\nname = \"steel\"\nyoungs_modulus = 211e9\npoisson_ratio = 0.3\ndensity = 7810.0\n[[shaft]]\nlength = 1.2\nouter_diameter = 0.06\nmaterial = \"steel\"\nelements = 12\n{}{}{}{}{}",
        disk(4, 30.0),
        disk(10, 45.0),
        bearing("left", 1, 0.0),
        bearing("middle", 7, middle),
        bearing("right", 13, 0.0)
    )
}

/// That line, built.
#[allow(dead_code)] // each test takes what it needs
pub fn line(middle: f64) -> Rotor {
    Rotor::new(RotorModel::from_toml(&text(middle), "film3.toml").unwrap()).unwrap()
}
