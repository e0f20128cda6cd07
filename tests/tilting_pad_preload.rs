//! Tilting-pad equilibrium and synchronously condensed coefficients on five
//! geometries (4–6 pads, load on pad and between pads, preload 0 to 0.5, light
//! and heavy loads) against the independent quadrature oracle
//! `tests/data/tilting_pad_preload_oracle.py` (its output
//! `tests/data/tilting_pad_preload_reference.json`).

use nalgebra::{Matrix2, Vector2};
use serde_json::Value;

#[path = "common/reference.rs"]
mod common_reference;
use common_reference::{mat, num};

fn reference() -> Value {
    common_reference::reference("tilting_pad_preload_reference.json")
}

use rotor_bearing::bearing::equilibrium::{
    coefficient_points, condensed_coefficients, journal_equilibrium,
};
use rotor_bearing::bearing::tilting_pad::{Pad, TiltingPadBearing};

fn bearing(case: &Value) -> (TiltingPadBearing, f64, f64) {
    let p = &case["parameters"];
    let pads = p["pads"]
        .as_array()
        .unwrap()
        .iter()
        .map(|d| {
            Pad::new(
                num(&d["pivot_deg"]).to_radians(),
                num(&d["arc_deg"]).to_radians(),
                num(&d["offset"]),
                num(&d["preload"]),
            )
        })
        .collect();
    (
        TiltingPadBearing {
            radius: num(&p["R"]),
            length: num(&p["L"]),
            clearance: num(&p["C"]),
            viscosity: num(&p["mu"]),
            pads,
            contact: None,
            support: Default::default(),
        },
        num(&p["omega"]),
        num(&p["W"]),
    )
}

/// Entry-wise agreement within `tol` of the matrix's largest entry.
fn close(name: &str, ours: &Matrix2<f64>, oracle: &Matrix2<f64>, tol: f64) {
    let scale = oracle.abs().max();
    for i in 0..2 {
        for j in 0..2 {
            let d = (ours[(i, j)] - oracle[(i, j)]).abs();
            assert!(
                d <= tol * scale,
                "{name}[{i}{j}] = {:.6e}, oracle {:.6e} (off by {:.3} % of the largest entry)",
                ours[(i, j)],
                oracle[(i, j)],
                100.0 * d / scale
            );
        }
    }
}

#[test]
fn preloaded_and_load_on_pad_equilibria_and_coefficients_match_the_oracle() {
    let r = reference();
    let cases = r["cases"].as_array().unwrap();
    assert!(cases.len() >= 4);
    for case in cases {
        let name = case["name"].as_str().unwrap();
        let (b, w, load) = bearing(case);
        let eq = journal_equilibrium(&b, Vector2::new(0.0, -load), w, b.clearance)
            .unwrap_or_else(|e| panic!("{name}: {e}"));
        let re = &case["equilibrium"];
        let c = b.clearance;
        assert!(
            (eq.q[0] - num(&re["X"])).abs() < 1e-6 * c
                && (eq.q[1] - num(&re["Y"])).abs() < 1e-6 * c,
            "{name}: journal at ({:.6e}, {:.6e}), oracle ({:.6e}, {:.6e})",
            eq.q[0],
            eq.q[1],
            num(&re["X"]),
            num(&re["Y"])
        );
        for (k, tilt) in re["pad_tilts"].as_array().unwrap().iter().enumerate() {
            assert!(
                (eq.q[2 + k] - num(tilt)).abs() < 1e-5 * c,
                "{name}: pad {k} tilt {:.6e}, oracle {:.6e}",
                eq.q[2 + k],
                num(tilt)
            );
        }
        let (k, d) = condensed_coefficients(&eq.eval, w);
        let red = &case["synchronous_reduced"];
        close(&format!("{name} K"), &k, &mat(&red["K"]), 0.01);
        close(&format!("{name} C"), &d, &mat(&red["C"]), 0.01);
    }
}

#[test]
fn a_load_sweep_reports_every_load_and_follows_the_oracle_branch() {
    let r = reference();
    for case in r["cases"].as_array().unwrap() {
        let name = case["name"].as_str().unwrap();
        let (b, w, load) = bearing(case);
        // A sweep up to the oracle's load: every point is reported, solved or not,
        // and the last one lands on the oracle's equilibrium.
        let loads: Vec<f64> = (1..=6).map(|i| load * i as f64 / 6.0).collect();
        let points = coefficient_points(&b, (w, w), b.clearance, &loads);
        assert_eq!(points.len(), loads.len(), "{name}: a load was dropped");
        let (last_load, last) = points.last().unwrap();
        assert_eq!(*last_load, load);
        let last = last
            .as_ref()
            .unwrap_or_else(|e| panic!("{name} at {load} N: {e}"));
        let red = &case["synchronous_reduced"];
        close(
            &format!("{name} K (sweep)"),
            &last.stiffness,
            &mat(&red["K"]),
            0.01,
        );
        close(
            &format!("{name} C (sweep)"),
            &last.damping,
            &mat(&red["C"]),
            0.01,
        );
    }
}
