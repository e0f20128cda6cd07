//! Equilibria the bearings hold (issue 45, acceptance 3): with its field
//! above about 1.5 × nominal the pull of the unit on brackets (vertical,
//! unpreloaded guide pads, no lateral load) makes its centred equilibrium
//! statically unstable at 300 rpm — the rotor linearized there with the pad
//! tilts as coordinates has growing non-oscillating roots — and the statics
//! continue onto an equilibrium off the centre.
//!
//! Truth, independent of the statics that found it:
//! - force balance: every bearing, the seal and the pull evaluated afresh at
//!   the equilibrium's journal positions; their forces on the rotor (no
//!   lateral gravity) sum to zero to 1e-9 of the pull's force;
//! - the nonlinear transient started there: field 2.0, the equilibrium's
//!   linearization has no growing root, and a displacement of 1 µm dies out
//!   back to that point; field 1.6, its least damped mode grows (a whirl),
//!   and the transient started on that mode at 1 nm grows at the linear rate
//!   (a two-exponential Prony fit of the journal's x motion while it is
//!   below 1e-3 of the equilibrium's offset) and saturates in a bounded limit
//!   cycle, as the transient from the centre does.

use rotor_bearing::analysis::held_equilibrium::held_equilibrium;
use rotor_bearing::analysis::modal::ModalOptions;
use rotor_bearing::analysis::whirl_modes::modal_analysis_own;
use rotor_bearing::model::{Drive, RotorModel};
use rotor_bearing::rotor::Rotor;
use rotor_bearing::rotor::elements::bearing_dofs;
use rotor_bearing::solver::{Equilibrium, Simulator, SolverOptions, equilibrium};

const RPM: f64 = std::f64::consts::PI / 30.0;

/// The hydro unit on its brackets with its generator field at `excitation`.
fn brackets(excitation: f64) -> Rotor {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/models/hydro_unit_brackets.toml"
    );
    let mut model = RotorModel::from_file(std::path::Path::new(path)).unwrap();
    model.drive = Drive::Speed;
    let pulls = model
        .bearings
        .iter_mut()
        .filter_map(|b| b.kind.set_excitation(excitation).then_some(()))
        .count();
    assert_eq!(pulls, 1);
    Rotor::new(model).unwrap()
}

/// The journal displacement relative to the housing of model bearing `b`
/// in the rotor displacement `u`.
fn journal(rotor: &Rotor, b: usize, u: &[f64]) -> [f64; 2] {
    let dofs = bearing_dofs(&rotor.dofs, &rotor.model.bearings[b]);
    let at = |k: usize| {
        dofs[k].map_or(0.0, |i| u[i]) - dofs.get(2 + k).copied().flatten().map_or(0.0, |i| u[i])
    };
    [at(0), at(1)]
}

/// Every bearing, seal and pull evaluated afresh at `eq` (pad tilts from
/// `eq`, zero rates): the sum of their forces on the rotor and the pull's.
fn force_balance(rotor: &Rotor, eq: &Equilibrium, speed: f64) -> ([f64; 2], [f64; 2]) {
    let mut sum = [0.0; 2];
    let mut pull = [0.0; 2];
    let mut tilt = 0;
    for (b, placed) in rotor.model.bearings.iter().enumerate() {
        let bearing = placed.kind.build();
        let internal = bearing.internal_dofs();
        let mut q = journal(rotor, b, &eq.displacement).to_vec();
        q.extend_from_slice(&eq.tilts[tilt..tilt + internal]);
        tilt += internal;
        let mut eval = rotor_bearing::bearing::BearingEval::new(q.len());
        bearing
            .evaluate(&q, &vec![0.0; q.len()], speed, &mut eval)
            .unwrap();
        for (total, f) in sum.iter_mut().zip(&eval.force) {
            *total += f;
        }
        if placed.kind.is_magnetic_pull() {
            pull = [eval.force[0], eval.force[1]];
        }
    }
    assert_eq!(tilt, eq.tilts.len());
    (sum, pull)
}

/// The upper guide bearing's model index.
fn upper_guide(rotor: &Rotor) -> usize {
    rotor
        .model
        .bearings
        .iter()
        .position(|b| b.name == "upper_guide")
        .unwrap()
}

/// A simulator of `rotor` at `speed` (unbalance off) in equal steps of `h`.
fn simulator(rotor: &Rotor, speed: f64, h: f64) -> Simulator {
    let options = SolverOptions {
        time_step: h,
        local_error_tolerance: 0.0,
        tolerance: 1e-12,
        ..SolverOptions::default()
    };
    let mut sim = Simulator::new(Rotor::new(rotor.model.clone()).unwrap(), options).unwrap();
    sim.set_speed(speed, 0.0).unwrap();
    for k in 0..rotor.model.unbalances.len() {
        sim.set_unbalance(k, 0.0).unwrap();
    }
    sim
}

/// [`simulator`] at rest at `eq` (displacement and pad tilts).
fn at_rest(rotor: &Rotor, speed: f64, h: f64, eq: &Equilibrium) -> Simulator {
    let mut sim = simulator(rotor, speed, h);
    let mut state = sim.state().clone();
    state.u.copy_from_slice(&eq.displacement);
    state.p.copy_from_slice(&eq.tilts);
    sim.set_state(state).unwrap();
    sim.consistent_acceleration().unwrap();
    sim
}

#[test]
fn a_pull_that_diverges_the_centre_is_held_off_it_and_the_held_point_is_stable_at_field_2() {
    let speed = 300.0 * RPM;
    let rotor = brackets(2.0);
    let (eq, off) = held_equilibrium(&rotor, speed, None).unwrap();
    let off = off.expect("the centre is statically unstable at field 2");
    assert!(
        off.divergence.iter().all(|&r| r > 0.0) && !off.divergence.is_empty(),
        "{off:?}"
    );
    assert!(off.describe().contains("generator"), "{}", off.describe());
    // The same point on every run.
    assert_eq!(held_equilibrium(&rotor, speed, None).unwrap().0, eq);
    // Off the centre, inside the clearance.
    let ug = upper_guide(&rotor);
    let (_, _, ratio) = off
        .journals
        .iter()
        .find(|(name, _, _)| name == "upper_guide")
        .unwrap()
        .clone();
    assert!(ratio > 0.2 && ratio < 1.0, "upper guide e/C {ratio}");
    // The pull equals what the films (and seal) carry.
    let (sum, pull) = force_balance(&rotor, &eq, speed);
    let load = pull[0].hypot(pull[1]);
    assert!(load > 1e3, "pull {pull:?} N");
    assert!(
        sum[0].hypot(sum[1]) <= 1e-9 * load,
        "force balance {sum:?} N against a pull of {load} N"
    );
    // Linear verdict: nothing grows.
    let modes = modal_analysis_own(
        &rotor,
        speed,
        &ModalOptions {
            modes: 8,
            ..ModalOptions::default()
        },
    )
    .unwrap();
    assert!(
        modes.modes.iter().all(|m| m.log_decrement > 0.0),
        "{:?}",
        modes.modes
    );
    assert!(modes.overdamped.iter().all(|r| !r.is_growing()));
    // Transient: 1 µm off, back to the equilibrium.
    let mut sim = at_rest(&rotor, speed, 2e-3, &eq);
    let rest = journal(&rotor, ug, &eq.displacement);
    // At rest there: 1 s later it has not moved.
    sim.advance_to(1.0).unwrap();
    let still = journal(&rotor, ug, &sim.state().u);
    let moved = (still[0] - rest[0]).hypot(still[1] - rest[1]);
    assert!(
        moved <= 1e-6 * rest[0].hypot(rest[1]),
        "{moved} m in 1 s at rest"
    );
    let mut state = sim.state().clone();
    let dofs = bearing_dofs(&rotor.dofs, &rotor.model.bearings[ug]);
    state.u[dofs[0].unwrap()] += 1e-6;
    sim.set_state(state).unwrap();
    sim.consistent_acceleration().unwrap();
    sim.advance_to(sim.time() + 8.0).unwrap();
    let end = journal(&rotor, ug, &sim.state().u);
    let left = (end[0] - rest[0]).hypot(end[1] - rest[1]);
    assert!(left <= 1e-3 * 1e-6, "still {left} m off after 8 s");
}

/// `λ` of the two-exponential Prony model `q_{k+2} = p₁ q_{k+1} + p₀ q_k`
/// fitted to `q` sampled every `dt` (least squares).
fn prony(q: &[f64], dt: f64) -> nalgebra::Complex<f64> {
    let (mut a, mut b) = (
        nalgebra::Matrix2::<f64>::zeros(),
        nalgebra::Vector2::zeros(),
    );
    for w in q.windows(3) {
        let row = nalgebra::Vector2::new(w[1], w[0]);
        a += row * row.transpose();
        b += row * w[2];
    }
    let p = a.lu().solve(&b).unwrap();
    // z² − p₁ z − p₀ = 0.
    let disc = nalgebra::Complex::new(p[0] * p[0] + 4.0 * p[1], 0.0).sqrt();
    let z = (nalgebra::Complex::new(p[0], 0.0) + disc) / 2.0;
    z.ln() / dt
}

#[test]
fn at_field_1_6_the_held_point_whirls_and_the_transient_grows_at_the_linear_rate_into_a_limit_cycle()
 {
    let speed = 300.0 * RPM;
    let rotor = brackets(1.6);
    let (eq, off) = held_equilibrium(&rotor, speed, None).unwrap();
    assert!(
        off.is_some(),
        "the centre is statically unstable at field 1.6"
    );
    let (sum, pull) = force_balance(&rotor, &eq, speed);
    let load = pull[0].hypot(pull[1]);
    assert!(
        sum[0].hypot(sum[1]) <= 1e-9 * load,
        "{sum:?} against {load}"
    );
    let modes = modal_analysis_own(
        &rotor,
        speed,
        &ModalOptions {
            modes: 8,
            ..ModalOptions::default()
        },
    )
    .unwrap();
    let growing: Vec<_> = modes
        .modes
        .iter()
        .filter(|m| m.log_decrement < 0.0)
        .collect();
    assert_eq!(growing.len(), 1, "{:?}", modes.modes);
    let mode = growing[0];
    assert!(modes.overdamped.iter().all(|r| !r.is_growing()));
    // Started on the mode at 1 pm (largest translation), pad tilts at the
    // equilibrium; equal steps of a two-hundredth of its period.
    let period = std::f64::consts::TAU / mode.damped_frequency;
    let h = period / 200.0;
    let mut sim = at_rest(&rotor, speed, h, &eq);
    let rest = eq.displacement.clone();
    let peak = mode.shape.iter().fold(0.0_f64, |m, z| m.max(z.norm()));
    let a = 1e-12 / peak;
    let mut state = sim.state().clone();
    for i in 0..state.u.len() {
        let x = mode.shape[rotor.dofs.full(i)];
        state.u[i] += a * x.re;
        state.ud[i] += a * (mode.eigenvalue * x).re;
    }
    sim.set_state(state).unwrap();
    sim.consistent_acceleration().unwrap();
    let ug = upper_guide(&rotor);
    let dofs = bearing_dofs(&rotor.dofs, &rotor.model.bearings[ug]);
    let ix = dofs[0].unwrap();
    let offset = journal(&rotor, ug, &rest);
    // One period: the first half carries the other modes' decay, the
    // second is fitted (the motion stays below 1e-8 m, 4e-5 of the
    // clearance; measured 7.1645 ± 5.9528i 1/s against 7.1652 ± 5.9500i).
    // Beyond about 1e-8 m the growth slows (5.8 1/s at 1e-7 m): the film is
    // no longer linear there.
    let mut motion = Vec::new();
    let t0 = sim.time();
    for k in 1..=200 {
        sim.advance_to(t0 + k as f64 * h).unwrap();
        motion.push(sim.state().u[ix] - rest[ix]);
    }
    let reached = motion.iter().fold(0.0_f64, |m, x| m.max(x.abs()));
    assert!(reached < 1e-8, "{reached} m after one period");
    let lambda = prony(&motion[100..], h);
    let linear = mode.eigenvalue;
    assert!(
        (lambda - linear).norm() <= 0.03 * linear.norm(),
        "{lambda} 1/s in the transient, {linear} 1/s linear"
    );
    // Then a limit cycle: bounded, not decaying.
    let mut radius = Vec::new();
    let t1 = sim.time();
    for j in 1..=4000 {
        sim.advance_to(t1 + j as f64 * 5e-3).unwrap();
        let d = journal(&rotor, ug, &sim.state().u);
        radius.push((d[0] - offset[0]).hypot(d[1] - offset[1]));
    }
    let last = &radius[2000..];
    let (lo, hi) = last.iter().fold((f64::INFINITY, 0.0_f64), |(lo, hi), r| {
        (lo.min(*r), hi.max(*r))
    });
    let clearance = rotor.model.bearings[ug].kind.journal_clearance().unwrap();
    assert!(
        hi > 0.1 * offset[0].hypot(offset[1]),
        "limit cycle {lo}..{hi} m"
    );
    assert!(
        hi < 2.0 * clearance,
        "bounded: {hi} m against C = {clearance} m"
    );
}

/// A rotor without negative stiffness (the Jeffcott rotor on plain
/// bearings), or with a pull its films hold (field 1, centre statically
/// stable with the pad coordinates): the solver's own equilibrium, bit for
/// bit, and no note.
#[test]
fn an_equilibrium_that_holds_is_the_solvers_own_bit_for_bit() {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/models/jeffcott.toml");
    let jeffcott = Rotor::new(RotorModel::from_file(std::path::Path::new(path)).unwrap()).unwrap();
    for (rotor, speed) in [(jeffcott, 3000.0 * RPM), (brackets(1.0), 300.0 * RPM)] {
        let (held, off) = held_equilibrium(&rotor, speed, None).unwrap();
        assert!(off.is_none(), "{off:?}");
        let own = equilibrium(&rotor, speed, &SolverOptions::default(), None).unwrap();
        assert_eq!(held, own);
    }
}
