//! The tilting-pad evaluation as the solver's hot path runs it (the pressure
//! half circle's cover of each pad from the signs of the film source at the
//! pad's ends, the written-out potential jet, no contact law within the gap)
//! against a straightforward evaluation kept here: the formulas of the module
//! docs of `bearing::tilting_pad` and `bearing::plain` step by step, the
//! pressure arc by its angles on every pad, the potential by the generic jet
//! arithmetic and the contact law on every pad. Forces and both Jacobians of
//! every pad and the journal agree to 1e-12 of each entry (plus 1e-15 of the
//! largest, for entries that cancel) on five geometries (3–12 pads, preload 0
//! to 0.5, pivot offsets 0.5 and 0.6), eccentricities from the centre through
//! the film's saturation into contact, tilts that unload pads, squeeze and
//! whirl velocities, and speeds from standstill to reverse rotation.
//!
//! The front ends' pass (`Bearing::output`: each pad once, the force without
//! its Jacobians) gives the same forces and report bit for bit, as does the
//! chord iterations' (`Bearing::forces`), the thinnest
//! film (now by cross products instead of angles) within 1e-14 of the
//! clearance of the formula by angles kept here.
//!
//! Then the orbits: `rotor simulate` of the shipped hydro unit and the
//! three-guide-bearing unit at a 5 ms step against the runs of the solver
//! before this hot path (`tests/data/orbit_*.csv`, made on main at 2d919c5).

use std::f64::consts::PI;
use std::path::PathBuf;
use std::process::Command;

use nalgebra::{DMatrix, DVector, Matrix2, Vector2};

use rotor_bearing::bearing::film::{FilmIntegrals, Jet3, atan_difference};
use rotor_bearing::bearing::short_film::film_position;
use rotor_bearing::bearing::tilting_pad::{Pad, TiltingPadBearing};
use rotor_bearing::bearing::{Bearing, BearingEval};

/// `Φ(x, y)` over an arc by the generic jet arithmetic (`bearing::film`
/// docs), the two arc tangents of its value taken as one
/// ([`atan_difference`], tested against their difference in the library).
fn potential(x: f64, y: f64, span: f64, end1: (f64, f64), end2: (f64, f64)) -> Jet3 {
    let (jx, jy) = (Jet3::var_x(x), Jet3::var_y(y));
    let one = Jet3::constant(1.0);
    let m = one - jx * jx - jy * jy;
    let root = m.sqrt();
    let ratio = |(s, c): (f64, f64)| {
        let num = jx * s - jy * c;
        let den = one + root - jx * c - jy * s;
        num / den
    };
    let (t2, t1) = (ratio(end2), ratio(end1));
    let diff = (t2.atan() - t1.atan()).with_value(atan_difference(t2.value(), t1.value()));
    (Jet3::constant(span) + diff * 2.0) / root
}

/// Force, `K`, `C` of the short-bearing film at `(p, v)` over the part of the
/// window `[from, from + arc]` where the film source `S = A sin θ − B cos θ`
/// is negative, the arc found by its angles (`bearing::plain` docs).
#[allow(clippy::too_many_arguments)]
fn film(
    b: &TiltingPadBearing,
    p: Vector2<f64>,
    v: Vector2<f64>,
    speed: f64,
    from: f64,
    arc: f64,
) -> (Vector2<f64>, Matrix2<f64>, Matrix2<f64>) {
    let cl = b.clearance;
    let (p, saturation) = film_position(p, cl);
    let (x, y) = (p.x / cl, p.y / cl);
    let (a, bb) = (speed * p.x - 2.0 * v.y, speed * p.y + 2.0 * v.x);
    let r = a.hypot(bb);
    let scale = (speed * p.x).abs() + (speed * p.y).abs() + 2.0 * v.x.abs() + 2.0 * v.y.abs();
    let pressure = !(r <= 1e-14 * scale || r == 0.0);
    let start = if pressure {
        bb.atan2(a) + PI
    } else {
        y.atan2(x) + 0.5 * PI
    };
    let start_sc = if pressure {
        (-bb / r, -a / r)
    } else {
        start.sin_cos()
    };
    let end_sc = (-start_sc.0, -start_sc.1);
    let (to, from_sc, to_sc) = (from + arc, from.sin_cos(), (from + arc).sin_cos());
    let mut f = FilmIntegrals::default();
    for k in -2..=1 {
        let lo_angle = start + 2.0 * PI * k as f64;
        let hi_angle = lo_angle + PI;
        let (lo, lo_sc) = if lo_angle >= from {
            (lo_angle, start_sc)
        } else {
            (from, from_sc)
        };
        let (hi, hi_sc) = if hi_angle <= to {
            (hi_angle, end_sc)
        } else {
            (to, to_sc)
        };
        if hi > lo {
            f = f + FilmIntegrals::from_potential(potential(x, y, hi - lo, lo_sc, hi_sc));
        }
    }
    let c = b.viscosity * b.radius * b.length.powi(3) / (4.0 * cl.powi(3));
    let force = Vector2::new(c * (a * f.xy - bb * f.xx), c * (a * f.yy - bb * f.xy));
    let k = -Matrix2::new(
        c * (speed * f.xy + (a * f.xxy - bb * f.xxx) / cl),
        c * (-speed * f.xx + (a * f.xyy - bb * f.xxy) / cl),
        c * (speed * f.yy + (a * f.xyy - bb * f.xxy) / cl),
        c * (-speed * f.xy + (a * f.yyy - bb * f.xyy) / cl),
    ) * saturation;
    let damping = Matrix2::new(f.xx, f.xy, f.xy, f.yy) * (2.0 * c);
    (force, k, damping)
}

/// Generalized force, `K` and `C` of the bearing at `q`, `q̇`: every pad's film
/// and contact at its effective journal state, mapped by
/// `T = [[1, 0, −sin θp], [0, 1, cos θp]]`, plus the pivots' rest moment
/// (`bearing::tilting_pad` docs).
fn straightforward(
    b: &TiltingPadBearing,
    q: &[f64],
    qd: &[f64],
    speed: f64,
) -> (DVector<f64>, DMatrix<f64>, DMatrix<f64>) {
    let n = 2 + b.pads.len();
    let (mut force, mut kk, mut cc) = (
        DVector::zeros(n),
        DMatrix::zeros(n, n),
        DMatrix::zeros(n, n),
    );
    let law = b.contact_law();
    let c_rest = 1e-9 * b.viscosity * b.radius * b.length.powi(3) / b.clearance.powi(3);
    let k_rest = c_rest * speed.abs().max(1.0);
    for (k, pad) in b.pads.iter().enumerate() {
        let (s, c) = pad.pivot().sin_cos();
        let (eta, eta_dot) = (q[2 + k], qd[2 + k]);
        let shift = pad.preload() * b.clearance;
        let p = Vector2::new(q[0] + shift * c - eta * s, q[1] + shift * s + eta * c);
        let v = Vector2::new(qd[0] - eta_dot * s, qd[1] + eta_dot * c);
        let from = (pad.pivot() - pad.offset() * pad.arc()).rem_euclid(2.0 * PI);
        let (ff, fk, fc) = film(b, p, v, speed, from, pad.arc());
        let phi = p.y.atan2(p.x);
        let (contact, _) = if (phi - from).rem_euclid(2.0 * PI) <= pad.arc() {
            law.evaluate(p, v, speed)
        } else {
            let lead = Vector2::new(from.cos(), from.sin());
            let trail = Vector2::new((from + pad.arc()).cos(), (from + pad.arc()).sin());
            let normal = if p.dot(&lead) >= p.dot(&trail) {
                lead
            } else {
                trail
            };
            law.evaluate_edge(normal, p, v, speed)
        };
        let mut t = DMatrix::zeros(2, n);
        t[(0, 0)] = 1.0;
        t[(1, 1)] = 1.0;
        t[(0, 2 + k)] = -s;
        t[(1, 2 + k)] = c;
        let total_f = DVector::from_column_slice((ff + contact.force).as_slice());
        let to_dense = |m: Matrix2<f64>| DMatrix::from_fn(2, 2, |i, j| m[(i, j)]);
        force += t.transpose() * total_f;
        kk += t.transpose() * to_dense(fk + contact.stiffness) * &t;
        cc += t.transpose() * to_dense(fc + contact.damping) * &t;
        force[2 + k] -= k_rest * q[2 + k] + c_rest * qd[2 + k];
        kk[(2 + k, 2 + k)] += k_rest;
        cc[(2 + k, 2 + k)] += c_rest;
    }
    (force, kk, cc)
}

/// `n` pads of arc `arc_deg`, the first pivot at `first_deg`.
fn bearing(
    (radius, length, clearance, viscosity): (f64, f64, f64, f64),
    n: usize,
    first_deg: f64,
    arc_deg: f64,
    offset: f64,
    preload: f64,
) -> TiltingPadBearing {
    TiltingPadBearing {
        radius,
        length,
        clearance,
        viscosity,
        pads: (0..n)
            .map(|k| {
                Pad::new(
                    (first_deg + 360.0 * k as f64 / n as f64).to_radians(),
                    arc_deg.to_radians(),
                    offset,
                    preload,
                )
            })
            .collect(),
        contact: None,
        support: Default::default(),
    }
}

/// Thinnest film (m) on pad `k` by angles: `h(θ) = C − X_e cos θ − Y_e sin θ`
/// at `θ = atan2(Y_e, X_e)` when on the pad's arc, else the smaller at its edges.
fn min_film_by_angles(b: &TiltingPadBearing, k: usize, q: &[f64]) -> f64 {
    let pad = &b.pads[k];
    let (s, c) = pad.pivot().sin_cos();
    let shift = pad.preload() * b.clearance;
    let eta = q[2 + k];
    let (x, y) = (q[0] + shift * c - eta * s, q[1] + shift * s + eta * c);
    let (from, to) = pad.edges();
    let h = |t: f64| b.clearance - x * t.cos() - y * t.sin();
    let phi = y.atan2(x);
    if (phi - from).rem_euclid(2.0 * PI) <= to - from {
        h(phi)
    } else {
        h(from).min(h(to))
    }
}

/// Largest `|a − b| / (|b| + 1e-3 · max |b|)` over the entries.
fn worst(a: &[f64], b: &[f64]) -> f64 {
    let scale = b.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    a.iter()
        .zip(b)
        .map(|(x, y)| (x - y).abs() / (y.abs() + 1e-3 * scale).max(f64::MIN_POSITIVE))
        .fold(0.0, f64::max)
}

#[test]
fn the_hot_path_matches_a_straightforward_evaluation_on_every_pad() {
    let small = (0.05, 0.03, 1e-4, 0.02);
    let guide = (0.35, 0.2, 0.25e-3, 0.03);
    let bearings = [
        bearing(small, 4, 45.0, 80.0, 0.5, 0.0),
        bearing(small, 5, 270.0, 60.0, 0.6, 0.5),
        bearing(small, 3, 90.0, 110.0, 0.5, 0.2),
        bearing(guide, 12, 15.0, 24.0, 0.5, 0.3),
        bearing(guide, 8, 22.5, 36.0, 0.5, 0.0),
    ];
    let mut seed = 5u64;
    let mut rand = || {
        seed = seed
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (seed >> 11) as f64 / (1u64 << 53) as f64 - 0.5
    };
    let (mut cases, mut loaded, mut unloaded, mut contact) = (0, 0, 0, 0);
    let mut largest: f64 = 0.0;
    let (mut largest_film, mut outputs): (f64, usize) = (0.0, 0);
    for b in &bearings {
        let n = 2 + b.pads.len();
        let cl = b.clearance;
        let mut out = BearingEval::new(n);
        for speed in [0.0f64, 31.4, 314.16, -120.0] {
            for eps in [0.0, 0.2, 0.5, 0.8, 0.96, 0.985, 1.03] {
                for angle in [-90.0f64, 17.0, 200.0] {
                    let (s, c) = angle.to_radians().sin_cos();
                    // Tilts within ±0.4 C unload some pads and load others;
                    // rates: at rest, squeeze, whirl.
                    let eta: Vec<f64> = (0..b.pads.len()).map(|_| 0.8 * cl * rand()).collect();
                    let whirl = speed.abs().max(10.0) * cl;
                    for rates in [0.0, 0.05, 0.5] {
                        let mut q = vec![eps * cl * c, eps * cl * s];
                        q.extend(&eta);
                        let qd: Vec<f64> = (0..n).map(|_| rates * whirl * rand()).collect();
                        b.evaluate(&q, &qd, speed, &mut out).unwrap();
                        let (f, k, d) = straightforward(b, &q, &qd, speed);
                        // Row-major as `BearingEval` stores them.
                        let k = k.transpose();
                        let d = d.transpose();
                        for (what, got, want) in [
                            ("force", out.force.as_slice(), f.as_slice()),
                            ("stiffness", out.stiffness.as_slice(), k.as_slice()),
                            ("damping", out.damping.as_slice(), d.as_slice()),
                        ] {
                            let e = worst(got, want);
                            largest = largest.max(e);
                            assert!(
                                e <= 1e-12,
                                "{} pads, speed {speed}, ε = {eps} at {angle}°, rates {rates}: {what} differs by {e:e}\n{got:?}\n{want:?}",
                                b.pads.len()
                            );
                        }
                        // The front ends' pass: the same forces and report, bit
                        // for bit, the thinnest film to round-off of the clearance.
                        let report = b.report(&q, &qd, speed, &out);
                        let mut single = BearingEval::new(n);
                        let got = b.output(&q, &qd, speed, &mut single).unwrap();
                        for (a, w) in single.force.iter().zip(&out.force) {
                            assert_eq!(
                                a.to_bits(),
                                w.to_bits(),
                                "output force {:?} vs {:?}",
                                single.force,
                                out.force
                            );
                        }
                        assert_eq!(got, report);
                        // The chord iterations' pass: the same forces, bit for bit.
                        let mut forces = BearingEval::new(n);
                        b.forces(&q, &qd, speed, &mut forces).unwrap();
                        assert_eq!(forces.force, single.force);
                        let thinnest = (0..b.pads.len())
                            .map(|k| min_film_by_angles(b, k, &q))
                            .fold(f64::INFINITY, f64::min)
                            .max(0.0);
                        let e = (report.min_film_thickness - thinnest).abs();
                        largest_film = largest_film.max(e / cl);
                        assert!(
                            e <= 1e-14 * cl,
                            "min film {} vs {thinnest}",
                            report.min_film_thickness
                        );
                        outputs += 1;
                        for k in 0..b.pads.len() {
                            if b.pad_force(k, &q, &qd, speed).unwrap().norm() == 0.0 {
                                unloaded += 1;
                            } else {
                                loaded += 1;
                            }
                        }
                        contact += usize::from(b.contact_extent(&q, &qd, speed).is_some());
                        cases += 1;
                    }
                }
            }
        }
    }
    println!(
        "{cases} states, {loaded} loaded and {unloaded} unloaded pad films, {contact} in contact: worst relative difference {largest:e}"
    );
    println!("{outputs} outputs: thinnest film within {largest_film:e} of the clearance");
    // The cases reach what they are meant to: unloaded pads, contact.
    assert!(unloaded > 1000 && loaded > 1000 && contact > 50);
}

fn csv(text: &str) -> (Vec<String>, Vec<Vec<f64>>) {
    let mut lines = text.lines();
    let header = lines
        .next()
        .unwrap()
        .split(',')
        .map(str::to_string)
        .collect();
    let rows = lines
        .map(|l| l.split(',').map(|v| v.parse().unwrap()).collect())
        .collect();
    (header, rows)
}

/// `rotor simulate` of `model` at `rpm`, 2 s in 5 ms steps, against the
/// reference run: every column within 1e-7 of its largest value. A change of
/// the last bits of a force can move a Newton iterate by up to the solver's
/// tolerance (1e-8 of the step's displacement scale) where it decides whether
/// a step has converged; ten times that bounds such round-off.
fn orbit_matches(model: &str, rpm: &str) {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("tilting_pad_evaluation");
    std::fs::create_dir_all(&dir).unwrap();
    let out = dir.join(format!("{model}.csv"));
    let run = Command::new(env!("CARGO_BIN_EXE_rotor"))
        .arg("simulate")
        .arg(root.join("models").join(format!("{model}.toml")))
        .args(["--rpm", rpm, "--duration", "2", "--step", "5e-3"])
        .args(["--output-step", "0.02", "--csv"])
        .arg(&out)
        .output()
        .unwrap();
    assert!(
        run.status.success(),
        "{}",
        String::from_utf8_lossy(&run.stderr)
    );
    let (header, rows) = csv(&std::fs::read_to_string(&out).unwrap());
    let reference = root.join("tests/data").join(format!("orbit_{model}.csv"));
    let (want_header, want) = csv(&std::fs::read_to_string(reference).unwrap());
    // Columns appended since the reference was stored (the power losses)
    // come after its own.
    assert_eq!(header[..want_header.len()], want_header[..]);
    assert_eq!(rows.len(), want.len());
    let mut largest: f64 = 0.0;
    for (c, name) in want_header.iter().enumerate() {
        let scale = want.iter().fold(0.0f64, |m, r| m.max(r[c].abs()));
        for (got, row) in rows.iter().zip(&want) {
            let e = (got[c] - row[c]).abs() / scale.max(f64::MIN_POSITIVE);
            largest = largest.max(e);
            assert!(
                e <= 1e-7,
                "{model} {name} at t = {} s: {} vs {}",
                row[0],
                got[c],
                row[c]
            );
        }
    }
    println!(
        "{model}: {} rows, worst relative difference {largest:e}",
        rows.len()
    );
}

#[test]
fn the_hydro_unit_orbit_is_the_one_before_the_hot_path() {
    orbit_matches("hydro_unit", "150");
}

#[test]
fn the_three_guide_unit_orbit_is_the_one_before_the_hot_path() {
    orbit_matches("hydro_unit_three_guide", "300");
}
