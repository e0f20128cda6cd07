//! Supports in series with bearings, speed tables and seals against ROSS 3.1
//! on rotors both codes build identically (`tests/data/ross_supports.py`
//! made `tests/data/ross_supports.json`): every eigenvalue of ours at three
//! speeds is one of ROSS's, and the unbalance response at the disk and both
//! bearings over twelve speeds is ROSS's, both to 1e-9 relative (measured:
//! eigenvalues 8e-11 and 1.0e-10, responses 1.6e-13 and 6e-14). The
//! response speeds lie inside the tables' rows: outside them ROSS
//! extrapolates linearly where we hold the end values.

use nalgebra::Complex;
use serde_json::Value;

use rotor_bearing::analysis::linear::{node_xy, unbalance_response};
use rotor_bearing::analysis::linearize::linearized;
use rotor_bearing::analysis::modal::{ModalOptions, modes};
use rotor_bearing::model::RotorModel;
use rotor_bearing::rotor::Rotor;

const RPM: f64 = std::f64::consts::PI / 30.0;

fn reference() -> Value {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/ross_supports.json");
    serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap()
}

fn complex(v: &Value) -> Complex<f64> {
    Complex::new(v[0].as_f64().unwrap(), v[1].as_f64().unwrap())
}

fn check_case(name: &str) {
    let data = reference();
    let case = &data["cases"][name];
    let model = RotorModel::from_toml(case["model"].as_str().unwrap(), name).unwrap();
    let rotor = Rotor::new(model).unwrap();
    let mut worst_mode: f64 = 0.0;
    for at in case["modes"].as_array().unwrap() {
        let speed = at["rpm"].as_f64().unwrap() * RPM;
        let ross: Vec<Complex<f64>> = at["eigenvalues"]
            .as_array()
            .unwrap()
            .iter()
            .map(complex)
            .collect();
        let linear = linearized(&rotor, speed, speed).unwrap();
        let ours = modes(
            &linear,
            speed,
            &ModalOptions {
                modes: 10,
                target_frequency: 0.0,
            },
        )
        .unwrap();
        for m in &ours {
            let nearest = ross
                .iter()
                .map(|r| (r - m.eigenvalue).norm() / m.eigenvalue.norm())
                .fold(f64::INFINITY, f64::min);
            worst_mode = worst_mode.max(nearest);
            assert!(
                nearest < 1e-9,
                "{name} at {} rpm: eigenvalue {} has no ROSS match (nearest relative {nearest:e})",
                speed / RPM,
                m.eigenvalue
            );
        }
    }
    let mut worst_response: f64 = 0.0;
    let rpms: Vec<f64> = case["response_rpm"]
        .as_array()
        .unwrap()
        .iter()
        .map(|v| v.as_f64().unwrap())
        .collect();
    for (k, rpm) in rpms.iter().enumerate() {
        let speed = rpm * RPM;
        let linear = linearized(&rotor, speed, speed).unwrap();
        let ours = unbalance_response(&linear, speed).unwrap();
        let at = |node: usize, axis: &str| complex(&case["response"][node.to_string()][axis][k]);
        let scale = [0, 3, 6]
            .iter()
            .flat_map(|&n| [at(n, "x").norm(), at(n, "y").norm()])
            .fold(0.0, f64::max);
        for node in [0, 3, 6] {
            let (x, y) = node_xy(&ours, node);
            for (mine, theirs) in [(x, at(node, "x")), (y, at(node, "y"))] {
                let d = (mine - theirs).norm() / scale;
                worst_response = worst_response.max(d);
                assert!(
                    d < 1e-9,
                    "{name} at {rpm} rpm, node {}: {mine} against ROSS {theirs}",
                    node + 1
                );
            }
        }
    }
    eprintln!(
        "{name}: worst eigenvalue difference {worst_mode:e}, worst response difference {worst_response:e}"
    );
}

/// Bearings in series with support masses (ROSS `n_link`): anisotropic,
/// cross-coupled, damped supports.
#[test]
fn pedestals_match_ross_n_link_supports() {
    check_case("pedestals");
}

/// A bearing given as a speed table and a seal with a speed table (ROSS
/// PCHIP on both sides), at speeds between the rows.
#[test]
fn table_bearing_and_seal_match_ross() {
    check_case("table_and_seal");
}
