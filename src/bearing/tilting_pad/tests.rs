//! Unit tests of `bearing::tilting_pad` (the parent module's `mod tests`).

use super::*;

/// Four pads without preload, load on the bottom pad: with the journal low
/// in the bearing and moved sideways, the side pad it moves towards has a
/// loaded zero-moment tilt. Left at zero tilt its film diverges everywhere
/// and carries nothing; `reseat_internal` puts it on the loaded tilt, where
/// it pushes the journal back, and leaves the loaded bottom pad and the
/// side pad the journal moves away from alone.
/// `internal_balance` is pad `m`'s row of the whole bearing's
/// evaluation: its generalized force and diagonal Jacobians agree with
/// `evaluate` (which batches the pads' films) to round-off, for loaded,
/// unloaded and contacting pads, with tilt rates.
#[test]
fn a_pads_own_balance_is_its_row_of_the_bearing_evaluation() {
    let pads = (0..5)
        .map(|k| {
            Pad::new(
                (18.0 + 72.0 * k as f64).to_radians(),
                0.9,
                0.6,
                0.2 * (k % 2) as f64,
            )
        })
        .collect();
    let b = TiltingPadBearing {
        radius: 0.05,
        length: 0.03,
        clearance: 1e-4,
        viscosity: 0.02,
        pads,
        contact: None,
        support: Default::default(),
    };
    let speed = 314.16;
    let n = 7;
    let mut eval = BearingEval::new(n);
    for (journal, tilt) in [
        ([0.3e-4, -0.5e-4], 1e-5),
        ([0.0, 0.0], 0.0),
        ([-0.9e-4, 0.5e-4], -2e-5),
    ] {
        let mut q = vec![journal[0], journal[1], 0.0, 0.0, 0.0, 0.0, 0.0];
        b.guess_internal(journal, speed, &mut q[2..]);
        q[3] += tilt;
        let qd: Vec<f64> = (0..n).map(|i| 1e-4 * (i as f64 - 3.0)).collect();
        b.evaluate(&q, &qd, speed, &mut eval).unwrap();
        for m in 0..5 {
            let [f, k, c] = b.internal_balance(m, &q, &qd, speed).unwrap().unwrap();
            let i = 2 + m;
            let close = |a: f64, e: f64, scale: f64| (a - e).abs() <= 1e-12 * scale.max(1e-300);
            let fs = eval.force.iter().fold(0.0f64, |a, v| a.max(v.abs()));
            let ks = eval.stiffness.iter().fold(0.0f64, |a, v| a.max(v.abs()));
            let cs = eval.damping.iter().fold(0.0f64, |a, v| a.max(v.abs()));
            assert!(close(f, eval.force[i], fs), "{m}: {f} {}", eval.force[i]);
            assert!(close(k, eval.stiffness[i * n + i], ks), "{m}: {k}");
            assert!(close(c, eval.damping[i * n + i], cs), "{m}: {c}");
        }
    }
    assert!(
        b.internal_balance(5, &[0.0; 7], &[0.0; 7], speed)
            .unwrap()
            .is_err()
    );
}

#[test]
fn a_side_pad_left_on_its_unloaded_branch_is_reseated_on_the_loaded_one() {
    let pads = (0..4)
        .map(|k| {
            Pad::new(
                (270.0 + 90.0 * k as f64).to_radians(),
                80f64.to_radians(),
                0.5,
                0.0,
            )
        })
        .collect();
    let b = TiltingPadBearing {
        radius: 0.05,
        length: 0.03,
        clearance: 1e-4,
        viscosity: 0.02,
        pads,
        contact: None,
        support: Default::default(),
    };
    let speed = 314.16;
    let journal = [0.3e-4, -0.5e-4];
    let mut q = vec![journal[0], journal[1], 0.0, 0.0, 0.0, 0.0];
    b.guess_internal(journal, speed, &mut q[2..]);
    let bottom = q[2];
    q[3] = 0.0; // the side pad at 0°, which the journal moves towards
    q[5] = 0.0; // the side pad at 180°, which it moves away from
    let rates = vec![0.0; 6];
    let force = |q: &[f64], k: usize| b.pad_force(k, q, &rates, speed).unwrap();
    assert_eq!(force(&q, 1).norm(), 0.0, "unloaded at zero tilt");
    assert!(force(&q, 0).y > 0.0, "the bottom pad carries");
    let before = q.clone();
    assert!(b.reseat_internal(&mut q, speed));
    assert_eq!(q[2], bottom, "the loaded pad is left alone");
    assert_eq!(
        q[5], before[5],
        "no loaded tilt for the pad the journal leaves"
    );
    assert_eq!(Some(q[3]), b.stable_tilt(1, journal, speed));
    assert!(
        force(&q, 1).x < 0.0,
        "the re-seated pad pushes the journal back"
    );
    let mut again = q.clone();
    assert!(
        !b.reseat_internal(&mut again, speed),
        "nothing left to move"
    );
    assert_eq!(again, q);
}
