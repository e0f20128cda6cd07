//! `rotor report`: one self-contained HTML page to sign — the stamp (model
//! file and its SHA-256, software version, date), a first-page summary of
//! every verdict, then the model and its drawing, the Campbell diagram, the
//! unbalance response, the bearings' operating point, the modes and their
//! shapes, the stability screening and the critical speed map. Every section
//! runs the library study its single command runs, with that command's
//! defaults; a study that fails is reported in its section and the summary,
//! and the page is still written.

use std::path::{Path, PathBuf};

use rotor_bearing::analysis::alignment::alignment;
use rotor_bearing::analysis::api_unbalance::{ApiRequest, api_unbalance};
use rotor_bearing::analysis::campbell::{CampbellRequest, campbell_study};
use rotor_bearing::analysis::element_operating_point::thrust_operating_points;
use rotor_bearing::analysis::housing_vibration;
use rotor_bearing::analysis::level_two::level_two;
use rotor_bearing::analysis::modal::ModalOptions;
use rotor_bearing::analysis::operating_point::{operating_point, pedestal_operating_points};
use rotor_bearing::analysis::shaft_loads::coupling_loads;
use rotor_bearing::analysis::shaft_orbits::{self, CaseOrbits};
use rotor_bearing::analysis::speed_range::default_top_speed;
use rotor_bearing::analysis::stability::{
    StabilityRequest, StageData, level_one_stages, mid_span_node, site_label, stability_study,
};
use rotor_bearing::analysis::tolerance_cases::tolerance_cases;
use rotor_bearing::analysis::ucs::{
    DEFAULT_BEARING_SPEEDS, DEFAULT_CRITICALS, DEFAULT_POINTS as UCS_POINTS,
    DEFAULT_STIFFNESS_RANGE, bearing_speeds, critical_speed_map, stiffness_grid,
};
use rotor_bearing::analysis::unbalance::{
    DEFAULT_POINTS, OperatingRange, UnbalanceRequest, unbalance_study, with_unbalance_at,
};
use rotor_bearing::analysis::whirl_modes::modal_analysis_own;
use rotor_bearing::model::DEFAULT_MODEL_TOML;
use rotor_bearing::model::shaft_zones::ShaftZones;
use rotor_bearing::plot::{
    OrbitPanel, PlotError, RAD_S_TO_RPM, campbell_png, mode_shapes_png, orbits_png, rotor_png,
    stability_png, ucs_png, unbalance_png,
};
use rotor_bearing::report::api as api_report;
use rotor_bearing::report::cases as cases_report;
use rotor_bearing::report::html::{Block, Section, Verdict, page};
use rotor_bearing::report::hydro::{self, HousingStudy};
use rotor_bearing::report::level_two::{level_two_blocks, level_two_summary_rows};
use rotor_bearing::report::orbits::{orbit_blocks, orbit_summary_row};
use rotor_bearing::report::review;
use rotor_bearing::report::review_summary::{self, SummaryInputs};
use rotor_bearing::report::stamp::{now_utc, sha256_hex, software_version};
use rotor_bearing::report::text::short;
use rotor_bearing::report::{hydro_loads, hydro_torsion};
use rotor_bearing::rotor::Rotor;
use rotor_bearing::solver::SolverOptions;
use rotor_bearing::units::Amplitude;

use crate::write_file;

/// What `rotor report` was asked for.
pub struct Request {
    /// The model file (`None`: the built-in classic rotor).
    pub source: Option<PathBuf>,
    pub rpm: Option<f64>,
    /// The operating range of the margins (`--operating-rpm`) and its text;
    /// `None`: the operating speed alone.
    pub operating: Option<OperatingRange>,
    pub operating_rpm: Option<String>,
    pub amplitude: Amplitude,
    /// Nodes of the cross-coupling (0-based), empty for the default.
    pub sites: Vec<usize>,
    pub stages: Option<StageData>,
    pub out: PathBuf,
}

/// A PNG drawn by `draw` into `dir/name`, read back.
fn figure(
    dir: &Path,
    name: &str,
    draw: impl FnOnce(&Path) -> Result<(), PlotError>,
) -> Result<Vec<u8>, String> {
    let path = dir.join(name);
    draw(&path).map_err(|e| e.to_string())?;
    std::fs::read(&path).map_err(|e| format!("{}: {e}", path.display()))
}

/// The figure, or the reason it could not be drawn.
fn figure_block(result: Result<Vec<u8>, String>, caption: &str) -> Block {
    match result {
        Ok(png) => Block::Figure(png, caption.to_string()),
        Err(e) => Block::Failure(format!("{caption}: {e}")),
    }
}

fn section(id: &str, title: &str, blocks: Vec<Block>) -> Section {
    Section {
        id: id.into(),
        title: title.into(),
        blocks,
    }
}

pub fn run(rotor: &Rotor, req: Request) -> Result<(), String> {
    let model = &rotor.model;
    let rpm = match req.rpm {
        Some(r) => r,
        None if model.nominal_speed != 0.0 => model.nominal_speed.abs() * RAD_S_TO_RPM,
        None => {
            return Err(format!(
                "{}: the model states no speed_rpm: give --rpm",
                model.source
            ));
        }
    };
    if !(rpm.is_finite() && rpm > 0.0) {
        return Err(format!("--rpm must be a positive speed, got {rpm}"));
    }
    let speed = rpm / RAD_S_TO_RPM;
    let name = model.name.clone();
    crate::warn_short_films(rotor, &[speed]);
    crate::held::note_off_centre(rotor, &[speed]);
    // `--operating-rpm`, else the model's `operating_rpm`, else the speed.
    let stated = req.operating.or(rotor
        .model
        .operating_range
        .map(|[min, max]| OperatingRange { min, max }));
    let operating = stated.unwrap_or(OperatingRange {
        min: speed,
        max: speed,
    });
    let amplitude = req.amplitude;
    let dir = std::env::temp_dir().join(format!("rotor-report-{}", std::process::id()));
    std::fs::create_dir_all(&dir).map_err(|e| format!("{}: {e}", dir.display()))?;
    let err = |e: &dyn std::fmt::Display| e.to_string();

    // The stamp: what was judged, by what, when.
    let (file, bytes) = match &req.source {
        Some(p) => (
            p.display().to_string(),
            std::fs::read(p).map_err(|e| format!("{}: {e}", p.display()))?,
        ),
        None => (
            "built-in classic_disk_rotor.toml".to_string(),
            DEFAULT_MODEL_TOML.as_bytes().to_vec(),
        ),
    };
    let args: Vec<String> = std::env::args().skip(1).collect();
    let stamp = vec![
        ("model file".to_string(), file),
        ("model SHA-256".to_string(), sha256_hex(&bytes)),
        (
            "model".to_string(),
            format!("{name}: {}", model.description),
        ),
        ("operating speed".to_string(), format!("{} rpm", short(rpm))),
        (
            "operating range (separation margins)".to_string(),
            format!(
                "{} to {} rpm",
                short(operating.min * RAD_S_TO_RPM),
                short(operating.max * RAD_S_TO_RPM)
            ),
        ),
        (
            "software".to_string(),
            format!("rotor_bearing {}", software_version()),
        ),
        ("date".to_string(), now_utc()),
        ("command".to_string(), format!("rotor {}", args.join(" "))),
    ];

    // The studies, each with its command's defaults.
    let campbell =
        campbell_study(rotor, &CampbellRequest::default_for(Some(operating))).map_err(|e| err(&e));
    let excited;
    let (unbalanced, what) = if model.unbalances.is_empty() {
        let node = mid_span_node(rotor);
        excited = with_unbalance_at(rotor, node, 1e-3).map_err(|e| err(&e))?;
        (
            &excited,
            format!(
                "1e-3 kg·m at node {} (the model has no unbalance planes)",
                node + 1
            ),
        )
    } else {
        (rotor, "the model's unbalance planes".to_string())
    };
    let unbalance = unbalance_study(
        unbalanced,
        &UnbalanceRequest {
            min: 0.0,
            max: None,
            points: DEFAULT_POINTS,
            operating: Some(operating),
        },
    )
    .map_err(|e| err(&e));
    let points = operating_point(rotor, speed).map_err(|e| err(&e));
    let options = ModalOptions {
        modes: 8,
        ..ModalOptions::default()
    };
    let modes = modal_analysis_own(rotor, speed, &options).map_err(|e| err(&e));
    let stability = stability_study(
        rotor,
        &StabilityRequest {
            sites: req.sites.clone(),
            stages: level_one_stages(rotor, req.stages),
            ..StabilityRequest::at(speed)
        },
    )
    .map_err(|e| err(&e));
    let (top, _) = default_top_speed(model, Some(&operating));
    let ucs = stiffness_grid(
        DEFAULT_STIFFNESS_RANGE.0,
        DEFAULT_STIFFNESS_RANGE.1,
        UCS_POINTS,
    )
    .map_err(|e| err(&e))
    .and_then(|k| {
        critical_speed_map(
            rotor,
            &k,
            DEFAULT_CRITICALS,
            &bearing_speeds(top, DEFAULT_BEARING_SPEEDS),
        )
        .map_err(|e| err(&e))
    });

    // A hydro unit's housings, from the transient at the operating speed.
    let housing = model.machine.is_hydro().then(|| {
        let (settle, record) = housing_vibration::report_spans(rotor, speed);
        housing_vibration::housing_vibration(rotor, speed, settle, record).map_err(|e| err(&e))
    });

    // A hydro unit's shaft orbits: operating speed, field on, runaway.
    let orbits = model.machine.is_hydro().then(|| {
        shaft_orbits::report_orbits(rotor, &shaft_orbits::hydro_cases(rotor, speed))
            .map_err(|e| err(&e))
    });

    // A hydro unit's torsional modes against the running and grid frequencies.
    let torsion = model
        .machine
        .is_hydro()
        .then(|| hydro_torsion::torsion_study(model, speed));

    // An API machine's unbalance cases, on the unbalance study's speeds.
    let api = model.machine.is_api().then(|| {
        let max = match &unbalance {
            Ok(study) => study.sweep.speeds.last().copied().unwrap_or(top),
            Err(_) => top,
        };
        let request = ApiRequest {
            operating,
            max,
            points: DEFAULT_POINTS,
        };
        api_unbalance(rotor, &request).map_err(|e| err(&e))
    });

    // An API machine's Level II at the maximum continuous speed.
    let level_two = model.machine.is_api().then(|| {
        level_two(
            rotor,
            operating.max,
            &level_one_stages(rotor, req.stages),
            StabilityRequest::at(speed).modes,
        )
        .map_err(|e| err(&e))
    });

    // The tolerance cases of a model with a [cases] section.
    let cases = model
        .tolerance_cases
        .is_some()
        .then(|| tolerance_cases(rotor, speed, operating).map_err(|e| err(&e)));

    let mut summary = review_summary::summary(&SummaryInputs {
        campbell: campbell.as_ref().map_err(Clone::clone),
        unbalance: unbalance.as_ref().map_err(Clone::clone),
        stability: stability.as_ref().map_err(Clone::clone),
        operating: points.as_deref().map_err(Clone::clone),
        amplitude,
        machine: model.machine,
        runaway: model.max_speed,
        housing: housing.as_ref().map(|h| housing_study(model, h)),
        api: api.as_ref().map(|a| a.as_ref().map_err(Clone::clone)),
    });
    if let Some(l) = &level_two {
        // After the stability rows of the summary.
        let at = summary
            .rows
            .iter()
            .rposition(|r| r.first().is_some_and(|c| c.text.starts_with("stability")))
            .map_or(summary.rows.len(), |k| k + 1);
        let rows = level_two_summary_rows(&l.as_ref().map_err(Clone::clone));
        summary.rows.splice(at..at, rows);
    }
    if let Some(o) = &orbits {
        summary.rows.push(orbit_summary_row(
            &o.as_deref().map_err(Clone::clone),
            model.shaft_zones.as_ref(),
        ));
    }
    if let Some(t) = &torsion {
        summary.rows.extend(hydro_torsion::torsion_rows(t));
    }
    if let Some(c) = &cases {
        summary.rows.extend(cases_report::summary_rows(
            &c.as_ref().map_err(Clone::clone),
        ));
    }
    let overall = review_summary::overall(&summary);
    let file_arg = req
        .source
        .as_ref()
        .map_or(String::new(), |p| format!(" {}", p.display()));
    let range = match (&req.operating_rpm, stated) {
        (Some(text), _) => text.clone(),
        (None, Some(r)) => format!("{}:{}", r.min * RAD_S_TO_RPM, r.max * RAD_S_TO_RPM),
        (None, None) => format!("{rpm}:{rpm}"),
    };
    let same = |cmd: &str| format!("As `rotor {cmd}{file_arg} --operating-rpm {range}` prints it.");
    let mut sections = vec![section(
        "summary",
        "Summary",
        vec![
            Block::Text(format!(
                "Overall: {} — {} at {} rpm.",
                match overall {
                    Verdict::Pass => "every check passes",
                    Verdict::Fail => "at least one check FAILS",
                    Verdict::NotJudged => "no check fails; some are not judged",
                },
                name,
                short(rpm)
            )),
            Block::Table(summary),
        ],
    )];

    let mut blocks = review::model_blocks(rotor);
    blocks.push(figure_block(
        figure(&dir, "rotor.png", |p| {
            rotor_png(p, &format!("Rotor {name}"), model)
        }),
        "rotor drawing",
    ));
    sections.push(section("model", "Model", blocks));

    let blocks = match &campbell {
        Ok(study) => {
            let mut b = vec![Block::Text(same("campbell"))];
            b.push(figure_block(
                figure(&dir, "campbell.png", |p| {
                    campbell_png(p, &format!("Campbell diagram: {name}"), study)
                }),
                "Campbell diagram",
            ));
            b.extend(review::campbell_blocks(rotor, study));
            b
        }
        Err(e) => vec![Block::Failure(format!("Campbell diagram: {e}"))],
    };
    sections.push(section(
        "campbell",
        "Campbell diagram and critical speeds",
        blocks,
    ));

    let blocks = match &unbalance {
        Ok(study) => {
            let mut b = vec![Block::Text(format!(
                "Response to {what}. {}",
                same("unbalance")
            ))];
            b.push(figure_block(
                figure(&dir, "unbalance.png", |p| {
                    unbalance_png(
                        p,
                        &format!("Unbalance response: {name} ({what})"),
                        study,
                        amplitude,
                    )
                }),
                "Bode and polar plots",
            ));
            b.extend(review::unbalance_blocks(study, amplitude));
            b
        }
        Err(e) => vec![Block::Failure(format!("unbalance response: {e}"))],
    };
    let blocks = match &api {
        None => blocks,
        Some(Ok(a)) => blocks
            .into_iter()
            .chain(api_report::api_blocks(a))
            .collect(),
        Some(Err(e)) => blocks
            .into_iter()
            .chain([Block::Failure(format!("API unbalance cases: {e}"))])
            .collect(),
    };
    sections.push(section("unbalance", "Unbalance response", blocks));

    let mut blocks = match &points {
        Ok(p) => review::operating_blocks(p),
        Err(e) => vec![Block::Failure(format!("operating point: {e}"))],
    };
    let pedestal_points =
        (!model.pedestals.is_empty()).then(|| pedestal_operating_points(rotor, speed));
    if let Some(p) = &pedestal_points {
        blocks.push(match p {
            Ok(p) => Block::Text(rotor_bearing::report::text::pedestals(rpm, p)),
            Err(e) => Block::Failure(format!("pedestals: {e}")),
        });
    }
    sections.push(section(
        "operating-point",
        &format!("Bearings at {} rpm", short(rpm)),
        blocks,
    ));
    if model.machine.is_hydro() {
        let thrusts = thrust_operating_points(rotor, speed);
        let losses = points
            .as_deref()
            .map(|p| hydro_loads::power_losses(model, p, &thrusts))
            .map_err(Clone::clone);
        sections.push(section(
            "thrust-bearings",
            &format!("Thrust bearings and power losses at {} rpm", short(rpm)),
            hydro_loads::thrust_blocks(model, speed, &thrusts, &losses),
        ));
        if let Some(p) = &pedestal_points {
            let blocks = match (&points, p) {
                (Ok(guides), Ok(p)) => {
                    hydro_loads::bracket_blocks(rpm, &hydro_loads::bracket_loads(model, guides, p))
                }
                (Err(e), _) => vec![Block::Failure(format!("brackets: {e}"))],
                (_, Err(e)) => vec![Block::Failure(format!("brackets: {e}"))],
            };
            sections.push(section(
                "brackets",
                &format!("Brackets at {} rpm", short(rpm)),
                blocks,
            ));
        }
    }
    if let Some(h) = &housing {
        let blocks = match h {
            Ok(_) => hydro::housing_blocks(&housing_study(model, h)),
            Err(e) => vec![Block::Failure(format!("housing vibration: {e}"))],
        };
        sections.push(section(
            "housing-vibration",
            "Bearing-housing vibration (ISO 10816-5)",
            blocks,
        ));
    }
    if let Some(o) = &orbits {
        sections.push(section(
            "shaft-orbits",
            "Shaft orbits: operating speed, field on, runaway",
            orbit_section(o, model.shaft_zones.as_ref(), &dir),
        ));
    }

    // A line set off its axis or a train: its alignment.
    if model.bearings.iter().any(|b| b.is_offset()) || !model.couplings.is_empty() {
        let options = SolverOptions::default();
        let blocks = match alignment(rotor, speed, &options) {
            Ok(line) => {
                let all = rotor.dofs.expand(&line.equilibrium.displacement);
                let couplings = coupling_loads(rotor, &all, options.gravity);
                let mut b = vec![Block::Text(format!(
                    "As `rotor alignment{file_arg} --rpm {rpm}` prints it."
                ))];
                b.extend(review::alignment_blocks(&line, &couplings));
                b
            }
            Err(e) => vec![Block::Failure(format!("alignment: {e}"))],
        };
        sections.push(section(
            "alignment",
            &format!("Alignment at {} rpm", short(rpm)),
            blocks,
        ));
    }

    let blocks = match &modes {
        Ok(m) => {
            let mut b = review::modes_blocks(m);
            b.push(figure_block(
                figure(&dir, "shapes.png", |p| {
                    mode_shapes_png(
                        p,
                        &format!(
                            "Mode shapes of {name} at {} rpm (red forward, blue backward whirl)",
                            short(rpm)
                        ),
                        model,
                        &m.modes,
                    )
                }),
                "mode shapes",
            ));
            b
        }
        Err(e) => vec![Block::Failure(format!("modes: {e}"))],
    };
    sections.push(section("modes", "Modes and mode shapes", blocks));
    if let Some(t) = &torsion {
        let blocks = match t {
            Ok(study) => hydro_torsion::torsion_blocks(study),
            Err(e) => vec![Block::Failure(format!("torsional modes: {e}"))],
        };
        sections.push(section("torsional-modes", "Torsional modes", blocks));
    }

    let blocks = match &stability {
        Ok(s) => {
            let labels: Vec<String> = s.sites.iter().map(|&n| site_label(rotor, n)).collect();
            let mut b = review::stability_blocks(s, &labels);
            let tables = rotor_bearing::report::text::synchronous_tables(&rotor.model);
            if !tables.is_empty() {
                b.push(Block::Text(tables.trim_end().to_string()));
            }
            b.push(figure_block(
                figure(&dir, "stability.png", |p| {
                    stability_png(
                        p,
                        &format!(
                            "Stability of {name} at {} rpm: cross-coupling at {}",
                            short(rpm),
                            labels.join(", ")
                        ),
                        s,
                    )
                }),
                "log decrement against cross-coupled stiffness",
            ));
            b
        }
        Err(e) => vec![Block::Failure(format!("stability: {e}"))],
    };
    let mut blocks = blocks;
    match &level_two {
        Some(Ok(l)) => {
            let sites: Vec<String> = l
                .anticipated
                .as_ref()
                .map(|(_, _, c)| c.sites.iter().map(|&n| site_label(rotor, n)).collect())
                .unwrap_or_default();
            blocks.extend(level_two_blocks(l, &sites, model));
        }
        Some(Err(e)) => blocks.push(Block::Failure(format!("API 617 Level II: {e}"))),
        None => {}
    }
    sections.push(section("stability", "Stability", blocks));

    let blocks = match &ucs {
        Ok(map) => {
            let mut b = vec![figure_block(
                figure(&dir, "ucs.png", |p| {
                    ucs_png(p, &format!("Undamped critical speed map: {name}"), map)
                }),
                "critical speed map",
            )];
            b.extend(review::ucs_blocks(map));
            b
        }
        Err(e) => vec![Block::Failure(format!("critical speed map: {e}"))],
    };
    sections.push(section("ucs", "Undamped critical speed map", blocks));

    if let Some(c) = &cases {
        let blocks = match c {
            Ok(study) => {
                let mut b = vec![Block::Text(same("cases"))];
                b.extend(cases_report::cases_blocks(&name, study));
                b
            }
            Err(e) => vec![Block::Failure(format!("tolerance cases: {e}"))],
        };
        sections.push(section("cases", "Tolerance cases", blocks));
    }

    std::fs::remove_dir_all(&dir).ok();
    write_file(
        &req.out,
        &page(
            &format!("Rotordynamic design review: {name} at {} rpm", short(rpm)),
            &stamp,
            &sections,
        ),
    )
}

/// The housing study of the report from the model's group and the vibration.
fn housing_study<'a>(
    model: &rotor_bearing::model::RotorModel,
    vibration: &'a Result<Vec<housing_vibration::HousingVibration>, String>,
) -> HousingStudy<'a> {
    HousingStudy {
        group: model.housing_group,
        vibration: vibration.as_deref().map_err(Clone::clone),
    }
}

/// A hydro unit's shaft orbits in its cases: the table, and one figure of
/// each case's orbits in their clearance circles.
fn orbit_section(
    orbits: &Result<Vec<CaseOrbits>, String>,
    zones: Option<&ShaftZones>,
    dir: &Path,
) -> Vec<Block> {
    let orbits = match orbits {
        Ok(o) => o,
        Err(e) => return vec![Block::Failure(format!("shaft orbits: {e}"))],
    };
    let mut blocks = orbit_blocks(orbits, zones);
    for (k, c) in orbits.iter().enumerate() {
        let panels: Vec<OrbitPanel> = c
            .bearings
            .iter()
            .map(|b| OrbitPanel {
                name: format!("bearing {}", b.name),
                x: b.x.clone(),
                y: b.y.clone(),
                clearance: b.clearance,
            })
            .collect();
        let caption = format!("shaft orbits relative to the housings: {}", c.case.label);
        let png = figure(dir, &format!("orbits_{k}.png"), |p| {
            orbits_png(p, &caption, &panels, &c.spin_angle, c.case.speed)
        });
        blocks.push(figure_block(png, &caption));
    }
    blocks
}
