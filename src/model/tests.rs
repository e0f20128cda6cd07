use super::*;
use crate::bearing::BearingKind;

pub(super) const BASE: &str = r#"
name = "t"
[[materials]]
name = "steel"
youngs_modulus = 211e9
shear_modulus = 81.2e9
density = 7810.0

[[shaft]]
length = 1.5
outer_diameter = 0.05
material = "steel"
elements = 6
"#;

pub(super) fn err_of(extra: &str) -> String {
    let text = format!("{BASE}{extra}");
    match RotorModel::from_toml(&text, "m.toml") {
        Ok(_) => panic!("expected an error for:\n{extra}"),
        Err(e) => e.to_string(),
    }
}

#[test]
fn default_model_is_the_classic_rotor() {
    let m = RotorModel::default_model();
    assert_eq!(m.name, DEFAULT_MODEL_NAME);
    assert_eq!(m.node_count(), 7);
    assert_eq!(m.elements.len(), 6);
    assert_eq!(m.disks[0].node, 3);
    assert!((m.disks[0].disk.mass - 32.590).abs() < 5e-4);
    assert_eq!(m.bearings.len(), 2);
    assert!((m.node_z[6] - 1.5).abs() < 1e-15);
}

#[test]
fn shipped_models_load() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("models");
    let mut count = 0;
    for entry in std::fs::read_dir(&dir).unwrap() {
        let path = entry.unwrap().path();
        if path.extension().is_some_and(|e| e == "toml") {
            let m = RotorModel::from_file(&path).unwrap_or_else(|e| panic!("{e}"));
            assert!(m.node_count() >= 2, "{}", path.display());
            count += 1;
        }
    }
    assert!(
        count >= 4,
        "expected the four shipped models, found {count}"
    );
}

#[test]
fn hydro_unit_has_the_papers_layout() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("models/hydro_unit.toml");
    let m = RotorModel::from_file(&path).unwrap();
    assert_eq!(m.elements.len(), 19);
    let probe_nodes: Vec<usize> = m.probes.iter().map(|p| p.node + 1).collect();
    assert_eq!(probe_nodes, vec![6, 11, 16]);
    assert_eq!(m.unbalances[0].node + 1, 5);
    // 15 kg·m at 150 rpm is the paper's ≈3700 N synchronous force.
    let w = 150.0 * std::f64::consts::PI / 30.0;
    let force = m.unbalances[0].magnitude * w * w;
    assert!((force - 3700.0).abs() < 0.01 * 3700.0, "{force}");
}

#[test]
fn bad_value_names_file_field_value_and_line() {
    let text = BASE.replace("outer_diameter = 0.05", "outer_diameter = -0.05");
    let e = RotorModel::from_toml(&text, "m.toml")
        .unwrap_err()
        .to_string();
    assert!(
        e.starts_with("m.toml:11: shaft[0].outer_diameter = -0.05"),
        "{e}"
    );
    assert!(e.contains("greater than zero"), "{e}");
}

#[test]
fn unknown_key_is_a_syntax_error_with_line() {
    let e = err_of("\n[[disks]]\nnode = 4\nmas = 3.0\n");
    assert!(e.starts_with("m.toml:17"), "{e}");
    assert!(e.contains("mas"), "{e}");
}

#[test]
fn unknown_bearing_type_is_rejected() {
    let e = err_of("\n[[bearings]]\ntype = \"magnetic\"\nnode = 1\n");
    assert!(e.contains("magnetic"), "{e}");
}

#[test]
fn semantic_errors_are_reported() {
    let cases = [
        (
            "\n[[disks]]\nnode = 9\nmass = 1.0\npolar_inertia = 0.1\ndiametral_inertia = 0.1\n",
            "disks[0].node = 9",
        ),
        (
            "\n[[disks]]\nz = 0.3\nmass = 1.0\npolar_inertia = 0.1\ndiametral_inertia = 0.1\n",
            "nearest is node 2",
        ),
        (
            "\n[[disks]]\nnode = 2\nmass = 1.0\n",
            "disks[0].polar_inertia",
        ),
        (
            "\n[[disks]]\nnode = 2\nmass = 1.0\npolar_inertia = 0.1\ndiametral_inertia = 0.1\nwidth = 0.1\n",
            "not both",
        ),
        (
            "\n[[disks]]\nnode = 2\nmaterial = \"brass\"\nouter_diameter = 0.2\nwidth = 0.1\n",
            "unknown material",
        ),
        (
            "\n[[probes]]\nname = \"a\"\nnode = 1\n[[probes]]\nname = \"a\"\nnode = 2\n",
            "duplicate probe",
        ),
        (
            "\n[[supports]]\nnode = 1\nfix = [\"x\", \"q\"]\n",
            "supports[0].fix[1] = \"q\"",
        ),
        (
            "\n[[bearings]]\ntype = \"linear\"\nnode = 1\nkxx = -5.0\n",
            "bearings[0].kxx = -5",
        ),
        (
            "\n[[unbalance]]\nnode = 4\nz = 0.75\nmagnitude = 1e-3\n",
            "not both",
        ),
        ("\n[[unbalance]]\nmagnitude = 1e-3\n", "needs node or z"),
        ("\ngravity = [0.0, -9.81]\n", "gravity"),
    ];
    for (extra, expect) in cases {
        let e = err_of(extra);
        assert!(e.contains(expect), "expected {expect:?} in: {e}");
        assert!(e.starts_with("m.toml"), "{e}");
    }
}

#[test]
fn material_from_poisson_ratio_and_bad_ratio() {
    let text = BASE.replace("shear_modulus = 81.2e9", "poisson_ratio = 0.3");
    let m = RotorModel::from_toml(&text, "m.toml").unwrap();
    let g = m.elements[0].element.material.shear_modulus;
    assert!((g - 211e9 / 2.6).abs() < 1.0);
    let text = BASE.replace("shear_modulus = 81.2e9", "shear_modulus = 10e9");
    let e = RotorModel::from_toml(&text, "m.toml")
        .unwrap_err()
        .to_string();
    assert!(e.contains("materials[0].shear_modulus"), "{e}");
}

#[test]
fn positions_by_z_and_supports() {
    let extra = "\n[[disks]]\nz = 0.75\nmass = 1.0\npolar_inertia = 0.1\ndiametral_inertia = 0.1\n\
                 [[supports]]\nnode = 1\nfix = [\"pinned\"]\n[[supports]]\nz = 1.5\nfix = [\"clamped\"]\n";
    let m = RotorModel::from_toml(&format!("{BASE}{extra}"), "m.toml").unwrap();
    assert_eq!(m.disks[0].node, 3);
    assert_eq!(m.supports[0].fixed, [true, true, false, false]);
    assert_eq!(m.supports[1].node, 6);
    assert_eq!(m.supports[1].fixed, [true; 4]);
}

#[test]
fn missing_file_is_an_io_error() {
    let e = RotorModel::from_file(Path::new("/no/such/model.toml")).unwrap_err();
    assert!(
        e.to_string()
            .starts_with("/no/such/model.toml: cannot read"),
        "{e}"
    );
}

#[test]
fn hydrodynamic_bearings_parse() {
    let extra = r#"
[[bearings]]
name = "plain"
type = "plain"
node = 1
radius = 0.05
journal_collar = true
length = 0.03
clearance = 1e-4
viscosity = 0.02

[[bearings]]
name = "tilting"
type = "tilting_pad"
node = 7
radius = 0.05
journal_collar = true
length = 0.03
clearance = 1e-4
viscosity = 0.02
pads = 4
first_pivot_deg = 45.0
pad_arc_deg = 80.0
preload = 0.1
"#;
    let m = RotorModel::from_toml(&format!("{BASE}{extra}"), "m.toml").unwrap();
    match &m.bearings[0].kind {
        BearingKind::Plain(b) => assert_eq!(b.clearance, 1e-4),
        k => panic!("{k:?}"),
    }
    match &m.bearings[1].kind {
        BearingKind::TiltingPad(b) => {
            assert_eq!(b.pads.len(), 4);
            assert!((b.pads[1].pivot() - 135f64.to_radians()).abs() < 1e-15);
            assert_eq!(b.pads[0].offset(), 0.5);
            assert_eq!(b.pads[0].preload(), 0.1);
        }
        k => panic!("{k:?}"),
    }
}

#[test]
fn hydrodynamic_bearing_errors() {
    let tp = "\n[[bearings]]\ntype = \"tilting_pad\"\nnode = 1\nradius = 0.05\njournal_collar = true\nlength = 0.03\nclearance = 1e-4\nviscosity = 0.02\n";
    let cases = [
        (format!("{tp}pads = 2\npad_arc_deg = 80.0\n"), "bearings[0].pads = 2"),
        (format!("{tp}pads = 4\npad_arc_deg = 100.0\n"), "pads overlap"),
        (format!("{tp}pads = 4\npivots_deg = [0.0, 90.0, 180.0, 270.0]\npad_arc_deg = 60.0\n"), "either pads"),
        (format!("{tp}pads = 4\npad_arc_deg = 60.0\npreload = 1.0\n"), "bearings[0].preload = 1"),
        (format!("{tp}pads = 4\npad_arc_deg = 60.0\npivot_offset = 1.5\n"), "pivot_offset = 1.5"),
        (format!("{tp}pads = 4\npad_arc_deg = 60.0\npivot_stiffness = 0.0\n"), "bearings[0].pivot_stiffness = 0"),
        (format!("{tp}pads = 4\npad_arc_deg = 60.0\npivot_stiffness = 1e20\n"), "m.toml:25: bearings[0].pivot_stiffness = 1e20: must lie in [1, 1e15] N/m"),
        (format!("{tp}pads = 4\npad_arc_deg = 60.0\npad_inertia = -1.0\n"), "bearings[0].pad_inertia = -1"),
        (format!("{tp}pads = 4\npad_arc_deg = 60.0\npad_mass = 2.0\n"), "bearings[0].pad_mass = 2: needs pivot_stiffness"),
        (format!("{tp}pads = 4\npad_arc_deg = 60.0\npivot_damping = 5.0\n"), "bearings[0].pivot_damping = 5: needs pivot_stiffness"),
        (format!("{tp}pads = 4\npad_arc_deg = 60.0\npivot_stiffness = 1e9\npivot_damping = -5.0\n"), "bearings[0].pivot_damping = -5"),
        (
            "\n[[bearings]]\ntype = \"plain\"\nnode = 1\nradius = 0.05\njournal_collar = true\nlength = 0.03\nclearance = 0.01\nviscosity = 0.02\n".to_string(),
            "bearings[0].clearance = 0.01",
        ),
        (
            "\n[[bearings]]\ntype = \"plain\"\nnode = 1\nradius = 0.05\njournal_collar = true\nlength = 0.03\nclearance = 1e-4\nviscosity = -0.02\n".to_string(),
            "bearings[0].viscosity = -0.02",
        ),
    ];
    for (extra, expect) in cases {
        let e = err_of(&extra);
        assert!(e.contains(expect), "expected {expect:?} in: {e}");
    }
}

/// 1-based line of the `nth` (0-based) occurrence of `needle` in `BASE + extra`.
pub(super) fn line_in(extra: &str, needle: &str, nth: usize) -> usize {
    let text = format!("{BASE}{extra}");
    let at = text.match_indices(needle).nth(nth).unwrap().0;
    text[..at].matches('\n').count() + 1
}

#[test]
fn duplicate_names_are_rejected_with_path_value_and_line() {
    let disk = "mass = 1.0\npolar_inertia = 0.1\ndiametral_inertia = 0.1\n";
    let cases = [
        (
            format!(
                "\n[[disks]]\nname = \"d\"\nnode = 2\n{disk}[[disks]]\nname = \"d\"\nnode = 3\n{disk}"
            ),
            "disks[1].name = d: duplicate disk name",
        ),
        (
            "\n[[bearings]]\ntype = \"linear\"\nname = \"b\"\nnode = 1\nkxx = 1e6\n\
             [[bearings]]\ntype = \"linear\"\nname = \"b\"\nnode = 7\nkxx = 1e6\n"
                .to_string(),
            "bearings[1].name = b: duplicate bearing name",
        ),
        (
            "\n[[unbalance]]\nname = \"u\"\nnode = 2\nmagnitude = 1e-3\n\
             [[unbalance]]\nname = \"u\"\nnode = 3\nmagnitude = 1e-3\n"
                .to_string(),
            "unbalance[1].name = u: duplicate unbalance name",
        ),
        (
            "\n[[probes]]\nname = \"p\"\nnode = 2\n[[probes]]\nname = \"p\"\nnode = 3\n"
                .to_string(),
            "probes[1].name = p: duplicate probe name",
        ),
    ];
    for (extra, expect) in &cases {
        let e = err_of(extra);
        let name = &expect[expect.find("= ").unwrap() + 2..expect.find(':').unwrap()];
        let line = line_in(extra, &format!("name = \"{name}\""), 1);
        assert_eq!(e, format!("m.toml:{line}: {expect}"));
    }
    // A given name may not take the default name of another entry either.
    let e = err_of(
        "\n[[bearings]]\ntype = \"linear\"\nnode = 1\n\
         [[bearings]]\ntype = \"linear\"\nname = \"bearing1\"\nnode = 7\n",
    );
    assert!(
        e.contains("bearings[1].name = bearing1: duplicate bearing name"),
        "{e}"
    );
}

#[test]
fn zero_or_negative_disk_mass_or_negative_inertia_is_rejected() {
    for (key, bad, problem) in [
        ("mass", "0.0", "must be a finite number greater than zero"),
        ("mass", "-2.0", "must be a finite number greater than zero"),
        (
            "polar_inertia",
            "-0.1",
            "must be a finite number not less than zero",
        ),
        (
            "diametral_inertia",
            "-0.1",
            "must be a finite number not less than zero",
        ),
    ] {
        let mut fields = [
            ("mass", "1.0"),
            ("polar_inertia", "0.1"),
            ("diametral_inertia", "0.1"),
        ];
        fields.iter_mut().find(|f| f.0 == key).unwrap().1 = bad;
        let body: String = fields.iter().map(|(k, v)| format!("{k} = {v}\n")).collect();
        let extra = format!("\n[[disks]]\nnode = 2\n{body}");
        let e = err_of(&extra);
        let line = line_in(&extra, &format!("{key} = {bad}"), 0);
        let value: f64 = bad.parse().unwrap();
        assert_eq!(
            e,
            format!("m.toml:{line}: disks[0].{key} = {value}: {problem}")
        );
    }
}

#[test]
fn type_errors_name_the_field_path_and_line() {
    let disk = "\n[[disks]]\nnode = 4\nmass = 1.0\npolar_inertia = 0.1\ndiametral_inertia = 0.1\n";
    let cases = [
        (
            BASE.replace("elements = 6", "elements = inf"),
            "elements = inf",
            "shaft[0].elements: invalid type",
        ),
        (
            BASE.replace("density = 7810.0", "density = \"heavy\""),
            "density =",
            "materials[0].density: invalid type",
        ),
        (
            format!("{BASE}{}", disk.replace("node = 4", "node = 4.5")),
            "node = 4.5",
            "disks[0].node: invalid type",
        ),
        (
            format!("gravity = [0.0, \"down\", 0.0]{BASE}"),
            "\"down\"",
            "gravity[1]: invalid type",
        ),
        (
            format!("{BASE}\n[[probes]]\nname = 3\nnode = 2\n"),
            "name = 3",
            "probes[0].name: invalid type",
        ),
        (
            format!("{BASE}\n[[supports]]\nnode = 1\nfix = \"x\"\n"),
            "fix = ",
            "supports[0].fix: invalid type",
        ),
        (
            format!("{BASE}{}", disk.replace("mass = 1.0", "mas = 1.0")),
            "mas = 1.0",
            "disks[0].mas: unknown field `mas`",
        ),
        (
            format!("speed_rpm = true{BASE}"),
            "speed_rpm",
            "speed_rpm: invalid type",
        ),
    ];
    for (text, at, expect) in &cases {
        let e = RotorModel::from_toml(text, "m.toml")
            .unwrap_err()
            .to_string();
        let offset = text.find(at).unwrap();
        let line = text[..offset].matches('\n').count() + 1;
        assert!(
            e.starts_with(&format!("m.toml:{line}: {expect}")),
            "expected m.toml:{line}: {expect}…, got: {e}"
        );
    }
    // Bearings are an internally tagged enum: serde buffers the entry, so its
    // span is the whole entry; the key holding the offending value is found in
    // the entry and named with its own line.
    let text = format!(
        "{BASE}\n[[bearings]]\ntype = \"plain\"\nnode = 1\nradius = \"big\"\nlength = 0.02\nclearance = 1e-4\nviscosity = 0.02\n"
    );
    let e = RotorModel::from_toml(&text, "m.toml")
        .unwrap_err()
        .to_string();
    assert!(
        e.starts_with("m.toml:18: bearings[0].radius: invalid type: string \"big\""),
        "{e}"
    );
    // Broken TOML keeps its parser message and line.
    let e = RotorModel::from_toml(&format!("{BASE}\nspeed_rpm = = 3\n"), "m.toml")
        .unwrap_err()
        .to_string();
    assert!(
        e.starts_with("m.toml:15: ") && e.contains("extra `=`"),
        "{e}"
    );
}

#[test]
fn a_model_beyond_the_memory_budget_is_refused_before_allocating() {
    // Three sections of 10⁶ elements: 12 million DOFs, about 18 GB.
    let section = r#"
[[shaft]]
length = 1.0
outer_diameter = 0.05
material = "steel"
elements = 1000000
"#;
    let text = format!("{BASE}{section}{section}{section}");
    let start = std::time::Instant::now();
    let e = RotorModel::from_toml(&text, "huge.toml")
        .unwrap_err()
        .to_string();
    assert!(
        start.elapsed() < std::time::Duration::from_secs(1),
        "checked before building"
    );
    assert!(
        e.contains("huge.toml") && e.contains("memory_budget_mb") && e.contains("3000006 elements"),
        "{e}"
    );
    // The budget is the model's to set: a tight one refuses even this small rotor…
    let tight = format!("memory_budget_mb = 0.01\n{BASE}");
    let e = RotorModel::from_toml(&tight, "m.toml")
        .unwrap_err()
        .to_string();
    assert!(e.contains("0.01"), "{e}");
    // …and the default accepts it (7 nodes, 28 DOFs: 43 kB).
    assert!(RotorModel::from_toml(BASE, "m.toml").is_ok());
}

#[test]
fn a_type_error_in_a_later_bearing_names_that_bearing_and_key() {
    // serde's span for an internally tagged entry can be an earlier sibling's.
    let bearing = |name: &str, node: &str| {
        format!("\n[[bearings]]\nname = \"{name}\"\ntype = \"linear\"\nnode = {node}\nkxx = 1e6\n")
    };
    let text = format!("{BASE}{}{}", bearing("a", "1"), bearing("b", "inf"));
    let e = RotorModel::from_toml(&text, "m.toml")
        .unwrap_err()
        .to_string();
    let line = text.lines().position(|l| l == "node = inf").unwrap() + 1;
    assert!(
        e.starts_with(&format!("m.toml:{line}: bearings[1].node: invalid type")),
        "{e}"
    );
}

#[test]
fn stated_maximum_speed_is_told_from_the_default() {
    let m = RotorModel::from_toml(BASE, "m.toml").unwrap();
    assert!(!m.max_speed_stated);
    assert!((m.max_speed * 30.0 / std::f64::consts::PI - DEFAULT_MAX_SPEED_RPM).abs() < 1e-9);
    let m = RotorModel::from_toml(&format!("max_speed_rpm = 5000.0\n{BASE}"), "m.toml").unwrap();
    assert!(m.max_speed_stated);
}

/// `[reduction]` asks for a reduced rotor: the documented default count
/// without `modes`, the count given, and a count out of range is refused
/// with the field, value and line.
#[test]
fn reduction_section_sets_the_mode_count() {
    let m = RotorModel::from_toml(BASE, "m.toml").unwrap();
    assert_eq!(m.reduction, None);
    let m = RotorModel::from_toml(&format!("{BASE}\n[reduction]\n"), "m.toml").unwrap();
    assert_eq!(m.reduction, Some(ReductionRequest::FromSpeedRange));
    let m = RotorModel::from_toml(&format!("{BASE}\n[reduction]\nmodes = 4\n"), "m.toml").unwrap();
    assert_eq!(m.reduction, Some(ReductionRequest::Modes(4)));
    for bad in ["0", "-3", "1001"] {
        let e = err_of(&format!("\n[reduction]\nmodes = {bad}\n"));
        assert!(e.contains("reduction.modes") && e.contains(bad), "{e}");
        assert!(e.contains("m.toml:16"), "{e}");
    }
    let e = err_of("\n[reduction]\nnodes = 4\n");
    assert!(e.contains("nodes"), "{e}");
}

#[test]
fn operating_range_is_read_in_rad_s_and_bad_ranges_are_refused() {
    let m = RotorModel::from_toml(
        &format!("operating_rpm = [8000.0, 11500.0]\n{BASE}"),
        "m.toml",
    )
    .unwrap();
    let [a, b] = m.operating_range.unwrap();
    assert_eq!(a, 8000.0 * std::f64::consts::PI / 30.0);
    assert_eq!(b, 11500.0 * std::f64::consts::PI / 30.0);
    assert!(
        RotorModel::from_toml(BASE, "m.toml")
            .unwrap()
            .operating_range
            .is_none()
    );
    for (range, problem) in [
        ("[0.0, 100.0]", "greater than zero"),
        ("[200.0, 100.0]", "min ≤ max"),
        ("[1.0, 2.0, 3.0]", "[min, max]"),
        ("[100.0, 1e6]", "max_speed_rpm"),
    ] {
        let text = format!("max_speed_rpm = 20000.0\noperating_rpm = {range}\n{BASE}");
        let e = RotorModel::from_toml(&text, "m.toml")
            .unwrap_err()
            .to_string();
        assert!(
            e.contains("m.toml:2:") && e.contains("operating_rpm"),
            "{range}: {e}"
        );
        assert!(e.contains(problem), "{range}: {e}");
    }
}
