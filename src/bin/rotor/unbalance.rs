//! `rotor unbalance`: unbalance response over a speed range (Bode, polar), its
//! peaks, amplification factors and API 684 separation margins.

use std::path::PathBuf;

use rotor_bearing::analysis::unbalance::{
    OperatingRange, peaks, response_points, separation_margin, speed_grid, sweep, with_unbalance_at,
};
use rotor_bearing::plot::{RAD_S_TO_RPM, unbalance_png};
use rotor_bearing::report::{csv as report_csv, text};
use rotor_bearing::rotor::Rotor;

use crate::write_file;

/// What `rotor unbalance` was asked for.
pub struct Request {
    pub min_rpm: f64,
    pub max_rpm: f64,
    pub points: usize,
    /// 1-based node of a single unbalance, instead of the model's planes.
    pub node: Option<usize>,
    pub unbalance: f64,
    pub operating_rpm: Option<String>,
    pub csv: Option<PathBuf>,
    pub png: Option<PathBuf>,
}

/// `--operating-rpm A:B` in rad/s.
pub fn operating_range(text: &str) -> Result<OperatingRange, String> {
    let bad = || format!("--operating-rpm {text:?}: expected MIN:MAX in rpm with 0 < MIN ≤ MAX");
    let (a, b) = text.split_once(':').ok_or_else(bad)?;
    let (a, b): (f64, f64) = (
        a.trim().parse().map_err(|_| bad())?,
        b.trim().parse().map_err(|_| bad())?,
    );
    if !(a.is_finite() && b.is_finite() && a > 0.0 && b >= a) {
        return Err(bad());
    }
    Ok(OperatingRange {
        min: a / RAD_S_TO_RPM,
        max: b / RAD_S_TO_RPM,
    })
}

pub fn unbalance(rotor: &Rotor, req: Request) -> Result<(), String> {
    let range = match &req.operating_rpm {
        Some(t) => Some(operating_range(t)?),
        None => (rotor.model.nominal_speed > 0.0).then_some(OperatingRange {
            min: rotor.model.nominal_speed,
            max: rotor.model.nominal_speed,
        }),
    };
    let excited;
    let rotor = match req.node {
        Some(0) => return Err("--node counts from 1, got 0".into()),
        Some(n) => {
            excited = with_unbalance_at(rotor, n - 1, req.unbalance).map_err(|e| e.to_string())?;
            &excited
        }
        None if rotor.model.unbalances.is_empty() => {
            return Err(format!(
                "model {} has no [[unbalance]] planes: give --node N (and --unbalance kg·m)",
                rotor.model.name
            ));
        }
        None => rotor,
    };
    let mut speeds = speed_grid(
        req.min_rpm / RAD_S_TO_RPM,
        req.max_rpm / RAD_S_TO_RPM,
        req.points,
    )
    .map_err(|e| e.to_string())?;
    // A fluid film at standstill carries no load: start the grid one step up.
    if !rotor.nonlinear_bearings.is_empty() && speeds[0] == 0.0 {
        speeds.remove(0);
    }
    crate::warn_table_speeds(&rotor.model, &speeds);
    let points = response_points(rotor);
    let result = sweep(rotor, &speeds, &points).map_err(|e| e.to_string())?;
    let mut rows = Vec::new();
    for p in 0..points.len() {
        for peak in peaks(rotor, &result, p).map_err(|e| e.to_string())? {
            let margin = match (peak.amplification_factor, &range) {
                (Some(af), Some(r)) => Some(separation_margin(peak.speed, af, r)),
                _ => None,
            };
            rows.push((peak, margin));
        }
    }
    let what = match req.node {
        Some(n) => format!("{} kg·m at node {n}", req.unbalance),
        None => "the model's unbalance planes".to_string(),
    };
    println!(
        "unbalance response of {} to {what}, {} … {} rpm:",
        rotor.model.name, req.min_rpm, req.max_rpm
    );
    match &range {
        Some(r) => println!(
            "operating range {:.1} … {:.1} rpm (API 684 separation margins)",
            r.min * RAD_S_TO_RPM,
            r.max * RAD_S_TO_RPM
        ),
        None => println!("no operating range (speed_rpm or --operating-rpm): margins not judged"),
    }
    print!("{}", text::peak_table(&result, &rows));
    if let Some(path) = req.csv {
        write_file(&path, &report_csv::unbalance(&result))?;
    }
    if let Some(path) = req.png {
        let title = format!("Unbalance response: {} ({what})", rotor.model.name);
        let found: Vec<_> = rows.iter().map(|(p, _)| *p).collect();
        unbalance_png(
            &path,
            &title,
            &result,
            &found,
            range.map(|r| (r.min, r.max)),
        )
        .map_err(|e| e.to_string())?;
        eprintln!("wrote {}", path.display());
    }
    Ok(())
}
