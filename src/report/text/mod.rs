//! Plain-text summaries of a model and its results for people: engineering
//! units, no float noise, no debug structures. The modal and Campbell tables
//! are in [`modal`], the unbalance response in [`unbalance`].

use std::fmt::Write;

use crate::analysis::operating_point::{
    BearingOperatingPoint, PedestalOperatingPoint, ROUND_OFF_LOAD,
};
use crate::analysis::stability::{
    LEVEL_I_MIN_LOG_DEC, LEVEL_I_MIN_RATIO, MACHINE_STAGE, Stability, StageData,
};
use crate::analysis::ucs::CriticalSpeedMap;
use crate::bearing::{BearingKind, CoefficientTable};
use crate::model::RotorModel;
use crate::solver::Outputs;
use crate::units::RAD_S_TO_RPM;

mod api_unbalance;
mod cases;
mod element_points;
mod hydro_verdicts;
mod level_two;
mod modal;
mod ring_down;
mod summary;
mod synchronous;
mod unbalance;

pub use api_unbalance::{
    api_critical_cells, api_unbalance, api_verdict, case_planes, worst_clearance,
};
pub use cases::{case_value, cases_heading, governing_cells, tolerance_cases};
pub use element_points::element_points;
pub use hydro_verdicts::{log_dec_holds, stability_verdict, unbalance_runaway};
pub use level_two::{level_two, level_two_elements, level_two_finding, level_two_verdict};
pub use modal::{
    ROUND_OFF_DAMPING_RATIO, campbell_study, critical_margins, damping_ratio, margin_cells, modes,
    overdamped_roots, overdamped_summary, static_divergence, torsional_modes, zeta_and_log_dec,
};
pub use ring_down::{RING_DOWN_AGREEMENT, ring_downs};
pub use summary::{
    describe_force, describe_pedestal, describe_thrust_bearing, element_kind, model_summary,
};
pub use synchronous::synchronous_tables;
pub use unbalance::{peak_cells, peak_table, unbalance_heading, unbalance_study};

/// A number without float noise: at most 6 significant digits, no trailing zeros.
pub fn short(x: f64) -> String {
    if x == 0.0 {
        return "0".into();
    }
    let value: f64 = format!("{x:.5e}").parse().unwrap_or(x);
    if (1e-4..1e7).contains(&value.abs()) {
        format!("{value}")
    } else {
        format!("{value:e}")
    }
}

/// A bearing's type and parameters in engineering units.
pub fn describe_bearing(kind: &BearingKind) -> String {
    match kind {
        BearingKind::Linear {
            stiffness: k,
            damping: c,
        } => format!(
            "linear, K = [[{}, {}], [{}, {}]] N/m, C = [[{}, {}], [{}, {}]] N·s/m",
            short(k[0][0]),
            short(k[0][1]),
            short(k[1][0]),
            short(k[1][1]),
            short(c[0][0]),
            short(c[0][1]),
            short(c[1][0]),
            short(c[1][1])
        ),
        BearingKind::Plain(b) => format!(
            "plain short bearing, R = {} mm, L = {} mm, radial clearance C = {} µm, μ = {} Pa·s",
            short(b.radius * 1e3),
            short(b.length * 1e3),
            short(b.clearance * 1e6),
            short(b.viscosity)
        ),
        BearingKind::TiltingPad(b) => {
            let pads: Vec<String> = b
                .pads
                .iter()
                .map(|p| short(p.pivot().to_degrees()))
                .collect();
            let first = &b.pads[0];
            format!(
                "tilting pad, {} pads (pivots at {}°, arc {}°, offset {}, preload {}), R = {} mm, L = {} mm, pad clearance C = {} µm, μ = {} Pa·s",
                b.pads.len(),
                pads.join(", "),
                short(first.arc().to_degrees()),
                short(first.offset()),
                short(first.preload()),
                short(b.radius * 1e3),
                short(b.length * 1e3),
                short(b.clearance * 1e6),
                short(b.viscosity)
            ) + &pad_support(&b.support)
        }
        BearingKind::Rub(r) => format!(
            "rub element, radial gap {} µm, rotor radius {} mm, contact stiffness {} N/m, damping {} N·s/m, friction μ = {}",
            short(r.contact.gap * 1e6),
            short(r.contact.radius * 1e3),
            short(r.contact.stiffness),
            short(r.contact.damping),
            short(r.contact.friction)
        ),
        BearingKind::Table(t) => format!(
            "coefficient table over speed, {}",
            describe_table(&t.table, t.added_mass)
        ),
        BearingKind::Seal(s) => {
            let contact = match &s.contact {
                None => "never touches".to_string(),
                Some(c) => format!(
                    "touches its stator at a radial clearance of {} µm (contact stiffness {} N/m, friction μ = {})",
                    short(c.gap * 1e6),
                    short(c.stiffness),
                    short(c.friction)
                ),
            };
            format!(
                "seal, {}; {contact}",
                describe_table(&s.table, s.added_mass)
            )
        }
        BearingKind::MagneticPull(m) => {
            let rotating = if m.dynamic_eccentricity > 0.0 {
                format!(
                    "; dynamic eccentricity {} mm at {}° (1× pull {} N at nominal field)",
                    short(m.dynamic_eccentricity * 1e3),
                    short(m.dynamic_phase.to_degrees()),
                    short(m.stiffness * m.dynamic_eccentricity)
                )
            } else {
                String::new()
            };
            format!(
                "unbalanced magnetic pull, k = {} N/m at nominal field (excitation {}), radial air gap {} mm, law k e/(1 − ε²)^1.5{rotating}; stator contact stiffness {} N/m",
                short(m.stiffness),
                short(m.excitation),
                short(m.gap * 1e3),
                short(m.contact.stiffness)
            )
        }
        BearingKind::FiniteFilm(f) => format!(
            "{}; finite-length film ({} cavitation, mesh {} × {})",
            describe_bearing(&f.short_kind()).replacen("plain short bearing", "plain bearing", 1),
            f.cavitation.name(),
            f.mesh.circumferential,
            f.mesh.axial
        ),
    }
}

/// A coefficient table in one line: its speed range and rows, and the
/// coefficients at both ends (or the constant ones).
fn describe_table(table: &CoefficientTable, mass: [[f64; 2]; 2]) -> String {
    let (lo, hi) = table.range();
    let at = |speed: f64| {
        let (k, c) = table.at(speed);
        format!(
            "K = [[{}, {}], [{}, {}]] N/m, C = [[{}, {}], [{}, {}]] N·s/m",
            short(k[0][0]),
            short(k[0][1]),
            short(k[1][0]),
            short(k[1][1]),
            short(c[0][0]),
            short(c[0][1]),
            short(c[1][0]),
            short(c[1][1])
        )
    };
    let rows = table.speeds.len();
    let mut s = if rows == 1 {
        format!("constant: {}", at(lo))
    } else {
        format!(
            "{rows} speeds from {} to {} rpm: at {} rpm {}; at {} rpm {}",
            short(lo * RAD_S_TO_RPM),
            short(hi * RAD_S_TO_RPM),
            short(lo * RAD_S_TO_RPM),
            at(lo),
            short(hi * RAD_S_TO_RPM),
            at(hi)
        )
    };
    if mass.iter().flatten().any(|&m| m != 0.0) {
        s.push_str(&format!(
            ", added mass [[{}, {}], [{}, {}]] kg",
            short(mass[0][0]),
            short(mass[0][1]),
            short(mass[1][0]),
            short(mass[1][1])
        ));
    }
    s
}

/// Fraction of a coefficient matrix's largest entry below which an entry is
/// the equilibrium's round-off (it is solved to 1e-8): printed as 0.
pub const ROUND_OFF_COEFFICIENT: f64 = 1e-7;

/// A 2×2 matrix in one line: `[[a, b], [c, d]]`, six significant digits,
/// entries below [`ROUND_OFF_COEFFICIENT`] of the largest as 0.
pub fn coefficient_matrix(m: &[[f64; 2]; 2]) -> String {
    let largest = m.iter().flatten().fold(0.0f64, |a, v| a.max(v.abs()));
    let cell = |v: f64| {
        if v.abs() <= ROUND_OFF_COEFFICIENT * largest {
            "0".to_string()
        } else {
            short(v)
        }
    };
    format!(
        "[[{}, {}], [{}, {}]]",
        cell(m[0][0]),
        cell(m[0][1]),
        cell(m[1][0]),
        cell(m[1][1])
    )
}

/// What `rotor operating-point` prints per bearing: load, journal position,
/// eccentricity, attitude angle, minimum film thickness (µm), friction torque
/// and power loss, K and C, and each pad's tilt and film thickness.
pub fn operating_point(rpm: f64, points: &[BearingOperatingPoint]) -> String {
    let mut s = String::new();
    for p in points {
        writeln!(s, "bearing {} at {} rpm:", p.name, short(rpm)).ok();
        if p.is_unloaded() {
            // Round-off: the journal is centred, the load line undefined.
            let centred = p
                .film
                .as_ref()
                .is_some_and(|f| f.eccentricity <= ROUND_OFF_LOAD);
            let (x, y) = if centred {
                ("0".into(), "0".into())
            } else {
                (short(p.journal[0] * 1e6), short(p.journal[1] * 1e6))
            };
            writeln!(
                s,
                "  static load 0 N (unloaded), journal at x = {x} µm, y = {y} µm"
            )
            .ok();
        } else {
            writeln!(
                s,
                "  static load {} N (Fx = {} N, Fy = {} N), journal at x = {} µm, y = {} µm",
                short(p.load),
                short(p.force[0]),
                short(p.force[1]),
                short(p.journal[0] * 1e6),
                short(p.journal[1] * 1e6)
            )
            .ok();
        }
        if let Some(h) = &p.housing {
            writeln!(
                s,
                "  journal relative to its housing on pedestal {}, which is at x = {} µm, y = {} µm",
                h.name,
                short(h.displacement[0] * 1e6),
                short(h.displacement[1] * 1e6)
            )
            .ok();
        }
        if let Some(f) = p.film.as_ref().filter(|f| !f.has_geometry()) {
            writeln!(
                s,
                "  coefficient table: no film geometry, so no eccentricity or film thickness; friction torque {} N·m, power loss {} W",
                short(f.friction_torque),
                short(f.power_loss)
            )
            .ok();
        } else if let Some(f) = &p.film {
            let (eccentricity, attitude) = if p.is_unloaded() {
                let e = if f.eccentricity <= ROUND_OFF_LOAD {
                    "0".to_string()
                } else {
                    short(f.eccentricity)
                };
                (e, "—".to_string())
            } else {
                (
                    short(f.eccentricity),
                    format!("{}°", short(f.attitude_angle.to_degrees())),
                )
            };
            // A tilting pad's ratio is over the assembled (bearing) clearance.
            let eccentricity = match f.eccentricity_over_pad_clearance() {
                Some(over_pad) => format!(
                    "e/C_b (bearing clearance) {eccentricity}, e/C_p (pad clearance) {}",
                    if eccentricity == "0" {
                        "0".to_string()
                    } else {
                        short(over_pad)
                    }
                ),
                None => format!("ratio {eccentricity}"),
            };
            writeln!(
                s,
                "  eccentricity {eccentricity}, attitude angle {attitude}, minimum film thickness {} µm",
                short(f.min_film_thickness * 1e6)
            )
            .ok();
            writeln!(
                s,
                "  friction torque {} N·m, power loss {} W",
                short(f.friction_torque),
                short(f.power_loss)
            )
            .ok();
            if f.contact_force > 0.0 {
                writeln!(
                    s,
                    "  in contact: normal force {} N (the film does not lift the journal)",
                    short(f.contact_force)
                )
                .ok();
            }
        }
        writeln!(s, "  K = {} N/m", coefficient_matrix(&p.stiffness)).ok();
        writeln!(s, "  C = {} N·s/m", coefficient_matrix(&p.damping)).ok();
        for (k, pad) in p.film.iter().flat_map(|f| f.pads.iter()).enumerate() {
            writeln!(
                s,
                "  pad {} (pivot {}°): tilt {} µm ({} mrad), {}minimum film thickness {} µm",
                k + 1,
                short(pad.pivot.to_degrees()),
                short(pad.tilt * 1e6),
                short(pad.tilt_angle * 1e3),
                pad.radial
                    .map(|xi| format!("radial displacement {} µm, ", short(xi * 1e6)))
                    .unwrap_or_default(),
                short(pad.min_film_thickness * 1e6)
            )
            .ok();
        }
    }
    s
}

/// The pedestals at the operating point: deflection (µm) and the load each
/// passes on to its support (N).
pub fn pedestals(rpm: f64, points: &[PedestalOperatingPoint]) -> String {
    let mut s = String::new();
    for p in points {
        writeln!(
            s,
            "pedestal {} at {} rpm: deflection x = {} µm, y = {} µm; load on its support {} N (Fx = {} N, Fy = {} N)",
            p.name,
            short(rpm),
            short(p.deflection[0] * 1e6),
            short(p.deflection[1] * 1e6),
            short(p.load[0].hypot(p.load[1])),
            short(p.load[0]),
            short(p.load[1])
        )
        .ok();
    }
    s
}

/// What `rotor stability` prints: the modes at the speed (frequency, damping
/// ratio, logarithmic decrement, whirl), where the cross-coupling acts, the
/// threshold `Q` of the least stable forward mode and, with stage data, the
/// Level I screening with its formula and verdict. `sites` names the nodes
/// (e.g. "node 6 (disk impeller)").
pub fn stability(result: &Stability, sites: &[String]) -> String {
    let mut s = format!(
        "modes at {} rpm (no added cross-coupling):\n mode  f_d (Hz)   damping ratio   log dec     whirl\n",
        short(result.speed * RAD_S_TO_RPM)
    );
    for (k, m) in result.modes.iter().enumerate() {
        let (zeta, delta) = if m.damping_ratio.abs() < ROUND_OFF_DAMPING_RATIO {
            ("0".to_string(), "0".to_string())
        } else {
            (
                format!("{:.6}", m.damping_ratio),
                format!("{:.6}", m.log_decrement),
            )
        };
        writeln!(
            s,
            "{:5} {:9.4} {:>15} {:>9} {:>9}",
            k + 1,
            m.damped_frequency / (2.0 * std::f64::consts::PI),
            zeta,
            delta,
            m.whirl.label()
        )
        .ok();
    }
    let why = result
        .placement
        .as_ref()
        .map(|p| format!(" ({p})"))
        .unwrap_or_default();
    if sites.len() == 1 {
        writeln!(
            s,
            "cross-coupled stiffness [[0, Q], [-Q, 0]] at {}{why}",
            sites[0]
        )
        .ok();
    } else {
        writeln!(
            s,
            "cross-coupled stiffness [[0, Q], [-Q, 0]] split equally over {}{why}",
            sites.join(", ")
        )
        .ok();
    }
    if !result.diverging.is_empty() {
        let growing: Vec<&crate::analysis::modal::OverdampedRoot> =
            result.diverging.iter().collect();
        s.push_str(&static_divergence(&growing));
        writeln!(
            s,
            "unstable without cross-coupling: the rotor is statically unstable at {} rpm (threshold Q = 0)",
            short(result.speed.abs() * RAD_S_TO_RPM)
        )
        .ok();
    }
    match (result.threshold, &result.threshold_mode) {
        _ if !result.diverging.is_empty() => {}
        (Some(0.0), Some(m)) if m.is_undamped() => {
            writeln!(
                s,
                "the least stable forward mode has no damping (log dec 0): any cross-coupling destabilizes it"
            )
            .ok();
        }
        (Some(0.0), Some(m)) if m.log_decrement < 0.0 => {
            writeln!(
                s,
                "unstable without cross-coupling (threshold Q = 0): the {} mode at {} Hz grows (log dec {:.4})",
                m.whirl.label(),
                short(m.damped_frequency / (2.0 * std::f64::consts::PI)),
                m.log_decrement
            )
            .ok();
        }
        (Some(0.0), _) => {
            writeln!(
                s,
                "the least stable forward mode is unstable without cross-coupling"
            )
            .ok();
        }
        (Some(q), Some(m)) => {
            writeln!(
                s,
                "threshold Q = {} N/m: least stable forward mode at {} Hz reaches log dec {:.1e}",
                short(q),
                short(m.damped_frequency / (2.0 * std::f64::consts::PI)),
                m.log_decrement
            )
            .ok();
        }
        _ => {
            writeln!(
                s,
                "stable up to Q = {} N/m (no threshold found)",
                short(result.q_max)
            )
            .ok();
        }
    }
    if let Some(l) = &result.level_one {
        writeln!(s, "API 617 / API 684 Level I screening:").ok();
        let term = |st: &StageData, q: f64| {
            format!(
                "{} × {} W × {} / ({} m × {} m × {} rad/s) = {} N/m",
                short(st.stage_factor),
                short(st.power),
                short(st.density_ratio),
                short(st.diameter),
                short(st.width),
                short(result.speed.abs()),
                short(q)
            )
        };
        match l.stages.as_slice() {
            [one] if one.name == MACHINE_STAGE => {
                writeln!(
                    s,
                    "  anticipated cross-coupling Q_A = B P (ρd/ρs) / (D H Ω) = {} (Wachel)",
                    term(&one.data, l.anticipated)
                )
                .ok();
            }
            stages => {
                writeln!(
                    s,
                    "  anticipated cross-coupling of each impeller q_A = B P (ρd/ρs) / (D H Ω) (Wachel):"
                )
                .ok();
                for st in stages {
                    let q = st.data.anticipated(result.speed);
                    writeln!(s, "    {}: {}", st.name, term(&st.data, q)).ok();
                }
                writeln!(
                    s,
                    "  Q_A = the sum over the {} impellers = {} N/m",
                    stages.len(),
                    short(l.anticipated)
                )
                .ok();
            }
        }
        let ratio = match l.ratio {
            Some(r) => format!("{r:.2}"),
            None => format!("> {:.2}", result.q_max / l.anticipated),
        };
        writeln!(
            s,
            "  stability margin Q0/Q_A = {ratio} (at least {LEVEL_I_MIN_RATIO} required): {}",
            if l.ratio_pass { "pass" } else { "FAIL" }
        )
        .ok();
        writeln!(
            s,
            "  log dec at Q_A = {:.4} (at least {LEVEL_I_MIN_LOG_DEC} required): {}",
            l.mode_at_anticipated.log_decrement,
            if l.log_dec_pass { "pass" } else { "FAIL" }
        )
        .ok();
        writeln!(
            s,
            "  Level I: {}",
            if l.pass() {
                "pass"
            } else {
                "FAIL: a Level II analysis is required"
            }
        )
        .ok();
    }
    s
}

/// Every `step`-th row of a critical speed map: stiffness (N/m) and the forward
/// critical speeds (rpm).
pub fn critical_speed_map(name: &str, map: &CriticalSpeedMap, step: usize) -> String {
    let mut s =
        format!("forward critical speeds (rpm) of {name} against isotropic support stiffness:\n");
    let rows = map.stiffness.iter().zip(&map.speeds).zip(&map.unstable);
    for ((k, speeds), &unstable) in rows.step_by(step.max(1)) {
        if unstable > 0 {
            writeln!(
                s,
                "  k = {k:9.3e} N/m: STATICALLY UNSTABLE ({unstable} mode(s) of negative net stiffness: the magnetic pull exceeds what the supports hold; no critical speed)"
            )
            .ok();
            continue;
        }
        let rpm: Vec<String> = speeds
            .iter()
            .map(|v| format!("{:10.1}", v * RAD_S_TO_RPM))
            .collect();
        writeln!(s, "  k = {k:9.3e} N/m: {}", rpm.join(" ")).ok();
    }
    s
}

/// What `rotor simulate` prints without `--csv` (the table goes to a file,
/// never to the terminal): the run's length and records, and per bearing and
/// probe the largest displacement from the centre (µm) and, for fluid-film
/// bearings, the largest eccentricity ratio and smallest film thickness.
pub fn run_summary(model: &RotorModel, records: &[Outputs]) -> String {
    let (Some(first), Some(last)) = (records.first(), records.last()) else {
        return "no records\n".into();
    };
    let mut s = format!(
        "{}: {} records from t = {} to {} s, {} → {} rpm (--csv FILE writes them all)\n",
        model.name,
        records.len(),
        short(first.time),
        short(last.time),
        short(first.speed * RAD_S_TO_RPM),
        short(last.speed * RAD_S_TO_RPM)
    );
    s.push_str("largest displacement from the centre:\n");
    for (k, (name, x, y)) in super::series::orbits(model, records).iter().enumerate() {
        let r = x
            .iter()
            .zip(y)
            .map(|(a, b)| a.hypot(*b))
            .fold(0.0, f64::max);
        write!(s, "  {name:<28} {:>10} µm", short(r * 1e6)).ok();
        let film = model
            .bearings
            .get(k)
            .filter(|b| b.kind.journal_clearance().is_some() && !b.kind.is_rub());
        if film.is_some() {
            let e = records
                .iter()
                .map(|o| o.bearings[k].report.eccentricity)
                .fold(0.0, f64::max);
            let h = records
                .iter()
                .map(|o| o.bearings[k].report.min_film_thickness)
                .fold(f64::INFINITY, f64::min);
            // A tilting pad's ratio is over the assembled (bearing) clearance.
            let pads = film.is_some_and(|b| {
                matches!(b.kind.short_film().as_ref(), BearingKind::TiltingPad(_))
            });
            write!(
                s,
                ", eccentricity {} up to {}, film down to {} µm",
                if pads {
                    "e/C_b (bearing clearance)"
                } else {
                    "ratio"
                },
                short(e),
                short(h * 1e6)
            )
            .ok();
        }
        s.push('\n');
    }
    s
}

/// The pads' pivot stiffness and inertia for a bearing's description
/// (nothing for rigid pivots and massless pads).
fn pad_support(support: &crate::bearing::tilting_pad::PadSupport) -> String {
    let mut parts = Vec::new();
    if let Some(k) = support.pivot_stiffness {
        parts.push(format!("pivot stiffness {} N/m", short(k)));
    }
    if support.pivot_damping != 0.0 {
        parts.push(format!(
            "pivot damping {} N·s/m",
            short(support.pivot_damping)
        ));
    }
    if support.pad_inertia != 0.0 {
        parts.push(format!("pad inertia {} kg·m²", short(support.pad_inertia)));
    }
    if support.pad_mass != 0.0 {
        parts.push(format!("pad mass {} kg", short(support.pad_mass)));
    }
    if parts.is_empty() {
        String::new()
    } else {
        format!(", {}", parts.join(", "))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_lose_their_float_noise() {
        assert_eq!(short(0.49999999999999994), "0.5");
        assert_eq!(short(0.0), "0");
        assert_eq!(short(-9.81), "-9.81");
        assert_eq!(short(1e-4 * 1e6), "100");
        assert_eq!(short(2.5e-9), "2.5e-9");
    }
}
