//! Ground for API 617 Level II (issue 48): a seal's cross-coupled stiffness
//! already enters the eigenproblem of `rotor stability` (the modes "without
//! added cross-coupling" and every point of the Q sweep carry the seals'
//! linearized coefficients). On the rigid test compressor of
//! `tests/data/api_compressor.toml` (a uniform shaft of a thousand times
//! steel's stiffness on two identical damped isotropic bearings, the seal at
//! mid-span where the conical mode has its node), the cylindrical mode is one
//! degree of freedom `m s² + c s + (k − iQ) = 0` (`z = x + iy`, `Q` the seal's
//! `kxy = −kyx`), whose forward root gives the log decrement in closed form.

use rotor_bearing::analysis::modal::Whirl;
use rotor_bearing::analysis::stability::{StabilityRequest, stability_study};
use rotor_bearing::model::RotorModel;
use rotor_bearing::rotor::Rotor;

/// The forward root's log decrement and damped frequency (Hz) of
/// `m s² + c s + k − iQ = 0`.
fn closed_form(m: f64, c: f64, k: f64, q: f64) -> (f64, f64) {
    type C = nalgebra::Complex<f64>;
    let disc = (C::new(c * c - 4.0 * m * k, 4.0 * m * q)).sqrt();
    let roots = [(-c + disc) / (2.0 * m), (-c - disc) / (2.0 * m)];
    // Forward whirl: z = e^{st} turns with the spin (positive imaginary part).
    let s = roots.into_iter().find(|s| s.im > 0.0).unwrap();
    (
        std::f64::consts::TAU * -s.re / s.im,
        s.im / std::f64::consts::TAU,
    )
}

fn cylindrical_forward(q: f64) -> (f64, f64) {
    let text = std::fs::read_to_string(
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/api_compressor.toml"),
    )
    .unwrap()
    .replace(
        "kxx = [0.0, 0.0]",
        &format!(
            "kxx = [0.0, 0.0]\nkxy = [{q:e}, {q:e}]\nkyx = [{:e}, {:e}]",
            -q, -q
        ),
    );
    assert!(text.contains("kxy = "));
    let rotor = Rotor::new(RotorModel::from_toml(&text, "seal.toml").unwrap()).unwrap();
    let speed = 3000.0 * std::f64::consts::PI / 30.0;
    let s = stability_study(&rotor, &StabilityRequest::at(speed)).unwrap();
    // The cylindrical mode: the lowest forward mode (the 14 kHz bending
    // modes of the stiffened shaft are the least damped ones).
    let mode = s
        .modes
        .iter()
        .filter(|m| m.whirl == Whirl::Forward)
        .min_by(|a, b| a.damped_frequency.total_cmp(&b.damped_frequency))
        .unwrap();
    (
        mode.log_decrement,
        mode.damped_frequency / std::f64::consts::TAU,
    )
}

/// The seal's `Q` lowers the forward log decrement as the closed form says:
/// without it δ and f_d within 1e-3 (the shaft's own flexibility, a
/// thousand times steel's stiffness, leaves 2.5e-4), and the drop δ(0) − δ(Q)
/// within 1e-3 of the closed form's at Q = 3e5 and 1.5e6 N/m (measured
/// 3.4e-4 and 3.5e-4; δ falls 0.315 → 0.267 → 0.078) — the seal is in the
/// eigenproblem, not added beside it.
#[test]
fn a_seals_cross_coupling_enters_the_stability_eigenproblem() {
    let m = 7850.0 * std::f64::consts::FRAC_PI_4 * 0.1 * 0.1 * 1.0;
    let (k, c) = (2.0e7, 2.0 * 1756.0);
    let (d0, f0) = cylindrical_forward(0.0);
    let (e0, g0) = closed_form(m, c, k, 0.0);
    assert!((d0 / e0 - 1.0).abs() < 1e-3, "{d0} against {e0}");
    assert!((f0 / g0 - 1.0).abs() < 1e-3, "{f0} Hz against {g0} Hz");
    for q in [3e5, 1.5e6] {
        let (d, _) = cylindrical_forward(q);
        let (e, _) = closed_form(m, c, k, q);
        let drop = (d0 - d) / (e0 - e);
        assert!(
            (drop - 1.0).abs() < 1e-3,
            "Q = {q}: {d} ({d0} at 0) against {e} ({e0})"
        );
        assert!(d < d0 - 0.04, "Q = {q}: {d} against {d0}");
    }
}
