//! `rotor operating-point` and `analysis::operating_point` against the
//! quadrature oracles of `tests/data/`: the plain short bearing and the
//! four-pad tilting-pad bearing, each carrying W = 1000 N along −y at
//! ω = 314.16 rad/s, built as a one-bearing rotor whose whole weight is W.

use rotor_bearing::report::text::short;
use std::path::PathBuf;
use std::process::Command;

use serde_json::Value;

#[path = "common/reference.rs"]
mod reference;
use reference::{mat, num, reference};

use rotor_bearing::analysis::operating_point::operating_point;
use rotor_bearing::model::RotorModel;
use rotor_bearing::rotor::Rotor;
use rotor_bearing::units::RAD_S_TO_RPM;

/// A rotor of one shaft element (rotations fixed at both nodes) whose only
/// bearing, at node 1, carries its whole weight, scaled to exactly `W` by
/// choosing gravity `g = W / m`.
fn one_bearing_rotor(bearing: &str, load: f64) -> (String, RotorModel) {
    let text = format!(
        r#"
name = "one_bearing"
gravity = [0.0, -9.81, 0.0]
[[materials]]
name = "steel"
youngs_modulus = 2e11
poisson_ratio = 0.3
density = 7800.0
[[shaft]]
length = 0.2
outer_diameter = 0.1
material = "steel"
elements = 1
[[disks]]
node = 2
mass = 50.0
polar_inertia = 0.1
diametral_inertia = 0.05
[[bearings]]
name = "journal"
node = 1
{bearing}
[[supports]]
node = 1
fix = ["rx", "ry"]
[[supports]]
node = 2
fix = ["rx", "ry"]
"#
    );
    let mut model = RotorModel::from_toml(&text, "one_bearing.toml").unwrap();
    let g = load / model.total_mass();
    model.gravity = [0.0, -g, 0.0];
    (text.replace("-9.81", &format!("{:?}", -g)), model)
}

fn plain_bearing(p: &Value) -> String {
    format!(
        "type = \"plain\"\nradius = {:?}\nlength = {:?}\nclearance = {:?}\nviscosity = {:?}",
        num(&p["R"]),
        num(&p["L"]),
        num(&p["C"]),
        num(&p["mu"])
    )
}

fn rel(a: f64, b: f64) -> f64 {
    (a - b).abs() / b.abs()
}

#[test]
fn plain_bearing_operating_point_matches_the_short_bearing_reference() {
    let r = reference("short_bearing_reference.json");
    let p = &r["parameters"];
    let (_, model) = one_bearing_rotor(&plain_bearing(p), num(&p["W"]));
    let rotor = Rotor::new(model).unwrap();
    let points = operating_point(&rotor, num(&p["omega"])).unwrap();
    let b = &points[0];
    let film = b.film.as_ref().unwrap();
    let eq = &r["equilibrium"];
    let co = &r["coefficients_at_equilibrium"];
    let (k, c) = (mat(&co["K"]), mat(&co["C"]));
    eprintln!(
        "ε {} (ref {}), attitude {}° (ref {}), h_min {} m",
        film.eccentricity,
        num(&eq["eps"]),
        film.attitude_angle.to_degrees(),
        num(&eq["attitude_deg"]),
        film.min_film_thickness
    );
    // The static solve stops at a relative residual of 1e-8 of the load.
    assert!(rel(b.load, num(&p["W"])) < 1e-8, "load {}", b.load);
    assert!(rel(film.eccentricity, num(&eq["eps"])) < 1e-6);
    assert!(rel(film.attitude_angle.to_degrees(), num(&eq["attitude_deg"])) < 1e-6);
    assert!(rel(film.min_film_thickness, num(&eq["h_min"])) < 1e-6);
    let clearance = num(&p["C"]);
    assert!(
        rel(
            film.min_film_thickness,
            clearance * (1.0 - film.eccentricity)
        ) < 1e-12
    );
    let mut worst: f64 = 0.0;
    for i in 0..2 {
        for j in 0..2 {
            worst = worst
                .max(rel(b.stiffness[i][j], k[(i, j)]))
                .max(rel(b.damping[i][j], c[(i, j)]));
            assert!(rel(b.stiffness[i][j], k[(i, j)]) < 1e-6, "K{i}{j}");
            assert!(rel(b.damping[i][j], c[(i, j)]) < 1e-6, "C{i}{j}");
        }
    }
    eprintln!("worst relative error of K and C: {worst:.1e}");
    // Petroff-corrected friction torque over the whole film, T = 2π μ ω R³ L / (C √(1 − ε²)),
    // and its power T ω.
    let (mu, omega, radius, length) = (num(&p["mu"]), num(&p["omega"]), num(&p["R"]), num(&p["L"]));
    let eps = film.eccentricity;
    let torque = 2.0 * std::f64::consts::PI * mu * omega * radius.powi(3) * length
        / (clearance * (1.0 - eps * eps).sqrt());
    assert!(rel(film.friction_torque, torque) < 1e-12);
    assert!(rel(film.power_loss, torque * omega) < 1e-12);
}

fn out_dir(name: &str) -> PathBuf {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join(name);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// Header and rows (text cells) of a CSV file.
fn read_csv(path: &std::path::Path) -> Vec<std::collections::BTreeMap<String, String>> {
    let text = std::fs::read_to_string(path).unwrap();
    let mut lines = text.lines();
    let header: Vec<String> = lines.next().unwrap().split(',').map(String::from).collect();
    lines
        .map(|l| {
            header
                .iter()
                .cloned()
                .zip(l.split(',').map(String::from))
                .collect()
        })
        .collect()
}

#[test]
fn command_prints_and_writes_the_reference_operating_point() {
    let r = reference("short_bearing_reference.json");
    let p = &r["parameters"];
    let (text, _) = one_bearing_rotor(&plain_bearing(p), num(&p["W"]));
    let dir = out_dir("operating_point");
    let (model, csv) = (dir.join("one_bearing.toml"), dir.join("op.csv"));
    std::fs::write(&model, text).unwrap();
    let rpm = num(&p["omega"]) * RAD_S_TO_RPM;
    let out = Command::new(env!("CARGO_BIN_EXE_rotor"))
        .arg("operating-point")
        .arg(&model)
        .args(["--rpm", &format!("{rpm:?}"), "--csv"])
        .arg(&csv)
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    // ε = 0.586463, φ = 47.3274°, h_min = C(1 − ε) = 41.3537 µm, 1000 N.
    for needle in [
        "static load 1000 N",
        "eccentricity ratio 0.586463",
        "attitude angle 47.3274°",
        "minimum film thickness 41.3537 µm",
        "K = [[2.10807e7, 3757590], [-4.10333e7, 3.78281e7]] N/m",
        "C = [[74331.9, -68525.7], [-68525.7, 210815]] N·s/m",
    ] {
        assert!(stdout.contains(needle), "{needle} not in\n{stdout}");
    }
    let rows = read_csv(&csv);
    let row = &rows[0];
    let eq = &r["equilibrium"];
    let get = |k: &str| -> f64 { row[k].parse().unwrap() };
    assert_eq!(row["bearing"], "journal");
    assert!(rel(get("eccentricity"), num(&eq["eps"])) < 1e-6);
    assert!(rel(get("attitude_angle_deg"), num(&eq["attitude_deg"])) < 1e-6);
    assert!(
        rel(
            get("min_film_thickness_m"),
            num(&p["C"]) * (1.0 - get("eccentricity"))
        ) < 1e-12
    );
    let k = mat(&r["coefficients_at_equilibrium"]["K"]);
    assert!(rel(get("kyx_N_m"), k[(1, 0)]) < 1e-6);
    let out = Command::new(env!("CARGO_BIN_EXE_rotor"))
        .arg("operating-point")
        .arg(&model)
        .args(["--rpm", "0"])
        .output()
        .unwrap();
    // At standstill the journal rests on its bushing: the contact carries the
    // load and the friction torque is the breakaway torque μ W R (μ = 0.2).
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let w = num(&p["W"]);
    let breakaway = 0.2 * w * num(&p["R"]);
    assert!(
        stdout.contains("minimum film thickness 0 µm")
            && stdout.contains(&format!("in contact: normal force {}", short(w)))
            && stdout.contains(&format!("friction torque {} N·m", short(breakaway))),
        "{stdout}"
    );
}

#[test]
fn tilting_pad_operating_point_matches_the_pad_reference() {
    let r = reference("tilting_pad_reference.json");
    let p = &r["parameters"];
    let pivots: Vec<String> = p["pivots_deg"]
        .as_array()
        .unwrap()
        .iter()
        .map(|d| format!("{:?}", num(d)))
        .collect();
    let bearing = format!(
        "type = \"tilting_pad\"\nradius = {:?}\nlength = {:?}\nclearance = {:?}\nviscosity = {:?}\npad_arc_deg = {:?}\npivots_deg = [{}]\npivot_offset = {:?}\npreload = {:?}",
        num(&p["R"]),
        num(&p["L"]),
        num(&p["C"]),
        num(&p["mu"]),
        num(&p["pad_arc_deg"]),
        pivots.join(", "),
        num(&p["pivot_offset"]),
        num(&p["preload"])
    );
    let (text, model) = one_bearing_rotor(&bearing, num(&p["W"]));
    let rotor = Rotor::new(model).unwrap();
    let points = operating_point(&rotor, num(&p["omega"])).unwrap();
    let film = points[0].film.as_ref().unwrap();
    // The command's pad table holds the same tilts and film thicknesses.
    let dir = out_dir("operating_point_pads");
    let (path, pads_csv) = (dir.join("pads.toml"), dir.join("pads.csv"));
    std::fs::write(&path, text).unwrap();
    let rpm = num(&p["omega"]) * RAD_S_TO_RPM;
    let out = Command::new(env!("CARGO_BIN_EXE_rotor"))
        .arg("operating-point")
        .arg(&path)
        .args(["--rpm", &format!("{rpm:?}"), "--pads-csv"])
        .arg(&pads_csv)
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let rows = read_csv(&pads_csv);
    assert_eq!(rows.len(), 4);
    for (row, pad) in rows.iter().zip(&film.pads) {
        let get = |k: &str| -> f64 { row[k].parse().unwrap() };
        assert_eq!(row["bearing"], "journal");
        assert!((get("pivot_deg") - pad.pivot.to_degrees()).abs() < 1e-12);
        assert!(rel(get("tilt_m"), pad.tilt) < 1e-6);
        assert!(rel(get("min_film_thickness_m"), pad.min_film_thickness) < 1e-6);
    }
    let eq = &r["equilibrium"];
    // The oracle's tolerance (tests/tilting_pad_reference.rs): 1e-5.
    assert!(
        rel(film.eccentricity, num(&eq["eps"])) < 1e-5,
        "ε {}",
        film.eccentricity
    );
    assert_eq!(film.pads.len(), 4);
    for pad in eq["pads"].as_array().unwrap() {
        let k = pad["pad"].as_u64().unwrap() as usize;
        let mine = film.pads[k];
        assert!((mine.pivot.to_degrees() - num(&pad["pivot_deg"])).abs() < 1e-12);
        if pad["loaded"].as_bool().unwrap() {
            assert!(
                rel(mine.tilt, num(&pad["eta"])) < 1e-5,
                "pad {k} η {}",
                mine.tilt
            );
            assert!(rel(mine.tilt_angle, num(&pad["psi_rad"])) < 1e-5);
            assert!(
                rel(mine.min_film_thickness, num(&pad["h_min"])) < 1e-5,
                "pad {k} h_min {}",
                mine.min_film_thickness
            );
        }
    }
    let smallest = film
        .pads
        .iter()
        .map(|p| p.min_film_thickness)
        .fold(f64::INFINITY, f64::min);
    assert_eq!(film.min_film_thickness, smallest);
    let sync = &r["synchronous_reduced"];
    let (k, c) = (mat(&sync["K"]), mat(&sync["C"]));
    let b = &points[0];
    for i in 0..2 {
        assert!(
            rel(b.stiffness[i][i], k[(i, i)]) < 1e-5,
            "K{i}{i} {}",
            b.stiffness[i][i]
        );
        assert!(
            rel(b.damping[i][i], c[(i, i)]) < 1e-5,
            "C{i}{i} {}",
            b.damping[i][i]
        );
        // Cross-coupling below 1e-3 of the direct terms (the oracle's own limit).
        assert!(b.stiffness[i][1 - i].abs() < 1e-3 * k[(i, i)]);
    }
}

/// A vertical rotor's journals carry no lateral load: the pad forces of the
/// hydro unit's centred tilting-pad journals sum to 1e-10 N (round-off of
/// forces of 10⁵ N), and the coefficients' cross terms to 1e-8 of the direct
/// ones. They print as an unloaded journal with no attitude angle and zero
/// cross-coupling, never as `9.8e-11 N` at some angle.
#[test]
fn centred_vertical_journals_print_as_unloaded() {
    let model = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("models/hydro_unit.toml");
    let out = Command::new(env!("CARGO_BIN_EXE_rotor"))
        .arg("operating-point")
        .arg(&model)
        .args(["--rpm", "150"])
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    for bearing in ["generator_guide", "turbine_guide"] {
        let block = stdout
            .split(&format!("bearing {bearing} at 150 rpm:\n"))
            .nth(1)
            .expect(&stdout);
        let lines: Vec<&str> = block.lines().take(5).collect();
        assert_eq!(
            lines[0],
            "  static load 0 N (unloaded), journal at x = 0 µm, y = 0 µm"
        );
        assert!(
            lines[1].starts_with(
                "  eccentricity e/C_b (bearing clearance) 0, e/C_p (pad clearance) 0, attitude angle —, "
            ),
            "{}",
            lines[1]
        );
        assert!(
            lines[3].starts_with("  K = [[2.06697e9, 0], [0, 2.06697e9]]"),
            "{}",
            lines[3]
        );
        assert!(
            lines[4].starts_with("  C = [[1.65541e8, 0], [0, 1.65541e8]]"),
            "{}",
            lines[4]
        );
    }
    // The library's numbers are the round-off the text hides.
    let rotor = Rotor::new(rotor_bearing::model::RotorModel::from_file(&model).unwrap()).unwrap();
    let points = operating_point(&rotor, 150.0 / RAD_S_TO_RPM).unwrap();
    for p in &points {
        assert!(p.is_unloaded() && p.load < 1e-9, "{}: {}", p.name, p.load);
        assert!(p.stiffness[0][1].abs() < 1e-7 * p.stiffness[0][0]);
    }
    // A loaded journal is not: the horizontal Jeffcott rotor.
    let jeffcott = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("models/jeffcott.toml");
    let rotor =
        Rotor::new(rotor_bearing::model::RotorModel::from_file(&jeffcott).unwrap()).unwrap();
    let points = operating_point(&rotor, 3000.0 / RAD_S_TO_RPM).unwrap();
    assert!(points.iter().all(|p| !p.is_unloaded() && p.load > 100.0));
}

/// Issue 48: a tilting-pad bearing's "eccentricity" is `e/C_b`, the journal's
/// offset over the assembled clearance `C_b = C (1 − m)`, not over the pad
/// clearance `C`, and the documents did not say so (an engineer read 1.24 at
/// rest as a journal through its pads). The four-pad bearing of the oracle
/// with preload m = 0.4, loaded between two pads, at rest: the reported
/// eccentricity is `√(x² + y²)/(C (1 − m))` of the reported journal position
/// (1e-12), above 1 although `e/C` is below 1 and the film is not crossed
/// (thinnest film ≥ 0); the operating-point paragraph of `docs/commands.md`,
/// the FMU outputs of `docs/fmu.md`, `docs/bearings.md` and the FMU's own
/// variable description say `e/C_b`, and so does the printed operating
/// point, with `e/C_p = e/C` (over the pad clearance) beside it.
#[test]
fn a_tilting_pad_eccentricity_is_over_the_assembled_clearance_and_says_so() {
    let (c, m) = (1e-4, 0.4);
    let bearing = format!(
        "type = \"tilting_pad\"\nradius = 0.05\nlength = 0.03\nclearance = {c:?}\nviscosity = 0.02\npad_arc_deg = 80.0\npivots_deg = [45.0, 135.0, 225.0, 315.0]\npreload = {m:?}"
    );
    let (text, model) = one_bearing_rotor(&bearing, 600.0);
    let dir = out_dir("operating_point_preload");
    let (path, csv) = (dir.join("preload.toml"), dir.join("preload.csv"));
    std::fs::write(&path, text).unwrap();
    let out = Command::new(env!("CARGO_BIN_EXE_rotor"))
        .arg("operating-point")
        .arg(&path)
        .args(["--rpm", "0", "--csv"])
        .arg(&csv)
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let row = &read_csv(&csv)[0];
    let get = |k: &str| -> f64 { row[k].parse().unwrap() };
    let e = get("x_m").hypot(get("y_m"));
    let ratio = get("eccentricity");
    assert!(
        rel(ratio, e / (c * (1.0 - m))) < 1e-12,
        "{ratio} against e/C_b = {}",
        e / (c * (1.0 - m))
    );
    assert!(
        ratio > 1.0 && e / c < 1.0,
        "e/C_b = {ratio}, e/C = {}",
        e / c
    );
    assert!(get("min_film_thickness_m") >= 0.0);
    assert!(rel(get("eccentricity_pad_clearance"), e / c) < 1e-12);
    // The printed label names the clearance, and gives e/C_p beside it.
    let stdout = String::from_utf8_lossy(&out.stdout);
    let label = format!(
        "  eccentricity e/C_b (bearing clearance) {}, e/C_p (pad clearance) {}, attitude angle ",
        short(ratio),
        short(e / c)
    );
    assert!(
        stdout.lines().any(|l| l.starts_with(&label)),
        "{label} in\n{stdout}"
    );
    let doc = |name: &str| {
        std::fs::read_to_string(PathBuf::from(env!("CARGO_MANIFEST_DIR")).join(name)).unwrap()
    };
    let commands = doc("docs/commands.md");
    let paragraph = commands
        .split("\n\n")
        .find(|p| p.starts_with("`operating-point` puts the rotor"))
        .expect("the operating-point paragraph");
    assert!(paragraph.contains("e/C_b"), "{paragraph}");
    let fmu = doc("docs/fmu.md");
    let outputs = fmu
        .lines()
        .skip_while(|l| !l.contains("`bearings.<b>.{x,y,fx,fy,eccentricity,friction_torque}`"))
        .take(8)
        .collect::<Vec<_>>()
        .join("\n");
    assert!(outputs.contains("e/C_b"), "{outputs}");
    assert!(doc("docs/bearings.md").contains("e/C_b"));
    let vars = rotor_bearing::fmi2::variables::variables(&model);
    let described = vars
        .iter()
        .find(|v| v.name == "bearings.journal.eccentricity")
        .map(|v| v.description.clone())
        .unwrap();
    assert!(described.contains("e/C_b"), "{described}");
}

/// The elements that are not bearings (issue 48): the unit on brackets with
/// its field at 2 × nominal at 300 rpm, held off the centre — its guide
/// bearings', seal's and pull's forces on the rotor at the equilibrium sum to
/// zero (no lateral gravity, its static forces zero) within 1e-9 of the
/// pull's; the torque-driven unit's thrust bearing at its speed — the power
/// loss of Petroff's film plus the fading boundary friction, written out here
/// from the model's numbers (1e-12); and `rotor operating-point` prints them.
#[test]
fn seals_pulls_thrust_bearings_and_forces_have_an_operating_point() {
    use rotor_bearing::analysis::element_operating_point::{
        element_operating_points, force_operating_points, thrust_operating_points,
    };
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    let mut model = RotorModel::from_file(&root.join("models/hydro_unit_brackets.toml")).unwrap();
    for b in &mut model.bearings {
        b.kind.set_excitation(2.0);
    }
    let rotor = Rotor::new(model).unwrap();
    let speed = 300.0 / RAD_S_TO_RPM;
    let bearings = operating_point(&rotor, speed).unwrap();
    let elements = element_operating_points(&rotor, speed).unwrap();
    let names: Vec<&str> = elements.iter().map(|e| e.name.as_str()).collect();
    assert_eq!(names, ["runner_seal", "generator"]);
    let mut sum = [0.0; 2];
    for f in bearings
        .iter()
        .map(|b| b.force)
        .chain(elements.iter().map(|e| e.force))
    {
        sum[0] += f[0];
        sum[1] += f[1];
    }
    let pull = elements[1].force[0].hypot(elements[1].force[1]);
    assert!(pull > 1e5, "{pull}");
    assert!(
        sum[0].hypot(sum[1]) <= 1e-9 * pull,
        "{sum:?} against {pull}"
    );
    let forces = force_operating_points(&rotor, speed);
    assert_eq!(forces.len(), rotor.model.forces.len());

    let path = root.join("models/hydro_unit_torque.toml");
    let torque = Rotor::new(RotorModel::from_file(&path).unwrap()).unwrap();
    let w = torque.model.nominal_speed;
    let t = &torque.model.thrust_bearings[0].bearing;
    // T = c π μ ω (R_o⁴ − R_i⁴) / (2 h) + μ_b W R_m φ(ω) e^{−ω/ω_l}.
    let film = t.coverage
        * std::f64::consts::PI
        * t.viscosity
        * w
        * (t.outer_radius.powi(4) - t.inner_radius.powi(4))
        / (2.0 * t.film_thickness);
    let eps = 1e-3 * t.lift_off_speed;
    let boundary = if t.oil_lift { 0.0 } else { t.boundary_friction }
        * t.load
        * 0.5
        * (t.inner_radius + t.outer_radius)
        * (w / (w * w + eps * eps).sqrt())
        * (-w / t.lift_off_speed).exp();
    let hand = (film + boundary) * w;
    let thrust = thrust_operating_points(&torque, w);
    assert!(
        (thrust[0].power_loss - hand).abs() <= 1e-12 * hand,
        "{thrust:?} {hand}"
    );
    let out = Command::new(env!("CARGO_BIN_EXE_rotor"))
        .args(["operating-point", path.to_str().unwrap()])
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(
        stdout.contains(&format!("power loss {} W", short(hand))),
        "{stdout}"
    );
}
