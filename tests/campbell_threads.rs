//! The Campbell study spread over threads and on coarse speed grids:
//! the same study bit for bit on 1, 2 and 3 threads (each speed and each
//! critical-speed refinement is the same computation whichever thread takes
//! it), and the critical speeds of grids of 1 to 8 steps (brackets of 2500
//! rpm and more, the refinement starting far from each root) equal to those
//! of the 40-step grid to the refinement's 1e-8, also where the grid asked
//! for is too coarse to follow the modes (the study refines it).

use rotor_bearing::analysis::campbell::{CampbellRequest, CampbellStudy, campbell_study};
use rotor_bearing::model::RotorModel;
use rotor_bearing::rotor::Rotor;
use std::path::PathBuf;

fn model(name: &str) -> Rotor {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("models")
        .join(name);
    Rotor::new(RotorModel::from_file(&path).unwrap()).unwrap()
}

/// The study up to `max_rpm` (the model's default top speed when `None`).
fn study(rotor: &Rotor, max_rpm: Option<f64>, steps: usize, threads: usize) -> CampbellStudy {
    let request = CampbellRequest {
        max: max_rpm.map(|r| r * std::f64::consts::PI / 30.0),
        steps,
        threads,
        ..CampbellRequest::default_for(None)
    };
    let mut s = campbell_study(rotor, &request).unwrap();
    s.diagram_seconds = 0.0;
    s
}

#[test]
fn the_study_is_the_same_bit_for_bit_on_any_number_of_threads() {
    for (rotor, top) in [
        (
            Rotor::new(RotorModel::default_model()).unwrap(),
            Some(20_000.0),
        ),
        (model("hydro_unit.toml"), None),
    ] {
        let serial = study(&rotor, top, 40, 1);
        assert!(!serial.criticals.is_empty(), "{:?}", serial.criticals);
        for threads in [2, 3] {
            assert_eq!(study(&rotor, top, 40, threads), serial, "{threads} threads");
        }
    }
}

/// On grids of 1 to 8 steps up to 20 000 rpm (steps of 2500 to 20 000 rpm,
/// across which the gyroscopic split moves the modes by up to 20 %), the
/// study finds the 40-step grid's seven critical speeds one for one, with
/// their whirls, to 1e-7, and their damping. Grids of 1 to 4 steps follow a
/// mode onto another's branch (the same critical speed found twice, one
/// missed): the study doubles their steps until that is gone, and says so.
#[test]
fn a_coarse_grid_finds_the_critical_speeds_of_the_fine_grid() {
    let rotor = Rotor::new(RotorModel::default_model()).unwrap();
    let fine = study(&rotor, Some(20_000.0), 40, 0);
    assert_eq!(fine.diagram.len(), 41);
    assert!(fine.repeated.is_empty());
    let fine = fine.criticals;
    assert_eq!(fine.len(), 7, "{fine:?}");
    for (steps, used) in [(1, 8), (2, 8), (3, 6), (4, 8), (8, 8)] {
        let coarse = study(&rotor, Some(20_000.0), steps, 0);
        assert_eq!(coarse.requested_steps, steps);
        assert_eq!(coarse.diagram.len(), used + 1, "{steps} steps");
        assert!(
            coarse.repeated.is_empty(),
            "{steps} steps: {:?}",
            coarse.repeated
        );
        let coarse = coarse.criticals;
        assert_eq!(coarse.len(), fine.len(), "{steps} steps: {coarse:?}");
        for (c, f) in coarse.iter().zip(&fine) {
            assert_eq!(c.whirl, f.whirl, "{steps} steps: {c:?} against {f:?}");
            assert!(
                (f.speed - c.speed).abs() <= 1e-7 * f.speed,
                "{steps} steps: {} rad/s against {} rad/s",
                c.speed,
                f.speed
            );
            assert!(
                (f.damping_ratio - c.damping_ratio).abs() <= 1e-6 * f.damping_ratio.abs().max(1e-9)
            );
        }
    }
}
