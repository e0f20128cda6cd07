//! `rotor modes` and `rotor campbell`: complex modes at one speed and over a range.

use std::path::PathBuf;

use rotor_bearing::analysis::campbell::{
    CriticalSpeed, OVERDAMPED_DAMPING_RATIO, campbell, critical_margins, critical_speeds,
    default_top_speed, speed_grid,
};
use rotor_bearing::analysis::modal::{ModalOptions, modal_analysis_at};
use rotor_bearing::analysis::unbalance::OperatingRange;
use rotor_bearing::plot::{CampbellMarks, RAD_S_TO_RPM, campbell_png, mode_shapes_png};
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
    let result = modal_analysis_at(rotor, speed, &options).map_err(|e| e.to_string())?;
    let ms = &result.modes;
    let mut out = text::modes(&rotor.model.name, rpm, ms);
    out.push_str(&text::overdamped_roots(&result.overdamped));
    if let Some(path) = files.csv {
        write_file(&path, &report_csv::modes(rpm, ms))?;
    }
    if let Some(path) = files.shapes_csv {
        write_file(&path, &report_csv::mode_shapes(&rotor.model, ms))?;
    }
    if let Some(path) = files.shapes_png {
        let title = format!(
            "Mode shapes of {} at {rpm} rpm (red forward, blue backward whirl)",
            rotor.model.name
        );
        mode_shapes_png(&path, &title, &rotor.model, ms).map_err(|e| e.to_string())?;
        eprintln!("wrote {}", path.display());
    }
    // Printed last: files are written even when stdout is a closed pipe.
    print!("{out}");
    Ok(())
}

/// `rpm` rounded to 1e-6 rpm: the value a model file gave, without the
/// round-off of its conversion to rad/s and back.
fn rounded(rpm: f64) -> f64 {
    (rpm * 1e6).round() / 1e6
}

/// What `rotor campbell` was asked for.
pub struct CampbellRequest {
    pub max_rpm: Option<f64>,
    pub steps: usize,
    pub modes: usize,
    pub operating_rpm: Option<String>,
    pub csv: Option<PathBuf>,
    pub png: Option<PathBuf>,
}

/// The operating range of `--operating-rpm`, else the model's `speed_rpm`.
pub fn operating_range(
    rotor: &Rotor,
    operating_rpm: Option<&str>,
) -> Result<Option<OperatingRange>, String> {
    match operating_rpm {
        Some(t) => Ok(Some(crate::unbalance::operating_range(t)?)),
        None => Ok((rotor.model.nominal_speed != 0.0).then(|| OperatingRange {
            min: rotor.model.nominal_speed.abs(),
            max: rotor.model.nominal_speed.abs(),
        })),
    }
}

/// `rotor campbell`: the diagram up to `max_rpm` (default from the model, see
/// [`default_top_speed`]), the 1× critical speeds with their API 684
/// separation margins, overdamped crossings apart.
pub fn campbell_diagram(rotor: &Rotor, req: CampbellRequest) -> Result<(), String> {
    let model = &rotor.model;
    let steps = req.steps;
    let (max_rpm, origin) = match req.max_rpm {
        Some(rpm) => (rpm, "--max-rpm".to_string()),
        None => {
            let origin = if model.max_speed_stated {
                format!(
                    "1.25 × the model's max_speed_rpm {}",
                    rounded(model.max_speed * RAD_S_TO_RPM)
                )
            } else if model.nominal_speed != 0.0 {
                format!(
                    "1.25 × the model's speed_rpm {}",
                    rounded(model.nominal_speed.abs() * RAD_S_TO_RPM)
                )
            } else {
                "the model states neither max_speed_rpm nor speed_rpm".to_string()
            };
            (default_top_speed(model) * RAD_S_TO_RPM, origin)
        }
    };
    if !(max_rpm.is_finite() && max_rpm > 0.0) || steps == 0 {
        return Err(format!(
            "--max-rpm must be positive (got {max_rpm}) and --steps at least 1 (got {steps})"
        ));
    }
    let range = operating_range(rotor, req.operating_rpm.as_deref())?;
    let options = ModalOptions {
        modes: req.modes,
        ..ModalOptions::default()
    };
    let speeds = speed_grid(rotor, max_rpm / RAD_S_TO_RPM, steps);
    let mut out = format!(
        "speed grid of {}: {:.2} to {:.2} rpm in {steps} steps (top speed: {origin}{})\n",
        model.name,
        speeds[0] * RAD_S_TO_RPM,
        max_rpm,
        if rotor.nonlinear_bearings.is_empty() {
            ""
        } else {
            "; fluid-film bearings: from 1 % of the top speed"
        }
    );
    let clock = std::time::Instant::now();
    let diagram = campbell(rotor, &speeds, &options).map_err(|e| e.to_string())?;
    let seconds = clock.elapsed().as_secs_f64();
    eprintln!(
        "campbell diagram: {} speeds in {seconds:.4} s wall-clock ({:.3} ms per speed)",
        speeds.len(),
        1e3 * seconds / speeds.len() as f64
    );
    let criticals = critical_speeds(rotor, &diagram, 1.0, &options).map_err(|e| e.to_string())?;
    let line = |c: &CriticalSpeed| {
        format!(
            "  {:10.2} rpm ({:9.3} rad/s)  branch {}  {} whirl  ζ = {}\n",
            c.speed * RAD_S_TO_RPM,
            c.speed,
            c.branch + 1,
            c.whirl.label(),
            text::damping_ratio(c.damping_ratio)
        )
    };
    out.push_str(&format!(
        "critical speeds of {} (1× unbalance excitation, ζ < {OVERDAMPED_DAMPING_RATIO}):\n",
        model.name
    ));
    let (overdamped, critical): (Vec<_>, Vec<_>) =
        criticals.iter().partition(|c| c.is_overdamped());
    if critical.is_empty() {
        out.push_str(&format!("  none up to {max_rpm:.2} rpm\n"));
    }
    critical.into_iter().for_each(|c| out.push_str(&line(c)));
    if !overdamped.is_empty() {
        out.push_str(&format!(
            "overdamped crossings of the 1× line (ζ ≥ {OVERDAMPED_DAMPING_RATIO}: no resonance peak, not critical speeds):\n"
        ));
        overdamped.into_iter().for_each(|c| out.push_str(&line(c)));
    }
    let max_speed = model.max_speed_stated.then_some(model.max_speed);
    let margins = critical_margins(&criticals, range.as_ref(), max_speed);
    out.push_str(&text::critical_margins(&margins, range.as_ref(), max_speed));
    out.push_str(&text::overdamped_summary(&diagram));
    if let Some(path) = req.csv {
        write_file(&path, &report_csv::campbell(&diagram))?;
    }
    if let Some(path) = req.png {
        let title = format!("Campbell diagram: {}", model.name);
        let marks = CampbellMarks {
            operating: range.map(|r| (r.min, r.max)),
            max_speed,
            margins,
        };
        campbell_png(&path, &title, &diagram, &[1.0], &criticals, &marks)
            .map_err(|e| e.to_string())?;
        eprintln!("wrote {}", path.display());
    }
    print!("{out}");
    Ok(())
}
