//! The static solve's second start, from the bearings' own equilibria, and the
//! check that a static equilibrium has every tilting pad on its loaded branch
//! (see [`super::statics`]).
//!
//! Newton on the whole rotor from the undeflected shaft starts every journal
//! at its bearing centre. Pads without preload around a centred journal have a
//! uniform film and carry nothing at any small tilt, so the first steps are
//! taken on a degenerate Jacobian; a side pad can then be left on its unloaded
//! branch — tilted so that its film diverges everywhere — while the journal
//! drifts sideways with nothing to hold it, to a false equilibrium or a stall.
//! The bearing-level solver has neither problem: it continues in load from a
//! journal off the centre along the load, the pads at their stable zero-moment
//! tilts ([`crate::bearing::equilibrium::journal_equilibrium`]). This start
//! solves each fluid-film bearing that way under its share of the load — the
//! reactions of the rotor on rigid supports at the journals, exact for two
//! bearings — and puts the rotor on the journals it finds.

use crate::bearing::Bearing;
use crate::bearing::equilibrium::journal_equilibrium;
use crate::rotor::Rotor;
use nalgebra::Vector2;

use super::sites::{Sites, add_coupling};

/// The rotor on its fluid-film bearings' own equilibria at spin `speed`
/// (rad/s) under `f_ext`: each film journal held by its contact stiffness `k`
/// (from [`crate::bearing::Bearing::resting_contact`]), `A = K + Σ k E Eᵀ`;
/// the reactions `R = k Eᵀ A⁻¹ f` load the bearings, whose equilibria `q*`
/// under `R` give the journal positions and pad tilts; the rotor deflection
/// solves `A u = f + Σ E (k j* − R)`, which puts every journal on its `j*`
/// when the reactions are exact. `None` without a fluid-film bearing, or when
/// a bearing has no equilibrium under its reaction.
pub(super) fn film_start(
    rotor: &Rotor,
    sites: &Sites,
    f_ext: &[f64],
    speed: f64,
) -> Option<(Vec<f64>, Vec<f64>)> {
    let mut a = rotor.stiffness.clone();
    let mut held = Vec::new();
    for site in &sites.list {
        let kind = &rotor.model.bearings[site.index].kind;
        let (Some(_), Some(clearance)) = (kind.film_geometry(), kind.journal_clearance()) else {
            continue;
        };
        let (_, k) = site.bearing.resting_contact([0.0, -1.0])?;
        for c in &site.journal {
            add_coupling(&mut a, c, c, k);
        }
        held.push((site, k, clearance));
    }
    if held.is_empty() {
        return None;
    }
    let lu = a.lu().ok()?;
    let mut u = f_ext.to_vec();
    // The springs of a bearing set off the axis hold its journal at its centre.
    for &(site, k, _) in held.iter().filter(|(s, ..)| is_offset(s.centre)) {
        site.journal[0].add(&mut u, k * site.centre[0]);
        site.journal[1].add(&mut u, k * site.centre[1]);
    }
    lu.solve_in_place(&mut u);
    let mut rhs = f_ext.to_vec();
    let mut p = vec![0.0; sites.n_internal];
    for &(site, k, clearance) in &held {
        let [cx, cy] = site.journal;
        let (reaction, eq) = if is_offset(site.centre) {
            // The bearing about its own centre, its equilibrium moved there.
            let o = site.centre;
            let reaction = Vector2::new(k * (cx.of(&u) - o[0]), k * (cy.of(&u) - o[1]));
            let own = rotor.model.bearings[site.index].kind.build();
            let mut eq = journal_equilibrium(own.as_ref(), reaction, speed, clearance).ok()?;
            eq.q[0] += o[0];
            eq.q[1] += o[1];
            (reaction, eq)
        } else {
            let reaction = Vector2::new(k * cx.of(&u), k * cy.of(&u));
            let eq = journal_equilibrium(&site.bearing, reaction, speed, clearance).ok()?;
            (reaction, eq)
        };
        cx.add(&mut rhs, k * eq.q[0] - reaction.x);
        cy.add(&mut rhs, k * eq.q[1] - reaction.y);
        p[site.offset..site.offset + site.internal].copy_from_slice(&eq.q[2..]);
    }
    lu.solve_in_place(&mut rhs);
    Some((rhs, p))
}

/// Whether a site's centre is off the nominal axis (the starts then anchor
/// its journal there; on the axis they do exactly what they did before).
pub(super) fn is_offset(centre: [f64; 2]) -> bool {
    centre != [0.0, 0.0]
}

/// Re-seat, at the journal positions of `u`, every pad of `sites` left on its
/// unloaded branch where a loaded zero-moment tilt exists
/// ([`crate::bearing::Bearing::reseat_internal`]), in `p`; returns whether any
/// moved (an equilibrium where none moves has every pad on its branch).
pub(super) fn reseat_pads(sites: &Sites, u: &[f64], p: &mut [f64], speed: f64) -> bool {
    let mut moved = false;
    for site in &sites.list {
        if site.internal == 0 {
            continue;
        }
        let mut q = vec![0.0; 2 + site.internal];
        q[0] = site.journal[0].of(u);
        q[1] = site.journal[1].of(u);
        let range = site.offset..site.offset + site.internal;
        q[2..].copy_from_slice(&p[range.clone()]);
        if site.bearing.reseat_internal(&mut q, speed) {
            p[range].copy_from_slice(&q[2..]);
            moved = true;
        }
    }
    moved
}

/// Smallest journal displacement from its centre, over the length scale
/// (the smallest clearance), at which [`pushed_off_centre`] judges a film.
const PUSH_DISPLACEMENT: f64 = 1e-3;
/// Largest cosine between a pad bearing's force on the journal and the
/// journal's displacement from its centre at a held equilibrium.
const PUSH_COSINE: f64 = 1e-2;

/// Whether a tilting-pad bearing of `sites` (their forces evaluated at the
/// journal positions of `u`) pushes its journal further from its centre,
/// `F·q > 0` (attitude angle beyond 90°): a film restores, and a tilting-pad
/// bearing's attitude is near zero, so such an equilibrium has its pads on
/// a branch the running bearing does not hold (one its linearization finds
/// diverging).
pub(super) fn pushed_off_centre(sites: &Sites, u: &[f64]) -> bool {
    sites.list.iter().filter(|s| s.internal > 0).any(|site| {
        let q = [
            site.journal[0].of(u) - site.centre[0],
            site.journal[1].of(u) - site.centre[1],
        ];
        let f = [site.eval.force[0], site.eval.force[1]];
        let (nq, nf) = (q[0].hypot(q[1]), f[0].hypot(f[1]));
        nq > PUSH_DISPLACEMENT * sites.length_scale
            && f[0] * q[0] + f[1] * q[1] > PUSH_COSINE * nf * nq
    })
}
