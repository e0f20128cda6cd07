//! The model a command reads: the file (its plausibility warnings and film
//! table notes on stderr) or the built-in rotor, `--excitation`, and the
//! speed of `--rpm` or the model's `speed_rpm`.

use std::path::Path;

use rotor_bearing::model::RotorModel;
use rotor_bearing::rotor::Rotor;
use rotor_bearing::units::RAD_S_TO_RPM;

use crate::ModelArg;

/// The speed (rpm) of `--rpm`, else the model's `speed_rpm`.
pub(crate) fn model_rpm(model: &RotorModel, rpm: Option<f64>) -> Result<f64, String> {
    match rpm {
        Some(r) => Ok(r),
        None if model.nominal_speed != 0.0 => Ok(model.nominal_speed * RAD_S_TO_RPM),
        None => Err(format!(
            "{}: the model states no speed_rpm: give --rpm",
            model.source
        )),
    }
}

/// Read a model file and print its plausibility warnings on stderr.
pub(crate) fn read_model(path: &Path) -> Result<RotorModel, String> {
    let model = RotorModel::from_file(path).map_err(|e| e.to_string())?;
    for w in model.plausibility_warnings() {
        eprintln!("warning: {w}");
    }
    // A force table built (not read from the cache) is told with its time.
    for b in &model.bearings {
        if let Some(note) = b.kind.film_table_note() {
            for line in note.lines() {
                eprintln!("bearing {}: film table {line}", b.name);
            }
        }
    }
    Ok(model)
}

pub(crate) fn load(arg: &ModelArg) -> Result<Rotor, String> {
    let mut model = match &arg.model {
        Some(path) => read_model(path)?,
        None => RotorModel::default_model(),
    };
    if let Some(e) = arg.excitation {
        let max = rotor_bearing::model::limits::MAX_EXCITATION;
        if !(e.is_finite() && (0.0..=max).contains(&e)) {
            return Err(format!(
                "--excitation {e}: must lie in [0, {max}] (1 is the nominal field)"
            ));
        }
        let mut pulls = 0;
        for b in &mut model.bearings {
            if b.kind.set_excitation(e) {
                pulls += 1;
            }
        }
        if pulls == 0 {
            return Err(format!(
                "--excitation {e}: {} has no magnetic pull",
                model.source
            ));
        }
    }
    Rotor::new(model).map_err(|e| e.to_string())
}
