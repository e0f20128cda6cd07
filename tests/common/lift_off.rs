//! Lift-off and touch-down helpers of the tests that run a rotor through
//! them (`operating_envelope`, `finite_film_lift_off`).

use rotor_bearing::model::RotorModel;
use rotor_bearing::rotor::Rotor;
use rotor_bearing::solver::{Outputs, Simulator, SolverOptions, SpeedProfile, record};

/// Largest contact force over the bearings (N).
pub fn contact(o: &Outputs) -> f64 {
    o.bearings
        .iter()
        .map(|b| b.report.contact_force)
        .fold(0.0, f64::max)
}

/// The outputs of `model`'s static equilibrium at `speed` (rad/s).
pub fn settled(model: &RotorModel, speed: f64) -> Outputs {
    let mut sim =
        Simulator::new(Rotor::new(model.clone()).unwrap(), SolverOptions::default()).unwrap();
    sim.set_speed(speed, 0.0).unwrap();
    sim.settle_static().unwrap();
    sim.outputs().unwrap()
}

/// The lowest speed (rad/s) whose static equilibrium keeps every journal clear
/// of contact, by bisection between `lo` (in contact) and `hi` (clear).
pub fn static_lift_off(model: &RotorModel, mut lo: f64, mut hi: f64) -> f64 {
    let clear = |speed: f64| contact(&settled(model, speed)) == 0.0;
    assert!(
        !clear(lo) && clear(hi),
        "no lift-off between {lo} and {hi} rad/s"
    );
    for _ in 0..40 {
        let mid = 0.5 * (lo + hi);
        if clear(mid) { hi = mid } else { lo = mid }
    }
    hi
}

/// `model` settled at `from` (rad/s), then ramped to `to` over `ramp` (s) and
/// held there for `hold` (s), with time step `step` (s); outputs every
/// 37 steps.
pub fn ramp(
    model: &RotorModel,
    (from, to): (f64, f64),
    (ramp, hold): (f64, f64),
    step: f64,
) -> Vec<Outputs> {
    let options = SolverOptions {
        time_step: step,
        ..SolverOptions::default()
    };
    let mut sim = Simulator::new(Rotor::new(model.clone()).unwrap(), options).unwrap();
    sim.set_speed(from, 0.0).unwrap();
    sim.settle_static().unwrap();
    let profile = SpeedProfile::Ramp {
        from,
        to,
        duration: ramp,
    };
    record(&mut sim, &profile, ramp + hold, 37.0 * step, |_, _| {})
        .unwrap_or_else(|e| panic!("ramp {from} → {to} rad/s: {e}"))
}
