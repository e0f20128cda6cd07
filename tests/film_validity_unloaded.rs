//! The short-film warning on a nearly unloaded bearing (issue 47): the unit
//! on brackets (vertical, unpreloaded guide pads) with a 1 N side force on
//! its runner compares its films centred, as it does with none — the same
//! ratios bit for bit — instead of seeking a finite-film equilibrium under a
//! load of a millionth of the film's scale `μ Ω R L (R/C)²` (which took about
//! 200 times the CPU time the whole `rotor static` takes now, found none,
//! and made `rotor static` look hung to the model fuzzer; one run each,
//! back to back).

use rotor_bearing::analysis::film_validity::{NEARLY_UNLOADED, short_film_warnings};
use rotor_bearing::model::RotorModel;
use rotor_bearing::rotor::Rotor;

const RPM: f64 = std::f64::consts::PI / 30.0;

fn brackets(fx: &str) -> Rotor {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/models/hydro_unit_brackets.toml"
    );
    let text = std::fs::read_to_string(path).unwrap();
    let line = text
        .lines()
        .find(|l| l.starts_with("fx = 0.0"))
        .expect("the hydraulic thrust's fx")
        .to_string();
    let text = text.replace(&line, &format!("fx = {fx}"));
    Rotor::new(RotorModel::from_toml(&text, "brackets.toml").unwrap()).unwrap()
}

#[test]
fn a_nearly_unloaded_bearing_is_compared_centred() {
    let speed = 300.0 * RPM;
    let none = short_film_warnings(&brackets("0.0"), speed).unwrap();
    let side = short_film_warnings(&brackets("-1.0"), speed).unwrap();
    assert_eq!(none.len(), 3);
    assert_eq!(side.len(), 3);
    // μ Ω R L (R/C)² of the guide bearings: 0.03 × 31.4 × 0.35 × 0.25 × 1400².
    let scale = 0.03 * speed * 0.35 * 0.25 * (0.35f64 / 0.25e-3).powi(2);
    for (a, b) in none.iter().zip(&side) {
        assert_eq!(a.load, 0.0);
        assert!(
            b.load > 0.0 && b.load < NEARLY_UNLOADED * scale,
            "{}",
            b.load
        );
        assert_eq!(a.stiffness_ratio, b.stiffness_ratio, "{}", a.bearing);
        assert_eq!(a.damping_ratio, b.damping_ratio, "{}", a.bearing);
        assert!(b.stiffness_ratio.is_some() && b.damping_ratio.is_some());
    }
}
