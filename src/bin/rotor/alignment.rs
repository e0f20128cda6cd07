//! `rotor alignment`: the bearing reactions of a shaft line at its offsets,
//! the reaction influence matrix, the offsets for a target load sharing and
//! the shaft's bending stress and the stability's slope against each
//! bearing's offset (issue 49). Formatting only: the physics is
//! `analysis::alignment`, `analysis::shaft_loads` and
//! `analysis::offset_stability`.

use clap::Args;
use rotor_bearing::analysis::alignment::{
    Alignment, AlignmentError, alignment, carries_weight, equal_specific_loads, offsets_for_loads,
};
use rotor_bearing::analysis::offset_stability::{STEP, offset_sensitivity};
use rotor_bearing::analysis::operating_point::operating_point;
use rotor_bearing::analysis::shaft_loads::{coupling_loads, largest_stress, section_loads};
use rotor_bearing::rotor::Rotor;
use rotor_bearing::solver::SolverOptions;
use rotor_bearing::units::{RAD_S_TO_RPM, Short};

/// Options of `rotor alignment`.
#[derive(Args)]
pub struct AlignmentArgs {
    /// Spin speed (rpm); default the model's speed_rpm (0 for a line on
    /// linear bearings only).
    #[arg(long)]
    pub rpm: Option<f64>,
    /// Target loads (N), one per bearing in model order, comma-separated;
    /// default equal specific load W/(L·D) (equal loads when a bearing has
    /// no film area).
    #[arg(long, value_delimiter = ',')]
    pub target: Option<Vec<f64>>,
}

/// Relative tolerance on the loads of the target alignment (of the total load).
const LOAD_TOLERANCE: f64 = 1e-6;

/// Most Newton steps on the elevations.
const MAX_STEPS: usize = 30;

pub fn run(rotor: &Rotor, args: AlignmentArgs) -> Result<(), String> {
    let rpm = match args.rpm {
        Some(r) => r,
        None if rotor.nonlinear_bearings.is_empty() && rotor.model.nominal_speed == 0.0 => 0.0,
        None => crate::model_rpm(&rotor.model, None)?,
    };
    if !rpm.is_finite() {
        return Err(format!("--rpm must be finite, got {rpm}"));
    }
    let speed = rpm / RAD_S_TO_RPM;
    crate::warn_table_speeds(&rotor.model, &[speed]);
    crate::warn_short_films(rotor, &[speed]);
    let name = &rotor.model.name;
    let options = SolverOptions::default();
    let at = |e: &dyn std::fmt::Display| format!("{name} at {rpm} rpm: {e}");
    let line = alignment(rotor, speed, &options).map_err(|e| at(&e))?;
    let films = operating_point(rotor, speed).map_err(|e| at(&e))?;
    let d = line.direction;
    let weight = carries_weight(rotor);
    println!(
        "alignment of {name} at {} rpm: loads and elevations along ({:.3}, {:.3}) ({})",
        Short(rpm),
        d[0] + 0.0,
        d[1] + 0.0,
        if weight {
            "against gravity"
        } else {
            "a vertical machine: in the plane of its largest offset"
        }
    );
    println!(
        "{:<14} {:>6} {:>12} {:>12} {:>12} {:>12} {:>12} {:>10} {:>8} {:>9}",
        "bearing",
        "node",
        "offset_x µm",
        "offset_y µm",
        "Fx N",
        "Fy N",
        "load N",
        "W/LD kPa",
        "ε",
        "attitude°"
    );
    for b in &line.bearings {
        let placed = &rotor.model.bearings[b.bearing];
        let film = films
            .iter()
            .find(|p| p.bearing == b.bearing)
            .and_then(|p| p.film.as_ref())
            .filter(|f| f.has_geometry());
        let specific = b
            .area
            .map_or("–".to_string(), |a| format!("{:.1}", b.load / a * 1e-3));
        let (eps, attitude) = film.map_or(("–".to_string(), "–".to_string()), |f| {
            (
                format!("{:.3}", f.eccentricity),
                format!("{:.1}", f.attitude_angle.to_degrees()),
            )
        });
        println!(
            "{:<14} {:>6} {:>12.2} {:>12.2} {:>12.1} {:>12.1} {:>12.1} {:>10} {:>8} {:>9}",
            b.name,
            placed.node + 1,
            b.offset[0] * 1e6,
            b.offset[1] * 1e6,
            b.reaction[0],
            b.reaction[1],
            b.load,
            specific,
            eps,
            attitude
        );
    }
    let s = line.load_influence();
    println!("reaction influence dR_i/do_j (N/mm): load of row i per mm of elevation of column j");
    print!("{:<14}", "");
    for b in &line.bearings {
        print!(" {:>12}", b.name);
    }
    println!();
    for (i, b) in line.bearings.iter().enumerate() {
        print!("{:<14}", b.name);
        for j in 0..line.bearings.len() {
            print!(" {:>12.4e}", s[(i, j)] * 1e-3);
        }
        println!();
    }
    let (target, what) = match args.target {
        Some(t) => (Some(t), "the given target"),
        // A vertical machine's guide bearings share no weight: the straight
        // line unloads them all.
        None if !weight => (None, ""),
        None => (Some(equal_specific_loads(&line)), "equal specific load"),
    };
    if let Some(target) = target {
        print_target(rotor, speed, &options, &line, &target, what).map_err(|e| at(&e))?;
    } else {
        println!(
            "a vertical machine carries no weight on its guide bearings: the straight line (all offsets zero) unloads them; --target asks for other loads"
        );
    }
    let all = rotor.dofs.expand(&line.equilibrium.displacement);
    let loads = section_loads(rotor, &all, options.gravity);
    if let Some(worst) = largest_stress(&loads) {
        println!(
            "shaft at the model's offsets: largest bending moment {:.1} N·m, stress {:.2} MPa at z = {:.3} m (node {})",
            worst.moment_magnitude,
            worst.stress * 1e-6,
            worst.z,
            worst.node + 1
        );
    }
    for c in coupling_loads(rotor, &all, options.gravity) {
        println!(
            "coupling {} between nodes {} and {} at the model's offsets: shear ({:.1}, {:.1}) N, bending moment ({:.1}, {:.1}) N·m in the x–z and y–z planes",
            c.name,
            c.node + 1,
            c.node + 2,
            c.shear[0],
            c.shear[1],
            c.moment[0],
            c.moment[1]
        );
    }
    if speed != 0.0 && !rotor.nonlinear_bearings.is_empty() {
        let (delta, slopes) = offset_sensitivity(rotor, speed).map_err(|e| at(&e))?;
        println!(
            "stability against the offsets at {} rpm: least stable forward mode log dec {delta:.4}; its slope per mm of each fluid-film bearing's offset (central differences of ±{} of the clearance):",
            Short(rpm),
            STEP
        );
        println!(
            "{:<14} {:>14} {:>14}",
            "bearing", "dδ/do_x 1/mm", "dδ/do_y 1/mm"
        );
        for s in &slopes {
            println!(
                "{:<14} {:>14.4e} {:>14.4e}",
                s.name,
                s.log_decrement_slope[0] * 1e-3,
                s.log_decrement_slope[1] * 1e-3
            );
        }
    }
    Ok(())
}

/// The offsets that give `target` (`what` it is) and the loads they give.
fn print_target(
    rotor: &Rotor,
    speed: f64,
    options: &SolverOptions,
    line: &Alignment,
    target: &[f64],
    what: &str,
) -> Result<(), AlignmentError> {
    let d = line.direction;
    let total: f64 = line.loads().iter().sum();
    let found = offsets_for_loads(
        rotor,
        speed,
        options,
        target,
        LOAD_TOLERANCE * total.abs().max(1.0),
        MAX_STEPS,
    )?;
    println!(
        "offsets for {what} (least-norm change of the elevations, {} Newton steps):",
        found.iterations
    );
    println!(
        "{:<14} {:>12} {:>12} {:>12} {:>12} {:>12}",
        "bearing", "offset_x µm", "offset_y µm", "change µm", "target N", "achieved N"
    );
    for (k, b) in found.achieved.bearings.iter().enumerate() {
        let before = line.bearings[k].offset;
        let change = (b.offset[0] - before[0]) * d[0] + (b.offset[1] - before[1]) * d[1];
        println!(
            "{:<14} {:>12.2} {:>12.2} {:>12.2} {:>12.1} {:>12.1}",
            b.name,
            b.offset[0] * 1e6,
            b.offset[1] * 1e6,
            change * 1e6,
            found.target[k],
            b.load
        );
    }
    if found.unreachable > LOAD_TOLERANCE * total.abs().max(1.0) {
        println!(
            "no alignment reaches this target: {:.3e} N of it is out of reach (the loads must balance the line's weight and its moment); the offsets meet it in the least-squares sense",
            found.unreachable
        );
    }
    Ok(())
}
