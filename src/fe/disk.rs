//! Lumped rigid disk on one node (paper eq. 5): mass, diametral inertia and the
//! gyroscopic term of its polar inertia.

use nalgebra::SMatrix;

use super::{DOF_RX, DOF_RY};

/// 4×4 nodal matrix in the node's DOF order `(x, y, θx, θy)`.
pub type NodeMatrix = SMatrix<f64, 4, 4>;

/// A rigid disk (impeller, generator rotor, coupling) lumped at one node.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Disk {
    /// Mass `m` (kg).
    pub mass: f64,
    /// Polar moment of inertia about the spin axis `I_p` (kg·m²).
    pub polar_inertia: f64,
    /// Diametral moment of inertia about a diameter through the centre `I_d` (kg·m²).
    pub diametral_inertia: f64,
}

impl Disk {
    /// A uniform annular disk: `m = ρ π (D_o² − D_i²) w / 4`,
    /// `I_p = m (D_o² + D_i²) / 8`, `I_d = I_p / 2 + m w² / 12`.
    pub fn from_geometry(
        density: f64,
        outer_diameter: f64,
        inner_diameter: f64,
        width: f64,
    ) -> Self {
        let mass = density * std::f64::consts::PI / 4.0
            * (outer_diameter.powi(2) - inner_diameter.powi(2))
            * width;
        let polar_inertia = mass * (outer_diameter.powi(2) + inner_diameter.powi(2)) / 8.0;
        let diametral_inertia = polar_inertia / 2.0 + mass * width.powi(2) / 12.0;
        Self {
            mass,
            polar_inertia,
            diametral_inertia,
        }
    }

    /// Outer diameter and width (m) of the solid uniform disk with this mass and
    /// these inertias, for drawings: `D = √(8 I_p/m)` and
    /// `w = √(12 (I_d − I_p/2)/m)` (zero when `I_d ≤ I_p/2`, a thin disk),
    /// inverting [`Disk::from_geometry`] with no bore.
    pub fn equivalent_solid_dimensions(&self) -> (f64, f64) {
        let diameter = (8.0 * self.polar_inertia / self.mass).sqrt();
        let width = (12.0 * (self.diametral_inertia - self.polar_inertia / 2.0) / self.mass)
            .max(0.0)
            .sqrt();
        (diameter, width)
    }

    /// Mass matrix `diag(m, m, I_d, I_d)`.
    pub fn mass_matrix(&self) -> NodeMatrix {
        NodeMatrix::from_diagonal(&nalgebra::Vector4::new(
            self.mass,
            self.mass,
            self.diametral_inertia,
            self.diametral_inertia,
        ))
    }

    /// Gyroscopic matrix per rad/s of spin: `G[θx, θy] = I_p`, `G[θy, θx] = −I_p`,
    /// from `T = ½ I_p (Ω² + 2 Ω θ̇x θy)`.
    pub fn gyroscopic_matrix(&self) -> NodeMatrix {
        let mut g = NodeMatrix::zeros();
        g[(DOF_RX, DOF_RY)] = self.polar_inertia;
        g[(DOF_RY, DOF_RX)] = -self.polar_inertia;
        g
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn equivalent_dimensions_invert_the_solid_disk() {
        let d = Disk::from_geometry(7810.0, 0.28, 0.0, 0.07);
        let (diameter, width) = d.equivalent_solid_dimensions();
        assert!((diameter - 0.28).abs() < 1e-14, "{diameter}");
        assert!((width - 0.07).abs() < 1e-12, "{width}");
    }

    /// The classic disk of Friswell et al. (2010), example 5.9.1.
    #[test]
    fn classic_disk_geometry() {
        let d = Disk::from_geometry(7810.0, 0.28, 0.05, 0.07);
        assert!((d.mass - 32.590).abs() < 5e-4);
        assert!((d.polar_inertia - 0.32956).abs() < 5e-6);
        assert!((d.diametral_inertia - 0.17809).abs() < 5e-6);
    }

    /// A spinning disk on a rotational spring: the two whirl frequencies satisfy
    /// `I_d ω² ∓ I_p Ω ω − k = 0` (forward +, backward −).
    #[test]
    fn gyroscopic_sign_stiffens_forward_whirl() {
        let d = Disk {
            mass: 1.0,
            polar_inertia: 0.4,
            diametral_inertia: 0.2,
        };
        let (k, spin) = (100.0, 30.0);
        let g = d.gyroscopic_matrix();
        // Forward whirl: θy = s cos ωt, θx = −s sin ωt (slope vector rotating with +Ω).
        let forward = (d.polar_inertia * spin
            + ((d.polar_inertia * spin).powi(2) + 4.0 * d.diametral_inertia * k).sqrt())
            / (2.0 * d.diametral_inertia);
        // Residual of row θx at t = π/(2ω): θx = −s, θy = 0, θ̇x = 0, θ̇y = −sω,
        // θ̈x = sω², so I_d θ̈x + Ω G[θx,θy] θ̇y + k θx must vanish.
        let w = forward;
        let residual = d.diametral_inertia * w * w + spin * g[(DOF_RX, DOF_RY)] * (-w) - k;
        assert!(residual.abs() < 1e-9 * k);
    }
}
