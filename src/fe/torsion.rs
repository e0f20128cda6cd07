//! Torsion of a shaft element: the twist angles `φ₁`, `φ₂` of its two nodes
//! (rad, about `+z`, the spin direction), linear interpolation of the twist,
//! Saint-Venant torsion of a circular tube. The element's strain energy is
//! `½ (G J / L)(φ₂ − φ₁)²` and its kinetic energy `½ ∫ ρ J φ̇² dz`, so
//!
//! `K = (G J / L) [[1, −1], [−1, 1]]`, `M = (ρ J L / 6) [[2, 1], [1, 2]]`
//!
//! (consistent mass; `J` the polar second moment of area). Uniform shafts
//! converge to the exact torsional frequencies at second order in the element
//! length.

use super::shaft::ShaftElement;

/// A 2×2 element matrix in the order `(φ₁, φ₂)`.
pub type TorsionMatrix = [[f64; 2]; 2];

/// The element's torsional stiffness `G J / L` (N·m/rad).
pub fn torsional_stiffness(e: &ShaftElement) -> f64 {
    e.material.shear_modulus * e.section.polar_moment() / e.length
}

/// Consistent torsional mass and stiffness of a shaft element.
pub fn torsion_matrices(e: &ShaftElement) -> (TorsionMatrix, TorsionMatrix) {
    let k = torsional_stiffness(e);
    let m = e.material.density * e.section.polar_moment() * e.length / 6.0;
    ([[2.0 * m, m], [m, 2.0 * m]], [[k, -k], [-k, k]])
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::fe::section::{CircularSection, Material};
    use crate::fe::shaft::ShaftEffects;

    /// The element's polar mass sums to `ρ J L` (a rigid rotation), and a
    /// rigid rotation is strain-free.
    #[test]
    fn rigid_rotation_carries_the_element_polar_inertia_and_no_strain() {
        let e = ShaftElement {
            length: 0.3,
            section: CircularSection {
                outer_diameter: 0.1,
                inner_diameter: 0.04,
            },
            material: Material {
                name: "steel".into(),
                youngs_modulus: 211e9,
                shear_modulus: 81.2e9,
                density: 7810.0,
            },
            effects: ShaftEffects::default(),
        };
        let (m, k) = torsion_matrices(&e);
        let total: f64 = m.iter().flatten().sum();
        let want = 7810.0 * e.section.polar_moment() * 0.3;
        assert!((total / want - 1.0).abs() < 1e-14);
        assert_eq!(k[0][0] + k[0][1], 0.0);
    }
}
