//! `rotor`: command-line front end of the rotor-bearing library.
//!
//! ```text
//! rotor info     [MODEL.toml]
//! rotor static   [MODEL.toml] [--csv FILE]
//! rotor modes    [MODEL.toml] [--rpm N] [--modes K] [--csv FILE]
//! rotor campbell [MODEL.toml] [--max-rpm N] [--steps S] [--modes K] [--csv FILE] [--png FILE]
//! rotor coefficients [MODEL.toml] [--bearing NAME] [--rpm N] [--points P] [--csv FILE] [--png FILE]
//! rotor simulate [MODEL.toml] (--rpm N | --ramp-rpm A:B | --speed-csv FILE) [--duration S] [--step S]
//!                [--output-step S] [--ramp-time S] [--no-gravity] [--csv FILE] [--plots PREFIX]
//! ```
//! Without MODEL.toml the built-in classic disk-on-shaft rotor is used (and, for
//! `coefficients`, the reference plain short bearing).

use std::path::{Path, PathBuf};
use std::process::ExitCode;

use clap::{Args, Parser, Subcommand};

use rotor_bearing::analysis::campbell::{campbell, critical_speeds};
use rotor_bearing::analysis::linear::static_deflection;
use rotor_bearing::analysis::modal::{ModalOptions, modes_at};
use rotor_bearing::analysis::spectrum::{band_limit, frequency_grid, full_spectrum, waterfall};
use rotor_bearing::bearing::coefficients::dimensionless_curve;
use rotor_bearing::bearing::{BearingKind, PlainBearing};
use rotor_bearing::model::{RotorModel, speed_table};
use rotor_bearing::plot::{
    RAD_S_TO_RPM, campbell_png, coefficients_png, orbits_png, spectrum_png, waterfall_png,
};
use rotor_bearing::report::text::model_summary;
use rotor_bearing::report::{csv as report_csv, series};
use rotor_bearing::rotor::Rotor;
use rotor_bearing::solver::statics::equilibrium;
use rotor_bearing::solver::{Simulator, SolverOptions, SpeedProfile, record};

#[derive(Parser)]
#[command(
    name = "rotor",
    version,
    about = "Finite-element rotor-bearing dynamics"
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Args)]
struct ModelArg {
    /// Model file (TOML); the built-in classic disk-on-shaft rotor when omitted.
    model: Option<PathBuf>,
}

#[derive(Subcommand)]
enum Command {
    /// Summarize a model: nodes, elements, masses, bearings.
    Info {
        #[command(flatten)]
        model: ModelArg,
    },
    /// Static deflection under gravity (linear bearings).
    Static {
        #[command(flatten)]
        model: ModelArg,
        /// Spin speed (rpm): fluid-film bearings carry load only when turning.
        #[arg(long, default_value_t = 0.0)]
        rpm: f64,
        /// Write node displacements to this CSV file.
        #[arg(long)]
        csv: Option<PathBuf>,
    },
    /// Complex modes at one speed: damped frequencies, damping, whirl.
    Modes {
        #[command(flatten)]
        model: ModelArg,
        /// Spin speed (rpm).
        #[arg(long, default_value_t = 0.0)]
        rpm: f64,
        /// Number of modes.
        #[arg(long, default_value_t = 8)]
        modes: usize,
        /// Write the modes to this CSV file.
        #[arg(long)]
        csv: Option<PathBuf>,
    },
    /// Campbell diagram and critical speeds over 0..max-rpm.
    Campbell {
        #[command(flatten)]
        model: ModelArg,
        /// Highest spin speed (rpm).
        #[arg(long, default_value_t = 4000.0)]
        max_rpm: f64,
        /// Number of speed steps (the grid has steps + 1 points).
        #[arg(long, default_value_t = 40)]
        steps: usize,
        /// Number of modes per speed.
        #[arg(long, default_value_t = 8)]
        modes: usize,
        /// Write the diagram to this CSV file.
        #[arg(long)]
        csv: Option<PathBuf>,
        /// Draw the diagram to this PNG file.
        #[arg(long)]
        png: Option<PathBuf>,
    },
    /// Time simulation (Newmark + Newton–Raphson) with nonlinear bearings: CSV of
    /// bearing and probe outputs, orbit and full-spectrum plots.
    Simulate {
        #[command(flatten)]
        model: ModelArg,
        /// Constant spin speed (rpm).
        #[arg(long, conflicts_with_all = ["ramp_rpm", "speed_csv"])]
        rpm: Option<f64>,
        /// Linear run-up or coast-down FROM:TO (rpm) over the whole duration.
        #[arg(long, conflicts_with = "speed_csv")]
        ramp_rpm: Option<String>,
        /// Speed table: CSV with columns time_s,speed_rpm (header line optional).
        #[arg(long)]
        speed_csv: Option<PathBuf>,
        /// Simulated time (s).
        #[arg(long, default_value_t = 1.0)]
        duration: f64,
        /// Internal time step (s).
        #[arg(long, default_value_t = 1e-4)]
        step: f64,
        /// Output interval (s); defaults to the internal step, at least 1/20 000 of the duration.
        #[arg(long)]
        output_step: Option<f64>,
        /// Unbalance ramp time constant (s), 0 for none.
        #[arg(long, default_value_t = 0.0)]
        ramp_time: f64,
        /// Switch gravity off.
        #[arg(long)]
        no_gravity: bool,
        /// Start from rest at the bearing centres instead of the static equilibrium.
        #[arg(long)]
        no_settle: bool,
        /// Write the outputs to this CSV file.
        #[arg(long)]
        csv: Option<PathBuf>,
        /// Write PREFIX_orbits.png and PREFIX_spectrum.png (last half of the run).
        #[arg(long)]
        plots: Option<String>,
    },
    /// Write the generated parts of an FMU for MODEL into DIR: modelDescription.xml,
    /// resources/model.toml and documentation/index.html (fmu_pack.sh adds the binary).
    FmuStage {
        /// Model file.
        model: PathBuf,
        /// Staging directory.
        dir: PathBuf,
    },
    /// Dimensionless stiffness and damping of a hydrodynamic bearing against
    /// eccentricity ratio (paper Fig. 3), from equilibria under a swept load.
    Coefficients {
        /// Model file whose bearing to use; the reference plain short bearing when omitted.
        model: Option<PathBuf>,
        /// Bearing name in the model (default: its first hydrodynamic bearing).
        #[arg(long)]
        bearing: Option<String>,
        /// Spin speed (rpm).
        #[arg(long, default_value_t = 3000.0)]
        rpm: f64,
        /// Number of load steps.
        #[arg(long, default_value_t = 60)]
        points: usize,
        /// Write the coefficients to this CSV file.
        #[arg(long)]
        csv: Option<PathBuf>,
        /// Draw them to this PNG file.
        #[arg(long)]
        png: Option<PathBuf>,
    },
}

/// The plain short bearing of the project's reference data: R = 50 mm, L = 30 mm,
/// C = 0.1 mm, μ = 0.02 Pa·s.
const REFERENCE_BEARING: PlainBearing = PlainBearing {
    radius: 0.05,
    length: 0.03,
    clearance: 1e-4,
    viscosity: 0.02,
};

fn main() -> ExitCode {
    // A closed pipe (`rotor info | head`) ends the CLI quietly, as for any Unix
    // tool, instead of a panic in println!: restore the default SIGPIPE action
    // the Rust runtime replaced with "ignore".
    // SAFETY: called once at start-up before any thread exists; SIG_DFL is a
    // valid disposition for SIGPIPE.
    unsafe {
        libc::signal(libc::SIGPIPE, libc::SIG_DFL);
    }
    match run(Cli::parse()) {
        Ok(()) => ExitCode::SUCCESS,
        Err(message) => {
            eprintln!("rotor: error: {message}");
            ExitCode::FAILURE
        }
    }
}

fn load(arg: &ModelArg) -> Result<Rotor, String> {
    let model = match &arg.model {
        Some(path) => RotorModel::from_file(path).map_err(|e| e.to_string())?,
        None => RotorModel::default_model(),
    };
    Rotor::new(model).map_err(|e| e.to_string())
}

fn write_file(path: &Path, text: &str) -> Result<(), String> {
    std::fs::write(path, text).map_err(|e| format!("{}: cannot write: {e}", path.display()))?;
    eprintln!("wrote {}", path.display());
    Ok(())
}

/// Node displacements (`4·node + k`) at the static equilibrium under gravity at
/// `rpm`: linear deflection for linear bearings; for fluid-film bearings the
/// simulator's settled state (the one place to call a statics solver instead).
fn static_state(rotor: &Rotor, rpm: f64) -> Result<Vec<f64>, String> {
    if rotor.nonlinear_bearings.is_empty() {
        return static_deflection(rotor).map_err(|e| e.to_string());
    }
    let eq = equilibrium(rotor, rpm / RAD_S_TO_RPM, &SolverOptions::default(), None)
        .map_err(|e| format!("{} at {rpm} rpm: {e}", rotor.model.name))?;
    Ok(rotor.dofs.expand(&eq.displacement))
}

fn run(cli: Cli) -> Result<(), String> {
    match cli.command {
        Command::Info { model } => {
            let rotor = load(&model)?;
            print!("{}", model_summary(&rotor));
        }
        Command::Static { model, rpm, csv } => {
            let rotor = load(&model)?;
            let q = static_state(&rotor, rpm)?;
            let out = report_csv::static_deflection(&rotor.model.node_z, &q);
            let (peak_node, peak) = series::largest_deflection(&q, rotor.model.node_count());
            println!(
                "static deflection of {}: largest {:.4e} m at node {}",
                rotor.model.name,
                peak,
                peak_node + 1
            );
            match csv {
                Some(path) => write_file(&path, &out)?,
                None => print!("{out}"),
            }
        }
        Command::Modes {
            model,
            rpm,
            modes: count,
            csv,
        } => {
            let rotor = load(&model)?;
            let speed = rpm / RAD_S_TO_RPM;
            let options = ModalOptions {
                modes: count,
                ..ModalOptions::default()
            };
            let ms = modes_at(&rotor, speed, &options).map_err(|e| e.to_string())?;
            println!("{} at {rpm} rpm:", rotor.model.name);
            println!(" mode  ω_d (rad/s)    f_d (Hz)   damping ratio  log dec   whirl");
            for (k, m) in ms.iter().enumerate() {
                let f = m.damped_frequency / (2.0 * std::f64::consts::PI);
                println!(
                    "{:5} {:12.4} {:11.4} {:14.4e} {:9.4} {:>9}",
                    k + 1,
                    m.damped_frequency,
                    f,
                    m.damping_ratio,
                    m.log_decrement,
                    m.whirl.label()
                );
            }
            if let Some(path) = csv {
                write_file(&path, &report_csv::modes(rpm, &ms))?;
            }
        }
        Command::Campbell {
            model,
            max_rpm,
            steps,
            modes: count,
            csv,
            png,
        } => {
            if !(max_rpm.is_finite() && max_rpm > 0.0) || steps == 0 {
                return Err(format!(
                    "--max-rpm must be positive (got {max_rpm}) and --steps at least 1 (got {steps})"
                ));
            }
            let rotor = load(&model)?;
            let options = ModalOptions {
                modes: count,
                ..ModalOptions::default()
            };
            // Fluid-film bearings have no coefficients at standstill: start one step up.
            let first = usize::from(!rotor.nonlinear_bearings.is_empty());
            let speeds: Vec<f64> = (first..=steps)
                .map(|k| max_rpm / RAD_S_TO_RPM * k as f64 / steps as f64)
                .collect();
            let diagram = campbell(&rotor, &speeds, &options).map_err(|e| e.to_string())?;
            let criticals =
                critical_speeds(&rotor, &diagram, 1.0, &options).map_err(|e| e.to_string())?;
            println!(
                "critical speeds of {} (1× unbalance excitation):",
                rotor.model.name
            );
            for c in &criticals {
                println!(
                    "  {:10.2} rpm ({:9.3} rad/s)  branch {}  {} whirl  ζ = {:.3e}",
                    c.speed * RAD_S_TO_RPM,
                    c.speed,
                    c.rank + 1,
                    c.whirl.label(),
                    c.damping_ratio
                );
            }
            let out = report_csv::campbell(&diagram);
            match csv {
                Some(path) => write_file(&path, &out)?,
                None => print!("{out}"),
            }
            if let Some(path) = png {
                let title = format!("Campbell diagram: {}", rotor.model.name);
                campbell_png(&path, &title, &diagram, &[1.0], &criticals)
                    .map_err(|e| e.to_string())?;
                eprintln!("wrote {}", path.display());
            }
        }
        Command::Coefficients {
            model,
            bearing,
            rpm,
            points,
            csv,
            png,
        } => coefficients(model, bearing, rpm, points, csv, png)?,
        Command::FmuStage { model, dir } => {
            let m = RotorModel::from_file(&model).map_err(|e| e.to_string())?;
            let text =
                std::fs::read_to_string(&model).map_err(|e| format!("{}: {e}", model.display()))?;
            let (xml, guid) = rotor_bearing::fmi2::xml::model_description(&m);
            for sub in ["resources", "documentation", "binaries/linux64"] {
                std::fs::create_dir_all(dir.join(sub))
                    .map_err(|e| format!("{}: {e}", dir.join(sub).display()))?;
            }
            write_file(&dir.join("modelDescription.xml"), &xml)?;
            write_file(&dir.join("resources/model.toml"), &text)?;
            write_file(
                &dir.join("documentation/index.html"),
                &rotor_bearing::fmi2::docs::index_html(&m),
            )?;
            println!("{} {guid}", m.name);
        }
        Command::Simulate {
            model,
            rpm,
            ramp_rpm,
            speed_csv,
            duration,
            step,
            output_step,
            ramp_time,
            no_gravity,
            no_settle,
            csv,
            plots,
        } => {
            let profile = speed_profile(rpm, ramp_rpm.as_deref(), speed_csv.as_deref(), duration)?;
            let rotor = load(&model)?;
            let options = SolverOptions {
                time_step: step,
                unbalance_ramp_time: ramp_time,
                gravity: !no_gravity,
                ..SolverOptions::default()
            };
            let output_step = output_step.unwrap_or(step.max(duration / 20_000.0));
            let run = Run {
                profile,
                duration,
                output_step,
                settle: !no_settle,
                csv,
                plots,
            };
            simulate(rotor, options, run)?;
        }
    }
    Ok(())
}

fn speed_profile(
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
struct Run {
    profile: SpeedProfile,
    duration: f64,
    output_step: f64,
    settle: bool,
    csv: Option<PathBuf>,
    plots: Option<String>,
}

fn simulate(rotor: Rotor, options: SolverOptions, run: Run) -> Result<(), String> {
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
    let records = record(&mut sim, profile, duration, output_step, |f| {
        let pct = (f * 100.0) as usize;
        if terminal && pct >= shown + 5 {
            shown = pct - pct % 5;
            eprint!("\rsimulating {}: {shown:3}%", model.name);
        }
    })
    .map_err(|e| format!("{}: {e}", model.name))?;
    eprintln!(
        "{}simulated {} s of {} in {:.4} s wall-clock ({:?})",
        if terminal { "\r" } else { "" },
        duration,
        model.name,
        started.elapsed().as_secs_f64(),
        sim.stats()
    );
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
        let wf = waterfall(&t, &x, &y, &speed, output_step);
        println!("window  speed_rpm  dominant_Hz  ratio  amplitude_um");
        for (w, row) in wf.rows.iter().enumerate() {
            if let (Some((f, a)), Some(ratio)) = (row.peak, row.peak_order()) {
                println!(
                    "{w:6} {:10.1} {f:12.3} {ratio:6.3} {:12.4}",
                    row.speed * RAD_S_TO_RPM,
                    a * 1e6
                );
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
            &format!("Waterfall: {}", model.name),
            &wf.freqs,
            &rows,
        )
        .map_err(|e| e.to_string())?;
        eprintln!("wrote {}", path.display());
    }
    Ok(())
}

fn coefficients(
    model: Option<PathBuf>,
    bearing: Option<String>,
    rpm: f64,
    points: usize,
    csv: Option<PathBuf>,
    png: Option<PathBuf>,
) -> Result<(), String> {
    if !(rpm.is_finite() && rpm > 0.0) || points < 2 {
        return Err(format!(
            "--rpm must be positive (got {rpm}) and --points at least 2 (got {points})"
        ));
    }
    let (label, kind) = match &model {
        None => (
            "reference plain short bearing".to_string(),
            BearingKind::Plain(REFERENCE_BEARING),
        ),
        Some(path) => {
            let m = RotorModel::from_file(path).map_err(|e| e.to_string())?;
            let found = m.bearings.iter().find(|b| match &bearing {
                Some(name) => &b.name == name,
                None => b.kind.is_nonlinear(),
            });
            let b = found.ok_or_else(|| {
                let names: Vec<&str> = m.bearings.iter().map(|b| b.name.as_str()).collect();
                format!(
                    "{}: no {} among the bearings {names:?}",
                    path.display(),
                    bearing
                        .as_deref()
                        .map_or("hydrodynamic bearing".to_string(), |n| format!(
                            "bearing named {n:?}"
                        ))
                )
            })?;
            (format!("bearing {} of {}", b.name, m.name), b.kind.clone())
        }
    };
    let speed = rpm / RAD_S_TO_RPM;
    let Some(sweep) = dimensionless_curve(&kind, speed, points) else {
        return Err(format!("{label} is linear: its coefficients are constant"));
    };
    let mut curve = Vec::with_capacity(sweep.len());
    for (load, point) in sweep {
        match point {
            Ok(p) => curve.push(p),
            Err(e) => eprintln!("warning: {label}: no equilibrium at W = {load:.6e} N: {e}"),
        }
    }
    if curve.len() < 2 {
        return Err(format!("{label}: fewer than two equilibria found"));
    }
    println!("{label} at {rpm} rpm (load along −y; K̄ = K C/W, C̄ = C ω C/W):");
    println!("    ε     φ (°)     K̄xx     K̄xy     K̄yx     K̄yy     C̄xx     C̄xy     C̄yx     C̄yy");
    let mut eps = Vec::new();
    let mut kbar: Vec<Vec<f64>> = vec![Vec::new(); 4];
    let mut cbar: Vec<Vec<f64>> = vec![Vec::new(); 4];
    for p in &curve {
        let (kv, cv) = (p.stiffness, p.damping);
        println!(
            "{:6.3} {:8.2} {:8.3} {:8.3} {:8.3} {:8.3} {:8.3} {:8.3} {:8.3} {:8.3}",
            p.eccentricity,
            p.attitude_angle.to_degrees(),
            kv[0],
            kv[1],
            kv[2],
            kv[3],
            cv[0],
            cv[1],
            cv[2],
            cv[3]
        );
        eps.push(p.eccentricity);
        for i in 0..4 {
            kbar[i].push(kv[i]);
            cbar[i].push(cv[i]);
        }
    }
    if let Some(path) = csv {
        write_file(&path, &report_csv::coefficients(&curve))?;
    }
    if let Some(path) = png {
        let names = ["xx", "xy", "yx", "yy"];
        let k: Vec<(String, Vec<f64>)> = names
            .iter()
            .zip(kbar)
            .map(|(n, v)| (format!("K{n}"), v))
            .collect();
        let c: Vec<(String, Vec<f64>)> = names
            .iter()
            .zip(cbar)
            .map(|(n, v)| (format!("C{n}"), v))
            .collect();
        let title = format!("Dimensionless coefficients: {label}, {rpm} rpm");
        coefficients_png(&path, &title, &eps, &k, &c).map_err(|e| e.to_string())?;
        eprintln!("wrote {}", path.display());
    }
    Ok(())
}
