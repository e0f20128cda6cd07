//! The rotor's nodes along the shaft: how many, and which is nearest an
//! axial position.

use super::RotorModel;

impl RotorModel {
    /// Number of nodes.
    pub fn node_count(&self) -> usize {
        self.node_z.len()
    }

    /// The node (0-based) nearest the axial position `z` (m); the first of
    /// two equally near.
    pub fn nearest_node(&self, z: f64) -> usize {
        nearest(&self.node_z, z)
    }
}

/// The index in `node_z` (m) nearest `z` (m); the first of two equally near,
/// 0 for none.
pub(crate) fn nearest(node_z: &[f64], z: f64) -> usize {
    (0..node_z.len())
        .min_by(|&a, &b| (node_z[a] - z).abs().total_cmp(&(node_z[b] - z).abs()))
        .unwrap_or(0)
}

#[cfg(test)]
mod tests {
    use super::nearest;

    /// The nearest node, the first of two equally near, the ends beyond the
    /// shaft, and 0 without nodes.
    #[test]
    fn the_nearest_node_to_a_position() {
        let z = [0.0, 0.5, 1.0, 2.0];
        assert_eq!(nearest(&z, 0.7), 1);
        assert_eq!(nearest(&z, 0.75), 1);
        assert_eq!(nearest(&z, 1.6), 3);
        assert_eq!(nearest(&z, -3.0), 0);
        assert_eq!(nearest(&z, 9.0), 3);
        assert_eq!(nearest(&[], 1.0), 0);
    }
}
