//! Complex modal analysis of the gyroscopic rotor, `(λ² M + λ (C + Ω G) + K) x = 0`,
//! by shift-invert Arnoldi on the first-order form.
//!
//! With `z = [x; λx]`, `A = [[0, I], [−K, −D]]`, `B = diag(I, M)` and a shift `σ`,
//! the operator `(A − σB)⁻¹ B` applied to `[c; d]` is `[a; c + σ a]` with
//! `(K + σD + σ²M) a = −M d − (D + σM) c`: one banded solve of size `n` per
//! Krylov step, so the few wanted modes cost O(n) work and memory even for
//! thousands of elements. Eigenvalues follow from `λ = σ + 1/μ`.

use nalgebra::Complex;

use crate::fe::{DOF_PER_NODE, DOF_X, DOF_Y};
use crate::linalg::{ArnoldiOptions, BandMatrix, LinalgError, largest_eigenpairs, map_to_complex};
use crate::rotor::Rotor;

use super::linearize::linearized;

type C64 = Complex<f64>;

/// Direction of whirl of a mode relative to the spin.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Whirl {
    /// Every node orbits in the direction of the spin.
    Forward,
    /// Every node orbits against the spin.
    Backward,
    /// Nodes disagree, or the orbits are straight lines (e.g. at zero speed).
    Mixed,
}

impl Whirl {
    /// Short label for tables: `forward`, `backward`, `mixed`.
    pub fn label(&self) -> &'static str {
        match self {
            Whirl::Forward => "forward",
            Whirl::Backward => "backward",
            Whirl::Mixed => "mixed",
        }
    }
}

/// One complex mode.
#[derive(Debug, Clone, PartialEq)]
pub struct Mode {
    /// Eigenvalue `λ` (1/s).
    pub eigenvalue: C64,
    /// Undamped natural frequency `|λ|` (rad/s).
    pub natural_frequency: f64,
    /// Damped natural frequency `Im λ` (rad/s).
    pub damped_frequency: f64,
    /// Damping ratio `ζ = −Re λ / |λ|`.
    pub damping_ratio: f64,
    /// Logarithmic decrement `δ = −2π Re λ / Im λ` (infinite for non-oscillating modes).
    pub log_decrement: f64,
    /// Whirl direction.
    pub whirl: Whirl,
    /// Mode shape on all DOFs (`4·node + k`), largest displacement scaled to 1.
    pub shape: Vec<C64>,
    /// Relative residual of the eigenpair, `‖(λ²M + λD + K)x‖ / (‖K x‖)`-like.
    pub residual: f64,
}

/// Options of a modal analysis.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ModalOptions {
    /// Number of modes wanted (with positive damped frequency).
    pub modes: usize,
    /// Find the modes nearest this frequency (rad/s); 0 for the lowest.
    pub target_frequency: f64,
}

impl Default for ModalOptions {
    fn default() -> Self {
        Self {
            modes: 8,
            target_frequency: 0.0,
        }
    }
}

/// Modal analysis failure.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ModalError {
    /// Eigen-solver or factorization failure.
    #[error("modal analysis at {speed} rad/s: {source}")]
    Linalg { speed: f64, source: LinalgError },
    /// Bad options.
    #[error("modal analysis: {0}")]
    Options(String),
    /// The model has nonlinear bearings that need linearizing first.
    #[error("modal analysis: bearing {0} is nonlinear; modal analysis uses linear bearings only")]
    NonlinearBearing(String),
    /// Linearizing the nonlinear bearings failed.
    #[error(transparent)]
    Linearize(#[from] crate::analysis::linearize::LinearizeError),
}

/// Modes at `speed` of a rotor whose nonlinear bearings are first linearized about
/// the static equilibrium at that speed (synchronous coefficients); linear rotors
/// go straight to [`modes`].
pub fn modes_at(
    rotor: &Rotor,
    speed: f64,
    options: &ModalOptions,
) -> Result<Vec<Mode>, ModalError> {
    if rotor.nonlinear_bearings.is_empty() {
        return modes(rotor, speed, options);
    }
    let linear = linearized(rotor, speed, speed)?;
    modes(&linear, speed, options)
}

/// `D = C + Ω G` as a band matrix.
pub(crate) fn damping_at_speed(rotor: &Rotor, speed: f64) -> BandMatrix<f64> {
    let mut d = rotor.damping.clone();
    d.scale_add(speed, &rotor.gyroscopic);
    d
}

/// `K + σ D + σ² M` in complex band storage.
fn dynamic_stiffness(rotor: &Rotor, d: &BandMatrix<f64>, sigma: C64) -> BandMatrix<C64> {
    let mut q = map_to_complex(&rotor.stiffness);
    q.scale_add(sigma, &map_to_complex(d));
    q.scale_add(sigma * sigma, &map_to_complex(&rotor.mass));
    q
}

/// The lowest (or nearest-target) oscillating modes of `rotor` at spin speed
/// `speed` (rad/s), by increasing damped frequency. Non-oscillating eigenvalues
/// (rigid-body motion of a free rotor, overdamped modes) are not listed.
///
/// ```
/// use rotor_bearing::analysis::modal::{ModalOptions, modes};
/// use rotor_bearing::model::RotorModel;
/// use rotor_bearing::rotor::Rotor;
///
/// // The built-in classic disk-on-shaft rotor, on linear bearings.
/// let rotor = Rotor::new(RotorModel::default_model())?;
/// let speed = 4000.0 * std::f64::consts::PI / 30.0; // rad/s
/// let found = modes(&rotor, speed, &ModalOptions { modes: 2, ..ModalOptions::default() })?;
/// assert_eq!(found.len(), 2);
/// assert!(found[0].damped_frequency <= found[1].damped_frequency);
/// println!("first mode {:.1} Hz, {}", found[0].damped_frequency / std::f64::consts::TAU, found[0].whirl.label());
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn modes(rotor: &Rotor, speed: f64, options: &ModalOptions) -> Result<Vec<Mode>, ModalError> {
    if let Some(b) = rotor.nonlinear_bearings.first() {
        return Err(ModalError::NonlinearBearing(b.name.clone()));
    }
    if options.modes == 0 {
        return Err(ModalError::Options(
            "at least one mode must be requested".into(),
        ));
    }
    if !(speed.is_finite()
        && options.target_frequency.is_finite()
        && options.target_frequency >= 0.0)
    {
        return Err(ModalError::Options(format!(
            "speed {speed} and target frequency {} must be finite, target ≥ 0",
            options.target_frequency
        )));
    }
    let lin = |source| ModalError::Linalg { speed, source };
    let n = rotor.dof_count();
    let d = damping_at_speed(rotor, speed);

    // A shift on the imaginary axis finds the modes nearest the target; at zero a
    // singular K (free rotor) needs a small step off the origin along −Re.
    let mut sigma = C64::new(0.0, options.target_frequency);
    let factor = match dynamic_stiffness(rotor, &d, sigma).lu() {
        Ok(f) => f,
        Err(LinalgError::Singular { .. }) => {
            sigma -= 1e-3 * frequency_scale(rotor);
            dynamic_stiffness(rotor, &d, sigma).lu().map_err(lin)?
        }
        Err(e) => return Err(lin(e)),
    };
    let mass_c = map_to_complex(&rotor.mass);
    let mut d_sigma = map_to_complex(&d);
    d_sigma.scale_add(sigma, &mass_c);

    let mut rhs = vec![C64::new(0.0, 0.0); n];
    let mut tmp = vec![C64::new(0.0, 0.0); n];
    let mut apply = |z: &[C64], out: &mut [C64]| -> Result<(), LinalgError> {
        let (c, dd) = z.split_at(n);
        mass_c.mul_vec(dd, &mut rhs);
        d_sigma.mul_vec(c, &mut tmp);
        for (r, t) in rhs.iter_mut().zip(&tmp) {
            *r = -(*r + *t);
        }
        factor.solve_in_place(&mut rhs);
        let (a, b) = out.split_at_mut(n);
        a.copy_from_slice(&rhs);
        for ((bi, ci), ai) in b.iter_mut().zip(c).zip(rhs.iter()) {
            *bi = *ci + sigma * *ai;
        }
        Ok(())
    };
    // Oscillating modes come as conjugate pairs; non-oscillating eigenvalues
    // (rigid-body motion, overdamped modes) take slots too: widen until enough
    // oscillating ones are found or the whole spectrum is in hand.
    let scale = frequency_scale(rotor);
    let oscillating = |l: &C64| l.im > 1e-6 * l.norm() + 1e-9 * scale;
    // Ritz residuals of the shift-inverted operator to 1e-13 keep the residual of
    // the quadratic eigenproblem near 1e-10 even for modes far from the shift.
    let arnoldi = ArnoldiOptions {
        tol: 1e-13,
        ..ArnoldiOptions::default()
    };
    let mut nev = (2 * options.modes + 4).min(2 * n);
    let mut eigen = loop {
        let pairs = largest_eigenpairs(2 * n, nev, &mut apply, &arnoldi).map_err(lin)?;
        let found: Vec<(C64, Vec<C64>)> = pairs
            .into_iter()
            .map(|p| (sigma + C64::new(1.0, 0.0) / p.value, p.vector))
            .collect();
        let kept = found.iter().filter(|(l, _)| oscillating(l)).count();
        if kept >= options.modes || nev == 2 * n {
            break found;
        }
        let not_oscillating = found.len() - 2 * kept;
        nev = (nev + 2 * (options.modes - kept) + not_oscillating).min(2 * n);
    };
    eigen.retain(|(l, _)| oscillating(l));
    let mut out: Vec<Mode> = eigen
        .into_iter()
        .map(|(lambda, z)| make_mode(rotor, &d, speed, lambda, &z[..n]))
        .collect();
    out.sort_by(|a, b| a.damped_frequency.total_cmp(&b.damped_frequency));
    if options.target_frequency > 0.0 {
        let t = options.target_frequency;
        out.sort_by(|a, b| {
            (a.damped_frequency - t)
                .abs()
                .total_cmp(&(b.damped_frequency - t).abs())
        });
        out.truncate(options.modes);
        out.sort_by(|a, b| a.damped_frequency.total_cmp(&b.damped_frequency));
    } else {
        out.truncate(options.modes);
    }
    Ok(out)
}

/// `√(max K_ii / M_ii)`: the scale of the highest frequencies (rad/s).
fn frequency_scale(rotor: &Rotor) -> f64 {
    (0..rotor.dof_count())
        .map(|i| {
            rotor.stiffness.get(i, i).abs() / rotor.mass.get(i, i).abs().max(f64::MIN_POSITIVE)
        })
        .fold(0.0, f64::max)
        .sqrt()
}

fn make_mode(rotor: &Rotor, d: &BandMatrix<f64>, speed: f64, lambda: C64, x: &[C64]) -> Mode {
    // Residual ‖(λ²M + λD + K) x‖ / (‖Kx‖ + |λ|‖Dx‖ + |λ|²‖Mx‖).
    let n = x.len();
    let mut r = vec![C64::new(0.0, 0.0); n];
    let mut norms = [0.0; 3];
    for (k, (mat, coef)) in [
        (&rotor.stiffness, C64::new(1.0, 0.0)),
        (d, lambda),
        (&rotor.mass, lambda * lambda),
    ]
    .into_iter()
    .enumerate()
    {
        let mut t = vec![C64::new(0.0, 0.0); n];
        map_to_complex(mat).mul_vec(x, &mut t);
        norms[k] = coef.norm() * norm(&t);
        for (ri, ti) in r.iter_mut().zip(&t) {
            *ri += coef * ti;
        }
    }
    let residual = norm(&r) / norms.iter().sum::<f64>().max(f64::MIN_POSITIVE);

    let mut shape = rotor.dofs.expand(x);
    let peak = shape
        .iter()
        .enumerate()
        .filter(|(i, _)| i % DOF_PER_NODE < 2)
        .map(|(_, v)| *v)
        .max_by(|a, b| a.norm().total_cmp(&b.norm()))
        .unwrap_or(C64::new(1.0, 0.0));
    if peak.norm() > 0.0 {
        for v in &mut shape {
            *v /= peak;
        }
    }

    let natural_frequency = lambda.norm();
    let damped_frequency = lambda.im.abs();
    let damping_ratio = if natural_frequency > 0.0 {
        -lambda.re / natural_frequency
    } else {
        0.0
    };
    let log_decrement = if damped_frequency > 0.0 {
        -2.0 * std::f64::consts::PI * lambda.re / damped_frequency
    } else {
        f64::INFINITY
    };
    Mode {
        eigenvalue: lambda,
        natural_frequency,
        damped_frequency,
        damping_ratio,
        log_decrement,
        whirl: classify_whirl(&shape, speed),
        shape,
        residual,
    }
}

fn norm(v: &[C64]) -> f64 {
    v.iter().map(|c| c.norm_sqr()).sum::<f64>().sqrt()
}

/// Forward and backward orbit radii of one node, `(|X + iY|/2, |X − iY|/2)`:
/// `x + iy = ½[(X + iY) e^{iωt} + conj(X − iY) e^{−iωt}]`.
pub fn orbit_radii(x: C64, y: C64) -> (f64, f64) {
    let i = C64::new(0.0, 1.0);
    ((x + i * y).norm() / 2.0, (x - i * y).norm() / 2.0)
}

/// Whirl relative to the spin; without spin there is no direction to compare
/// with (and degenerate pairs are arbitrary combinations): `Mixed`.
fn classify_whirl(shape: &[C64], speed: f64) -> Whirl {
    if speed == 0.0 {
        return Whirl::Mixed;
    }
    let nodes = shape.len() / DOF_PER_NODE;
    let radii: Vec<(f64, f64)> = (0..nodes)
        .map(|k| {
            orbit_radii(
                shape[k * DOF_PER_NODE + DOF_X],
                shape[k * DOF_PER_NODE + DOF_Y],
            )
        })
        .collect();
    let peak = radii.iter().map(|(f, b)| f + b).fold(0.0, f64::max);
    let mut forward = 0;
    let mut backward = 0;
    let mut planar = 0;
    for (f, b) in radii {
        if f + b < 1e-3 * peak {
            continue;
        }
        if f > 1.01 * b {
            forward += 1;
        } else if b > 1.01 * f {
            backward += 1;
        } else {
            planar += 1;
        }
    }
    if speed < 0.0 {
        std::mem::swap(&mut forward, &mut backward);
    }
    match (forward, backward, planar) {
        (f, 0, 0) if f > 0 => Whirl::Forward,
        (0, b, 0) if b > 0 => Whirl::Backward,
        _ => Whirl::Mixed,
    }
}
