//! How a bearing's offset moves the line's stability (issue 49, alignment
//! tools), on the three plain bearings of `tests/alignment_whirl.rs` at 6000
//! rpm: the slopes `∂δ/∂o` of the least stable forward mode's log decrement
//! are the central differences of the log decrements at `±h` (recomputed
//! here from `linearized` and `least_stable_forward`, and against half the
//! step to 2 %), and they obey the line's geometry — moving every bearing by
//! the same amount, or tilting the straight line as a whole, carries the
//! rotor along and changes nothing, so `Σ_b ∂δ/∂o_b = 0` and
//! `Σ_b z_b ∂δ/∂o_b = 0` in each direction (to 1e-4 of the largest term: the
//! differences' truncation, and the tilt's second-order turn of gravity). A
//! linear bearing's offset leaves the stability as it is.

use rotor_bearing::analysis::linearize::linearized;
use rotor_bearing::analysis::offset_stability::{MODES, STEP, offset_sensitivity};
use rotor_bearing::analysis::stability::least_stable_forward;
use rotor_bearing::model::{DEFAULT_MODEL_TOML, RotorModel};
use rotor_bearing::rotor::Rotor;

#[path = "common/film_line.rs"]
mod film_line;

const RPM: f64 = std::f64::consts::PI / 30.0;

fn least(rotor: &Rotor, speed: f64) -> f64 {
    let linear = linearized(rotor, speed, speed).unwrap();
    least_stable_forward(&linear, speed, MODES)
        .unwrap()
        .log_decrement
}

#[test]
fn the_slopes_are_differences_of_the_stability_and_respect_the_lines_geometry() {
    let speed = 6000.0 * RPM;
    let rotor = film_line::line(0.0);
    let (base, slopes) = offset_sensitivity(&rotor, speed).unwrap();
    assert_eq!(base, least(&rotor, speed));
    let names: Vec<&str> = slopes.iter().map(|s| s.name.as_str()).collect();
    assert_eq!(names, ["left", "middle", "right"]);
    let middle = &slopes[1];
    let h = STEP * 80e-6;
    assert_eq!(middle.step, h);
    let z = [0.0, 0.6, 1.2];
    for k in 0..2 {
        let largest = slopes
            .iter()
            .map(|s| s.log_decrement_slope[k].abs())
            .fold(0.0, f64::max);
        assert!(
            largest > 0.0,
            "the films make the stability depend on the offsets"
        );
        let shift: f64 = slopes.iter().map(|s| s.log_decrement_slope[k]).sum();
        let tilt: f64 = slopes
            .iter()
            .zip(z)
            .map(|(s, z)| z * s.log_decrement_slope[k])
            .sum();
        assert!(
            shift.abs() < 1e-4 * largest,
            "direction {k}: Σ = {shift}, largest {largest}"
        );
        assert!(
            tilt.abs() < 1.2e-4 * largest,
            "direction {k}: Σ z = {tilt}, largest {largest}"
        );
    }
    // The central difference, recomputed, and at half the step.
    let at = |d: f64| least(&film_line::line(d), speed);
    let full = (at(h) - at(-h)) / (2.0 * h);
    assert!((full - middle.log_decrement_slope[1]).abs() <= 1e-12 * full.abs());
    let half = (at(0.5 * h) - at(-0.5 * h)) / h;
    assert!((half / full - 1.0).abs() < 2e-2, "{half} against {full}");
}

#[test]
fn a_linear_bearings_offset_leaves_the_stability_as_it_is() {
    let speed = 1000.0 * RPM;
    let damped =
        DEFAULT_MODEL_TOML.replace("kyy = 1e6\n", "kyy = 1e6\ncxx = 4000.0\ncyy = 4000.0\n");
    let aligned = Rotor::new(RotorModel::from_toml(&damped, "aligned.toml").unwrap()).unwrap();
    let offset = damped.replace("kyy = 1e6\n", "kyy = 1e6\noffset_y = 2e-4\n");
    let offset = Rotor::new(RotorModel::from_toml(&offset, "offset.toml").unwrap()).unwrap();
    assert_eq!(least(&aligned, speed), least(&offset, speed));
    let (_, slopes) = offset_sensitivity(&offset, speed).unwrap();
    assert!(slopes.is_empty(), "no fluid-film bearing to differentiate");
}

/// `rotor alignment` prints the log decrement and each bearing's slopes in
/// 1/mm, as `offset_sensitivity` gives them.
#[test]
fn the_alignment_command_prints_the_slopes() {
    let dir = std::env::temp_dir().join(format!("offset-stability-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("film3.toml");
    std::fs::write(&file, film_line::text(0.0)).unwrap();
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_rotor"))
        .args(["alignment", file.to_str().unwrap(), "--rpm", "6000"])
        .output()
        .unwrap();
    let _ = std::fs::remove_dir_all(&dir);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let printed = String::from_utf8(out.stdout).unwrap();
    let speed = 6000.0 * RPM;
    let (delta, slopes) = offset_sensitivity(&film_line::line(0.0), speed).unwrap();
    assert!(
        printed.contains(&format!("least stable forward mode log dec {delta:.4};")),
        "{printed}"
    );
    for s in &slopes {
        let row = format!(
            "{:<14} {:>14.4e} {:>14.4e}",
            s.name,
            s.log_decrement_slope[0] * 1e-3,
            s.log_decrement_slope[1] * 1e-3
        );
        assert!(printed.contains(&row), "{row}\n{printed}");
    }
}
