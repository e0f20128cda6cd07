//! What the simulator keeps about its contacts between steps: which closed
//! after the last completed internal step ([`super::contact_onset`]) and the
//! warnings of contact beyond its law not yet taken ([`super::contact_watch`]).

use super::contact_watch::ContactWarning;

/// Whether to stop at a contact's start, and which contacts were closed
/// after the last completed internal step.
#[derive(Debug, Default)]
pub(super) struct ContactOnset {
    /// Stop at the start of a contact.
    pub(super) enabled: bool,
    /// Per site: in contact after the last completed internal step.
    pub(super) closed: Vec<bool>,
}

/// The warnings not yet taken. Which limits each site has been reported on
/// is part of the state ([`SimState::contact_reported`]), so a restored
/// state raises a warning again.
///
/// [`SimState::contact_reported`]: super::SimState::contact_reported
#[derive(Debug, Default)]
pub(super) struct ContactWatch {
    pub(super) pending: Vec<ContactWarning>,
}
