//! `rotor coefficients`: dimensionless stiffness and damping of a hydrodynamic
//! bearing against eccentricity ratio (paper Fig. 3).

use std::path::PathBuf;

use rotor_bearing::bearing::coefficients::dimensionless_curve_of;
use rotor_bearing::bearing::finite_bearing::FiniteFilmBearing;
use rotor_bearing::bearing::reynolds::Cavitation;
use rotor_bearing::bearing::{Bearing, BearingKind, PlainBearing};
use rotor_bearing::plot::{RAD_S_TO_RPM, coefficients_png};
use rotor_bearing::report::csv as report_csv;

use crate::write_file;

/// The plain short bearing of the project's reference data: R = 50 mm, L = 30 mm,
/// C = 0.1 mm, μ = 0.02 Pa·s.
const REFERENCE_BEARING: PlainBearing = PlainBearing {
    radius: 0.05,
    length: 0.03,
    clearance: 1e-4,
    viscosity: 0.02,
    contact: None,
};

pub fn coefficients(
    model: Option<PathBuf>,
    bearing: Option<String>,
    (rpm, whirl_hz): (f64, Option<f64>),
    (points, film): (usize, &str),
    csv: Option<PathBuf>,
    png: Option<PathBuf>,
) -> Result<(), String> {
    if !(rpm.is_finite() && rpm > 0.0) || points < 2 {
        return Err(format!(
            "--rpm must be positive (got {rpm}) and --points at least 2 (got {points})"
        ));
    }
    let (label, kind) = match &model {
        None => (
            "reference plain short bearing".to_string(),
            BearingKind::Plain(REFERENCE_BEARING),
        ),
        Some(path) => {
            let m = crate::read_model(path)?;
            let found = m.bearings.iter().find(|b| match &bearing {
                Some(name) => &b.name == name,
                None => b.kind.film_geometry().is_some(),
            });
            let b = found.ok_or_else(|| {
                let names: Vec<&str> = m.bearings.iter().map(|b| b.name.as_str()).collect();
                format!(
                    "{}: no {} among the bearings {names:?}",
                    path.display(),
                    bearing
                        .as_deref()
                        .map_or("hydrodynamic bearing".to_string(), |n| format!(
                            "bearing named {n:?}"
                        ))
                )
            })?;
            (format!("bearing {} of {}", b.name, m.name), b.kind.clone())
        }
    };
    let speed = rpm / RAD_S_TO_RPM;
    let whirl = match whirl_hz {
        None => speed,
        Some(hz) if hz.is_finite() && hz >= 0.0 => hz * std::f64::consts::TAU,
        Some(hz) => {
            return Err(format!(
                "--whirl-frequency must be a frequency ≥ 0 Hz, got {hz}"
            ));
        }
    };
    let finite = match film {
        "model" | "short" => None,
        "finite" => Some(
            FiniteFilmBearing::of(&kind, Cavitation::SwiftStieber).ok_or_else(|| {
                format!("{label}: --film finite needs a plain or tilting-pad bearing")
            })?,
        ),
        other => {
            return Err(format!(
                "--film must be \"model\", \"short\" or \"finite\", got {other:?}"
            ));
        }
    };
    let short = if film == "short" {
        kind.short_film().build()
    } else {
        kind.build()
    };
    let model: &dyn Bearing = match &finite {
        Some(f) => f,
        None => short.as_ref(),
    };
    let Some(sweep) = dimensionless_curve_of(&kind, model, (speed, whirl), points) else {
        return Err(format!("{label} is linear: its coefficients are constant"));
    };
    let mut curve = Vec::with_capacity(sweep.len());
    for (load, point) in sweep {
        match point {
            Ok(p) => curve.push(p),
            Err(e) => eprintln!("warning: {label}: no equilibrium at W = {load:.6e} N: {e}"),
        }
    }
    if curve.len() < 2 {
        return Err(format!("{label}: fewer than two equilibria found"));
    }
    let condensed = match whirl_hz {
        None => "pads condensed at the running speed (synchronous)".to_string(),
        Some(hz) => format!("pads condensed at a whirl of {hz} Hz"),
    };
    let film_name = match (film, &kind) {
        ("finite", _) => ", finite-length film (Swift–Stieber),".to_string(),
        ("model", BearingKind::FiniteFilm(f)) => {
            format!(", finite-length film ({}),", f.cavitation.name())
        }
        _ => String::new(),
    };
    let mut out = format!(
        "{label}{film_name} at {rpm} rpm, {condensed} (load along −y; K̄ = K C/W, C̄ = C ω C/W):\n"
    );
    out.push_str(
        "    ε     φ (°)     K̄xx     K̄xy     K̄yx     K̄yy     C̄xx     C̄xy     C̄yx     C̄yy\n",
    );
    let mut eps = Vec::new();
    let mut kbar: Vec<Vec<f64>> = vec![Vec::new(); 4];
    let mut cbar: Vec<Vec<f64>> = vec![Vec::new(); 4];
    for p in &curve {
        let (kv, cv) = (p.stiffness, p.damping);
        out.push_str(&format!(
            "{:6.3} {:8.2} {:8.3} {:8.3} {:8.3} {:8.3} {:8.3} {:8.3} {:8.3} {:8.3}\n",
            p.eccentricity,
            p.attitude_angle.to_degrees(),
            kv[0],
            kv[1],
            kv[2],
            kv[3],
            cv[0],
            cv[1],
            cv[2],
            cv[3]
        ));
        eps.push(p.eccentricity);
        for i in 0..4 {
            kbar[i].push(kv[i]);
            cbar[i].push(cv[i]);
        }
    }
    if let Some(path) = csv {
        write_file(&path, &report_csv::coefficients(&curve))?;
    }
    if let Some(path) = png {
        let names = ["xx", "xy", "yx", "yy"];
        let k: Vec<(String, Vec<f64>)> = names
            .iter()
            .zip(kbar)
            .map(|(n, v)| (format!("K{n}"), v))
            .collect();
        let c: Vec<(String, Vec<f64>)> = names
            .iter()
            .zip(cbar)
            .map(|(n, v)| (format!("C{n}"), v))
            .collect();
        let title = format!("Dimensionless coefficients: {label}, {rpm} rpm");
        coefficients_png(&path, &title, &eps, &k, &c).map_err(|e| e.to_string())?;
        eprintln!("wrote {}", path.display());
    }
    // Printed last: the files are written even when stdout is a closed pipe
    // (`rotor coefficients --png X | head`).
    print!("{out}");
    Ok(())
}
