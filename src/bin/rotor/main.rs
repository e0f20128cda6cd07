//! `rotor`: command-line front end of the rotor-bearing library.
//!
//! ```text
//! rotor info     [MODEL.toml]
//! rotor draw     [MODEL.toml] --png FILE
//! rotor static   [MODEL.toml] [--rpm N] [--csv FILE] [--shaft-csv FILE]
//! rotor alignment [MODEL.toml] [--rpm N] [--target N1,N2,…]
//! rotor modes    [MODEL.toml] [--rpm N] [--modes K] [--csv FILE] [--shapes-csv FILE] [--shapes-png FILE]
//! rotor campbell [MODEL.toml] [--max-rpm N] [--steps S] [--modes K] [--operating-rpm A:B] [--csv FILE] [--png FILE]
//! rotor coefficients [MODEL.toml] [--bearing NAME] [--rpm N] [--points P] [--film model|short|finite] [--csv FILE] [--png FILE]
//! rotor simulate [MODEL.toml] (--rpm N | --ramp-rpm A:B | --speed-csv FILE) [--duration S] [--step S]
//!                [--output-step S] [--ramp-time S] [--no-gravity] [--amplitude 0-pk|pk-pk] [--csv FILE] [--plots PREFIX]
//! rotor unbalance [MODEL.toml] [--min-rpm N] [--max-rpm N] [--points P] [--node N --unbalance KGM]
//!                 [--operating-rpm A:B] [--amplitude 0-pk|pk-pk] [--csv FILE] [--png FILE]
//! rotor operating-point [MODEL.toml] --rpm N [--csv FILE] [--pads-csv FILE]
//! rotor ucs [MODEL.toml] [--min-stiffness K] [--max-stiffness K] [--points P] [--modes K] [--max-rpm N]
//!           [--speeds S] [--csv FILE] [--bearings-csv FILE] [--png FILE]
//! rotor report [MODEL.toml] [--rpm N] [--amplitude 0-pk|pk-pk] [--at NODES] [--power W --impeller-diameter D
//!              --flow-width H [--density-ratio R] [--stage-factor B]] --out FILE.html
//! rotor stability [MODEL.toml] --rpm N [--at NODES] [--cross-coupling-max Q] [--points P] [--modes K]
//!                 [--power W --impeller-diameter D --flow-width H …] [--csv FILE] [--png FILE]
//! ```
//! Without MODEL.toml the built-in classic disk-on-shaft rotor is used (and, for
//! `coefficients`, the reference plain short bearing).

mod alignment;
mod cases;
mod coefficients;
mod fmu_stage;
mod held;
mod modal;
mod model_input;
mod operating_point;
mod report;
mod response;
mod simulate;
mod simulate_args;
mod stability;
mod statics;
mod ucs;
mod unbalance;
mod warnings;

use std::path::{Path, PathBuf};
use std::process::ExitCode;

use clap::{Args, Parser, Subcommand};
pub(crate) use model_input::{load, model_rpm, read_model};
use rotor_bearing::units::Amplitude;
pub(crate) use warnings::{warn_short_films, warn_table_speeds};

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
    /// Field excitation of every magnetic pull (0 off, 1 nominal, up to 2),
    /// instead of the model file's: e.g. 1 to analyse a generator
    /// synchronized whose file starts it at standstill with the field off.
    #[arg(long)]
    excitation: Option<f64>,
}

/// Where the destabilizing cross-coupling acts and the machine data of its
/// anticipated size (`rotor stability` and `rotor report`).
#[derive(Args)]
struct StageArgs {
    /// Where the cross-coupling acts: node numbers or disk names, comma-separated,
    /// Q split equally; default where API 617 places it: mid-span between the bearings, or the overhung impellers (disks with role = "impeller", else every disk) of an overhung rotor.
    #[arg(long)]
    at: Option<String>,
    /// Rated power of the stages (W), for Wachel's anticipated cross-coupling Q_A.
    #[arg(long)]
    power: Option<f64>,
    /// Impeller diameter D (m).
    #[arg(long)]
    impeller_diameter: Option<f64>,
    /// Restrictive flow width H (m): the smaller of impeller discharge and diffuser widths.
    #[arg(long)]
    flow_width: Option<f64>,
    /// Discharge over suction density (1 for a liquid).
    #[arg(long, default_value_t = 1.0)]
    density_ratio: f64,
    /// Stage factor B: 3 for centrifugal impellers (Wachel), 1.5 for axial stages (Alford).
    #[arg(long, default_value_t = 3.0)]
    stage_factor: f64,
}

impl StageArgs {
    fn stages(&self) -> Result<Option<rotor_bearing::analysis::stability::StageData>, String> {
        stability::stages(
            self.power,
            self.impeller_diameter,
            self.flow_width,
            self.density_ratio,
            self.stage_factor,
        )
    }
}

#[derive(Subcommand)]
enum Command {
    /// Summarize a model: nodes, elements, masses, bearings.
    Info {
        #[command(flatten)]
        model: ModelArg,
    },
    /// Draw the rotor: shaft sections to scale, disks, bearings, probes, node numbers.
    Draw {
        #[command(flatten)]
        model: ModelArg,
        /// PNG file to draw to.
        #[arg(long)]
        png: PathBuf,
    },
    /// Static deflection under gravity: linear bearings, or fluid films in their
    /// static equilibrium at --rpm (at standstill the journals rest on their
    /// bushings or pads).
    Static {
        #[command(flatten)]
        model: ModelArg,
        /// Spin speed (rpm): fluid-film bearings carry load only when turning.
        #[arg(long, default_value_t = 0.0)]
        rpm: f64,
        /// Write node displacements to this CSV file.
        #[arg(long)]
        csv: Option<PathBuf>,
        /// Write the shaft's bending moment, shear and bending stress at both
        /// ends of every element to this CSV file.
        #[arg(long)]
        shaft_csv: Option<PathBuf>,
    },
    /// Bearing reactions of the shaft line at its offsets (offset_x, offset_y),
    /// the reaction influence matrix, the offsets for a target load sharing
    /// (default equal specific load W/(L·D)) and the shaft's largest bending stress.
    Alignment {
        #[command(flatten)]
        model: ModelArg,
        #[command(flatten)]
        args: alignment::AlignmentArgs,
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
        /// Write the complex mode shapes (x, y per node, orbit ellipses) to this CSV file.
        #[arg(long)]
        shapes_csv: Option<PathBuf>,
        /// Draw the mode shapes (orbits along the shaft) to this PNG file.
        #[arg(long)]
        shapes_png: Option<PathBuf>,
        /// Number of torsional modes listed after the lateral ones (0: none).
        /// Default: 3 for a model that describes its torsion (torque-driven,
        /// or with torque nodes, couplings or thrust bearings), else 0.
        #[arg(long)]
        torsional_modes: Option<usize>,
        /// Write the torsional mode shapes (twist per node) to this CSV file.
        #[arg(long)]
        torsional_shapes_csv: Option<PathBuf>,
    },
    /// Campbell diagram and critical speeds up to --max-rpm (from 0 on linear
    /// bearings, from 1 % of --max-rpm with fluid-film bearings); crossings with
    /// damping ratio ζ ≥ 0.5 are listed apart as overdamped, not as critical speeds.
    Campbell {
        #[command(flatten)]
        model: ModelArg,
        /// Highest spin speed (rpm). Default: 1.25 × the model's max_speed_rpm if
        /// the file states it, else 1.25 × its speed_rpm if given, else 4000.
        #[arg(long)]
        max_rpm: Option<f64>,
        /// Number of speed steps (the grid has steps + 1 points).
        #[arg(long, default_value_t = 40)]
        steps: usize,
        /// Number of oscillating modes per speed (overdamped roots are listed apart).
        #[arg(long, default_value_t = 8)]
        modes: usize,
        /// Operating speed range MIN:MAX (rpm) for the separation margins; default: the model's speed_rpm.
        #[arg(long)]
        operating_rpm: Option<String>,
        /// Write the diagram to this CSV file.
        #[arg(long)]
        csv: Option<PathBuf>,
        /// Draw the diagram to this PNG file.
        #[arg(long)]
        png: Option<PathBuf>,
        /// Threads the speeds are solved on (0: every core; the results are the same).
        #[arg(long, default_value_t = 0)]
        threads: usize,
    },
    /// Time simulation (Newmark + Newton–Raphson) with nonlinear bearings: CSV of
    /// bearing and probe outputs, orbit and full-spectrum plots.
    Simulate {
        #[command(flatten)]
        model: ModelArg,
        #[command(flatten)]
        args: simulate_args::SimulateArgs,
    },
    /// Write the generated parts of an FMU for MODEL into DIR: modelDescription.xml,
    /// resources/model.toml and documentation/index.html (fmu_pack.sh adds the binary).
    FmuStage {
        /// Model file.
        model: PathBuf,
        /// Staging directory.
        dir: PathBuf,
        /// FMI version of the model description: 2 (FMI 2.0) or 3 (FMI 3.0).
        #[arg(long, default_value_t = 2, value_parser = clap::value_parser!(u8).range(2..=3))]
        fmi: u8,
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
        /// Whirl frequency (Hz) the pad tilts of a tilting-pad bearing are
        /// condensed at; default the running speed (synchronous coefficients).
        #[arg(long)]
        whirl_frequency: Option<f64>,
        /// Number of load steps.
        #[arg(long, default_value_t = 60)]
        points: usize,
        /// Film model: `model` (the bearing's own film, as its entry's
        /// `film` key chooses; the default), `short` (Ocvirk, Gümbel
        /// cavitation) or `finite` (the finite-length Reynolds film,
        /// Swift–Stieber cavitation, on the bearing's geometry).
        #[arg(long, default_value = "model")]
        film: String,
        /// Write the coefficients to this CSV file.
        #[arg(long)]
        csv: Option<PathBuf>,
        /// Draw them to this PNG file.
        #[arg(long)]
        png: Option<PathBuf>,
    },
    /// Every bearing at one speed: static load, eccentricity, attitude angle,
    /// minimum film thickness, friction power, stiffness and damping.
    OperatingPoint {
        #[command(flatten)]
        model: ModelArg,
        /// Spin speed (rpm); default the model's speed_rpm.
        #[arg(long)]
        rpm: Option<f64>,
        /// Write one row per bearing to this CSV file.
        #[arg(long)]
        csv: Option<PathBuf>,
        /// Write the tilting pads' tilts and film thicknesses to this CSV file.
        #[arg(long)]
        pads_csv: Option<PathBuf>,
        #[command(flatten)]
        table: operating_point::FrequencyTableArgs,
    },
    /// Log decrements at a speed, the threshold of cross-coupled stiffness where API 617
    /// places it (mid-span, or the overhung impellers; or --at) where the least stable forward mode turns unstable, and with
    /// --power/--impeller-diameter/--flow-width the API 617 / API 684 Level I screening.
    Stability {
        #[command(flatten)]
        model: ModelArg,
        /// Spin speed (rpm); default the model's speed_rpm.
        #[arg(long)]
        rpm: Option<f64>,
        #[command(flatten)]
        stages: StageArgs,
        /// Operating range MIN:MAX (rpm) of an API class: its top is the maximum
        /// continuous speed of the API 617 Level II analysis. Default: the model's
        /// operating_rpm, else its speed_rpm, else --rpm.
        #[arg(long)]
        operating_rpm: Option<String>,
        /// Largest cross-coupled stiffness Q (N/m); default 10 × Q_A with stage data,
        /// else a tenth of the largest direct bearing stiffness.
        #[arg(long)]
        cross_coupling_max: Option<f64>,
        /// Number of Q values from 0 to the maximum.
        #[arg(long, default_value_t = 21)]
        points: usize,
        /// Number of modes listed (and searched for the least stable forward one).
        #[arg(long, default_value_t = 8)]
        modes: usize,
        /// Write log decrement against Q to this CSV file.
        #[arg(long)]
        csv: Option<PathBuf>,
        /// Write an API machine's API 617 Level II (each case's judged modes
        /// and verdict) to this CSV file.
        #[arg(long)]
        level_two_csv: Option<PathBuf>,
        /// Draw it to this PNG file.
        #[arg(long)]
        png: Option<PathBuf>,
        /// Ring the three least-damped modes down in the nonlinear transient
        /// from the equilibrium and print each one's log decrement beside the
        /// linear one (a disagreement beyond 5 % is flagged).
        #[arg(long)]
        verify: bool,
    },
    /// Undamped critical speed map: forward critical speeds against isotropic
    /// support stiffness, with the bearings' stiffness over a speed range.
    Ucs {
        #[command(flatten)]
        model: ModelArg,
        /// Softest support stiffness (N/m).
        #[arg(long, default_value_t = 1e5)]
        min_stiffness: f64,
        /// Stiffest support stiffness (N/m).
        #[arg(long, default_value_t = 1e10)]
        max_stiffness: f64,
        /// Number of stiffnesses (geometric spacing).
        #[arg(long, default_value_t = 31)]
        points: usize,
        /// Number of critical speeds per stiffness.
        #[arg(long, default_value_t = 4)]
        modes: usize,
        /// Highest speed (rpm) of the bearings' stiffness curves. Default: 1.25 × the
        /// higher of the model's max_speed_rpm and speed_rpm, else 4000.
        #[arg(long)]
        max_rpm: Option<f64>,
        /// Number of speeds of the bearings' stiffness curves.
        #[arg(long, default_value_t = 20)]
        speeds: usize,
        /// Write the map to this CSV file.
        #[arg(long)]
        csv: Option<PathBuf>,
        /// Write the bearings' kxx, kyy against speed to this CSV file.
        #[arg(long)]
        bearings_csv: Option<PathBuf>,
        /// Draw the map to this PNG file.
        #[arg(long)]
        png: Option<PathBuf>,
    },
    /// Tolerance cases ([cases]): every combination judged, the governing case of each criterion.
    Cases(cases::CasesArgs),
    /// One self-contained HTML page: model and drawing, operating point,
    /// unbalance response, modes and shapes, stability, critical speed map.
    Report {
        #[command(flatten)]
        model: ModelArg,
        /// Operating speed (rpm); default the model's speed_rpm.
        #[arg(long)]
        rpm: Option<f64>,
        /// Operating speed range MIN:MAX (rpm) the separation margins are
        /// judged against (API 684); default the operating speed alone.
        #[arg(long)]
        operating_rpm: Option<String>,
        /// Amplitudes as the orbit's semi-axis (0-pk) or twice it (pk-pk).
        #[arg(long, default_value = "0-pk", value_parser = parse_amplitude)]
        amplitude: Amplitude,
        #[command(flatten)]
        stages: StageArgs,
        /// HTML file to write.
        #[arg(long)]
        out: PathBuf,
    },
    /// Steady response of every probe and journal to one harmonic force of the
    /// model (a vortex rope, blade passing, a fixed-frequency excitation) over
    /// a speed range: the largest orbit of each, and a CSV of amplitude and
    /// phase at every speed.
    Response {
        #[command(flatten)]
        model: ModelArg,
        /// The harmonic force (`[[forces]]` name).
        #[arg(long)]
        force: String,
        /// Lowest spin speed (rpm).
        #[arg(long, default_value_t = 0.0)]
        min_rpm: f64,
        /// Highest spin speed (rpm).
        #[arg(long)]
        max_rpm: f64,
        /// Number of speeds.
        #[arg(long, default_value_t = 200)]
        points: usize,
        /// The force's amplitude (N), instead of the model file's.
        #[arg(long)]
        magnitude: Option<f64>,
        /// Write the response to this CSV file.
        #[arg(long)]
        csv: Option<PathBuf>,
    },
    /// Unbalance response over a speed range (Bode and polar plots), its peaks,
    /// amplification factors and API 684 separation margins.
    ///
    /// An API machine (`machine = "compressor" | "steam_turbine" | "pump"`) also gets its API 684/617 unbalance cases.
    Unbalance {
        #[command(flatten)]
        model: ModelArg,
        /// Lowest spin speed (rpm).
        #[arg(long, default_value_t = 0.0)]
        min_rpm: f64,
        /// Highest spin speed (rpm). Default: 1.25 × the highest of the model's
        /// max_speed_rpm, its speed_rpm and the top of --operating-rpm, else 4000.
        #[arg(long)]
        max_rpm: Option<f64>,
        /// Number of evenly spaced speeds (both ends included), refined near resonances.
        #[arg(long, default_value_t = 200)]
        points: usize,
        /// Excite with one unbalance at this node (numbered from 1) instead of the model's planes.
        #[arg(long)]
        node: Option<usize>,
        /// Size of that unbalance (kg·m).
        #[arg(long, default_value_t = 1e-3, requires = "node")]
        unbalance: f64,
        /// Operating speed range MIN:MAX (rpm) for the separation margins; default: the model's speed_rpm.
        #[arg(long)]
        operating_rpm: Option<String>,
        /// Amplitudes as the orbit's semi-axis (0-pk) or twice it (pk-pk), in tables, on axes and in the CSV's amplitude columns.
        #[arg(long, default_value = "0-pk", value_parser = parse_amplitude)]
        amplitude: Amplitude,
        /// Write the response to this CSV file.
        #[arg(long)]
        csv: Option<PathBuf>,
        /// Draw the Bode and polar plots to this PNG file.
        #[arg(long)]
        png: Option<PathBuf>,
    },
}

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

/// `--amplitude 0-pk|pk-pk`.
pub(crate) fn parse_amplitude(text: &str) -> Result<Amplitude, String> {
    Amplitude::parse(text)
}

fn write_file(path: &Path, text: &str) -> Result<(), String> {
    std::fs::write(path, text).map_err(|e| format!("{}: cannot write: {e}", path.display()))?;
    eprintln!("wrote {}", path.display());
    Ok(())
}

fn run(cli: Cli) -> Result<(), String> {
    match cli.command {
        Command::Info { model } => statics::info(&load(&model)?),
        Command::Draw { model, png } => statics::draw(&load(&model)?, &png),
        Command::Static {
            model,
            rpm,
            csv,
            shaft_csv,
        } => statics::deflection(&load(&model)?, rpm, csv, shaft_csv),
        Command::Alignment { model, args } => alignment::run(&load(&model)?, args),
        Command::Modes {
            model,
            rpm,
            modes,
            csv,
            shapes_csv,
            shapes_png,
            torsional_modes,
            torsional_shapes_csv,
        } => modal::modes(
            &load(&model)?,
            rpm,
            (modes, torsional_modes),
            modal::ModeFiles {
                csv,
                shapes_csv,
                shapes_png,
                torsional_shapes_csv,
            },
        ),
        Command::Campbell {
            model,
            max_rpm,
            steps,
            modes,
            operating_rpm,
            csv,
            png,
            threads,
        } => modal::campbell_diagram(
            &load(&model)?,
            modal::CampbellRequest {
                max_rpm,
                steps,
                modes,
                operating_rpm,
                csv,
                png,
                threads,
            },
        ),
        Command::Coefficients {
            model,
            bearing,
            rpm,
            whirl_frequency,
            points,
            film,
            csv,
            png,
        } => coefficients::coefficients(
            model,
            bearing,
            (rpm, whirl_frequency),
            (points, &film),
            csv,
            png,
        ),
        Command::Response {
            model,
            force,
            min_rpm,
            max_rpm,
            points,
            magnitude,
            csv,
        } => response::run(
            &load(&model)?,
            response::Request {
                force,
                min_rpm,
                max_rpm,
                points,
                magnitude,
                csv,
            },
        ),
        Command::Unbalance {
            model,
            min_rpm,
            max_rpm,
            points,
            node,
            unbalance: size,
            operating_rpm,
            amplitude,
            csv,
            png,
        } => unbalance::unbalance(
            &load(&model)?,
            unbalance::Request {
                min_rpm,
                max_rpm,
                points,
                node,
                unbalance: size,
                operating_rpm,
                amplitude,
                csv,
                png,
            },
        ),
        Command::OperatingPoint {
            model,
            rpm,
            csv,
            pads_csv,
            table,
        } => {
            let rotor = load(&model)?;
            let rpm = model_rpm(&rotor.model, rpm)?;
            operating_point::run(&rotor, rpm, (csv, pads_csv), table)
        }
        Command::Stability {
            model,
            rpm,
            stages,
            operating_rpm,
            cross_coupling_max,
            points,
            modes,
            csv,
            level_two_csv,
            png,
            verify,
        } => {
            let rotor = load(&model)?;
            let rpm = model_rpm(&rotor.model, rpm)?;
            let operating = modal::operating_range(&rotor, operating_rpm.as_deref())?;
            stability::run(
                &rotor,
                stability::Request {
                    rpm,
                    operating,
                    q_max: cross_coupling_max,
                    points,
                    modes,
                    stages: stages.stages()?,
                    at: stages.at,
                    csv,
                    level_two_csv,
                    png,
                    verify,
                },
            )
        }
        Command::Ucs {
            model,
            min_stiffness,
            max_stiffness,
            points,
            modes,
            max_rpm,
            speeds,
            csv,
            bearings_csv,
            png,
        } => ucs::run(
            &load(&model)?,
            ucs::Request {
                min_stiffness,
                max_stiffness,
                points,
                criticals: modes,
                max_rpm,
                speeds,
                csv,
                bearings_csv,
                png,
            },
        ),
        Command::Cases(args) => cases::command(&args),
        Command::Report {
            model,
            rpm,
            operating_rpm,
            amplitude,
            stages,
            out,
        } => {
            let rotor = load(&model)?;
            report::run(
                &rotor,
                report::Request {
                    source: model.model.clone(),
                    rpm,
                    operating: operating_rpm
                        .as_deref()
                        .map(unbalance::operating_range)
                        .transpose()?,
                    operating_rpm,
                    amplitude,
                    sites: stability::sites(&rotor, stages.at.as_deref())?,
                    stages: stages.stages()?,
                    out,
                },
            )
        }
        Command::FmuStage { model, dir, fmi } => fmu_stage::stage(&model, &dir, fmi),
        Command::Simulate { model, args } => simulate_args::run(load(&model)?, args),
    }
}
