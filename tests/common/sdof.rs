//! The single-degree-of-freedom rotor of the analyst toolkit tests.

/// Disk mass (kg), bearing stiffness each (N/m) and damping ratio of the
/// single-DOF rotor.
pub const MASS: f64 = 100.0;
pub const K_EACH: f64 = 1e6;
pub const ZETA: f64 = 0.02;

/// A rigid 100 kg disk at the middle of a short, thick (d = 0.4 m, L = 0.4 m),
/// nearly massless shaft on two isotropic spring–dampers: in translation a
/// single-DOF oscillator `m ẍ + 2c ẋ + 2k x = m e Ω² cos Ωt` with
/// `ω_n = √(2k/m)` and `ζ = 2c/(2√(2k m))`. The shaft's bending stiffness
/// (48EI/L³ = 1.9e11 N/m, 1e5 × the springs, shear stiffer still) and mass (4e-5 kg) move ω_n by
/// about 1e-5; the rocking mode is not excited (the unbalance is at the
/// plane of symmetry) and, with `Ip > Id`, has no forward synchronous critical.
pub fn sdof_model() -> String {
    let c_each = ZETA * (2.0 * K_EACH * MASS).sqrt();
    format!(
        r#"
name = "sdof"
[[materials]]
name = "light_steel"
youngs_modulus = 2e11
poisson_ratio = 0.3
density = 1e-3
[[shaft]]
length = 0.4
outer_diameter = 0.4
material = "light_steel"
elements = 2
[[disks]]
name = "disk"
node = 2
mass = {MASS}
polar_inertia = 2.0
diametral_inertia = 1.0
[[bearings]]
name = "left"
type = "linear"
node = 1
kxx = {K_EACH}
kyy = {K_EACH}
cxx = {c_each}
cyy = {c_each}
[[bearings]]
name = "right"
type = "linear"
node = 3
kxx = {K_EACH}
kyy = {K_EACH}
cxx = {c_each}
cyy = {c_each}
[[unbalance]]
name = "disk"
node = 2
magnitude = 1e-3
phase_deg = 0.0
[[probes]]
name = "disk"
node = 2
"#
    )
}
