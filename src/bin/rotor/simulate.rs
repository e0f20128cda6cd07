//! `rotor simulate`: a time simulation with its CSV, orbit, spectrum and waterfall plots.

use std::path::{Path, PathBuf};

use rotor_bearing::analysis::spectrum::{
    MIN_REVOLUTIONS, band_limit, frequency_grid, full_spectrum, waterfall,
};
use rotor_bearing::model::speed_table;
use rotor_bearing::plot::{RAD_S_TO_RPM, orbits_png, spectrum_png, waterfall_png};
use rotor_bearing::report::{csv as report_csv, series};
use rotor_bearing::rotor::Rotor;
use rotor_bearing::solver::reduction_check::{
    Excursion, ValidityWatch, error_estimate, excursion_report,
};
use rotor_bearing::solver::{Simulator, SolverOptions, SpeedProfile, record};

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

/// What `rotor simulate` records and writes.
pub struct Run {
    pub profile: SpeedProfile,
    pub duration: f64,
    pub output_step: f64,
    pub settle: bool,
    pub csv: Option<PathBuf>,
    pub plots: Option<String>,
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
    } = run;
    let profile = &profile;
    let model = rotor.model.clone();
    eprintln!("{}", rotor.coordinates());
    let mut watch = ValidityWatch::new(&rotor);
    let top = profile.top_speed();
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
    // highest at the end: (count, time, speed, excursion).
    let mut excursions: (usize, f64, f64, Option<Excursion>) = (0, 0.0, 0.0, None);
    let result = record(&mut sim, profile, duration, output_step, |f, sim| {
        let speed = sim.speed_at(sim.time());
        // The speed was judged before the run: here the motion's frequency.
        let motion = watch.check(speed, sim.state());
        if let (Some(e @ Excursion::Motion(_)), Some(full)) = (motion, &full) {
            let t = sim.time();
            if excursions.0 == 0 {
                let report = excursion_report(full, sim.rotor(), speed, e);
                eprintln!("warning: {}: at t = {t:.4} s {report}", model.name);
            }
            if excursions.3.is_none_or(|x| e.frequency() > x.frequency()) {
                (excursions.1, excursions.2, excursions.3) = (t, speed, Some(e));
            }
            excursions.0 += 1;
        }
        let pct = (f * 100.0) as usize;
        if terminal && pct >= shown + 5 {
            shown = pct - pct % 5;
            eprint!("\rsimulating {}: {shown:3}%", model.name);
        }
    });
    for w in sim.take_warnings() {
        eprintln!("warning: {}: {w}", model.source);
    }
    // Contact beyond its law's limits is reported whether or not the run ended.
    for w in sim.take_contact_warnings() {
        eprintln!("{}warning: {}", if terminal { "\r" } else { "" }, w.message);
    }
    let records = result.map_err(|e| format!("{}: {e}", model.name))?;
    eprintln!(
        "{}simulated {} s of {} in {:.4} s wall-clock ({:?})",
        if terminal { "\r" } else { "" },
        duration,
        model.name,
        started.elapsed().as_secs_f64(),
        sim.stats()
    );
    if let (Some(full), (count @ 2.., t, speed, Some(e))) = (&full, excursions) {
        let report = excursion_report(full, sim.rotor(), speed, e);
        eprintln!(
            "warning: {}: the motion left the validated range {count} times; the highest, at t = {t:.4} s: {report}",
            model.name
        );
    }
    let out = report_csv::simulation(&model, &records);
    match csv {
        Some(path) => write_file(&path, &out)?,
        None if plots.is_none() => print!("{out}"),
        None => {}
    }
    if let Some(prefix) = plots {
        // The last half of the run: settled orbits and their spectra.
        let tail = &records[records.len() / 2..];
        let t: Vec<f64> = tail.iter().map(|o| o.time).collect();
        let orbits = series::orbits(&model, tail);
        let path = PathBuf::from(format!("{prefix}_orbits.png"));
        orbits_png(
            &path,
            &format!("Orbits: {} (last half of the run)", model.name),
            &orbits,
            None,
        )
        .map_err(|e| e.to_string())?;
        eprintln!("wrote {}", path.display());
        let mean_speed = tail.iter().map(|o| o.speed).sum::<f64>() / tail.len() as f64;
        let f_spin = mean_speed / (2.0 * std::f64::consts::PI);
        let f_max = band_limit(2.5 * f_spin, output_step);
        let freqs = frequency_grid(-f_max, f_max, 1601);
        let spectra: Vec<(String, Vec<f64>)> = orbits
            .iter()
            .map(|(name, x, y)| (name.clone(), full_spectrum(&t, x, y, &freqs)))
            .collect();
        let path = PathBuf::from(format!("{prefix}_spectrum.png"));
        let markers = vec![
            ("1×".to_string(), f_spin),
            ("0.5×".to_string(), 0.5 * f_spin),
            ("−1×".to_string(), -f_spin),
        ];
        spectrum_png(
            &path,
            &format!("Full spectrum: {}", model.name),
            &freqs,
            &spectra,
            &markers,
        )
        .map_err(|e| e.to_string())?;
        eprintln!("wrote {}", path.display());
        // Waterfall over the whole run, of the first probe (else the first bearing).
        let t: Vec<f64> = records.iter().map(|o| o.time).collect();
        let speed: Vec<f64> = records.iter().map(|o| o.speed).collect();
        let (x, y): (Vec<f64>, Vec<f64>) = records.iter().map(series::watched_point).unzip();
        let watched = series::watched_point_name(&model);
        println!("spectra of {watched}, windows of {MIN_REVOLUTIONS} revolutions (Hann):");
        println!(
            "window    start_s      end_s  revolutions  speed_rpm  dominant_Hz   ratio  amplitude_um  subsync_share"
        );
        let wf = match waterfall(&t, &x, &y, &speed, output_step) {
            Ok(wf) => wf,
            Err(short) => {
                println!("     -  {short}: no frequency ratio");
                eprintln!(
                    "warning: {short} in the whole run: no frequency ratio and no waterfall (run longer or faster)"
                );
                return Ok(());
            }
        };
        for (w, row) in wf.rows.iter().enumerate() {
            let s = &row.window;
            print!(
                "{w:6} {:10.6} {:10.6} {:12.1} {:10.1}",
                s.start,
                s.end,
                s.revolutions,
                s.speed * RAD_S_TO_RPM
            );
            match (s.peak, s.order()) {
                (Some(p), Some(ratio)) => println!(
                    " {:12.3} {ratio:7.3} {:13.4} {:14.6}",
                    p.frequency,
                    p.amplitude * 1e6,
                    s.subsynchronous_share
                ),
                _ => println!("  no motion: no dominant frequency"),
            }
        }
        let rows: Vec<(f64, Vec<f64>)> = wf
            .rows
            .into_iter()
            .map(|r| (r.speed * RAD_S_TO_RPM, r.amplitudes))
            .collect();
        let path = PathBuf::from(format!("{prefix}_waterfall.png"));
        waterfall_png(
            &path,
            &format!("Waterfall: {}, {watched}", model.name),
            &wf.freqs,
            &rows,
        )
        .map_err(|e| e.to_string())?;
        eprintln!("wrote {}", path.display());
    }
    Ok(())
}
