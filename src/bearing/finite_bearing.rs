//! A plain or tilting-pad bearing with the finite-length film
//! ([`super::finite_film`]) in place of the short one: the same geometry,
//! the same journal–bushing or journal–pad contact, the same pad kinematics
//! (each pad's film at its effective journal state,
//! [`TiltingPadBearing::pad_state`], so a pad's film thickness is the short
//! pad's function; generalized forces `Tᵀ F` and Jacobians `Tᵀ K T`, `Tᵀ C T`,
//! `Q_η` the pivot moment over the journal radius) and the same weak pivot
//! rest. Starting guesses and re-seating of pads during a static solve, the
//! resting contact and the report (friction is the Couette shear, which does
//! not depend on the film's length theory) are the short bearing's.

use std::sync::Arc;

use super::contact::ContactExtent;
use super::film_table::TableGeometry;
use super::film_table_cache::PreparedTable;
use super::finite_film::FiniteFilm;
use super::pad_table::{PadGeometry, PadTable};
use super::reynolds::{Cavitation, ReynoldsError, ReynoldsMesh};
use super::{
    Bearing, BearingError, BearingEval, BearingForce, BearingKind, BearingReport, JournalState,
    PlainBearing, TiltingPadBearing, check_state,
};

/// The bearing a finite-length film supports.
#[derive(Debug, Clone, PartialEq)]
pub enum FilmSupport {
    /// A full 360° plain bearing.
    Plain(PlainBearing),
    /// Tilting pads, each an arc.
    TiltingPad(TiltingPadBearing),
}

/// A plain or tilting-pad bearing on the finite-length film.
#[derive(Debug, Clone, PartialEq)]
pub struct FiniteFilmBearing {
    /// Geometry, oil, pads and contact.
    pub support: FilmSupport,
    /// The film's mesh (per pad for tilting pads).
    pub mesh: ReynoldsMesh,
    /// The cavitation condition.
    pub cavitation: Cavitation,
    /// Force tables of a plain film (`film_tables = true`,
    /// [`super::film_table`]): used while they match the film's geometry,
    /// the direct solves otherwise.
    pub table: Option<Arc<PreparedTable>>,
    /// Force tables of tilting pads (`film_tables = true`,
    /// [`super::pad_table`]), one per pad arc: a pad uses the one built for
    /// its film's geometry and arc, the direct solves when none is.
    pub pad_tables: Vec<Arc<PreparedTable<PadTable>>>,
}

impl FiniteFilmBearing {
    /// The finite-film twin of a plain or tilting-pad bearing on the default
    /// mesh ([`ReynoldsMesh::FULL_CIRCLE`], [`ReynoldsMesh::PAD`]), or a
    /// finite-film bearing on its own mesh with `cavitation`; `None` for
    /// other kinds.
    pub fn of(kind: &BearingKind, cavitation: Cavitation) -> Option<Self> {
        let (support, mesh, table, pad_tables) = match kind {
            BearingKind::Plain(b) => (
                FilmSupport::Plain(*b),
                ReynoldsMesh::FULL_CIRCLE,
                None,
                Vec::new(),
            ),
            BearingKind::TiltingPad(b) => (
                FilmSupport::TiltingPad(b.clone()),
                ReynoldsMesh::PAD,
                None,
                Vec::new(),
            ),
            BearingKind::FiniteFilm(f) => (
                f.support.clone(),
                f.mesh,
                f.table.clone(),
                f.pad_tables.clone(),
            ),
            _ => return None,
        };
        Some(Self {
            support,
            mesh,
            cavitation,
            table,
            pad_tables,
        })
    }

    /// The film of this bearing.
    pub fn film(&self) -> FiniteFilm {
        let (radius, length, clearance, viscosity) = match &self.support {
            FilmSupport::Plain(b) => (b.radius, b.length, b.clearance, b.viscosity),
            FilmSupport::TiltingPad(b) => (b.radius, b.length, b.clearance, b.viscosity),
        };
        FiniteFilm {
            radius,
            length,
            clearance,
            viscosity,
            mesh: self.mesh,
            cavitation: self.cavitation,
        }
    }

    /// The force table of the plain film `film` if it carries one built
    /// for that film's geometry.
    fn table_for(&self, film: &FiniteFilm) -> Option<&PreparedTable> {
        self.table
            .as_deref()
            .filter(|t| t.table.geometry() == TableGeometry::of(film))
    }

    /// The force table of pad `k`'s film if the bearing carries one built
    /// for `film`'s geometry and that pad's arc.
    fn pad_table_for(&self, film: &FiniteFilm, arc: f64) -> Option<&PadTable> {
        let geometry = PadGeometry::of(film, arc);
        self.pad_tables
            .iter()
            .map(|t| &*t.table)
            .find(|t| t.geometry() == geometry)
    }

    /// The film of pad `k` of `b` at its effective journal `state`: force
    /// and Jacobians from the pad's table if there is one
    /// ([`PadTable::force_and_jacobian`]), else the direct Reynolds solve
    /// ([`FiniteFilm::force_and_jacobian`]) — the same question, over the
    /// pad's arc.
    fn pad_film(
        &self,
        film: &FiniteFilm,
        b: &TiltingPadBearing,
        k: usize,
        state: &JournalState,
        speed: f64,
    ) -> Result<BearingForce, ReynoldsError> {
        let pad = &b.pads[k];
        let arc = pad.film_arc();
        match self.pad_table_for(film, pad.arc()) {
            Some(t) => t.force_and_jacobian(film, state, speed, arc),
            None => film.force_and_jacobian(state, speed, Some(arc)),
        }
    }

    /// The force alone of [`Self::pad_film`].
    fn pad_film_force(
        &self,
        film: &FiniteFilm,
        b: &TiltingPadBearing,
        k: usize,
        state: &JournalState,
        speed: f64,
    ) -> Result<nalgebra::Vector2<f64>, ReynoldsError> {
        let pad = &b.pads[k];
        let arc = pad.film_arc();
        match self.pad_table_for(film, pad.arc()) {
            Some(t) => Ok(t.force_and_jacobian(film, state, speed, arc)?.force),
            None => film.force(state, speed, Some(arc)),
        }
    }

    /// The distinct pad arcs (rad) of a tilting-pad support, in pad order
    /// (none for a plain one): one table each.
    pub fn pad_arcs(&self) -> Vec<f64> {
        let mut arcs: Vec<f64> = Vec::new();
        if let FilmSupport::TiltingPad(b) = &self.support {
            for pad in &b.pads {
                if !arcs.contains(&pad.arc()) {
                    arcs.push(pad.arc());
                }
            }
        }
        arcs
    }

    /// The short-film bearing of the same geometry.
    fn short(&self) -> &dyn Bearing {
        match &self.support {
            FilmSupport::Plain(b) => b,
            FilmSupport::TiltingPad(b) => b,
        }
    }

    /// The short-film kind of the same geometry ([`BearingKind::Plain`] or
    /// [`BearingKind::TiltingPad`]).
    pub fn short_kind(&self) -> BearingKind {
        match &self.support {
            FilmSupport::Plain(b) => BearingKind::Plain(*b),
            FilmSupport::TiltingPad(b) => BearingKind::TiltingPad(b.clone()),
        }
    }

    /// Set the oil viscosity (Pa·s).
    pub fn set_viscosity(&mut self, viscosity: f64) {
        match &mut self.support {
            FilmSupport::Plain(b) => b.viscosity = viscosity,
            FilmSupport::TiltingPad(b) => b.viscosity = viscosity,
        }
    }

    /// The film's slenderness: `L/D` of a plain bearing, a pad's axial
    /// length over its arc length `L/(R β)` (the smallest of the pads').
    pub fn slenderness(&self) -> f64 {
        slenderness(&self.short_kind()).expect("a plain or tilting-pad support")
    }
}

/// Range of the slenderness ([`slenderness`]) the finite film is stated
/// for: from the short limit it was checked against (L/D = 0.05,
/// `tests/finite_film.rs`) to four times the square bearing; beyond it the
/// default mesh no longer resolves the film (a slender film's boundary layer
/// at the pad edges, a long one's axial profile).
pub const SLENDERNESS_RANGE: (f64, f64) = (0.05, 4.0);

/// Range of a pad's arc (rad) the finite film is stated for: 10° to 180°.
pub const PAD_ARC_RANGE: (f64, f64) = (10.0 * std::f64::consts::PI / 180.0, std::f64::consts::PI);

/// The slenderness of a plain bearing (`L/D`) or of tilting pads (axial
/// length over arc length, `L/(R β)`, of the longest-arc pad); `None` for
/// other kinds. The number the short film's validity is judged by.
pub fn slenderness(kind: &BearingKind) -> Option<f64> {
    match kind {
        BearingKind::Plain(b) => Some(b.length / (2.0 * b.radius)),
        BearingKind::TiltingPad(b) => {
            let arc = b.pads.iter().map(|p| p.arc()).fold(0.0, f64::max);
            Some(b.length / (b.radius * arc))
        }
        BearingKind::FiniteFilm(f) => slenderness(&f.short_kind()),
        _ => None,
    }
}

impl Bearing for FiniteFilmBearing {
    fn internal_dofs(&self) -> usize {
        self.short().internal_dofs()
    }

    fn internal_mass(&self, m: usize) -> f64 {
        self.short().internal_mass(m)
    }

    fn evaluate(
        &self,
        q: &[f64],
        qdot: &[f64],
        speed: f64,
        out: &mut BearingEval,
    ) -> Result<(), BearingError> {
        let film = self.film();
        match &self.support {
            FilmSupport::Plain(b) => {
                check_state(2, q, qdot, speed, out)?;
                let state = JournalState::from_coordinates(q, qdot);
                let part = match self.table_for(&film) {
                    Some(t) => t.table.force_and_jacobian(&film, &state, speed)?,
                    None => film.force_and_jacobian(&state, speed, None)?,
                };
                out.clear();
                out.add_transformed(&part, None);
                let (contact, _) = b
                    .contact_law()
                    .evaluate(state.position, state.velocity, speed);
                out.add_transformed(&contact, None);
            }
            FilmSupport::TiltingPad(b) => {
                let n = 2 + b.internal_dofs();
                check_state(n, q, qdot, speed, out)?;
                out.clear();
                b.write_mass(out);
                let law = b.contact_law();
                for k in 0..b.pads.len() {
                    let (s, c, state) = b.pad_state(k, q, qdot);
                    let part = self.pad_film(&film, b, k, &state, speed)?;
                    b.add_pad_part(out, k, (s, c), &part);
                    if let Some((contact, _)) = b.pad_contact(&law, k, &state, speed) {
                        b.add_pad_part(out, k, (s, c), &contact);
                    }
                    b.add_pivot(out, k, q, qdot, speed, true);
                }
            }
        }
        Ok(())
    }

    fn is_linear(&self) -> bool {
        false
    }

    /// One Reynolds solve per film (plain) or pad instead of the nine of
    /// `evaluate`'s central differences.
    fn cheap_forces(&self) -> bool {
        true
    }

    /// The forces of [`Bearing::evaluate`] alone: the film force of each
    /// film or pad ([`FiniteFilm::force`]), the contact and the pivot rest.
    fn forces(
        &self,
        q: &[f64],
        qdot: &[f64],
        speed: f64,
        out: &mut BearingEval,
    ) -> Result<(), BearingError> {
        let film = self.film();
        match &self.support {
            FilmSupport::Plain(b) => {
                check_state(2, q, qdot, speed, out)?;
                let state = JournalState::from_coordinates(q, qdot);
                let force = match self.table_for(&film) {
                    Some(t) => t.table.force_and_jacobian(&film, &state, speed)?.force,
                    None => film.force(&state, speed, None)?,
                };
                let (contact, _) = b
                    .contact_law()
                    .evaluate(state.position, state.velocity, speed);
                out.force.fill(0.0);
                out.add_force(&(force + contact.force), None);
            }
            FilmSupport::TiltingPad(b) => {
                let n = 2 + b.internal_dofs();
                check_state(n, q, qdot, speed, out)?;
                out.force.fill(0.0);
                let law = b.contact_law();
                for k in 0..b.pads.len() {
                    let (s, c, state) = b.pad_state(k, q, qdot);
                    let mut force = self.pad_film_force(&film, b, k, &state, speed)?;
                    if let Some((contact, _)) = b.pad_contact(&law, k, &state, speed) {
                        force += contact.force;
                    }
                    b.add_pad_force(out, k, (s, c), &force);
                    b.add_pivot(out, k, q, qdot, speed, false);
                }
            }
        }
        Ok(())
    }

    /// [`Bearing::forces`], then the short bearing's report on that force.
    fn output(
        &self,
        q: &[f64],
        qdot: &[f64],
        speed: f64,
        out: &mut BearingEval,
    ) -> Result<BearingReport, BearingError> {
        self.forces(q, qdot, speed, out)?;
        Ok(self.report(q, qdot, speed, out))
    }

    /// The short twin's equilibrium under the same load: the same pads and
    /// kinematics, a film that carries a little more.
    fn equilibrium_start(&self, load: [f64; 2], speed: f64) -> Option<Vec<f64>> {
        let kind = self.short_kind();
        let scale = kind.journal_clearance()?;
        let load = nalgebra::Vector2::new(load[0], load[1]);
        super::equilibrium::journal_equilibrium(self.short(), load, speed, scale)
            .ok()
            .map(|eq| eq.q)
    }

    /// Pad `m`'s moment balance alone, as the short film's
    /// ([`TiltingPadBearing`]'s), with the pad's finite film (table or
    /// direct solve); `None` for a plain film (no internal coordinates) and
    /// for pads on pivot springs.
    fn internal_balance(
        &self,
        m: usize,
        q: &[f64],
        qdot: &[f64],
        speed: f64,
    ) -> Option<Result<[f64; 3], BearingError>> {
        let FilmSupport::TiltingPad(b) = &self.support else {
            return None;
        };
        // On pivot springs a pad's tilt and radial displacement balance
        // together, as for the short film.
        if b.radial() {
            return None;
        }
        let film = self.film();
        Some(b.pad_balance_of(m, q, qdot, speed, &|state| {
            Ok(self.pad_film(&film, b, m, state, speed)?)
        }))
    }

    fn guess_internal(&self, journal: [f64; 2], speed: f64, internal: &mut [f64]) {
        self.short().guess_internal(journal, speed, internal);
    }

    fn reseat_internal(&self, q: &mut [f64], speed: f64) -> bool {
        self.short().reseat_internal(q, speed)
    }

    fn resting_contact(&self, direction: [f64; 2]) -> Option<(f64, f64)> {
        self.short().resting_contact(direction)
    }

    fn contact_extent(&self, q: &[f64], qdot: &[f64], speed: f64) -> Option<ContactExtent> {
        self.short().contact_extent(q, qdot, speed)
    }

    fn report(&self, q: &[f64], qdot: &[f64], speed: f64, eval: &BearingEval) -> BearingReport {
        self.short().report(q, qdot, speed, eval)
    }
}
