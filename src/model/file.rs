//! The TOML model file as written by a user: plain serde structs, every unknown
//! key rejected. Validation into a [`super::RotorModel`] happens in `build`.
//!
//! Units are SI throughout (m, kg, s, N, Pa, rad/s); angles in model files are in
//! degrees where the key says `_deg`. Nodes are numbered from 1 along the shaft.

use serde::Deserialize;

pub use super::file_bearings::{BearingEntry, Coefficient};

/// Top level of a model file.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ModelFile {
    /// Short identifier (letters, digits, `_`): becomes the FMU's model name.
    pub name: String,
    /// Free text shown in reports and the FMU documentation.
    #[serde(default)]
    pub description: String,
    /// Gravity vector in the rotor frame (m/s²); `z` is the shaft axis.
    #[serde(default)]
    pub gravity: Option<[f64; 3]>,
    /// Axial tension (N, compression negative) applied to every shaft element
    /// that does not give its own.
    #[serde(default)]
    pub axial_force: Option<f64>,
    /// Nominal (operating) spin speed (rpm) of the machine, for analyses and
    /// the CLI; an FMU starts at standstill whatever it is.
    #[serde(default)]
    pub speed_rpm: Option<f64>,
    /// Memory a model may need (MB) before it is refused; default
    /// [`crate::model::DEFAULT_MEMORY_BUDGET_MB`].
    #[serde(default)]
    pub memory_budget_mb: Option<f64>,
    /// Operating speed range `[min, max]` (rpm) the separation margins are
    /// judged against (API 684); default `speed_rpm` alone.
    #[serde(default)]
    pub operating_rpm: Option<Vec<f64>>,
    /// The machine's class: `generic` (default), `hydro_generator`,
    /// `pump_turbine`, `compressor`, `steam_turbine` or `pump`.
    #[serde(default)]
    pub machine: Option<String>,
    /// ISO 10816-5 machine group (2, 3 or 4) of a hydro class.
    #[serde(default)]
    pub housing_group: Option<i64>,
    /// Electrical grid frequency (Hz) a hydro class's torsional modes are
    /// judged against (1x and 2x); none: those checks are not judged.
    #[serde(default)]
    pub grid_frequency_hz: Option<f64>,
    /// Separation (fraction) a hydro class's torsional natural frequencies
    /// keep from the excitations; default
    /// [`crate::model::machine_class::DEFAULT_TORSIONAL_MARGIN`].
    #[serde(default)]
    pub torsional_margin: Option<f64>,
    /// Largest spin speed the machine may be driven at (rpm, either direction);
    /// default [`crate::model::DEFAULT_MAX_SPEED_RPM`].
    #[serde(default)]
    pub max_speed_rpm: Option<f64>,
    /// Axial position of the first node (m).
    #[serde(default)]
    pub start_z: Option<f64>,
    /// Include shear deformation (Timoshenko); default true.
    #[serde(default)]
    pub shear_deformation: Option<bool>,
    /// Include rotary inertia of the shaft; default true.
    #[serde(default)]
    pub rotary_inertia: Option<bool>,
    #[serde(default)]
    pub materials: Vec<MaterialEntry>,
    #[serde(default)]
    pub shaft: Vec<ShaftEntry>,
    #[serde(default)]
    pub disks: Vec<DiskEntry>,
    #[serde(default)]
    pub bearings: Vec<BearingEntry>,
    /// `[[rubs]]`.
    #[serde(default)]
    pub rubs: Vec<RubEntry>,
    /// `[[seals]]`.
    #[serde(default)]
    pub seals: Vec<SealEntry>,
    /// `[[point_masses]]`.
    #[serde(default)]
    pub point_masses: Vec<PointMassEntry>,
    /// `[[magnetic_pull]]`.
    #[serde(default)]
    pub magnetic_pull: Vec<MagneticPullEntry>,
    /// `[[forces]]`.
    #[serde(default)]
    pub forces: Vec<ForceEntry>,
    /// `[[ports]]`.
    #[serde(default)]
    pub ports: Vec<PortEntry>,
    /// `[[couplings]]`: flexible couplings in the torsional chain.
    #[serde(default)]
    pub couplings: Vec<CouplingEntry>,
    /// `[[torques]]`: nodes where the plant applies torque (torque-driven FMU).
    #[serde(default)]
    pub torques: Vec<TorqueEntry>,
    /// `[[thrust_bearings]]`.
    #[serde(default)]
    pub thrust_bearings: Vec<ThrustBearingEntry>,
    /// `[torsion]`: how the shaft is driven.
    #[serde(default)]
    pub torsion: Option<TorsionEntry>,
    #[serde(default)]
    pub unbalance: Vec<UnbalanceEntry>,
    #[serde(default)]
    pub probes: Vec<ProbeEntry>,
    #[serde(default)]
    pub supports: Vec<SupportEntry>,
    /// `[[pedestals]]`: bearing supports in series with bearings.
    #[serde(default)]
    pub pedestals: Vec<PedestalEntry>,
    /// `[reduction]`: transients on a reduced rotor.
    #[serde(default)]
    pub reduction: Option<ReductionEntry>,
    /// `[cases]`: the tolerance cases (oil temperature, clearance, preload).
    #[serde(default)]
    pub cases: Option<super::tolerance_cases::CasesEntry>,
    /// `[shaft_vibration_zones]`: a hydro unit's shaft-displacement zones.
    #[serde(default)]
    pub shaft_vibration_zones: Option<super::shaft_zones::ShaftZonesEntry>,
}

/// `[reduction]`: run transients on a Craig–Bampton reduced rotor (the
/// nonlinear bearings, rubs, probes and unbalance planes kept physical).
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ReductionEntry {
    /// Fixed-interface modes kept; default: as many as the model's speed
    /// range needs ([`crate::rotor::Rotor::transient_modes`]).
    pub modes: Option<i64>,
}

/// `[[materials]]`: give `shear_modulus` or `poisson_ratio`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MaterialEntry {
    pub name: String,
    /// Young's modulus (Pa).
    pub youngs_modulus: f64,
    /// Shear modulus (Pa).
    pub shear_modulus: Option<f64>,
    /// Poisson's ratio (–), used when `shear_modulus` is absent.
    pub poisson_ratio: Option<f64>,
    /// Density (kg/m³).
    pub density: f64,
}

/// `[[shaft]]`: a uniform section, split into `elements` equal elements.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ShaftEntry {
    /// Section length (m).
    pub length: f64,
    /// Outer diameter (m).
    pub outer_diameter: f64,
    /// Inner diameter (m), default 0 (solid).
    #[serde(default)]
    pub inner_diameter: f64,
    /// Material name from `[[materials]]`.
    pub material: String,
    /// Number of finite elements, default 1.
    pub elements: Option<usize>,
    /// Axial tension in this section (N, compression negative).
    pub axial_force: Option<f64>,
    /// Viscous torsional damping of the whole section (N·m·s/rad), in
    /// parallel with its torsional stiffness; default 0.
    pub torsional_damping: Option<f64>,
}

/// `[[disks]]`: either inertias (`mass`, `polar_inertia`, `diametral_inertia`) or
/// geometry (`material`, `outer_diameter`, `inner_diameter`, `width`).
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct DiskEntry {
    #[serde(default)]
    pub name: Option<String>,
    pub node: Option<i64>,
    pub z: Option<f64>,
    /// Mass (kg).
    pub mass: Option<f64>,
    /// Polar inertia (kg·m²).
    pub polar_inertia: Option<f64>,
    /// Diametral inertia (kg·m²).
    pub diametral_inertia: Option<f64>,
    pub material: Option<String>,
    /// Outer diameter (m).
    pub outer_diameter: Option<f64>,
    /// Inner diameter (m).
    pub inner_diameter: Option<f64>,
    /// Axial width (m).
    pub width: Option<f64>,
    /// What the disk is: `"impeller"` (a compressor, pump or turbine stage,
    /// a hydro runner: where API 617 places the stability study's
    /// cross-coupling on an overhung rotor) or `"other"` (the default).
    pub role: Option<String>,
    /// An impeller's stage for Wachel's `q_A`: rated power (W).
    pub stage_power: Option<f64>,
    /// Impeller diameter (m).
    pub impeller_diameter: Option<f64>,
    /// Restrictive flow width (m).
    pub flow_width: Option<f64>,
    /// Discharge over suction density (–, default 1).
    pub density_ratio: Option<f64>,
    /// Stage factor `B` (–, default 3).
    pub stage_factor: Option<f64>,
}

/// `[[seals]]`: an annular seal, labyrinth or wear ring given by its linear
/// coefficients over speed, optionally closing on its stator at `clearance`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SealEntry {
    pub name: Option<String>,
    pub node: Option<i64>,
    pub z: Option<f64>,
    /// The pedestal (`[[pedestals]]` name) the stator stands on; default rigid ground.
    pub pedestal: Option<String>,
    /// Stator centre off the nominal axis (m), x and y (default 0).
    pub offset_x: Option<f64>,
    pub offset_y: Option<f64>,
    /// Speeds of the table rows (rpm), increasing; with the coefficient
    /// columns below. Omit for constant coefficients.
    pub speeds_rpm: Option<Vec<f64>>,
    /// Coefficients (N/m, N·s/m): one value, or one per speed.
    pub kxx: Option<Coefficient>,
    pub kxy: Option<Coefficient>,
    pub kyx: Option<Coefficient>,
    pub kyy: Option<Coefficient>,
    pub cxx: Option<Coefficient>,
    pub cxy: Option<Coefficient>,
    pub cyx: Option<Coefficient>,
    pub cyy: Option<Coefficient>,
    /// A CSV file (beside the model file) with a `speed_rpm` column and
    /// any of the coefficient columns, instead of the inline table.
    pub table: Option<String>,
    /// Added mass (kg), constant over speed.
    pub mxx: Option<f64>,
    pub mxy: Option<f64>,
    pub myx: Option<f64>,
    pub myy: Option<f64>,
    /// Radial clearance at which the seal touches its stator (m); default: never.
    pub clearance: Option<f64>,
    /// Rotor surface radius at the seal (m); default the shaft's outer radius there.
    pub radius: Option<f64>,
    /// Contact stiffness (N/m); default the steel line contact of a 10 mm wide ring.
    pub contact_stiffness: Option<f64>,
    /// Contact damping (N·s/m); default 1e-5 s × the contact stiffness.
    pub contact_damping: Option<f64>,
    /// Coulomb friction coefficient (–), default 0.2.
    pub friction_coefficient: Option<f64>,
}

/// `[[magnetic_pull]]`: the unbalanced magnetic pull of a generator rotor in
/// its stator, given by its pull stiffness or by the data it follows from.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MagneticPullEntry {
    pub name: Option<String>,
    pub node: Option<i64>,
    pub z: Option<f64>,
    /// The pedestal (`[[pedestals]]` name) the stator stands on; default rigid ground.
    pub pedestal: Option<String>,
    /// Stator centre off the nominal axis (m), x and y (default 0).
    pub offset_x: Option<f64>,
    pub offset_y: Option<f64>,
    /// Radial air gap (m).
    pub gap: f64,
    /// Pull stiffness at nominal excitation (N/m), or give the three below.
    pub stiffness: Option<f64>,
    /// Rotor (air-gap) radius (m).
    pub rotor_radius: Option<f64>,
    /// Core length (m).
    pub core_length: Option<f64>,
    /// Mean air-gap flux density at nominal excitation (T).
    pub flux_density: Option<f64>,
    /// Field excitation, 1 = nominal (the pull goes with its square); default 1.
    pub excitation: Option<f64>,
    /// Dynamic (rotating) eccentricity of the rotor (m), default 0.
    pub dynamic_eccentricity: Option<f64>,
    /// Its direction at spin angle 0 (°), default 0.
    pub dynamic_phase_deg: Option<f64>,
    /// Stator contact stiffness (N/m); default the steel line contact over the core length.
    pub contact_stiffness: Option<f64>,
    /// Stator contact damping (N·s/m); default 1e-5 s × the contact stiffness.
    pub contact_damping: Option<f64>,
    /// Coulomb friction coefficient of the stator contact (–), default 0.2.
    pub friction_coefficient: Option<f64>,
}

/// `[[point_masses]]`: a non-rotating lumped mass at a node (coupling hub,
/// housing, thrust collar): `mass`, or `mx` and `my` (kg).
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PointMassEntry {
    pub name: Option<String>,
    pub node: Option<i64>,
    pub z: Option<f64>,
    /// Mass (kg) in x and y.
    pub mass: Option<f64>,
    /// Mass in x (kg), with `my`, instead of `mass`.
    pub mx: Option<f64>,
    /// Mass in y (kg).
    pub my: Option<f64>,
}

/// `[[rubs]]`: a stator ring (seal, labyrinth, air gap) the rotor may touch.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RubEntry {
    pub name: Option<String>,
    pub node: Option<i64>,
    pub z: Option<f64>,
    /// The pedestal (`[[pedestals]]` name) the stator stands on; default rigid ground.
    pub pedestal: Option<String>,
    /// Stator centre off the nominal axis (m), x and y (default 0).
    pub offset_x: Option<f64>,
    pub offset_y: Option<f64>,
    /// Radial clearance between rotor and stator (m).
    pub gap: f64,
    /// Rotor surface radius at the rub (m); default the shaft's outer radius at the node.
    pub radius: Option<f64>,
    /// Contact stiffness (N/m); default the steel line contact of a 10 mm wide ring.
    pub contact_stiffness: Option<f64>,
    /// Contact damping (N·s/m); default 1e-5 s × the contact stiffness.
    pub contact_damping: Option<f64>,
    /// Coulomb friction coefficient (–), default 0.2.
    pub friction_coefficient: Option<f64>,
}

/// `[[unbalance]]`: an unbalance plane.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct UnbalanceEntry {
    pub name: Option<String>,
    pub node: Option<i64>,
    pub z: Option<f64>,
    /// Unbalance `m·e` (kg·m).
    pub magnitude: f64,
    /// Angular position at spin angle zero, from +x toward +y (degrees).
    #[serde(default)]
    pub phase_deg: f64,
}

/// `[[forces]]`: an external force at a node, static (`fx`, `fy`) or
/// harmonic (`magnitude`, `phase_deg`, `ratio` to the running speed or
/// `frequency_hz`, `direction`).
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ForceEntry {
    pub name: Option<String>,
    pub node: Option<i64>,
    pub z: Option<f64>,
    /// Static force (N).
    pub fx: Option<f64>,
    pub fy: Option<f64>,
    /// Harmonic force amplitude (N).
    pub magnitude: Option<f64>,
    /// Its phase (°) at time 0 and spin angle 0.
    pub phase_deg: Option<f64>,
    /// Its frequency as a multiple of the running speed (e.g. 0.3 for a
    /// vortex rope, the blade number for blade passing) …
    pub ratio: Option<f64>,
    /// … or a fixed frequency (Hz).
    pub frequency_hz: Option<f64>,
    /// `"forward"` (rotating with the spin), `"backward"` or `"fixed"`
    /// (a line of action at `angle_deg`).
    pub direction: Option<String>,
    /// Direction of a fixed force's line of action (°, from +x toward +y).
    pub angle_deg: Option<f64>,
}

/// `[[ports]]`: a node where another FMU pushes on the rotor.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PortEntry {
    pub name: String,
    pub node: Option<i64>,
    pub z: Option<f64>,
}

/// `[[couplings]]`: a coupling between two shafts of a train at the shaft
/// element from `node` to the next node: torsionally it takes the element's
/// torsional stiffness and damping instead of its own; laterally it is a
/// rigid flange (the element stays, the shaft after it set off by the
/// misalignment) or, with `lateral_stiffness` and `angular_stiffness`, a
/// flexible coupling that replaces the element by a spring–damper.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CouplingEntry {
    pub name: Option<String>,
    /// The element's left node (numbered from 1); the coupling joins it to the next.
    pub node: Option<i64>,
    pub z: Option<f64>,
    /// Torsional stiffness (N·m/rad); without it the element keeps its own.
    pub torsional_stiffness: Option<f64>,
    /// Torsional damping (N·m·s/rad), default 0.
    pub torsional_damping: Option<f64>,
    /// Lateral (relative translation) stiffness (N/m) of a flexible coupling.
    pub lateral_stiffness: Option<f64>,
    /// Angular (relative rotation) stiffness (N·m/rad) of a flexible coupling.
    pub angular_stiffness: Option<f64>,
    /// Lateral damping (N·s/m), default 0.
    pub lateral_damping: Option<f64>,
    /// Angular damping (N·m·s/rad), default 0.
    pub angular_damping: Option<f64>,
    /// Parallel misalignment `[x, y]` (m) of the shaft after the coupling.
    pub parallel_offset: Option<[f64; 2]>,
    /// Angular misalignment `[dx/dz, dy/dz]` (rad) of the shaft after it.
    pub angular_offset: Option<[f64; 2]>,
}

/// `[[torques]]`: a node where a drive or load torque acts (the FMU's torque
/// inputs in torque mode).
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct TorqueEntry {
    pub name: String,
    pub node: Option<i64>,
    pub z: Option<f64>,
}

/// `[[thrust_bearings]]`: the axial bearing carrying the rotor's weight or
/// thrust: its friction torque.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ThrustBearingEntry {
    pub name: Option<String>,
    pub node: Option<i64>,
    pub z: Option<f64>,
    /// Axial load (N); default the rotor's weight along the shaft axis.
    pub load: Option<f64>,
    /// Inner and outer radius of the pad ring (m).
    pub inner_radius: f64,
    pub outer_radius: f64,
    /// Fraction of the ring the pads cover (–), default 0.8.
    pub pad_coverage: Option<f64>,
    /// Oil film thickness at running speed (m).
    pub film_thickness: f64,
    /// Oil dynamic viscosity (Pa·s).
    pub viscosity: f64,
    /// Boundary friction coefficient at standstill (–), default 0.15.
    pub friction_coefficient: Option<f64>,
    /// Speed (rpm) by which the film has lifted the pads (boundary friction
    /// fades as exp(−n / lift_off_rpm)); default 5 rpm.
    pub lift_off_rpm: Option<f64>,
    /// A high-pressure oil lift: no boundary friction at standstill.
    pub oil_lift: Option<bool>,
}

/// `[torsion]`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct TorsionEntry {
    /// `"speed"` (the shaft follows a prescribed speed, default) or
    /// `"torque"` (torques at the `[[torques]]` nodes drive it).
    pub drive: Option<String>,
    /// Modal damping ratio of the listed torsional modes (–), default 0.
    pub damping_ratio: Option<f64>,
}

/// `[[probes]]`: a named node whose displacements are reported.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ProbeEntry {
    pub name: String,
    pub node: Option<i64>,
    pub z: Option<f64>,
    /// The bearing whose installed centre the probe measures from (a
    /// proximity probe on that bearing's housing); default the nominal axis.
    pub relative_to: Option<String>,
}

/// `[[pedestals]]`: a bearing support (pedestal, bracket, foundation): a
/// non-rotating lumped mass on a spring–damper to ground or to the pedestal
/// it stands on. Bearings and rubs stand on it with `pedestal = "<name>"`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PedestalEntry {
    pub name: String,
    /// Mass (kg), the same in x and y.
    pub mass: f64,
    /// Stiffness to ground or to `on` (N/m).
    #[serde(default)]
    pub kxx: f64,
    #[serde(default)]
    pub kxy: f64,
    #[serde(default)]
    pub kyx: f64,
    #[serde(default)]
    pub kyy: f64,
    /// Damping to ground or to `on` (N·s/m).
    #[serde(default)]
    pub cxx: f64,
    #[serde(default)]
    pub cxy: f64,
    #[serde(default)]
    pub cyx: f64,
    #[serde(default)]
    pub cyy: f64,
    /// The pedestal it stands on (a bracket on a foundation); default ground.
    pub on: Option<String>,
    /// Spring anchor off the nominal axis (m), x and y, relative to `on` (default 0).
    pub offset_x: Option<f64>,
    pub offset_y: Option<f64>,
    /// Braced against the generator stator (ISO 10816-5 group 4's
    /// measurement location 1); default false.
    #[serde(default)]
    pub on_stator: bool,
}

/// `[[supports]]`: ideal constraints (boundary conditions) at a node.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SupportEntry {
    pub node: Option<i64>,
    pub z: Option<f64>,
    /// Constrained DOFs: any of `"x"`, `"y"`, `"rx"`, `"ry"`; or `"pinned"`
    /// (= x, y) or `"clamped"` (= all four).
    pub fix: Vec<String>,
}
