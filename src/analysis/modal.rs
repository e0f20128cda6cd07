//! Complex modal analysis of the gyroscopic rotor, `(λ² M + λ (C + Ω G) + K) x = 0`,
//! by shift-invert Arnoldi on the first-order form.
//!
//! With `z = [x; λx]`, `A = [[0, I], [−K, −D]]`, `B = diag(I, M)` and a shift `σ`,
//! the operator `(A − σB)⁻¹ B` applied to `[c; d]` is `[a; c + σ a]` with
//! `(K + σD + σ²M) a = −M d − (D + σM) c`: one banded solve of size `n` per
//! Krylov step, so the few wanted modes cost O(n) work and memory even for
//! thousands of elements. Eigenvalues follow from `λ = σ + 1/μ`.
//!
//! Per speed the pencil is factored once and every Krylov step reuses that
//! factor. For the lowest modes the shift is real (0, or a small step along
//! −Re for a free rotor), so the operator is real: the Arnoldi process then
//! runs in real arithmetic ([`largest_eigenpairs_real`]) with a real banded
//! LU, and each conjugate pair `μ, μ̄` is found once (the member with
//! `Im μ ≥ 0`, i.e. `Im λ ≤ 0`, conjugated to the mode with `Im λ > 0`). The
//! Krylov dimension does not depend on the model size (the lowest modes of a
//! refined mesh converge to those of the continuum), so the work per speed is
//! O(n). A target frequency needs a complex shift and the complex process.

use nalgebra::Complex;

use crate::fe::{DOF_PER_NODE, DOF_X, DOF_Y};
use crate::linalg::{
    ArnoldiOptions, BandLu, BandMatrix, EigenPair, LinalgError, Scalar, largest_eigenpairs,
    largest_eigenpairs_real, map_to_complex,
};
use crate::rotor::Rotor;

use super::linearize::linearized;
use super::polish::Polisher;

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

/// Damping ratio from which an eigenvalue is a non-oscillating (overdamped)
/// root, not a mode: `|Im λ| ≤ √(1 − 0.999²) |λ| ≈ 0.045 |λ|`, a log
/// decrement above 140 (the amplitude falls by e¹⁴⁰ within one period).
/// Such roots (journal and pad-tilt film roots on tilting pads,
/// `λ ≈ −K/C`) are reported apart ([`ModalResult::overdamped`]), never
/// counted among the requested modes and never given a whirl direction.
pub const NON_OSCILLATING_DAMPING_RATIO: f64 = 0.999;

/// Damping ratios smaller than this are the eigen-solver's round-off, not
/// damping: it resolves ζ to about 1e-11 (`tests/modal_reference.rs`), and an
/// undamped rotor's modes come out with |ζ| of 1e-24 … 1e-13. Tables print
/// them as 0; an amplification factor `1/(2ζ)` is then unbounded.
pub const ROUND_OFF_DAMPING_RATIO: f64 = 1e-9;

impl Mode {
    /// Whether the mode has no damping beyond round-off
    /// ([`ROUND_OFF_DAMPING_RATIO`]).
    pub fn is_undamped(&self) -> bool {
        self.damping_ratio.abs() < ROUND_OFF_DAMPING_RATIO
    }
}

/// A non-oscillating root of the linearized rotor: `x(t) ∝ e^{λt}` decays
/// (or grows, `Re λ > 0`) without completing an oscillation.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct OverdampedRoot {
    /// Eigenvalue `λ` (1/s); `|Im λ| ≤ 0.045 |λ|`.
    pub eigenvalue: C64,
}

impl OverdampedRoot {
    /// Decay rate `−Re λ` (1/s); negative for a growing root.
    pub fn decay_rate(&self) -> f64 {
        -self.eigenvalue.re
    }

    /// Whether the root grows (`Re λ > 0`): a static divergence, the rotor
    /// linearized about an equilibrium its supports cannot hold (a magnetic
    /// pull stiffer than the unloaded films, a negative-stiffness seal).
    pub fn is_growing(&self) -> bool {
        self.eigenvalue.re > 0.0
    }

    /// Time constant `1/|Re λ|` (s).
    pub fn time_constant(&self) -> f64 {
        1.0 / self.eigenvalue.re.abs()
    }
}

/// The modes of one modal analysis and the non-oscillating roots found with
/// them.
#[derive(Debug, Clone, PartialEq)]
pub struct ModalResult {
    /// The requested number of oscillating modes, by increasing damped
    /// frequency (fewer only when the rotor has no more).
    pub modes: Vec<Mode>,
    /// The non-oscillating roots (ζ ≥ [`NON_OSCILLATING_DAMPING_RATIO`]) no
    /// farther from the shift than the last listed mode, by increasing `|λ|`;
    /// rigid-body roots (`λ = 0` of a free rotor) excluded.
    pub overdamped: Vec<OverdampedRoot>,
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
    /// The modes with the pads at their own frequency could not be found
    /// (`whirl_modes`).
    #[error("{0}")]
    OwnFrequency(String),
}

/// Modes at `speed` of a rotor whose nonlinear bearings are first linearized about
/// the static equilibrium at that speed (synchronous coefficients); linear rotors
/// go straight to [`modes`].
pub fn modes_at(
    rotor: &Rotor,
    speed: f64,
    options: &ModalOptions,
) -> Result<Vec<Mode>, ModalError> {
    Ok(modal_analysis_at(rotor, speed, options)?.modes)
}

/// [`modal_analysis`] of a rotor whose nonlinear bearings are first
/// linearized about the static equilibrium at `speed` (as [`modes_at`]).
pub fn modal_analysis_at(
    rotor: &Rotor,
    speed: f64,
    options: &ModalOptions,
) -> Result<ModalResult, ModalError> {
    if rotor.nonlinear_bearings.is_empty() {
        return modal_analysis(rotor, speed, options);
    }
    let linear = linearized(rotor, speed, speed)?;
    modal_analysis(&linear, speed, options)
}

/// `D = C + Ω G` as a band matrix.
pub(crate) fn damping_at_speed(rotor: &Rotor, speed: f64) -> BandMatrix<f64> {
    let mut d = rotor.damping.clone();
    d.scale_add(speed, &rotor.gyroscopic);
    d
}

/// Ritz residuals of the shift-inverted operator to 1e-13 keep the residual of
/// the quadratic eigenproblem near 1e-10 even for modes far from the shift.
const ARNOLDI_TOL: f64 = 1e-13;

/// An eigenvalue `λ` with its first-order vector `[x; λx]`.
type Eigenpair = (C64, Vec<C64>);

/// One application of the shift-inverted first-order operator to `z = [c; d]`
/// (either field): `a = −(K + σD + σ²M)⁻¹ ((D + σM) c + M d)`, `out = [a; c + σa]`.
#[allow(clippy::too_many_arguments)]
fn shift_invert_apply<T: Scalar>(
    sigma: T,
    factor: &BandLu<T>,
    mass: &BandMatrix<T>,
    d_sigma: &BandMatrix<T>,
    z: &[T],
    out: &mut [T],
    rhs: &mut [T],
    tmp: &mut [T],
) {
    let n = mass.n();
    let (c, dd) = z.split_at(n);
    mass.mul_vec(dd, rhs);
    d_sigma.mul_vec(c, tmp);
    for (r, t) in rhs.iter_mut().zip(tmp.iter()) {
        *r = -(*r + *t);
    }
    factor.solve_in_place(rhs);
    let (a, b) = out.split_at_mut(n);
    a.copy_from_slice(rhs);
    for ((bi, ci), ai) in b.iter_mut().zip(c).zip(rhs.iter()) {
        *bi = *ci + sigma * *ai;
    }
}

/// The shift-inverted first-order operator of one speed: `K + σD + σ²M`
/// factored once, with `M` and `D + σM` for the right-hand sides.
enum ShiftInvert {
    /// Real shift: real band matrices and a real Krylov basis.
    Real {
        sigma: f64,
        factor: BandLu<f64>,
        mass: BandMatrix<f64>,
        d_sigma: BandMatrix<f64>,
    },
    /// Complex shift (a target frequency).
    Complex {
        sigma: C64,
        factor: BandLu<C64>,
        mass: BandMatrix<C64>,
        d_sigma: BandMatrix<C64>,
    },
}

impl ShiftInvert {
    fn real(rotor: &Rotor, d: &BandMatrix<f64>, sigma: f64) -> Result<Self, LinalgError> {
        let mut q = rotor.stiffness.clone();
        q.scale_add(sigma, d);
        q.scale_add(sigma * sigma, &rotor.mass);
        let mut d_sigma = d.clone();
        d_sigma.scale_add(sigma, &rotor.mass);
        Ok(Self::Real {
            sigma,
            factor: q.lu()?,
            mass: rotor.mass.clone(),
            d_sigma,
        })
    }

    fn complex(rotor: &Rotor, d: &BandMatrix<f64>, sigma: C64) -> Result<Self, LinalgError> {
        let mut q = map_to_complex(&rotor.stiffness);
        q.scale_add(sigma, &map_to_complex(d));
        q.scale_add(sigma * sigma, &map_to_complex(&rotor.mass));
        let mass = map_to_complex(&rotor.mass);
        let mut d_sigma = map_to_complex(d);
        d_sigma.scale_add(sigma, &mass);
        Ok(Self::Complex {
            sigma,
            factor: q.lu()?,
            mass,
            d_sigma,
        })
    }

    /// The `nev` eigenvalues `λ = σ + 1/μ` nearest the shift, with their
    /// first-order vectors `[x; λx]`, and how many of a conjugate pair the list
    /// holds (1 on the real path: the member with `Im λ ≥ 0`).
    fn eigenpairs(&mut self, nev: usize) -> Result<(Vec<Eigenpair>, usize), LinalgError> {
        let arnoldi = ArnoldiOptions {
            tol: ARNOLDI_TOL,
            ..ArnoldiOptions::default()
        };
        match self {
            Self::Real {
                sigma,
                factor,
                mass,
                d_sigma,
            } => {
                let (sigma, n) = (*sigma, mass.n());
                let mut rhs = vec![0.0; n];
                let mut tmp = vec![0.0; n];
                let mut apply = |z: &[f64], out: &mut [f64]| -> Result<(), LinalgError> {
                    shift_invert_apply(sigma, factor, mass, d_sigma, z, out, &mut rhs, &mut tmp);
                    Ok(())
                };
                let pairs = largest_eigenpairs_real(2 * n, nev, &mut apply, &arnoldi)?;
                let conjugated = |p: EigenPair| {
                    let lambda = sigma + C64::new(1.0, 0.0) / p.value;
                    let vector = p.vector.iter().map(|z| z.conj()).collect();
                    (lambda.conj(), vector)
                };
                Ok((pairs.into_iter().map(conjugated).collect(), 1))
            }
            Self::Complex {
                sigma,
                factor,
                mass,
                d_sigma,
            } => {
                let (sigma, n) = (*sigma, mass.n());
                let mut rhs = vec![C64::new(0.0, 0.0); n];
                let mut tmp = vec![C64::new(0.0, 0.0); n];
                let mut apply = |z: &[C64], out: &mut [C64]| -> Result<(), LinalgError> {
                    shift_invert_apply(sigma, factor, mass, d_sigma, z, out, &mut rhs, &mut tmp);
                    Ok(())
                };
                let pairs = largest_eigenpairs(2 * n, nev, &mut apply, &arnoldi)?;
                let shifted = |p: EigenPair| (sigma + C64::new(1.0, 0.0) / p.value, p.vector);
                Ok((pairs.into_iter().map(shifted).collect(), 2))
            }
        }
    }
}

/// The mode of a linear `rotor` at `speed` (rad/s) that nonlinear inverse
/// iteration on the quadratic problem reaches from `guess` (`Im > 0`) and
/// `seed` (free DOFs; a neighbouring speed's mode), with its vector `x`
/// ([`Polisher::followed`]: one to three complex factorizations from a
/// neighbouring speed of the 480-element benchmark rotor); `None` when the
/// iteration does not converge.
pub(crate) fn mode_near(
    rotor: &Rotor,
    speed: f64,
    guess: C64,
    seed: &[C64],
) -> Option<(Mode, Vec<C64>)> {
    let d = damping_at_speed(rotor, speed);
    let (lambda, x) = Polisher::new(rotor, &d).followed(guess, seed)?;
    Some((make_mode(rotor, &d, speed, lambda, &x), x))
}

/// The mode of a linear `rotor` at `speed` (rad/s) with eigenvalue `lambda`
/// and vector `x` (free DOFs) found elsewhere (e.g. with the pad
/// coordinates, [`super::pad_eigen`]): its shape, whirl and residual here.
pub(crate) fn mode_from_pair(rotor: &Rotor, speed: f64, lambda: C64, x: &[C64]) -> Mode {
    make_mode(rotor, &damping_at_speed(rotor, speed), speed, lambda, x)
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
    Ok(modal_analysis(rotor, speed, options)?.modes)
}

/// The lowest (or nearest-target) `options.modes` oscillating modes of a
/// linear rotor at `speed` (rad/s), as [`modes`], and the non-oscillating
/// roots found with them (see [`ModalResult`]).
pub fn modal_analysis(
    rotor: &Rotor,
    speed: f64,
    options: &ModalOptions,
) -> Result<ModalResult, ModalError> {
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
    let scale = frequency_scale(rotor);
    let step = 1e-3 * scale;
    let mut solver = if options.target_frequency == 0.0 {
        match ShiftInvert::real(rotor, &d, 0.0) {
            Err(LinalgError::Singular { .. }) => ShiftInvert::real(rotor, &d, -step),
            other => other,
        }
    } else {
        let sigma = C64::new(0.0, options.target_frequency);
        match ShiftInvert::complex(rotor, &d, sigma) {
            Err(LinalgError::Singular { .. }) => ShiftInvert::complex(rotor, &d, sigma - step),
            other => other,
        }
    }
    .map_err(lin)?;
    // Oscillating modes come as conjugate pairs; non-oscillating eigenvalues
    // (rigid-body motion, overdamped roots) take slots too: widen until enough
    // oscillating ones are found or the whole spectrum is in hand.
    let real_part = (1.0 - NON_OSCILLATING_DAMPING_RATIO.powi(2)).sqrt();
    let oscillating = |l: &C64| l.im > real_part * l.norm() + 1e-9 * scale;
    let mut nev = (2 * options.modes + 4).min(2 * n);
    let mut eigen = loop {
        let (found, per_pair) = solver.eigenpairs(nev).map_err(lin)?;
        let kept = found.iter().filter(|(l, _)| oscillating(l)).count();
        if kept >= options.modes || nev == 2 * n {
            break found;
        }
        let not_oscillating = found.len() - per_pair * kept;
        nev = (nev + 2 * (options.modes - kept) + not_oscillating).min(2 * n);
    };
    // Non-oscillating roots: one of each conjugate pair (Im λ ≥ 0, or real to
    // round-off), not the rigid-body roots λ = 0 of a free rotor.
    let mut overdamped: Vec<OverdampedRoot> = eigen
        .iter()
        .map(|(l, _)| *l)
        .filter(|l| {
            !oscillating(l)
                && l.im.abs() <= real_part * l.norm() + 1e-9 * scale
                && (l.im >= 0.0 || l.im.abs() <= 1e-9 * scale)
                && l.norm() > 1e-9 * scale
        })
        .map(|eigenvalue| OverdampedRoot { eigenvalue })
        .collect();
    eigen.retain(|(l, _)| oscillating(l));
    // Only the modes that can be listed are polished: those ranked within
    // `options.modes` by the Arnoldi values, or close enough to the last of
    // them (1e-6 relative, fifty times the largest change polishing makes)
    // that polishing could move them into the list.
    let t = options.target_frequency;
    let key = |l: &C64| {
        if t > 0.0 {
            (l.im.abs() - t).abs()
        } else {
            l.im.abs()
        }
    };
    eigen.sort_by(|a, b| key(&a.0).total_cmp(&key(&b.0)));
    if let Some((cut, _)) = eigen.get(options.modes - 1) {
        let (cut_key, cut_norm) = (key(cut), cut.norm());
        eigen.retain(|(l, _)| key(l) <= cut_key + 1e-6 * (l.norm() + cut_norm));
    }
    let mut polish = Polisher::new(rotor, &d);
    let mut out: Vec<Mode> = eigen
        .into_iter()
        .map(|(lambda, z)| {
            let lambda = polish.polished(lambda, &z[..n]);
            make_mode(rotor, &d, speed, lambda, &z[..n])
        })
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
    // Only the roots no farther from the shift than the last listed mode:
    // the Krylov process found every eigenvalue that near, none beyond.
    let distance = |l: C64| {
        if t > 0.0 {
            (l - C64::new(0.0, t)).norm()
        } else {
            l.norm()
        }
    };
    if out.len() == options.modes {
        let reach = out
            .iter()
            .map(|m| distance(m.eigenvalue))
            .fold(0.0, f64::max);
        overdamped.retain(|r| distance(r.eigenvalue) <= reach);
    }
    overdamped.sort_by(|a, b| a.eigenvalue.norm().total_cmp(&b.eigenvalue.norm()));
    Ok(ModalResult {
        modes: out,
        overdamped,
    })
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
    let mut t = vec![C64::new(0.0, 0.0); n];
    let (xr, xi): (Vec<f64>, Vec<f64>) = x.iter().map(|z| (z.re, z.im)).unzip();
    let (mut yr, mut yi) = (vec![0.0; n], vec![0.0; n]);
    let mut norms = [0.0; 3];
    for (k, (mat, coef)) in [
        (&rotor.stiffness, C64::new(1.0, 0.0)),
        (d, lambda),
        (&rotor.mass, lambda * lambda),
    ]
    .into_iter()
    .enumerate()
    {
        mat.mul_vec(&xr, &mut yr);
        mat.mul_vec(&xi, &mut yi);
        for ((tk, &a), &b) in t.iter_mut().zip(&yr).zip(&yi) {
            *tk = C64::new(a, b);
        }
        norms[k] = coef.norm() * norm(&t);
        for (ri, ti) in r.iter_mut().zip(&t) {
            *ri += coef * ti;
        }
    }
    let residual = norm(&r) / norms.iter().sum::<f64>().max(f64::MIN_POSITIVE);

    let mut shape = rotor.dofs.expand(x);
    let nodes = rotor.dofs.node_count();
    let peak = shape
        .iter()
        .enumerate()
        .filter(|(i, _)| *i < nodes * DOF_PER_NODE && i % DOF_PER_NODE < 2)
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
        whirl: classify_whirl(&shape[..nodes * DOF_PER_NODE], speed),
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

/// Whirl relative to the spin of the rotor nodes' DOFs `shape`; without spin
/// there is no direction to compare with (and degenerate pairs are arbitrary
/// combinations): `Mixed`.
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
