//! The solver parameters and the lateral machine's variables, in the order
//! of their value references since the first release: solver parameters,
//! viscosities, unbalance phases, the speed and unbalance inputs, bearing
//! and probe outputs, spin and friction, contact outputs, then (appended)
//! `solver.reduced_modes`, the seals and the housings on pedestals. (A
//! torque-driven shaft's `shaft.speed` is an output: [`super::drive`].)

use super::Causality::*;
use super::Kind::*;
use super::Variability::*;
use super::{
    Binding, DEFAULT_MAX_ITERATIONS, DEFAULT_TOLERANCE, OutputSpec, START_SPEED, Table,
    default_fmu_time_step,
};
use crate::model::{DEFAULT_REDUCED_MODES, Drive};

/// Append the machine's variables to `t`.
pub(super) fn add(t: &mut Table) {
    t.push(
        "solver.time_step".into(),
        "Largest internal Newmark time step: each fmi2DoStep is split into sub-steps no longer than this, sized by solver.local_error_tolerance (equal sub-steps when it is 0)".into(),
        Real,
        Parameter,
        Fixed,
        Some("s"),
        None,
        Some(default_fmu_time_step(t.model)),
        Binding::TimeStep,
    );
    t.push(
        "solver.tolerance".into(),
        "Relative tolerance of the Newton-Raphson iterations on residual and increment".into(),
        Real,
        Parameter,
        Fixed,
        Some("1"),
        None,
        Some(DEFAULT_TOLERANCE),
        Binding::Tolerance,
    );
    t.push(
        "solver.max_iterations".into(),
        "Newton-Raphson iterations per step attempt before the step is halved".into(),
        Integer,
        Parameter,
        Fixed,
        None,
        None,
        Some(DEFAULT_MAX_ITERATIONS),
        Binding::MaxIterations,
    );
    t.push(
        "unbalance_ramp_time".into(),
        "Time constant of the unbalance ramp-in 1 - exp(-t/tau); 0 applies the unbalance at once"
            .into(),
        Real,
        Parameter,
        Fixed,
        Some("s"),
        None,
        Some(0.0),
        Binding::RampTime,
    );
    t.push(
        "gravity".into(),
        "Apply the model's gravity vector".into(),
        Boolean,
        Parameter,
        Fixed,
        None,
        None,
        Some(1.0),
        Binding::Gravity,
    );
    for (k, b) in t.model.bearings.iter().enumerate() {
        let Some(mu) = b.kind.viscosity() else {
            continue;
        };
        t.push(
            format!("bearings.{}.viscosity", b.name),
            format!(
                "Oil dynamic viscosity of bearing {} (node {})",
                b.name,
                b.node + 1
            ),
            Real,
            Parameter,
            Tunable,
            Some("Pa.s"),
            None,
            Some(mu),
            Binding::Viscosity(k),
        );
    }
    for (k, u) in t.model.unbalances.iter().enumerate() {
        t.push(
            format!("unbalance.{}.phase", u.name),
            format!(
                "Angular position of unbalance plane {} (node {}) at spin angle 0, from +x toward +y",
                u.name,
                u.node + 1
            ),
            Real,
            Parameter,
            Tunable,
            Some("rad"),
            Some("deg"),
            Some(u.phase),
            Binding::UnbalancePhase(k),
        );
    }
    if t.model.drive == Drive::Torque {
        t.push(
            "shaft.speed".into(),
            "Mean spin speed of the torque-driven shaft about +z (polar-inertia weighted; its start is shaft.initial_speed)".into(),
            Real,
            Output,
            Continuous,
            Some("rad/s"),
            Some("rpm"),
            None,
            Binding::Speed,
        );
    } else {
        t.push(
            "shaft.speed".into(),
            "Spin speed of the shaft about +z (input; a first-order input derivative gives a ramp within a step)".into(),
            Real,
            Input,
            Continuous,
            Some("rad/s"),
            Some("rpm"),
            Some(START_SPEED),
            Binding::Speed,
        );
    }
    for (k, u) in t.model.unbalances.iter().enumerate() {
        t.push(
            format!("unbalance.{}", u.name),
            format!("Unbalance m*e of plane {} (node {})", u.name, u.node + 1),
            Real,
            Input,
            Continuous,
            Some("kg.m"),
            None,
            Some(u.magnitude),
            Binding::Unbalance(k),
        );
    }
    for (k, b) in t.model.bearings.iter().enumerate() {
        if !b.kind.is_bearing() {
            continue;
        }
        let node = b.node + 1;
        let n = &b.name;
        let outputs: [OutputSpec; 6] = [
            (
                "x",
                format!("Journal displacement x at bearing {n} (node {node})"),
                Some("m"),
                Some("um"),
                Binding::BearingX(k),
            ),
            (
                "y",
                format!("Journal displacement y at bearing {n} (node {node})"),
                Some("m"),
                Some("um"),
                Binding::BearingY(k),
            ),
            (
                "fx",
                format!("Force x of bearing {n} on the journal"),
                Some("N"),
                None,
                Binding::BearingFx(k),
            ),
            (
                "fy",
                format!("Force y of bearing {n} on the journal"),
                Some("N"),
                None,
                Binding::BearingFy(k),
            ),
            (
                "eccentricity",
                if matches!(
                    b.kind.short_film().as_ref(),
                    crate::bearing::BearingKind::TiltingPad(_)
                ) {
                    format!(
                        "Eccentricity ratio e/C_b of bearing {n}: journal offset over the assembled clearance C_b = C (1 - preload), above 1 on the pads with preload"
                    )
                } else {
                    format!("Eccentricity ratio e/C of bearing {n} (0 for linear bearings)")
                },
                Some("1"),
                None,
                Binding::BearingEccentricity(k),
            ),
            (
                "friction_torque",
                format!(
                    "Friction torque of bearing {n} on the journal, opposing the spin: film shear plus contact friction mu*N*R (at standstill the breakaway torque)"
                ),
                Some("N.m"),
                None,
                Binding::BearingFriction(k),
            ),
        ];
        t.outputs("bearings", n, outputs);
    }
    for (k, p) in t.model.probes.iter().enumerate() {
        let node = p.node + 1;
        let from = p.relative_to.map_or(String::new(), |b| {
            format!(
                ", from the installed centre of bearing {}",
                t.model.bearings[b].name
            )
        });
        t.push(
            format!("probes.{}.x", p.name),
            format!("Displacement x at probe {} (node {node}{from})", p.name),
            Real,
            Output,
            Continuous,
            Some("m"),
            Some("um"),
            None,
            Binding::ProbeX(k),
        );
        t.push(
            format!("probes.{}.y", p.name),
            format!("Displacement y at probe {} (node {node}{from})", p.name),
            Real,
            Output,
            Continuous,
            Some("m"),
            Some("um"),
            None,
            Binding::ProbeY(k),
        );
    }
    t.push(
        "shaft.spin_angle".into(),
        "Spin angle of the shaft (integral of the speed)".into(),
        Real,
        Output,
        Continuous,
        Some("rad"),
        Some("deg"),
        None,
        Binding::SpinAngle,
    );
    t.push(
        "friction_torque".into(),
        "Sum of the bearings' friction torques on the shaft (for a generator torque balance)"
            .into(),
        Real,
        Output,
        Continuous,
        Some("N.m"),
        None,
        None,
        Binding::FrictionTorque,
    );
    // Contact outputs come last, so the value references above stay as they were.
    for (k, b) in t.model.bearings.iter().enumerate() {
        let n = &b.name;
        if b.kind.is_seal() || b.kind.is_magnetic_pull() {
            continue;
        }
        if b.kind.is_rub() {
            t.push(
                format!("rubs.{n}.contact_force"),
                format!(
                    "Normal force of rub {n} (node {}) on the rotor (0 while clear of the stator)",
                    b.node + 1
                ),
                Real,
                Output,
                Continuous,
                Some("N"),
                None,
                None,
                Binding::BearingContact(k),
            );
            t.push(
                format!("rubs.{n}.friction_torque"),
                format!("Friction torque mu*N*R of rub {n} on the rotor, opposing the spin"),
                Real,
                Output,
                Continuous,
                Some("N.m"),
                None,
                None,
                Binding::BearingFriction(k),
            );
            continue;
        }
        t.push(
            format!("bearings.{n}.contact_force"),
            format!(
                "Normal force of the metal-to-metal contact of the journal in bearing {n} (0 while it floats on its film)"
            ),
            Real,
            Output,
            Continuous,
            Some("N"),
            None,
            None,
            Binding::BearingContact(k),
        );
        t.push(
            format!("bearings.{n}.min_film_thickness"),
            format!(
                "Minimum oil-film thickness of bearing {n} (0 in contact and for linear bearings)"
            ),
            Real,
            Output,
            Continuous,
            Some("m"),
            Some("um"),
            None,
            Binding::BearingMinFilm(k),
        );
    }
    // Appended after the contact outputs, so earlier value references stay.
    t.push(
        "solver.reduced_modes".into(),
        "Fixed-interface modes of the Craig-Bampton reduced rotor the transient runs on (nonlinear bearings, rubs, probes and unbalance planes kept physical); 0 runs the full rotor".into(),
        Integer,
        Parameter,
        Fixed,
        None,
        None,
        Some(crate::rotor::Rotor::transient_modes(t.model).unwrap_or(DEFAULT_REDUCED_MODES) as f64),
        Binding::ReducedModes,
    );
    // Appended after solver.reduced_modes: seals, then the housings of the
    // bearings, rubs and seals that stand on pedestals (none in a model
    // without them, so earlier value references stay).
    for (k, b) in t.model.bearings.iter().enumerate() {
        if !b.kind.is_seal() {
            continue;
        }
        let (n, node) = (&b.name, b.node + 1);
        let outputs: [OutputSpec; 3] = [
            (
                "fx",
                format!("Force x of seal {n} (node {node}) on the rotor"),
                Some("N"),
                None,
                Binding::BearingFx(k),
            ),
            (
                "fy",
                format!("Force y of seal {n} (node {node}) on the rotor"),
                Some("N"),
                None,
                Binding::BearingFy(k),
            ),
            (
                "contact_force",
                format!(
                    "Normal force of seal {n} touching its stator (0 while clear or without a clearance)"
                ),
                Some("N"),
                None,
                Binding::BearingContact(k),
            ),
        ];
        t.outputs("seals", n, outputs);
    }
    for (k, b) in t.model.bearings.iter().enumerate() {
        let Some(p) = b.pedestal else { continue };
        let group = if b.kind.is_rub() {
            "rubs"
        } else if b.kind.is_seal() {
            "seals"
        } else {
            "bearings"
        };
        let (n, pedestal) = (&b.name, &t.model.pedestals[p].name);
        let outputs: [OutputSpec; 6] = [
            (
                "x_rel",
                format!(
                    "Journal displacement x relative to the housing of {n} (what a proximity probe on the bearing measures)"
                ),
                Some("m"),
                Some("um"),
                Binding::BearingRelativeX(k),
            ),
            (
                "y_rel",
                format!("Journal displacement y relative to the housing of {n}"),
                Some("m"),
                Some("um"),
                Binding::BearingRelativeY(k),
            ),
            (
                "housing_x",
                format!("Absolute displacement x of the housing of {n} (pedestal {pedestal})"),
                Some("m"),
                Some("um"),
                Binding::HousingX(k),
            ),
            (
                "housing_y",
                format!("Absolute displacement y of the housing of {n} (pedestal {pedestal})"),
                Some("m"),
                Some("um"),
                Binding::HousingY(k),
            ),
            (
                "housing_vx",
                format!(
                    "Absolute velocity x of the housing of {n} (what a seismic sensor on pedestal {pedestal} measures)"
                ),
                Some("m/s"),
                Some("mm/s"),
                Binding::HousingVx(k),
            ),
            (
                "housing_vy",
                format!("Absolute velocity y of the housing of {n} (pedestal {pedestal})"),
                Some("m/s"),
                Some("mm/s"),
                Binding::HousingVy(k),
            ),
        ];
        t.outputs(group, n, outputs);
    }
}
