//! Stopping a call of [`Simulator::advance_to`] at the start of a contact
//! episode (the FMI 3.0 FMU's early return from `fmi3DoStep`): when asked, the
//! call ends after the first completed internal step at which a bearing's or
//! rub's journal touches its stator (contact force above zero) that was clear
//! after the step before, at that step's time, instead of at its target time.
//! A later call to the same target continues the stepping from there. Off by
//! default: a simulator not asked steps exactly as before.

use super::simulator::Simulator;
use crate::bearing::Bearing;

impl Simulator {
    /// Whether each call of [`Simulator::advance_to`] stops at the first
    /// internal step at which a contact begins ([`Simulator::contact_began_at`]
    /// tells whether and when the last call did).
    pub fn set_stop_at_contact(&mut self, on: bool) {
        self.contact_onset.enabled = on;
        self.contact_began = None;
    }

    /// The time (s) at which the last [`Simulator::advance_to`] stopped
    /// because a contact began, with the bearings or rubs whose contact began
    /// there; `None` when it ran to its target.
    pub fn contact_began_at(&self) -> Option<&(f64, Vec<String>)> {
        self.contact_began.as_ref()
    }

    /// Whether site `k`'s journal touches its stator at the current state.
    fn site_in_contact(&mut self, k: usize, speed: f64) -> bool {
        let s = &self.state;
        let site = &mut self.sites.list[k];
        for (a, c) in site.journal.iter().enumerate() {
            site.q[a] = c.of(&s.u);
            site.qd[a] = c.of(&s.ud);
        }
        let range = site.offset..site.offset + site.internal;
        site.q[2..].copy_from_slice(&s.p[range.clone()]);
        site.qd[2..].copy_from_slice(&s.pd[range]);
        site.bearing
            .contact_extent(&site.q, &site.qd, speed)
            .is_some_and(|e| e.force > 0.0)
    }

    /// At the start of a call: which contacts are closed now (a contact
    /// already closed does not stop the call).
    pub(super) fn contact_onset_start(&mut self) {
        self.contact_began = None;
        if !self.contact_onset.enabled {
            return;
        }
        let speed = self.speed_at(self.state.time);
        let closed = (0..self.sites.list.len())
            .map(|k| self.site_in_contact(k, speed))
            .collect();
        self.contact_onset.closed = closed;
    }

    /// After a completed internal step: whether a contact began in it (then
    /// recorded for [`Simulator::contact_began_at`]).
    pub(super) fn contact_began_now(&mut self) -> bool {
        if !self.contact_onset.enabled {
            return false;
        }
        let speed = self.speed_at(self.state.time);
        let mut began = Vec::new();
        for k in 0..self.sites.list.len() {
            let now = self.site_in_contact(k, speed);
            if now && !self.contact_onset.closed[k] {
                began.push(self.sites.list[k].name.clone());
            }
            self.contact_onset.closed[k] = now;
        }
        if began.is_empty() {
            return false;
        }
        self.contact_began = Some((self.state.time, began));
        true
    }
}
