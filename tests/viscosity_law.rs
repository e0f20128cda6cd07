//! The oil's viscosity–temperature law (ASTM D341, Walther) against
//! independent numbers: its own anchor points to round-off, and the 0 °C
//! viscosities the oils' data sheet publishes (`tests/data/iso_vg_oils.csv`).

use rotor_bearing::bearing::oil::{ANCHORS, CELSIUS_ZERO, ISO_VG, Oil, WaltherLaw};

/// The data sheet's rows: grade, ν(0 °C), ν(40 °C), ν(100 °C) (mm²/s).
fn sheet() -> Vec<[f64; 4]> {
    let text = std::fs::read_to_string(
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/iso_vg_oils.csv"),
    )
    .unwrap();
    text.lines()
        .filter(|l| !l.starts_with('#') && !l.starts_with("grade"))
        .map(|l| {
            let v: Vec<f64> = l.split(',').map(|s| s.trim().parse().unwrap()).collect();
            [v[0], v[1], v[2], v[3]]
        })
        .collect()
}

#[test]
fn the_fit_reproduces_its_anchor_points_to_round_off() {
    for &(grade, nu_40, nu_100) in &ISO_VG {
        let oil = Oil::iso_vg(grade).unwrap();
        let at_40 = oil.kinematic_viscosity(ANCHORS[0]).unwrap();
        let at_100 = oil.kinematic_viscosity(ANCHORS[1]).unwrap();
        assert!((at_40 / nu_40 - 1.0).abs() < 1e-12, "VG {grade}: {at_40}");
        assert!(
            (at_100 / nu_100 - 1.0).abs() < 1e-12,
            "VG {grade}: {at_100}"
        );
    }
    // Any two points, not only 40/100 °C: through (20 °C, 150) and (80 °C, 12).
    let law = WaltherLaw::through([293.15, 150.0], [353.15, 12.0]).unwrap();
    assert!((law.kinematic_viscosity(293.15) / 150.0 - 1.0).abs() < 1e-12);
    assert!((law.kinematic_viscosity(353.15) / 12.0 - 1.0).abs() < 1e-12);
}

#[test]
fn the_shipped_grades_are_the_data_sheets_and_iso_3448_midpoints() {
    let rows = sheet();
    assert_eq!(rows.len(), ISO_VG.len());
    for (row, &(grade, nu_40, nu_100)) in rows.iter().zip(&ISO_VG) {
        assert_eq!(row[0], grade as f64);
        // ISO 3448: the grade is the midpoint viscosity at 40 °C.
        assert_eq!(nu_40, grade as f64);
        assert_eq!(row[2], nu_40);
        assert_eq!(row[3], nu_100);
    }
}

/// The fit through 40 and 100 °C, extrapolated to 0 °C, against the data
/// sheet's measured 0 °C value within 5 %: the sheet's typical values carry
/// two or three digits (the 100 °C one to ±0.05 mm²/s, which alone moves the
/// 0 °C extrapolation of VG 22 by 1.6 %), and the Walther law is a straight
/// line on the D341 chart that a real mineral oil follows to a few per cent
/// over 0–100 °C. (The law's deviations measured here: VG 22 +3.8 %, VG 32
/// −0.6 %, VG 46 −0.5 %, VG 68 +2.0 %.)
#[test]
fn the_fit_extrapolates_to_the_data_sheets_zero_celsius_viscosity() {
    for row in sheet() {
        let oil = Oil::new(row[2], row[3], 870.0).unwrap();
        let nu_0 = oil.kinematic_viscosity(CELSIUS_ZERO).unwrap();
        let error = nu_0 / row[1] - 1.0;
        assert!(
            error.abs() < 0.05,
            "VG {}: {nu_0} mm²/s at 0 °C against {} ({:+.2} %)",
            row[0],
            row[1],
            100.0 * error
        );
    }
}

/// Between the anchors the law is monotone and the dynamic viscosity is ρ ν
/// with ρ = ρ15 (1 − 6.4e-4 (T − 288.15)): VG 32 at 50 °C, written out.
#[test]
fn dynamic_viscosity_is_density_times_kinematic() {
    let oil = Oil::iso_vg(32).unwrap();
    let t = CELSIUS_ZERO + 50.0;
    let nu = oil.kinematic_viscosity(t).unwrap();
    assert!(nu < 32.0 && nu > 5.4);
    let rho = 870.0 * (1.0 - 6.4e-4 * 35.0);
    let mu = oil.dynamic_viscosity(t).unwrap();
    assert!((mu - rho * nu * 1e-6).abs() < 1e-15);
    // Colder is thicker.
    let mut last = f64::INFINITY;
    for c in [0.0, 20.0, 40.0, 60.0, 80.0, 100.0, 120.0] {
        let mu = oil.dynamic_viscosity(CELSIUS_ZERO + c).unwrap();
        assert!(mu < last);
        last = mu;
    }
}
