//! `rotor stability`: log decrements at a speed and the threshold of added
//! cross-coupled stiffness at mid-span (API 684 Level I style).

use std::path::PathBuf;

use rotor_bearing::analysis::stability::{default_cross_coupling_max, stability};
use rotor_bearing::plot::{RAD_S_TO_RPM, stability_png};
use rotor_bearing::report::{csv as report_csv, text};
use rotor_bearing::rotor::Rotor;

use crate::write_file;

/// What `rotor stability` was asked for.
pub struct Request {
    pub rpm: f64,
    pub q_max: Option<f64>,
    pub points: usize,
    pub modes: usize,
    pub csv: Option<PathBuf>,
    pub png: Option<PathBuf>,
}

pub fn run(rotor: &Rotor, req: Request) -> Result<(), String> {
    if !(req.rpm.is_finite() && req.rpm != 0.0) {
        return Err(format!(
            "--rpm must be a nonzero speed (forward whirl is relative to the spin), got {}",
            req.rpm
        ));
    }
    let speed = req.rpm / RAD_S_TO_RPM;
    crate::warn_table_speeds(&rotor.model, &[speed]);
    let q_max = match req.q_max {
        Some(q) => q,
        None => default_cross_coupling_max(rotor, speed).map_err(|e| e.to_string())?,
    };
    let result = stability(rotor, speed, q_max, req.points, req.modes)
        .map_err(|e| format!("{} at {} rpm: {e}", rotor.model.name, req.rpm))?;
    print!("{}", text::stability(&result, q_max));
    if let Some(path) = req.csv {
        write_file(&path, &report_csv::stability(&result))?;
    }
    if let Some(path) = req.png {
        let title = format!(
            "Stability of {} at {} rpm: cross-coupling at node {}",
            rotor.model.name,
            req.rpm,
            result.node + 1
        );
        stability_png(&path, &title, &result).map_err(|e| e.to_string())?;
        eprintln!("wrote {}", path.display());
    }
    Ok(())
}
