//! `rotor modes --shapes-csv/--shapes-png`: the complex mode shapes of slender
//! uniform beams against the Euler–Bernoulli shapes (modal assurance criterion).

use std::path::{Path, PathBuf};
use std::process::Command;

const ELEMENTS: usize = 40;

/// A steel beam, L = 1 m, d = 10 mm (L/d = 100), Euler–Bernoulli element flags,
/// 40 elements; `ends` fixes both end nodes (`pinned`) or nothing.
fn beam(dir: &Path, ends: &str) -> PathBuf {
    let supports = if ends.is_empty() {
        String::new()
    } else {
        format!(
            "[[supports]]\nnode = 1\nfix = [\"{ends}\"]\n[[supports]]\nnode = {}\nfix = [\"{ends}\"]\n",
            ELEMENTS + 1
        )
    };
    let text = format!(
        r#"name = "beam"
shear_deformation = false
rotary_inertia = false
[[materials]]
name = "steel"
youngs_modulus = 211e9
shear_modulus = 81.2e9
density = 7810.0
[[shaft]]
length = 1.0
outer_diameter = 0.01
material = "steel"
elements = {ELEMENTS}
{supports}"#
    );
    let path = dir.join(format!(
        "beam_{}.toml",
        if ends.is_empty() { "free" } else { ends }
    ));
    std::fs::write(&path, text).unwrap();
    path
}

fn out_dir(name: &str) -> PathBuf {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join(name);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// One mode read from the shapes CSV: frequency (Hz), z, X and Y per node.
struct Shape {
    hz: f64,
    z: Vec<f64>,
    x: Vec<(f64, f64)>,
    y: Vec<(f64, f64)>,
}

fn shapes(model: &Path, csv: &Path, png: &Path, modes: usize) -> Vec<Shape> {
    let out = Command::new(env!("CARGO_BIN_EXE_rotor"))
        .arg("modes")
        .arg(model)
        .args(["--modes", &modes.to_string(), "--shapes-csv"])
        .arg(csv)
        .arg("--shapes-png")
        .arg(png)
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = std::fs::read_to_string(csv).unwrap();
    let mut lines = text.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let col = |name: &str| header.iter().position(|h| *h == name).unwrap();
    let mut found: Vec<Shape> = Vec::new();
    for line in lines {
        let c: Vec<&str> = line.split(',').collect();
        let num = |name: &str| -> f64 { c[col(name)].parse().unwrap() };
        let mode: usize = c[col("mode")].parse().unwrap();
        if found.len() < mode {
            found.push(Shape {
                hz: num("damped_frequency_hz"),
                z: Vec::new(),
                x: Vec::new(),
                y: Vec::new(),
            });
        }
        let s = &mut found[mode - 1];
        s.z.push(num("z_m"));
        s.x.push((num("x_re"), num("x_im")));
        s.y.push((num("y_re"), num("y_im")));
    }
    let bytes = std::fs::read(png).unwrap();
    assert_eq!(&bytes[..8], b"\x89PNG\r\n\x1a\n");
    found
}

/// Modal assurance criterion of a real shape `phi` and a complex one `v`:
/// `|φᵀ v|² / ((φᵀφ)(vᴴv))`.
fn mac(phi: &[f64], v: &[(f64, f64)]) -> f64 {
    let (mut re, mut im, mut pp, mut vv) = (0.0, 0.0, 0.0, 0.0);
    for (p, (a, b)) in phi.iter().zip(v) {
        re += p * a;
        im += p * b;
        pp += p * p;
        vv += a * a + b * b;
    }
    (re * re + im * im) / (pp * vv)
}

/// Norm of a complex shape.
fn norm(v: &[(f64, f64)]) -> f64 {
    v.iter().map(|(a, b)| a * a + b * b).sum::<f64>().sqrt()
}

/// MAC of the mode's x and y parts (at zero speed a planar pair may come as any
/// mix of the two planes: each part with motion must match) and the largest
/// normalized translation, which must be exactly 1 + 0i.
fn check(shape: &Shape, phi: &[f64], what: &str) -> f64 {
    let biggest = shape
        .x
        .iter()
        .chain(&shape.y)
        .copied()
        .max_by(|a, b| a.0.hypot(a.1).total_cmp(&b.0.hypot(b.1)))
        .unwrap();
    assert_eq!(biggest, (1.0, 0.0), "{what}: normalization");
    let scale = norm(&shape.x).max(norm(&shape.y));
    let mut worst: f64 = 1.0;
    for part in [&shape.x, &shape.y] {
        if norm(part) > 1e-6 * scale {
            worst = worst.min(mac(phi, part));
        }
    }
    eprintln!("{what}: {:.4} Hz, 1 − MAC = {:.1e}", shape.hz, 1.0 - worst);
    assert!(worst >= 0.999, "{what}: MAC {worst}");
    worst
}

#[test]
fn pinned_pinned_beam_shapes_are_sines() {
    let dir = out_dir("shapes_pinned");
    let model = beam(&dir, "pinned");
    let found = shapes(&model, &dir.join("s.csv"), &dir.join("s.png"), 6);
    assert_eq!(found.len(), 6);
    for (k, shape) in found.iter().enumerate() {
        // Planar pairs: modes 1–2, 3–4, 5–6 share n = 1, 2, 3.
        let n = k / 2 + 1;
        let phi: Vec<f64> = shape
            .z
            .iter()
            .map(|z| (n as f64 * std::f64::consts::PI * z).sin())
            .collect();
        check(
            shape,
            &phi,
            &format!("pinned–pinned n = {n} (mode {})", k + 1),
        );
    }
    // A wrong shape is told apart: mode 1 against sin(2πz/L).
    let wrong: Vec<f64> = found[0]
        .z
        .iter()
        .map(|z| (2.0 * std::f64::consts::PI * z).sin())
        .collect();
    assert!(mac(&wrong, &found[0].x).max(mac(&wrong, &found[0].y)) < 0.01);
}

#[test]
fn free_free_beam_shapes_are_the_euler_bernoulli_ones() {
    let dir = out_dir("shapes_free");
    let model = beam(&dir, "");
    let found = shapes(&model, &dir.join("s.csv"), &dir.join("s.png"), 12);
    // Rigid-body motion (≈ 0 Hz) is not a bending mode: keep those above 1 Hz
    // (the first bending mode is at 46 Hz).
    let bending: Vec<&Shape> = found.iter().filter(|s| s.hz > 1.0).collect();
    assert!(bending.len() >= 6, "{} bending modes", bending.len());
    let beta_l: [f64; 3] = [4.730_040_7, 7.853_204_6, 10.995_607_8];
    for (k, shape) in bending.iter().take(6).enumerate() {
        let bl = beta_l[k / 2];
        let sigma = (bl.cosh() - bl.cos()) / (bl.sinh() - bl.sin());
        let phi: Vec<f64> = shape
            .z
            .iter()
            .map(|z| {
                let b = bl * z;
                b.cosh() + b.cos() - sigma * (b.sinh() + b.sin())
            })
            .collect();
        check(
            shape,
            &phi,
            &format!("free–free βL = {bl} (mode {})", k + 1),
        );
    }
}

/// The orbit columns of the shapes CSV follow from its X and Y (classic rotor
/// at 4000 rpm, where the modes whirl): forward radius `|X + iY|/2`, backward
/// `|X − iY|/2`, semi-axes their sum and difference, and the node's whirl.
#[test]
fn orbit_columns_follow_from_the_shape() {
    let dir = out_dir("shapes_classic");
    let csv = dir.join("s.csv");
    let out = Command::new(env!("CARGO_BIN_EXE_rotor"))
        .args(["modes", "--rpm", "4000", "--modes", "4", "--shapes-csv"])
        .arg(&csv)
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(out.status.success());
    let text = std::fs::read_to_string(&csv).unwrap();
    let mut lines = text.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let col = |name: &str| header.iter().position(|h| *h == name).unwrap();
    let mut rows = 0;
    for line in lines {
        let c: Vec<&str> = line.split(',').collect();
        let num = |name: &str| -> f64 { c[col(name)].parse().unwrap() };
        let (xr, xi, yr, yi) = (num("x_re"), num("x_im"), num("y_re"), num("y_im"));
        // X + iY = (xr − yi) + i(xi + yr); X − iY = (xr + yi) + i(xi − yr).
        let forward = (xr - yi).hypot(xi + yr) / 2.0;
        let backward = (xr + yi).hypot(xi - yr) / 2.0;
        let close = |a: f64, b: f64| (a - b).abs() <= 1e-12;
        assert!(close(num("forward_radius"), forward), "{line}");
        assert!(close(num("backward_radius"), backward), "{line}");
        assert!(close(num("major_semi_axis"), forward + backward), "{line}");
        assert!(
            close(num("minor_semi_axis"), (forward - backward).abs()),
            "{line}"
        );
        let node = c[col("node_whirl")];
        if forward + backward > 1e-3 {
            assert_eq!(
                node,
                if forward > backward {
                    "forward"
                } else {
                    "backward"
                },
                "{line}"
            );
        }
        // The mode's whirl is the one `rotor modes` prints for it.
        let mode: usize = c[col("mode")].parse().unwrap();
        let printed = stdout.lines().nth(1 + mode).unwrap();
        assert!(
            printed.ends_with(c[col("mode_whirl")]),
            "{printed} vs {line}"
        );
        rows += 1;
    }
    assert_eq!(rows, 4 * 7);
}
