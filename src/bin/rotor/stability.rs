//! `rotor stability`: log decrements at a speed, the threshold of added
//! cross-coupled stiffness at the disks (or named nodes), and the API 617 /
//! API 684 Level I screening against Wachel's anticipated cross-coupling.

use std::path::PathBuf;

use rotor_bearing::analysis::level_two::{LevelTwo, level_two};
use rotor_bearing::analysis::ring_down::{RingDown, ring_down};
use rotor_bearing::analysis::stability::{
    StabilityRequest, StageData, disks_and_seals, level_one_stages, site_label, stability_study,
};
use rotor_bearing::analysis::unbalance::OperatingRange;
use rotor_bearing::plot::{RAD_S_TO_RPM, stability_png};
use rotor_bearing::report::{csv as report_csv, text};
use rotor_bearing::rotor::Rotor;

use crate::write_file;

/// What `rotor stability` was asked for.
pub struct Request {
    pub rpm: f64,
    /// The operating range (`--operating-rpm`, else the model's): its top
    /// is the maximum continuous speed of API 617 Level II.
    pub operating: Option<OperatingRange>,
    pub q_max: Option<f64>,
    pub points: usize,
    pub modes: usize,
    pub at: Option<String>,
    pub stages: Option<StageData>,
    pub csv: Option<PathBuf>,
    /// Level II's CSV (an API machine).
    pub level_two_csv: Option<PathBuf>,
    pub png: Option<PathBuf>,
    /// Ring the least-damped modes down in the nonlinear transient.
    pub verify: bool,
}

/// `--at 6,9` or `--at impeller,runner`: node numbers (from 1) or disk names,
/// as 0-based nodes.
pub fn sites(rotor: &Rotor, at: Option<&str>) -> Result<Vec<usize>, String> {
    let Some(text) = at else {
        return Ok(Vec::new());
    };
    text.split(',')
        .map(|item| {
            let item = item.trim();
            if let Ok(n) = item.parse::<usize>() {
                if n == 0 || n > rotor.model.node_count() {
                    return Err(format!(
                        "--at {item}: nodes count from 1 to {}",
                        rotor.model.node_count()
                    ));
                }
                return Ok(n - 1);
            }
            rotor
                .model
                .disks
                .iter()
                .find(|d| d.name == item)
                .map(|d| d.node)
                .ok_or_else(|| {
                    let names: Vec<&str> =
                        rotor.model.disks.iter().map(|d| d.name.as_str()).collect();
                    format!("--at {item:?}: not a node number or a disk name (disks: {names:?})")
                })
        })
        .collect()
}

/// The stage data of `--power`, `--impeller-diameter`, `--flow-width`
/// (all three, or none), `--density-ratio` and `--stage-factor`.
pub fn stages(
    power: Option<f64>,
    diameter: Option<f64>,
    width: Option<f64>,
    density_ratio: f64,
    stage_factor: f64,
) -> Result<Option<StageData>, String> {
    match (power, diameter, width) {
        (None, None, None) => Ok(None),
        (Some(power), Some(diameter), Some(width)) => Ok(Some(StageData {
            power,
            diameter,
            width,
            density_ratio,
            stage_factor,
        })),
        _ => Err(
            "the anticipated cross-coupling needs --power, --impeller-diameter and --flow-width together"
                .into(),
        ),
    }
}

pub fn run(rotor: &Rotor, req: Request) -> Result<(), String> {
    if !(req.rpm.is_finite() && req.rpm != 0.0) {
        return Err(format!(
            "--rpm must be a nonzero speed (forward whirl is relative to the spin), got {}",
            req.rpm
        ));
    }
    let machine = rotor.model.machine;
    // API 617's Level I screening is not written for hydro units.
    if machine.is_hydro() && req.stages.is_some() {
        eprintln!(
            "note: --power, --impeller-diameter and --flow-width are not used: machine = {} is judged by its log decrement, not by API 617 Level I",
            machine.name()
        );
    }
    let request = StabilityRequest {
        sites: sites(rotor, req.at.as_deref())?,
        q_max: req.q_max,
        points: req.points,
        modes: req.modes,
        stages: level_one_stages(rotor, req.stages.filter(|_| !machine.is_hydro())),
        ..StabilityRequest::at(req.rpm / RAD_S_TO_RPM)
    };
    crate::warn_table_speeds(&rotor.model, &[req.rpm / RAD_S_TO_RPM]);
    crate::warn_short_films(rotor, &[req.rpm / RAD_S_TO_RPM]);
    crate::held::note_off_centre(rotor, &[req.rpm / RAD_S_TO_RPM]);
    let result = stability_study(rotor, &request)
        .map_err(|e| format!("{} at {} rpm: {e}", rotor.model.name, req.rpm))?;
    let labels: Vec<String> = result.sites.iter().map(|&n| site_label(rotor, n)).collect();
    let mut out = text::stability(&result, &labels);
    if machine.is_hydro() {
        out.push_str(&text::stability_verdict(&result, machine.name()));
    }
    if let Some(path) = req.csv {
        write_file(&path, &report_csv::stability(&result))?;
    }
    if let Some(path) = req.png {
        let title = format!(
            "Stability of {} at {} rpm: cross-coupling at {}",
            rotor.model.name,
            req.rpm,
            labels.join(", ")
        );
        stability_png(&path, &title, &result).map_err(|e| e.to_string())?;
        eprintln!("wrote {}", path.display());
    }
    print!("{out}");
    print!("{}", text::synchronous_tables(&rotor.model));
    if req.at.is_none() {
        placement_note(rotor, &request, &result)?;
    }
    if machine.is_api() {
        let mcs = req
            .operating
            .map_or(req.rpm.abs() / RAD_S_TO_RPM, |r| r.max);
        // A Level II that cannot be computed is said, not fatal: the
        // study above stands.
        match level_two_text(rotor, &request, mcs) {
            Ok((text, l)) => {
                if let Some(path) = &req.level_two_csv {
                    write_file(path, &report_csv::level_two(&l))?;
                }
                print!("{text}")
            }
            Err(e) => println!("\n{e}: not computed"),
        }
    } else if req.level_two_csv.is_some() {
        eprintln!(
            "note: --level-two-csv is not written: API 617 Level II is run for an API machine (machine = {}), not this one",
            machine.name()
        );
    }
    if req.verify {
        let checks = verify(rotor, result.speed, &result.modes)?;
        print!("{}", text::ring_downs(&checks));
    }
    Ok(())
}

/// An API machine's Level II analysis at its maximum continuous speed
/// `mcs` (rad/s), with the Level I stages' `Q_A` when there are stages: its
/// text and the analysis.
pub fn level_two_text(
    rotor: &Rotor,
    request: &StabilityRequest,
    mcs: f64,
) -> Result<(String, LevelTwo), String> {
    let l = level_two(rotor, mcs, &request.stages, request.modes)
        .map_err(|e| format!("{}: API 617 Level II: {e}", rotor.model.name))?;
    let labels: Vec<String> = l
        .anticipated
        .as_ref()
        .map(|(_, _, c)| c.sites.iter().map(|&n| site_label(rotor, n)).collect())
        .unwrap_or_default();
    Ok((
        format!("\n{}", text::level_two(&l, &labels, &rotor.model)),
        l,
    ))
}

/// The three least-damped oscillating modes rung down in the transient.
fn verify(
    rotor: &Rotor,
    speed: f64,
    modes: &[rotor_bearing::analysis::modal::Mode],
) -> Result<Vec<RingDown>, String> {
    let mut least: Vec<_> = modes.iter().collect();
    least.sort_by(|a, b| a.log_decrement.total_cmp(&b.log_decrement));
    least
        .into_iter()
        .take(VERIFIED_MODES)
        .map(|m| ring_down(rotor, speed, m, VERIFY_PERIODS).map_err(|e| e.to_string()))
        .collect()
}

/// Modes `--verify` rings down, and over how many periods.
const VERIFIED_MODES: usize = 3;
const VERIFY_PERIODS: usize = 12;

/// Where the default cross-coupling acts changed on 2026-12-05 from the
/// disks and seals (the default since 2026-12-01, ff560cb; before, the node
/// nearest mid-span) to API 617's placement. When the two differ, the
/// verdict is followed by the threshold the earlier default gives, so that
/// a published figure can be traced (CHANGELOG.md).
fn placement_note(
    rotor: &Rotor,
    request: &StabilityRequest,
    result: &rotor_bearing::analysis::stability::Stability,
) -> Result<(), String> {
    let earlier_sites = disks_and_seals(rotor);
    if result.placement.is_none() || result.sites == earlier_sites {
        return Ok(());
    }
    let earlier = StabilityRequest {
        sites: earlier_sites.clone(),
        ..request.clone()
    };
    let before = stability_study(rotor, &earlier).map_err(|e| e.to_string())?;
    let threshold = match before.threshold {
        Some(q) => format!("threshold Q = {} N/m", text::short(q)),
        None => format!("stable up to Q = {} N/m", text::short(before.q_max)),
    };
    let labels: Vec<String> = earlier_sites
        .iter()
        .map(|&n| site_label(rotor, n))
        .collect();
    println!(
        "placement: API 617's since 2026-12-05 (CHANGELOG.md); from 2026-12-01 the default was the disks and seals, {}, where the same study gives {threshold}; give --at to choose",
        labels.join(", ")
    );
    Ok(())
}
