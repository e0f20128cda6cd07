//! `rotor report`: one self-contained HTML page with the model and its
//! drawing, the operating point, the unbalance response, the modes and their
//! shapes, the stability check and the critical speed map at one speed.

use std::path::{Path, PathBuf};

use rotor_bearing::analysis::modal::{ModalOptions, modes_at};
use rotor_bearing::analysis::operating_point::{operating_point, pedestal_operating_points};
use rotor_bearing::analysis::stability::{default_cross_coupling_max, mid_span_node, stability};
use rotor_bearing::analysis::ucs::{critical_speed_map, stiffness_grid};
use rotor_bearing::analysis::unbalance::{
    OperatingRange, peaks, response_points, separation_margin, speed_grid, sweep, with_unbalance_at,
};
use rotor_bearing::plot::{
    RAD_S_TO_RPM, mode_shapes_png, rotor_png, stability_png, ucs_png, unbalance_png,
};
use rotor_bearing::report::html::{Section, page};
use rotor_bearing::report::text;
use rotor_bearing::rotor::Rotor;

use crate::write_file;

/// A PNG drawn by `draw` into `dir/name`, read back.
fn figure(
    dir: &Path,
    name: &str,
    draw: impl FnOnce(&Path) -> Result<(), rotor_bearing::plot::PlotError>,
) -> Result<Vec<u8>, String> {
    let path = dir.join(name);
    draw(&path).map_err(|e| e.to_string())?;
    std::fs::read(&path).map_err(|e| format!("{}: {e}", path.display()))
}

fn section(id: &str, title: &str, text: String, images: Vec<(Vec<u8>, String)>) -> Section {
    Section {
        id: id.into(),
        title: title.into(),
        text,
        images,
    }
}

pub fn run(rotor: &Rotor, rpm: f64, out: PathBuf) -> Result<(), String> {
    if !(rpm.is_finite() && rpm > 0.0) {
        return Err(format!("--rpm must be a positive speed, got {rpm}"));
    }
    let speed = rpm / RAD_S_TO_RPM;
    crate::warn_table_speeds(&rotor.model, &[0.0, 2.0 * speed]);
    let name = rotor.model.name.clone();
    let dir = std::env::temp_dir().join(format!("rotor-report-{}", std::process::id()));
    std::fs::create_dir_all(&dir).map_err(|e| format!("{}: {e}", dir.display()))?;
    let err = |e: &dyn std::fmt::Display| format!("{name} at {rpm} rpm: {e}");
    let mut sections = Vec::new();

    let drawing = figure(&dir, "rotor.png", |p| {
        rotor_png(p, &format!("Rotor {name}"), &rotor.model)
    })?;
    sections.push(section(
        "model",
        "Model",
        text::model_summary(rotor),
        vec![(drawing, "rotor drawing".into())],
    ));

    let points = operating_point(rotor, speed).map_err(|e| err(&e))?;
    let pedestals = pedestal_operating_points(rotor, speed).map_err(|e| err(&e))?;
    sections.push(section(
        "operating-point",
        &format!("Operating point at {rpm} rpm"),
        text::operating_point(rpm, &points) + &text::pedestals(rpm, &pedestals),
        Vec::new(),
    ));

    // Unbalance response from 0 to twice the speed, judged against the speed itself.
    let excited;
    let (unbalanced, what) = if rotor.model.unbalances.is_empty() {
        let node = mid_span_node(rotor);
        excited = with_unbalance_at(rotor, node, 1e-3).map_err(|e| err(&e))?;
        (&excited, format!("1e-3 kg·m at node {}", node + 1))
    } else {
        (rotor, "the model's unbalance planes".to_string())
    };
    let mut speeds = speed_grid(0.0, 2.0 * speed, 201).map_err(|e| err(&e))?;
    if !rotor.nonlinear_bearings.is_empty() {
        speeds.remove(0);
    }
    let result = sweep(unbalanced, &speeds, &response_points(unbalanced)).map_err(|e| err(&e))?;
    let range = OperatingRange {
        min: speed,
        max: speed,
    };
    let mut rows = Vec::new();
    for p in 0..result.points.len() {
        for peak in peaks(unbalanced, &result, p).map_err(|e| err(&e))? {
            let margin = peak
                .amplification_factor
                .map(|af| separation_margin(peak.speed, af, &range));
            rows.push((peak, margin));
        }
    }
    let found: Vec<_> = rows.iter().map(|(p, _)| *p).collect();
    let bode = figure(&dir, "unbalance.png", |p| {
        unbalance_png(
            p,
            &format!("Unbalance response: {name} ({what})"),
            &result,
            &found,
            Some((speed, speed)),
        )
    })?;
    sections.push(section(
        "unbalance",
        "Unbalance response",
        format!(
            "response to {what}, 0 … {} rpm; separation margins from {rpm} rpm\n{}",
            2.0 * rpm,
            text::peak_table(&result, &rows)
        ),
        vec![(bode, "Bode and polar plots".into())],
    ));

    let options = ModalOptions {
        modes: 8,
        ..ModalOptions::default()
    };
    let modes = modes_at(rotor, speed, &options).map_err(|e| err(&e))?;
    let shapes = figure(&dir, "shapes.png", |p| {
        mode_shapes_png(
            p,
            &format!("Mode shapes of {name} at {rpm} rpm (red forward, blue backward whirl)"),
            &rotor.model,
            &modes,
        )
    })?;
    sections.push(section(
        "modes",
        "Modes and mode shapes",
        text::modes(&name, rpm, &modes),
        vec![(shapes, "mode shapes".into())],
    ));

    let q_max = default_cross_coupling_max(rotor, speed).map_err(|e| err(&e))?;
    let check = stability(rotor, speed, q_max, 21, 8).map_err(|e| err(&e))?;
    let curve = figure(&dir, "stability.png", |p| {
        stability_png(
            p,
            &format!(
                "Stability of {name} at {rpm} rpm: cross-coupling at node {}",
                check.node + 1
            ),
            &check,
        )
    })?;
    sections.push(section(
        "stability",
        "Stability",
        text::stability(&check, q_max),
        vec![(
            curve,
            "log decrement against cross-coupled stiffness".into(),
        )],
    ));

    let stiffness = stiffness_grid(1e5, 1e10, 31).map_err(|e| err(&e))?;
    let bearing_speeds: Vec<f64> = (1..=20).map(|k| 2.0 * speed * k as f64 / 20.0).collect();
    let map = critical_speed_map(rotor, &stiffness, 4, &bearing_speeds).map_err(|e| err(&e))?;
    let ucs = figure(&dir, "ucs.png", |p| {
        ucs_png(p, &format!("Undamped critical speed map: {name}"), &map)
    })?;
    sections.push(section(
        "ucs",
        "Undamped critical speed map",
        text::critical_speed_map(&name, &map, 3),
        vec![(ucs, "critical speed map".into())],
    ));

    std::fs::remove_dir_all(&dir).ok();
    write_file(
        &out,
        &page(
            &format!("Rotordynamic report: {name} at {rpm} rpm"),
            &sections,
        ),
    )
}
