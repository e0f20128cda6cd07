//! `rotor response`: the steady response of every probe and bearing journal
//! to one harmonic force of the model (`[[forces]]`: a vortex rope, blade
//! passing, a fixed-frequency excitation) over a speed range, the rotor
//! linearized at each speed ([`forced_sweep`]).

use std::path::PathBuf;

use rotor_bearing::analysis::forced::{forced_sweep, harmonic_force};
use rotor_bearing::analysis::unbalance::{response_points, speed_grid};
use rotor_bearing::model::ForceKind;
use rotor_bearing::plot::RAD_S_TO_RPM;
use rotor_bearing::report::csv as report_csv;
use rotor_bearing::report::text::short;
use rotor_bearing::rotor::Rotor;

use crate::write_file;

/// What `rotor response` was asked for.
pub struct Request {
    pub force: String,
    pub min_rpm: f64,
    pub max_rpm: f64,
    pub points: usize,
    /// Amplitude (N) instead of the model file's.
    pub magnitude: Option<f64>,
    pub csv: Option<PathBuf>,
}

/// Per response point, the largest orbit (major semi-axis, µm) over the
/// speeds, the speed (rpm) and the force's frequency (Hz) where it occurs.
pub fn run(rotor: &Rotor, req: Request) -> Result<(), String> {
    let index = harmonic_force(rotor, &req.force).map_err(|e| e.to_string())?;
    let scaled;
    let rotor = match req.magnitude {
        Some(m) if !(m.is_finite() && m >= 0.0) => {
            return Err(format!(
                "--magnitude {m}: must be a finite force, not negative (N)"
            ));
        }
        Some(m) => {
            let mut model = rotor.model.clone();
            if let ForceKind::Harmonic { magnitude, .. } = &mut model.forces[index].kind {
                *magnitude = m;
            }
            scaled = Rotor::new(model).map_err(|e| e.to_string())?;
            &scaled
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
    crate::warn_short_films(rotor, &speeds);
    crate::held::note_off_centre(rotor, &speeds);
    let (frequencies, sweep) = forced_sweep(rotor, index, &speeds, &response_points(rotor))
        .map_err(|e| format!("{}: {e}", rotor.model.name))?;
    if let Some(path) = req.csv {
        write_file(&path, &report_csv::forced(&frequencies, &sweep))?;
    }
    let mut out = format!(
        "response of {} to the harmonic force {}, {} … {} rpm ({} speeds):\n\
         point                      largest orbit (µm)  at speed (rpm)  frequency (Hz)\n",
        rotor.model.name,
        req.force,
        short(speeds[0] * RAD_S_TO_RPM),
        short(req.max_rpm),
        speeds.len()
    );
    for (p, point) in sweep.points.iter().enumerate() {
        let major = sweep.major(p);
        let k = (0..major.len())
            .max_by(|&a, &b| major[a].total_cmp(&major[b]))
            .unwrap_or(0);
        out.push_str(&format!(
            "{:<26} {:>19} {:>15.1} {:>15}\n",
            point.label,
            short(major[k] * 1e6),
            speeds[k] * RAD_S_TO_RPM,
            short(frequencies[k] / (2.0 * std::f64::consts::PI))
        ));
    }
    // Printed last: files are written even when stdout is a closed pipe.
    print!("{out}");
    Ok(())
}
