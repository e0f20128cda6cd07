//! The `[[bearings]]` entries of the model file as written by a user (one
//! variant per `type`, every unknown key rejected), and the table
//! coefficient they and the seals share; the rest of the file is
//! [`super::file`].

use serde::Deserialize;

/// `[[bearings]]`, selected by `type`.
#[derive(Debug, Deserialize)]
#[serde(tag = "type", rename_all = "snake_case", deny_unknown_fields)]
pub enum BearingEntry {
    /// Linear spring–damper to ground: `F = −K q − C q̇` on (x, y).
    Linear {
        name: Option<String>,
        node: Option<i64>,
        z: Option<f64>,
        /// The pedestal (`[[pedestals]]` name) its housing stands on; default rigid ground.
        pedestal: Option<String>,
        /// Housing centre off the nominal axis (m), x and y (default 0).
        offset_x: Option<f64>,
        offset_y: Option<f64>,
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
        /// The pedestal (`[[pedestals]]` name) its housing stands on; default rigid ground.
        pedestal: Option<String>,
        /// Housing centre off the nominal axis (m), x and y (default 0).
        offset_x: Option<f64>,
        offset_y: Option<f64>,
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
        /// The film theory: `"short"` (Ocvirk, the default) or `"finite"`
        /// (the finite-length Reynolds film).
        film: Option<String>,
        /// With `film = "finite"`: `[n_theta, n_z]`, intervals around the
        /// circle (a pad's arc) and over half the length.
        film_mesh: Option<Vec<i64>>,
        /// With `film = "finite"`: `"swift_stieber"` (Reynolds, the default)
        /// or `"gumbel"` (half-Sommerfeld).
        cavitation: Option<String>,
        /// With `film = "finite"` on a plain bearing: `true` evaluates the
        /// film by force tables (built once per geometry and cached),
        /// `false` (the default) by direct Reynolds solves.
        film_tables: Option<bool>,
    },
    /// Linear coefficients over speed (a vendor's bearing code), PCHIP-interpolated.
    Table {
        name: Option<String>,
        node: Option<i64>,
        z: Option<f64>,
        /// The pedestal (`[[pedestals]]` name) its housing stands on; default rigid ground.
        pedestal: Option<String>,
        /// Housing centre off the nominal axis (m), x and y (default 0).
        offset_x: Option<f64>,
        offset_y: Option<f64>,
        /// Speeds of the table rows (rpm), increasing; with the coefficient
        /// columns below. Omit for constant coefficients.
        speeds_rpm: Option<Vec<f64>>,
        /// Coefficients (N/m, N·s/m): one value, or one per speed.
        kxx: Option<Coefficient>,
        kxy: Option<Coefficient>,
        kyx: Option<Coefficient>,
        kyy: Option<Coefficient>,
        cxx: Option<Coefficient>,
        cxy: Option<Coefficient>,
        cyx: Option<Coefficient>,
        cyy: Option<Coefficient>,
        /// A CSV file (beside the model file) with a `speed_rpm` column and
        /// any of the coefficient columns, instead of the inline table.
        table: Option<String>,
        /// Added mass (kg), constant over speed.
        mxx: Option<f64>,
        mxy: Option<f64>,
        myx: Option<f64>,
        myy: Option<f64>,
    },
    /// Tilting-pad journal bearing: short-bearing film on each pad, pads tilt freely.
    TiltingPad {
        name: Option<String>,
        node: Option<i64>,
        z: Option<f64>,
        /// The pedestal (`[[pedestals]]` name) its housing stands on; default rigid ground.
        pedestal: Option<String>,
        /// Housing centre off the nominal axis (m), x and y (default 0).
        offset_x: Option<f64>,
        offset_y: Option<f64>,
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
        /// Radial stiffness of each pad's pivot (N/m), default rigid.
        pivot_stiffness: Option<f64>,
        /// Each pad's moment of inertia about its pivot (kg·m²), default 0.
        pad_inertia: Option<f64>,
        /// Each pad's mass (kg) on its pivot spring, default 0 (needs
        /// `pivot_stiffness`).
        pad_mass: Option<f64>,
        /// Radial damping of each pad's pivot (N·s/m), default 0 (needs
        /// `pivot_stiffness`).
        pivot_damping: Option<f64>,
        /// Contact penalty stiffness (N/m) once the journal touches; default
        /// the steel line contact `(π/4) E* L` of `ContactLaw::steel`.
        contact_stiffness: Option<f64>,
        /// Contact damping (N·s/m); default 1e-5 s × the contact stiffness.
        contact_damping: Option<f64>,
        /// Coulomb friction coefficient of the contact (–), default 0.2.
        friction_coefficient: Option<f64>,
        /// The film theory: `"short"` (Ocvirk, the default) or `"finite"`
        /// (the finite-length Reynolds film).
        film: Option<String>,
        /// With `film = "finite"`: `[n_theta, n_z]`, intervals around the
        /// circle (a pad's arc) and over half the length.
        film_mesh: Option<Vec<i64>>,
        /// With `film = "finite"`: `"swift_stieber"` (Reynolds, the default)
        /// or `"gumbel"` (half-Sommerfeld).
        cavitation: Option<String>,
        /// With `film = "finite"` on a plain bearing: `true` evaluates the
        /// film by force tables (built once per geometry and cached),
        /// `false` (the default) by direct Reynolds solves.
        film_tables: Option<bool>,
    },
}

/// A table coefficient: one value for every speed, or one per speed.
#[derive(Debug, Clone, Deserialize)]
#[serde(untagged)]
pub enum Coefficient {
    /// The same value at every speed.
    Constant(f64),
    /// One value per entry of `speeds_rpm`.
    Column(Vec<f64>),
}
