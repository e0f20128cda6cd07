//! The numbering of the assembled rotor's degrees of freedom.
//!
//! The *full* numbering has every rotor node's four DOFs first, `4·node + k`
//! (`k` = 0–3: `x`, `y`, `θx`, `θy`, see [`crate::fe`]), then each pedestal's
//! two translations, `4·nodes + 2·pedestal + k` (`k` = 0, 1: `x`, `y`).
//! The *free* numbering (the order of the matrices) drops the DOFs fixed by
//! ideal supports and places each pedestal's DOFs right after the rotor node
//! it is anchored at (the lowest node of the bearings standing on it,
//! directly or through other pedestals), so that a bearing between a journal
//! and its housing couples DOFs a few places apart and the matrices stay
//! banded. Without pedestals the free numbering is node by node.

use crate::fe::DOF_PER_NODE;
use crate::model::RotorModel;

/// Translational DOFs of a pedestal (`x`, `y`).
pub const DOF_PER_PEDESTAL: usize = 2;

/// What a free coordinate is.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Dof {
    /// DOF `k` (0–3: `x`, `y`, `θx`, `θy`) of rotor node `node`.
    Node { node: usize, k: usize },
    /// Translation `k` (0: `x`, 1: `y`) of pedestal `pedestal` (model order).
    Pedestal { pedestal: usize, k: usize },
    /// Modal coordinate `m` of a reduced rotor (m, scaled to its mode's peak
    /// translation).
    Modal(usize),
}

impl Dof {
    /// Whether it is a displacement in metres: a rotor translation, a
    /// pedestal translation or a modal coordinate (not a rotation).
    pub fn is_displacement(&self) -> bool {
        match *self {
            Dof::Node { k, .. } => k < 2,
            Dof::Pedestal { .. } | Dof::Modal(_) => true,
        }
    }

    /// The lateral direction (0: `x`, 1: `y`) of a rotor or pedestal
    /// translation; `None` for a rotation or a modal coordinate.
    pub fn translation(&self) -> Option<usize> {
        match *self {
            Dof::Node { k, .. } if k < 2 => Some(k),
            Dof::Pedestal { k, .. } => Some(k),
            _ => None,
        }
    }
}

/// Map between the full DOF numbering and the free DOFs left after ideal
/// supports are removed. A [reduced](super::Rotor::reduced) rotor's map has
/// its physical coordinates first (the kept nodes' and the pedestals' free
/// DOFs) and then `modal` coordinates that belong to no node.
#[derive(Debug, Clone, PartialEq)]
pub struct DofMap {
    pub(super) full_to_free: Vec<Option<usize>>,
    pub(super) free_to_full: Vec<usize>,
    pub(super) modal: usize,
    /// Number of rotor nodes (the pedestal DOFs follow theirs in the full numbering).
    pub(super) nodes: usize,
}

impl DofMap {
    /// The numbering of `model`: rotor nodes less their supported DOFs, each
    /// pedestal after its anchor node.
    pub(super) fn new(model: &RotorModel) -> Self {
        let nodes = model.node_count();
        let n_node_dofs = nodes * DOF_PER_NODE;
        let n_full = n_node_dofs + model.pedestals.len() * DOF_PER_PEDESTAL;
        let mut fixed = vec![false; n_node_dofs];
        for s in &model.supports {
            for (k, &f) in s.fixed.iter().enumerate() {
                fixed[s.node * DOF_PER_NODE + k] |= f;
            }
        }
        let anchors = model.pedestal_anchors();
        let mut full_to_free = vec![None; n_full];
        let mut free_to_full = Vec::with_capacity(n_full);
        let mut push = |full: usize, free_to_full: &mut Vec<usize>| {
            full_to_free[full] = Some(free_to_full.len());
            free_to_full.push(full);
        };
        for node in 0..nodes {
            for k in 0..DOF_PER_NODE {
                let full = node * DOF_PER_NODE + k;
                if !fixed[full] {
                    push(full, &mut free_to_full);
                }
            }
            // Pedestals anchored here, in model order.
            for &p in anchors.iter().filter(|a| a.1 == node).map(|(p, _)| p) {
                for k in 0..DOF_PER_PEDESTAL {
                    push(n_node_dofs + p * DOF_PER_PEDESTAL + k, &mut free_to_full);
                }
            }
        }
        Self {
            full_to_free,
            free_to_full,
            modal: 0,
            nodes,
        }
    }

    /// Number of free DOFs (coordinates, for a reduced rotor).
    pub fn free_count(&self) -> usize {
        self.free_to_full.len() + self.modal
    }

    /// What coordinate `i` is.
    pub fn kind(&self, i: usize) -> Dof {
        match self.free_to_full.get(i) {
            None => Dof::Modal(i - self.free_to_full.len()),
            Some(&full) => {
                let node_dofs = self.nodes * DOF_PER_NODE;
                if full < node_dofs {
                    Dof::Node {
                        node: full / DOF_PER_NODE,
                        k: full % DOF_PER_NODE,
                    }
                } else {
                    Dof::Pedestal {
                        pedestal: (full - node_dofs) / DOF_PER_PEDESTAL,
                        k: (full - node_dofs) % DOF_PER_PEDESTAL,
                    }
                }
            }
        }
    }

    /// Whether coordinate `i` is a displacement in metres: a translation `x`,
    /// `y` of a node or a pedestal, or a modal coordinate (scaled to its
    /// mode's peak translation).
    pub fn is_displacement(&self, i: usize) -> bool {
        self.kind(i).is_displacement()
    }

    /// Number of DOFs before constraints (rotor nodes, then pedestals).
    pub fn full_count(&self) -> usize {
        self.full_to_free.len()
    }

    /// Number of rotor nodes.
    pub fn node_count(&self) -> usize {
        self.nodes
    }

    /// Free index of DOF `k` of `node`, `None` when that DOF is fixed.
    pub fn free(&self, node: usize, k: usize) -> Option<usize> {
        self.full_to_free[node * DOF_PER_NODE + k]
    }

    /// Free index of translation `k` (0: `x`, 1: `y`) of pedestal `pedestal`.
    pub fn pedestal(&self, pedestal: usize, k: usize) -> Option<usize> {
        self.full_to_free[self.nodes * DOF_PER_NODE + pedestal * DOF_PER_PEDESTAL + k]
    }

    /// Full index of a free DOF.
    ///
    /// # Panics
    /// For a modal coordinate of a reduced rotor (it belongs to no node).
    pub fn full(&self, free: usize) -> usize {
        self.free_to_full[free]
    }

    /// Expand a free-DOF vector to all DOFs (fixed DOFs are zero): rotor
    /// node `i`'s DOF `k` at `4·i + k`, then the pedestals' translations.
    ///
    /// # Panics
    /// For a reduced rotor's map: read its nodes with [`super::Rotor::node_value`].
    pub fn expand<T: Copy + Default>(&self, free: &[T]) -> Vec<T> {
        assert_eq!(self.modal, 0, "DofMap::expand of reduced coordinates");
        let mut out = vec![T::default(); self.full_count()];
        for (i, &v) in free.iter().enumerate() {
            out[self.free_to_full[i]] = v;
        }
        out
    }
}
