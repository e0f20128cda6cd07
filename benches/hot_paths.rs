//! Criterion benchmarks of the hot paths: one bearing evaluation (plain, tilting
//! pad with 4 and 12 pads), one Newmark step of each shipped model (full and reduced; the
//! three-guide-bearing unit at h = 5 ms and 1 ms), and one
//! fmi2DoStep of the default FMU (through the safe instance the C exports call).

use std::hint::black_box;
use std::path::PathBuf;

use criterion::{Criterion, criterion_group, criterion_main};

use rotor_bearing::bearing::tilting_pad::{Pad, TiltingPadBearing};
use rotor_bearing::bearing::{Bearing, BearingEval, PlainBearing};
use rotor_bearing::fmi2::instance::{Instance, Status};
use rotor_bearing::model::RotorModel;
use rotor_bearing::rotor::Rotor;
use rotor_bearing::solver::{Simulator, SolverOptions};

fn bearings(c: &mut Criterion) {
    let plain = PlainBearing {
        radius: 0.05,
        length: 0.03,
        clearance: 1e-4,
        viscosity: 0.02,
        contact: None,
    };
    let q = [4.3e-5, -4.0e-5];
    let qd = [1e-3, -2e-3];
    let mut out = BearingEval::new(2);
    c.bench_function("plain bearing force + Jacobians", |b| {
        b.iter(|| {
            plain
                .evaluate(black_box(&q), black_box(&qd), 314.16, &mut out)
                .unwrap()
        })
    });
    for pads in [4usize, 12] {
        let tp = TiltingPadBearing {
            radius: 0.05,
            length: 0.03,
            clearance: 1e-4,
            viscosity: 0.02,
            pads: (0..pads)
                .map(|k| {
                    Pad::new(
                        (45.0 + 360.0 * k as f64 / pads as f64).to_radians(),
                        (0.8 * 360.0 / pads as f64).to_radians(),
                        0.5,
                        0.2,
                    )
                })
                .collect(),
            contact: None,
            support: Default::default(),
        };
        let n = 2 + pads;
        let mut q = vec![0.0; n];
        q[1] = -5e-5;
        let qd = vec![1e-4; n];
        let mut out = BearingEval::new(n);
        c.bench_function(&format!("tilting-pad bearing, {pads} pads"), |b| {
            b.iter(|| {
                tp.evaluate(black_box(&q), black_box(&qd), 314.16, &mut out)
                    .unwrap()
            })
        });
    }
}

fn model(name: &str) -> RotorModel {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("models")
        .join(format!("{name}.toml"));
    RotorModel::from_file(&path).unwrap()
}

fn newmark_steps(c: &mut Criterion) {
    for (name, step) in [
        ("classic_disk_rotor", 1e-4),
        ("jeffcott", 1e-4),
        ("vertical_rotor", 2e-3),
        ("hydro_unit", 5e-3),
        ("hydro_unit_plain", 5e-3),
        ("hydro_unit_three_guide", 5e-3),
        ("hydro_unit_three_guide", 1e-3),
    ] {
        // The full rotor, then the reduced one with the default mode count.
        for modes in [0, rotor_bearing::model::DEFAULT_REDUCED_MODES] {
            let m = model(name);
            let mut sim = Simulator::new(
                Rotor::for_transients(m.clone(), modes).unwrap(),
                SolverOptions {
                    time_step: step,
                    ..SolverOptions::default()
                },
            )
            .unwrap();
            sim.set_speed(m.nominal_speed, 0.0).unwrap();
            sim.settle_static().unwrap();
            sim.advance_to(50.0 * step).unwrap();
            let rotor = if modes == 0 {
                String::new()
            } else {
                format!(", reduced to {modes} modes")
            };
            c.bench_function(
                &format!("Newmark step: {name}{rotor} (h = {step} s)"),
                |b| {
                    b.iter(|| {
                        let t = sim.time() + step;
                        sim.advance_to(t).unwrap();
                    })
                },
            );
        }
    }
}

fn fmu_do_step(c: &mut Criterion) {
    let mut fmu = Instance::new("bench", model("hydro_unit")).unwrap();
    assert_eq!(fmu.enter_initialization_mode(), Status::Ok);
    assert_eq!(fmu.exit_initialization_mode(), Status::Ok);
    let h = 0.01;
    let mut t = 0.0;
    c.bench_function(
        "fmi2DoStep of the default FMU (hydro unit, 10 ms, internal 1 ms)",
        |b| {
            b.iter(|| {
                assert_eq!(fmu.do_step(t, h), Status::Ok);
                t += h;
            })
        },
    );
}

criterion_group!(benches, bearings, newmark_steps, fmu_do_step);
criterion_main!(benches);
