//! The options of `rotor simulate` and the run they ask for: the speed
//! profile or the torques, the time step, the rotor (full or reduced) and
//! the solver options, handed to [`crate::simulate::simulate`].

use std::path::PathBuf;

use clap::Args;
use rotor_bearing::rotor::Rotor;
use rotor_bearing::solver::time_step;
use rotor_bearing::units::Amplitude;

use crate::simulate;

/// `rotor simulate`'s options besides the model.
#[derive(Args)]
pub struct SimulateArgs {
    /// Constant spin speed (rpm).
    #[arg(long, conflicts_with_all = ["ramp_rpm", "speed_csv"])]
    pub rpm: Option<f64>,
    /// Linear run-up or coast-down FROM:TO (rpm) over the whole duration.
    #[arg(long, conflicts_with = "speed_csv")]
    pub ramp_rpm: Option<String>,
    /// Speed table: CSV with columns time_s,speed_rpm (header line optional).
    #[arg(long)]
    pub speed_csv: Option<PathBuf>,
    /// A torque-driven shaft's torque NAME=VALUE (N·m, a `[[torques]]`
    /// name, constant from the start; repeat for each); --rpm is then its
    /// initial speed (default 0: from rest).
    #[arg(long = "torque", value_name = "NAME=N·m")]
    pub torques: Vec<String>,
    /// How the shaft is driven in this run, overriding the model's
    /// `[torsion] drive`: `speed` (the speed options prescribe its speed) or
    /// `torque` (the `--torque` inputs drive it; --rpm is its initial speed;
    /// the model needs `[[torques]]` nodes).
    #[arg(long, value_parser = ["speed", "torque"])]
    pub drive: Option<String>,
    /// Simulated time (s).
    #[arg(long, default_value_t = 1.0)]
    pub duration: f64,
    /// Internal time step (s): equal steps of it (the largest step with
    /// --local-error-tolerance). Default: accuracy-controlled steps of at most
    /// 12 per revolution at the top speed (the larger of the run's and the
    /// model's max_speed_rpm, else speed_rpm), at most 20 ms — the FMU's
    /// solver.time_step follows the same rule at the model's top speed; with
    /// --local-error-tolerance 0, 60 equal steps per revolution, at most 1 ms.
    #[arg(long)]
    pub step: Option<f64>,
    /// Accuracy-controlled steps: the local error allowed to each step,
    /// the relative period error (ωh)²/12 of the motion it resolves; --step
    /// is then the largest step. 0: equal steps. Default: 0.003 without
    /// --step (the FMU's default), equal steps with it.
    #[arg(long)]
    pub local_error_tolerance: Option<f64>,
    /// Output interval (s); defaults to the internal step, at least 1/20 000 of the duration.
    #[arg(long)]
    pub output_step: Option<f64>,
    /// Unbalance ramp time constant (s), 0 for none.
    #[arg(long, default_value_t = 0.0)]
    pub ramp_time: f64,
    /// Switch gravity off.
    #[arg(long)]
    pub no_gravity: bool,
    /// Start from rest at the bearing centres instead of the static equilibrium.
    #[arg(long)]
    pub no_settle: bool,
    /// Run on a Craig–Bampton reduced rotor with this many fixed-interface
    /// modes (bearings, rubs, probes and unbalance planes kept physical);
    /// 0 for the full rotor. Default: the model's `[reduction]`, else full.
    #[arg(long)]
    pub reduced_modes: Option<usize>,
    /// Write the outputs to this CSV file (without it the terminal gets a
    /// summary, not the table); a run that fails keeps the rows up to the failure.
    #[arg(long)]
    pub csv: Option<PathBuf>,
    /// Write PREFIX_orbits.png and PREFIX_spectrum.png (last half of the run) and
    /// PREFIX_waterfall.png, and print the spectrum of each window of 20 revolutions
    /// (a run under 20 revolutions gets no frequency ratio).
    #[arg(long)]
    pub plots: Option<String>,
    /// Amplitudes of the spectra and the window table: the orbit's radius (0-pk)
    /// or twice it (pk-pk).
    #[arg(long, default_value = "0-pk", value_parser = crate::parse_amplitude)]
    pub amplitude: Amplitude,
}

/// `rotor` with its shaft driven as `--drive` says (the model's own drive
/// when not given).
fn with_drive(rotor: Rotor, drive: Option<&str>) -> Result<Rotor, String> {
    use rotor_bearing::model::Drive;
    let wanted = match drive {
        None => return Ok(rotor),
        Some("speed") => Drive::Speed,
        Some(_) => Drive::Torque,
    };
    if rotor.model.drive == wanted {
        return Ok(rotor);
    }
    let mut model = rotor.model.clone();
    if wanted == Drive::Torque && model.torques.is_empty() {
        return Err(format!(
            "--drive torque: {} has no [[torques]] nodes to apply the torques at",
            model.source
        ));
    }
    model.drive = wanted;
    Rotor::new(model).map_err(|e| e.to_string())
}

/// Run `rotor simulate` on `rotor` as `args` ask.
pub fn run(rotor: Rotor, args: SimulateArgs) -> Result<(), String> {
    let SimulateArgs {
        rpm,
        ramp_rpm,
        speed_csv,
        torques,
        drive,
        duration,
        step,
        local_error_tolerance,
        output_step,
        ramp_time,
        no_gravity,
        no_settle,
        reduced_modes,
        csv,
        plots,
        amplitude,
    } = args;
    let rotor = with_drive(rotor, drive.as_deref())?;
    let torque_driven = rotor.model.drive == rotor_bearing::model::Drive::Torque;
    if torque_driven {
        let name = &rotor.model.name;
        if ramp_rpm.is_some() || speed_csv.is_some() {
            let option = if ramp_rpm.is_some() {
                "--ramp-rpm"
            } else {
                "--speed-csv"
            };
            return Err(format!(
                "{option}: the shaft of {name} is torque-driven: its speed comes from the torques (--torque NAME=N·m), so a speed profile cannot be prescribed; give --drive speed to prescribe it"
            ));
        }
        if torques.is_empty() {
            eprintln!(
                "note: the shaft of {name} is torque-driven and no --torque is given: {} it coasts under its bearings' friction (give --torque NAME=N·m to drive it, or --drive speed to hold the speed)",
                match rpm {
                    Some(r) if r != 0.0 => format!("from its initial speed --rpm {r}"),
                    _ => "from rest".to_string(),
                }
            );
        }
    }
    let rpm = match (rpm, ramp_rpm.is_none() && speed_csv.is_none()) {
        (None, true) if torque_driven => Some(0.0),
        (rpm, _) => rpm,
    };
    let profile =
        simulate::speed_profile(rpm, ramp_rpm.as_deref(), speed_csv.as_deref(), duration)?;
    let torques = simulate::torque_inputs(&rotor.model, &torques)?;
    simulate::check_speeds(&rotor.model, &profile)?;
    let local_error_tolerance = local_error_tolerance.unwrap_or(if step.is_some() {
        0.0
    } else {
        time_step::DEFAULT_LOCAL_ERROR_TOLERANCE
    });
    let adaptive = local_error_tolerance > 0.0;
    let step = step.unwrap_or_else(|| {
        let peak = profile.top_speed();
        let h = if adaptive {
            time_step::largest_adaptive_step(&rotor.model, Some(peak))
        } else {
            time_step::default_time_step(&rotor.model, Some(peak))
        };
        eprintln!(
            "{}",
            simulate::describe_default_step(&rotor.model, peak, h, local_error_tolerance)
        );
        h
    });
    let modes = match reduced_modes {
        Some(m) => m,
        None => Rotor::transient_modes(&rotor.model).map_err(|e| e.to_string())?,
    };
    let (rotor, full) = if modes == 0 {
        (rotor, None)
    } else {
        (
            rotor.reduced(modes).map_err(|e| e.to_string())?,
            Some(rotor),
        )
    };
    let options = rotor_bearing::solver::SolverOptions {
        time_step: step,
        unbalance_ramp_time: ramp_time,
        gravity: !no_gravity,
        local_error_tolerance,
        ..Default::default()
    };
    let output_step = output_step.unwrap_or(step.max(duration / 20_000.0));
    let run = simulate::Run {
        profile,
        duration,
        output_step,
        settle: !no_settle,
        csv,
        plots,
        amplitude,
        torques,
    };
    simulate::simulate(rotor, full, options, run)
}
