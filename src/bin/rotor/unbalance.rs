//! `rotor unbalance`: unbalance response over a speed range (Bode, polar), its
//! peaks, amplification factors and API 684 separation margins.

use std::path::PathBuf;

use rotor_bearing::analysis::api_unbalance::{ApiRequest, api_unbalance};
use rotor_bearing::analysis::unbalance::{
    OperatingRange, UnbalanceRequest, model_operating_range, unbalance_study, with_unbalance_at,
};
use rotor_bearing::plot::{RAD_S_TO_RPM, unbalance_png};
use rotor_bearing::report::{csv as report_csv, text};
use rotor_bearing::rotor::Rotor;
use rotor_bearing::units::Amplitude;

use crate::write_file;

/// What `rotor unbalance` was asked for.
pub struct Request {
    pub min_rpm: f64,
    /// `None` for the model's default top speed.
    pub max_rpm: Option<f64>,
    pub points: usize,
    /// 1-based node of a single unbalance, instead of the model's planes.
    pub node: Option<usize>,
    pub unbalance: f64,
    pub operating_rpm: Option<String>,
    pub amplitude: Amplitude,
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
    let operating = match &req.operating_rpm {
        Some(t) => Some(operating_range(t)?),
        None => model_operating_range(rotor),
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
    let request = UnbalanceRequest {
        min: req.min_rpm / RAD_S_TO_RPM,
        max: req.max_rpm.map(|r| r / RAD_S_TO_RPM),
        points: req.points,
        operating,
    };
    let study = unbalance_study(rotor, &request).map_err(|e| e.to_string())?;
    crate::warn_table_speeds(&rotor.model, &study.sweep.speeds);
    crate::warn_short_films(rotor, &study.sweep.speeds);
    crate::held::note_off_centre(rotor, &study.sweep.speeds);
    let what = match req.node {
        Some(n) => format!("{} kg·m at node {n}", req.unbalance),
        None => "the model's unbalance planes".to_string(),
    };
    let model = &rotor.model;
    let mut out = if model.machine.is_hydro() {
        // A hydro unit is judged by its runaway speed, not API 684's margins.
        text::unbalance_heading(&model.name, &what, &study)
            + &text::unbalance_runaway(
                &study.sweep,
                &study.rows,
                req.amplitude,
                model.max_speed,
                model.machine.name(),
            )
    } else {
        text::unbalance_study(&model.name, &what, &study, req.amplitude)
    };
    if model.machine.is_api() {
        out.push('\n');
        out.push_str(&api_cases(rotor, &study, operating, req.points));
    }
    if let Some(path) = req.csv {
        write_file(&path, &report_csv::unbalance(&study.sweep, req.amplitude))?;
    }
    if let Some(path) = req.png {
        let title = format!("Unbalance response: {} ({what})", rotor.model.name);
        unbalance_png(&path, &title, &study, req.amplitude).map_err(|e| e.to_string())?;
        eprintln!("wrote {}", path.display());
    }
    // Printed last: files are written even when stdout is a closed pipe.
    print!("{out}");
    Ok(())
}

/// The API 684/617 unbalance cases of an API machine, on the study's speed
/// range, as text (or why they could not be run).
pub fn api_cases(
    rotor: &Rotor,
    study: &rotor_bearing::analysis::unbalance::UnbalanceStudy,
    operating: Option<OperatingRange>,
    points: usize,
) -> String {
    let machine = rotor.model.machine.name();
    let Some(operating) = operating else {
        return format!(
            "API unbalance cases (machine = {machine}): not run: no operating range (operating_rpm, speed_rpm or --operating-rpm) gives the maximum continuous speed\n"
        );
    };
    let request = ApiRequest {
        operating,
        max: study.sweep.speeds.last().copied().unwrap_or(operating.max),
        points,
    };
    match api_unbalance(rotor, &request) {
        Ok(api) => text::api_unbalance(&api),
        Err(e) => format!("API unbalance cases (machine = {machine}): not run: {e}\n"),
    }
}
