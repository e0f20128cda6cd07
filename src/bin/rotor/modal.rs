//! `rotor modes` and `rotor campbell`: complex modes at one speed and over a range.

use std::path::PathBuf;

use rotor_bearing::analysis::campbell::{campbell, critical_speeds};
use rotor_bearing::analysis::modal::{ModalOptions, modes_at};
use rotor_bearing::plot::{RAD_S_TO_RPM, campbell_png, mode_shapes_png};
use rotor_bearing::report::{csv as report_csv, text};
use rotor_bearing::rotor::Rotor;

use crate::write_file;

/// Where `rotor modes` writes its files.
pub struct ModeFiles {
    pub csv: Option<PathBuf>,
    pub shapes_csv: Option<PathBuf>,
    pub shapes_png: Option<PathBuf>,
}

/// `rotor modes`: damped frequencies, damping, log dec and whirl at `rpm`, and
/// the mode shapes.
pub fn modes(rotor: &Rotor, rpm: f64, count: usize, files: ModeFiles) -> Result<(), String> {
    let speed = rpm / RAD_S_TO_RPM;
    let options = ModalOptions {
        modes: count,
        ..ModalOptions::default()
    };
    let ms = modes_at(rotor, speed, &options).map_err(|e| e.to_string())?;
    print!("{}", text::modes(&rotor.model.name, rpm, &ms));
    if let Some(path) = files.csv {
        write_file(&path, &report_csv::modes(rpm, &ms))?;
    }
    if let Some(path) = files.shapes_csv {
        write_file(&path, &report_csv::mode_shapes(&rotor.model, &ms))?;
    }
    if let Some(path) = files.shapes_png {
        let title = format!(
            "Mode shapes of {} at {rpm} rpm (red forward, blue backward whirl)",
            rotor.model.name
        );
        mode_shapes_png(&path, &title, &rotor.model, &ms).map_err(|e| e.to_string())?;
        eprintln!("wrote {}", path.display());
    }
    Ok(())
}

/// `rotor campbell`: the diagram over `0..max_rpm` and the 1× critical speeds.
pub fn campbell_diagram(
    rotor: &Rotor,
    max_rpm: f64,
    steps: usize,
    count: usize,
    csv: Option<PathBuf>,
    png: Option<PathBuf>,
) -> Result<(), String> {
    if !(max_rpm.is_finite() && max_rpm > 0.0) || steps == 0 {
        return Err(format!(
            "--max-rpm must be positive (got {max_rpm}) and --steps at least 1 (got {steps})"
        ));
    }
    let options = ModalOptions {
        modes: count,
        ..ModalOptions::default()
    };
    // Fluid-film bearings have no coefficients at standstill: start one step up.
    let first = usize::from(!rotor.nonlinear_bearings.is_empty());
    let speeds: Vec<f64> = (first..=steps)
        .map(|k| max_rpm / RAD_S_TO_RPM * k as f64 / steps as f64)
        .collect();
    let diagram = campbell(rotor, &speeds, &options).map_err(|e| e.to_string())?;
    let criticals = critical_speeds(rotor, &diagram, 1.0, &options).map_err(|e| e.to_string())?;
    println!(
        "critical speeds of {} (1× unbalance excitation):",
        rotor.model.name
    );
    for c in &criticals {
        println!(
            "  {:10.2} rpm ({:9.3} rad/s)  branch {}  {} whirl  ζ = {:.3e}",
            c.speed * RAD_S_TO_RPM,
            c.speed,
            c.rank + 1,
            c.whirl.label(),
            c.damping_ratio
        );
    }
    let out = report_csv::campbell(&diagram);
    match csv {
        Some(path) => write_file(&path, &out)?,
        None => print!("{out}"),
    }
    if let Some(path) = png {
        let title = format!("Campbell diagram: {}", rotor.model.name);
        campbell_png(&path, &title, &diagram, &[1.0], &criticals).map_err(|e| e.to_string())?;
        eprintln!("wrote {}", path.display());
    }
    Ok(())
}
