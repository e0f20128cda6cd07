//! `rotor cases`: the tolerance cases of the model's `[cases]` section —
//! the nominal model and every combination of the oil temperature,
//! clearance and preload ends — judged by the criteria of `rotor report`,
//! and the case that governs each criterion.

use clap::Args;
use rotor_bearing::analysis::speed_range::OperatingRange;
use rotor_bearing::analysis::tolerance_cases::tolerance_cases;
use rotor_bearing::report::text;
use rotor_bearing::rotor::Rotor;
use rotor_bearing::units::RAD_S_TO_RPM;

/// `rotor cases`' arguments.
#[derive(Args)]
pub struct CasesArgs {
    #[command(flatten)]
    model: crate::ModelArg,
    /// Operating speed (rpm); default the model's speed_rpm.
    #[arg(long)]
    rpm: Option<f64>,
    /// Operating speed range MIN:MAX (rpm) of the separation margins;
    /// default the model's operating_rpm, else the operating speed.
    #[arg(long)]
    operating_rpm: Option<String>,
}

/// `rotor cases` as parsed.
pub fn command(args: &CasesArgs) -> Result<(), String> {
    let rotor = crate::load(&args.model)?;
    let rpm = crate::model_rpm(&rotor.model, args.rpm)?;
    let operating = args
        .operating_rpm
        .as_deref()
        .map(crate::unbalance::operating_range)
        .transpose()?;
    run(&rotor, rpm, operating)
}

/// Run the cases at `rpm` with the margins against `operating` (else the
/// model's `operating_rpm`, else the speed alone) and print them.
pub fn run(rotor: &Rotor, rpm: f64, operating: Option<OperatingRange>) -> Result<(), String> {
    if !(rpm.is_finite() && rpm > 0.0) {
        return Err(format!("--rpm must be a positive speed, got {rpm}"));
    }
    let speed = rpm / RAD_S_TO_RPM;
    let operating = operating
        .or(rotor
            .model
            .operating_range
            .map(|[min, max]| OperatingRange { min, max }))
        .unwrap_or(OperatingRange {
            min: speed,
            max: speed,
        });
    let study = tolerance_cases(rotor, speed, operating).map_err(|e| e.to_string())?;
    print!("{}", text::tolerance_cases(&rotor.model.name, &study));
    Ok(())
}
