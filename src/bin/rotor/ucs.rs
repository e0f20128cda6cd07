//! `rotor ucs`: undamped critical speed map against support stiffness, with
//! the bearings' stiffness over a speed range.

use std::path::PathBuf;

use rotor_bearing::analysis::speed_range::default_top_speed;
use rotor_bearing::analysis::ucs::{bearing_speeds, critical_speed_map, stiffness_grid};
use rotor_bearing::analysis::unbalance::model_operating_range;
use rotor_bearing::plot::{RAD_S_TO_RPM, ucs_png};
use rotor_bearing::report::text::short;
use rotor_bearing::report::{csv as report_csv, text};
use rotor_bearing::rotor::Rotor;

use crate::write_file;

/// What `rotor ucs` was asked for.
pub struct Request {
    pub min_stiffness: f64,
    pub max_stiffness: f64,
    pub points: usize,
    pub criticals: usize,
    /// `None` for the model's default top speed.
    pub max_rpm: Option<f64>,
    pub speeds: usize,
    pub csv: Option<PathBuf>,
    pub bearings_csv: Option<PathBuf>,
    pub png: Option<PathBuf>,
}

pub fn run(rotor: &Rotor, req: Request) -> Result<(), String> {
    if req.criticals == 0 {
        return Err("--modes must be at least 1".into());
    }
    let (top, origin) = match req.max_rpm {
        Some(rpm) => (rpm / RAD_S_TO_RPM, "--max-rpm".to_string()),
        None => {
            let (t, o) = default_top_speed(&rotor.model, model_operating_range(rotor).as_ref());
            (t, o.to_string())
        }
    };
    if !(top.is_finite() && top > 0.0) || req.speeds == 0 {
        return Err(format!(
            "--max-rpm must be positive (got {}) and --speeds at least 1 (got {})",
            top * RAD_S_TO_RPM,
            req.speeds
        ));
    }
    let stiffness = stiffness_grid(req.min_stiffness, req.max_stiffness, req.points)
        .map_err(|e| e.to_string())?;
    let speeds = bearing_speeds(top, req.speeds);
    crate::warn_table_speeds(&rotor.model, &speeds);
    crate::warn_short_films(rotor, &speeds);
    let map = critical_speed_map(rotor, &stiffness, req.criticals, &speeds)
        .map_err(|e| format!("{}: {e}", rotor.model.name))?;
    let mut out = text::critical_speed_map(&rotor.model.name, &map, req.points / 10);
    out.push_str(&format!(
        "bearings' kxx, kyy at {} speeds up to {} rpm (top speed: {origin})\n",
        req.speeds,
        short(top * RAD_S_TO_RPM)
    ));
    if let Some(path) = req.csv {
        write_file(&path, &report_csv::critical_speed_map(&map))?;
    }
    if let Some(path) = req.bearings_csv {
        write_file(&path, &report_csv::bearing_stiffness(&map))?;
    }
    if let Some(path) = req.png {
        let title = format!("Undamped critical speed map: {}", rotor.model.name);
        ucs_png(&path, &title, &map).map_err(|e| e.to_string())?;
        eprintln!("wrote {}", path.display());
    }
    print!("{out}");
    Ok(())
}
