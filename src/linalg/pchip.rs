//! Shape-preserving piecewise cubic Hermite interpolation (PCHIP) of tabulated
//! data, held at the end values outside the table.
//!
//! The node derivatives are those of Fritsch & Butland (SIAM J. Sci. Stat.
//! Comput. 5(2), 1984) as SciPy's `PchipInterpolator` computes them — the
//! interpolator ROSS uses for its bearing and seal coefficient tables — so
//! the two codes interpolate a table identically:
//! - interior nodes: `d_k = (w₁ + w₂) / (w₁/δ_{k−1} + w₂/δ_k)` with
//!   `w₁ = 2h_k + h_{k−1}`, `w₂ = h_k + 2h_{k−1}`, and `d_k = 0` where the
//!   secants `δ` change sign or one of them is zero;
//! - end nodes: the three-point estimate `((2h₀ + h₁) δ₀ − h₀ δ₁)/(h₀ + h₁)`,
//!   set to 0 when its sign differs from `δ₀`'s and to `3δ₀` when the secants
//!   change sign and it exceeds `3|δ₀|`.
//!
//! Two points interpolate linearly, one point is a constant. On monotone data
//! the interpolant is monotone (no overshoot), and a cubic is not reproduced
//! in general (PCHIP is third-order accurate only where the data are smooth
//! and monotone; its derivatives are the harmonic-mean estimates above).
//!
//! ```
//! use rotor_bearing::linalg::pchip::Pchip;
//!
//! let p = Pchip::new(&[0.0, 1.0, 2.0, 4.0], &[0.0, 1.0, 1.5, 1.6]).unwrap();
//! assert_eq!(p.at(2.0), 1.5); // passes through the table
//! assert!(p.at(3.0) > 1.5 && p.at(3.0) < 1.6); // monotone between nodes
//! assert_eq!(p.at(10.0), 1.6); // held at the end value outside
//! ```

/// Why a table cannot be interpolated.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum PchipError {
    /// No points, or abscissae and values of different lengths.
    #[error("{abscissae} abscissae for {values} values")]
    Lengths { abscissae: usize, values: usize },
    /// A NaN or infinite entry at `index`.
    #[error("entry {index} is not finite")]
    NotFinite { index: usize },
    /// Abscissa `index` is not greater than the one before it.
    #[error("abscissa {index} is not greater than the one before it")]
    NotIncreasing { index: usize },
}

/// A PCHIP interpolant of `y(x)` on increasing `x`.
#[derive(Debug, Clone, PartialEq)]
pub struct Pchip {
    x: Vec<f64>,
    y: Vec<f64>,
    /// Derivative at each node.
    d: Vec<f64>,
}

impl Pchip {
    /// The interpolant of the table `(x_k, y_k)`, `x` strictly increasing.
    pub fn new(x: &[f64], y: &[f64]) -> Result<Self, PchipError> {
        if x.is_empty() || x.len() != y.len() {
            return Err(PchipError::Lengths {
                abscissae: x.len(),
                values: y.len(),
            });
        }
        for (index, (a, b)) in x.iter().zip(y).enumerate() {
            if !(a.is_finite() && b.is_finite()) {
                return Err(PchipError::NotFinite { index });
            }
        }
        if let Some(index) = (1..x.len()).find(|&k| x[k] <= x[k - 1]) {
            return Err(PchipError::NotIncreasing { index });
        }
        Ok(Self {
            d: derivatives(x, y),
            x: x.to_vec(),
            y: y.to_vec(),
        })
    }

    /// The table's abscissa range `(x_first, x_last)`.
    pub fn range(&self) -> (f64, f64) {
        (self.x[0], self.x[self.x.len() - 1])
    }

    /// The interpolated value at `t`; the end value outside the table.
    pub fn at(&self, t: f64) -> f64 {
        let n = self.x.len();
        if n == 1 || t <= self.x[0] {
            return self.y[0];
        }
        if t >= self.x[n - 1] {
            return self.y[n - 1];
        }
        // The interval [x_k, x_{k+1}) holding t.
        let k = self.x.partition_point(|&xk| xk <= t) - 1;
        let h = self.x[k + 1] - self.x[k];
        let s = (t - self.x[k]) / h;
        let (y0, y1) = (self.y[k], self.y[k + 1]);
        let (d0, d1) = (self.d[k] * h, self.d[k + 1] * h);
        // Cubic Hermite basis on [0, 1].
        let s2 = s * s;
        let s3 = s2 * s;
        (2.0 * s3 - 3.0 * s2 + 1.0) * y0
            + (s3 - 2.0 * s2 + s) * d0
            + (-2.0 * s3 + 3.0 * s2) * y1
            + (s3 - s2) * d1
    }
}

/// Node derivatives (see the module docs).
fn derivatives(x: &[f64], y: &[f64]) -> Vec<f64> {
    let n = x.len();
    if n == 1 {
        return vec![0.0];
    }
    let h: Vec<f64> = x.windows(2).map(|w| w[1] - w[0]).collect();
    let m: Vec<f64> = (0..n - 1).map(|k| (y[k + 1] - y[k]) / h[k]).collect();
    if n == 2 {
        return vec![m[0], m[0]];
    }
    let mut d = vec![0.0; n];
    for k in 1..n - 1 {
        let (a, b) = (m[k - 1], m[k]);
        if a == 0.0 || b == 0.0 || a.signum() != b.signum() {
            continue;
        }
        let w1 = 2.0 * h[k] + h[k - 1];
        let w2 = h[k] + 2.0 * h[k - 1];
        d[k] = (w1 + w2) / (w1 / a + w2 / b);
    }
    d[0] = edge(h[0], h[1], m[0], m[1]);
    d[n - 1] = edge(h[n - 2], h[n - 3], m[n - 2], m[n - 3]);
    d
}

/// One-sided three-point derivative at an end, shape-preserving.
fn edge(h0: f64, h1: f64, m0: f64, m1: f64) -> f64 {
    let d = ((2.0 * h0 + h1) * m0 - h0 * m1) / (h0 + h1);
    if d.signum() != m0.signum() || m0 == 0.0 {
        0.0
    } else if m0.signum() != m1.signum() && d.abs() > 3.0 * m0.abs() {
        3.0 * m0
    } else {
        d
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Values SciPy 1.16 `PchipInterpolator` (the interpolator of ROSS's
    /// coefficient tables) gives for the table x = [0, 1, 2.5, 4, 7],
    /// y = [1, 3, 2, 2.5, 9] (not monotone, uneven spacing: a zero derivative
    /// at the extremum, weighted harmonic means, both end formulas) and for
    /// the cubic y = x³ on x = 0…4, computed with
    /// `scipy.interpolate.PchipInterpolator(x, y)(t)`.
    #[test]
    fn matches_scipy_on_uneven_and_cubic_tables() {
        let p = Pchip::new(&[0.0, 1.0, 2.5, 4.0, 7.0], &[1.0, 3.0, 2.0, 2.5, 9.0]).unwrap();
        let uneven = [
            (0.5, 2.3833333333333333),
            (1.7, 2.5499259259259257),
            (3.1, 2.0990684931506847),
            (5.5, 4.679509132420091),
        ];
        let x = [0.0, 1.0, 2.0, 3.0, 4.0];
        let cube = Pchip::new(&x, &x.map(|v: f64| v.powi(3))).unwrap();
        let cubic = [
            (0.5, 0.28125),
            (1.5, 3.439903846153846),
            (2.5, 15.640453296703297),
            (3.5, 42.88839285714286),
        ];
        for (table, want) in [(&p, uneven), (&cube, cubic)] {
            for (t, y) in want {
                let got = table.at(t);
                assert!(
                    (got - y).abs() < 1e-14 * y.abs(),
                    "at {t}: {got} against {y}"
                );
            }
        }
    }

    /// On the smooth monotone cubic y = x³ (0 ≤ x ≤ 2) the largest error
    /// falls as h³ (the derivative estimates are second-order): each halving
    /// of the spacing divides it by 8 ± 15 %.
    #[test]
    fn converges_at_third_order_on_a_cubic() {
        let error = |n: usize| {
            let x: Vec<f64> = (0..n).map(|k| 2.0 * k as f64 / (n - 1) as f64).collect();
            let y: Vec<f64> = x.iter().map(|v| v.powi(3)).collect();
            let p = Pchip::new(&x, &y).unwrap();
            (0..=1000)
                .map(|k| 2.0 * k as f64 / 1000.0)
                .map(|t| (p.at(t) - t.powi(3)).abs())
                .fold(0.0, f64::max)
        };
        let errors: Vec<f64> = [5, 9, 17, 33].into_iter().map(error).collect();
        for w in errors.windows(2) {
            let ratio = w[0] / w[1];
            assert!((ratio / 8.0 - 1.0).abs() < 0.15, "{errors:?}");
        }
    }

    /// Through every node, monotone between nodes of monotone data, held at
    /// the ends; two points are a straight line; bad tables are refused.
    #[test]
    fn interpolates_monotone_and_refuses_bad_tables() {
        let x = [100.0, 200.0, 400.0, 450.0, 900.0];
        let y = [1e8, 1.1e8, 3e8, 3.05e8, 8e8];
        let p = Pchip::new(&x, &y).unwrap();
        for (a, b) in x.iter().zip(&y) {
            assert_eq!(p.at(*a), *b);
        }
        let mut last = p.at(100.0);
        for k in 1..=800 {
            let v = p.at(100.0 + k as f64);
            assert!(v >= last, "not monotone at {}", 100 + k);
            last = v;
        }
        assert_eq!(p.at(0.0), 1e8);
        assert_eq!(p.at(1e4), 8e8);
        let line = Pchip::new(&[0.0, 2.0], &[1.0, 5.0]).unwrap();
        assert_eq!(line.at(0.5), 2.0);
        assert_eq!(Pchip::new(&[3.0], &[7.0]).unwrap().at(-1.0), 7.0);
        assert!(matches!(
            Pchip::new(&[0.0, 1.0, 1.0], &[0.0; 3]),
            Err(PchipError::NotIncreasing { index: 2 })
        ));
        assert!(Pchip::new(&[0.0, 1.0], &[0.0]).is_err());
        assert!(Pchip::new(&[0.0, f64::NAN], &[0.0, 1.0]).is_err());
    }
}
