//! Stator elements: `[[rubs]]` (a stator ring the rotor may touch),
//! `[[seals]]` (coefficient tables, optionally touching) and
//! `[[magnetic_pull]]` (a generator's pull with its stator contact). They act
//! between a rotor node and a stator (ground or a pedestal) but support
//! nothing; they follow the bearings in the model's list and share their
//! names.

use crate::bearing::contact::ContactLaw;
use crate::bearing::magnetic_pull::pull_stiffness;
use crate::bearing::{BearingKind, MagneticPull, RubElement, SealElement};
use crate::model::context::{Ctx, Names, default_name};
use crate::model::error::FieldPath;
use crate::model::file::{MagneticPullEntry, RubEntry, SealEntry};
use crate::model::{ModelError, Pedestal, PlacedBearing, PlacedElement, TableFile};

use super::contact::{RUB_WIDTH, contact_law};
use super::pedestals::lookup;
use super::placement::{centre_offset, shaft_radius_at};
use super::tables::{TableInput, coefficient_table};
use crate::model::limits::{
    CLEARANCE, FLUX_DENSITY, LENGTH, MAX_EXCITATION, PULL_STIFFNESS, RADIUS,
};

/// Check each rub, seal and magnetic pull; names are claimed in `names`
/// (shared with the bearings), table files read are added to `files`.
pub(super) fn stators(
    ctx: &Ctx,
    root: &FieldPath,
    (rubs, seals, pulls): (Vec<RubEntry>, Vec<SealEntry>, Vec<MagneticPullEntry>),
    node_z: &[f64],
    elements: &[PlacedElement],
    pedestals: &[Pedestal],
    (names, files): (&mut Names, &mut Vec<TableFile>),
) -> Result<Vec<PlacedBearing>, ModelError> {
    let mut bearings = Vec::new();
    for (i, r) in rubs.into_iter().enumerate() {
        let p = root.key("rubs").index(i);
        let node = ctx.location(&p, r.node, r.z, node_z)?;
        let offset = centre_offset(ctx, &p, (r.offset_x, r.offset_y))?;
        let gap = ctx.within(p.key("gap"), r.gap, &CLEARANCE)?;
        let radius = ctx.within(
            p.key("radius"),
            r.radius.unwrap_or(shaft_radius_at(elements, node)),
            &RADIUS,
        )?;
        let default = ContactLaw::steel(gap, radius, RUB_WIDTH);
        let law = contact_law(
            ctx,
            &p,
            default,
            [
                r.contact_stiffness,
                r.contact_damping,
                r.friction_coefficient,
            ],
        )?
        .unwrap_or(default);
        let pedestal = match &r.pedestal {
            None => None,
            Some(on) => Some(lookup(ctx, &p.key("pedestal"), pedestals, on)?),
        };
        bearings.push(PlacedBearing {
            name: names.claim(ctx, &p, default_name(r.name, "rub", i), "rub")?,
            node,
            kind: BearingKind::Rub(RubElement { contact: law }),
            pedestal,
            offset,
        });
    }

    for (i, e) in seals.into_iter().enumerate() {
        let p = root.key("seals").index(i);
        let node = ctx.location(&p, e.node, e.z, node_z)?;
        let offset = centre_offset(ctx, &p, (e.offset_x, e.offset_y))?;
        let input = TableInput {
            speeds_rpm: &e.speeds_rpm,
            columns: [
                &e.kxx, &e.kxy, &e.kyx, &e.kyy, &e.cxx, &e.cxy, &e.cyx, &e.cyy,
            ],
            table: &e.table,
            mass: [e.mxx, e.mxy, e.myx, e.myy],
        };
        let read = coefficient_table(ctx, &p, &input)?;
        files.extend(read.file);
        let contact = match e.clearance {
            None => {
                for (key, given) in [
                    ("radius", e.radius.is_some()),
                    ("contact_stiffness", e.contact_stiffness.is_some()),
                    ("contact_damping", e.contact_damping.is_some()),
                    ("friction_coefficient", e.friction_coefficient.is_some()),
                ] {
                    if given {
                        return Err(ctx.err(
                            p.key(key),
                            "(given)",
                            "a contact parameter needs the seal's clearance (the radial gap at which it touches)",
                        ));
                    }
                }
                None
            }
            Some(gap) => {
                let gap = ctx.within(p.key("clearance"), gap, &CLEARANCE)?;
                let radius = ctx.within(
                    p.key("radius"),
                    e.radius.unwrap_or(shaft_radius_at(elements, node)),
                    &RADIUS,
                )?;
                let default = ContactLaw::steel(gap, radius, RUB_WIDTH);
                Some(
                    contact_law(
                        ctx,
                        &p,
                        default,
                        [
                            e.contact_stiffness,
                            e.contact_damping,
                            e.friction_coefficient,
                        ],
                    )?
                    .unwrap_or(default),
                )
            }
        };
        let pedestal = match &e.pedestal {
            None => None,
            Some(on) => Some(lookup(ctx, &p.key("pedestal"), pedestals, on)?),
        };
        bearings.push(PlacedBearing {
            name: names.claim(ctx, &p, default_name(e.name, "seal", i), "seal")?,
            node,
            kind: BearingKind::Seal(SealElement {
                table: read.table,
                added_mass: read.added_mass,
                contact,
            }),
            pedestal,
            offset,
        });
    }

    for (i, e) in pulls.into_iter().enumerate() {
        let p = root.key("magnetic_pull").index(i);
        let node = ctx.location(&p, e.node, e.z, node_z)?;
        let offset = centre_offset(ctx, &p, (e.offset_x, e.offset_y))?;
        let gap = ctx.within(p.key("gap"), e.gap, &CLEARANCE)?;
        let stiffness = match (e.stiffness, e.rotor_radius, e.core_length, e.flux_density) {
            (Some(k), None, None, None) => ctx.within(p.key("stiffness"), k, &PULL_STIFFNESS)?,
            (None, Some(r), Some(l), Some(b)) => pull_stiffness(
                ctx.within(p.key("rotor_radius"), r, &RADIUS)?,
                ctx.within(p.key("core_length"), l, &LENGTH)?,
                ctx.within(p.key("flux_density"), b, &FLUX_DENSITY)?,
                gap,
            ),
            _ => {
                return Err(ctx.err(
                    p.clone(),
                    "stiffness / rotor_radius, core_length, flux_density",
                    "give either stiffness, or all of rotor_radius, core_length and flux_density",
                ));
            }
        };
        let excitation = e.excitation.unwrap_or(1.0);
        if !(excitation.is_finite() && (0.0..=MAX_EXCITATION).contains(&excitation)) {
            return Err(ctx.err(
                p.key("excitation"),
                excitation,
                &format!("must lie in [0, {MAX_EXCITATION}] (1 is the nominal field)"),
            ));
        }
        let dynamic_eccentricity = e.dynamic_eccentricity.unwrap_or(0.0);
        if !(dynamic_eccentricity.is_finite() && (0.0..gap).contains(&dynamic_eccentricity)) {
            return Err(ctx.err(
                p.key("dynamic_eccentricity"),
                dynamic_eccentricity,
                &format!("must lie in [0, gap = {gap}) m (the rotor's centre inside the air gap)"),
            ));
        }
        let dynamic_phase = ctx
            .finite(
                p.key("dynamic_phase_deg"),
                e.dynamic_phase_deg.unwrap_or(0.0),
            )?
            .to_radians();
        let radius = e.rotor_radius.unwrap_or(shaft_radius_at(elements, node));
        let default = ContactLaw::steel(gap, radius, e.core_length.unwrap_or(RUB_WIDTH));
        let contact = contact_law(
            ctx,
            &p,
            default,
            [
                e.contact_stiffness,
                e.contact_damping,
                e.friction_coefficient,
            ],
        )?
        .unwrap_or(default);
        let pedestal = match &e.pedestal {
            None => None,
            Some(on) => Some(lookup(ctx, &p.key("pedestal"), pedestals, on)?),
        };
        bearings.push(PlacedBearing {
            name: names.claim(
                ctx,
                &p,
                default_name(e.name, "magnetic_pull", i),
                "magnetic pull",
            )?,
            node,
            kind: BearingKind::MagneticPull(MagneticPull {
                stiffness,
                gap,
                excitation,
                contact,
                dynamic_eccentricity,
                dynamic_phase,
            }),
            pedestal,
            offset,
        });
    }

    Ok(bearings)
}
