//! Closed-form film integrals of the short (Ocvirk) bearing.
//!
//! With the dimensionless film `H(θ) = 1 − x cos θ − y sin θ` (`x = X/C`, `y = Y/C`,
//! `x² + y² < 1`), every integral the short-bearing force and its Jacobians need
//! over an arc `[θ1, θ2]` is a partial derivative of one function,
//!
//! `Φ(x, y) = ∫_{θ1}^{θ2} dθ / H = (1/√m) [θ2 − θ1 + 2 atan(N(θ2)/D(θ2)) − 2 atan(N(θ1)/D(θ1))]`,
//!
//! `m = 1 − x² − y²`, `N(θ) = x sin θ − y cos θ`, `D(θ) = 1 + √m − x cos θ − y sin θ > 0`
//! (the continuous antiderivative of `1/(1 − ε cos ψ)`, written in Cartesian
//! form so that it stays regular at the centre `ε = 0`). At fixed arc ends:
//!
//! * `∂²Φ/∂x² = 2 ∫ cos²θ/H³`, `∂²Φ/∂x∂y = 2 ∫ sinθ cosθ/H³`, `∂²Φ/∂y² = 2 ∫ sin²θ/H³`;
//! * `∂³Φ/∂x^i∂y^j = 6 ∫ cos^iθ sin^jθ / H⁴` for `i + j = 3`.
//!
//! [`arc_potential`] evaluates `Φ` as a bivariate Taylor polynomial of degree 3
//! ([`Jet3`]): exact derivatives of the closed form, no finite differences.
//! The two arc tangents of the value are taken as one ([`atan_difference`]);
//! their derivatives stay end by end.

use std::ops::{Add, Div, Mul, Neg, Sub};

pub use super::film_lanes::atan_difference;
use super::film_lanes::{ArcLanes, JetLanes, arc_potentials, arc_potentials2};

/// Truncated bivariate Taylor series `Σ c_k dxⁱ dyʲ`, `i + j ≤ 3`, stored flat in
/// the monomial order `1, x, y, x², xy, y², x³, x²y, xy², y³`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Jet3 {
    c: [f64; 10],
}

/// Exponents `(i, j)` of the flat monomials.
pub(crate) const MONOMIALS: [(usize, usize); 10] = [
    (0, 0),
    (1, 0),
    (0, 1),
    (2, 0),
    (1, 1),
    (0, 2),
    (3, 0),
    (2, 1),
    (1, 2),
    (0, 3),
];

impl Jet3 {
    /// A constant.
    pub fn constant(v: f64) -> Self {
        let mut c = [0.0; 10];
        c[0] = v;
        Self { c }
    }

    /// The same jet with the constant term `v`.
    pub fn with_value(mut self, v: f64) -> Self {
        self.c[0] = v;
        self
    }

    /// The first variable `x` at `x0`.
    pub fn var_x(x0: f64) -> Self {
        let mut j = Self::constant(x0);
        j.c[1] = 1.0;
        j
    }

    /// The second variable `y` at `y0`.
    pub fn var_y(y0: f64) -> Self {
        let mut j = Self::constant(y0);
        j.c[2] = 1.0;
        j
    }

    /// The jet of the given Taylor coefficients (monomial order above).
    pub(crate) fn from_coefficients(c: [f64; 10]) -> Self {
        Self { c }
    }

    /// Value at the expansion point.
    pub fn value(&self) -> f64 {
        self.c[0]
    }

    /// Partial derivative `∂^{i+j}/∂xⁱ∂yʲ` at the expansion point (`i + j ≤ 3`).
    pub fn derivative(&self, i: usize, j: usize) -> f64 {
        const FACT: [f64; 4] = [1.0, 1.0, 2.0, 6.0];
        MONOMIALS
            .iter()
            .position(|&m| m == (i, j))
            .map_or(0.0, |k| self.c[k] * FACT[i] * FACT[j])
    }

    fn scale(mut self, s: f64) -> Self {
        for v in &mut self.c {
            *v *= s;
        }
        self
    }

    /// The jet as the one lane of a [`JetLanes`] (whose operations are the
    /// ones written out; one arc alone is the one-lane case).
    fn lane(self) -> JetLanes<1> {
        JetLanes {
            c: self.c.map(|v| [v]),
        }
    }

    fn from_lane(j: JetLanes<1>) -> Self {
        Self {
            c: j.c.map(|[v]| v),
        }
    }

    /// Square root (value must be positive).
    pub fn sqrt(self) -> Self {
        Self::from_lane(self.lane().sqrt())
    }

    /// Reciprocal (value must be non-zero).
    pub fn recip(self) -> Self {
        Self::from_lane(self.lane().recip())
    }

    /// Arc tangent.
    pub fn atan(self) -> Self {
        Self::from_lane(self.lane().atan())
    }
}

impl Add for Jet3 {
    type Output = Self;
    fn add(mut self, o: Self) -> Self {
        for (a, b) in self.c.iter_mut().zip(o.c) {
            *a += b;
        }
        self
    }
}

impl Sub for Jet3 {
    type Output = Self;
    fn sub(self, o: Self) -> Self {
        self + (-o)
    }
}

impl Neg for Jet3 {
    type Output = Self;
    fn neg(self) -> Self {
        self.scale(-1.0)
    }
}

impl Mul for Jet3 {
    type Output = Self;
    /// Truncated product ([`JetLanes::mul`] on one lane).
    fn mul(self, o: Self) -> Self {
        Self::from_lane(self.lane().mul(&o.lane()))
    }
}

impl Mul<f64> for Jet3 {
    type Output = Self;
    fn mul(self, s: f64) -> Self {
        self.scale(s)
    }
}

impl Div for Jet3 {
    type Output = Self;
    fn div(self, o: Self) -> Self {
        Mul::mul(self, o.recip())
    }
}

/// `Φ(x, y) = ∫_{θ1}^{θ2} dθ / (1 − x cos θ − y sin θ)` as a degree-3 Taylor jet at
/// `(x, y)`, `x² + y² < 1`, arc ends held fixed.
pub fn arc_potential(x: f64, y: f64, theta1: f64, theta2: f64) -> Jet3 {
    arc_potential_sc(x, y, theta2 - theta1, theta1.sin_cos(), theta2.sin_cos())
}

/// [`arc_potential`] over an arc of length `span` whose ends have the given
/// `(sin θ, cos θ)` (callers that know them algebraically skip the trigonometry).
///
/// The jets of `x` and `y` are linear, so `m = 1 − x² − y²` and the numerators
/// `N = x sin θ − y cos θ` are written out with the coefficients that are
/// exactly zero left out, and `N / D` multiplies a linear jet: the same
/// floating-point operations on the non-zero terms as the generic jet
/// arithmetic, so the same values (`tests::the_written_out_potential_is_the_generic_one`).
pub fn arc_potential_sc(x: f64, y: f64, span: f64, end1: (f64, f64), end2: (f64, f64)) -> Jet3 {
    Jet3::from_lane(arc_potentials(&one_arc(x, y, span, end1, end2)))
}

/// The value of [`arc_potential_sc`] alone, by the same operations on the
/// constant terms (so the same number).
pub fn arc_potential_value(x: f64, y: f64, span: f64, end1: (f64, f64), end2: (f64, f64)) -> f64 {
    let root = ((1.0 - x * x) - y * y).sqrt();
    let end = |(s, c): (f64, f64)| (x * s - y * c) * (1.0 / (((1.0 + root) - x * c) - y * s));
    (span + atan_difference(end(end2), end(end1)) * 2.0) * (1.0 / root)
}

/// The terms of [`arc_potential_sc`] up to degree 2 (value, gradient and
/// Hessian coefficients, monomial order `1, x, y, x², xy, y²`): what the film
/// force needs without its Jacobians. Degree-2 coefficients of a truncated
/// product or composition take no degree-3 terms, so these are the same
/// floating-point operations on the same numbers as the first six of
/// [`arc_potential_sc`], the same values
/// (`tests::the_degree_two_potential_is_the_head_of_the_degree_three_one`).
pub fn arc_potential_sc2(
    x: f64,
    y: f64,
    span: f64,
    end1: (f64, f64),
    end2: (f64, f64),
) -> [f64; 6] {
    arc_potentials2(&one_arc(x, y, span, end1, end2)).map(|[v]| v)
}

/// One arc as the one lane of an [`ArcLanes`].
fn one_arc(x: f64, y: f64, span: f64, end1: (f64, f64), end2: (f64, f64)) -> ArcLanes<1> {
    ArcLanes {
        x: [x],
        y: [y],
        span: [span],
        from_sc: ([end1.0], [end1.1]),
        to_sc: ([end2.0], [end2.1]),
    }
}

/// The second and third derivatives of [`arc_potential`], named by the trig
/// monomials they integrate. Integrals over several arcs add.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct FilmIntegrals {
    /// `Φ_xx = 2 ∫ cos²/H³`.
    pub xx: f64,
    /// `Φ_xy = 2 ∫ sin cos/H³`.
    pub xy: f64,
    /// `Φ_yy = 2 ∫ sin²/H³`.
    pub yy: f64,
    /// `Φ_xxx = 6 ∫ cos³/H⁴`.
    pub xxx: f64,
    /// `Φ_xxy = 6 ∫ cos² sin/H⁴`.
    pub xxy: f64,
    /// `Φ_xyy = 6 ∫ cos sin²/H⁴`.
    pub xyy: f64,
    /// `Φ_yyy = 6 ∫ sin³/H⁴`.
    pub yyy: f64,
}

impl Add for FilmIntegrals {
    type Output = Self;
    fn add(self, o: Self) -> Self {
        Self {
            xx: self.xx + o.xx,
            xy: self.xy + o.xy,
            yy: self.yy + o.yy,
            xxx: self.xxx + o.xxx,
            xxy: self.xxy + o.xxy,
            xyy: self.xyy + o.xyy,
            yyy: self.yyy + o.yyy,
        }
    }
}

impl FilmIntegrals {
    /// The film integrals over `[θ1, θ2]` at `(x, y)`.
    pub fn over_arc(x: f64, y: f64, theta1: f64, theta2: f64) -> Self {
        Self::from_potential(arc_potential(x, y, theta1, theta2))
    }

    /// The second-derivative integrals from the potential's terms up to
    /// degree 2 ([`arc_potential_sc2`]); the third derivatives are left zero.
    pub fn from_potential2(c: [f64; 6]) -> Self {
        Self {
            xx: 2.0 * c[3],
            xy: c[4],
            yy: 2.0 * c[5],
            ..Self::default()
        }
    }

    /// The film integrals from the potential's jet.
    pub fn from_potential(phi: Jet3) -> Self {
        // Taylor coefficients times i! j! (monomial order of [`Jet3`]).
        let c = phi.c;
        Self {
            xx: 2.0 * c[3],
            xy: c[4],
            yy: 2.0 * c[5],
            xxx: 6.0 * c[6],
            xxy: 2.0 * c[7],
            xyy: 2.0 * c[8],
            yyy: 6.0 * c[9],
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Composite Gauss–Legendre (8 points per panel) on a smooth periodic integrand.
    fn quad(f: impl Fn(f64) -> f64, a: f64, b: f64, panels: usize) -> f64 {
        let nodes = [
            (0.183_434_642_495_649_8, 0.362_683_783_378_362),
            (0.525_532_409_916_329, 0.313_706_645_877_887_3),
            (0.796_666_477_413_626_7, 0.222_381_034_453_374_5),
            (0.960_289_856_497_536_3, 0.101_228_536_290_376_3),
        ];
        let h = (b - a) / panels as f64;
        let mut sum = 0.0;
        for k in 0..panels {
            let mid = a + (k as f64 + 0.5) * h;
            for (t, w) in nodes {
                sum += w * (f(mid + 0.5 * h * t) + f(mid - 0.5 * h * t));
            }
        }
        sum * 0.5 * h
    }

    /// Uniform numbers in [0, 1) from a 64-bit LCG seeded with `seed`.
    fn uniform(mut seed: u64) -> impl FnMut() -> f64 {
        move || {
            seed = seed
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            (seed >> 11) as f64 / (1u64 << 53) as f64
        }
    }

    #[test]
    fn film_integrals_match_quadrature() {
        let cases = [
            (0.0, 0.0, 0.3, 0.3 + std::f64::consts::PI),
            (1e-7, -2e-7, -1.0, 2.0),
            (0.3, -0.4, 1.0, 1.0 + std::f64::consts::PI),
            (-0.7, 0.5, -2.5, 0.4),
            (0.05, 0.9, 2.0, 5.5),
            (0.6, 0.1, -4.0, 4.0),
        ];
        for (x, y, t1, t2) in cases {
            let f = FilmIntegrals::over_arc(x, y, t1, t2);
            let h = |t: f64| 1.0 - x * t.cos() - y * t.sin();
            let q = |g: &dyn Fn(f64) -> f64| quad(g, t1, t2, 400);
            let expect = [
                (f.xx, 2.0 * q(&|t| t.cos().powi(2) / h(t).powi(3))),
                (f.xy, 2.0 * q(&|t| t.sin() * t.cos() / h(t).powi(3))),
                (f.yy, 2.0 * q(&|t| t.sin().powi(2) / h(t).powi(3))),
                (f.xxx, 6.0 * q(&|t| t.cos().powi(3) / h(t).powi(4))),
                (
                    f.xxy,
                    6.0 * q(&|t| t.cos().powi(2) * t.sin() / h(t).powi(4)),
                ),
                (
                    f.xyy,
                    6.0 * q(&|t| t.cos() * t.sin().powi(2) / h(t).powi(4)),
                ),
                (f.yyy, 6.0 * q(&|t| t.sin().powi(3) / h(t).powi(4))),
            ];
            let scale = expect.iter().map(|(_, e)| e.abs()).fold(0.0, f64::max);
            for (got, want) in expect {
                assert!(
                    (got - want).abs() < 1e-11 * scale,
                    "(x, y) = ({x}, {y}) arc [{t1}, {t2}]: {got} vs {want}"
                );
            }
            let phi = arc_potential(x, y, t1, t2).value();
            let want = q(&|t| 1.0 / h(t));
            assert!((phi - want).abs() < 1e-12 * want.abs().max(1.0));
        }
    }

    /// The written-out potential against the generic jet arithmetic it
    /// replaced (kept here, the two arc tangents of the value taken as one as
    /// there): bit for bit, over random positions up to `ε = 0.995` and arcs
    /// of every length and place.
    #[test]
    fn the_written_out_potential_is_the_generic_one() {
        let generic = |x: f64, y: f64, span: f64, end1: (f64, f64), end2: (f64, f64)| {
            let (jx, jy) = (Jet3::var_x(x), Jet3::var_y(y));
            let one = Jet3::constant(1.0);
            let m = one - jx * jx - jy * jy;
            let root = m.sqrt();
            let ratio = |(s, c): (f64, f64)| (jx * s - jy * c) / (one + root - jx * c - jy * s);
            let (t2, t1) = (ratio(end2), ratio(end1));
            let diff = (t2.atan() - t1.atan()).with_value(atan_difference(t2.value(), t1.value()));
            (Jet3::constant(span) + diff * 2.0) / root
        };
        let mut rand = uniform(7);
        for _ in 0..20_000 {
            let (eps, angle) = (0.995 * rand().sqrt(), 2.0 * std::f64::consts::PI * rand());
            let (x, y) = (eps * angle.cos(), eps * angle.sin());
            let t1 = 8.0 * rand() - 4.0;
            let t2 = t1 + 2.0 * std::f64::consts::PI * rand();
            let (a, b) = (t1.sin_cos(), t2.sin_cos());
            let got = arc_potential_sc(x, y, t2 - t1, a, b);
            let want = generic(x, y, t2 - t1, a, b);
            assert_eq!(got, want, "(x, y) = ({x}, {y}), arc [{t1}, {t2}]");
            let value = arc_potential_value(x, y, t2 - t1, a, b);
            assert_eq!(value.to_bits(), want.value().to_bits());
        }
        let centre = arc_potential_sc(0.0, 0.0, 1.0, (0.0, 1.0), 1f64.sin_cos());
        assert_eq!(centre, generic(0.0, 0.0, 1.0, (0.0, 1.0), 1f64.sin_cos()));
    }

    /// The force's degree-2 potential against the first six terms of the
    /// degree-3 one: bit for bit over random positions up to `ε = 0.995`, arcs
    /// of every length and place, and the centre.
    #[test]
    fn the_degree_two_potential_is_the_head_of_the_degree_three_one() {
        let mut rand = uniform(11);
        let mut cases: Vec<(f64, f64, f64, f64)> = (0..20_000)
            .map(|_| {
                let (eps, angle) = (0.995 * rand().sqrt(), 2.0 * std::f64::consts::PI * rand());
                let t1 = 8.0 * rand() - 4.0;
                (
                    eps * angle.cos(),
                    eps * angle.sin(),
                    t1,
                    t1 + 2.0 * std::f64::consts::PI * rand(),
                )
            })
            .collect();
        cases.push((0.0, 0.0, 0.0, 1.0));
        for (x, y, t1, t2) in cases {
            let (a, b) = (t1.sin_cos(), t2.sin_cos());
            let head = arc_potential_sc2(x, y, t2 - t1, a, b);
            let full = arc_potential_sc(x, y, t2 - t1, a, b);
            for (k, v) in head.iter().enumerate() {
                assert_eq!(
                    v.to_bits(),
                    full.c[k].to_bits(),
                    "term {k} at ({x}, {y}), arc [{t1}, {t2}]"
                );
            }
        }
    }

    #[test]
    fn jet_arithmetic_matches_known_derivatives() {
        // f = atan(x y) / sqrt(1 + x²): compare derivatives with hand formulas at (0.3, −0.7).
        let (x0, y0) = (0.3, -0.7);
        let x = Jet3::var_x(x0);
        let y = Jet3::var_y(y0);
        let f = (x * y).atan() / (Jet3::constant(1.0) + x * x).sqrt();
        let h = 1e-3;
        let g = |a: f64, b: f64| (a * b).atan() / (1.0 + a * a).sqrt();
        // Central differences of order h² for the mixed third derivative ∂³/∂x²∂y.
        let fxxy = ((g(x0 + h, y0 + h) - 2.0 * g(x0, y0 + h) + g(x0 - h, y0 + h))
            - (g(x0 + h, y0 - h) - 2.0 * g(x0, y0 - h) + g(x0 - h, y0 - h)))
            / (2.0 * h * h * h);
        assert!((f.derivative(2, 1) - fxxy).abs() < 1e-5 * fxxy.abs().max(1.0));
        assert!((f.value() - g(x0, y0)).abs() < 1e-15);
    }
}
