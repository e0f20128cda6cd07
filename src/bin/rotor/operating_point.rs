//! `rotor operating-point`: every bearing's load, film state, friction and
//! coefficients at one speed.

use std::path::PathBuf;

use rotor_bearing::analysis::element_operating_point::{
    element_operating_points, force_operating_points, thrust_operating_points,
};
use rotor_bearing::analysis::frequency_table::frequency_table;
use rotor_bearing::analysis::operating_point::{operating_point, pedestal_operating_points};
use rotor_bearing::plot::RAD_S_TO_RPM;
use rotor_bearing::report::text::{coefficient_matrix, short};
use rotor_bearing::report::{csv as report_csv, text};
use rotor_bearing::rotor::Rotor;

use crate::write_file;

/// The speed × whirl-frequency table of the film bearings' coefficients.
#[derive(clap::Args, Debug)]
pub struct FrequencyTableArgs {
    /// Whirl frequency over spin speed at which the pad tilts are condensed,
    /// comma-separated (e.g. 0.25,0.5,1): print each film bearing's K and C
    /// at each, at `--rpm` or every speed of `--table-rpm`.
    #[arg(long, value_delimiter = ',')]
    whirl_ratios: Vec<f64>,
    /// Speeds (rpm) of the table, comma-separated; default `--rpm`.
    #[arg(long, value_delimiter = ',')]
    table_rpm: Vec<f64>,
    /// Write the table to this CSV file.
    #[arg(long)]
    table_csv: Option<PathBuf>,
}

pub fn run(
    rotor: &Rotor,
    rpm: f64,
    (csv, pads_csv): (Option<PathBuf>, Option<PathBuf>),
    table: FrequencyTableArgs,
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
    frequency_table_of(rotor, rpm, table)
}

/// `--whirl-ratios`: the table printed and written.
fn frequency_table_of(rotor: &Rotor, rpm: f64, args: FrequencyTableArgs) -> Result<(), String> {
    if args.whirl_ratios.is_empty() {
        if !args.table_rpm.is_empty() || args.table_csv.is_some() {
            return Err("--table-rpm and --table-csv need --whirl-ratios".into());
        }
        return Ok(());
    }
    let rpms = if args.table_rpm.is_empty() {
        vec![rpm]
    } else {
        args.table_rpm.clone()
    };
    if let Some(bad) = rpms.iter().find(|r| !(r.is_finite() && **r > 0.0)) {
        return Err(format!(
            "--table-rpm: every speed must be positive, got {bad}"
        ));
    }
    if let Some(bad) = args
        .whirl_ratios
        .iter()
        .find(|r| !(r.is_finite() && **r >= 0.0))
    {
        return Err(format!(
            "--whirl-ratios: every ratio must be finite and ≥ 0, got {bad}"
        ));
    }
    let speeds: Vec<f64> = rpms.iter().map(|r| r / RAD_S_TO_RPM).collect();
    let rows = frequency_table(rotor, &speeds, &args.whirl_ratios)
        .map_err(|e| format!("{}: {e}", rotor.model.name))?;
    let mut csv = String::from(
        "bearing,speed_rpm,whirl_ratio,whirl_frequency_hz,kxx_N_m,kxy_N_m,kyx_N_m,kyy_N_m,cxx_Ns_m,cxy_Ns_m,cyx_Ns_m,cyy_Ns_m\n",
    );
    println!("film bearings condensed at whirl frequency ω = r Ω (K in N/m, C in N·s/m):");
    for r in &rows {
        let (k, c) = (r.stiffness, r.damping);
        let rpm = r.speed * RAD_S_TO_RPM;
        let hz = r.ratio * r.speed / std::f64::consts::TAU;
        println!(
            "  {} at {} rpm, r = {} ({} Hz): K = {}, C = {}",
            r.name,
            short(rpm),
            short(r.ratio),
            short(hz),
            coefficient_matrix(&k),
            coefficient_matrix(&c)
        );
        csv.push_str(&format!(
            "{},{rpm},{},{hz},{},{},{},{},{},{},{},{}\n",
            r.name, r.ratio, k[0][0], k[0][1], k[1][0], k[1][1], c[0][0], c[0][1], c[1][0], c[1][1]
        ));
    }
    if let Some(path) = args.table_csv {
        write_file(&path, &csv)?;
    }
    Ok(())
}
