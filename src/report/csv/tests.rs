//! Unit tests of `report::csv` (the parent module's `mod tests`).

use super::*;
use crate::analysis::campbell::ModeSummary;
use crate::analysis::modal::Whirl;
use crate::bearing::BearingReport;
use crate::solver::{BearingOutput, ProbeOutput};

/// Rows of a CSV text as numbers (text cells as NaN), header checked.
fn parse(text: &str, header: &str) -> Vec<Vec<f64>> {
    let mut lines = text.lines();
    assert_eq!(lines.next(), Some(header));
    lines
        .map(|l| {
            l.split(',')
                .map(|c| c.parse().unwrap_or(f64::NAN))
                .collect()
        })
        .collect()
}

#[test]
fn static_table_round_trips() {
    let z = [0.0, 0.25, 0.5];
    let q: Vec<f64> = (0..12)
        .map(|k| (k as f64 - 5.5) * 1.234_567_890_123e-5)
        .collect();
    let rows = parse(&static_deflection(&z, &q), "node,z_m,x_m,y_m,rx_rad,ry_rad");
    assert_eq!(rows.len(), 3);
    for (i, r) in rows.iter().enumerate() {
        assert_eq!(r[0], (i + 1) as f64);
        assert_eq!(r[1], z[i]);
        assert_eq!(&r[2..], &q[4 * i..4 * i + 4]);
    }
}

#[test]
fn modes_table_round_trips() {
    let m = Mode {
        eigenvalue: nalgebra::Complex::new(-1.0, 100.0),
        natural_frequency: 100.005,
        damped_frequency: 100.0,
        damping_ratio: 0.01,
        log_decrement: 0.0628,
        whirl: Whirl::Forward,
        shape: Vec::new(),
        residual: 0.0,
    };
    let text = modes(1500.0, &[m.clone(), m]);
    let rows = parse(
        &text,
        "mode,speed_rpm,damped_frequency_rad_s,damped_frequency_hz,natural_frequency_rad_s,damping_ratio,log_decrement,whirl",
    );
    assert_eq!(rows.len(), 2);
    assert_eq!(
        rows[1][..7],
        [
            2.0,
            1500.0,
            100.0,
            100.0 / (2.0 * PI),
            100.005,
            0.01,
            0.0628
        ]
    );
    assert!(text.ends_with(",forward\n"));
}

#[test]
fn campbell_table_round_trips() {
    let mode = |f: f64, whirl, branch| ModeSummary {
        damped_frequency: f,
        damping_ratio: 0.01,
        log_decrement: 0.0628,
        whirl,
        branch,
    };
    let diagram = [
        CampbellPoint {
            speed: 0.0,
            modes: vec![
                mode(100.0, Whirl::Backward, 0),
                mode(101.0, Whirl::Forward, 1),
            ],
            overdamped: vec![],
        },
        CampbellPoint {
            speed: 50.0,
            modes: vec![mode(98.0, Whirl::Backward, 0)],
            overdamped: vec![],
        },
    ];
    let text = campbell(&diagram);
    let rows = parse(
        &text,
        "speed_rpm,speed_rad_s,mode,damped_frequency_rad_s,damped_frequency_hz,damping_ratio,log_decrement,whirl,branch",
    );
    assert_eq!(rows.len(), 3);
    assert_eq!(rows[2][0], 50.0 * RAD_S_TO_RPM);
    assert_eq!(rows[2][1], 50.0);
    assert_eq!((rows[1][2], rows[1][3]), (2.0, 101.0));
    assert_eq!(rows[0][4], 100.0 / (2.0 * PI));
    assert!(text.lines().nth(1).unwrap().ends_with(",backward,1"));
    assert!(text.lines().nth(2).unwrap().ends_with(",forward,2"));
}

#[test]
fn coefficient_table_round_trips() {
    let p = DimensionlessPoint {
        load: 1234.5,
        eccentricity: 0.42,
        attitude_angle: 1.0,
        stiffness: [1.5, 2.5, -3.5, 4.5],
        damping: [5.5, 6.5, 7.5, 8.5e-3],
    };
    let rows = parse(
        &coefficients(&[p, p]),
        "load_N,eccentricity,attitude_deg,Kxx_bar,Kxy_bar,Kyx_bar,Kyy_bar,Cxx_bar,Cxy_bar,Cyx_bar,Cyy_bar",
    );
    assert_eq!(rows.len(), 2);
    assert_eq!(rows[1][..3], [1234.5, 0.42, 1f64.to_degrees()]);
    assert_eq!(rows[1][3..7], p.stiffness);
    assert_eq!(rows[1][7..], p.damping);
}

#[test]
fn simulation_table_has_a_column_per_bearing_and_probe_output() {
    let model = RotorModel::default_model();
    let bearing = BearingOutput {
        x: 1e-6,
        y: -2e-6,
        fx: 3.0,
        fy: -4.0,
        report: BearingReport {
            eccentricity: 0.25,
            friction_torque: 0.5,
            contact_force: 9.5,
            min_film_thickness: 2.5e-5,
            power_loss: 0.75,
            ..BearingReport::default()
        },
        ..Default::default()
    };
    let record = Outputs {
        time: 0.125,
        speed: 100.0,
        spin_angle: 12.5,
        bearings: vec![bearing; model.bearings.len()],
        probes: vec![ProbeOutput { x: 7e-6, y: 8e-6 }; model.probes.len()],
        ports: Vec::new(),
        thrust_bearings: Vec::new(),
        torques: Vec::new(),
        shaft_torques: Vec::new(),
        friction_torque: 1.0,
        power_loss: 1.5,
    };
    let text = simulation(&model, &[record.clone(), record]);
    let header = text.lines().next().unwrap();
    // Each bearing's power loss and the total close the row.
    let columns = 3 + 9 * model.bearings.len() + 2 * model.probes.len() + 2;
    assert_eq!(header.split(',').count(), columns);
    let b = &model.bearings[1].name;
    assert!(header.contains(&format!(",{b}_fx_N,")));
    let rows = parse(&text, header);
    assert_eq!(rows.len(), 2);
    assert_eq!(rows[0][..3], [0.125, 100.0 * RAD_S_TO_RPM, 12.5]);
    assert_eq!(
        rows[0][3..11],
        [1e-6, -2e-6, 3.0, -4.0, 0.25, 0.5, 9.5, 2.5e-5]
    );
    assert!(header.contains(&format!(",{b}_contact_force_N,{b}_min_film_thickness_m")));
    let losses = columns - model.bearings.len() - 1;
    assert_eq!(rows[0][losses - 3..losses], [7e-6, 8e-6, 1.0]);
    assert_eq!(rows[0][losses..], [0.75, 0.75, 1.5]);
    assert!(header.ends_with(&format!(",{b}_power_loss_W,power_loss_W")));
}
