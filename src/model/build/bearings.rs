//! `[[bearings]]`: linear spring–dampers, plain and tilting-pad journal
//! bearings, with the geometric checks thin-film theory needs.

use crate::bearing::film_table_cache::PreparedTable;
use crate::bearing::finite_bearing::{
    FilmSupport, FiniteFilmBearing, PAD_ARC_RANGE, SLENDERNESS_RANGE, slenderness,
};
use crate::bearing::reynolds::{Cavitation, ReynoldsMesh};
use crate::bearing::tilting_pad::{Pad, PadSupport};
use crate::bearing::{BearingKind, PlainBearing, TableBearing, TiltingPadBearing};

use crate::model::context::{Ctx, Names, default_name};
use crate::model::error::FieldPath;
use crate::model::file::{BearingEntry, MagneticPullEntry, RubEntry, SealEntry};
use crate::model::limits::{
    CLEARANCE, DAMPING, DIAMETRAL_CLEARANCE, LENGTH, Limit, PAD_INERTIA, PAD_MASS, PIVOT_DAMPING,
    PIVOT_STIFFNESS, RADIUS, STIFFNESS, VISCOSITY,
};
use crate::model::{
    ModelError, Pedestal, PlacedBearing, PlacedElement, RADIUS_TOLERANCE, TableFile,
};

use super::contact::contact_law;
use super::pedestals::lookup;
use super::placement::centre_offset;
use super::stators::stators;
use super::tables::{TableInput, coefficient_table};

/// The radial clearance (m) of a film bearing from `clearance` (radial) or
/// `diametral_clearance` (bore diameter less journal diameter, twice the
/// radial one): exactly one of them, within its range ([`CLEARANCE`],
/// [`DIAMETRAL_CLEARANCE`]).
fn radial_clearance(
    ctx: &Ctx,
    p: &FieldPath,
    clearance: Option<f64>,
    diametral: Option<f64>,
) -> Result<f64, ModelError> {
    match (clearance, diametral) {
        (Some(c), None) => ctx.within(p.key("clearance"), c, &CLEARANCE),
        (None, Some(d)) => {
            let d = ctx.within(p.key("diametral_clearance"), d, &DIAMETRAL_CLEARANCE)?;
            Ok(0.5 * d)
        }
        (Some(c), Some(_)) => Err(ctx.err(
            p.key("diametral_clearance"),
            "both",
            &format!(
                "give either clearance (radial, here {c} m) or diametral_clearance (twice it), not both"
            ),
        )),
        (None, None) => Err(ctx.err(
            p.key("clearance"),
            "missing",
            "give clearance (the radial clearance, m) or diametral_clearance (bore diameter less journal diameter, m)",
        )),
    }
}

/// The film theory of a plain or tilting-pad entry: `short` (the kind as
/// it is, the default) or `finite`, the same geometry on the finite-length
/// film ([`FiniteFilmBearing`]) with its mesh (`film_mesh = [n_theta, n_z]`,
/// default [`ReynoldsMesh::FULL_CIRCLE`] or [`ReynoldsMesh::PAD`]) and
/// cavitation condition (default Swift–Stieber). `film_mesh` and
/// `cavitation` belong to the finite film only; the slenderness (L/D, a
/// pad's L/(R β)) and pad arc must lie in the ranges the finite film is
/// stated for ([`SLENDERNESS_RANGE`], [`PAD_ARC_RANGE`]). `film_tables =
/// true` loads or builds the force tables through the cache: a plain film's
/// one, or one per pad arc of a tilting-pad bearing.
fn film_theory(
    ctx: &Ctx,
    p: &FieldPath,
    kind: BearingKind,
    (film, mesh, cavitation, tables): (
        Option<String>,
        Option<Vec<i64>>,
        Option<String>,
        Option<bool>,
    ),
) -> Result<BearingKind, ModelError> {
    match film.as_deref() {
        None | Some("short") => {
            for (key, given) in [
                ("film_mesh", mesh.is_some()),
                ("cavitation", cavitation.is_some()),
                ("film_tables", tables.is_some()),
            ] {
                if given {
                    return Err(ctx.err(
                        p.key(key),
                        "given",
                        "belongs to the finite film only: add film = \"finite\" or remove it",
                    ));
                }
            }
            return Ok(kind);
        }
        Some("finite") => {}
        Some(other) => {
            return Err(ctx.err(
                p.key("film"),
                format!("\"{other}\""),
                "must be \"short\" (Ocvirk, the default) or \"finite\" (finite-length Reynolds film)",
            ));
        }
    }
    let cavitation = match cavitation.as_deref() {
        None | Some("swift_stieber") => Cavitation::SwiftStieber,
        Some("gumbel") => Cavitation::Gumbel,
        Some(other) => {
            return Err(ctx.err(
                p.key("cavitation"),
                format!("\"{other}\""),
                "must be \"swift_stieber\" (Reynolds, the default) or \"gumbel\" (half-Sommerfeld)",
            ));
        }
    };
    let ratio = slenderness(&kind).expect("plain or tilting pad");
    let (lo, hi) = SLENDERNESS_RANGE;
    if !(lo..=hi).contains(&ratio) {
        let what = match kind {
            BearingKind::TiltingPad(_) => "the pads' axial length over arc length L/(R β)",
            _ => "L/D",
        };
        return Err(ctx.err(
            p.key("length"),
            kind.film_geometry().map_or(0.0, |g| g.length),
            &format!(
                "{what} = {ratio:.4} is outside {lo}–{hi}, the range the finite film (film = \"finite\") is stated for"
            ),
        ));
    }
    if let BearingKind::TiltingPad(b) = &kind {
        let (lo, hi) = PAD_ARC_RANGE;
        let arc = b.pads[0].arc();
        if !(lo..=hi).contains(&arc) {
            return Err(ctx.err(
                p.key("pad_arc_deg"),
                arc.to_degrees(),
                &format!(
                    "is outside {}–{}°, the pad arcs the finite film (film = \"finite\") is stated for",
                    lo.to_degrees().round(),
                    hi.to_degrees().round()
                ),
            ));
        }
    }
    let mut bearing = FiniteFilmBearing::of(&kind, cavitation).expect("plain or tilting pad");
    if let Some(list) = mesh {
        let key = p.key("film_mesh");
        if list.len() != 2 {
            return Err(ctx.err(
                key,
                format!("{list:?}"),
                "must be [n_theta, n_z]: intervals around the circle (a pad's arc) and over half the length",
            ));
        }
        let (c0, c1) = ReynoldsMesh::CIRCUMFERENTIAL_RANGE;
        let (a0, a1) = ReynoldsMesh::AXIAL_RANGE;
        for (k, (v, (lo, hi))) in list.iter().zip([(c0, c1), (a0, a1)]).enumerate() {
            if !(lo as i64..=hi as i64).contains(v) {
                return Err(ctx.err(key.index(k), v, &format!("must be from {lo} to {hi}")));
            }
        }
        bearing.mesh = ReynoldsMesh {
            circumferential: list[0] as usize,
            axial: list[1] as usize,
        };
    }
    if tables == Some(true) {
        let fail = |e: crate::bearing::reynolds::ReynoldsError| {
            ctx.err(p.key("film_tables"), "true", &e.to_string())
        };
        if matches!(bearing.support, FilmSupport::Plain(_)) {
            bearing.table = Some(std::sync::Arc::new(
                PreparedTable::load_or_build(&bearing.film(), ctx.film_cache).map_err(fail)?,
            ));
        } else {
            let film = bearing.film();
            for arc in bearing.pad_arcs() {
                bearing.pad_tables.push(std::sync::Arc::new(
                    PreparedTable::load_or_build_pad(&film, arc, ctx.film_cache).map_err(fail)?,
                ));
            }
        }
    }
    Ok(BearingKind::FiniteFilm(bearing))
}

/// The journal radius (m) checked against the shaft at `node`: within
/// [`RADIUS_TOLERANCE`] of an element's outer radius there, or larger when the
/// entry declares `journal_collar = true` (a collar or sleeve on the shaft).
/// Larger without the declaration is an error that names it (and the
/// millimetre slip it more often is); declared but not larger is an error too.
fn journal_radius(
    ctx: &Ctx,
    p: &FieldPath,
    radius: f64,
    collar: Option<bool>,
    node: usize,
    elements: &[PlacedElement],
) -> Result<f64, ModelError> {
    let radius = ctx.within(p.key("radius"), radius, &RADIUS)?;
    let shaft = elements
        .iter()
        .filter(|e| e.node == node || e.node + 1 == node)
        .map(|e| 0.5 * e.element.section.outer_diameter)
        .fold(0.0, f64::max);
    if shaft == 0.0 {
        return Ok(radius);
    }
    let larger = radius > shaft * (1.0 + RADIUS_TOLERANCE);
    match (larger, collar.unwrap_or(false)) {
        (true, false) => Err(ctx.err(
            p.key("radius"),
            radius,
            &format!(
                "is larger than the shaft's outer radius {shaft} m at node {}: a journal collar or sleeve \
                 is declared with journal_collar = true; otherwise the radius is in metres (millimetres, or a diameter?)",
                node + 1
            ),
        )),
        (false, true) => Err(ctx.err(
            p.key("journal_collar"),
            "true",
            &format!(
                "the radius {radius} m is not larger than the shaft's outer radius {shaft} m at node {}: no collar",
                node + 1
            ),
        )),
        _ => Ok(radius),
    }
}

/// Check each bearing: unique name, its node and the parameters of its `type`; film bearings
/// need a clearance below a tenth of the radius, tilting pads 3–18
/// non-overlapping pads.
///
/// Rub elements (`[[rubs]]`) follow the bearings in the list, as
/// [`BearingKind::Rub`], then seals (`[[seals]]`, [`BearingKind::Seal`]),
/// their names unique among the bearings'. Also returns the coefficient-table
/// files read (as written, and resolved).
pub(super) fn bearings(
    ctx: &Ctx,
    root: &FieldPath,
    (entries, rubs, seals, pulls): (
        Vec<BearingEntry>,
        Vec<RubEntry>,
        Vec<SealEntry>,
        Vec<MagneticPullEntry>,
    ),
    node_z: &[f64],
    elements: &[PlacedElement],
    pedestals: &[Pedestal],
) -> Result<(Vec<PlacedBearing>, Vec<TableFile>), ModelError> {
    let mut bearings = Vec::new();
    let mut files = Vec::new();
    let mut names = Names::default();
    for (i, b) in entries.into_iter().enumerate() {
        let p = root.key("bearings").index(i);
        let (name, node, kind, pedestal, centre) = match b {
            BearingEntry::Linear {
                name,
                node,
                z,
                pedestal,
                offset_x,
                offset_y,
                kxx,
                kxy,
                kyx,
                kyy,
                cxx,
                cxy,
                cyx,
                cyy,
            } => {
                let node = ctx.location(&p, node, z, node_z)?;
                let centre = centre_offset(ctx, &p, (offset_x, offset_y))?;
                let k = |key: &str, v: f64| ctx.within(p.key(key), v, &STIFFNESS);
                let c = |key: &str, v: f64| ctx.within(p.key(key), v, &DAMPING);
                let k = [
                    [k("kxx", kxx)?, k("kxy", kxy)?],
                    [k("kyx", kyx)?, k("kyy", kyy)?],
                ];
                let c = [
                    [c("cxx", cxx)?, c("cxy", cxy)?],
                    [c("cyx", cyx)?, c("cyy", cyy)?],
                ];
                for (key, v) in [
                    ("kxx", k[0][0]),
                    ("kyy", k[1][1]),
                    ("cxx", c[0][0]),
                    ("cyy", c[1][1]),
                ] {
                    ctx.non_negative(p.key(key), v)?;
                }
                (
                    name,
                    node,
                    BearingKind::Linear {
                        stiffness: k,
                        damping: c,
                    },
                    pedestal,
                    centre,
                )
            }
            BearingEntry::Plain {
                name,
                node,
                z,
                pedestal,
                offset_x,
                offset_y,
                radius,
                journal_collar,
                length,
                clearance,
                diametral_clearance,
                viscosity,
                contact_stiffness,
                contact_damping,
                friction_coefficient,
                film,
                film_mesh,
                cavitation,
                film_tables,
            } => {
                let node = ctx.location(&p, node, z, node_z)?;
                let centre = centre_offset(ctx, &p, (offset_x, offset_y))?;
                let mut bearing = PlainBearing {
                    radius: journal_radius(ctx, &p, radius, journal_collar, node, elements)?,
                    length: ctx.within(p.key("length"), length, &LENGTH)?,
                    clearance: radial_clearance(ctx, &p, clearance, diametral_clearance)?,
                    viscosity: ctx.within(p.key("viscosity"), viscosity, &VISCOSITY)?,
                    contact: None,
                };
                bearing.contact = contact_law(
                    ctx,
                    &p,
                    bearing.contact_law(),
                    [contact_stiffness, contact_damping, friction_coefficient],
                )?;
                if bearing.clearance >= 0.1 * bearing.radius {
                    return Err(ctx.err(
                        p.key("clearance"),
                        bearing.clearance,
                        &format!(
                            "must be much smaller than the radius {} (thin-film theory)",
                            bearing.radius
                        ),
                    ));
                }
                let kind = film_theory(
                    ctx,
                    &p,
                    BearingKind::Plain(bearing),
                    (film, film_mesh, cavitation, film_tables),
                )?;
                (name, node, kind, pedestal, centre)
            }
            BearingEntry::Table {
                name,
                node,
                z,
                pedestal,
                offset_x,
                offset_y,
                speeds_rpm,
                kxx,
                kxy,
                kyx,
                kyy,
                cxx,
                cxy,
                cyx,
                cyy,
                table,
                mxx,
                mxy,
                myx,
                myy,
            } => {
                let node = ctx.location(&p, node, z, node_z)?;
                let centre = centre_offset(ctx, &p, (offset_x, offset_y))?;
                let input = TableInput {
                    speeds_rpm: &speeds_rpm,
                    columns: [&kxx, &kxy, &kyx, &kyy, &cxx, &cxy, &cyx, &cyy],
                    table: &table,
                    mass: [mxx, mxy, myx, myy],
                };
                let read = coefficient_table(ctx, &p, &input)?;
                files.extend(read.file);
                (
                    name,
                    node,
                    BearingKind::Table(TableBearing {
                        table: read.table,
                        added_mass: read.added_mass,
                    }),
                    pedestal,
                    centre,
                )
            }
            BearingEntry::TiltingPad {
                name,
                node,
                z,
                pedestal,
                offset_x,
                offset_y,
                radius,
                journal_collar,
                length,
                clearance,
                diametral_clearance,
                viscosity,
                pads,
                first_pivot_deg,
                pivots_deg,
                pad_arc_deg,
                pivot_offset,
                preload,
                pivot_stiffness,
                pad_inertia,
                pad_mass,
                pivot_damping,
                contact_stiffness,
                contact_damping,
                friction_coefficient,
                film,
                film_mesh,
                cavitation,
                film_tables,
            } => {
                let node = ctx.location(&p, node, z, node_z)?;
                let centre = centre_offset(ctx, &p, (offset_x, offset_y))?;
                let radius = journal_radius(ctx, &p, radius, journal_collar, node, elements)?;
                let clearance = radial_clearance(ctx, &p, clearance, diametral_clearance)?;
                if clearance >= 0.1 * radius {
                    return Err(ctx.err(
                        p.key("clearance"),
                        clearance,
                        &format!(
                            "must be much smaller than the radius {radius} (thin-film theory)"
                        ),
                    ));
                }
                let pivots: Vec<f64> = match (pads, first_pivot_deg, pivots_deg) {
                    (Some(count), first, None) => {
                        if !(3..=18).contains(&count) {
                            return Err(ctx.err(p.key("pads"), count, "must be from 3 to 18"));
                        }
                        let first = ctx.finite(p.key("first_pivot_deg"), first.unwrap_or(0.0))?;
                        (0..count)
                            .map(|k| first + 360.0 * k as f64 / count as f64)
                            .collect()
                    }
                    (None, None, Some(list)) => {
                        if !(3..=18).contains(&list.len()) {
                            return Err(ctx.err(
                                p.key("pivots_deg"),
                                format!("{list:?}"),
                                "must list from 3 to 18 pivot angles",
                            ));
                        }
                        for (k, v) in list.iter().enumerate() {
                            ctx.finite(p.key("pivots_deg").index(k), *v)?;
                        }
                        list
                    }
                    _ => {
                        return Err(ctx.err(
                            p.clone(),
                            "pads / first_pivot_deg / pivots_deg",
                            "give either pads (and optionally first_pivot_deg) or pivots_deg",
                        ));
                    }
                };
                let arc = ctx.positive(p.key("pad_arc_deg"), pad_arc_deg)?;
                let offset = pivot_offset.unwrap_or(0.5);
                if !(0.0..=1.0).contains(&offset) {
                    return Err(ctx.err(p.key("pivot_offset"), offset, "must lie in [0, 1]"));
                }
                let preload = preload.unwrap_or(0.0);
                if !(0.0..1.0).contains(&preload) {
                    return Err(ctx.err(p.key("preload"), preload, "must lie in [0, 1)"));
                }
                // Pads must not overlap: sorted pivots at least one arc apart.
                let mut sorted: Vec<f64> = pivots.iter().map(|d| d.rem_euclid(360.0)).collect();
                sorted.sort_by(f64::total_cmp);
                let gaps = sorted
                    .windows(2)
                    .map(|w| w[1] - w[0])
                    .chain(std::iter::once(
                        sorted[0] + 360.0 - sorted[sorted.len() - 1],
                    ));
                if gaps.fold(f64::INFINITY, f64::min) < arc {
                    return Err(ctx.err(
                        p.key("pad_arc_deg"),
                        arc,
                        "pads overlap: the arc exceeds the spacing of the pivots",
                    ));
                }
                let mut bearing = TiltingPadBearing {
                    radius,
                    length: ctx.within(p.key("length"), length, &LENGTH)?,
                    clearance,
                    viscosity: ctx.within(p.key("viscosity"), viscosity, &VISCOSITY)?,
                    pads: pivots
                        .iter()
                        .map(|d| Pad::new(d.to_radians(), arc.to_radians(), offset, preload))
                        .collect(),
                    contact: None,
                    support: pad_support(
                        ctx,
                        &p,
                        [pivot_stiffness, pad_inertia, pad_mass, pivot_damping],
                    )?,
                };
                bearing.contact = contact_law(
                    ctx,
                    &p,
                    bearing.contact_law(),
                    [contact_stiffness, contact_damping, friction_coefficient],
                )?;
                let kind = film_theory(
                    ctx,
                    &p,
                    BearingKind::TiltingPad(bearing),
                    (film, film_mesh, cavitation, film_tables),
                )?;
                (name, node, kind, pedestal, centre)
            }
        };
        let pedestal = match pedestal {
            None => None,
            Some(on) => Some(lookup(ctx, &p.key("pedestal"), pedestals, &on)?),
        };
        bearings.push(PlacedBearing {
            name: names.claim(ctx, &p, default_name(name, "bearing", i), "bearing")?,
            node,
            kind,
            pedestal,
            offset: centre,
        });
    }
    bearings.extend(stators(
        ctx,
        root,
        (rubs, seals, pulls),
        node_z,
        elements,
        pedestals,
        (&mut names, &mut files),
    )?);
    Ok((bearings, files))
}

/// The pads' support from `pivot_stiffness` (N/m, > 0; none: rigid),
/// `pad_inertia` (kg·m², ≥ 0), `pad_mass` (kg, ≥ 0) and `pivot_damping`
/// (N·s/m, ≥ 0), the last two only on a pivot with a stiffness.
fn pad_support(
    ctx: &Ctx,
    p: &FieldPath,
    [pivot_stiffness, pad_inertia, pad_mass, pivot_damping]: [Option<f64>; 4],
) -> Result<PadSupport, ModelError> {
    let pivot_stiffness = pivot_stiffness
        .map(|k| ctx.within(p.key("pivot_stiffness"), k, &PIVOT_STIFFNESS))
        .transpose()?;
    let pad_inertia = ctx.within(
        p.key("pad_inertia"),
        pad_inertia.unwrap_or(0.0),
        &PAD_INERTIA,
    )?;
    let radial = |key: &str, value: Option<f64>, limit: &Limit| -> Result<f64, ModelError> {
        let Some(v) = value else {
            return Ok(0.0);
        };
        let v = ctx.within(p.key(key), v, limit)?;
        if pivot_stiffness.is_none() {
            return Err(ctx.err(
                p.key(key),
                v,
                "needs pivot_stiffness: a pad on a rigid pivot has no radial motion",
            ));
        }
        Ok(v)
    };
    let pad_mass = radial("pad_mass", pad_mass, &PAD_MASS)?;
    let pivot_damping = radial("pivot_damping", pivot_damping, &PIVOT_DAMPING)?;
    Ok(PadSupport {
        pivot_stiffness,
        pad_inertia,
        pad_mass,
        pivot_damping,
    })
}
