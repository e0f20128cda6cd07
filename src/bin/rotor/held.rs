//! The note of every command that linearizes, when the statics left a
//! statically unstable centre for the equilibrium the bearings hold
//! (`analysis::held_equilibrium`).

use rotor_bearing::analysis::held_equilibrium::held_equilibrium;
use rotor_bearing::rotor::Rotor;

/// Print, before the results, how the statics left a statically unstable
/// centre: at the model's `speed_rpm` when it states one, else at the
/// fastest of `speeds` (rad/s). Nothing for a rotor whose centre holds (or
/// without nonlinear bearings); the analyses themselves report an
/// equilibrium that cannot be found.
pub(crate) fn note_off_centre(rotor: &Rotor, speeds: &[f64]) {
    if rotor.nonlinear_bearings.is_empty() {
        return;
    }
    let nominal = rotor.model.nominal_speed.abs();
    let speed = if speeds.len() == 1 || nominal == 0.0 {
        speeds.iter().fold(0.0f64, |a, s| a.max(s.abs()))
    } else {
        nominal
    };
    if let Ok((_, Some(off))) = held_equilibrium(rotor, speed, None) {
        println!("note: {}", off.describe());
    }
}
