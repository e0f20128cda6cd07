//! `rotor simulate`: a time simulation with its CSV, orbit, spectrum and waterfall plots.

use std::path::{Path, PathBuf};

use rotor_bearing::analysis::spectrum::{
    MIN_REVOLUTIONS, about_moving_centre, band_limit, frequency_grid, full_spectrum, waterfall,
};
use rotor_bearing::model::RotorModel;
use rotor_bearing::model::speed_table;
use rotor_bearing::plot::{
    OrbitPanel, RAD_S_TO_RPM, WaterfallTrace, orbits_png, spectrum_png, waterfall_png,
};
use rotor_bearing::report::text::{self, short};
use rotor_bearing::report::{csv as report_csv, series};
use rotor_bearing::rotor::Rotor;
use rotor_bearing::solver::reduction_check::{
    Excursion, ValidityWatch, error_estimate, excursion_report,
};
use rotor_bearing::solver::time_step::{
    ADAPTIVE_STEPS_PER_REVOLUTION, MAX_ADAPTIVE_TIME_STEP, MAX_DEFAULT_TIME_STEP,
    STEPS_PER_REVOLUTION,
};
use rotor_bearing::solver::{Simulator, SolverOptions, SpeedProfile, StepStats, record_into};
use rotor_bearing::units::Amplitude;

use crate::write_file;

pub fn speed_profile(
    rpm: Option<f64>,
    ramp: Option<&str>,
    table: Option<&Path>,
    duration: f64,
) -> Result<SpeedProfile, String> {
    let to_rad = 1.0 / RAD_S_TO_RPM;
    match (rpm, ramp, table) {
        (Some(r), None, None) => Ok(SpeedProfile::Constant(r * to_rad)),
        (None, Some(text), None) => {
            let parts: Vec<&str> = text.split(':').collect();
            let parse = |s: &str| {
                s.trim().parse::<f64>().map_err(|_| {
                    format!("--ramp-rpm {text:?}: {s:?} is not a number (expected FROM:TO)")
                })
            };
            if parts.len() != 2 {
                return Err(format!("--ramp-rpm {text:?}: expected FROM:TO in rpm"));
            }
            Ok(SpeedProfile::Ramp {
                from: parse(parts[0])? * to_rad,
                to: parse(parts[1])? * to_rad,
                duration,
            })
        }
        (None, None, Some(path)) => {
            let text = std::fs::read_to_string(path)
                .map_err(|e| format!("{}: cannot read: {e}", path.display()))?;
            let points = speed_table::parse(&text, &path.display().to_string())
                .map_err(|e| e.to_string())?
                .into_iter()
                .map(|(t, w)| (t, w * to_rad))
                .collect();
            let profile = SpeedProfile::Table(points);
            profile
                .validate()
                .map_err(|e| format!("{}: {e}", path.display()))?;
            Ok(profile)
        }
        _ => Err("give exactly one of --rpm, --ramp-rpm, --speed-csv".into()),
    }
}

/// Refuse, before the run, a speed profile that reaches past the model's
/// `max_speed_rpm`, in rpm (the simulator would stop there mid-run).
pub fn check_speeds(model: &RotorModel, profile: &SpeedProfile) -> Result<(), String> {
    let peak = profile.top_speed();
    if peak > model.max_speed {
        let stated = if model.max_speed_stated {
            format!(
                "{}: max_speed_rpm = {}",
                model.source,
                short(model.max_speed * RAD_S_TO_RPM)
            )
        } else {
            format!(
                "the default max_speed_rpm {} (give max_speed_rpm in {})",
                short(model.max_speed * RAD_S_TO_RPM),
                model.source
            )
        };
        return Err(format!(
            "the speed profile reaches {} rpm, above {stated}: nothing was run",
            short(peak * RAD_S_TO_RPM)
        ));
    }
    Ok(())
}

/// Where the default time step `h` of a run reaching `peak` (rad/s) came from.
/// (`tolerance`: the local error tolerance of accuracy-controlled steps, 0 for equal steps.)
pub fn describe_default_step(model: &RotorModel, peak: f64, h: f64, tolerance: f64) -> String {
    let top = model.transient_top_speed().unwrap_or(0.0).max(peak);
    if tolerance > 0.0 {
        let bound = if h < MAX_ADAPTIVE_TIME_STEP {
            format!(
                "{} per revolution at {} rpm",
                ADAPTIVE_STEPS_PER_REVOLUTION,
                short(top * RAD_S_TO_RPM)
            )
        } else {
            format!("at most 20 ms; {} rpm", short(top * RAD_S_TO_RPM))
        };
        return format!(
            "accuracy-controlled steps: local error tolerance {}, steps up to {} s ({bound}; --step for equal steps)",
            short(tolerance),
            short(h)
        );
    }
    if h < MAX_DEFAULT_TIME_STEP {
        format!(
            "time step {} s ({} steps per revolution at {} rpm; --step to choose)",
            short(h),
            STEPS_PER_REVOLUTION,
            short(top * RAD_S_TO_RPM)
        )
    } else {
        format!(
            "time step {} s (at most 1 ms; {} rpm needs no finer; --step to choose)",
            short(h),
            short(top * RAD_S_TO_RPM)
        )
    }
}

/// The motion's excursions from the reduced rotor's validated range in a run:
/// how many records were outside, and the highest (time, speed, excursion).
#[derive(Default)]
struct Excursions {
    count: usize,
    highest: Option<(f64, f64, Excursion)>,
}

impl Excursions {
    fn note(&mut self, t: f64, speed: f64, e: Excursion) {
        if self
            .highest
            .is_none_or(|(_, _, x)| e.frequency() > x.frequency())
        {
            self.highest = Some((t, speed, e));
        }
        self.count += 1;
    }

    /// The warning for the highest excursion when there were several (the
    /// first was reported as it happened).
    fn warn(&self, name: &str, full: Option<&Rotor>, rotor: &Rotor) {
        if let (Some(full), count @ 2.., Some((t, speed, e))) = (full, self.count, self.highest) {
            let report = excursion_report(full, rotor, speed, e);
            eprintln!(
                "warning: {name}: the motion left the validated range {count} times; the highest, at t = {t:.4} s: {report}"
            );
        }
    }
}

/// What `rotor simulate` records and writes.
pub struct Run {
    pub profile: SpeedProfile,
    pub duration: f64,
    pub output_step: f64,
    pub settle: bool,
    pub csv: Option<PathBuf>,
    pub plots: Option<String>,
    pub amplitude: Amplitude,
    /// Torques of a torque-driven shaft: load channel and value (N·m).
    pub torques: Vec<(usize, f64)>,
}

/// The `--torque NAME=VALUE` options as load channels of `model`'s torque
/// nodes: each name one of its `[[torques]]`, each value finite (N·m).
pub fn torque_inputs(model: &RotorModel, given: &[String]) -> Result<Vec<(usize, f64)>, String> {
    if !given.is_empty() && model.drive != rotor_bearing::model::Drive::Torque {
        return Err(format!(
            "--torque: the shaft of {} is speed-driven (its file has no [torsion] drive = \"torque\")",
            model.name
        ));
    }
    let names: Vec<&str> = model.torques.iter().map(|t| t.name.as_str()).collect();
    given
        .iter()
        .map(|g| {
            let (name, value) = g
                .split_once('=')
                .ok_or_else(|| format!("--torque {g:?}: expected NAME=VALUE (N·m)"))?;
            let k = names
                .iter()
                .position(|n| *n == name.trim())
                .ok_or_else(|| {
                    format!(
                        "--torque {g:?}: {name:?} is not a torque node of {} ({names:?})",
                        model.name
                    )
                })?;
            let value: f64 = value
                .trim()
                .parse()
                .ok()
                .filter(|v: &f64| v.is_finite())
                .ok_or_else(|| format!("--torque {g:?}: {value:?} is not a finite number (N·m)"))?;
            Ok((model.first_torque_input() + k, value))
        })
        .collect()
}

/// The run of `rotor` (reduced from `full` when that is given): the reduced
/// rotor says how far it is from the full one at the top speed, and warns
/// when the speed or the motion leaves the range it is validated for.
pub fn simulate(
    rotor: Rotor,
    full: Option<Rotor>,
    options: SolverOptions,
    run: Run,
) -> Result<(), String> {
    let Run {
        profile,
        duration,
        output_step,
        settle,
        csv,
        plots,
        amplitude,
        torques,
    } = run;
    let profile = &profile;
    let model = rotor.model.clone();
    eprintln!("{}", rotor.coordinates());
    let mut watch = ValidityWatch::new(&rotor);
    let top = profile.top_speed();
    // The full rotor's operating point (a reduced rotor has no static solve).
    crate::warn_short_films(full.as_ref().unwrap_or(&rotor), &[top]);
    if let Some(full) = &full {
        let rpm = top * RAD_S_TO_RPM;
        let estimate = error_estimate(full, &rotor, top, top);
        if top > watch.limit() {
            let report = excursion_report(full, &rotor, top, Excursion::Speed(top));
            eprintln!("warning: {}: top speed {rpm:.0} rpm: {report}", model.name);
        } else {
            eprintln!("reduced rotor at the top speed {rpm:.0} rpm: {estimate}");
        }
    }
    let mut sim = Simulator::new(rotor, options).map_err(|e| e.to_string())?;
    let (w0, _) = profile.at(0.0);
    sim.set_speed(w0, 0.0).map_err(|e| e.to_string())?;
    // The torques act from the start: the static state and its twist
    // accelerations are taken under them.
    for &(channel, torque) in &torques {
        sim.set_load(channel, torque, 0.0)
            .map_err(|e| format!("{}: {e}", model.name))?;
    }
    if settle {
        sim.settle_static()
            .map_err(|e| format!("{}: {e}", model.name))?;
    } else {
        // From rest at the undeflected position: start Newmark from the
        // accelerations the equations of motion give there (a zero start is a
        // first-order error that never decays).
        sim.consistent_acceleration()
            .map_err(|e| format!("{}: {e}", model.name))?;
    }
    let started = std::time::Instant::now();
    let mut shown = 0;
    let terminal = std::io::IsTerminal::is_terminal(&std::io::stderr());
    // The first excursion of the motion is reported as it happens, the
    // highest at the end, also of a failed run.
    let mut excursions = Excursions::default();
    let mut records = Vec::new();
    let outcome = record_into(
        &mut sim,
        profile,
        duration,
        output_step,
        &mut records,
        |f, sim| {
            let speed = sim.speed_at(sim.time());
            // The speed was judged before the run: here the motion's frequency.
            let motion = watch.check(speed, sim.state());
            if let (Some(e @ Excursion::Motion(_)), Some(full)) = (motion, &full) {
                let t = sim.time();
                if excursions.count == 0 {
                    let report = excursion_report(full, sim.rotor(), speed, e);
                    eprintln!("warning: {}: at t = {t:.4} s {report}", model.name);
                }
                excursions.note(t, speed, e);
            }
            let pct = (f * 100.0) as usize;
            if terminal && pct >= shown + 5 {
                shown = pct - pct % 5;
                eprint!("\rsimulating {}: {shown:3}%", model.name);
            }
        },
    );
    for w in sim.take_warnings() {
        eprintln!("warning: {}: {w}", model.source);
    }
    // Contact beyond its law's limits is reported whether or not the run ended.
    let contact = sim.take_contact_warnings();
    for w in &contact {
        eprintln!("{}warning: {}", if terminal { "\r" } else { "" }, w.message);
    }
    if let Err(e) = outcome {
        // End the progress line unless a warning already did.
        if terminal && contact.is_empty() {
            eprintln!();
        }
        excursions.warn(&model.name, full.as_ref(), sim.rotor());
        // Keep what was computed: the rows up to the last converged output.
        let reached = records.last().map_or(0.0, |o| o.time);
        let kept = match &csv {
            Some(path) if !records.is_empty() => {
                write_file(path, &report_csv::simulation(&model, &records))?;
                format!(
                    "; the {} rows up to t = {} s are in {}",
                    records.len(),
                    short(reached),
                    path.display()
                )
            }
            _ => String::new(),
        };
        return Err(format!(
            "{}: {e} (failed after t = {} s of {} s{kept})",
            model.name,
            short(reached),
            short(duration)
        ));
    }
    eprintln!(
        "{}{}",
        if terminal { "\r" } else { "" },
        run_line(
            duration,
            &model.name,
            started.elapsed().as_secs_f64(),
            &sim.stats()
        )
    );
    excursions.warn(&model.name, full.as_ref(), sim.rotor());
    match &csv {
        Some(path) => write_file(path, &report_csv::simulation(&model, &records))?,
        None if plots.is_none() => print!("{}", text::run_summary(&model, &records)),
        None => {}
    }
    if let Some(prefix) = plots {
        // The last half of the run: settled orbits and their spectra.
        let tail = &records[records.len() / 2..];
        let t: Vec<f64> = tail.iter().map(|o| o.time).collect();
        let orbits = series::orbits(&model, tail);
        let mean_speed = tail.iter().map(|o| o.speed).sum::<f64>() / tail.len() as f64;
        let panels: Vec<OrbitPanel> = orbits
            .iter()
            .enumerate()
            .map(|(k, (name, x, y))| OrbitPanel {
                name: name.clone(),
                x: x.clone(),
                y: y.clone(),
                clearance: model
                    .bearings
                    .get(k)
                    .filter(|b| !b.kind.is_rub())
                    .and_then(|b| b.kind.journal_clearance()),
            })
            .collect();
        let spin: Vec<f64> = tail.iter().map(|o| o.spin_angle).collect();
        let path = PathBuf::from(format!("{prefix}_orbits.png"));
        orbits_png(
            &path,
            &format!("Orbits: {} (last half of the run)", model.name),
            &panels,
            &spin,
            mean_speed,
        )
        .map_err(|e| e.to_string())?;
        eprintln!("wrote {}", path.display());
        let f_spin = mean_speed / (2.0 * std::f64::consts::PI);
        let f_max = band_limit(2.5 * f_spin.abs(), output_step);
        let freqs = frequency_grid(-f_max, f_max, 1601);
        // About the orbit's moving centre: the rest position's drift is no line at 0 Hz.
        let spectra: Vec<(String, Vec<f64>)> = orbits
            .iter()
            .map(|(name, x, y)| {
                (
                    name.clone(),
                    full_spectrum(
                        &t,
                        &about_moving_centre(x, &spin),
                        &about_moving_centre(y, &spin),
                        &freqs,
                    ),
                )
            })
            .collect();
        let path = PathBuf::from(format!("{prefix}_spectrum.png"));
        let markers = vec![
            ("1×".to_string(), f_spin),
            ("0.5×".to_string(), 0.5 * f_spin),
            ("−1×".to_string(), -f_spin),
        ];
        spectrum_png(
            &path,
            &format!(
                "Full spectrum: {} (last half of the run, about the orbit's moving centre)",
                model.name
            ),
            &freqs,
            &spectra,
            &markers,
            amplitude,
        )
        .map_err(|e| e.to_string())?;
        eprintln!("wrote {}", path.display());
        // Waterfall over the whole run, of the first probe (else the first bearing).
        let t: Vec<f64> = records.iter().map(|o| o.time).collect();
        let speed: Vec<f64> = records.iter().map(|o| o.speed).collect();
        let (x, y): (Vec<f64>, Vec<f64>) = records.iter().map(series::watched_point).unzip();
        let watched = series::watched_point_name(&model);
        let mut out =
            format!("spectra of {watched}, windows of {MIN_REVOLUTIONS} revolutions (Hann):\n");
        out.push_str(&format!(
            "window    start_s      end_s  revolutions  speed_rpm  dominant_Hz   ratio  amplitude_um_{}  subsync_share\n",
            amplitude.label()
        ));
        let wf = match waterfall(&t, &x, &y, &speed, output_step) {
            Ok(wf) => wf,
            Err(short) => {
                out.push_str(&format!("     -  {short}: no frequency ratio\n"));
                print!("{out}");
                eprintln!(
                    "warning: {short} in the whole run: no frequency ratio and no waterfall (run longer or faster)"
                );
                return Ok(());
            }
        };
        for (w, row) in wf.rows.iter().enumerate() {
            let s = &row.window;
            out.push_str(&format!(
                "{w:6} {:10.6} {:10.6} {:12.1} {:10.1}",
                s.start,
                s.end,
                s.revolutions,
                s.speed * RAD_S_TO_RPM
            ));
            match (s.peak, s.order()) {
                (Some(p), Some(ratio)) => out.push_str(&format!(
                    " {:12.3} {ratio:7.3} {:17.4} {:14.6}\n",
                    p.frequency,
                    p.amplitude * 1e6 * amplitude.factor(),
                    s.subsynchronous_share
                )),
                _ => out.push_str("  no motion: no dominant frequency\n"),
            }
        }
        let traces: Vec<WaterfallTrace> = wf
            .rows
            .into_iter()
            .map(|r| WaterfallTrace {
                time: 0.5 * (r.window.start + r.window.end),
                rpm: r.speed * RAD_S_TO_RPM,
                amplitudes: r.amplitudes,
            })
            .collect();
        let path = PathBuf::from(format!("{prefix}_waterfall.png"));
        waterfall_png(
            &path,
            &format!("Waterfall: {}, {watched}", model.name),
            &wf.freqs,
            &traces,
            amplitude,
        )
        .map_err(|e| e.to_string())?;
        eprintln!("wrote {}", path.display());
        print!("{out}");
    }
    Ok(())
}

/// The run's summary line: `simulated D s of NAME in W s wall-clock` (the
/// prefix `bench/ross_compare.py` reads), the real-time factor `D / W`,
/// then the steps, Newton iterations a step, factorizations (recalled ones
/// besides), step cuts, and damped retries and rejected steps when there
/// were any.
fn run_line(duration: f64, name: &str, wall: f64, stats: &StepStats) -> String {
    let plural =
        |n: usize, one: &str, many: &str| format!("{n} {}", if n == 1 { one } else { many });
    let per_step = stats.iterations as f64 / stats.steps.max(1) as f64;
    let mut line = format!(
        "simulated {duration} s of {name} in {wall:.4} s wall-clock, {:.1}x real time: {}, {per_step:.2} Newton iterations a step, {}",
        duration / wall,
        plural(stats.steps, "step", "steps"),
        plural(stats.factorizations, "factorization", "factorizations"),
    );
    if stats.factors_recalled > 0 {
        line += &format!(" (+{} recalled)", stats.factors_recalled);
    }
    line += &format!(", {}", plural(stats.step_cuts, "step cut", "step cuts"));
    if stats.retries > 0 {
        line += &format!(
            ", {}",
            plural(stats.retries, "damped retry", "damped retries")
        );
    }
    if stats.rejections > 0 {
        line += &format!(
            ", {}",
            plural(stats.rejections, "rejected step", "rejected steps")
        );
    }
    line
}

#[cfg(test)]
mod tests {
    use super::run_line;
    use rotor_bearing::solver::StepStats;

    /// One readable line, not a `Debug` dump; the counts as given, the
    /// iterations a step and the real-time factor worked out.
    #[test]
    fn the_run_line_reads_as_a_sentence() {
        let stats = StepStats {
            steps: 5000,
            iterations: 72730,
            factorizations: 1,
            ..StepStats::default()
        };
        assert_eq!(
            run_line(10.0, "hydro_unit_brackets", 0.25, &stats),
            "simulated 10 s of hydro_unit_brackets in 0.2500 s wall-clock, 40.0x real time: \
             5000 steps, 14.55 Newton iterations a step, 1 factorization, 0 step cuts"
        );
        let stats = StepStats {
            steps: 591,
            iterations: 8025,
            factorizations: 59,
            factors_recalled: 76,
            step_cuts: 1,
            retries: 2,
            rejections: 17,
            ..StepStats::default()
        };
        let line = run_line(2.0, "m", 4.0, &stats);
        assert!(
            line.ends_with(
                "0.5x real time: 591 steps, 13.58 Newton iterations a step, \
             59 factorizations (+76 recalled), 1 step cut, 2 damped retries, 17 rejected steps"
            ),
            "{line}"
        );
        assert!(!line.contains("StepStats"));
    }
}
