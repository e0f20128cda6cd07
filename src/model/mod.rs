//! Rotor model files (TOML) and the validated [`RotorModel`] they produce.
//!
//! `RotorModel` is plain data in SI units that has passed every check: the rest of
//! the crate never sees an unchecked number. Errors name the file, the field
//! (as a path such as `shaft[2].outer_diameter`), the offending value and, when
//! the TOML parser knows it, the line.

mod build;
mod context;
mod error;
pub mod file;
mod file_bearings;
pub mod impeller_stage;
pub mod limits;
mod load_inputs;
pub mod machine_class;
mod nodes;
mod plausibility;
pub mod schema;
pub mod shaft_zones;
mod source_map;
pub mod speed_table;
pub mod tolerance_cases;

pub use error::ModelError;
use error::Seg;
pub use load_inputs::{LoadChannel, LoadInput};
pub use plausibility::{
    CLEARANCE_RATIO_RANGE, ModelWarning, PEDESTAL_MASS_RATIO, PEDESTAL_STIFFNESS_RANGE,
    RADIUS_TOLERANCE, VISCOSITY_RANGE,
};

use std::path::Path;

use crate::bearing::BearingKind;
use crate::fe::disk::Disk;
use crate::fe::shaft::ShaftElement;
use context::Ctx;
use file::ModelFile;
use source_map::{culprit_in_entry, field_at, line_of, line_of_field};

/// Default largest spin speed (rpm) of a model that states none: above any
/// hydro, pump or turbine rotor, so only nonsense is refused.
pub const DEFAULT_MAX_SPEED_RPM: f64 = 60_000.0;

/// Fixed-interface modes a reduced rotor keeps when the model's `[reduction]`
/// gives no `modes` and the model no speed (neither `speed_rpm` nor
/// `max_speed_rpm`) to choose them by (see [`crate::rotor::Rotor::transient_modes`]).
pub const DEFAULT_REDUCED_MODES: usize = 10;

/// Most fixed-interface modes a reduced rotor may keep (its matrices are dense).
pub const MAX_REDUCED_MODES: usize = 1000;

/// Default memory budget (MB) of a model: its assembled matrices, factors and
/// work vectors must fit, estimated at [`BYTES_PER_DOF`] per degree of freedom.
pub const DEFAULT_MEMORY_BUDGET_MB: f64 = 4096.0;

/// Memory per degree of freedom of an assembled rotor in the simulator (bytes):
/// the measured peak is about 1.2 kB per DOF (BENCHMARKS.md, scaling), with margin.
pub const BYTES_PER_DOF: f64 = 1536.0;

/// The built-in default model: the classic disk-on-shaft rotor.
pub const DEFAULT_MODEL_NAME: &str = "classic_disk_rotor";
/// Text of the default model file (shipped as `models/classic_disk_rotor.toml`).
pub const DEFAULT_MODEL_TOML: &str = include_str!("../../models/classic_disk_rotor.toml");

/// A shaft element placed between nodes `node` and `node + 1` (0-based).
#[derive(Debug, Clone, PartialEq)]
pub struct PlacedElement {
    /// Index of the left node (0-based).
    pub node: usize,
    /// The element's section, material and effects.
    pub element: ShaftElement,
    /// Axial tension carried by the element (N, compression negative).
    pub axial_force: f64,
    /// Viscous torsional damping of the element (N·m·s/rad) between its two
    /// nodes' twists: its section's `torsional_damping` times the section's
    /// element count, so that the elements in series give the section's.
    pub torsional_damping: f64,
}

/// A disk on a node.
#[derive(Debug, Clone, PartialEq)]
pub struct PlacedDisk {
    /// Name (default `disk<k>`).
    pub name: String,
    /// Node index (0-based).
    pub node: usize,
    /// Inertia properties.
    pub disk: Disk,
    /// An impeller (stage, runner): `role = "impeller"`.
    pub impeller: bool,
    /// An impeller's stage data for Wachel's anticipated cross-coupling
    /// (`stage_power`, `impeller_diameter`, `flow_width`, …); `None` without.
    pub stage: Option<impeller_stage::ImpellerStage>,
}

/// A bearing between a shaft node (the journal) and its housing: ground, or
/// a pedestal.
#[derive(Debug, Clone, PartialEq)]
pub struct PlacedBearing {
    /// Name (default `bearing<k>`).
    pub name: String,
    /// Node index (0-based).
    pub node: usize,
    /// Bearing type and parameters.
    pub kind: BearingKind,
    /// The pedestal its housing stands on (index into
    /// [`RotorModel::pedestals`]); `None`: rigid ground.
    pub pedestal: Option<usize>,
    /// Housing centre off the nominal straight axis `(o_x, o_y)` (m; relative
    /// to its pedestal when it stands on one): the bearing's laws see the
    /// journal at `q − o` (`offset_x`, `offset_y`; zero: on the axis).
    pub offset: [f64; 2],
}

impl PlacedBearing {
    /// The bearing model as installed: [`BearingKind::build`] about the
    /// centre [`Self::offset`] ([`crate::bearing::offset::installed`]).
    pub fn build(&self) -> Box<dyn crate::bearing::Bearing> {
        crate::bearing::offset::installed(self.kind.build(), self.offset)
    }

    /// Whether the housing centre is off the nominal axis.
    pub fn is_offset(&self) -> bool {
        self.offset != [0.0, 0.0]
    }
}

/// A bearing support in series with its bearings (`[[pedestals]]`): a
/// non-rotating lumped mass on a spring–damper to ground, or to the pedestal
/// it stands on (a bracket on a foundation). Its force on the mass is
/// `F = −K (q − q_on) − C (q̇ − q̇_on)`.
#[derive(Debug, Clone, PartialEq)]
pub struct Pedestal {
    /// Name, unique among the pedestals.
    pub name: String,
    /// Mass (kg), the same in `x` and `y`.
    pub mass: f64,
    /// Stiffness (N/m), row-major `[[kxx, kxy], [kyx, kyy]]`.
    pub stiffness: [[f64; 2]; 2],
    /// Damping (N·s/m), row-major.
    pub damping: [[f64; 2]; 2],
    /// The pedestal it stands on (index, always an earlier-validated
    /// acyclic chain); `None`: ground.
    pub on: Option<usize>,
    /// Where its spring is anchored off the nominal axis `(o_x, o_y)` (m,
    /// relative to `on`): `F = −K (q − q_on − o) − C (q̇ − q̇_on)`
    /// (`offset_x`, `offset_y`; zero: on the axis).
    pub offset: [f64; 2],
    /// Braced against the generator stator (`on_stator`): the housings it
    /// carries are ISO 10816-5 group 4's measurement location 1.
    pub on_stator: bool,
}

/// A file a model reads besides its own: the path as written in the model
/// (relative to the model file's folder, or absolute) and the path read.
pub type TableFile = (String, std::path::PathBuf);

/// A non-rotating lumped mass at a node (`[[point_masses]]`): a coupling
/// hub, a housing carried by the shaft, a collar.
#[derive(Debug, Clone, PartialEq)]
pub struct PointMass {
    /// Name (default `point_mass<k>`).
    pub name: String,
    /// Node index (0-based).
    pub node: usize,
    /// Mass in `x` and in `y` (kg).
    pub mass: [f64; 2],
}

/// An unbalance plane: a mass `m` at radius `e` rotating with the shaft.
#[derive(Debug, Clone, PartialEq)]
pub struct UnbalancePlane {
    /// Name (default `unbalance<k>`).
    pub name: String,
    /// Node index (0-based).
    pub node: usize,
    /// Unbalance `m·e` (kg·m).
    pub magnitude: f64,
    /// Angular position at spin angle zero, from +x toward +y (rad).
    pub phase: f64,
}

/// How a harmonic force's frequency is set.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum HarmonicFrequency {
    /// A multiple of the running speed: the force's angle is the ratio times
    /// the spin angle (so it follows a run-up).
    Ratio(f64),
    /// A fixed frequency (rad/s).
    Fixed(f64),
}

/// How a harmonic force acts.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum HarmonicDirection {
    /// Rotating in the spin direction: `A (cos θ, sin θ)`.
    Forward,
    /// Rotating against it: `A (cos θ, −sin θ)`.
    Backward,
    /// Along a fixed line at this angle (rad, from +x toward +y): `A cos θ (cos α, sin α)`.
    Fixed(f64),
}

/// What an external force is.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum ForceKind {
    /// A constant force `(fx, fy)` (N), e.g. a hydraulic radial thrust.
    Static([f64; 2]),
    /// A harmonic force of amplitude `magnitude` (N) and angle
    /// `θ = phase + ratio × spin angle` or `phase + ω t`.
    Harmonic {
        magnitude: f64,
        /// Phase at time 0 and spin angle 0 (rad).
        phase: f64,
        frequency: HarmonicFrequency,
        direction: HarmonicDirection,
    },
}

/// An external force at a node (`[[forces]]`).
#[derive(Debug, Clone, PartialEq)]
pub struct ExternalForce {
    /// Name (default `force<k>`).
    pub name: String,
    /// Node index (0-based).
    pub node: usize,
    /// Static or harmonic.
    pub kind: ForceKind,
}

/// A node where another model pushes on the rotor (`[[ports]]`): FMU inputs
/// `ports.<p>.fx`, `fy`, outputs its motion.
#[derive(Debug, Clone, PartialEq)]
pub struct Port {
    /// Name, unique among the ports.
    pub name: String,
    /// Node index (0-based).
    pub node: usize,
}

/// How the shaft is driven (`[torsion] drive`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Drive {
    /// The shaft follows a prescribed speed (the `shaft.speed` input).
    #[default]
    Speed,
    /// Torques at the `[[torques]]` nodes drive the shaft's twist.
    Torque,
}

/// A coupling between two shafts of a train at shaft element `element`
/// (index into [`RotorModel::elements`]): torsionally it takes the
/// element's torsional stiffness and damping when it has its own; laterally
/// it is a [`CouplingJoint`].
#[derive(Debug, Clone, PartialEq)]
pub struct Coupling {
    /// Name (default `coupling<k>`).
    pub name: String,
    /// The element it sits at (it joins the element's left node to its right).
    pub element: usize,
    /// Torsional stiffness (N·m/rad); `None`: the element keeps its own.
    pub stiffness: Option<f64>,
    /// Torsional damping (N·m·s/rad).
    pub damping: f64,
    /// The lateral joint.
    pub joint: CouplingJoint,
    /// Misalignment of the shaft after the coupling relative to the one
    /// before, on the DOFs `[x, y, θx, θy]` (m, rad): a parallel offset
    /// `(x, y)` and an angular one `θy = dx/dz`, `θx = −dy/dz`.
    pub misalignment: [f64; 4],
}

/// How a coupling joins its two shafts laterally.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum CouplingJoint {
    /// A rigid flange: the shaft element stays; the shaft after the flange
    /// starts at the misalignment from the one before (an initial strain of
    /// the element, [`crate::rotor::Rotor::add_offset_loads`]).
    Flange,
    /// A flexible coupling: the shaft element is replaced by a zero-length
    /// spring–damper between its nodes, `lateral` on the relative
    /// translations and `angular` on the relative rotations (ROSS's
    /// `CouplingElement`, no masses of its own).
    Flexible {
        /// Lateral stiffness (N/m) and damping (N·s/m).
        lateral: [f64; 2],
        /// Angular stiffness (N·m/rad) and damping (N·m·s/rad).
        angular: [f64; 2],
    },
}

impl Coupling {
    /// Whether it changes the lateral model: a flexible joint or a
    /// misalignment (a flange without one is the shaft element as it was).
    pub fn is_lateral(&self) -> bool {
        matches!(self.joint, CouplingJoint::Flexible { .. }) || self.is_misaligned()
    }

    /// Whether it has a misalignment.
    pub fn is_misaligned(&self) -> bool {
        self.misalignment != [0.0; 4]
    }
}

/// A node where a drive or load torque acts (`[[torques]]`).
#[derive(Debug, Clone, PartialEq)]
pub struct TorqueNode {
    /// Name, unique among the torques.
    pub name: String,
    /// Node index (0-based).
    pub node: usize,
}

/// A thrust bearing at a node (`[[thrust_bearings]]`).
#[derive(Debug, Clone, PartialEq)]
pub struct PlacedThrustBearing {
    /// Name (default `thrust<k>`).
    pub name: String,
    /// Node index (0-based).
    pub node: usize,
    /// Its friction model.
    pub bearing: crate::bearing::thrust::ThrustBearing,
}

/// A named node whose displacements are reported.
#[derive(Debug, Clone, PartialEq)]
pub struct Probe {
    /// Name, unique in the model.
    pub name: String,
    /// Node index (0-based).
    pub node: usize,
    /// The model bearing (index) whose installed centre — its housing's
    /// motion plus its offset — the probe measures from (`relative_to`);
    /// `None`: from the nominal axis.
    pub relative_to: Option<usize>,
}

/// Ideal constraints at a node: `fixed[k]` fixes node DOF `k` (see [`crate::fe`]).
#[derive(Debug, Clone, PartialEq)]
pub struct Support {
    /// Node index (0-based).
    pub node: usize,
    /// Which of `(x, y, θx, θy)` are fixed.
    pub fixed: [bool; 4],
    /// Whether the twist about `z` is fixed (`"rz"`: torsional analyses only).
    pub twist: bool,
}

/// A validated rotor model, SI units.
#[derive(Debug, Clone, PartialEq)]
pub struct RotorModel {
    /// Identifier (letters, digits, `_`).
    pub name: String,
    /// Free text.
    pub description: String,
    /// Where the model came from (file path or `<built-in>`).
    pub source: String,
    /// Axial position of every node (m), increasing.
    pub node_z: Vec<f64>,
    /// Shaft elements, in node order.
    pub elements: Vec<PlacedElement>,
    /// Disks.
    pub disks: Vec<PlacedDisk>,
    /// Non-rotating point masses.
    pub point_masses: Vec<PointMass>,
    /// Bearings, then rubs, then seals (each a [`BearingKind`] between a
    /// rotor node and its housing).
    pub bearings: Vec<PlacedBearing>,
    /// Unbalance planes.
    pub unbalances: Vec<UnbalancePlane>,
    /// Probes.
    pub probes: Vec<Probe>,
    /// External static and harmonic forces.
    pub forces: Vec<ExternalForce>,
    /// Force ports.
    pub ports: Vec<Port>,
    /// Flexible couplings of the torsional chain.
    pub couplings: Vec<Coupling>,
    /// Torque nodes.
    pub torques: Vec<TorqueNode>,
    /// Thrust bearings.
    pub thrust_bearings: Vec<PlacedThrustBearing>,
    /// How the shaft is driven.
    pub drive: Drive,
    /// Modal damping ratio `ζ_m` of the listed torsional modes (–,
    /// `[torsion] damping_ratio`; `analysis::torsion`).
    pub torsional_damping_ratio: f64,
    /// Ideal supports.
    pub supports: Vec<Support>,
    /// Bearing supports (pedestals, brackets, foundations) in series with bearings.
    pub pedestals: Vec<Pedestal>,
    /// Gravity vector (m/s²), `z` along the shaft.
    pub gravity: [f64; 3],
    /// Nominal spin speed (rad/s), 0 when the file gives none.
    pub nominal_speed: f64,
    /// Largest spin speed in either direction (rad/s): inputs beyond it are refused.
    pub max_speed: f64,
    /// Whether the file states `max_speed_rpm` (else `max_speed` is
    /// [`DEFAULT_MAX_SPEED_RPM`]).
    pub max_speed_stated: bool,
    /// Operating speed range `[min, max]` (rad/s) from `operating_rpm`.
    pub operating_range: Option<[f64; 2]>,
    /// The machine's class (`machine`), selecting the criteria it is judged by.
    pub machine: machine_class::MachineClass,
    /// Its ISO 10816-5 machine group (`housing_group`), for a hydro class.
    pub housing_group: Option<machine_class::HousingGroup>,
    /// The electrical grid frequency (Hz, `grid_frequency_hz`) a hydro
    /// class's torsional modes are judged against; `None`: not judged.
    pub grid_frequency: Option<f64>,
    /// The separation (fraction, `torsional_margin`) a hydro class's
    /// torsional natural frequencies keep from the running speed and the
    /// grid frequency and its double; `None`: the default
    /// [`machine_class::DEFAULT_TORSIONAL_MARGIN`].
    pub torsional_margin: Option<f64>,
    /// Coefficient-table files read, as written and as resolved ([`Self::table_files`]).
    pub table_files: Vec<TableFile>,
    /// The reduced rotor transients run on (`[reduction]`, see
    /// [`crate::rotor::Rotor::reduced`]); `None`: the full rotor.
    pub reduction: Option<ReductionRequest>,
    /// The tolerance cases (`[cases]`), `None` without the section.
    pub tolerance_cases: Option<tolerance_cases::ToleranceCases>,
    /// `[shaft_vibration_zones]` of a hydro class: the zones its shaft
    /// orbits are judged by, from the user's copy of the standard.
    pub shaft_zones: Option<shaft_zones::ShaftZones>,
}

/// What a model's `[reduction]` asks for.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ReductionRequest {
    /// `modes = m`: that many fixed-interface modes.
    Modes(usize),
    /// No `modes`: as many as the model's speed range needs
    /// ([`crate::rotor::Rotor::transient_modes`]).
    FromSpeedRange,
}

impl RotorModel {
    /// Read and validate a model file.
    pub fn from_file(path: &Path) -> Result<Self, ModelError> {
        let source = path.display().to_string();
        let text = std::fs::read_to_string(path).map_err(|e| ModelError::Io {
            file: source.clone(),
            message: e.to_string(),
        })?;
        Self::from_toml(&text, &source)
    }

    /// The built-in default model (the classic disk-on-shaft rotor).
    pub fn default_model() -> Self {
        match Self::from_toml(DEFAULT_MODEL_TOML, "<built-in classic_disk_rotor.toml>") {
            Ok(model) => model,
            Err(e) => unreachable!("the built-in model is checked by tests: {e}"),
        }
    }

    /// Parse and validate model text; `source` names it in error messages.
    ///
    /// ```
    /// use rotor_bearing::model::RotorModel;
    ///
    /// let text = r#"
    /// name = "overhung"
    /// [[materials]]
    /// name = "steel"
    /// youngs_modulus = 211e9
    /// poisson_ratio = 0.3
    /// density = 7810.0
    ///
    /// [[shaft]]
    /// length = 0.8
    /// outer_diameter = 0.04
    /// material = "steel"
    /// elements = 4
    ///
    /// [[disks]]
    /// z = 0.8
    /// mass = 5.0
    /// polar_inertia = 0.02
    /// diametral_inertia = 0.01
    ///
    /// [[bearings]]
    /// type = "linear"
    /// node = 1
    /// kxx = 1e7
    /// kyy = 1e7
    ///
    /// [[bearings]]
    /// type = "plain"
    /// z = 0.4
    /// radius = 0.02
    /// length = 0.02
    /// clearance = 4e-5
    /// viscosity = 0.03
    /// "#;
    /// let model = RotorModel::from_toml(text, "overhung.toml")?;
    /// assert_eq!(model.node_count(), 5);
    /// assert_eq!(model.disks[0].node, 4); // z = 0.8 m is the fifth node
    /// assert_eq!(model.bearings[1].name, "bearing2");
    /// assert!(model.bearings[1].kind.is_nonlinear());
    ///
    /// // Errors name the file, line, field path and value.
    /// let bad = text.replace("mass = 5.0", "mass = -5.0");
    /// let err = RotorModel::from_toml(&bad, "overhung.toml").unwrap_err();
    /// assert!(err.to_string().starts_with("overhung.toml:17: disks[0].mass = -5:"));
    /// # Ok::<(), rotor_bearing::model::ModelError>(())
    /// ```
    pub fn from_toml(text: &str, source: &str) -> Result<Self, ModelError> {
        let cache = crate::bearing::film_table_cache::cache_dir();
        Self::from_toml_cached(text, source, cache.as_deref())
    }

    /// [`Self::from_file`] with the force tables of plain finite films
    /// (`film_tables = true`) cached in `film_cache` (`None`: built in
    /// memory) instead of the user's cache directory
    /// ([`crate::bearing::film_table_cache::cache_dir`]): an FMU's
    /// resources.
    pub fn from_file_cached(path: &Path, film_cache: Option<&Path>) -> Result<Self, ModelError> {
        let source = path.display().to_string();
        let text = std::fs::read_to_string(path).map_err(|e| ModelError::Io {
            file: source.clone(),
            message: e.to_string(),
        })?;
        Self::from_toml_cached(&text, &source, film_cache)
    }

    /// [`Self::from_toml`] with the force tables cached in `film_cache`
    /// (see [`Self::from_file_cached`]).
    pub fn from_toml_cached(
        text: &str,
        source: &str,
        film_cache: Option<&Path>,
    ) -> Result<Self, ModelError> {
        let raw: ModelFile = toml::from_str(text).map_err(|e| {
            let span = e.span();
            let line = span.as_ref().map(|s| line_of(text, s.start));
            let mut message = e.message().trim().to_string();
            // A key given twice: name it (the parser says only "duplicate key").
            if message == "duplicate key"
                && let Some(s) = span.as_ref()
            {
                let start = text[..s.start].rfind('\n').map_or(0, |i| i + 1);
                let key = text[start..].split(['=', '\n']).next().unwrap_or("").trim();
                if !key.is_empty() {
                    message = format!("duplicate key {key} (a key is given once per entry)");
                }
            }
            let message = message.as_str();
            let path = span.and_then(|s| field_at(text, &s));
            // A whole entry read at once (bearings, chosen by `type`): name the key.
            let culprit = path.as_ref().and_then(|p| {
                culprit_in_entry(text, p, message).or_else(|| {
                    // The span may be that of a neighbouring entry of the same array.
                    let (Some(Seg::Index(_)), Some(parent)) = (p.0.last(), p.parent()) else {
                        return None;
                    };
                    (0..256).find_map(|i| culprit_in_entry(text, &parent.index(i), message))
                })
            });
            let line = culprit
                .as_ref()
                .and_then(|p| line_of_field(text, p))
                .or(line);
            let message = match culprit.or(path) {
                Some(path) => format!("{path}: {message}"),
                None => message.to_string(),
            };
            ModelError::Syntax {
                file: source.to_string(),
                line,
                message,
            }
        })?;
        let ctx = Ctx {
            text,
            source,
            film_cache,
        };
        build::build(&ctx, raw)
    }

    /// Where each pedestal's DOFs are numbered: `(pedestal, node)` with node
    /// the lowest journal node of the bearings standing on it, directly or
    /// through the pedestals on it (node 0 for a pedestal that carries none).
    pub fn pedestal_anchors(&self) -> Vec<(usize, usize)> {
        let mut anchor = vec![usize::MAX; self.pedestals.len()];
        for b in &self.bearings {
            let mut at = b.pedestal;
            // Up the chain: every pedestal below this bearing carries it.
            while let Some(p) = at {
                anchor[p] = anchor[p].min(b.node);
                at = self.pedestals[p].on;
            }
        }
        anchor
            .into_iter()
            .map(|node| if node == usize::MAX { 0 } else { node })
            .enumerate()
            .collect()
    }

    /// Files the model reads besides its own (coefficient tables), as
    /// written in it (relative to the model file's folder) with the path
    /// they were read from.
    pub fn table_files(&self) -> &[TableFile] {
        &self.table_files
    }

    /// Whether the model describes its torsion: torque-driven, or with torque
    /// nodes, torsional couplings or thrust bearings. Analyses list torsional modes
    /// for such a model by default.
    pub fn models_torsion(&self) -> bool {
        self.drive == Drive::Torque
            || !self.torques.is_empty()
            || self.couplings.iter().any(|c| c.stiffness.is_some())
            || !self.thrust_bearings.is_empty()
    }

    /// Whether any bearing, seal, stator or pedestal is set off the nominal
    /// axis (`offset_x`, `offset_y`).
    pub fn has_offsets(&self) -> bool {
        self.bearings.iter().any(PlacedBearing::is_offset)
            || self.pedestals.iter().any(|p| p.offset != [0.0, 0.0])
    }

    /// The same model with every centre offset scaled by `s` (a step of the
    /// statics' continuation from the aligned line, `s = 0`, to `s = 1`).
    pub fn with_offsets_scaled(&self, s: f64) -> RotorModel {
        let mut model = self.clone();
        for o in model
            .bearings
            .iter_mut()
            .map(|b| &mut b.offset)
            .chain(model.pedestals.iter_mut().map(|p| &mut p.offset))
        {
            *o = [s * o[0], s * o[1]];
        }
        model
    }

    /// Whether a flexible coupling replaces shaft element `element`.
    pub fn flexible_coupling_at(&self, element: usize) -> bool {
        self.couplings
            .iter()
            .any(|c| c.element == element && matches!(c.joint, CouplingJoint::Flexible { .. }))
    }

    /// The shaft elements that are shaft (not replaced by a flexible coupling).
    fn shaft_elements(&self) -> impl Iterator<Item = &PlacedElement> {
        let shaft = |(k, _): &(usize, &PlacedElement)| !self.flexible_coupling_at(*k);
        self.elements
            .iter()
            .enumerate()
            .filter(shaft)
            .map(|(_, e)| e)
    }

    /// Total rotating mass: shaft plus disks (kg); the hubs of a flexible
    /// coupling are disks, its element none.
    pub fn total_mass(&self) -> f64 {
        self.shaft_elements().map(|e| e.element.mass()).sum::<f64>()
            + self.disks.iter().map(|d| d.disk.mass).sum::<f64>()
    }

    /// Total polar inertia about the shaft axis: shaft `ρ J_p L` plus the
    /// disks' (kg·m²).
    pub fn total_polar_inertia(&self) -> f64 {
        self.shaft_elements()
            .map(|e| {
                e.element.material.density * e.element.section.polar_moment() * e.element.length
            })
            .sum::<f64>()
            + self.disks.iter().map(|d| d.disk.polar_inertia).sum::<f64>()
    }

    /// The top speed (rad/s) transients of this model are prepared for (the
    /// default time step, the modes a reduced rotor keeps): its
    /// `max_speed_rpm` when the file states it, else its `speed_rpm` when not
    /// zero.
    pub fn transient_top_speed(&self) -> Option<f64> {
        if self.max_speed_stated {
            Some(self.max_speed.abs())
        } else {
            (self.nominal_speed != 0.0).then_some(self.nominal_speed.abs())
        }
    }
}

#[cfg(test)]
mod tests;
#[cfg(test)]
mod tests_machine;
#[cfg(test)]
mod tests_plausibility;
