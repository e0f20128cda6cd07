//! The TOML model file as written by a user: plain serde structs, every unknown
//! key rejected. Validation into a [`super::RotorModel`] happens in `build`.
//!
//! Units are SI throughout (m, kg, s, N, Pa, rad/s); angles in model files are in
//! degrees where the key says `_deg`. Nodes are numbered from 1 along the shaft.

use serde::Deserialize;

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
    #[serde(default)]
    pub unbalance: Vec<UnbalanceEntry>,
    #[serde(default)]
    pub probes: Vec<ProbeEntry>,
    #[serde(default)]
    pub supports: Vec<SupportEntry>,
    /// `[reduction]`: transients on a reduced rotor.
    #[serde(default)]
    pub reduction: Option<ReductionEntry>,
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
}

/// `[[bearings]]`, selected by `type`.
#[derive(Debug, Deserialize)]
#[serde(tag = "type", rename_all = "snake_case", deny_unknown_fields)]
pub enum BearingEntry {
    /// Linear spring–damper to ground: `F = −K q − C q̇` on (x, y).
    Linear {
        name: Option<String>,
        node: Option<i64>,
        z: Option<f64>,
        /// Stiffness (N/m).
        #[serde(default)]
        kxx: f64,
        #[serde(default)]
        kxy: f64,
        #[serde(default)]
        kyx: f64,
        #[serde(default)]
        kyy: f64,
        /// Damping (N·s/m).
        #[serde(default)]
        cxx: f64,
        #[serde(default)]
        cxy: f64,
        #[serde(default)]
        cyx: f64,
        #[serde(default)]
        cyy: f64,
    },
    /// Plain journal bearing, short-bearing (Ocvirk) theory, π-film cavitation.
    Plain {
        name: Option<String>,
        node: Option<i64>,
        z: Option<f64>,
        /// Journal radius (m).
        radius: f64,
        /// The journal is a collar or sleeve larger than the shaft at its node.
        journal_collar: Option<bool>,
        /// Bearing length (m).
        length: f64,
        /// Radial clearance (m), or `diametral_clearance` (twice it).
        clearance: Option<f64>,
        /// Diametral clearance (m): bore diameter less journal diameter.
        diametral_clearance: Option<f64>,
        /// Oil dynamic viscosity (Pa·s).
        viscosity: f64,
        /// Contact penalty stiffness (N/m) once the journal touches; default
        /// the steel line contact `(π/4) E* L` of `ContactLaw::steel`.
        contact_stiffness: Option<f64>,
        /// Contact damping (N·s/m); default 1e-5 s × the contact stiffness.
        contact_damping: Option<f64>,
        /// Coulomb friction coefficient of the contact (–), default 0.2.
        friction_coefficient: Option<f64>,
    },
    /// Tilting-pad journal bearing: short-bearing film on each pad, pads tilt freely.
    TiltingPad {
        name: Option<String>,
        node: Option<i64>,
        z: Option<f64>,
        /// Journal radius (m).
        radius: f64,
        /// The journal is a collar or sleeve larger than the shaft at its node.
        journal_collar: Option<bool>,
        /// Pad axial length (m).
        length: f64,
        /// Pad (machined) radial clearance (m), or `diametral_clearance`.
        clearance: Option<f64>,
        /// Pad (machined) diametral clearance (m): twice the radial one.
        diametral_clearance: Option<f64>,
        /// Oil dynamic viscosity (Pa·s).
        viscosity: f64,
        /// Number of equally spaced pads (3–18), with `first_pivot_deg`.
        pads: Option<i64>,
        /// Pivot angle of the first pad (°, from +x toward +y), default 0.
        first_pivot_deg: Option<f64>,
        /// Explicit pivot angles (°), instead of `pads`/`first_pivot_deg`.
        pivots_deg: Option<Vec<f64>>,
        /// Arc extent of each pad (°).
        pad_arc_deg: f64,
        /// Pivot position from the leading edge as a fraction of the arc, default 0.5.
        pivot_offset: Option<f64>,
        /// Preload m = 1 − C_b/C, default 0.
        preload: Option<f64>,
        /// Contact penalty stiffness (N/m) once the journal touches; default
        /// the steel line contact `(π/4) E* L` of `ContactLaw::steel`.
        contact_stiffness: Option<f64>,
        /// Contact damping (N·s/m); default 1e-5 s × the contact stiffness.
        contact_damping: Option<f64>,
        /// Coulomb friction coefficient of the contact (–), default 0.2.
        friction_coefficient: Option<f64>,
    },
}

/// `[[rubs]]`: a stator ring (seal, labyrinth, air gap) the rotor may touch.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RubEntry {
    pub name: Option<String>,
    pub node: Option<i64>,
    pub z: Option<f64>,
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

/// `[[probes]]`: a named node whose displacements are reported.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ProbeEntry {
    pub name: String,
    pub node: Option<i64>,
    pub z: Option<f64>,
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
