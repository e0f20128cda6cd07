//! The physical range every size, mass and stiffness of a model file must lie
//! in. A value outside is not a machine but a unit slip or a typo (a diameter
//! of 1e300 m, a disk of 1e12 kg), and would reach the solver as an infinite
//! mass or a NaN: it is refused with the field, file, line, value and range.
//! The ranges are wide on purpose: from micro-turbines to the largest hydro
//! generators, and the idealizations models use (a "rigid" shaft of
//! E = 1e15 Pa, a "massless" one of 1e-6 kg/m³).

/// A closed range `[min, max]` in `unit`, and why it is where it is.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Limit {
    /// Smallest value allowed.
    pub min: f64,
    /// Largest value allowed.
    pub max: f64,
    /// SI unit, for the message.
    pub unit: &'static str,
    /// What lies at the ends, for the message.
    pub why: &'static str,
}

impl Limit {
    /// Whether `v` is finite and within the range.
    pub fn holds(&self, v: f64) -> bool {
        v.is_finite() && (self.min..=self.max).contains(&v)
    }
}

/// Shaft section lengths, bearing lengths, disk widths (m).
pub const LENGTH: Limit = Limit {
    min: 1e-6,
    max: 1e3,
    unit: "m",
    why: "from a micrometre to a kilometre: the longest shaft lines are about 100 m",
};

/// Outer diameters of shaft sections and disks (m).
pub const DIAMETER: Limit = Limit {
    min: 1e-5,
    max: 100.0,
    unit: "m",
    why: "from 10 µm to 100 m: the largest hydro-generator rotors are about 20 m across",
};

/// Journal radii of fluid-film bearings and rotor radii of rubs (m).
pub const RADIUS: Limit = Limit {
    min: 5e-6,
    max: 50.0,
    unit: "m",
    why: "half of the diameter range",
};

/// Offsets of bearing, seal, stator and pedestal centres from the nominal
/// straight axis (m).
pub const OFFSET: Limit = Limit {
    min: -1.0,
    max: 1.0,
    unit: "m",
    why: "a bearing set a metre off its shaft's axis is a unit slip (alignment offsets are micrometres to millimetres)",
};

/// Radial clearances of fluid-film bearings and gaps of rubs (m).
pub const CLEARANCE: Limit = Limit {
    min: 1e-7,
    max: 1.0,
    unit: "m",
    why: "from 0.1 µm, the roughness of a lapped journal, to 1 m",
};

/// Diametral clearances of fluid-film bearings (m): twice [`CLEARANCE`].
pub const DIAMETRAL_CLEARANCE: Limit = Limit {
    min: 2e-7,
    max: 2.0,
    unit: "m",
    why: "twice the radial clearance's range, from 0.1 µm to 1 m",
};

/// Disk masses (kg).
pub const MASS: Limit = Limit {
    min: 1e-6,
    max: 1e7,
    unit: "kg",
    why: "from a milligram to 10 000 t: the heaviest generator rotors weigh 2 000–4 000 t",
};

/// Polar and diametral inertias of disks (kg·m²).
pub const INERTIA: Limit = Limit {
    min: 1e-18,
    max: 1e10,
    unit: "kg·m²",
    why: "a milligram at 1 µm to 10 000 t at 30 m",
};

/// Density of a material (kg/m³).
pub const DENSITY: Limit = Limit {
    min: 1e-9,
    max: 1e5,
    unit: "kg/m³",
    why: "up to 4 × osmium; down to the near-zero density of a massless-shaft idealization",
};

/// Young's and shear moduli of a material (Pa).
pub const MODULUS: Limit = Limit {
    min: 1e3,
    max: 1e17,
    unit: "Pa",
    why: "from soft foam to 1e5 × steel, which holds rigid-shaft idealizations",
};

/// Stiffness of linear bearings, entry by entry (N/m).
pub const STIFFNESS: Limit = Limit {
    min: -1e15,
    max: 1e15,
    unit: "N/m",
    why: "the stiffest supports are about 1e10 N/m; 1e15 N/m is rigid",
};

/// Damping of linear bearings, entry by entry, and contact damping (N·s/m).
pub const DAMPING: Limit = Limit {
    min: -1e12,
    max: 1e12,
    unit: "N·s/m",
    why: "squeeze-film dampers reach about 1e7 N·s/m",
};

/// Contact stiffness of journal–stator contacts and rubs (N/m).
pub const CONTACT_STIFFNESS: Limit = Limit {
    min: 1.0,
    max: 1e15,
    unit: "N/m",
    why: "a steel line contact is about 1e9–1e11 N/m",
};

/// Radial stiffness of a tilting pad's pivot (N/m).
pub const PIVOT_STIFFNESS: Limit = Limit {
    min: 1.0,
    max: 1e15,
    unit: "N/m",
    why: "a pad's pivot, liner and housing in series are about 1e8–1e10 N/m; 1e15 N/m is rigid",
};

/// Radial damping of a tilting pad's pivot (N·s/m).
pub const PIVOT_DAMPING: Limit = Limit {
    min: 0.0,
    max: 1e12,
    unit: "N·s/m",
    why: "a pivot's own damping is far below its pad's squeeze film, about 1e7–1e9 N·s/m",
};

/// A tilting pad's moment of inertia about its pivot (kg·m²).
pub const PAD_INERTIA: Limit = Limit {
    min: 0.0,
    max: 1e6,
    unit: "kg·m²",
    why: "the pads of the largest guide bearings are about 1e2 kg·m²",
};

/// A tilting pad's mass (kg).
pub const PAD_MASS: Limit = Limit {
    min: 0.0,
    max: 1e6,
    unit: "kg",
    why: "the pads of the largest guide bearings weigh about 1 t",
};

/// Largest field excitation of a magnetic pull (2: twice the nominal flux,
/// beyond any over-excitation a generator survives), also the FMU's bound.
pub const MAX_EXCITATION: f64 = 2.0;

/// Oil viscosity of fluid-film bearings (Pa·s), also the FMU's declared range.
pub const VISCOSITY: Limit = Limit {
    min: 1e-6,
    max: 1e3,
    unit: "Pa·s",
    why: "from a gas film to a heavy grease",
};

/// Unbalance of a plane (kg·m).
pub const UNBALANCE: Limit = Limit {
    min: 0.0,
    max: 1e6,
    unit: "kg·m",
    why: "10 000 t a tenth of a metre off its axis",
};

/// Axial force of the shaft (N, compression negative).
pub const AXIAL_FORCE: Limit = Limit {
    min: -1e10,
    max: 1e10,
    unit: "N",
    why: "the thrust of the largest hydro units is about 5e7 N",
};

/// Axial position of the first node (m).
pub const POSITION: Limit = Limit {
    min: -1e4,
    max: 1e4,
    unit: "m",
    why: "within ten kilometres of the origin",
};

/// Each gravity component (m/s²).
pub const GRAVITY: Limit = Limit {
    min: -1e3,
    max: 1e3,
    unit: "m/s²",
    why: "up to 100 g",
};

/// Largest spin speed (rpm).
pub const MAX_SPEED_RPM: Limit = Limit {
    min: 1e-3,
    max: 1e7,
    unit: "rpm",
    why: "the fastest micro-turbines spin at about 1e6 rpm",
};

/// Electrical grid frequency (Hz).
pub const GRID_FREQUENCY_HZ: Limit = Limit {
    min: 1.0,
    max: 1000.0,
    unit: "Hz",
    why: "public grids run at 50 or 60 Hz, aircraft and ship grids at 400 Hz",
};

/// Separation of a torsional natural frequency from an excitation (fraction).
pub const TORSIONAL_MARGIN: Limit = Limit {
    min: 0.0,
    max: 0.9,
    unit: "(fraction)",
    why: "0.1 is 10 %; a band of ±90 % would cover almost every frequency",
};

/// Pull stiffness of a generator's unbalanced magnetic pull (N/m).
pub const PULL_STIFFNESS: Limit = Limit {
    min: 1.0,
    max: 1e13,
    unit: "N/m",
    why: "the largest generators' pull is about 1e9–1e10 N/m",
};

/// Mean air-gap flux density (T).
pub const FLUX_DENSITY: Limit = Limit {
    min: 1e-3,
    max: 3.0,
    unit: "T",
    why: "iron saturates near 2 T; a generator's air gap runs at 0.6–1.1 T",
};

/// Mass of a pedestal or point mass (kg).
pub const SUPPORT_MASS: Limit = Limit {
    min: 1e-6,
    max: 1e9,
    unit: "kg",
    why: "from a milligram to a 1e6 t foundation block",
};

/// Torsional stiffness of a coupling (N·m/rad).
pub const TORSIONAL_STIFFNESS: Limit = Limit {
    min: 1e-3,
    max: 1e15,
    unit: "N·m/rad",
    why: "from a soft elastomer coupling to a rigid flange",
};

/// Lateral stiffness of a flexible coupling (N/m).
pub const COUPLING_LATERAL_STIFFNESS: Limit = Limit {
    min: 1e-3,
    max: 1e15,
    unit: "N/m",
    why: "from a soft elastomer coupling to a rigid flange",
};

/// Angular stiffness of a flexible coupling (N·m/rad).
pub const COUPLING_ANGULAR_STIFFNESS: Limit = Limit {
    min: 1e-3,
    max: 1e15,
    unit: "N·m/rad",
    why: "from a gear or disc coupling's flexing to a rigid flange",
};

/// Angular misalignment of a coupling (rad).
pub const ANGULAR_OFFSET: Limit = Limit {
    min: -0.1,
    max: 0.1,
    unit: "rad",
    why: "couplings are aligned to a fraction of a milliradian; 0.1 rad (5.7°) is a unit slip",
};

/// A stage's rated power (W): Wachel's anticipated cross-coupling.
pub const STAGE_POWER: Limit = Limit {
    min: 1.0,
    max: 1e10,
    unit: "W",
    why: "from a watt to 10 GW: the largest turbine stages carry about 1 GW",
};

/// A stage's discharge over suction density (–).
pub const DENSITY_RATIO: Limit = Limit {
    min: 0.1,
    max: 100.0,
    unit: "–",
    why: "1 for a liquid; a compressor stage raises the density by at most a few times",
};

/// A stage factor `B` (–): 3 centrifugal (Wachel), 1.5 axial (Alford).
pub const STAGE_FACTOR: Limit = Limit {
    min: 0.1,
    max: 10.0,
    unit: "–",
    why: "the published factors are 1.5 (axial) and 3 (centrifugal)",
};
