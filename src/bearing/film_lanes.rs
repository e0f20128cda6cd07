//! The film potential's Taylor jets over `L` arcs at once: the operations of
//! [`crate::bearing::film::Jet3`] written lane by lane on arrays of `L` values, so
//! that the compiler packs arcs into vector registers (two per SSE2
//! register, on any x86-64; a tilting-pad bearing evaluates its loaded pads
//! two at a time, which measured faster than four or eight). Every lane does
//! the same floating-point operations in the same order as one arc alone,
//! so the values are the same bit for bit.

/// `L` values, one per arc.
pub(crate) type Lanes<const L: usize> = [f64; L];

/// A degree-3 Taylor jet per lane, in the monomial order of
/// [`crate::bearing::film::Jet3`] (`1, x, y, x², xy, y², x³, x²y, xy², y³`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct JetLanes<const L: usize> {
    pub c: [Lanes<L>; 10],
}

/// One arc per lane: the film position `(x, y)` (of the clearance), the arc's
/// length and the `(sin θ, cos θ)` of its ends.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct ArcLanes<const L: usize> {
    pub x: Lanes<L>,
    pub y: Lanes<L>,
    pub span: Lanes<L>,
    pub from_sc: (Lanes<L>, Lanes<L>),
    pub to_sc: (Lanes<L>, Lanes<L>),
}

/// `atan u₂ − atan u₁` with one arc tangent:
/// `atan((u₂ − u₁)/(1 + u₁u₂))`, plus `π sgn(u₂ − u₁)` when `1 + u₁u₂ < 0`
/// (the difference then lies beyond `±π/2`). Equal to the difference of the
/// two arc tangents to round-off (`tests::one_arc_tangent_is_the_difference_of_two`),
/// and no less accurate where they nearly cancel.
#[inline(always)]
pub fn atan_difference(u2: f64, u1: f64) -> f64 {
    let (num, den) = (u2 - u1, 1.0 + u1 * u2);
    let t = (num / den).atan();
    if den < 0.0 {
        t + std::f64::consts::PI.copysign(num)
    } else {
        t
    }
}

#[inline(always)]
fn zip<const L: usize>(a: Lanes<L>, b: Lanes<L>, f: impl Fn(f64, f64) -> f64) -> Lanes<L> {
    std::array::from_fn(|i| f(a[i], b[i]))
}

#[inline(always)]
fn map<const L: usize>(a: Lanes<L>, f: impl Fn(f64) -> f64) -> Lanes<L> {
    std::array::from_fn(|i| f(a[i]))
}

#[inline(always)]
fn add<const L: usize>(a: Lanes<L>, b: Lanes<L>) -> Lanes<L> {
    zip(a, b, |x, y| x + y)
}

#[inline(always)]
fn sub<const L: usize>(a: Lanes<L>, b: Lanes<L>) -> Lanes<L> {
    zip(a, b, |x, y| x - y)
}

#[inline(always)]
fn mul<const L: usize>(a: Lanes<L>, b: Lanes<L>) -> Lanes<L> {
    zip(a, b, |x, y| x * y)
}

/// `s · a` (the scalar first, as in `2.0 * a`).
#[inline(always)]
fn scale<const L: usize>(s: f64, a: Lanes<L>) -> Lanes<L> {
    map(a, |x| s * x)
}

impl<const L: usize> JetLanes<L> {
    /// `f(u)` from `f` and its first three derivatives at `u0` (the jet's
    /// constant term): `f0 + f1 d + f2 d²/2 + f3 d³/6`, `d = u − u0`, with
    /// `d²` and `d³` written out term by term.
    #[inline(always)]
    pub fn compose(&self, f: [Lanes<L>; 4]) -> Self {
        let d = &self.c;
        let (h2, h3) = (scale(0.5, f[2]), map(f[3], |v| v / 6.0));
        let (a, b) = (d[1], d[2]);
        let sq = [
            mul(a, a),
            mul(scale(2.0, a), b),
            mul(b, b),
            mul(scale(2.0, a), d[3]),
            scale(2.0, add(mul(a, d[4]), mul(b, d[3]))),
            scale(2.0, add(mul(a, d[5]), mul(b, d[4]))),
            mul(scale(2.0, b), d[5]),
        ];
        let cube = [
            mul(mul(a, a), a),
            mul(mul(scale(3.0, a), a), b),
            mul(mul(scale(3.0, a), b), b),
            mul(mul(b, b), b),
        ];
        let f1 = f[1];
        Self {
            c: [
                f[0],
                mul(f1, a),
                mul(f1, b),
                add(mul(f1, d[3]), mul(h2, sq[0])),
                add(mul(f1, d[4]), mul(h2, sq[1])),
                add(mul(f1, d[5]), mul(h2, sq[2])),
                add(add(mul(f1, d[6]), mul(h2, sq[3])), mul(h3, cube[0])),
                add(add(mul(f1, d[7]), mul(h2, sq[4])), mul(h3, cube[1])),
                add(add(mul(f1, d[8]), mul(h2, sq[5])), mul(h3, cube[2])),
                add(add(mul(f1, d[9]), mul(h2, sq[6])), mul(h3, cube[3])),
            ],
        }
    }

    /// Square root (constant terms positive).
    #[inline(always)]
    pub fn sqrt(&self) -> Self {
        let u = self.c[0];
        let r = map(u, f64::sqrt);
        self.compose([
            r,
            map(r, |r| 0.5 / r),
            zip(u, r, |u, r| -0.25 / (u * r)),
            zip(u, r, |u, r| 0.375 / (u * u * r)),
        ])
    }

    /// Reciprocal (constant terms non-zero).
    #[inline(always)]
    pub fn recip(&self) -> Self {
        let r = map(self.c[0], |u| 1.0 / u);
        self.compose([
            r,
            map(r, |r| -r * r),
            map(r, |r| 2.0 * r * r * r),
            map(r, |r| -6.0 * r * r * r * r),
        ])
    }

    /// Arc tangent.
    #[inline(always)]
    pub fn atan(&self) -> Self {
        let mut jet = self.atan_rates();
        jet.c[0] = map(self.c[0], f64::atan);
        jet
    }

    /// [`JetLanes::atan`] without its value (left zero): the terms of
    /// degree 1 to 3.
    #[inline(always)]
    pub fn atan_rates(&self) -> Self {
        let u = self.c[0];
        let q = map(u, |u| 1.0 / (1.0 + u * u));
        self.compose([
            [0.0; L],
            q,
            zip(u, q, |u, q| -2.0 * u * q * q),
            zip(u, q, |u, q| (6.0 * u * u - 2.0) * q * q * q),
        ])
    }

    /// Truncated product, written out term by term.
    #[inline(always)]
    pub fn mul(&self, o: &Self) -> Self {
        let (a, b) = (&self.c, &o.c);
        let m = |i: usize, j: usize| mul(a[i], b[j]);
        Self {
            c: [
                m(0, 0),
                add(m(0, 1), m(1, 0)),
                add(m(0, 2), m(2, 0)),
                add(add(m(0, 3), m(1, 1)), m(3, 0)),
                add(add(add(m(0, 4), m(1, 2)), m(2, 1)), m(4, 0)),
                add(add(m(0, 5), m(2, 2)), m(5, 0)),
                add(add(add(m(0, 6), m(1, 3)), m(3, 1)), m(6, 0)),
                add(
                    add(add(add(add(m(0, 7), m(1, 4)), m(2, 3)), m(3, 2)), m(4, 1)),
                    m(7, 0),
                ),
                add(
                    add(add(add(add(m(0, 8), m(1, 5)), m(2, 4)), m(4, 2)), m(5, 1)),
                    m(8, 0),
                ),
                add(add(add(m(0, 9), m(2, 5)), m(5, 2)), m(9, 0)),
            ],
        }
    }

    /// The product of the linear jet `a0 + a1 dx + a2 dy` and `self`: the
    /// product with the terms of `a`'s zero coefficients left out (they come
    /// last in each sum, so the rounding is the same).
    #[inline(always)]
    fn mul_linear(&self, a: [Lanes<L>; 3]) -> Self {
        let b = &self.c;
        Self {
            c: [
                mul(a[0], b[0]),
                add(mul(a[0], b[1]), mul(a[1], b[0])),
                add(mul(a[0], b[2]), mul(a[2], b[0])),
                add(mul(a[0], b[3]), mul(a[1], b[1])),
                add(add(mul(a[0], b[4]), mul(a[1], b[2])), mul(a[2], b[1])),
                add(mul(a[0], b[5]), mul(a[2], b[2])),
                add(mul(a[0], b[6]), mul(a[1], b[3])),
                add(add(mul(a[0], b[7]), mul(a[1], b[4])), mul(a[2], b[3])),
                add(add(mul(a[0], b[8]), mul(a[1], b[5])), mul(a[2], b[4])),
                add(mul(a[0], b[9]), mul(a[2], b[5])),
            ],
        }
    }
}

/// The terms up to degree 2 of `m = 1 − x² − y²` (its higher ones are zero).
#[inline(always)]
fn film_m2<const L: usize>(x: Lanes<L>, y: Lanes<L>) -> Jet2Lanes<L> {
    let (zero, one) = ([0.0; L], [1.0; L]);
    [
        sub(sub(one, mul(x, x)), mul(y, y)),
        scale(-2.0, x),
        scale(-2.0, y),
        [-1.0; L],
        zero,
        [-1.0; L],
    ]
}

/// At an arc end with `(sin θ, cos θ) = (s, c)`: the linear numerator
/// `N = x sin θ − y cos θ` and the terms up to degree 1 of the denominator
/// `D = 1 + √m − x cos θ − y sin θ` (`r` the jet of `√m` from degree 0 to 2;
/// D's higher terms are those of `√m`).
#[inline(always)]
fn end_terms<const L: usize>(
    x: Lanes<L>,
    y: Lanes<L>,
    (s, c): (Lanes<L>, Lanes<L>),
    r: [Lanes<L>; 3],
) -> ([Lanes<L>; 3], [Lanes<L>; 3]) {
    let num = [sub(mul(x, s), mul(y, c)), s, map(c, |c| -c)];
    let den = [
        sub(sub(add([1.0; L], r[0]), mul(x, c)), mul(y, s)),
        sub(r[1], c),
        sub(r[2], s),
    ];
    (num, den)
}

/// Term `k` of `span + (atan t₂ − atan t₁)·2` with the generic jet
/// arithmetic's operations (`e₂ + (−e₁)`, times 2, then the constant added
/// to every term); the value's two arc tangents as one ([`atan_difference`]
/// of the ratios' values `u2`, `u1`), `e2`, `e1` the arc tangents' term `k`.
#[inline(always)]
fn potential_sum_term<const L: usize>(
    k: usize,
    span: Lanes<L>,
    (u2, u1): (Lanes<L>, Lanes<L>),
    (e2, e1): (Lanes<L>, Lanes<L>),
) -> Lanes<L> {
    if k == 0 {
        add(span, scale(2.0, zip(u2, u1, atan_difference)))
    } else {
        add([0.0; L], scale(2.0, add(e2, map(e1, |v| -v))))
    }
}

/// [`crate::bearing::film::arc_potential_sc`] on every lane of `arcs`: the jets of `x`
/// and `y` are linear, so `m = 1 − x² − y²` and the numerators
/// `N = x sin θ − y cos θ` are written out with the coefficients that are
/// exactly zero left out, and `N / D` multiplies a linear jet.
#[inline(always)]
pub(crate) fn arc_potentials<const L: usize>(arcs: &ArcLanes<L>) -> JetLanes<L> {
    let (x, y) = (arcs.x, arcs.y);
    let zero = [0.0; L];
    let [m0, m1, m2, m3, m4, m5] = film_m2(x, y);
    let m = JetLanes {
        c: [m0, m1, m2, m3, m4, m5, zero, zero, zero, zero],
    };
    let root = m.sqrt();
    let r = &root.c;
    let end = |sc: (Lanes<L>, Lanes<L>)| {
        let (num, [d0, d1, d2]) = end_terms(x, y, sc, [r[0], r[1], r[2]]);
        let den = JetLanes {
            c: [d0, d1, d2, r[3], r[4], r[5], r[6], r[7], r[8], r[9]],
        };
        den.recip().mul_linear(num)
    };
    let (t2, t1) = (end(arcs.to_sc), end(arcs.from_sc));
    let (e2, e1) = (t2.atan_rates(), t1.atan_rates());
    let mut sum = JetLanes { c: [zero; 10] };
    for (k, v) in sum.c.iter_mut().enumerate() {
        *v = potential_sum_term(k, arcs.span, (t2.c[0], t1.c[0]), (e2.c[k], e1.c[k]));
    }
    sum.mul(&root.recip())
}

/// A degree-2 Taylor jet per lane, monomials `1, x, y, x², xy, y²`.
pub(crate) type Jet2Lanes<const L: usize> = [Lanes<L>; 6];

/// [`JetLanes::compose`] truncated to degree 2.
#[inline(always)]
fn compose2<const L: usize>(d: &Jet2Lanes<L>, f: [Lanes<L>; 3]) -> Jet2Lanes<L> {
    let h2 = scale(0.5, f[2]);
    let (a, b) = (d[1], d[2]);
    let sq = [mul(a, a), mul(scale(2.0, a), b), mul(b, b)];
    [
        f[0],
        mul(f[1], a),
        mul(f[1], b),
        add(mul(f[1], d[3]), mul(h2, sq[0])),
        add(mul(f[1], d[4]), mul(h2, sq[1])),
        add(mul(f[1], d[5]), mul(h2, sq[2])),
    ]
}

/// [`JetLanes::sqrt`] truncated to degree 2.
#[inline(always)]
fn sqrt2<const L: usize>(d: &Jet2Lanes<L>) -> Jet2Lanes<L> {
    let u = d[0];
    let r = map(u, f64::sqrt);
    compose2(
        d,
        [r, map(r, |r| 0.5 / r), zip(u, r, |u, r| -0.25 / (u * r))],
    )
}

/// [`JetLanes::recip`] truncated to degree 2.
#[inline(always)]
fn recip2<const L: usize>(d: &Jet2Lanes<L>) -> Jet2Lanes<L> {
    let r = map(d[0], |u| 1.0 / u);
    compose2(d, [r, map(r, |r| -r * r), map(r, |r| 2.0 * r * r * r)])
}

/// [`JetLanes::atan_rates`] truncated to degree 2 (the value left zero).
#[inline(always)]
fn atan_rates2<const L: usize>(d: &Jet2Lanes<L>) -> Jet2Lanes<L> {
    let u = d[0];
    let q = map(u, |u| 1.0 / (1.0 + u * u));
    compose2(d, [[0.0; L], q, zip(u, q, |u, q| -2.0 * u * q * q)])
}

/// [`JetLanes::mul`] truncated to degree 2.
#[inline(always)]
fn mul2<const L: usize>(a: &Jet2Lanes<L>, b: &Jet2Lanes<L>) -> Jet2Lanes<L> {
    let m = |i: usize, j: usize| mul(a[i], b[j]);
    [
        m(0, 0),
        add(m(0, 1), m(1, 0)),
        add(m(0, 2), m(2, 0)),
        add(add(m(0, 3), m(1, 1)), m(3, 0)),
        add(add(add(m(0, 4), m(1, 2)), m(2, 1)), m(4, 0)),
        add(add(m(0, 5), m(2, 2)), m(5, 0)),
    ]
}

/// [`JetLanes::mul_linear`] truncated to degree 2.
#[inline(always)]
fn mul_linear2<const L: usize>(a: [Lanes<L>; 3], b: &Jet2Lanes<L>) -> Jet2Lanes<L> {
    [
        mul(a[0], b[0]),
        add(mul(a[0], b[1]), mul(a[1], b[0])),
        add(mul(a[0], b[2]), mul(a[2], b[0])),
        add(mul(a[0], b[3]), mul(a[1], b[1])),
        add(add(mul(a[0], b[4]), mul(a[1], b[2])), mul(a[2], b[1])),
        add(mul(a[0], b[5]), mul(a[2], b[2])),
    ]
}

/// [`arc_potentials`] truncated to degree 2 (what the film force needs
/// without its Jacobians) on every lane of `arcs`: degree-2 coefficients of a
/// truncated product or composition take no degree-3 terms, so these are the
/// same floating-point operations on the same numbers as the first six terms
/// of [`arc_potentials`], the same values.
#[inline(always)]
pub(crate) fn arc_potentials2<const L: usize>(arcs: &ArcLanes<L>) -> Jet2Lanes<L> {
    let (x, y) = (arcs.x, arcs.y);
    let root = sqrt2(&film_m2(x, y));
    let r = &root;
    let end = |sc: (Lanes<L>, Lanes<L>)| {
        let (num, [d0, d1, d2]) = end_terms(x, y, sc, [r[0], r[1], r[2]]);
        mul_linear2(num, &recip2(&[d0, d1, d2, r[3], r[4], r[5]]))
    };
    let (t2, t1) = (end(arcs.to_sc), end(arcs.from_sc));
    let (e2, e1) = (atan_rates2(&t2), atan_rates2(&t1));
    let sum: Jet2Lanes<L> =
        std::array::from_fn(|k| potential_sum_term(k, arcs.span, (t2[0], t1[0]), (e2[k], e1[k])));
    mul2(&sum, &recip2(&root))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bearing::film::{MONOMIALS, arc_potential_sc, arc_potential_sc2};

    /// Uniform numbers in [0, 1) from a 64-bit LCG seeded with `seed`.
    fn uniform(mut seed: u64) -> impl FnMut() -> f64 {
        move || {
            seed = seed
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            (seed >> 11) as f64 / (1u64 << 53) as f64
        }
    }

    /// `atan_difference(u₂, u₁)` against `atan u₂ − atan u₁`: within 4 ulp
    /// of π (the two rounded arc tangents and their difference are each
    /// within an ulp of it; so is the one arc tangent plus π) over ratios of
    /// every sign and size the film meets (`|u| ≤ 20`: `D ≥ √m ≥ 0.0999` at
    /// `ε ≤ 0.995`, `|N| ≤ ε`), both branches (`1 + u₁u₂` of either sign) and
    /// the nearly equal ratios where the difference of two cancels.
    #[test]
    fn one_arc_tangent_is_the_difference_of_two() {
        let mut rand = uniform(5);
        let (mut negative, mut positive) = (0, 0);
        for k in 0..200_000 {
            let u1 = 40.0 * rand() - 20.0;
            let u2 = if k % 4 == 0 {
                u1 * (1.0 + 1e-9 * rand())
            } else {
                40.0 * rand() - 20.0
            };
            if 1.0 + u1 * u2 < 0.0 {
                negative += 1;
            } else {
                positive += 1;
            }
            let (one, two) = (atan_difference(u2, u1), u2.atan() - u1.atan());
            assert!(
                (one - two).abs() <= 4.0 * f64::EPSILON * std::f64::consts::PI,
                "u2 = {u2}, u1 = {u1}: {one} vs {two}"
            );
        }
        assert!(
            negative > 10_000 && positive > 10_000,
            "{negative} / {positive}"
        );
        assert_eq!(atan_difference(0.0, 0.0), 0.0);
        assert_eq!(atan_difference(1.0, -1.0), std::f64::consts::FRAC_PI_2);
    }

    /// Arcs on lanes give, lane by lane, the jets of the arcs one by one, bit
    /// for bit, of degree 3 and of degree 2 (the force's alone): random
    /// positions up to `ε = 0.995`, arcs of every length and place, two,
    /// three and eight lanes.
    #[test]
    fn lanes_are_the_arcs_one_by_one() {
        let mut rand = uniform(3);
        fn check<const L: usize>(rand: &mut impl FnMut() -> f64) {
            let arcs: [(f64, f64, f64, f64); L] = std::array::from_fn(|_| {
                let (eps, angle) = (0.995 * rand().sqrt(), std::f64::consts::TAU * rand());
                let t1 = 8.0 * rand() - 4.0;
                (
                    eps * angle.cos(),
                    eps * angle.sin(),
                    t1,
                    t1 + std::f64::consts::TAU * rand(),
                )
            });
            let lanes = ArcLanes {
                x: arcs.map(|a| a.0),
                y: arcs.map(|a| a.1),
                span: arcs.map(|a| a.3 - a.2),
                from_sc: (arcs.map(|a| a.2.sin()), arcs.map(|a| a.2.cos())),
                to_sc: (arcs.map(|a| a.3.sin()), arcs.map(|a| a.3.cos())),
            };
            let phi = arc_potentials(&lanes);
            let phi2 = arc_potentials2(&lanes);
            for (lane, &(x, y, t1, t2)) in arcs.iter().enumerate() {
                let one = arc_potential_sc(x, y, t2 - t1, t1.sin_cos(), t2.sin_cos());
                let value = phi.c.map(|v| v[lane]);
                for (k, &(i, j)) in MONOMIALS.iter().enumerate() {
                    let factorial = [1.0, 1.0, 2.0, 6.0];
                    let got = value[k] * factorial[i] * factorial[j];
                    assert_eq!(got.to_bits(), one.derivative(i, j).to_bits(), "term {k}");
                }
                let head = arc_potential_sc2(x, y, t2 - t1, t1.sin_cos(), t2.sin_cos());
                for (k, h) in head.iter().enumerate() {
                    assert_eq!(phi2[k][lane].to_bits(), h.to_bits(), "degree 2, term {k}");
                }
            }
        }
        for _ in 0..2000 {
            check::<2>(&mut rand);
            check::<3>(&mut rand);
            check::<8>(&mut rand);
        }
    }
}
