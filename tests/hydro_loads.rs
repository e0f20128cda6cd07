//! The loads and losses of a hydro unit in its report (issue 48), each
//! against a hand calculation written here:
//!
//! - a vertical unit on two plain guide bearings and a thrust bearing: the
//!   thrust bearing carries the rotor's weight `W = (ρ π D²/4 L + m_d) g`;
//!   its film torque is Petroff's for a flat pad ring,
//!   `T = c π μ ω (R_o⁴ − R_i⁴)/(2h)` (the boundary friction has faded by
//!   `exp(−ω/ω_l) = e⁻⁶⁰`), its loss `T ω`; the unloaded guide bearings run
//!   centred, each losing Petroff's `2π μ ω R³ L/C · ω`; the report's total
//!   is their sum;
//! - a horizontal unit whose two bearings stand on brackets (pedestal
//!   springs in series with the bearings): statically determinate, each
//!   bearing's reaction is the beam's `R_b = g (m_s L/2 + m_d a)/L`,
//!   `R_a = g (m_s + m_d) − R_b`; each bracket passes on that reaction plus
//!   its own weight, `F = R + m_p g`, and deflects `F/k`.

use std::f64::consts::PI;

use rotor_bearing::analysis::element_operating_point::thrust_operating_points;
use rotor_bearing::analysis::operating_point::{operating_point, pedestal_operating_points};
use rotor_bearing::model::RotorModel;
use rotor_bearing::report::hydro_loads::{bracket_loads, power_losses};
use rotor_bearing::rotor::Rotor;

mod report_page;
use report_page::{report_page, table_rows};

const RPM: f64 = 300.0;
const G: f64 = 9.81;
// Shaft: length, diameter (m), density (kg/m³); generator disk mass (kg).
const L: f64 = 4.0;
const D: f64 = 0.5;
const RHO: f64 = 7850.0;
const M_DISK: f64 = 2.0e4;
// Guide bearings: radius, length, radial clearance (m), viscosity (Pa·s).
const R: f64 = 0.25;
const LB: f64 = 0.2;
const C: f64 = 0.25e-3;
const MU: f64 = 0.03;
// Thrust bearing: pad ring radii (m), film thickness (m), viscosity (Pa·s).
const RI: f64 = 0.4;
const RO: f64 = 0.8;
const H: f64 = 50e-6;

fn vertical_unit() -> String {
    format!(
        "name = \"vertical_unit\"\nmachine = \"hydro_generator\"\nspeed_rpm = {RPM}\nmax_speed_rpm = 600\n\
         gravity = [0.0, 0.0, {G}]\n\
         [[materials]]\nname = \"steel\"\nyoungs_modulus = 206e9\npoisson_ratio = 0.3\ndensity = {RHO}\n\
         [[shaft]]\nlength = {L}\nouter_diameter = {D}\nmaterial = \"steel\"\nelements = 8\n\
         [[disks]]\nname = \"generator\"\nnode = 3\nmass = {M_DISK}\npolar_inertia = 4.0e4\ndiametral_inertia = 2.0e4\n\
         [[bearings]]\nname = \"upper_guide\"\ntype = \"plain\"\nnode = 1\nradius = {R}\nlength = {LB}\nclearance = {C}\nviscosity = {MU}\n\
         [[bearings]]\nname = \"lower_guide\"\ntype = \"plain\"\nnode = 9\nradius = {R}\nlength = {LB}\nclearance = {C}\nviscosity = {MU}\n\
         [[thrust_bearings]]\nname = \"thrust\"\nnode = 1\ninner_radius = {RI}\nouter_radius = {RO}\nfilm_thickness = {H}\nviscosity = {MU}\n"
    )
}

fn close(a: f64, b: f64, tol: f64) -> bool {
    (a - b).abs() <= tol * b.abs()
}

#[test]
fn thrust_and_guide_bearing_losses_are_petroffs() {
    let omega = RPM * PI / 30.0;
    let weight = (RHO * PI * D * D / 4.0 * L + M_DISK) * G;
    // Thrust: pads cover c = 0.8 of the ring (the default); the boundary
    // friction μ_b W R_m (0.15, lift-off 5 rpm: defaults) has faded to e⁻⁶⁰.
    let film = 0.8 * PI * MU * omega * (RO.powi(4) - RI.powi(4)) / (2.0 * H);
    let boundary = 0.15 * weight * 0.5 * (RI + RO) * (-omega / (5.0 * PI / 30.0)).exp();
    let thrust_torque = film + boundary;
    let thrust_loss = thrust_torque * omega;
    // Guide bearings, centred: Petroff.
    let guide_torque = 2.0 * PI * MU * omega * R.powi(3) * LB / C;
    let guide_loss = guide_torque * omega;
    let total = 2.0 * guide_loss + thrust_loss;

    let text = vertical_unit();
    let rotor = Rotor::new(RotorModel::from_toml(&text, "vertical_unit.toml").unwrap()).unwrap();
    let thrusts = thrust_operating_points(&rotor, omega);
    assert_eq!(thrusts.len(), 1);
    assert!(
        close(thrusts[0].load, weight, 1e-12),
        "{} against {weight}",
        thrusts[0].load
    );
    assert!(close(thrusts[0].friction_torque, thrust_torque, 1e-12));
    let guides = operating_point(&rotor, omega).unwrap();
    for g in &guides {
        let f = g.film.as_ref().unwrap();
        assert!(f.eccentricity < 1e-6, "{}: ε {}", g.name, f.eccentricity);
    }
    let losses = power_losses(&rotor.model, &guides, &thrusts);
    for (name, film) in &losses.guide {
        let (t, p) = film.unwrap();
        assert!(
            close(t, guide_torque, 1e-9),
            "{name}: {t} against {guide_torque}"
        );
        assert!(
            close(p, guide_loss, 1e-9),
            "{name}: {p} against {guide_loss}"
        );
    }
    assert!(close(losses.thrust[0].2, thrust_loss, 1e-12));
    assert!(
        close(losses.total(), total, 1e-9),
        "{} against {total}",
        losses.total()
    );
    eprintln!(
        "thrust: W {weight:.6e} N, T {thrust_torque:.6e} N·m, P {thrust_loss:.6e} W; guide P {guide_loss:.6e} W each; total {total:.6e} W"
    );

    // The report's tables carry the same numbers.
    let page = report_page(&text, "vertical_unit");
    let rows = table_rows(&page, "thrust-bearings");
    assert_eq!(rows.len(), 1);
    let num = |s: &str| s.split_whitespace().next().unwrap().parse::<f64>().unwrap();
    assert_eq!(rows[0][0], "thrust");
    assert!(close(num(&rows[0][2]), weight, 1e-5), "{:?}", rows[0]);
    assert!(close(num(&rows[0][5]), H * 1e6, 1e-5), "{:?}", rows[0]);
    assert!(
        close(num(&rows[0][8]), thrust_torque, 1e-5),
        "{:?}",
        rows[0]
    );
    assert!(close(num(&rows[0][9]), thrust_loss, 1e-5), "{:?}", rows[0]);
    let rows = table_rows(&page, "power-losses");
    assert_eq!(rows.len(), 4, "{rows:?}");
    assert_eq!(rows[0][0], "guide bearing upper_guide");
    assert!(close(num(&rows[0][2]), guide_loss, 1e-5), "{:?}", rows[0]);
    assert_eq!(rows[2][0], "thrust bearing thrust");
    assert_eq!(rows[3][0], "total (guide and thrust bearings)");
    assert!(close(num(&rows[3][2]), total, 1e-5), "{:?}", rows[3]);
}

/// The horizontal unit: a 2 m × 100 mm shaft, a 100 kg disk at 0.5 m, rigid
/// bearings at the ends on brackets `a` (30 kg, 2e7 N/m) and `b` (50 kg,
/// 5e7 N/m).
const BRACKETS: [(&str, f64, f64); 2] = [("a", 30.0, 2.0e7), ("b", 50.0, 5.0e7)];

fn horizontal_unit() -> String {
    let mut s = format!(
        "name = \"horizontal_unit\"\nmachine = \"hydro_generator\"\nspeed_rpm = {RPM}\nmax_speed_rpm = 600\n\
         gravity = [0.0, -{G}, 0.0]\n\
         [[materials]]\nname = \"steel\"\nyoungs_modulus = 206e9\npoisson_ratio = 0.3\ndensity = {RHO}\n\
         [[shaft]]\nlength = 2.0\nouter_diameter = 0.1\nmaterial = \"steel\"\nelements = 4\n\
         [[disks]]\nname = \"disk\"\nnode = 2\nmass = 100.0\npolar_inertia = 2.0\ndiametral_inertia = 1.0\n\
         [[bearings]]\nname = \"bearing_a\"\ntype = \"linear\"\nnode = 1\nkxx = 1e8\nkyy = 1e8\ncxx = 1e4\ncyy = 1e4\npedestal = \"a\"\n\
         [[bearings]]\nname = \"bearing_b\"\ntype = \"linear\"\nnode = 5\nkxx = 1e8\nkyy = 1e8\ncxx = 1e4\ncyy = 1e4\npedestal = \"b\"\n"
    );
    for (name, mass, k) in BRACKETS {
        s += &format!(
            "[[pedestals]]\nname = \"{name}\"\nmass = {mass}\nkxx = {k}\nkyy = {k}\ncxx = 1e3\ncyy = 1e3\n"
        );
    }
    s
}

#[test]
fn each_bracket_passes_on_its_bearing_reaction_and_weight_and_deflects_f_over_k() {
    let m_s = RHO * PI * 0.1 * 0.1 / 4.0 * 2.0;
    let r_b = G * (m_s * 1.0 + 100.0 * 0.5) / 2.0;
    let r_a = G * (m_s + 100.0) - r_b;
    let text = horizontal_unit();
    let rotor = Rotor::new(RotorModel::from_toml(&text, "horizontal_unit.toml").unwrap()).unwrap();
    let omega = RPM * PI / 30.0;
    let guides = operating_point(&rotor, omega).unwrap();
    let pedestals = pedestal_operating_points(&rotor, omega).unwrap();
    let brackets = bracket_loads(&rotor.model, &guides, &pedestals);
    assert_eq!(brackets.len(), 2);
    let page = report_page(&text, "horizontal_unit");
    let rows = table_rows(&page, "brackets");
    assert_eq!(rows.len(), 2, "{rows:?}");
    for ((b, (name, mass, k)), (r, row)) in brackets
        .iter()
        .zip(BRACKETS)
        .zip([r_a, r_b].into_iter().zip(&rows))
    {
        assert_eq!(b.name, name);
        assert_eq!(b.carries, [format!("bearing_{name}")]);
        // The rotor pushes the bracket down by the bearing's reaction.
        assert!(b.reaction[0].abs() < 1e-9 * r, "{b:?}");
        assert!(
            close(-b.reaction[1], r, 1e-9),
            "{name}: {} against {r}",
            -b.reaction[1]
        );
        let f = r + mass * G;
        assert!(
            close(-b.load[1], f, 1e-9),
            "{name}: load {} against {f}",
            -b.load[1]
        );
        assert!(
            close(-b.deflection[1], f / k, 1e-9),
            "{name}: {} against {}",
            -b.deflection[1],
            f / k
        );
        eprintln!(
            "bracket {name}: reaction {r:.6} N, load {f:.6} N, deflection {:.6} µm",
            f / k * 1e6
        );
        // The report's row: "magnitude (x, y)".
        let first = |s: &str| s.split_whitespace().next().unwrap().parse::<f64>().unwrap();
        assert_eq!(row[0], name);
        assert_eq!(row[1], format!("bearing_{name}"));
        assert!(close(first(&row[2]), r, 1e-5), "{row:?}");
        assert!(close(first(&row[3]), mass * G, 1e-5), "{row:?}");
        assert!(close(first(&row[4]), f, 1e-5), "{row:?}");
        assert!(close(first(&row[6]), f / k * 1e6, 1e-5), "{row:?}");
    }
    assert!(!page.contains("Every bracket load is zero"));
    // Stood upright (gravity along the shaft) nothing loads the brackets
    // statically: every row is zero and the page says why.
    let upright = text.replace(
        &format!("gravity = [0.0, -{G}, 0.0]"),
        &format!("gravity = [0.0, 0.0, {G}]"),
    );
    let page = report_page(&upright, "upright_unit");
    assert!(page.contains("Every bracket load is zero"));
    for row in table_rows(&page, "brackets") {
        for cell in &row[2..5] {
            assert_eq!(cell, "0 (0, 0)", "{row:?}");
        }
        assert_eq!(row[6], "0 (0, 0)", "{row:?}");
    }
}
