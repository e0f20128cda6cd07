//! Plausibility warnings: values a model file may legally hold but that are
//! probably typed in the wrong unit (a viscosity in cSt, a radius in mm, a
//! diametral clearance). They do not stop the model; front ends print them.

use std::fmt;

use super::RotorModel;
use crate::units::Short;

/// Plausible dynamic viscosity of a lubricant (Pa·s): water (≈ 1e-3) to heavy
/// oils at low temperature.
pub const VISCOSITY_RANGE: (f64, f64) = (1e-4, 1.0);

/// Plausible ratio of radial clearance to journal radius of a fluid-film bearing.
pub const CLEARANCE_RATIO_RANGE: (f64, f64) = (1e-4, 1e-2);

/// Largest relative difference between a bearing's radius and the shaft's outer
/// radius at its node.
pub const RADIUS_TOLERANCE: f64 = 0.01;

/// Plausible direct stiffness of a bearing support (N/m): below, a soft mount
/// of a small machine given in N/mm by mistake is likelier than a real
/// structure; above, a support stiffer than solid steel under a bearing
/// (a rigid support needs no pedestal).
pub const PEDESTAL_STIFFNESS_RANGE: (f64, f64) = (1e3, 1e13);

/// Largest plausible ratio of a pedestal's mass to the rotor's mass: a
/// foundation heavier than that acts as ground (or a mass given in g).
pub const PEDESTAL_MASS_RATIO: f64 = 100.0;

/// Largest plausible rotating mass of a whole model (kg): the heaviest
/// hydro-generator rotors with their turbines weigh 2 000–4 000 t.
pub const MAX_PLAUSIBLE_MASS: f64 = 1e7;

/// Largest plausible length of a whole shaft line (m): turbine-generator
/// trains reach about 70 m, ship shafting about 150 m.
pub const MAX_PLAUSIBLE_LENGTH: f64 = 200.0;

/// Largest plausible outer diameter of a shaft section (m): hydro-unit shafts
/// reach about 2.5 m.
pub const MAX_PLAUSIBLE_SHAFT_DIAMETER: f64 = 10.0;

/// A value that passed validation but is probably a unit or typing slip.
#[derive(Debug, Clone, PartialEq)]
pub struct ModelWarning {
    /// The model file (its `source`).
    pub file: String,
    /// Field path, e.g. `bearings[0].viscosity`.
    pub field: String,
    /// The value as given (SI units).
    pub value: f64,
    /// What is implausible and the expected range.
    pub problem: String,
}

impl fmt::Display for ModelWarning {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{}: {} = {}: {}",
            self.file,
            self.field,
            Short(self.value),
            self.problem
        )
    }
}

impl RotorModel {
    /// Warnings for a whole model that looks drawn in millimetres: each size
    /// may be valid alone, but the rotating mass above [`MAX_PLAUSIBLE_MASS`],
    /// the shaft line longer than [`MAX_PLAUSIBLE_LENGTH`] or a shaft section
    /// thicker than [`MAX_PLAUSIBLE_SHAFT_DIAMETER`] is no machine.
    fn millimetre_warnings(&self) -> Vec<ModelWarning> {
        let mut warnings = Vec::new();
        let mut warn = |field: String, value: f64, problem: String| {
            warnings.push(ModelWarning {
                file: self.source.clone(),
                field,
                value,
                problem,
            })
        };
        let slip = "are the lengths in millimetres instead of metres?";
        let mass = self.total_mass();
        if mass > MAX_PLAUSIBLE_MASS {
            warn(
                "rotating mass (shaft and disks, kg)".into(),
                mass,
                format!(
                    "above the {} kg of the heaviest machines: {slip}",
                    Short(MAX_PLAUSIBLE_MASS)
                ),
            );
        }
        let length = self.node_z[self.node_z.len() - 1] - self.node_z[0];
        if length > MAX_PLAUSIBLE_LENGTH {
            warn(
                "shaft length (sum of shaft[*].length, m)".into(),
                length,
                format!(
                    "longer than the {MAX_PLAUSIBLE_LENGTH} m of the longest shaft lines: {slip}"
                ),
            );
        }
        let thickest = self
            .elements
            .iter()
            .position(|e| e.element.section.outer_diameter > MAX_PLAUSIBLE_SHAFT_DIAMETER);
        if let Some(k) = thickest {
            warn(
                format!("shaft outer_diameter (element {})", k + 1),
                self.elements[k].element.section.outer_diameter,
                format!("thicker than the {MAX_PLAUSIBLE_SHAFT_DIAMETER} m of any shaft: {slip}"),
            );
        }
        warnings
    }

    /// Outer radii (m) of the shaft elements that meet at `node` (0-based).
    fn shaft_radii_at(&self, node: usize) -> Vec<f64> {
        let mut radii: Vec<f64> = self
            .elements
            .iter()
            .filter(|e| e.node == node || e.node + 1 == node)
            .map(|e| 0.5 * e.element.section.outer_diameter)
            .collect();
        radii.dedup();
        radii
    }

    /// Warnings for plausible-looking slips, per fluid-film bearing:
    /// - viscosity outside [`VISCOSITY_RANGE`] (32 Pa·s is probably 32 cSt);
    /// - radius more than [`RADIUS_TOLERANCE`] below the outer radius of every
    ///   shaft element at the bearing's node (a larger one is a declared
    ///   `journal_collar` or an error when the model is read);
    /// - radial clearance / radius outside [`CLEARANCE_RATIO_RANGE`] (a
    ///   diametral clearance or a unit slip).
    ///
    /// ```
    /// use rotor_bearing::model::{DEFAULT_MODEL_TOML, RotorModel};
    ///
    /// // A plain bearing on the 50 mm shaft of the default model, oil given in cSt.
    /// let text = format!(
    ///     "{DEFAULT_MODEL_TOML}\n[[bearings]]\nname = \"guide\"\ntype = \"plain\"\nnode = 2\n\
    ///      radius = 0.025\nlength = 0.02\nclearance = 5e-5\nviscosity = 32.0\n"
    /// );
    /// let model = RotorModel::from_toml(&text, "m.toml").unwrap();
    /// let warnings = model.plausibility_warnings();
    /// assert_eq!(warnings.len(), 1);
    /// assert!(warnings[0].to_string().starts_with("m.toml: bearings[2].viscosity = 32: "));
    /// assert!(RotorModel::default_model().plausibility_warnings().is_empty());
    /// ```
    pub fn plausibility_warnings(&self) -> Vec<ModelWarning> {
        let mut warnings = self.millimetre_warnings();
        for (i, b) in self.bearings.iter().enumerate() {
            let Some(g) = b.kind.film_geometry() else {
                continue;
            };
            let mut warn = |key: &str, value: f64, problem: String| {
                warnings.push(ModelWarning {
                    file: self.source.clone(),
                    field: format!("bearings[{i}].{key}"),
                    value,
                    problem,
                })
            };
            let (lo, hi) = VISCOSITY_RANGE;
            if !(lo..=hi).contains(&g.viscosity) {
                warn(
                    "viscosity",
                    g.viscosity,
                    format!(
                        "dynamic viscosity outside the plausible {lo:e} to {hi} Pa·s \
                         (a kinematic viscosity in cSt, or mPa·s?)"
                    ),
                );
            }
            // Larger than the shaft is a declared collar or an error (model
            // build); smaller than every element there is suspicious.
            let radii = self.shaft_radii_at(b.node);
            if !radii.is_empty()
                && radii
                    .iter()
                    .all(|r| g.radius < r * (1.0 - RADIUS_TOLERANCE))
            {
                let shaft: Vec<String> = radii.iter().map(|r| format!("{r} m")).collect();
                warn(
                    "radius",
                    g.radius,
                    format!(
                        "is more than {} % below the shaft radius at node {} ({}) \
                         (a journal smaller than its shaft: a radius in the wrong unit?)",
                        RADIUS_TOLERANCE * 100.0,
                        b.node + 1,
                        shaft.join(", ")
                    ),
                );
            }
            let ratio = g.clearance / g.radius;
            let (lo, hi) = CLEARANCE_RATIO_RANGE;
            if !(lo..=hi).contains(&ratio) {
                warn(
                    "clearance",
                    g.clearance,
                    format!(
                        "radial clearance / radius = {ratio:.3e}, outside the plausible {lo:e} to {hi:e} \
                         (clearance is the radial clearance, in metres)"
                    ),
                );
            }
        }
        warnings.extend(self.offset_warnings());
        for (i, t) in self.thrust_bearings.iter().enumerate() {
            if t.bearing.load == 0.0 {
                warnings.push(ModelWarning {
                    file: self.source.clone(),
                    field: format!("thrust_bearings[{i}].load"),
                    value: 0.0,
                    problem: "the thrust bearing carries no axial load (the rotor's weight has no axial part: gravity is not along z): give the load it carries".into(),
                });
            }
        }
        let rotor_mass = self.total_mass();
        for (i, p) in self.pedestals.iter().enumerate() {
            let mut warn = |key: &str, value: f64, problem: String| {
                warnings.push(ModelWarning {
                    file: self.source.clone(),
                    field: format!("pedestals[{i}].{key}"),
                    value,
                    problem,
                })
            };
            let (lo, hi) = PEDESTAL_STIFFNESS_RANGE;
            for (key, k) in [("kxx", p.stiffness[0][0]), ("kyy", p.stiffness[1][1])] {
                if !(lo..=hi).contains(&k) {
                    warn(
                        key,
                        k,
                        format!(
                            "support stiffness outside the plausible {lo:e} to {hi:e} N/m (N/mm instead of N/m?)"
                        ),
                    );
                }
            }
            if p.mass > PEDESTAL_MASS_RATIO * rotor_mass {
                warn(
                    "mass",
                    p.mass,
                    format!(
                        "more than {PEDESTAL_MASS_RATIO} times the rotating mass ({} kg): such a foundation acts as ground (or the mass is in g?)",
                        (rotor_mass * 10.0).round() / 10.0
                    ),
                );
            }
        }
        warnings
    }
}

impl RotorModel {
    /// A warning for each bearing, seal, rub or magnetic pull set off the
    /// axis by more than the clearance its journal moves in
    /// ([`BearingKind::journal_clearance`](crate::bearing::BearingKind::journal_clearance)):
    /// the straight shaft would start in contact with it. Legal (the statics
    /// find where the line comes to rest), but more often a unit slip.
    fn offset_warnings(&self) -> Vec<ModelWarning> {
        let mut warnings = Vec::new();
        let mut counts = [0usize; 4];
        for b in &self.bearings {
            let section = if b.kind.is_rub() {
                1
            } else if b.kind.is_seal() {
                2
            } else if b.kind.is_magnetic_pull() {
                3
            } else {
                0
            };
            let i = counts[section];
            counts[section] += 1;
            let Some(clearance) = b.kind.journal_clearance() else {
                continue;
            };
            let offset = b.offset[0].hypot(b.offset[1]);
            if offset > clearance {
                let name = ["bearings", "rubs", "seals", "magnetic_pull"][section];
                let key = if b.offset[1].abs() >= b.offset[0].abs() {
                    "offset_y"
                } else {
                    "offset_x"
                };
                let o = if key == "offset_y" {
                    b.offset[1]
                } else {
                    b.offset[0]
                };
                warnings.push(ModelWarning {
                    file: self.source.clone(),
                    field: format!("{name}[{i}].{key}"),
                    value: o,
                    problem: format!(
                        "the centre offset |(offset_x, offset_y)| = {} m exceeds the clearance {} m: \
                         the journal would start in contact (offsets are in metres)",
                        Short(offset),
                        Short(clearance)
                    ),
                });
            }
        }
        warnings
    }

    /// One warning for each coefficient table (table bearing or seal) that an
    /// analysis at `speeds` (rad/s) asks for speeds outside its rows, naming
    /// the range of those speeds on each side and the table's range (its end
    /// values hold there); the warning's value is the farthest such speed.
    pub fn table_speed_warnings(&self, speeds: &[f64]) -> Vec<ModelWarning> {
        let mut warnings = Vec::new();
        for b in &self.bearings {
            let Some(table) = b.kind.coefficient_table() else {
                continue;
            };
            let (lo, hi) = table.range();
            let outside = speeds
                .iter()
                .copied()
                .filter(|&w| !table.covers(w))
                .max_by(|a, b| {
                    (a - a.clamp(lo, hi))
                        .abs()
                        .total_cmp(&(b - b.clamp(lo, hi)).abs())
                });
            if let (Some(speed), Some(problem)) = (outside, table.outside_speeds_message(speeds)) {
                warnings.push(ModelWarning {
                    file: self.source.clone(),
                    field: format!(
                        "{} {}",
                        if b.kind.is_seal() { "seal" } else { "bearing" },
                        b.name
                    ),
                    value: (speed * 30.0 / std::f64::consts::PI * 1e3).round() / 1e3,
                    problem,
                });
            }
        }
        warnings
    }
}
