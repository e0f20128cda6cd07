//! Verdicts that agree with the machine (issue 45): a linearization whose
//! equilibrium the bearings cannot hold is reported as a static divergence,
//! never as "overdamped roots", and fails the stability verdict.
//!
//! Truth: every eigenvalue of the linearized rotor's first-order state
//! matrix `[[0, I], [−M⁻¹K, −M⁻¹(C + ΩG)]]`, by a dense eigen-solve
//! (nalgebra's Schur form), independent of the shift-invert Arnoldi the
//! analyses use.

use nalgebra::DMatrix;
use rotor_bearing::analysis::linearize::linearized;
use rotor_bearing::analysis::modal::{ModalOptions, modal_analysis};
use rotor_bearing::analysis::stability::{StabilityRequest, stability_study};
use rotor_bearing::model::RotorModel;
use rotor_bearing::report::text;
use rotor_bearing::rotor::Rotor;

const RPM: f64 = std::f64::consts::PI / 30.0;

/// The hydro unit on its brackets with its generator field at `excitation`.
fn brackets(excitation: f64) -> Rotor {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/models/hydro_unit_brackets.toml"
    );
    let mut model = RotorModel::from_file(std::path::Path::new(path)).unwrap();
    let pulls = model
        .bearings
        .iter_mut()
        .filter_map(|b| b.kind.set_excitation(excitation).then_some(()))
        .count();
    assert_eq!(pulls, 1);
    Rotor::new(model).unwrap()
}

/// The real parts of the non-oscillating eigenvalues (0 ≤ Im λ ≤ 0.045 |λ|,
/// ζ ≥ 0.999, the analyses' definition; one of each conjugate pair) of the
/// linear rotor's state matrix at `speed`, by a dense solve.
fn real_roots(linear: &Rotor, speed: f64) -> Vec<f64> {
    let n = linear.dof_count();
    let m = linear.mass.to_dense();
    let k = linear.stiffness.to_dense();
    let mut d = linear.damping.to_dense();
    d += linear.gyroscopic.to_dense() * speed;
    let m_inv = m.try_inverse().expect("a positive mass matrix");
    let mut a = DMatrix::<f64>::zeros(2 * n, 2 * n);
    a.view_mut((0, n), (n, n)).fill_with_identity();
    a.view_mut((n, 0), (n, n)).copy_from(&(-&m_inv * k));
    a.view_mut((n, n), (n, n)).copy_from(&(-&m_inv * d));
    a.complex_eigenvalues()
        .iter()
        .filter(|l| l.im >= 0.0 && l.im <= 0.045 * l.norm())
        .map(|l| l.re)
        .collect()
}

/// With the field on, the pull (1.73e8 N/m at nominal field) is stiffer
/// than the unpreloaded guide pads can hold about the centred position: the
/// linearization has a growing real root. `modes` lists it as a static
/// divergence with the growth rate of the dense solve (1e-6), `stability`
/// gives threshold 0 and says so; with the field off neither has one.
#[test]
fn a_statically_unstable_linearization_is_flagged_not_called_overdamped() {
    let speed = 300.0 * RPM;
    for (excitation, unstable) in [(1.0, true), (0.0, false)] {
        let rotor = brackets(excitation);
        let linear = linearized(&rotor, speed, speed).unwrap();
        let growth: Vec<f64> = real_roots(&linear, speed)
            .into_iter()
            .filter(|&re| re > 1e-9)
            .collect();
        assert_eq!(
            !growth.is_empty(),
            unstable,
            "excitation {excitation}: {growth:?}"
        );
        let options = ModalOptions {
            modes: 8,
            ..ModalOptions::default()
        };
        let result = modal_analysis(&linear, speed, &options).unwrap();
        let reported: Vec<f64> = result
            .overdamped
            .iter()
            .filter(|r| r.is_growing())
            .map(|r| -r.decay_rate())
            .collect();
        assert_eq!(reported.len(), growth.len(), "excitation {excitation}");
        for g in &reported {
            assert!(
                growth.iter().any(|x| (x - g).abs() <= 1e-6 * g.abs()),
                "{g} 1/s not among the dense solve's {growth:?}"
            );
        }
        let printed = text::overdamped_roots(&result.overdamped);
        assert_eq!(
            printed.contains("STATICALLY UNSTABLE"),
            unstable,
            "{printed}"
        );
        let study = stability_study(&rotor, &StabilityRequest::at(speed)).unwrap();
        assert_eq!(!study.diverging.is_empty(), unstable);
        if unstable {
            assert_eq!(study.threshold, Some(0.0));
            let verdict = text::stability(&study, &["generator".into()]);
            assert!(
                verdict.contains("statically unstable at 300 rpm (threshold Q = 0)")
                    && !verdict.contains("no threshold found"),
                "{verdict}"
            );
        }
    }
}
