//! Model-file tests of the whole machine's sections: zero-inertia disks,
//! `[[pedestals]]`, `[[seals]]`, `[[point_masses]]`, `[[magnetic_pull]]`,
//! `[[forces]]`, `[[ports]]` and their plausibility warnings.

use super::RotorModel;
use super::tests::{BASE, err_of, line_in};

/// A disk with zero inertias is a point mass on the rotor: no gyroscopic term.
#[test]
fn a_disk_without_inertia_is_a_point_mass() {
    let text = format!(
        "{BASE}\n[[disks]]\nnode = 2\nmass = 5.0\npolar_inertia = 0.0\ndiametral_inertia = 0.0\n"
    );
    let m = RotorModel::from_toml(&text, "m.toml").unwrap();
    assert_eq!(m.disks[0].disk.polar_inertia, 0.0);
    assert_eq!(
        m.disks[0]
            .disk
            .gyroscopic_matrix()
            .iter()
            .filter(|v| **v != 0.0)
            .count(),
        0
    );
}

/// `[[pedestals]]`, `pedestal` keys, `[[seals]]` and `[[point_masses]]`:
/// every bad entry names the file, line, field and value.
#[test]
fn pedestal_seal_and_point_mass_errors_name_file_line_and_field() {
    let bearing =
        "\n[[bearings]]\ntype = \"linear\"\nnode = 1\nkxx = 1e6\nkyy = 1e6\npedestal = \"frame\"\n";
    let frame = "\n[[pedestals]]\nname = \"frame\"\nmass = 50.0\nkxx = 1e7\nkyy = 1e7\n";
    let cases: Vec<(String, &str, &str)> = vec![
        (
            bearing.replace("frame", "nowhere") + frame,
            "pedestal = \"nowhere\"",
            "bearings[0].pedestal = \"nowhere\": no pedestal has this name (defined: frame)",
        ),
        (
            bearing.to_string(),
            "pedestal = \"frame\"",
            "bearings[0].pedestal = \"frame\": no [[pedestals]] entry has this name",
        ),
        (
            format!("{bearing}{}", frame.replace("mass = 50.0", "mass = 0.0")),
            "mass = 0.0",
            "pedestals[0].mass = 0: must be a finite number greater than zero",
        ),
        (
            format!("{bearing}{}", frame.replace("kxx = 1e7", "kxx = -1e7")),
            "kxx = -1e7",
            "pedestals[0].kxx = -10000000: must be a finite number greater than zero",
        ),
        (
            format!(
                "{bearing}{}",
                frame.replace("kyy = 1e7", "kyy = 1e7\ncxy = nan")
            ),
            "cxy = nan",
            "pedestals[0].cxy = NaN: must be a finite number",
        ),
        (
            format!(
                "{bearing}{}",
                frame.replace("kyy = 1e7", "kyy = 1e7\non = \"frame\"")
            ),
            "on = \"frame\"",
            "pedestals[0].on = \"frame\": a pedestal cannot stand on itself",
        ),
        (
            format!("{bearing}{frame}{}", frame.replace("frame", "spare")),
            "name = \"spare\"",
            "pedestals[1].name = \"spare\": no bearing, rub, seal or magnetic pull stands on this pedestal",
        ),
        (
            format!(
                "{bearing}{}{}",
                frame.replace("kyy = 1e7", "kyy = 1e7\non = \"base\""),
                frame
                    .replace("frame", "base")
                    .replace("kyy = 1e7", "kyy = 1e7\non = \"frame\"")
            ),
            "on = \"base\"",
            "pedestals[0].on = \"base\": the pedestals stand on each other in a loop",
        ),
        (
            format!("{bearing}{frame}{frame}"),
            "name = \"frame\"",
            "duplicate pedestal name",
        ),
        (
            "\n[[seals]]\nnode = 4\nkxy = 1e6\nradius = 0.1\n".to_string(),
            "radius = 0.1",
            "seals[0].radius = (given): a contact parameter needs the seal's clearance",
        ),
        (
            "\n[[seals]]\nnode = 4\nkxy = 1e6\nclearance = -1e-3\n".to_string(),
            "clearance = -1e-3",
            "seals[0].clearance = -0.001: must be a finite number greater than zero",
        ),
        (
            "\n[[seals]]\nnode = 40\nkxy = 1e6\n".to_string(),
            "node = 40",
            "seals[0].node = 40: must be a node number from 1 to 7",
        ),
        (
            "\n[[point_masses]]\nnode = 2\nmx = 3.0\n".to_string(),
            "mx = 3.0",
            "point_masses[0] = mass / mx / my: give either mass, or both mx and my",
        ),
        (
            "\n[[point_masses]]\nnode = 2\nmass = -3.0\n".to_string(),
            "mass = -3.0",
            "point_masses[0].mass = -3: must be a finite number greater than zero",
        ),
    ];
    for (extra, needle, want) in cases {
        let e = err_of(&extra);
        assert!(e.starts_with("m.toml:"), "{e}");
        assert!(e.contains(want), "{extra}\ngave: {e}\nwant: {want}");
        let nth = usize::from(want == "duplicate pedestal name");
        let line = line_in(&extra, needle, nth);
        if !want.starts_with("point_masses[0] =") {
            assert!(
                e.starts_with(&format!("m.toml:{line}: ")),
                "{e} (line {line})"
            );
        }
    }
}

/// Implausible pedestals (stiffness in N/mm, a mass in g) are warned about.
#[test]
fn implausible_pedestals_are_warned() {
    let text = format!(
        "{BASE}\n[[bearings]]\ntype = \"linear\"\nnode = 1\nkxx = 1e6\nkyy = 1e6\npedestal = \"frame\"\n\
         \n[[pedestals]]\nname = \"frame\"\nmass = 5e6\nkxx = 200.0\nkyy = 1e14\n"
    );
    let m = RotorModel::from_toml(&text, "m.toml").unwrap();
    let warnings: Vec<String> = m
        .plausibility_warnings()
        .iter()
        .map(|w| w.to_string())
        .collect();
    assert_eq!(warnings.len(), 3, "{warnings:?}");
    assert!(warnings[0].starts_with("m.toml: pedestals[0].kxx = 200: support stiffness outside"));
    assert!(
        warnings[1]
            .starts_with("m.toml: pedestals[0].kyy = 100000000000000: support stiffness outside")
    );
    assert!(
        warnings[2].starts_with(
            "m.toml: pedestals[0].mass = 5000000: more than 100 times the rotating mass"
        )
    );
}

/// `[[magnetic_pull]]`, `[[forces]]` and `[[ports]]`: every bad entry names
/// the file, line, field and value.
#[test]
fn pull_force_and_port_errors_name_file_line_and_field() {
    let cases: Vec<(&str, &str, &str)> = vec![
        (
            "\n[[magnetic_pull]]\nnode = 4\ngap = -0.01\nstiffness = 1e8\n",
            "gap = -0.01",
            "magnetic_pull[0].gap = -0.01: must be a finite number greater than zero",
        ),
        (
            "\n[[magnetic_pull]]\nnode = 4\ngap = 0.01\n",
            "gap = 0.01",
            "magnetic_pull[0] = stiffness / rotor_radius, core_length, flux_density: give either stiffness",
        ),
        (
            "\n[[magnetic_pull]]\nnode = 4\ngap = 0.01\nstiffness = 1e8\nrotor_radius = 1.0\n",
            "gap = 0.01",
            "give either stiffness, or all of rotor_radius",
        ),
        (
            "\n[[magnetic_pull]]\nnode = 4\ngap = 0.01\nstiffness = nan\n",
            "stiffness = nan",
            "magnetic_pull[0].stiffness = NaN: must be a finite number greater than zero",
        ),
        (
            "\n[[magnetic_pull]]\nnode = 4\ngap = 0.01\nstiffness = 1e8\nexcitation = 3.0\n",
            "excitation = 3.0",
            "magnetic_pull[0].excitation = 3: must lie in [0, 2]",
        ),
        (
            "\n[[magnetic_pull]]\nnode = 9\ngap = 0.01\nstiffness = 1e8\n",
            "node = 9",
            "magnetic_pull[0].node = 9: must be a node number from 1 to 7",
        ),
        (
            "\n[[forces]]\nnode = 4\n",
            "node = 4",
            "forces[0] = (no force): give fx and/or fy",
        ),
        (
            "\n[[forces]]\nnode = 4\nfx = 1.0\nmagnitude = 2.0\n",
            "magnitude = 2.0",
            "forces[0].magnitude = (given): a force is static (fx, fy) or harmonic",
        ),
        (
            "\n[[forces]]\nnode = 4\nmagnitude = 2.0\n",
            "magnitude = 2.0",
            "forces[0] = ratio / frequency_hz: a harmonic force needs either ratio",
        ),
        (
            "\n[[forces]]\nnode = 4\nmagnitude = 2.0\nratio = 0.3\ndirection = \"sideways\"\n",
            "direction = \"sideways\"",
            "forces[0].direction = \"sideways\": must be \"forward\", \"backward\" or \"fixed\"",
        ),
        (
            "\n[[forces]]\nnode = 4\nmagnitude = -2.0\nratio = 0.3\n",
            "magnitude = -2.0",
            "forces[0].magnitude = -2: must be a finite number not less than zero",
        ),
        (
            "\n[[forces]]\nnode = 4\nfy = inf\n",
            "fy = inf",
            "forces[0].fy = inf: must be a finite number",
        ),
        (
            "\n[[forces]]\nnode = 4\nmagnitude = 2.0\nratio = 0.3\nangle_deg = 30.0\n",
            "angle_deg = 30.0",
            "forces[0].angle_deg = 30: only a fixed-direction force",
        ),
        (
            "\n[[ports]]\nname = \"amb\"\nnode = 0\n",
            "node = 0",
            "ports[0].node = 0: must be a node number from 1 to 7",
        ),
        (
            "\n[[ports]]\nname = \"amb\"\nnode = 2\n[[ports]]\nname = \"amb\"\nnode = 3\n",
            "name = \"amb\"",
            "ports[1].name = amb: duplicate port name",
        ),
    ];
    for (extra, needle, want) in cases {
        let e = err_of(extra);
        assert!(e.contains(want), "{extra}\ngave: {e}\nwant: {want}");
        let nth = usize::from(want.contains("duplicate"));
        let line = line_in(extra, needle, nth);
        // Errors of a whole entry name the entry's line instead.
        if !e.contains("[0] = ") {
            assert!(
                e.starts_with(&format!("m.toml:{line}: ")),
                "{e} (line {line})"
            );
        }
    }
}

/// `[torsion]`, `[[torques]]`, `[[couplings]]` and `[[thrust_bearings]]`:
/// every bad entry names the file, line, field and value; a thrust bearing
/// without an axial load on a horizontal rotor is a warning naming it.
#[test]
fn torsion_errors_name_file_line_and_field() {
    let cases: Vec<(&str, &str, &str)> = vec![
        (
            "\n[torsion]\ndrive = \"torque\"\n[[torques]]\nname = \"turbine\"\nnode = 9\n",
            "node = 9",
            "torques[0].node = 9: must be a node number from 1 to 7",
        ),
        (
            "\n[[couplings]]\nnode = 2\ntorsional_stiffness = -1e5\n",
            "torsional_stiffness = -1e5",
            "couplings[0].torsional_stiffness = -100000: must be a finite number greater than zero",
        ),
        (
            "\n[[couplings]]\nnode = 2\ntorsional_stiffness = 1e5\ntorsional_damping = -3.0\n",
            "torsional_damping = -3.0",
            "couplings[0].torsional_damping = -3: must be a finite number not less than zero",
        ),
        (
            "\n[[couplings]]\nnode = 7\ntorsional_stiffness = 1e5\n",
            "node = 7",
            "couplings[0].node = 7: no shaft element starts at this node",
        ),
        (
            "\n[torsion]\ndrive = \"electric\"\n",
            "drive = \"electric\"",
            "torsion.drive = \"electric\": must be \"speed\" or \"torque\"",
        ),
        (
            "\n[torsion]\ndrive = \"torque\"\n",
            "drive = \"torque\"",
            "torsion.drive = \"torque\": ",
        ),
    ];
    for (extra, needle, want) in cases {
        let e = err_of(extra);
        assert!(e.contains(want), "{extra}\ngave: {e}\nwant: {want}");
        let line = line_in(extra, needle, 0);
        assert!(
            e.starts_with(&format!("m.toml:{line}: ")),
            "{e} (line {line})"
        );
    }
    let text = format!(
        "{BASE}\n[[thrust_bearings]]\nname = \"thrust\"\nnode = 1\ninner_radius = 0.05\nouter_radius = 0.1\nfilm_thickness = 3e-5\nviscosity = 0.03\n"
    );
    let m = RotorModel::from_toml(&text, "m.toml").unwrap();
    let warnings: Vec<String> = m
        .plausibility_warnings()
        .iter()
        .map(|w| w.to_string())
        .collect();
    assert!(
        warnings.iter().any(|w| w.starts_with(
            "m.toml: thrust_bearings[0].load = 0: the thrust bearing carries no axial load"
        )),
        "{warnings:?}"
    );
}
