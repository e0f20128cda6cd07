//! The warnings an analysis prints on stderr before its results: coefficient
//! tables asked beyond their rows, short films beyond their range.

use rotor_bearing::model::RotorModel;
use rotor_bearing::rotor::Rotor;

/// Print a warning for each coefficient table an analysis at `speeds`
/// (rad/s) asks for a speed outside its rows.
pub(crate) fn warn_table_speeds(model: &RotorModel, speeds: &[f64]) {
    for w in model.table_speed_warnings(speeds) {
        eprintln!("warning: {w}");
    }
}

/// Print one warning for each plain or tilting-pad bearing on the short
/// film beyond its range (`analysis::film_validity`), with its ratios at
/// the operating point: at the model's `speed_rpm` when it states one,
/// else at the fastest of `speeds` (rad/s).
pub(crate) fn warn_short_films(rotor: &Rotor, speeds: &[f64]) {
    let nominal = rotor.model.nominal_speed.abs();
    let speed = if nominal > 0.0 {
        nominal
    } else {
        speeds.iter().fold(0.0f64, |a, s| a.max(s.abs()))
    };
    match rotor_bearing::analysis::film_validity::short_film_warnings(rotor, speed) {
        Ok(warnings) => {
            for w in warnings {
                eprintln!("warning: {}: {w}", rotor.model.source);
            }
        }
        Err(e) => eprintln!(
            "warning: {}: the short films' validity was not checked: {e}",
            rotor.model.source
        ),
    }
}
