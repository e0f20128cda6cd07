//! `rotor operating-point`: every bearing's load, film state, friction and
//! coefficients at one speed.

use std::path::PathBuf;

use rotor_bearing::analysis::element_operating_point::{
    element_operating_points, force_operating_points, thrust_operating_points,
};
use rotor_bearing::analysis::operating_point::{operating_point, pedestal_operating_points};
use rotor_bearing::plot::RAD_S_TO_RPM;
use rotor_bearing::report::{csv as report_csv, text};
use rotor_bearing::rotor::Rotor;

use crate::write_file;

pub fn run(
    rotor: &Rotor,
    rpm: f64,
    csv: Option<PathBuf>,
    pads_csv: Option<PathBuf>,
) -> Result<(), String> {
    if !rpm.is_finite() {
        return Err(format!("--rpm must be finite, got {rpm}"));
    }
    crate::warn_table_speeds(&rotor.model, &[rpm / RAD_S_TO_RPM]);
    crate::warn_short_films(rotor, &[rpm / RAD_S_TO_RPM]);
    crate::held::note_off_centre(rotor, &[rpm / RAD_S_TO_RPM]);
    let points = operating_point(rotor, rpm / RAD_S_TO_RPM)
        .map_err(|e| format!("{} at {rpm} rpm: {e}", rotor.model.name))?;
    if let Some(path) = csv {
        write_file(&path, &report_csv::operating_point(rpm, &points))?;
    }
    if let Some(path) = pads_csv {
        write_file(&path, &report_csv::operating_pads(&points))?;
    }
    print!("{}", text::operating_point(rpm, &points));
    let pedestals = pedestal_operating_points(rotor, rpm / RAD_S_TO_RPM)
        .map_err(|e| format!("{} at {rpm} rpm: {e}", rotor.model.name))?;
    print!("{}", text::pedestals(rpm, &pedestals));
    let speed = rpm / RAD_S_TO_RPM;
    let elements = element_operating_points(rotor, speed)
        .map_err(|e| format!("{} at {rpm} rpm: {e}", rotor.model.name))?;
    print!(
        "{}",
        text::element_points(
            rpm,
            &rotor.model,
            (
                &elements,
                &thrust_operating_points(rotor, speed),
                &force_operating_points(rotor, speed),
            ),
        )
    );
    Ok(())
}
