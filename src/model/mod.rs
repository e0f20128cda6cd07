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
pub mod limits;
mod plausibility;
mod source_map;
pub mod speed_table;

pub use error::ModelError;
use error::Seg;
pub use plausibility::{CLEARANCE_RATIO_RANGE, ModelWarning, RADIUS_TOLERANCE, VISCOSITY_RANGE};

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
}

/// A bearing between a shaft node and ground.
#[derive(Debug, Clone, PartialEq)]
pub struct PlacedBearing {
    /// Name (default `bearing<k>`).
    pub name: String,
    /// Node index (0-based).
    pub node: usize,
    /// Bearing type and parameters.
    pub kind: BearingKind,
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

/// A named node whose displacements are reported.
#[derive(Debug, Clone, PartialEq)]
pub struct Probe {
    /// Name, unique in the model.
    pub name: String,
    /// Node index (0-based).
    pub node: usize,
}

/// Ideal constraints at a node: `fixed[k]` fixes node DOF `k` (see [`crate::fe`]).
#[derive(Debug, Clone, PartialEq)]
pub struct Support {
    /// Node index (0-based).
    pub node: usize,
    /// Which of `(x, y, θx, θy)` are fixed.
    pub fixed: [bool; 4],
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
    /// Bearings.
    pub bearings: Vec<PlacedBearing>,
    /// Unbalance planes.
    pub unbalances: Vec<UnbalancePlane>,
    /// Probes.
    pub probes: Vec<Probe>,
    /// Ideal supports.
    pub supports: Vec<Support>,
    /// Gravity vector (m/s²), `z` along the shaft.
    pub gravity: [f64; 3],
    /// Nominal spin speed (rad/s), 0 when the file gives none.
    pub nominal_speed: f64,
    /// Largest spin speed in either direction (rad/s): inputs beyond it are refused.
    pub max_speed: f64,
    /// Whether the file states `max_speed_rpm` (else `max_speed` is
    /// [`DEFAULT_MAX_SPEED_RPM`]).
    pub max_speed_stated: bool,
    /// The reduced rotor transients run on (`[reduction]`, see
    /// [`crate::rotor::Rotor::reduced`]); `None`: the full rotor.
    pub reduction: Option<ReductionRequest>,
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
        let raw: ModelFile = toml::from_str(text).map_err(|e| {
            let span = e.span();
            let line = span.as_ref().map(|s| line_of(text, s.start));
            let message = e.message().trim();
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
        let ctx = Ctx { text, source };
        build::build(&ctx, raw)
    }

    /// Number of nodes.
    pub fn node_count(&self) -> usize {
        self.node_z.len()
    }

    /// Total rotating mass: shaft plus disks (kg).
    pub fn total_mass(&self) -> f64 {
        self.elements.iter().map(|e| e.element.mass()).sum::<f64>()
            + self.disks.iter().map(|d| d.disk.mass).sum::<f64>()
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
