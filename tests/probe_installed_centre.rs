//! Probes that measure from a bearing's installed centre (issue 49):
//! `[[probes]] relative_to = "<bearing>"` reads the shaft's displacement
//! less the bearing housing's motion and the bearing's offset — what a
//! proximity probe mounted on that bearing sees. On the three plain
//! bearings with the middle one raised 30 µm, a probe at the middle journal
//! reads the nominal-axis probe less (0, 30 µm) exactly, and its distance over
//! the clearance is the film's own eccentricity ratio (1e-12); on pedestals
//! it is the journal's displacement relative to its housing; an unknown
//! bearing is an error naming file, field and value.

use rotor_bearing::model::RotorModel;
use rotor_bearing::rotor::Rotor;
use rotor_bearing::solver::{Simulator, SolverOptions};

#[path = "common/film_line.rs"]
mod film_line;
#[path = "common/pedestal_rotor.rs"]
mod pedestal_rotor;

const RPM: f64 = std::f64::consts::PI / 30.0;

fn settled(text: &str, rpm: f64) -> rotor_bearing::solver::Outputs {
    let model = RotorModel::from_toml(text, "probes.toml").unwrap();
    let mut sim = Simulator::new(Rotor::new(model).unwrap(), SolverOptions::default()).unwrap();
    sim.set_speed(rpm * RPM, 0.0).unwrap();
    sim.settle_static().unwrap();
    sim.outputs().unwrap()
}

#[test]
fn a_probe_measures_from_its_bearings_installed_centre() {
    let text = film_line::text(30e-6)
        + "[[probes]]\nname = \"axis\"\nnode = 7\n"
        + "[[probes]]\nname = \"middle_probe\"\nnode = 7\nrelative_to = \"middle\"\n";
    let out = settled(&text, 3000.0);
    let (axis, probe) = (&out.probes[0], &out.probes[1]);
    assert_eq!(probe.x, axis.x - 0.0 - 0.0);
    assert_eq!(probe.y, axis.y - 0.0 - 30e-6);
    let eps = probe.x.hypot(probe.y) / 80e-6;
    let film = out.bearings[1].report.eccentricity;
    assert!((eps - film).abs() < 1e-12, "{eps} against {film}");
    assert!(
        axis.y > 0.0 && probe.y < 0.0,
        "the raised journal hangs below its bearing's centre"
    );
    let described = rotor_bearing::report::text::model_summary(
        &Rotor::new(RotorModel::from_toml(&text, "probes.toml").unwrap()).unwrap(),
    );
    assert!(
        described.contains(
            "probe middle_probe at node 7, measuring from bearing middle's installed centre"
        ),
        "{described}"
    );
}

#[test]
fn on_a_pedestal_the_probe_moves_with_the_housing() {
    let text = pedestal_rotor::on_pedestals(4.5e-3, "")
        + "[[probes]]\nname = \"de\"\nnode = 1\nrelative_to = \"drive_end\"\n";
    let out = settled(&text, 1000.0);
    let b = &out.bearings[0];
    assert!(
        b.housing.y.abs() > 0.0,
        "the pedestal sags under the rotor's weight"
    );
    let probe = out.probes.last().unwrap();
    assert_eq!(
        (probe.x, probe.y),
        (b.x - b.housing.x - 0.0, b.y - b.housing.y - 0.0)
    );
}

#[test]
fn an_unknown_bearing_is_named() {
    let text =
        film_line::text(0.0) + "[[probes]]\nname = \"p\"\nnode = 7\nrelative_to = \"centre\"\n";
    let e = RotorModel::from_toml(&text, "probes.toml")
        .unwrap_err()
        .to_string();
    assert!(
        e.contains("probes.toml")
            && e.contains("probes[0].relative_to = \"centre\": is not a bearing of the model (its bearings: left, middle, right)"),
        "{e}"
    );
}
