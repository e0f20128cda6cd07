//! Overdamped roots apart from the modes, and Campbell branches tracked by
//! their shapes (issue 27).
//!
//! The hydro unit on tilting pads has non-oscillating film roots
//! (`λ ≈ −25 1/s`, ζ = 1 − 1e-6) below its first lateral mode; the previous
//! solver listed them as modes 1–3 (how many depended on the speed), so they
//! used up `--modes` and the branches by rank jumped between speeds.

use std::path::PathBuf;
use std::process::Command;

use rotor_bearing::analysis::campbell::{CampbellPoint, branch, branch_count, campbell};
use rotor_bearing::analysis::modal::{
    ModalOptions, NON_OSCILLATING_DAMPING_RATIO, modal_analysis_at,
};
use rotor_bearing::model::RotorModel;
use rotor_bearing::rotor::Rotor;
use rotor_bearing::units::RAD_S_TO_RPM;

fn model(name: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join(format!("models/{name}.toml"))
}

fn rotor(name: &str) -> Rotor {
    Rotor::new(RotorModel::from_file(&model(name)).unwrap()).unwrap()
}

/// At every speed the requested number of oscillating modes is listed, and
/// the two film roots apart (the previous solver listed one at 7.5 rpm and
/// two at 300 rpm as modes), below
/// the first mode.
#[test]
fn tilting_pad_roots_are_listed_apart_and_never_counted_as_modes() {
    let rotor = rotor("hydro_unit");
    let options = ModalOptions {
        modes: 4,
        ..ModalOptions::default()
    };
    for (rpm, roots) in [(7.5, 2), (150.0, 2), (300.0, 2)] {
        let r = modal_analysis_at(&rotor, rpm / RAD_S_TO_RPM, &options).unwrap();
        assert_eq!(r.modes.len(), 4, "{rpm} rpm");
        assert!(
            r.modes
                .iter()
                .all(|m| m.damping_ratio < 0.2 && m.damped_frequency > 5.0),
            "{rpm} rpm: {:?}",
            r.modes
                .iter()
                .map(|m| m.damped_frequency)
                .collect::<Vec<_>>()
        );
        assert_eq!(r.overdamped.len(), roots, "{rpm} rpm: {:?}", r.overdamped);
        for root in &r.overdamped {
            let l = root.eigenvalue;
            // Non-oscillating: ζ ≥ 0.999, decaying, well below the first mode.
            assert!(-l.re / l.norm() >= NON_OSCILLATING_DAMPING_RATIO, "{l}");
            assert!(root.decay_rate() > 0.0 && l.im.abs() < 0.01 * r.modes[0].damped_frequency);
        }
    }
    // The command line prints exactly the requested modes, the roots apart.
    let out = Command::new(env!("CARGO_BIN_EXE_rotor"))
        .arg("modes")
        .arg(model("hydro_unit"))
        .args(["--rpm", "300", "--modes", "3"])
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let (modes, roots) = stdout.split_once("non-oscillating").expect(&stdout);
    let rows: Vec<&str> = modes.lines().skip(2).collect();
    assert_eq!(rows.len(), 3, "{stdout}");
    // Mode 1 as the library gives it with the pads at its own frequency
    // (what `rotor modes` lists on tilting pads), to the printed 4 decimals.
    let own = rotor_bearing::analysis::whirl_modes::modes_at_own_frequency(
        &rotor,
        300.0 / RAD_S_TO_RPM,
        &ModalOptions {
            modes: 3,
            ..ModalOptions::default()
        },
    )
    .unwrap();
    let printed: f64 = rows[0].split_whitespace().nth(1).unwrap().parse().unwrap();
    assert!(
        (printed - own[0].damped_frequency).abs() <= 5e-5 && (printed - 9.8293).abs() < 1e-9,
        "{stdout}"
    );
    assert!(rows.iter().all(|r| !r.contains("1.0000e0")), "{stdout}");
    // With the pad tilts as coordinates the roots are the twelve pads'
    // own (one per pad, all at 41.14 1/s: every pad of the vertical unit is
    // alike), printed once with their count, as the dense solve of the
    // rotor with the pad coordinates has them; the synchronous condensation
    // shows two roots of 25.5 and 27.4 1/s instead (above).
    let speed = 300.0 / RAD_S_TO_RPM;
    let (_, eq) =
        rotor_bearing::analysis::linearize::linearized_from(&rotor, speed, speed, None).unwrap();
    let exact: Vec<f64> =
        rotor_bearing::analysis::pad_eigen::eigenvalues_with_pads(&rotor, &eq.unwrap(), speed)
            .unwrap()
            .into_iter()
            .filter(|l| l.im.abs() <= 1e-9 * l.norm() && l.norm() < own[2].natural_frequency)
            .map(|l| -l.re)
            .collect();
    assert_eq!(exact.len(), 12, "{exact:?}");
    let lines: Vec<&str> = roots.lines().skip(2).collect();
    assert_eq!(lines.len(), 1, "{stdout}");
    let decay: f64 = lines[0].split_whitespace().next().unwrap().parse().unwrap();
    assert!(lines[0].ends_with("(×12)"), "{stdout}");
    for d in &exact {
        assert!((decay - d).abs() <= 1e-6 * d, "{decay} printed, {d} exact");
    }
    assert!(!roots.contains("forward") && !roots.contains("backward"));
}

/// The diagram on speeds `coarse`, and on the grid with `sub` steps in each
/// coarse step (the coarse speeds included exactly).
fn coarse_and_fine(
    rotor: &Rotor,
    coarse: &[f64],
    sub: usize,
) -> (Vec<CampbellPoint>, Vec<CampbellPoint>) {
    let options = ModalOptions {
        modes: 6,
        ..ModalOptions::default()
    };
    let mut fine = Vec::new();
    for w in coarse.windows(2) {
        for j in 0..sub {
            fine.push(w[0] + (w[1] - w[0]) * j as f64 / sub as f64);
        }
    }
    fine.push(*coarse.last().unwrap());
    (
        campbell(rotor, coarse, &options).unwrap(),
        campbell(rotor, &fine, &options).unwrap(),
    )
}

/// Whether every step of every coarse branch is the step of one eigenvalue
/// followed continuously: starting at the coarse branch's mode, the fine
/// diagram's branch through it must arrive at the coarse branch's next mode
/// (same eigenvalue, to round-off). Returns the offending steps.
fn discontinuities(coarse: &[CampbellPoint], fine: &[CampbellPoint], sub: usize) -> Vec<String> {
    let mut bad = Vec::new();
    for b in 0..branch_count(coarse) {
        let points = branch(coarse, b);
        for w in points.windows(2) {
            let (k0, k1) = (
                coarse.iter().position(|p| p.speed == w[0].0).unwrap(),
                coarse.iter().position(|p| p.speed == w[1].0).unwrap(),
            );
            if k1 != k0 + 1 {
                continue; // the branch left the listed range in between
            }
            let start = &fine[k0 * sub];
            assert_eq!(start.speed, w[0].0);
            let Some(m) = start
                .modes
                .iter()
                .find(|m| m.damped_frequency == w[0].1.damped_frequency)
            else {
                bad.push(format!("branch {b}: start not found at {}", w[0].0));
                continue;
            };
            let end = &fine[k1 * sub];
            let arrived = end.modes.iter().find(|e| e.branch == m.branch);
            let same = arrived.is_some_and(|e| {
                (e.damped_frequency - w[1].1.damped_frequency).abs() <= 1e-9 * e.damped_frequency
                    && (e.damping_ratio - w[1].1.damping_ratio).abs() <= 1e-9
            });
            if !same {
                bad.push(format!(
                    "branch {b}, {:.2} → {:.2} rpm: {:.4} → {:.4} rad/s, the eigenvalue followed arrives at {:?}",
                    w[0].0 * RAD_S_TO_RPM,
                    w[1].0 * RAD_S_TO_RPM,
                    w[0].1.damped_frequency,
                    w[1].1.damped_frequency,
                    arrived.map(|e| e.damped_frequency)
                ));
            }
        }
    }
    bad
}

/// Acceptance: the tilting-pad unit's branches are continuous, each step
/// the change of one tracked eigenvalue, from 7.5 to 300 rpm, where the film
/// roots the previous solver counted as modes change in number.
#[test]
fn tilting_pad_campbell_branches_are_continuous() {
    let rotor = rotor("hydro_unit");
    let coarse: Vec<f64> = (0..=8)
        .map(|k| (7.5 + (300.0 - 7.5) * k as f64 / 8.0) / RAD_S_TO_RPM)
        .collect();
    let (c, f) = coarse_and_fine(&rotor, &coarse, 4);
    assert!(c.iter().all(|p| p.modes.len() == 6));
    let bad = discontinuities(&c, &f, 4);
    assert!(bad.is_empty(), "{bad:#?}");
    // Six branches, one per listed mode all the way: no jump, no new branch.
    assert_eq!(branch_count(&c), 6);
}

/// Where two forward branches of the pump on plain bearings cross (near
/// 4380 rpm), the tracked branches stay continuous, and branches by rank —
/// what the diagram drew before — are caught as jumps by the same check.
#[test]
fn crossing_branches_are_followed_by_shape_and_ranks_would_jump() {
    let rotor = Rotor::new(
        RotorModel::from_file(
            &PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("examples/my_pump.toml"),
        )
        .unwrap(),
    )
    .unwrap();
    let coarse: Vec<f64> = (0..=6)
        .map(|k| (3800.0 + 200.0 * k as f64) / RAD_S_TO_RPM)
        .collect();
    let (c, f) = coarse_and_fine(&rotor, &coarse, 4);
    let bad = discontinuities(&c, &f, 4);
    assert!(bad.is_empty(), "{bad:#?}");
    let crossed = c.iter().any(|p| {
        p.modes
            .iter()
            .enumerate()
            .any(|(k, m)| m.branch != c[0].modes[k].branch)
    });
    assert!(
        crossed,
        "no crossing in the range: the test would prove nothing"
    );
    let mut by_rank = c.clone();
    for p in &mut by_rank {
        for (k, m) in p.modes.iter_mut().enumerate() {
            m.branch = k;
        }
    }
    assert!(!discontinuities(&by_rank, &f, 4).is_empty());
}
