//! Watching every accepted step for contact outside the range of the contact
//! law ([`crate::bearing::contact`]: penetration beyond 10 % of the gap, or a
//! normal force beyond the yield onset of the surfaces), and reporting each
//! bearing's or rub's first excursion once per episode.

use super::simulator::Simulator;
use crate::bearing::Bearing;

/// Which limit of the contact law a contact left.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ContactLimit {
    /// The penetration exceeds [`crate::bearing::contact::ContactLaw::PENETRATION_LIMIT`] of the gap.
    Penetration,
    /// The normal force exceeds [`crate::bearing::contact::ContactLaw::yield_force`].
    Force,
}

/// The first excursion of one contact beyond one limit of its law.
#[derive(Debug, Clone, PartialEq)]
pub struct ContactWarning {
    /// The bearing's or rub's name.
    pub name: String,
    /// Which limit.
    pub limit: ContactLimit,
    /// Time of the first step beyond it (s).
    pub time: f64,
    /// Penetration (m) or force (N) there.
    pub value: f64,
    /// The limit (m or N).
    pub bound: f64,
    /// The message for the user.
    pub message: String,
}

impl Simulator {
    /// Check every nonlinear bearing at the accepted state (time `t`, spin
    /// `speed`) against the limits of its contact law; the first excursion of
    /// each contact beyond each limit is queued. A contact reported on both
    /// limits is not evaluated again.
    pub(super) fn watch_contacts(&mut self, t: f64, speed: f64) {
        let (s, watch) = (&mut self.state, &mut self.contact_watch);
        for (k, site) in self.sites.list.iter_mut().enumerate() {
            let [penetration_done, force_done] =
                [2 * k, 2 * k + 1].map(|i| s.contact_reported[i] != 0.0);
            if penetration_done && force_done {
                continue;
            }
            for (a, c) in site.journal.iter().enumerate() {
                site.q[a] = c.of(&s.u);
                site.qd[a] = c.of(&s.ud);
            }
            let range = site.offset..site.offset + site.internal;
            site.q[2..].copy_from_slice(&s.p[range.clone()]);
            site.qd[2..].copy_from_slice(&s.pd[range]);
            let Some(extent) = site.bearing.contact_extent(&site.q, &site.qd, speed) else {
                continue;
            };
            let kind = if self.rotor.model.bearings[site.index].kind.is_rub() {
                "rub"
            } else {
                "bearing"
            };
            if !penetration_done && extent.penetration > extent.penetration_limit {
                s.contact_reported[2 * k] = 1.0;
                let gap = extent.penetration_limit
                    / crate::bearing::contact::ContactLaw::PENETRATION_LIMIT;
                watch.pending.push(ContactWarning {
                    name: site.name.clone(),
                    limit: ContactLimit::Penetration,
                    time: t,
                    value: extent.penetration,
                    bound: extent.penetration_limit,
                    message: format!(
                        "{kind} {}: at t = {t:.6} s the journal is {:.3e} m into its stator, {:.3} times the gap of {:.3e} m; the contact law stands for elastic contact only up to a penetration of 10 % of the gap ({:.3e} m), so from here on the results are not physical (reported once per run)",
                        site.name,
                        extent.penetration,
                        extent.penetration / gap,
                        gap,
                        extent.penetration_limit
                    ),
                });
            }
            if !force_done && extent.force > extent.force_limit {
                s.contact_reported[2 * k + 1] = 1.0;
                watch.pending.push(ContactWarning {
                    name: site.name.clone(),
                    limit: ContactLimit::Force,
                    time: t,
                    value: extent.force,
                    bound: extent.force_limit,
                    message: format!(
                        "{kind} {}: at t = {t:.6} s the contact force is {:.3e} N, beyond the {:.3e} N at which the Hertz pressure of the contact reaches the yield onset of steel ({:.0} MPa); the linear contact law does not describe a yielding contact, so from here on the results are not physical (reported once per run)",
                        site.name,
                        extent.force,
                        extent.force_limit,
                        crate::bearing::contact::ContactLaw::YIELD_PRESSURE / 1e6
                    ),
                });
            }
        }
    }

    /// The contact warnings raised since the last call: the first step at
    /// which each bearing's or rub's contact went beyond a limit of its law,
    /// each reported once in the life of the simulator (an episode).
    pub fn take_contact_warnings(&mut self) -> Vec<ContactWarning> {
        std::mem::take(&mut self.contact_watch.pending)
    }

    /// Forget the pending warnings raised after time `t` (s): their step
    /// was undone.
    pub(super) fn drop_contact_warnings_after(&mut self, t: f64) {
        self.contact_watch.pending.retain(|w| w.time <= t);
    }
}
