//! `rotor modes` and `rotor campbell`: complex modes at one speed and over a range.

use rotor_bearing::analysis::torsion::torsional_modes;
use std::path::PathBuf;

use rotor_bearing::analysis::campbell::{self, campbell_study};
use rotor_bearing::analysis::modal::ModalOptions;
use rotor_bearing::analysis::unbalance::{OperatingRange, model_operating_range};
use rotor_bearing::analysis::whirl_modes::modal_analysis_own;
use rotor_bearing::plot::{RAD_S_TO_RPM, campbell_png, mode_shapes_png};
use rotor_bearing::report::{csv as report_csv, text};
use rotor_bearing::rotor::Rotor;

use crate::write_file;

/// Where `rotor modes` writes its files.
pub struct ModeFiles {
    pub csv: Option<PathBuf>,
    pub shapes_csv: Option<PathBuf>,
    pub shapes_png: Option<PathBuf>,
    pub torsional_shapes_csv: Option<PathBuf>,
}

/// `rotor modes`: damped frequencies, damping, log dec and whirl at `rpm`, and
/// the mode shapes; then the lowest `torsional` torsional modes.
pub fn modes(
    rotor: &Rotor,
    rpm: f64,
    (count, torsional): (usize, Option<usize>),
    files: ModeFiles,
) -> Result<(), String> {
    let speed = rpm / RAD_S_TO_RPM;
    crate::warn_table_speeds(&rotor.model, &[speed]);
    crate::warn_short_films(rotor, &[speed]);
    crate::held::note_off_centre(rotor, &[speed]);
    let options = ModalOptions {
        modes: count,
        ..ModalOptions::default()
    };
    let result = modal_analysis_own(rotor, speed, &options).map_err(|e| e.to_string())?;
    let ms = &result.modes;
    let mut out = text::modes(&rotor.model.name, rpm, ms);
    out.push_str(&text::overdamped_roots(&result.overdamped));
    let torsional = torsional.unwrap_or(if rotor.model.models_torsion() { 3 } else { 0 });
    let twist = torsional_modes(&rotor.model, torsional).map_err(|e| e.to_string())?;
    out.push_str(&text::torsional_modes(&twist));
    if let Some(path) = files.torsional_shapes_csv {
        write_file(
            &path,
            &report_csv::torsional_mode_shapes(&rotor.model, &twist),
        )?;
    }
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

/// What `rotor campbell` was asked for.
pub struct CampbellRequest {
    pub max_rpm: Option<f64>,
    pub steps: usize,
    pub modes: usize,
    pub operating_rpm: Option<String>,
    pub csv: Option<PathBuf>,
    pub png: Option<PathBuf>,
    pub threads: usize,
}

/// The operating range of `--operating-rpm`, else the model's `speed_rpm`.
pub fn operating_range(
    rotor: &Rotor,
    operating_rpm: Option<&str>,
) -> Result<Option<OperatingRange>, String> {
    match operating_rpm {
        Some(t) => Ok(Some(crate::unbalance::operating_range(t)?)),
        None => Ok(model_operating_range(rotor)),
    }
}

/// `rotor campbell`: the diagram up to `max_rpm` (default from the model, see
/// [`default_top_speed`](rotor_bearing::analysis::speed_range::default_top_speed)),
/// the 1× critical speeds with their API 684 separation margins, overdamped
/// crossings apart.
pub fn campbell_diagram(rotor: &Rotor, req: CampbellRequest) -> Result<(), String> {
    let model = &rotor.model;
    let request = campbell::CampbellRequest {
        max: req.max_rpm.map(|r| r / RAD_S_TO_RPM),
        steps: req.steps,
        modes: req.modes,
        operating: operating_range(rotor, req.operating_rpm.as_deref())?,
        threads: req.threads,
    };
    let study = campbell_study(rotor, &request).map_err(|e| e.to_string())?;
    let seconds = study.diagram_seconds;
    let speeds: Vec<f64> = study.diagram.iter().map(|p| p.speed).collect();
    crate::warn_table_speeds(model, &speeds);
    crate::warn_short_films(rotor, &speeds);
    crate::held::note_off_centre(rotor, &speeds);
    eprintln!(
        "campbell diagram: {} speeds in {seconds:.4} s wall-clock ({:.3} ms per speed)",
        study.diagram.len(),
        1e3 * seconds / study.diagram.len() as f64
    );
    let out = text::campbell_study(rotor, &study);
    if let Some(path) = req.csv {
        write_file(&path, &report_csv::campbell(&study.diagram))?;
    }
    if let Some(path) = req.png {
        let title = format!("Campbell diagram: {}", model.name);
        campbell_png(&path, &title, &study).map_err(|e| e.to_string())?;
        eprintln!("wrote {}", path.display());
    }
    print!("{out}");
    Ok(())
}
