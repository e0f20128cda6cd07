//! Driving a [`Simulator`] through a speed profile and recording its outputs.

use super::{Outputs, Simulator, SolverError};

/// Spin speed against time.
#[derive(Debug, Clone, PartialEq)]
pub enum SpeedProfile {
    /// Constant speed (rad/s).
    Constant(f64),
    /// Linear ramp from `from` to `to` (rad/s) over `duration` (s), then constant.
    Ramp { from: f64, to: f64, duration: f64 },
    /// Piecewise-linear table of `(time s, speed rad/s)`, times increasing;
    /// constant before the first and after the last point.
    Table(Vec<(f64, f64)>),
}

impl SpeedProfile {
    /// Speed (rad/s) and its rate (rad/s²) at time `t`, the rate taken on the
    /// segment that starts at `t`.
    pub fn at(&self, t: f64) -> (f64, f64) {
        match self {
            SpeedProfile::Constant(w) => (*w, 0.0),
            SpeedProfile::Ramp { from, to, duration } => {
                if *duration <= 0.0 || t >= *duration {
                    (*to, 0.0)
                } else {
                    let rate = (to - from) / duration;
                    (from + rate * t.max(0.0), rate)
                }
            }
            SpeedProfile::Table(points) => {
                let Some(&(t0, w0)) = points.first() else {
                    return (0.0, 0.0);
                };
                if t < t0 {
                    return (w0, 0.0);
                }
                for pair in points.windows(2) {
                    let ((ta, wa), (tb, wb)) = (pair[0], pair[1]);
                    if t >= ta && t < tb {
                        let rate = (wb - wa) / (tb - ta);
                        return (wa + rate * (t - ta), rate);
                    }
                }
                (points[points.len() - 1].1, 0.0)
            }
        }
    }

    /// The largest |speed| (rad/s) the profile reaches.
    pub fn top_speed(&self) -> f64 {
        match self {
            SpeedProfile::Constant(w) => w.abs(),
            SpeedProfile::Ramp { from, to, .. } => from.abs().max(to.abs()),
            SpeedProfile::Table(points) => points.iter().fold(0.0, |m, p| m.max(p.1.abs())),
        }
    }

    /// Check the profile's numbers.
    pub fn validate(&self) -> Result<(), String> {
        match self {
            SpeedProfile::Constant(w) if !w.is_finite() => Err(format!("speed {w} is not finite")),
            SpeedProfile::Ramp { from, to, duration }
                if !(from.is_finite()
                    && to.is_finite()
                    && duration.is_finite()
                    && *duration >= 0.0) =>
            {
                Err(format!(
                    "ramp {from} → {to} rad/s over {duration} s is not valid"
                ))
            }
            SpeedProfile::Table(points) => {
                if points.is_empty() {
                    return Err("speed table is empty".into());
                }
                for (k, pair) in points.windows(2).enumerate() {
                    if pair[1].0 <= pair[0].0 || pair[1].0.is_nan() {
                        return Err(format!(
                            "speed table times must increase (row {}: {} after {})",
                            k + 2,
                            pair[1].0,
                            pair[0].0
                        ));
                    }
                }
                if let Some((t, w)) = points
                    .iter()
                    .find(|(t, w)| !(t.is_finite() && w.is_finite()))
                {
                    return Err(format!("speed table row ({t}, {w}) is not finite"));
                }
                Ok(())
            }
            _ => Ok(()),
        }
    }
}

/// Run `sim` from its current time for `duration` s, following `profile`,
/// recording outputs every `output_step` s (the first record at the start).
/// `progress` is called with the fraction done and the simulator after
/// every record.
pub fn record(
    sim: &mut Simulator,
    profile: &SpeedProfile,
    duration: f64,
    output_step: f64,
    progress: impl FnMut(f64, &Simulator),
) -> Result<Vec<Outputs>, SolverError> {
    let mut out = Vec::new();
    record_into(sim, profile, duration, output_step, &mut out, progress)?;
    Ok(out)
}

/// [`record`] into `out`, which keeps the records made before a failure (the
/// run up to the last converged output), so a failed run loses nothing.
pub fn record_into(
    sim: &mut Simulator,
    profile: &SpeedProfile,
    duration: f64,
    output_step: f64,
    out: &mut Vec<Outputs>,
    mut progress: impl FnMut(f64, &Simulator),
) -> Result<(), SolverError> {
    profile.validate().map_err(SolverError::Input)?;
    if !(duration.is_finite() && duration >= 0.0 && output_step.is_finite() && output_step > 0.0) {
        return Err(SolverError::Input(format!(
            "duration {duration} s and output step {output_step} s must be finite, the step positive"
        )));
    }
    let t0 = sim.time();
    let count = (duration / output_step).round() as usize;
    out.reserve(count + 1);
    // A torque-driven shaft takes its speed from the torques: the profile
    // can only be its initial speed.
    let driven = sim.is_torque_driven();
    if driven && !matches!(profile, SpeedProfile::Constant(_)) {
        return Err(SolverError::Input(format!(
            "the shaft of {} is torque-driven: its speed comes from the torques, a speed profile can only give its initial speed (a constant speed)",
            sim.rotor().model.name
        )));
    }
    let (w, rate) = profile.at(t0);
    if !driven || t0 == 0.0 {
        sim.set_speed(w, rate)?;
    }
    out.push(sim.outputs()?);
    for k in 1..=count {
        let t = t0 + k as f64 * output_step;
        sim.advance_to(t)?;
        if !driven {
            let (w, rate) = profile.at(t);
            sim.set_speed(w, rate)?;
        }
        out.push(sim.outputs()?);
        progress(k as f64 / count as f64, sim);
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn top_speed_is_the_largest_absolute_speed() {
        let ramp = SpeedProfile::Ramp {
            from: -10.0,
            to: 5.0,
            duration: 1.0,
        };
        assert_eq!(ramp.top_speed(), 10.0);
        assert_eq!(
            SpeedProfile::Table(vec![(0.0, 1.0), (1.0, -7.0)]).top_speed(),
            7.0
        );
        assert_eq!(SpeedProfile::Constant(-3.0).top_speed(), 3.0);
    }
}
