//! The oil's viscosity against temperature: the ASTM D341 (Walther) law
//! `log10 log10(ν + 0.7) = A − B log10 T` (ν in mm²/s, T in K) fitted through
//! an oil's two stated kinematic viscosities at 40 °C and 100 °C, and its
//! density `ρ(T) = ρ15 (1 − α (T − 288.15 K))` to give the dynamic viscosity
//! `μ = ρ ν` a film needs.
//!
//! The ISO VG grades of turbomachinery ([`Oil::iso_vg`]) take the grade's
//! midpoint at 40 °C (ISO 3448) and the 100 °C viscosity of a mineral oil of
//! viscosity index about 100 (the typical values of the Shell Tellus S2 M
//! data sheet, `tests/data/iso_vg_oils.csv`).

/// The constant of the Walther law ASTM D341 states for ν ≥ 2 mm²/s (mm²/s).
pub const WALTHER_OFFSET: f64 = 0.7;

/// 0 °C in kelvin.
pub const CELSIUS_ZERO: f64 = 273.15;

/// The anchor temperatures of an oil's stated viscosities: 40 °C and 100 °C (K).
pub const ANCHORS: [f64; 2] = [CELSIUS_ZERO + 40.0, CELSIUS_ZERO + 100.0];

/// Density at 15 °C of a mineral turbine oil (kg/m³) when none is stated:
/// the middle of the 860–880 kg/m³ ISO VG 22–68 turbine and hydraulic oils'
/// data sheets give.
pub const DEFAULT_DENSITY_15: f64 = 870.0;

/// Volumetric thermal expansion coefficient α (1/K) of a mineral oil of
/// about 870 kg/m³ at 15 °C: the density falls by α ρ15 per kelvin
/// (0.00064/K, the coefficient of the ASTM D1250 / API MPMS 11.1 tables
/// for lubricating oils of that density near room temperature), held
/// constant over the temperatures of an oil system.
pub const THERMAL_EXPANSION: f64 = 6.4e-4;

/// Reference temperature of the density (15 °C, in K).
pub const DENSITY_REFERENCE: f64 = CELSIUS_ZERO + 15.0;

/// The ISO VG grades with stated constants: grade, ν40 and ν100 (mm²/s).
pub const ISO_VG: [(u32, f64, f64); 4] = [
    (22, 22.0, 4.3),
    (32, 32.0, 5.4),
    (46, 46.0, 6.8),
    (68, 68.0, 8.6),
];

/// What an oil's data or a temperature cannot be.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum OilError {
    #[error("kinematic viscosities must be finite and above 2 mm²/s (ASTM D341), got {0} mm²/s")]
    Viscosity(f64),
    #[error(
        "the viscosity at 100 °C ({nu_100} mm²/s) must lie below the one at 40 °C ({nu_40} mm²/s)"
    )]
    NotThinning { nu_40: f64, nu_100: f64 },
    #[error("density must be finite and positive, got {0} kg/m³")]
    Density(f64),
    #[error("temperature must be finite and above absolute zero, got {0} K")]
    Temperature(f64),
}

/// The Walther law's constants: `log10 log10(ν + 0.7) = a − b log10 T`
/// (ν in mm²/s, T in K).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct WaltherLaw {
    /// `A` (–).
    pub a: f64,
    /// `B` (–).
    pub b: f64,
}

/// `log10 log10(ν + 0.7)` of a kinematic viscosity ν (mm²/s).
fn walther(nu: f64) -> f64 {
    (nu + WALTHER_OFFSET).log10().log10()
}

impl WaltherLaw {
    /// The law through `(t1, ν1)` and `(t2, ν2)` (K, mm²/s).
    pub fn through([t1, nu1]: [f64; 2], [t2, nu2]: [f64; 2]) -> Result<Self, OilError> {
        for t in [t1, t2] {
            check_temperature(t)?;
        }
        for nu in [nu1, nu2] {
            if !(nu.is_finite() && nu >= 2.0) {
                return Err(OilError::Viscosity(nu));
            }
        }
        let b = (walther(nu1) - walther(nu2)) / (t2.log10() - t1.log10());
        Ok(Self {
            a: walther(nu1) + b * t1.log10(),
            b,
        })
    }

    /// Kinematic viscosity (mm²/s) at `t` (K): `10^10^(A − B log10 T) − 0.7`.
    pub fn kinematic_viscosity(&self, t: f64) -> f64 {
        10f64.powf(10f64.powf(self.a - self.b * t.log10())) - WALTHER_OFFSET
    }
}

fn check_temperature(t: f64) -> Result<f64, OilError> {
    if t.is_finite() && t > 0.0 {
        Ok(t)
    } else {
        Err(OilError::Temperature(t))
    }
}

/// A lubricating oil: its kinematic viscosities at 40 °C and 100 °C and its
/// density at 15 °C.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Oil {
    /// Kinematic viscosity at 40 °C (mm²/s).
    pub nu_40: f64,
    /// Kinematic viscosity at 100 °C (mm²/s).
    pub nu_100: f64,
    /// Density at 15 °C (kg/m³).
    pub density_15: f64,
}

impl Oil {
    /// The oil of these data, checked: both viscosities above 2 mm²/s (the
    /// range of ASTM D341's 0.7), the 100 °C one the lower, the density
    /// positive.
    pub fn new(nu_40: f64, nu_100: f64, density_15: f64) -> Result<Self, OilError> {
        for nu in [nu_40, nu_100] {
            if !(nu.is_finite() && nu >= 2.0) {
                return Err(OilError::Viscosity(nu));
            }
        }
        if nu_100 >= nu_40 {
            return Err(OilError::NotThinning { nu_40, nu_100 });
        }
        if !(density_15.is_finite() && density_15 > 0.0) {
            return Err(OilError::Density(density_15));
        }
        Ok(Self {
            nu_40,
            nu_100,
            density_15,
        })
    }

    /// The ISO VG `grade` of [`ISO_VG`] at [`DEFAULT_DENSITY_15`]; `None` for
    /// a grade without stated constants.
    pub fn iso_vg(grade: u32) -> Option<Self> {
        ISO_VG
            .iter()
            .find(|(g, _, _)| *g == grade)
            .map(|&(_, nu_40, nu_100)| Self {
                nu_40,
                nu_100,
                density_15: DEFAULT_DENSITY_15,
            })
    }

    /// The Walther law through the oil's two stated viscosities.
    pub fn law(&self) -> WaltherLaw {
        WaltherLaw::through([ANCHORS[0], self.nu_40], [ANCHORS[1], self.nu_100])
            .expect("an Oil's viscosities are checked when it is made")
    }

    /// Kinematic viscosity (mm²/s) at `t` (K).
    pub fn kinematic_viscosity(&self, t: f64) -> Result<f64, OilError> {
        Ok(self.law().kinematic_viscosity(check_temperature(t)?))
    }

    /// Density (kg/m³) at `t` (K): `ρ15 (1 − α (T − 288.15))`.
    pub fn density(&self, t: f64) -> Result<f64, OilError> {
        let t = check_temperature(t)?;
        Ok(self.density_15 * (1.0 - THERMAL_EXPANSION * (t - DENSITY_REFERENCE)))
    }

    /// Dynamic viscosity μ = ρ ν (Pa·s) at `t` (K).
    pub fn dynamic_viscosity(&self, t: f64) -> Result<f64, OilError> {
        Ok(self.density(t)? * self.kinematic_viscosity(t)? * 1e-6)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bad_data_are_refused() {
        assert!(matches!(
            Oil::new(32.0, 40.0, 870.0),
            Err(OilError::NotThinning { .. })
        ));
        assert!(matches!(
            Oil::new(1.0, 0.5, 870.0),
            Err(OilError::Viscosity(_))
        ));
        assert!(matches!(
            Oil::new(32.0, 5.4, -1.0),
            Err(OilError::Density(_))
        ));
        let oil = Oil::iso_vg(32).unwrap();
        assert!(matches!(
            oil.dynamic_viscosity(-5.0),
            Err(OilError::Temperature(_))
        ));
        assert!(Oil::iso_vg(150).is_none());
    }
}
