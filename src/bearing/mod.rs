//! Bearings: the force the supporting element exerts on a journal, and its
//! Jacobians, as pure functions of the journal state and the spin speed.
//!
//! Every bearing kind implements [`Bearing`]; the assembly and the solvers only
//! see that trait. Sign conventions: the force acts **on the journal**;
//! `K = −∂F/∂(x, y)` and `C = −∂F/∂(ẋ, ẏ)`, so a plain spring has positive `K`.
//! Fluid-film bearings include the metal-to-metal contact of the journal with
//! the bushing or the pads ([`contact`]), so they give a finite force for every
//! finite state: the film at and beyond `ε = 1` is defined in [`plain`].
//!
//! Evaluating a plain journal bearing (short-bearing theory) with the journal
//! below the centre at eccentricity ratio ε = 0.5, spinning at 3000 rpm:
//!
//! ```
//! use rotor_bearing::bearing::{Bearing, BearingEval, PlainBearing};
//!
//! let bearing = PlainBearing {
//!     radius: 0.05,     // m
//!     length: 0.03,     // m
//!     clearance: 1e-4,  // m
//!     viscosity: 0.02,  // Pa·s
//!     contact: None,    // steel contact law of this geometry at ε = 1
//! };
//! let speed = 3000.0 * std::f64::consts::PI / 30.0; // rad/s
//! let q = [0.0, -0.5e-4]; // journal position (m)
//! let qdot = [0.0, 0.0]; // journal velocity (m/s)
//! let mut eval = BearingEval::new(2 + bearing.internal_dofs());
//! bearing.evaluate(&q, &qdot, speed, &mut eval)?;
//! let f = eval.journal();
//! // The film carries the journal (force upward) and pushes it sideways
//! // (attitude angle), with positive direct stiffness and damping.
//! assert!(f.force.y > 0.0 && f.force.x.abs() > 0.0);
//! assert!(f.stiffness[(1, 1)] > 0.0 && f.damping[(0, 0)] > 0.0);
//! let report = bearing.report(&q, &qdot, speed, &eval);
//! assert!((report.eccentricity - 0.5).abs() < 1e-12);
//! # Ok::<(), rotor_bearing::bearing::BearingError>(())
//! ```

pub mod coefficients;
pub mod contact;
pub mod equilibrium;
pub mod film;
mod film_lanes;
pub mod film_table;
pub mod film_table_cache;
pub mod finite_bearing;
pub mod finite_film;
pub mod linear;
pub mod magnetic_pull;
pub mod offset;
pub mod oil;
pub mod pad;
mod pad_coordinates;
pub mod pad_table;
mod pad_tally;
pub mod plain;
pub mod reynolds;
pub mod rub;
pub mod short_film;
pub mod table;
pub mod thrust;
pub mod tilting_pad;

use nalgebra::{Matrix2, Vector2};

pub use linear::LinearBearing;
pub use magnetic_pull::MagneticPull;
pub use plain::PlainBearing;
pub use rub::RubElement;
pub use table::{CoefficientTable, SealElement, TableBearing};
pub use tilting_pad::TiltingPadBearing;

/// Position and velocity of a journal centre relative to the bearing centre.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct JournalState {
    /// Displacement (m), `(x, y)`.
    pub position: Vector2<f64>,
    /// Velocity (m/s), `(ẋ, ẏ)`.
    pub velocity: Vector2<f64>,
}

impl JournalState {
    /// The journal part `(x, y)`, `(ẋ, ẏ)` of generalized coordinates `q`, `q̇`.
    pub fn from_coordinates(q: &[f64], qdot: &[f64]) -> Self {
        Self {
            position: Vector2::new(q[0], q[1]),
            velocity: Vector2::new(qdot[0], qdot[1]),
        }
    }
}

/// Force on the journal with its stiffness and damping Jacobians.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BearingForce {
    /// Force on the journal (N).
    pub force: Vector2<f64>,
    /// `K = −∂F/∂(x, y)` (N/m), `K[(i, j)] = −∂F_i/∂x_j`.
    pub stiffness: Matrix2<f64>,
    /// `C = −∂F/∂(ẋ, ẏ)` (N·s/m).
    pub damping: Matrix2<f64>,
}

/// Why a bearing cannot give a force for a state.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum BearingError {
    /// An input was NaN or infinite.
    #[error("bearing input {what} is not finite ({value})")]
    NotFinite { what: &'static str, value: f64 },
    /// State vectors of the wrong length.
    #[error("bearing state has {found} coordinates, expected {expected}")]
    Dimension { expected: usize, found: usize },
    /// The finite-length film could not be solved.
    #[error(transparent)]
    Reynolds(#[from] reynolds::ReynoldsError),
}

/// Quantities a bearing reports besides its force (for outputs and coupling).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct BearingReport {
    /// Eccentricity ratio `ε = e/C` (–); zero for bearings without a clearance.
    pub eccentricity: f64,
    /// Attitude angle (rad): from the load line to the eccentricity vector, in the spin direction.
    pub attitude_angle: f64,
    /// Minimum film thickness `C (1 − ε)` (m), zero in contact or without a film.
    pub min_film_thickness: f64,
    /// Friction torque on the journal, opposing the spin (N·m): film shear plus
    /// contact friction `μ N R` (at standstill the breakaway torque).
    pub friction_torque: f64,
    /// Power dissipated (W): the film's shear torque times the speed plus the
    /// contact friction's `μ N |v_s|` at the sliding velocity (spin and whirl).
    pub power_loss: f64,
    /// Normal force of the journal's metal-to-metal contact (N); zero while
    /// the journal floats. For tilting pads the magnitude of the resultant over the pads.
    pub contact_force: f64,
}

/// Generalized forces and Jacobians of a bearing with `n = 2 + m` coordinates
/// `q = [x, y, internal…]` (internal: pad tilts of a tilting-pad bearing),
/// and the constant mass of the internal coordinates.
/// Buffers are sized once, so evaluation allocates nothing.
#[derive(Debug, Clone, PartialEq)]
pub struct BearingEval {
    n: usize,
    /// Mass of each internal coordinate (kg; the diagonal `M_pp`, length
    /// `n − 2`), written by [`Bearing::evaluate`] from
    /// [`Bearing::internal_mass`]; zeros for massless coordinates. Its
    /// inertia `−M_pp p̈` is the integrator's and the linear analyses'
    /// (`Z = K + sC + s²M`), not part of `force`.
    pub mass: Vec<f64>,
    /// Generalized forces `Q` (N on the journal, then N for each pad tilt).
    pub force: Vec<f64>,
    /// `K = −∂Q/∂q`, row-major `n × n`.
    pub stiffness: Vec<f64>,
    /// `C = −∂Q/∂q̇`, row-major `n × n`.
    pub damping: Vec<f64>,
}

impl BearingEval {
    /// Zeroed buffers for `n` generalized coordinates.
    pub fn new(n: usize) -> Self {
        Self {
            n,
            mass: vec![0.0; n.saturating_sub(2)],
            force: vec![0.0; n],
            stiffness: vec![0.0; n * n],
            damping: vec![0.0; n * n],
        }
    }

    /// Number of generalized coordinates.
    pub fn n(&self) -> usize {
        self.n
    }

    /// `K[i][j]`.
    pub fn k(&self, i: usize, j: usize) -> f64 {
        self.stiffness[i * self.n + j]
    }

    /// `C[i][j]`.
    pub fn c(&self, i: usize, j: usize) -> f64 {
        self.damping[i * self.n + j]
    }

    /// The journal block: force on the journal and its 2×2 Jacobians (the
    /// internal coordinates held fixed).
    pub fn journal(&self) -> BearingForce {
        BearingForce {
            force: Vector2::new(self.force[0], self.force[1]),
            stiffness: Matrix2::new(self.k(0, 0), self.k(0, 1), self.k(1, 0), self.k(1, 1)),
            damping: Matrix2::new(self.c(0, 0), self.c(0, 1), self.c(1, 0), self.c(1, 1)),
        }
    }

    fn clear(&mut self) {
        self.force.fill(0.0);
        self.stiffness.fill(0.0);
        self.damping.fill(0.0);
    }

    /// The force part of [`BearingEval::add_transformed`]: `Q += Tᵀ f`.
    fn add_force(&mut self, f: &Vector2<f64>, internal: Option<(usize, f64, f64)>) {
        self.force[0] += f.x;
        self.force[1] += f.y;
        if let Some((m, a, b)) = internal {
            self.force[2 + m] += a * f.x + b * f.y;
        }
    }

    /// Add a journal-type contribution `f, K, C` acting on the effective
    /// journal coordinates `(x_e, y_e) = (x, y) + Σ q_i (a_i, b_i)` of two
    /// internal coordinates `internal = [(i, a_i, b_i); 2]` (indices into `q`),
    /// i.e. with `T = [[1, 0, a_1, a_2], [0, 1, b_1, b_2]]`: `Q += Tᵀ f`,
    /// `K += Tᵀ K T`, `C += Tᵀ C T` (a pad's tilt and radial displacement).
    fn add_columns(&mut self, part: &BearingForce, internal: [(usize, f64, f64); 2]) {
        let n = self.n;
        let cols = [(0, 1.0, 0.0), (1, 0.0, 1.0), internal[0], internal[1]];
        let f = &part.force;
        for &(r, a, b) in &cols {
            self.force[r] += a * f.x + b * f.y;
        }
        for (mat, out) in [
            (&part.stiffness, &mut self.stiffness),
            (&part.damping, &mut self.damping),
        ] {
            for &(c, a, b) in &cols {
                let col = [
                    mat[(0, 0)] * a + mat[(0, 1)] * b,
                    mat[(1, 0)] * a + mat[(1, 1)] * b,
                ];
                for &(r, ra, rb) in &cols {
                    out[r * n + c] += ra * col[0] + rb * col[1];
                }
            }
        }
    }

    /// Add a journal-type contribution `f, K, C` acting on the effective journal
    /// coordinates `(x_e, y_e) = (x, y) + η·(a, b)` of internal coordinate
    /// `internal` (`None`: the journal itself), i.e. with `T = [[1, 0, a], [0, 1, b]]`:
    /// `Q += Tᵀ f`, `K += Tᵀ K T`, `C += Tᵀ C T`.
    fn add_transformed(&mut self, part: &BearingForce, internal: Option<(usize, f64, f64)>) {
        let n = self.n;
        let (k, c) = (&part.stiffness, &part.damping);
        self.add_force(&part.force, internal);
        for i in 0..2 {
            for j in 0..2 {
                self.stiffness[i * n + j] += k[(i, j)];
                self.damping[i * n + j] += c[(i, j)];
            }
        }
        let Some((m, a, b)) = internal else {
            return;
        };
        // Third row and column of T = [[1, 0, a], [0, 1, b]]: t = (a, b).
        let p = 2 + m;
        for (mat, out) in [(k, &mut self.stiffness), (c, &mut self.damping)] {
            let col = [
                mat[(0, 0)] * a + mat[(0, 1)] * b,
                mat[(1, 0)] * a + mat[(1, 1)] * b,
            ];
            let row = [
                a * mat[(0, 0)] + b * mat[(1, 0)],
                a * mat[(0, 1)] + b * mat[(1, 1)],
            ];
            for i in 0..2 {
                out[i * n + p] += col[i];
                out[p * n + i] += row[i];
            }
            out[p * n + p] += a * col[0] + b * col[1];
        }
    }
}

/// A bearing kind: generalized force and Jacobians from the state and spin speed.
pub trait Bearing: Send + Sync + std::fmt::Debug {
    /// Internal generalized coordinates besides the journal's `(x, y)`: the pad
    /// tilts `η = ψ R` (m) of a tilting-pad bearing; none for other kinds.
    fn internal_dofs(&self) -> usize {
        0
    }

    /// The constant mass (kg) of internal coordinate `m`, its inertia
    /// `−M_m q̈_m` in its balance (a pad's moment of inertia over the squared
    /// radius on its tilt `η = ψR`); zero (the default) for a massless
    /// coordinate, whose balance is first order.
    fn internal_mass(&self, _m: usize) -> f64 {
        0.0
    }

    /// Forces and Jacobians at `q = [x, y, internal…]`, `q̇` likewise (SI), spin
    /// speed `speed` (rad/s), written into `out` (sized `2 + internal_dofs()`).
    fn evaluate(
        &self,
        q: &[f64],
        qdot: &[f64],
        speed: f64,
        out: &mut BearingEval,
    ) -> Result<(), BearingError>;

    /// True when the force is linear in the state and independent of speed, so it
    /// can be assembled once into the global matrices.
    fn is_linear(&self) -> bool;

    /// The balance of internal coordinate `m` alone at `q`, `q̇`: its
    /// generalized force `Q_m` and `K_mm = −∂Q_m/∂q_m`, `C_mm = −∂Q_m/∂q̇_m`
    /// (the diagonal entries [`Bearing::evaluate`] gives), for a solver that
    /// settles one pad's tilt at a time (`solver::pad_balance`). A pad's
    /// balance depends on the journal and its own tilt only. `None` for
    /// kinds that do not give it.
    fn internal_balance(
        &self,
        _m: usize,
        _q: &[f64],
        _qdot: &[f64],
        _speed: f64,
    ) -> Option<Result<[f64; 3], BearingError>> {
        None
    }

    /// A starting guess of the internal coordinates for a static solve with the
    /// journal at `journal` (m), spin `speed`, written into `internal`.
    fn guess_internal(&self, _journal: [f64; 2], _speed: f64, internal: &mut [f64]) {
        internal.fill(0.0);
    }

    /// Move internal coordinates that sit on a branch a static solve must not
    /// end on (a tilting pad that carries nothing where a loaded zero-moment
    /// tilt exists) to the right one, with the journal held at `q[..2]`;
    /// returns whether any moved. Nothing to do for other kinds.
    fn reseat_internal(&self, _q: &mut [f64], _speed: f64) -> bool {
        false
    }

    /// Where a journal pushed along the unit vector `direction` comes to rest
    /// when its film carries nothing: the distance (m) from the bearing centre
    /// at which it touches and the contact stiffness (N/m) there; `None` for a
    /// bearing without contact (a linear one).
    fn resting_contact(&self, _direction: [f64; 2]) -> Option<(f64, f64)> {
        None
    }

    /// How deep and how hard the journal touches its stator at `q`, `q̇` and
    /// spin `speed`, against the limits of the contact law (the worst over
    /// its contacts, [`contact::ContactExtent`]); `None` out of contact, and
    /// for a bearing without contact.
    fn contact_extent(
        &self,
        _q: &[f64],
        _qdot: &[f64],
        _speed: f64,
    ) -> Option<contact::ContactExtent> {
        None
    }

    /// A start for Newton's search of the equilibrium under `load` (N on
    /// the journal) at `speed` ([`equilibrium::journal_equilibrium`]), tried
    /// before the centred journal; `None` (the default): no better start
    /// than the centre. The finite film starts from its short twin's
    /// equilibrium.
    fn equilibrium_start(&self, _load: [f64; 2], _speed: f64) -> Option<Vec<f64>> {
        None
    }

    /// Eccentricity, attitude angle, film thickness, contact and friction at
    /// `q`, `q̇`, with `eval` the evaluation there.
    fn report(&self, _q: &[f64], _qdot: &[f64], _speed: f64, _eval: &BearingEval) -> BearingReport {
        BearingReport::default()
    }

    /// The generalized forces of [`Bearing::evaluate`] alone, the same numbers,
    /// in `out.force`; the Jacobians in `out` are left unspecified, so kinds
    /// may skip them (what a Newton iteration on frozen Jacobians needs).
    fn forces(
        &self,
        q: &[f64],
        qdot: &[f64],
        speed: f64,
        out: &mut BearingEval,
    ) -> Result<(), BearingError> {
        self.evaluate(q, qdot, speed, out)
    }

    /// Whether [`Bearing::forces`] costs markedly less than
    /// [`Bearing::evaluate`] (it skips the Jacobians): only then do Newton
    /// iterations on frozen Jacobians pay. No by default, where `forces` is
    /// `evaluate`.
    fn cheap_forces(&self) -> bool {
        false
    }

    /// What a front end reports at `q`, `q̇`, `speed`: the generalized forces
    /// in `out.force` and the film report, the numbers [`Bearing::evaluate`]
    /// and [`Bearing::report`] give; the Jacobians in `out` are left
    /// unspecified, so kinds may skip them (a tilting-pad bearing does).
    fn output(
        &self,
        q: &[f64],
        qdot: &[f64],
        speed: f64,
        out: &mut BearingEval,
    ) -> Result<BearingReport, BearingError> {
        self.evaluate(q, qdot, speed, out)?;
        Ok(self.report(q, qdot, speed, out))
    }
}

/// Force and 2×2 Jacobians of a bearing without internal coordinates at a
/// journal state (for journal-only bearings and tests).
pub fn journal_force(
    bearing: &dyn Bearing,
    state: &JournalState,
    speed: f64,
) -> Result<BearingForce, BearingError> {
    let mut out = BearingEval::new(2);
    let q = [state.position.x, state.position.y];
    let qd = [state.velocity.x, state.velocity.y];
    bearing.evaluate(&q, &qd, speed, &mut out)?;
    Ok(out.journal())
}

/// Check lengths and finiteness of a generalized state.
pub(crate) fn check_state(
    n: usize,
    q: &[f64],
    qdot: &[f64],
    speed: f64,
    out: &BearingEval,
) -> Result<(), BearingError> {
    if q.len() != n || qdot.len() != n || out.n() != n {
        return Err(BearingError::Dimension {
            expected: n,
            found: q.len().max(qdot.len()).max(out.n()),
        });
    }
    let names = ["x", "y"];
    for (k, (&v, &w)) in q.iter().zip(qdot).enumerate() {
        let what = names.get(k).copied().unwrap_or("pad tilt");
        if !v.is_finite() {
            return Err(BearingError::NotFinite { what, value: v });
        }
        if !w.is_finite() {
            return Err(BearingError::NotFinite {
                what: "velocity",
                value: w,
            });
        }
    }
    if !speed.is_finite() {
        return Err(BearingError::NotFinite {
            what: "speed",
            value: speed,
        });
    }
    Ok(())
}

/// Bearing type and parameters as given in a model file (plain data).
#[derive(Debug, Clone, PartialEq)]
pub enum BearingKind {
    /// Linear spring–damper: `F = −K q − C q̇`.
    Linear {
        /// Stiffness (N/m), row-major `[[kxx, kxy], [kyx, kyy]]`.
        stiffness: [[f64; 2]; 2],
        /// Damping (N·s/m), row-major.
        damping: [[f64; 2]; 2],
    },
    /// Plain journal bearing, short-bearing theory with π-film cavitation.
    Plain(PlainBearing),
    /// Tilting-pad journal bearing, short-bearing film on each pad.
    TiltingPad(TiltingPadBearing),
    /// Rub element (`[[rubs]]`): contact with a stator ring only.
    Rub(RubElement),
    /// Linear coefficients over speed (`type = "table"`).
    Table(TableBearing),
    /// Seal (`[[seals]]`): coefficients over speed, optionally closing on its stator.
    Seal(SealElement),
    /// Unbalanced magnetic pull (`[[magnetic_pull]]`) with the stator contact.
    MagneticPull(MagneticPull),
    /// A plain or tilting-pad bearing on the finite-length Reynolds film
    /// (`film = "finite"`).
    FiniteFilm(finite_bearing::FiniteFilmBearing),
}

impl BearingKind {
    /// The bearing model for these parameters.
    pub fn build(&self) -> Box<dyn Bearing> {
        match self {
            BearingKind::Linear { stiffness, damping } => {
                Box::new(LinearBearing::new(*stiffness, *damping))
            }
            BearingKind::Plain(b) => Box::new(*b),
            BearingKind::TiltingPad(b) => Box::new(b.clone()),
            BearingKind::Rub(r) => Box::new(*r),
            BearingKind::Table(t) => Box::new(t.clone()),
            BearingKind::Seal(s) => Box::new(s.clone()),
            BearingKind::MagneticPull(m) => Box::new(*m),
            BearingKind::FiniteFilm(f) => Box::new(f.clone()),
        }
    }

    /// A finite film's force tables (a plain film's, or tilting pads' one
    /// per arc) that were built (not read from the cache) when the model was
    /// read: their geometry and build time
    /// ([`film_table_cache::PreparedTable::describe`]), one table a line.
    pub fn film_table_note(&self) -> Option<String> {
        let BearingKind::FiniteFilm(f) = self else {
            return None;
        };
        let built = |origin: &film_table_cache::TableOrigin| {
            !matches!(origin, film_table_cache::TableOrigin::Loaded(_))
        };
        let lines: Vec<String> = f
            .table
            .iter()
            .filter(|t| built(&t.origin))
            .map(|t| t.describe())
            .chain(
                f.pad_tables
                    .iter()
                    .filter(|t| built(&t.origin))
                    .map(|t| t.describe()),
            )
            .collect();
        (!lines.is_empty()).then(|| lines.join("\n"))
    }

    /// Whether this is a magnetic pull rather than a bearing.
    pub fn is_magnetic_pull(&self) -> bool {
        matches!(self, BearingKind::MagneticPull(_))
    }

    /// Whether it supports the rotor (a bearing), rather than a rub, seal or
    /// magnetic pull acting on it.
    pub fn is_bearing(&self) -> bool {
        !(self.is_rub() || self.is_seal() || self.is_magnetic_pull())
    }

    /// The field excitation (0–1) of a magnetic pull, `None` for the others.
    pub fn excitation(&self) -> Option<f64> {
        match self {
            BearingKind::MagneticPull(m) => Some(m.excitation),
            _ => None,
        }
    }

    /// Set the field excitation of a magnetic pull; `false` (nothing changed)
    /// for the others.
    pub fn set_excitation(&mut self, excitation: f64) -> bool {
        match self {
            BearingKind::MagneticPull(m) => {
                m.excitation = excitation;
                true
            }
            _ => false,
        }
    }

    /// The constant added mass of a table bearing or seal (kg, row-major,
    /// acting on the journal's acceleration relative to its housing), `None`
    /// for the others.
    pub fn added_mass(&self) -> Option<[[f64; 2]; 2]> {
        match self {
            BearingKind::Table(t) => Some(t.added_mass),
            BearingKind::Seal(s) => Some(s.added_mass),
            _ => None,
        }
        .filter(|m| m.iter().flatten().any(|&v| v != 0.0))
    }

    /// The coefficient table of a table bearing or seal.
    pub fn coefficient_table(&self) -> Option<&CoefficientTable> {
        match self {
            BearingKind::Table(t) => Some(&t.table),
            BearingKind::Seal(s) => Some(&s.table),
            _ => None,
        }
    }

    /// Whether this is a seal rather than a bearing.
    pub fn is_seal(&self) -> bool {
        matches!(self, BearingKind::Seal(_))
    }

    /// Whether this is a rub element rather than a bearing.
    pub fn is_rub(&self) -> bool {
        matches!(self, BearingKind::Rub(_))
    }

    /// Whether the force depends nonlinearly on the journal state (a fluid film
    /// or a rub).
    pub fn is_nonlinear(&self) -> bool {
        !matches!(self, BearingKind::Linear { .. })
    }

    /// Film geometry and oil of a fluid-film bearing, `None` for a linear one.
    /// For tilting pads the clearance is the pad (machined) clearance.
    pub fn film_geometry(&self) -> Option<FilmGeometry> {
        let (radius, length, clearance, viscosity) = match self {
            BearingKind::Linear { .. }
            | BearingKind::Rub(_)
            | BearingKind::Table(_)
            | BearingKind::Seal(_)
            | BearingKind::MagneticPull(_) => return None,
            BearingKind::Plain(b) => (b.radius, b.length, b.clearance, b.viscosity),
            BearingKind::TiltingPad(b) => (b.radius, b.length, b.clearance, b.viscosity),
            BearingKind::FiniteFilm(f) => return f.short_kind().film_geometry(),
        };
        Some(FilmGeometry {
            radius,
            length,
            clearance,
            viscosity,
        })
    }

    /// Oil dynamic viscosity (Pa·s) of a fluid-film bearing, `None` for a linear one.
    pub fn viscosity(&self) -> Option<f64> {
        self.film_geometry().map(|g| g.viscosity)
    }

    /// The one value a master may tune on this bearing: the oil viscosity
    /// (Pa·s) of a fluid-film bearing, the field excitation of a magnetic pull.
    pub fn tuned(&self) -> Option<f64> {
        self.viscosity().or_else(|| self.excitation())
    }

    /// Set the [`Self::tuned`] value; `false` (nothing changed) where there is none.
    pub fn set_tuned(&mut self, value: f64) -> bool {
        self.set_viscosity(value) || self.set_excitation(value)
    }

    /// Set the oil viscosity (Pa·s); `false` (and nothing changed) for a linear bearing.
    pub fn set_viscosity(&mut self, viscosity: f64) -> bool {
        match self {
            BearingKind::Linear { .. }
            | BearingKind::Rub(_)
            | BearingKind::Table(_)
            | BearingKind::Seal(_)
            | BearingKind::MagneticPull(_) => return false,
            BearingKind::Plain(b) => b.viscosity = viscosity,
            BearingKind::TiltingPad(b) => b.viscosity = viscosity,
            BearingKind::FiniteFilm(f) => f.set_viscosity(viscosity),
        }
        true
    }

    /// Radial clearance (m) the journal moves in: the bushing clearance of a plain
    /// bearing, the assembled clearance `C (1 − preload)` of tilting pads, the
    /// radial gap of a rub element or of a seal that can touch; `None` for a
    /// linear or table bearing and a seal without a clearance.
    pub fn journal_clearance(&self) -> Option<f64> {
        match self {
            BearingKind::Linear { .. } | BearingKind::Table(_) => None,
            BearingKind::Plain(b) => Some(b.clearance),
            BearingKind::TiltingPad(b) => Some(b.assembled_clearance()),
            BearingKind::Rub(r) => Some(r.contact.gap),
            BearingKind::Seal(s) => s.contact.map(|c| c.gap),
            BearingKind::MagneticPull(m) => Some(m.gap),
            BearingKind::FiniteFilm(f) => f.short_kind().journal_clearance(),
        }
    }

    /// The short-film bearing of the same geometry: itself for every kind
    /// but a finite-film bearing, whose plain or tilting-pad twin it gives
    /// (for what does not depend on the film's theory: geometry, pads,
    /// descriptions).
    pub fn short_film(&self) -> std::borrow::Cow<'_, BearingKind> {
        match self {
            BearingKind::FiniteFilm(f) => std::borrow::Cow::Owned(f.short_kind()),
            other => std::borrow::Cow::Borrowed(other),
        }
    }
}

/// Geometry and oil of a fluid-film bearing (SI units).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FilmGeometry {
    /// Journal radius R (m).
    pub radius: f64,
    /// Axial length L (m).
    pub length: f64,
    /// Radial clearance C (m); for tilting pads the pad clearance.
    pub clearance: f64,
    /// Dynamic viscosity μ (Pa·s).
    pub viscosity: f64,
}

impl FilmGeometry {
    /// Short-bearing load scale `k0 = μ ω R L³ / C²` (N) at spin `speed` (rad/s):
    /// the dimensionless load is `W / k0` (Ocvirk's Sommerfeld-type number).
    pub fn load_scale(&self, speed: f64) -> f64 {
        self.viscosity * speed * self.radius * self.length.powi(3) / self.clearance.powi(2)
    }
}
