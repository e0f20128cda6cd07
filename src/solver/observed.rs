//! The coordinates a user observes, which the local error estimate of an
//! accuracy-controlled step watches ([`super::adaptive`]).

use crate::fe::{DOF_X, DOF_Y};
use crate::rotor::Rotor;

/// The coordinates the local error estimate watches, the ones a user
/// observes: the translations of every bearing's journal (rubs, seals and
/// linear supports included), of every housing, probe and unbalance plane;
/// every displacement coordinate when the model names none. (Bending modes
/// with nodes near the bearings ring undamped between them at amplitudes far
/// below the orbit; unresolved by the step they would hold it down for
/// nothing.)
pub(super) fn observed_dofs(rotor: &Rotor) -> Vec<usize> {
    let m = &rotor.model;
    let nodes = m
        .bearings
        .iter()
        .map(|b| b.node)
        .chain(m.probes.iter().map(|p| p.node))
        .chain(m.unbalances.iter().map(|u| u.node));
    let mut dofs: Vec<usize> = nodes
        .flat_map(|node| [DOF_X, DOF_Y].map(|k| rotor.dofs.free(node, k)))
        .chain((0..m.pedestals.len()).flat_map(|p| [0, 1].map(|k| rotor.dofs.pedestal(p, k))))
        .flatten()
        .collect();
    dofs.sort_unstable();
    dofs.dedup();
    if dofs.is_empty() {
        dofs = (0..rotor.dof_count())
            .filter(|&i| rotor.dofs.is_displacement(i))
            .collect();
    }
    dofs
}
