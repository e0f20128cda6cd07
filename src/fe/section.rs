//! Circular (solid or hollow) shaft cross-sections and their shear factor.

use std::f64::consts::PI;

/// Elastic and inertial properties of a shaft material (SI units).
#[derive(Debug, Clone, PartialEq)]
pub struct Material {
    /// Name used in model files.
    pub name: String,
    /// Young's modulus `E` (Pa).
    pub youngs_modulus: f64,
    /// Shear modulus `G` (Pa).
    pub shear_modulus: f64,
    /// Mass density `ρ` (kg/m³).
    pub density: f64,
}

impl Material {
    /// Poisson's ratio of an isotropic material, `ν = E/(2G) − 1`.
    pub fn poisson_ratio(&self) -> f64 {
        self.youngs_modulus / (2.0 * self.shear_modulus) - 1.0
    }
}

/// A circular tube cross-section (`inner_diameter = 0` for a solid shaft).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CircularSection {
    /// Outer diameter (m).
    pub outer_diameter: f64,
    /// Inner diameter (m), zero for a solid section.
    pub inner_diameter: f64,
}

impl CircularSection {
    /// Area `A = π (D_o² − D_i²) / 4` (m²).
    pub fn area(&self) -> f64 {
        PI / 4.0 * (self.outer_diameter.powi(2) - self.inner_diameter.powi(2))
    }

    /// Diametral second moment of area `I = π (D_o⁴ − D_i⁴) / 64` (m⁴).
    pub fn second_moment(&self) -> f64 {
        PI / 64.0 * (self.outer_diameter.powi(4) - self.inner_diameter.powi(4))
    }

    /// Polar second moment of area `I_p = 2 I` (m⁴).
    pub fn polar_moment(&self) -> f64 {
        2.0 * self.second_moment()
    }

    /// Cowper's shear factor of a circular tube (Cowper 1966, J. Appl. Mech. 33, table 1):
    /// `κ = 6(1+ν)(1+m²)² / [(7+6ν)(1+m²)² + (20+12ν)m²]`, `m = D_i/D_o`;
    /// `κ = 6(1+ν)/(7+6ν)` for a solid section.
    pub fn cowper_shear_factor(&self, poisson_ratio: f64) -> f64 {
        let nu = poisson_ratio;
        let m2 = (self.inner_diameter / self.outer_diameter).powi(2);
        let a = (1.0 + m2).powi(2);
        6.0 * (1.0 + nu) * a / ((7.0 + 6.0 * nu) * a + (20.0 + 12.0 * nu) * m2)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn solid_section_properties() {
        let s = CircularSection {
            outer_diameter: 0.05,
            inner_diameter: 0.0,
        };
        assert!((s.area() - PI * 0.025f64.powi(2)).abs() < 1e-15);
        assert!((s.second_moment() - PI * 0.025f64.powi(4) / 4.0).abs() < 1e-18);
        // Cowper: solid circle, ν = 0.3 → 6·1.3/8.8 = 0.886 36
        assert!((s.cowper_shear_factor(0.3) - 7.8 / 8.8).abs() < 1e-14);
    }

    #[test]
    fn thin_tube_shear_factor_tends_to_half() {
        // Cowper's thin-walled tube limit (m → 1): κ = 2(1+ν)/(4+3ν).
        let s = CircularSection {
            outer_diameter: 1.0,
            inner_diameter: 0.999_999,
        };
        let nu = 0.3;
        let limit = 2.0 * (1.0 + nu) / (4.0 + 3.0 * nu);
        assert!((s.cowper_shear_factor(nu) - limit).abs() < 1e-5);
    }
}
