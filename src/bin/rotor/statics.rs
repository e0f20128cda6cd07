//! `rotor info`, `rotor draw` and `rotor static`: the model summary, its drawing
//! and its static deflection.

use std::path::PathBuf;

use rotor_bearing::analysis::held_equilibrium::held_equilibrium;
use rotor_bearing::analysis::linear::static_deflection;
use rotor_bearing::analysis::shaft_loads::{largest_stress, section_loads};
use rotor_bearing::plot::RAD_S_TO_RPM;
use rotor_bearing::report::text::model_summary;
use rotor_bearing::report::{csv as report_csv, series};
use rotor_bearing::rotor::Rotor;
use rotor_bearing::solver::SolverOptions;

use crate::write_file;

/// `rotor draw`: the rotor's side view (shaft sections, disks, bearings,
/// probes, node numbers).
pub fn draw(rotor: &Rotor, png: &std::path::Path) -> Result<(), String> {
    let title = format!("Rotor {}", rotor.model.name);
    rotor_bearing::plot::rotor_png(png, &title, &rotor.model).map_err(|e| e.to_string())?;
    let scale = rotor_bearing::plot::radial_exaggeration(&rotor.model);
    if scale > 1.0 {
        println!("radial scale exaggerated ×{scale:.1}");
    }
    eprintln!("wrote {}", png.display());
    Ok(())
}

/// `rotor info`: nodes, elements, masses and bearings in engineering units.
pub fn info(rotor: &Rotor) -> Result<(), String> {
    print!("{}", model_summary(rotor));
    Ok(())
}

/// `rotor static`: the largest deflection and the node displacements as CSV;
/// the shaft's largest bending stress, and its section loads as CSV.
pub fn deflection(
    rotor: &Rotor,
    rpm: f64,
    csv: Option<PathBuf>,
    shaft_csv: Option<PathBuf>,
) -> Result<(), String> {
    let q = static_state(rotor, rpm)?;
    let loads = section_loads(rotor, &q, SolverOptions::default().gravity);
    if let Some(path) = shaft_csv {
        write_file(&path, &report_csv::shaft_loads(&loads))?;
    }
    if let Some(worst) = largest_stress(&loads) {
        println!(
            "largest bending moment {:.4e} N·m, bending stress {:.4e} Pa at z = {} m (node {})",
            worst.moment_magnitude,
            worst.stress,
            worst.z,
            worst.node + 1
        );
    }
    let out = report_csv::static_deflection(&rotor.model.node_z, &q);
    let (peak_node, peak) = series::largest_deflection(&q, rotor.model.node_count());
    let line = format!(
        "static deflection of {}: largest {:.4e} m at node {}",
        rotor.model.name,
        peak,
        peak_node + 1
    );
    match csv {
        Some(path) => {
            write_file(&path, &out)?;
            println!("{line}");
        }
        None => println!(
            "{line}\n(--csv FILE writes the displacements of all {} nodes)",
            rotor.model.node_count()
        ),
    }
    Ok(())
}

/// Node displacements (`4·node + k`) at the static equilibrium under gravity at
/// `rpm`: linear deflection for linear bearings; for fluid-film bearings the
/// statics solver's equilibrium (continued on the bearing offsets when needed).
fn static_state(rotor: &Rotor, rpm: f64) -> Result<Vec<f64>, String> {
    if rotor.nonlinear_bearings.is_empty() {
        return static_deflection(rotor).map_err(|e| e.to_string());
    }
    crate::warn_table_speeds(&rotor.model, &[rpm / RAD_S_TO_RPM]);
    crate::warn_short_films(rotor, &[rpm / RAD_S_TO_RPM]);
    let (eq, off_centre) = held_equilibrium(rotor, rpm / RAD_S_TO_RPM, None)
        .map_err(|e| format!("{} at {rpm} rpm: {e}", rotor.model.name))?;
    if let Some(off) = off_centre {
        println!("note: {}", off.describe());
    }
    Ok(rotor.dofs.expand(&eq.displacement))
}
