//! Tilting-pad bearing against the independent oracle in
//! `tests/data/tilting_pad_reference.json` (per-pad quadrature of the
//! short-bearing film, pad tilts from moment equilibrium, finite-difference
//! coefficients) and against finite differences of our own forces.

use nalgebra::{DMatrix, Matrix2, Vector2};
use serde_json::Value;

#[path = "common/reference.rs"]
mod common_reference;
use common_reference::num;

fn reference() -> Value {
    common_reference::reference("tilting_pad_reference.json")
}

use rotor_bearing::bearing::equilibrium::{condensed_coefficients, journal_equilibrium};
use rotor_bearing::bearing::tilting_pad::{Pad, TiltingPadBearing};
use rotor_bearing::bearing::{Bearing, BearingEval};

fn bearing(r: &Value) -> (TiltingPadBearing, f64) {
    let p = &r["parameters"];
    let pads = p["pivots_deg"]
        .as_array()
        .unwrap()
        .iter()
        .map(|d| {
            Pad::new(
                num(d).to_radians(),
                num(&p["pad_arc_deg"]).to_radians(),
                num(&p["pivot_offset"]),
                num(&p["preload"]),
            )
        })
        .collect();
    (
        TiltingPadBearing {
            radius: num(&p["R"]),
            length: num(&p["L"]),
            clearance: num(&p["C"]),
            viscosity: num(&p["mu"]),
            pads,
            contact: None,
            support: Default::default(),
        },
        num(&p["omega"]),
    )
}

fn equilibrium(
    r: &Value,
) -> (
    TiltingPadBearing,
    f64,
    rotor_bearing::bearing::equilibrium::Equilibrium,
) {
    let (b, w) = bearing(r);
    let load = num(&r["parameters"]["W"]);
    let eq = journal_equilibrium(&b, Vector2::new(0.0, -load), w, b.clearance).unwrap();
    (b, w, eq)
}

#[test]
fn equilibrium_journal_position_and_pad_tilts() {
    let r = reference();
    let (b, w, eq) = equilibrium(&r);
    let re = &r["equilibrium"];
    let c = b.clearance;
    // Load between pads: the journal sinks straight down.
    assert!(eq.q[0].abs() < 1e-9 * c, "X = {}", eq.q[0]);
    let eps = -eq.q[1] / c;
    assert!((eps - num(&re["eps"])).abs() < 1e-5, "ε = {eps}");
    for pad in re["pads"].as_array().unwrap() {
        let k = pad["pad"].as_u64().unwrap() as usize;
        let f = b.pad_force(k, &eq.q, &vec![0.0; eq.q.len()], w).unwrap();
        if pad["loaded"].as_bool().unwrap() {
            let eta = num(&pad["eta"]);
            assert!(
                (eq.q[2 + k] - eta).abs() < 1e-5 * eta.abs().max(1e-6 * c),
                "pad {k}: η {} vs {eta}",
                eq.q[2 + k]
            );
            let want = Vector2::new(num(&pad["Fx"]), num(&pad["Fy"]));
            assert!(
                (f - want).norm() < 1e-4 * want.norm(),
                "pad {k}: {f:?} vs {want:?}"
            );
            // Zero pivot moment: the pad force points through the pivot.
            let (s, co) = b.pads[k].pivot().sin_cos();
            assert!((co * f.y - s * f.x).abs() < 1e-6 * f.norm());
        } else {
            // The journal moves away from this pad: it must carry (next to) nothing.
            assert!(f.norm() < 1e-3, "unloaded pad {k} carries {f:?}");
        }
    }
}

#[test]
fn synchronously_condensed_coefficients() {
    let r = reference();
    let (_, w, eq) = equilibrium(&r);
    let (k, c) = condensed_coefficients(&eq.eval, w);
    let rs = &r["synchronous_reduced"];
    let (kr, cr) = (num(&rs["K"][0][0]), num(&rs["C"][0][0]));
    // Issue: within 1%; the formulation is exact, so ask for 1e-5.
    for i in 0..2 {
        assert!(
            (k[(i, i)] - kr).abs() < 1e-5 * kr,
            "K{i}{i} = {} vs {kr}",
            k[(i, i)]
        );
        assert!(
            (c[(i, i)] - cr).abs() < 1e-5 * cr,
            "C{i}{i} = {} vs {cr}",
            c[(i, i)]
        );
    }
    assert!(
        k[(0, 1)].abs() < 1e-3 * kr && k[(1, 0)].abs() < 1e-3 * kr,
        "{k}"
    );
    assert!(
        c[(0, 1)].abs() < 1e-3 * cr && c[(1, 0)].abs() < 1e-3 * cr,
        "{c}"
    );
    // Against excitation frequency (pads follow with their own squeeze film).
    for row in r["reduced_vs_frequency"].as_array().unwrap() {
        let f = num(&row["Omega_over_omega"]) * w;
        let (k, c) = condensed_coefficients(&eq.eval, f);
        let (kxx, cxx) = (num(&row["Kxx"]), num(&row["Cxx"]));
        assert!(
            (k[(0, 0)] - kxx).abs() < 1e-5 * kxx,
            "Ω = {f}: K {} vs {kxx}",
            k[(0, 0)]
        );
        assert!(
            (c[(0, 0)] - cxx).abs() < 1e-5 * cxx,
            "Ω = {f}: C {} vs {cxx}",
            c[(0, 0)]
        );
    }
}

#[test]
fn full_coefficients_with_pad_coordinates() {
    let r = reference();
    let (_, _, eq) = equilibrium(&r);
    let fc = &r["full_coefficients"];
    // Reference coordinates: X, Y, η of the loaded pads 2 and 3.
    let idx = [0usize, 1, 4, 5];
    for (name, mine) in [("K", &eq.eval.stiffness), ("C", &eq.eval.damping)] {
        let want = &fc[name];
        let err = &fc[format!("fd_error_estimate_{name}")];
        let n = eq.eval.n();
        let scale = (0..4)
            .flat_map(|i| (0..4).map(move |j| (i, j)))
            .map(|(i, j)| num(&want[i][j]).abs())
            .fold(0.0, f64::max);
        for (a, &i) in idx.iter().enumerate() {
            for (b, &j) in idx.iter().enumerate() {
                let got = mine[i * n + j];
                let w = num(&want[a][b]);
                let tol = 1e-5 * scale + 10.0 * num(&err[a][b]);
                assert!((got - w).abs() < tol, "{name}[{a}][{b}]: {got} vs {w}");
            }
        }
    }
}

#[test]
fn quasi_static_reduction_invents_cross_coupled_damping() {
    // Why the pad tilts are unknowns with their own dynamics: dropping η̇ (pads
    // re-equilibrating instantly) reproduces the reference's spurious coupling.
    let r = reference();
    let (_, _, eq) = equilibrium(&r);
    let n = eq.eval.n();
    let k = DMatrix::from_row_slice(n, n, &eq.eval.stiffness);
    let c = DMatrix::from_row_slice(n, n, &eq.eval.damping);
    let kpp = k.view((2, 2), (n - 2, n - 2)).into_owned();
    let kjp = k.view((0, 2), (2, n - 2)).into_owned();
    let cpj = c.view((2, 0), (n - 2, 2)).into_owned();
    let c_qs = c.view((0, 0), (2, 2)).into_owned() - &kjp * kpp.lu().solve(&cpj).unwrap();
    let want = &r["quasi_static_reduced"]["C"];
    let want = Matrix2::new(
        num(&want[0][0]),
        num(&want[0][1]),
        num(&want[1][0]),
        num(&want[1][1]),
    );
    let got = Matrix2::from_fn(|i, j| c_qs[(i, j)]);
    assert!((got - want).amax() < 1e-4 * want.amax(), "{got} vs {want}");
    assert!(got[(0, 1)].abs() > 0.5 * got[(0, 0)].abs());
}

#[test]
fn jacobians_match_finite_differences_at_moving_states() {
    let r = reference();
    let (b, w, eq) = equilibrium(&r);
    let n = eq.eval.n();
    let c = b.clearance;
    // Perturb the equilibrium into a moving state with tilting pads.
    let q: Vec<f64> =
        eq.q.iter()
            .enumerate()
            .map(|(i, v)| v + 0.03 * c * ((i as f64) * 1.3).sin())
            .collect();
    let qd: Vec<f64> = (0..n)
        .map(|i| 0.05 * w * c * ((i as f64) * 0.7 + 0.2).cos())
        .collect();
    let mut e = BearingEval::new(n);
    b.evaluate(&q, &qd, w, &mut e).unwrap();
    let force = |q: &[f64], qd: &[f64]| {
        let mut out = BearingEval::new(n);
        b.evaluate(q, qd, w, &mut out).unwrap();
        out.force
    };
    let (h, hv) = (1e-7 * c, 1e-7 * w * c);
    let ks = e.stiffness.iter().fold(0.0f64, |a, v| a.max(v.abs()));
    let cs = e.damping.iter().fold(0.0f64, |a, v| a.max(v.abs()));
    for j in 0..n {
        let (mut qp, mut qm) = (q.clone(), q.clone());
        qp[j] += h;
        qm[j] -= h;
        let (fp, fm) = (force(&qp, &qd), force(&qm, &qd));
        let (mut vp, mut vm) = (qd.clone(), qd.clone());
        vp[j] += hv;
        vm[j] -= hv;
        let (gp, gm) = (force(&q, &vp), force(&q, &vm));
        for i in 0..n {
            let kfd = -(fp[i] - fm[i]) / (2.0 * h);
            let cfd = -(gp[i] - gm[i]) / (2.0 * hv);
            assert!(
                (e.stiffness[i * n + j] - kfd).abs() < 1e-5 * ks,
                "K[{i}][{j}] {} vs {kfd}",
                e.stiffness[i * n + j]
            );
            assert!(
                (e.damping[i * n + j] - cfd).abs() < 1e-5 * cs,
                "C[{i}][{j}] {} vs {cfd}",
                e.damping[i * n + j]
            );
        }
    }
}

#[test]
fn many_pads_and_contact_are_handled() {
    // 3 to 18 pads, random states: finite results or a reported contact, no panic.
    let mut seed: u64 = 0x2545_F491_4F6C_DD1D;
    let mut next = || {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        (seed >> 11) as f64 / (1u64 << 53) as f64
    };
    for pads in [3usize, 5, 12, 18] {
        let arc = 0.8 * 2.0 * std::f64::consts::PI / pads as f64;
        let b = TiltingPadBearing {
            radius: 0.5,
            length: 0.3,
            clearance: 3e-4,
            viscosity: 0.03,
            pads: (0..pads)
                .map(|k| {
                    Pad::new(
                        2.0 * std::f64::consts::PI * k as f64 / pads as f64 + 0.3,
                        arc,
                        0.6,
                        0.2,
                    )
                })
                .collect(),
            contact: None,
            support: Default::default(),
        };
        let n = 2 + pads;
        let mut out = BearingEval::new(n);
        for _ in 0..2000 {
            let q: Vec<f64> = (0..n).map(|_| (next() - 0.5) * 2.4 * b.clearance).collect();
            let qd: Vec<f64> = (0..n).map(|_| (next() - 0.5) * 0.1).collect();
            let speed = 16.0 * next();
            b.evaluate(&q, &qd, speed, &mut out)
                .unwrap_or_else(|e| panic!("{e} at q = {q:?}"));
            assert!(
                out.force
                    .iter()
                    .chain(&out.stiffness)
                    .chain(&out.damping)
                    .all(|v| v.is_finite())
            );
            let rep = b.report(&q, &qd, speed, &out);
            assert!(rep.friction_torque.is_finite() && rep.min_film_thickness >= 0.0);
            assert!(rep.contact_force.is_finite() && rep.contact_force >= 0.0);
        }
    }
}

#[test]
fn report_of_the_loaded_bearing() {
    let r = reference();
    let (b, w, eq) = equilibrium(&r);
    let rep = b.report(&eq.q, &vec![0.0; eq.q.len()], w, &eq.eval);
    assert!((rep.eccentricity - num(&r["equilibrium"]["eps"])).abs() < 1e-6);
    // Load between pads 2 and 3: the thinnest film is theirs.
    let h_ref = num(&r["equilibrium"]["pads"][2]["h_min"]);
    assert!(
        (rep.min_film_thickness - h_ref).abs() < 1e-4 * h_ref,
        "{} vs {h_ref}",
        rep.min_film_thickness
    );
    // Friction of four 80° pads lies between 4·80/360 of a centred plain bearing and a full plain bearing at ε = 0.585.
    let petroff =
        2.0 * std::f64::consts::PI * b.viscosity * w * b.radius.powi(3) * b.length / b.clearance;
    assert!(
        rep.friction_torque > petroff * 320.0 / 360.0
            && rep.friction_torque < petroff / (1.0f64 - 0.585 * 0.585).sqrt()
    );
    eprintln!(
        "pad tilts at equilibrium: {:?} (iterations {})",
        &eq.q[2..],
        eq.iterations
    );
}
