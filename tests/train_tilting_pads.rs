//! The shipped turbine–generator train on four-pad tilting-pad bearings
//! (load between pads, centre pivots, preload 0.3) in place of its plain
//! ones (issue 49). Its Campbell diagram reported "statically unstable" at
//! one speed of its grid (3157.88 rpm): from the undeflected line, Newton
//! found there — and at every speed from about 3140 to 3160 rpm — an
//! equilibrium with the turbine's front journal 4 µm *above* its centre,
//! its bearing's force pointing away from the centre (attitude 111°): pads
//! on a branch the running bearing does not hold, whose linearization has a
//! growing non-oscillating root. The statics now take such an equilibrium
//! (a tilting-pad film pushing its journal off its centre, `F·q > 0`) as
//! unsettled and start again from the bearings' own equilibria.

use rotor_bearing::analysis::modal::{ModalOptions, modal_analysis_at};
use rotor_bearing::model::RotorModel;
use rotor_bearing::rotor::Rotor;
use rotor_bearing::solver::SolverOptions;
use rotor_bearing::solver::statics::equilibrium;

const RPM: f64 = std::f64::consts::PI / 30.0;

fn train_on_pads() -> Rotor {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/models/turbine_generator_train.toml"
    );
    let text = std::fs::read_to_string(path).unwrap().replace(
        "type = \"plain\"",
        "type = \"tilting_pad\"\npads = 4\nfirst_pivot_deg = 45.0\npad_arc_deg = 72.0\npivot_offset = 0.5\npreload = 0.3",
    );
    Rotor::new(RotorModel::from_toml(&text, "train_pads.toml").unwrap()).unwrap()
}

/// At 3150 and 3157.88 rpm every bearing's force on its journal points back
/// towards its centre (`F·q < 0`), the turbine's front journal sits below
/// its centre as at 3060 and 3250 rpm (within 0.3 µm of the mean of the two:
/// its sag changes smoothly with speed), and no non-oscillating root of the
/// linearized train grows.
#[test]
fn the_train_on_pads_is_held_at_every_speed_of_its_band() {
    let rotor = train_on_pads();
    let options = SolverOptions::default();
    let front = |speed: f64| {
        let eq = equilibrium(&rotor, speed, &options, None).unwrap();
        for (k, eval) in &eq.bearings {
            let node = rotor.model.bearings[*k].node;
            let o = rotor.model.bearings[*k].offset;
            let q = [
                rotor.node_value(node, 0, &eq.displacement) - o[0],
                rotor.node_value(node, 1, &eq.displacement) - o[1],
            ];
            let push = eval.force[0] * q[0] + eval.force[1] * q[1];
            assert!(
                push < 0.0,
                "{} at {} rpm: F·q = {push}",
                rotor.model.bearings[*k].name,
                speed / RPM
            );
        }
        let k = rotor
            .model
            .bearings
            .iter()
            .position(|b| b.name == "turbine_front")
            .unwrap();
        let node = rotor.model.bearings[k].node;
        rotor.node_value(node, 1, &eq.displacement) - rotor.model.bearings[k].offset[1]
    };
    let (low, high) = (front(3060.0 * RPM), front(3250.0 * RPM));
    assert!(low < 0.0 && high < 0.0, "{low} {high}");
    for rpm in [3150.0, 3157.88] {
        let y = front(rpm * RPM);
        assert!(
            (y - 0.5 * (low + high)).abs() < 0.3e-6,
            "{rpm} rpm: {y} m, neighbours {low} and {high} m"
        );
        let modes = modal_analysis_at(&rotor, rpm * RPM, &ModalOptions::default()).unwrap();
        for r in &modes.overdamped {
            assert!(r.decay_rate() > 0.0, "{rpm} rpm: {:?}", r.eigenvalue);
        }
    }
}
