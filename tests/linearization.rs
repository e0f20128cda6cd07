//! The linearized analyses (Campbell diagram, modes at a speed) on fluid-film
//! bearings take one static equilibrium per speed, without a transient
//! simulator, and add the bearing coefficients to the assembled matrices. They
//! must give the modes of the explicitly built model: the rotor settled by the
//! transient simulator, its bearings rewritten as linear bearings with the
//! condensed coefficients there, and the whole model assembled again.

use std::path::Path;

use rotor_bearing::analysis::campbell::campbell;
use rotor_bearing::analysis::modal::{ModalOptions, modes};
use rotor_bearing::bearing::BearingEval;
use rotor_bearing::bearing::BearingKind;
use rotor_bearing::bearing::equilibrium::condensed_coefficients;
use rotor_bearing::model::RotorModel;
use rotor_bearing::rotor::Rotor;
use rotor_bearing::solver::{Simulator, SolverOptions, equilibrium};

fn model(name: &str) -> RotorModel {
    let path = format!("{}/models/{name}.toml", env!("CARGO_MANIFEST_DIR"));
    RotorModel::from_file(Path::new(&path)).unwrap()
}

/// The linear-bearing model at the static equilibrium at `speed`, built the
/// long way: a transient simulator settled there, each nonlinear bearing
/// evaluated at its journal and pads, condensed at the spin speed, written
/// into the model as a linear bearing, and the model assembled.
fn explicitly_linearized(model: &RotorModel, speed: f64) -> Rotor {
    let rotor = Rotor::new(model.clone()).unwrap();
    let mut sim =
        Simulator::new(Rotor::new(model.clone()).unwrap(), SolverOptions::default()).unwrap();
    sim.set_speed(speed, 0.0).unwrap();
    sim.settle_static().unwrap();
    let state = sim.state().clone();
    let mut linear = model.clone();
    let mut offset = 0;
    for placed in &mut linear.bearings {
        if !placed.kind.is_nonlinear() {
            continue;
        }
        let bearing = placed.kind.build();
        let internal = bearing.internal_dofs();
        let at = |k: usize| rotor.dofs.free(placed.node, k).map_or(0.0, |i| state.u[i]);
        let mut q = vec![at(0), at(1)];
        q.extend_from_slice(&state.p[offset..offset + internal]);
        offset += internal;
        let mut eval = BearingEval::new(q.len());
        bearing
            .evaluate(&q, &vec![0.0; q.len()], speed, &mut eval)
            .unwrap();
        let (k, c) = condensed_coefficients(&eval, speed);
        placed.kind = BearingKind::Linear {
            stiffness: [[k[(0, 0)], k[(0, 1)]], [k[(1, 0)], k[(1, 1)]]],
            damping: [[c[(0, 0)], c[(0, 1)]], [c[(1, 0)], c[(1, 1)]]],
        };
    }
    Rotor::new(linear).unwrap()
}

/// Campbell frequencies of the library path (equilibrium, coefficients added to
/// the assembled matrices) equal the modes of the explicitly linearized and
/// assembled model to 1e-9 relative.
#[test]
fn campbell_equals_the_explicitly_linearized_model() {
    let options = ModalOptions {
        modes: 4,
        ..ModalOptions::default()
    };
    for (name, rpms) in [
        ("jeffcott", [3000.0, 4000.0, 5000.0, 6000.0]),
        ("hydro_unit", [100.0, 125.0, 150.0, 175.0]),
        ("hydro_unit_plain", [100.0, 125.0, 150.0, 175.0]),
    ] {
        let m = model(name);
        let rotor = Rotor::new(m.clone()).unwrap();
        let speeds: Vec<f64> = rpms
            .iter()
            .map(|r| r * std::f64::consts::PI / 30.0)
            .collect();
        let diagram = campbell(&rotor, &speeds, &options).unwrap();
        let (mut worst, mut worst_zeta): (f64, f64) = (0.0, 0.0);
        for point in &diagram {
            let reference = modes(
                &explicitly_linearized(&m, point.speed),
                point.speed,
                &options,
            )
            .unwrap();
            assert_eq!(reference.len(), point.modes.len(), "{name}");
            for (a, b) in point.modes.iter().zip(&reference) {
                let rel = (a.damped_frequency - b.damped_frequency).abs() / b.damped_frequency;
                let zeta = (a.damping_ratio - b.damping_ratio).abs();
                worst = worst.max(rel);
                worst_zeta = worst_zeta.max(zeta);
            }
        }
        println!(
            "{name}: largest relative difference of damped frequencies {worst:.3e}, of damping ratios {worst_zeta:.3e}"
        );
        assert!(worst < 1e-9, "{name}: frequencies differ by {worst:e}");
        assert!(
            worst_zeta < 1e-8,
            "{name}: damping ratios differ by {worst_zeta:e}"
        );
    }
}

/// The Jacobian of the bearing force at the static equilibrium (the source of
/// the linear coefficients) equals central finite differences of the nonlinear
/// force, journal and pad coordinates alike.
#[test]
fn equilibrium_jacobians_equal_finite_differences_of_the_force() {
    for name in ["jeffcott", "hydro_unit"] {
        let m = model(name);
        let rotor = Rotor::new(m.clone()).unwrap();
        let at = equilibrium(&rotor, m.nominal_speed, &SolverOptions::default(), None).unwrap();
        let mut offset = 0;
        for (index, eval) in &at.bearings {
            let placed = &m.bearings[*index];
            let bearing = placed.kind.build();
            let n = eval.n();
            let mut q = vec![0.0; n];
            for (k, qk) in q.iter_mut().take(2).enumerate() {
                *qk = at.displacement[rotor.dofs.free(placed.node, k).unwrap()];
            }
            q[2..].copy_from_slice(&at.tilts[offset..offset + n - 2]);
            offset += n - 2;
            let clearance = placed.kind.journal_clearance().unwrap();
            let h = 1e-6 * clearance;
            let zero = vec![0.0; n];
            let (mut plus, mut minus) = (BearingEval::new(n), BearingEval::new(n));
            let mut worst: f64 = 0.0;
            let scale = eval.stiffness.iter().fold(0.0_f64, |a, k| a.max(k.abs()));
            for j in 0..n {
                let (mut qp, mut qm) = (q.clone(), q.clone());
                qp[j] += h;
                qm[j] -= h;
                bearing
                    .evaluate(&qp, &zero, m.nominal_speed, &mut plus)
                    .unwrap();
                bearing
                    .evaluate(&qm, &zero, m.nominal_speed, &mut minus)
                    .unwrap();
                for i in 0..n {
                    let fd = -(plus.force[i] - minus.force[i]) / (2.0 * h);
                    worst = worst.max((fd - eval.stiffness[i * n + j]).abs() / scale);
                }
            }
            assert!(worst < 1e-5, "{name}/{}: {worst:e}", placed.name);
        }
    }
}
