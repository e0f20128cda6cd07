//! The whole operating envelope (issue 14): a rotor at rest on its bearings,
//! lift-off on a run-up, touch-down on a coast-down, and rubs that continue in
//! contact instead of ending the run.
//!
//! Independent truths: the reactions of a statically determinate beam on two
//! supports (from the linear static analysis with the bearings replaced by
//! rigid supports), Coulomb's law `T = μ N R`, and the lift-off speed of the
//! bearings' own static equilibria, found by bisection on the statics solver.

use rotor_bearing::analysis::linear::static_deflection;
use rotor_bearing::bearing::BearingKind;
use rotor_bearing::model::RotorModel;
use rotor_bearing::rotor::Rotor;
use rotor_bearing::solver::{Outputs, Simulator, SolverOptions, SpeedProfile, record};

#[path = "common/lift_off.rs"]
mod lift_off;
use lift_off::{contact, ramp, static_lift_off};

const JEFFCOTT: &str = include_str!("../models/jeffcott.toml");

/// The shipped Jeffcott rotor with `edit` applied to its text.
fn jeffcott_with(edit: impl Fn(&str) -> String) -> RotorModel {
    RotorModel::from_toml(&edit(JEFFCOTT), "jeffcott variant").unwrap()
}

/// The Jeffcott rotor with both plain bearings replaced by tilting-pad
/// bearings of the same journal, pivots from `first_pivot_deg`.
fn tilting_pad_jeffcott(first_pivot_deg: f64, preload: f64) -> RotorModel {
    let tilting = |name: &str, node: u32| {
        format!(
            "[[bearings]]\nname = \"{name}\"\ntype = \"tilting_pad\"\nnode = {node}\nradius = 0.02\nlength = 0.02\nclearance = 100e-6\nviscosity = 0.02\npads = 4\nfirst_pivot_deg = {first_pivot_deg}\npad_arc_deg = 70.0\npreload = {preload}\n\n"
        )
    };
    jeffcott_with(|text| {
        let start = text.find("[[bearings]]").unwrap();
        let end = text.find("[[unbalance]]").unwrap();
        format!(
            "{}{}{}{}",
            &text[..start],
            tilting("left", 1),
            tilting("right", 9),
            &text[end..]
        )
    })
}

/// A simulator of `model` at rest (speed 0) in its static equilibrium.
fn at_rest(model: RotorModel) -> Simulator {
    let mut sim = Simulator::new(Rotor::new(model).unwrap(), SolverOptions::default()).unwrap();
    sim.set_speed(0.0, 0.0).unwrap();
    sim.settle_static().unwrap();
    sim
}

/// The bearing reactions (N, magnitudes) of `model` with every bearing
/// replaced by a rigid isotropic support: `k |u_journal|` with `k = 10¹³ N/m`.
fn beam_reactions(model: &RotorModel) -> Vec<f64> {
    let k = 1e13;
    let mut rigid = model.clone();
    for b in &mut rigid.bearings {
        b.kind = BearingKind::Linear {
            stiffness: [[k, 0.0], [0.0, k]],
            damping: [[0.0; 2]; 2],
        };
    }
    let rotor = Rotor::new(rigid).unwrap();
    let u = static_deflection(&rotor).unwrap();
    model
        .bearings
        .iter()
        .map(|b| k * u[4 * b.node].hypot(u[4 * b.node + 1]))
        .collect()
}

/// Journal radius (m) and contact friction coefficient of bearing `k`.
fn radius_and_friction(model: &RotorModel, k: usize) -> (f64, f64) {
    match &model.bearings[k].kind {
        BearingKind::Plain(b) => (b.radius, b.contact_law().friction),
        BearingKind::TiltingPad(b) => (b.radius, b.contact_law().friction),
        _ => panic!("not a fluid-film bearing"),
    }
}

#[test]
fn at_rest_each_bearing_carries_its_beam_reaction_and_the_breakaway_torque_is_mu_n_r() {
    let cases = [
        ("plain, symmetric", jeffcott_with(str::to_string)),
        (
            "plain, disk off-centre",
            jeffcott_with(|t| {
                t.replace(
                    "name = \"disk\"\nnode = 5\nmass",
                    "name = \"disk\"\nnode = 3\nmass",
                )
            }),
        ),
        (
            "tilting pads, load on pad",
            tilting_pad_jeffcott(-90.0, 0.3),
        ),
        (
            "tilting pads, load between pads",
            tilting_pad_jeffcott(-45.0, 0.0),
        ),
    ];
    for (label, model) in cases {
        let reactions = beam_reactions(&model);
        let mut sim = at_rest(model.clone());
        let out = sim.outputs().unwrap();
        let mut total_torque = 0.0;
        for (k, b) in out.bearings.iter().enumerate() {
            let n = b.report.contact_force;
            let r = reactions[k];
            assert!(
                (n - r).abs() < 1e-6 * r,
                "{label}, bearing {k}: contact force {n} N, beam reaction {r} N"
            );
            // The journal sits below the centre, in contact.
            assert!(b.y < 0.0 && b.report.eccentricity >= 1.0, "{label}: {b:?}");
            assert_eq!(b.report.min_film_thickness, 0.0);
            let (radius, mu) = radius_and_friction(&model, k);
            // Between two pads at ±45° from the load, each pad presses with
            // N / (2 cos 45°): the pads' normal forces add up to √2 N.
            let pressing = if label.contains("between") {
                n * std::f64::consts::SQRT_2
            } else {
                n
            };
            let breakaway = mu * pressing * radius;
            assert!(
                (b.report.friction_torque - breakaway).abs() < 1e-6 * breakaway,
                "{label}: friction torque {} vs μNR = {breakaway}",
                b.report.friction_torque
            );
            total_torque += breakaway;
        }
        assert!((out.friction_torque - total_torque).abs() < 1e-6 * total_torque);
        if label.contains("off-centre") {
            assert!(reactions[0] > 1.5 * reactions[1], "{reactions:?}");
        }
    }
}

/// A slow run-up through the lift-off speed lifts the journals off within 2 %
/// of the speed at which their static equilibrium first stays clear of contact,
/// and a slow coast-down touches down within 2 % of it. Slow: near contact the
/// squeeze film makes the journal creep along the bushing with a time constant
/// of about 2 s, so the ramp spans ±20 % of the lift-off speed in 200 s.
#[test]
fn slow_run_up_lifts_off_and_coast_down_touches_down_at_the_static_lift_off_speed() {
    let model = jeffcott_with(str::to_string);
    let lift_off = static_lift_off(&model, 1e-3, 100.0);
    let (below, above) = (0.8 * lift_off, 1.2 * lift_off);
    let up = ramp(&model, (below, above), (200.0, 0.0), 1e-2);
    assert!(contact(&up[0]) > 0.0, "below lift-off the journals touch");
    // The speed after which the contact force stays zero.
    let last_contact = up.iter().rposition(|o| contact(o) > 0.0).unwrap();
    let lift = up[last_contact + 1].speed;
    assert!(
        (lift - lift_off).abs() < 0.02 * lift_off,
        "run-up lifts off at {lift} rad/s, static lift-off {lift_off} rad/s"
    );
    eprintln!("static lift-off {lift_off} rad/s, run-up lifts off at {lift} rad/s");
    let down = ramp(&model, (above, below), (200.0, 0.0), 1e-2);
    assert_eq!(contact(&down[0]), 0.0, "floating at {above} rad/s");
    let touch = down[down.iter().position(|o| contact(o) > 0.0).unwrap()].speed;
    eprintln!("coast-down touches down at {touch} rad/s");
    assert!(
        (touch - lift_off).abs() < 0.02 * lift_off,
        "coast-down touches down at {touch} rad/s, static lift-off {lift_off} rad/s"
    );
}

/// From rest to 3000 rpm and back to rest (1 s each way) runs through lift-off
/// and touch-down without an error, and ends with the journals carrying the
/// rotor's weight on contact again, once the squeeze film has let them sink
/// onto the bushings (about 4 s after the stop).
#[test]
fn run_up_from_rest_and_coast_down_to_rest() {
    let model = jeffcott_with(str::to_string);
    let top = 3000.0 * std::f64::consts::PI / 30.0;
    let up = ramp(&model, (0.0, top), (1.0, 0.0), 1e-4);
    assert!(contact(&up[0]) > 0.0);
    assert_eq!(contact(up.last().unwrap()), 0.0, "floating at 3000 rpm");
    let down = ramp(&model, (top, 0.0), (1.0, 6.0), 2e-4);
    let end = down.last().unwrap();
    assert_eq!(end.speed, 0.0);
    let reactions = beam_reactions(&model);
    for (b, r) in end.bearings.iter().zip(&reactions) {
        assert!(
            // The last percent is the squeeze film still letting the journal settle.
            (b.report.contact_force - r).abs() < 1e-2 * r,
            "at rest after the coast-down: {} N vs {r} N",
            b.report.contact_force
        );
    }
}

/// Largest journal radius (m) of bearing `k` over `records`.
fn largest_orbit(records: &[Outputs], k: usize) -> f64 {
    records
        .iter()
        .map(|o| o.bearings[k].x.hypot(o.bearings[k].y))
        .fold(0.0, f64::max)
}

#[test]
fn a_rub_continues_in_contact_with_the_orbit_at_the_contact_radius_plus_the_penetration() {
    for (label, text) in [
        ("jeffcott", JEFFCOTT.to_string()),
        (
            "vertical_rotor",
            include_str!("../models/vertical_rotor.toml").to_string(),
        ),
    ] {
        let text = text.replace("magnitude = 2e-5", "magnitude = 1e3");
        let model = RotorModel::from_toml(&text, label).unwrap();
        let mut sim = Simulator::new(
            Rotor::new(model.clone()).unwrap(),
            SolverOptions {
                time_step: 1e-4,
                ..SolverOptions::default()
            },
        )
        .unwrap();
        let speed = 3000.0 * std::f64::consts::PI / 30.0;
        sim.set_speed(speed, 0.0).unwrap();
        sim.settle_static().unwrap();
        let records = record(
            &mut sim,
            &SpeedProfile::Constant(speed),
            1.0,
            1e-4,
            |_, _| {},
        )
        .unwrap_or_else(|e| panic!("{label}: {e}"));
        for (k, b) in model.bearings.iter().enumerate() {
            let BearingKind::Plain(plain) = &b.kind else {
                continue;
            };
            let law = plain.contact_law();
            let peak_force = records
                .iter()
                .map(|o| o.bearings[k].report.contact_force)
                .fold(0.0, f64::max);
            assert!(peak_force > 0.0, "{label}: no rub");
            // Radius = gap + the penetration of the largest contact force:
            // N = k (δ − δ₀/2) beyond the smoothing length.
            let allowed = law.gap + peak_force / law.stiffness + law.smoothing;
            let orbit = largest_orbit(&records, k);
            assert!(
                orbit > law.gap && orbit <= allowed * (1.0 + 1e-6),
                "{label}, {}: orbit {orbit} m, gap {} m, allowed {allowed} m",
                b.name,
                law.gap
            );
        }
    }
}

/// The Jeffcott rotor with a rub ring at the disk (radial gap 200 µm, steel
/// ring default) and `unbalance` kg·m at the disk.
fn jeffcott_with_a_rub(unbalance: f64) -> RotorModel {
    jeffcott_with(|t| {
        t.replace("magnitude = 2e-5", &format!("magnitude = {unbalance:e}"))
            + "\n[[rubs]]\nname = \"seal\"\nnode = 5\ngap = 200e-6\n"
    })
}

/// A rub and bearing contact at once (issue 22): 1e3 kg·m at 3000 rpm throws
/// the disk onto a rub ring of gap 200 µm while the bent shaft presses the
/// journals into their bushings. It used to end in "Newton–Raphson did not
/// converge … after 10 halvings" within 2 ms, at the FMU's 1 ms step and at
/// 0.1 ms: the dry friction drives the disk towards rolling on the ring, where
/// the sign of the friction turns within `v_ε = 10 mm/s` and plain Newton
/// cycles from one side of it to the other. It runs 1 s, and the stator holds
/// the disk: the contact carries the unbalance force `F = m e Ω²` (its peak is
/// at least `F`) and the penetration stays below that of `2F` (a load applied
/// at once deflects a spring by at most twice its static deflection; the
/// shaft's own restoring force only reduces it): orbit ≤ gap + δ₀ + 2F/k.
#[test]
fn a_rub_with_the_journals_in_contact_runs_on_with_the_orbit_held_by_the_stator() {
    let unbalance = 1e3;
    let model = jeffcott_with_a_rub(unbalance);
    let seal = model.bearings.iter().position(|b| b.kind.is_rub()).unwrap();
    let BearingKind::Rub(rub) = &model.bearings[seal].kind else {
        unreachable!()
    };
    let law = rub.contact;
    let speed = 3000.0 * std::f64::consts::PI / 30.0;
    let force = unbalance * speed * speed;
    for step in [1e-3, 1e-4] {
        let options = SolverOptions {
            time_step: step,
            ..SolverOptions::default()
        };
        let mut sim = Simulator::new(Rotor::new(model.clone()).unwrap(), options).unwrap();
        sim.set_speed(speed, 0.0).unwrap();
        sim.settle_static().unwrap();
        let records = record(
            &mut sim,
            &SpeedProfile::Constant(speed),
            1.0,
            1e-3,
            |_, _| {},
        )
        .unwrap_or_else(|e| panic!("step {step} s: {e}"));
        assert_eq!(records.last().unwrap().time, 1.0);
        let peak_force = records
            .iter()
            .map(|o| o.bearings[seal].report.contact_force)
            .fold(0.0, f64::max);
        let orbit = largest_orbit(&records, seal);
        let allowed = law.gap + law.smoothing + 2.0 * force / law.stiffness;
        eprintln!(
            "step {step} s: orbit {orbit} m (allowed {allowed} m), peak rub force {peak_force} N (F = {force} N), {:?}",
            sim.stats()
        );
        assert!(
            peak_force >= force,
            "step {step} s: peak rub force {peak_force} N < F = {force} N"
        );
        assert!(
            orbit > law.gap && orbit <= allowed,
            "step {step} s: orbit {orbit} m, gap {} m, allowed {allowed} m",
            law.gap
        );
        let journals = [0, 1].map(|k| {
            records
                .iter()
                .map(|o| o.bearings[k].report.contact_force)
                .fold(0.0, f64::max)
        });
        assert!(
            journals.iter().all(|&n| n > 0.0),
            "journals in contact: {journals:?}"
        );
        assert!(sim.stats().retries > 0, "{:?}", sim.stats());
    }
}

/// `rotor simulate --ramp-rpm 0:N` and `N:0` run from and to standstill without
/// `--no-settle`: the CSV shows the journals on their bushings at rest (contact
/// force = the beam reaction, no film) and floating at speed.
#[test]
fn the_cli_runs_up_from_rest_and_coasts_down_to_rest() {
    let dir = std::path::PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("envelope_cli");
    std::fs::create_dir_all(&dir).unwrap();
    let model = concat!(env!("CARGO_MANIFEST_DIR"), "/models/jeffcott.toml");
    let reactions = beam_reactions(&jeffcott_with(str::to_string));
    for (ramp, rest_row) in [("0:3000", 0usize), ("3000:0", usize::MAX)] {
        let csv = dir.join(format!("ramp_{}.csv", ramp.replace(':', "_")));
        let out = std::process::Command::new(env!("CARGO_BIN_EXE_rotor"))
            .args(["simulate", model, "--ramp-rpm", ramp, "--duration", "0.3"])
            .args(["--step", "2e-4", "--csv"])
            .arg(&csv)
            .output()
            .unwrap();
        assert!(
            out.status.success(),
            "{ramp}: {}",
            String::from_utf8_lossy(&out.stderr)
        );
        let text = std::fs::read_to_string(&csv).unwrap();
        let mut lines = text.lines();
        let header: Vec<&str> = lines.next().unwrap().split(',').collect();
        let rows: Vec<Vec<f64>> = lines
            .map(|l| l.split(',').map(|v| v.parse().unwrap()).collect())
            .collect();
        let col = |name: &str| header.iter().position(|h| *h == name).unwrap();
        let (contact, film) = (
            col("left_contact_force_N"),
            col("left_min_film_thickness_m"),
        );
        let rest = &rows[rest_row.min(rows.len() - 1)];
        let moving = &rows[if rest_row == 0 { rows.len() - 1 } else { 0 }];
        if rest_row == 0 {
            // Starts settled at rest: the journal carries its share of the weight on contact.
            assert!(
                (rest[contact] - reactions[0]).abs() < 1e-6 * reactions[0],
                "{ramp}: {} N vs {} N",
                rest[contact],
                reactions[0]
            );
            assert_eq!(rest[film], 0.0);
        } else {
            // 0.3 s after the start of the coast-down the squeeze film still holds it off.
            assert_eq!(rest[col("speed_rpm")], 0.0);
        }
        assert_eq!(moving[contact], 0.0, "{ramp}: floating at 3000 rpm");
        assert!(moving[film] > 0.0);
    }
}

/// `rotor simulate` says when a contact leaves the range of its law (issue
/// 22): the 1e3 kg·m rub of the Jeffcott rotor throws the disk centimetres
/// "into" its seal at forces far past yield, and the journals into their
/// bushings; each contact gets one warning per limit for the whole run. The
/// shipped rotor at its own unbalance, run up from rest on its bushings,
/// gets none.
#[test]
fn the_cli_warns_once_per_run_when_a_contact_leaves_its_law() {
    let dir = std::path::PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("envelope_contact_cli");
    std::fs::create_dir_all(&dir).unwrap();
    let rub = dir.join("jeffcott_seal.toml");
    std::fs::write(
        &rub,
        JEFFCOTT.replace("magnitude = 2e-5", "magnitude = 1e3")
            + "\n[[rubs]]\nname = \"seal\"\nnode = 5\ngap = 200e-6\n",
    )
    .unwrap();
    let shipped =
        std::path::PathBuf::from(concat!(env!("CARGO_MANIFEST_DIR"), "/models/jeffcott.toml"));
    let run = |model: &std::path::Path, speed: &[&str]| {
        let out = std::process::Command::new(env!("CARGO_BIN_EXE_rotor"))
            .arg("simulate")
            .arg(model)
            .args(speed)
            .args([
                "--duration",
                "0.05",
                "--local-error-tolerance",
                "0",
                "--csv",
            ])
            .arg(dir.join("run.csv"))
            .output()
            .unwrap();
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        String::from_utf8_lossy(&out.stderr).into_owned()
    };
    let stderr = run(&rub, &["--rpm", "3000"]);
    for contact in ["rub seal", "bearing left", "bearing right"] {
        let count = |what: &str| {
            stderr
                .lines()
                .filter(|l| {
                    l.starts_with(&format!("warning: {contact}: at t = ")) && l.contains(what)
                })
                .count()
        };
        assert_eq!(count("into its stator"), 1, "{contact}:\n{stderr}");
        assert_eq!(count("yield onset of steel"), 1, "{contact}:\n{stderr}");
    }
    let stderr = run(&shipped, &["--ramp-rpm", "0:3000"]);
    // No warning but the short film's validity (issue 47: these bearings
    // are longer than the short film's range, and it says so).
    assert!(
        !stderr
            .lines()
            .any(|l| l.contains("warning") && !l.contains("short film at")),
        "{stderr}"
    );
}
