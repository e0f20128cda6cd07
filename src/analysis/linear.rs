//! Linear static and steady-state analyses with linear bearings.

use nalgebra::Complex;

use crate::fe::{DOF_PER_NODE, DOF_X, DOF_Y};
use crate::linalg::{LinalgError, map_to_complex};
use crate::rotor::Rotor;

use super::modal::damping_at_speed;

/// Linear analysis failure.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum LinearError {
    /// The model has nonlinear bearings.
    #[error("bearing {0} is nonlinear; this linear analysis needs linear bearings only")]
    NonlinearBearing(String),
    /// Singular system, e.g. a rotor with no bearing or support in some direction.
    #[error("{what}: {source} (is the rotor supported in x, y and against tilting?)")]
    Linalg {
        what: &'static str,
        source: LinalgError,
    },
}

fn linear_only(rotor: &Rotor) -> Result<(), LinearError> {
    match rotor.nonlinear_bearings.first() {
        Some(b) => Err(LinearError::NonlinearBearing(b.name.clone())),
        None => Ok(()),
    }
}

/// Static deflection under gravity and the model's static and port forces
/// (at their start values, as the nonlinear statics take them),
/// `K q = f_g + f_s`, on all DOFs (`4·node + k`).
pub fn static_deflection(rotor: &Rotor) -> Result<Vec<f64>, LinearError> {
    linear_only(rotor)?;
    let what = "static deflection";
    let lu = rotor
        .stiffness
        .lu()
        .map_err(|source| LinearError::Linalg { what, source })?;
    let mut q = rotor.gravity_load.clone();
    let loads: Vec<f64> = rotor.model.load_inputs().iter().map(|l| l.start).collect();
    rotor.add_static_loads(&loads, &mut q);
    lu.solve_in_place(&mut q);
    Ok(rotor.dofs.expand(&q))
}

/// Steady synchronous unbalance response at spin speed `Ω`:
/// `(K − Ω² M + iΩ (C + Ω G)) X = Ω² F_u`, with `q(t) = Re(X e^{iΩt})`.
/// Returned on all DOFs (`4·node + k`).
pub fn unbalance_response(rotor: &Rotor, speed: f64) -> Result<Vec<Complex<f64>>, LinearError> {
    linear_only(rotor)?;
    let what = "unbalance response";
    let lin = |source| LinearError::Linalg { what, source };
    let d = damping_at_speed(rotor, speed);
    let mut z = map_to_complex(&rotor.stiffness);
    z.scale_add(
        Complex::new(-speed * speed, 0.0),
        &map_to_complex(&rotor.mass),
    );
    z.scale_add(Complex::new(0.0, speed), &map_to_complex(&d));
    let lu = z.lu().map_err(lin)?;
    let mut x: Vec<Complex<f64>> = rotor
        .unbalance_load()
        .into_iter()
        .map(|f| f * speed * speed)
        .collect();
    lu.solve_in_place(&mut x);
    Ok(rotor.dofs.expand(&x))
}

/// `(x, y)` of `node` from a vector on all DOFs.
pub fn node_xy<T: Copy>(all: &[T], node: usize) -> (T, T) {
    (
        all[node * DOF_PER_NODE + DOF_X],
        all[node * DOF_PER_NODE + DOF_Y],
    )
}
