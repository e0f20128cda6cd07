//! Two-node Timoshenko shaft element, 4 DOF per node (see [`crate::fe`] for the
//! ordering `[x1, y1, θx1, θy1, x2, y2, θx2, θy2]`).
//!
//! All matrices come from one set of interpolation functions, the exact
//! "interdependent" Timoshenko shape functions (Friswell et al., *Dynamics of
//! Rotating Machines*, 2010, §5.4.2), integrated by 4-point Gauss–Legendre
//! quadrature, which is exact for their products (degree ≤ 6):
//!
//! * translational mass `∫ ρA N_wᵀ N_w dz`, rotary inertia `∫ ρI N_θᵀ N_θ dz`;
//! * bending `∫ EI N_θ'ᵀ N_θ' dz` plus shear `∫ κGA (N_w' − N_θ)ᵀ (N_w' − N_θ) dz`;
//! * axial-load (geometric) stiffness `∫ P N_w'ᵀ N_w' dz` for a tension `P`
//!   (the paper's `(F/2) ∫ (∂x/∂z)² dz`, eq. 1);
//! * gyroscopic `G` from `T_g = Ω ∫ ρ I_p θ̇x θy dz` (eq. 3).
//!
//! In the x–z plane the beam coordinates are `(w, θ) = (x, θy)`; in the y–z plane
//! they are `(y, −θx)` because `∂y/∂z = −θx`.

use nalgebra::{SMatrix, SVector};

use super::section::{CircularSection, Material};

/// 8×8 element matrix.
pub type ElementMatrix = SMatrix<f64, 8, 8>;
type PlaneMatrix = SMatrix<f64, 4, 4>;
type PlaneVector = SVector<f64, 4>;

/// Which physical effects a shaft element includes.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ShaftEffects {
    /// Shear deformation (Timoshenko); `false` gives the Euler–Bernoulli beam.
    pub shear_deformation: bool,
    /// Rotary inertia of the cross-sections.
    pub rotary_inertia: bool,
}

impl Default for ShaftEffects {
    fn default() -> Self {
        Self {
            shear_deformation: true,
            rotary_inertia: true,
        }
    }
}

/// One shaft element: a uniform circular tube between two nodes.
#[derive(Debug, Clone, PartialEq)]
pub struct ShaftElement {
    /// Element length `L` (m).
    pub length: f64,
    /// Cross-section.
    pub section: CircularSection,
    /// Material.
    pub material: Material,
    /// Effects to include.
    pub effects: ShaftEffects,
}

/// The element matrices of a shaft element, in the element's DOF order.
#[derive(Debug, Clone, PartialEq)]
pub struct ShaftMatrices {
    /// Consistent mass (translational plus rotary inertia), kg and kg·m².
    pub mass: ElementMatrix,
    /// Bending plus shear stiffness, N/m, N, N·m.
    pub stiffness: ElementMatrix,
    /// Geometric stiffness per newton of axial tension (multiply by the tension in N).
    pub axial_per_newton: ElementMatrix,
    /// Gyroscopic matrix per rad/s of spin (multiply by `Ω`); skew-symmetric.
    pub gyroscopic: ElementMatrix,
}

/// Element DOF indices of the x–z plane `(x1, θy1, x2, θy2)`.
const XZ_PLANE: [usize; 4] = [0, 3, 4, 7];
/// Element DOF indices of the y–z plane `(y1, θx1, y2, θx2)`.
const YZ_PLANE: [usize; 4] = [1, 2, 5, 6];
/// Sign mapping y–z plane DOFs to beam coordinates `(y, −θx)`.
const YZ_SIGN: [f64; 4] = [1.0, -1.0, 1.0, -1.0];

/// Gauss–Legendre points and weights on [0, 1], 4 points (exact to degree 7).
fn gauss4() -> [(f64, f64); 4] {
    let a = (3.0 / 7.0 - 2.0 / 7.0 * (6.0f64 / 5.0).sqrt()).sqrt();
    let b = (3.0 / 7.0 + 2.0 / 7.0 * (6.0f64 / 5.0).sqrt()).sqrt();
    let wa = (18.0 + 30.0f64.sqrt()) / 36.0;
    let wb = (18.0 - 30.0f64.sqrt()) / 36.0;
    [
        (0.5 * (1.0 - b), 0.5 * wb),
        (0.5 * (1.0 - a), 0.5 * wa),
        (0.5 * (1.0 + a), 0.5 * wa),
        (0.5 * (1.0 + b), 0.5 * wb),
    ]
}

/// Shape functions of one bending plane at `ξ = z/L` for the coordinates
/// `(w1, θ1, w2, θ2)`: returns `(N_w, dN_w/dz, N_θ, dN_θ/dz)`.
fn shape_functions(xi: f64, length: f64, phi: f64) -> [PlaneVector; 4] {
    let l = length;
    let d = 1.0 + phi;
    let (x, x2, x3) = (xi, xi * xi, xi * xi * xi);
    let nw = PlaneVector::new(
        (1.0 - 3.0 * x2 + 2.0 * x3 + phi * (1.0 - x)) / d,
        l * (x - 2.0 * x2 + x3 + 0.5 * phi * (x - x2)) / d,
        (3.0 * x2 - 2.0 * x3 + phi * x) / d,
        l * (-x2 + x3 - 0.5 * phi * (x - x2)) / d,
    );
    let dnw = PlaneVector::new(
        (-6.0 * x + 6.0 * x2 - phi) / (l * d),
        (1.0 - 4.0 * x + 3.0 * x2 + 0.5 * phi * (1.0 - 2.0 * x)) / d,
        (6.0 * x - 6.0 * x2 + phi) / (l * d),
        (-2.0 * x + 3.0 * x2 - 0.5 * phi * (1.0 - 2.0 * x)) / d,
    );
    let nt = PlaneVector::new(
        6.0 * (x2 - x) / (l * d),
        (1.0 - 4.0 * x + 3.0 * x2 + phi * (1.0 - x)) / d,
        -6.0 * (x2 - x) / (l * d),
        (3.0 * x2 - 2.0 * x + phi * x) / d,
    );
    let dnt = PlaneVector::new(
        6.0 * (2.0 * x - 1.0) / (l * l * d),
        (-4.0 + 6.0 * x - phi) / (l * d),
        -6.0 * (2.0 * x - 1.0) / (l * l * d),
        (6.0 * x - 2.0 + phi) / (l * d),
    );
    [nw, dnw, nt, dnt]
}

impl ShaftElement {
    /// Cowper shear factor of the section for this material.
    pub fn shear_factor(&self) -> f64 {
        self.section
            .cowper_shear_factor(self.material.poisson_ratio())
    }

    /// Shear parameter `φ = 12 E I / (κ G A L²)`; zero without shear deformation.
    pub fn shear_parameter(&self) -> f64 {
        if !self.effects.shear_deformation {
            return 0.0;
        }
        12.0 * self.material.youngs_modulus * self.section.second_moment()
            / (self.shear_factor()
                * self.material.shear_modulus
                * self.section.area()
                * self.length.powi(2))
    }

    /// Mass of the element (kg).
    pub fn mass(&self) -> f64 {
        self.material.density * self.section.area() * self.length
    }

    /// All element matrices, from the shape functions by exact quadrature.
    pub fn matrices(&self) -> ShaftMatrices {
        let l = self.length;
        let phi = self.shear_parameter();
        let rho = self.material.density;
        let area = self.section.area();
        let inertia = self.section.second_moment();
        let ei = self.material.youngs_modulus * inertia;
        let kga = self.shear_factor() * self.material.shear_modulus * area;
        let rotary = if self.effects.rotary_inertia {
            rho * inertia
        } else {
            0.0
        };

        let mut m_trans = PlaneMatrix::zeros();
        let mut m_rot = PlaneMatrix::zeros();
        let mut k_bend = PlaneMatrix::zeros();
        let mut k_shear = PlaneMatrix::zeros();
        let mut k_axial = PlaneMatrix::zeros();
        for (xi, weight) in gauss4() {
            let w = weight * l;
            let [nw, dnw, nt, dnt] = shape_functions(xi, l, phi);
            m_trans += nw * nw.transpose() * (w * rho * area);
            m_rot += nt * nt.transpose() * w;
            k_bend += dnt * dnt.transpose() * (w * ei);
            if self.effects.shear_deformation {
                let gamma = dnw - nt;
                k_shear += gamma * gamma.transpose() * (w * kga);
            }
            k_axial += dnw * dnw.transpose() * w;
        }
        let plane_mass = m_trans + m_rot * rotary;
        let plane_stiffness = k_bend + k_shear;

        let mut out = ShaftMatrices {
            mass: ElementMatrix::zeros(),
            stiffness: ElementMatrix::zeros(),
            axial_per_newton: ElementMatrix::zeros(),
            gyroscopic: ElementMatrix::zeros(),
        };
        for a in 0..4 {
            for b in 0..4 {
                let (xa, xb) = (XZ_PLANE[a], XZ_PLANE[b]);
                let (ya, yb) = (YZ_PLANE[a], YZ_PLANE[b]);
                let s = YZ_SIGN[a] * YZ_SIGN[b];
                for (target, source) in [
                    (&mut out.mass, &plane_mass),
                    (&mut out.stiffness, &plane_stiffness),
                    (&mut out.axial_per_newton, &k_axial),
                ] {
                    target[(xa, xb)] = source[(a, b)];
                    target[(ya, yb)] = s * source[(a, b)];
                }
                // The y–z beam rotation is ∂y/∂z = −θx = N_θ·(S q_y), S = YZ_SIGN, so
                // θx = −Σ S_b N_θ,b q_y,b, while θy = Σ N_θ,a q_x,a. With
                // T_g = Ω ∫ρI_p θ̇x θy: G[y-plane row, x-plane col] = −ρI_p ∫ (S N_θ) N_θᵀ,
                // and G[x-plane row, y-plane col] is its negative transpose.
                let g = -2.0 * rho * inertia * YZ_SIGN[a] * m_rot[(a, b)];
                out.gyroscopic[(ya, xb)] = g;
                out.gyroscopic[(xb, ya)] = -g;
            }
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn steel() -> Material {
        Material {
            name: "steel".into(),
            youngs_modulus: 211e9,
            shear_modulus: 81.2e9,
            density: 7810.0,
        }
    }

    fn element(length: f64, outer: f64, inner: f64) -> ShaftElement {
        ShaftElement {
            length,
            section: CircularSection {
                outer_diameter: outer,
                inner_diameter: inner,
            },
            material: steel(),
            effects: ShaftEffects::default(),
        }
    }

    fn max_abs(m: &ElementMatrix) -> f64 {
        m.iter().fold(0.0f64, |a, v| a.max(v.abs()))
    }

    #[test]
    fn symmetry_and_skew_symmetry() {
        let m = element(0.25, 0.05, 0.02).matrices();
        for (mat, sign) in [
            (&m.mass, 1.0),
            (&m.stiffness, 1.0),
            (&m.axial_per_newton, 1.0),
            (&m.gyroscopic, -1.0),
        ] {
            let defect = mat - mat.transpose() * sign;
            assert!(max_abs(&defect) <= 1e-13 * max_abs(mat), "{mat}");
        }
        assert!(max_abs(&m.gyroscopic) > 0.0);
    }

    #[test]
    fn translational_mass_sums_to_element_mass() {
        let e = element(0.25, 0.05, 0.0);
        let m = e.matrices().mass;
        // A rigid translation along x: qᵀ M q = element mass.
        let mut q = SVector::<f64, 8>::zeros();
        q[0] = 1.0;
        q[4] = 1.0;
        let rigid = (q.transpose() * m * q)[(0, 0)];
        assert!((rigid - e.mass()).abs() < 1e-12 * e.mass());
    }

    #[test]
    fn rigid_body_motions_store_no_strain_energy() {
        let l = 0.3;
        let m = element(l, 0.08, 0.03).matrices();
        // Translations, and rigid rotations: x = a(z − z1) with θy = a; y = −b z with θx = b.
        let mut modes = Vec::new();
        for (x, y) in [(1.0, 0.0), (0.0, 1.0)] {
            modes.push(SVector::<f64, 8>::from_column_slice(&[
                x, y, 0.0, 0.0, x, y, 0.0, 0.0,
            ]));
        }
        modes.push(SVector::<f64, 8>::from_column_slice(&[
            0.0, 0.0, 0.0, 1.0, l, 0.0, 0.0, 1.0,
        ]));
        modes.push(SVector::<f64, 8>::from_column_slice(&[
            0.0, 0.0, 1.0, 0.0, 0.0, -l, 1.0, 0.0,
        ]));
        let scale = max_abs(&m.stiffness);
        for q in &modes {
            let force = m.stiffness * q;
            assert!(
                force.amax() < 1e-10 * scale,
                "rigid mode {q} gives force {force}"
            );
        }
        // The axial load term is zero for rigid translations only.
        for q in &modes[..2] {
            assert!((m.axial_per_newton * q).amax() < 1e-12);
        }
    }

    /// Closed-form Timoshenko matrices of Friswell et al. (2010), eqs. (5.51)–(5.53),
    /// for the x–z plane `(x1, θy1, x2, θy2)`: an independent check of the quadrature.
    #[test]
    fn matches_closed_form_timoshenko_matrices() {
        let e = element(0.2, 0.1, 0.04);
        let mats = e.matrices();
        let (l, phi) = (e.length, e.shear_parameter());
        let rho_a = e.material.density * e.section.area();
        let rho_i = e.material.density * e.section.second_moment();
        let ei = e.material.youngs_modulus * e.section.second_moment();

        let m1 = 312.0 + 588.0 * phi + 280.0 * phi * phi;
        let m2 = (44.0 + 77.0 * phi + 35.0 * phi * phi) * l;
        let m3 = 108.0 + 252.0 * phi + 140.0 * phi * phi;
        let m4 = -(26.0 + 63.0 * phi + 35.0 * phi * phi) * l;
        let m5 = (8.0 + 14.0 * phi + 7.0 * phi * phi) * l * l;
        let m6 = -(6.0 + 14.0 * phi + 7.0 * phi * phi) * l * l;
        let mt = PlaneMatrix::new(
            m1, m2, m3, m4, m2, m5, -m4, m6, m3, -m4, m1, -m2, m4, m6, -m2, m5,
        ) * (rho_a * l / (840.0 * (1.0 + phi).powi(2)));
        let r1 = 36.0;
        let r2 = (3.0 - 15.0 * phi) * l;
        let r3 = (4.0 + 5.0 * phi + 10.0 * phi * phi) * l * l;
        let r4 = (-1.0 - 5.0 * phi + 5.0 * phi * phi) * l * l;
        let mr = PlaneMatrix::new(
            r1, r2, -r1, r2, r2, r3, -r2, r4, -r1, -r2, r1, -r2, r2, r4, -r2, r3,
        ) * (rho_i / (30.0 * l * (1.0 + phi).powi(2)));
        let k = PlaneMatrix::new(
            12.0,
            6.0 * l,
            -12.0,
            6.0 * l,
            6.0 * l,
            (4.0 + phi) * l * l,
            -6.0 * l,
            (2.0 - phi) * l * l,
            -12.0,
            -6.0 * l,
            12.0,
            -6.0 * l,
            6.0 * l,
            (2.0 - phi) * l * l,
            -6.0 * l,
            (4.0 + phi) * l * l,
        ) * (ei / ((1.0 + phi) * l.powi(3)));
        let expect_m = mt + mr;
        for a in 0..4 {
            for b in 0..4 {
                let (i, j) = (XZ_PLANE[a], XZ_PLANE[b]);
                let tol_m = 1e-12 * expect_m.amax();
                let tol_k = 1e-12 * k.amax();
                assert!((mats.mass[(i, j)] - expect_m[(a, b)]).abs() < tol_m);
                assert!((mats.stiffness[(i, j)] - k[(a, b)]).abs() < tol_k);
            }
        }
    }

    /// A rigid spinning cylinder tilting about its centre: the gyroscopic moment of
    /// the element must equal that of a disk with the cylinder's polar inertia
    /// `I_p = ρ I_p,area L` acting on the common tilt, `M = Ω I_p (θ̇y, −θ̇x)`
    /// (the sign convention of [`crate::fe::disk`]).
    #[test]
    fn gyroscopic_moment_of_rigid_tilt_equals_disk_of_same_polar_inertia() {
        let l = 0.4;
        let e = element(l, 0.1, 0.03);
        let g = e.matrices().gyroscopic;
        let ip = e.material.density * e.section.polar_moment() * l;
        // Rigid tilt rates about the mid-point: θ̇x = a, θ̇y = b.
        let (a, b) = (0.7, -1.3);
        let qdot = SVector::<f64, 8>::from_column_slice(&[
            -b * l / 2.0,
            a * l / 2.0,
            a,
            b,
            b * l / 2.0,
            -a * l / 2.0,
            a,
            b,
        ]);
        let f = g * qdot;
        // Net moments about x and y (nodal moments plus forces × arm about the centre).
        let moment_x = f[2] + f[6] - (f[5] * l / 2.0 - f[1] * l / 2.0);
        let moment_y = f[3] + f[7] + (f[4] * l / 2.0 - f[0] * l / 2.0);
        let disk = crate::fe::disk::Disk {
            mass: 0.0,
            polar_inertia: ip,
            diametral_inertia: 0.0,
        }
        .gyroscopic_matrix();
        let expect_x = disk[(2, 3)] * b;
        let expect_y = disk[(3, 2)] * a;
        assert!(
            (moment_x - expect_x).abs() < 1e-9 * ip,
            "{moment_x} vs {expect_x}"
        );
        assert!(
            (moment_y - expect_y).abs() < 1e-9 * ip,
            "{moment_y} vs {expect_y}"
        );
        // Net gyroscopic force of a rigid tilt is zero.
        assert!((f[0] + f[4]).abs() < 1e-9 * ip && (f[1] + f[5]).abs() < 1e-9 * ip);
    }

    #[test]
    fn euler_bernoulli_limit_has_no_shear() {
        let mut e = element(0.2, 0.05, 0.0);
        e.effects.shear_deformation = false;
        assert_eq!(e.shear_parameter(), 0.0);
        let k = e.matrices().stiffness;
        let ei = e.material.youngs_modulus * e.section.second_moment();
        assert!((k[(0, 0)] - 12.0 * ei / 0.008).abs() < 1e-9 * k[(0, 0)]);
    }
}
