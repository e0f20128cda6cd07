//! The variables of the loads, appended after the housings: each magnetic
//! pull's field excitation (a tunable parameter), the force inputs (static
//! components and harmonic amplitudes of `[[forces]]`, the two components of
//! each `[[ports]]` force), then the ports' motion and the pulls' forces.
//! A model without pulls, forces or ports adds nothing here.

use super::Causality::*;
use super::Kind::*;
use super::Variability::*;
use super::{Binding, OutputSpec, Table};
use crate::model::ForceKind;

/// Append the harmonic forces' frequencies to `t` (after every other
/// variable, so that no earlier value reference moves): tunable parameters
/// `forces.<f>.ratio` (to the running speed) or `forces.<f>.frequency` (Hz),
/// the model file's values at start. A change takes effect from the next
/// step, the force's angle going on without a jump
/// ([`Simulator::set_force_frequency`](crate::solver::Simulator::set_force_frequency)).
pub(super) fn add_frequencies(t: &mut Table) {
    let model = t.model;
    for (h, (force, _, frequency)) in model.harmonic_forces().enumerate() {
        let (n, node) = (&model.forces[force].name, model.forces[force].node + 1);
        let (name, description, unit, start) = if super::force_has_ratio(model, force) {
            (
                format!("forces.{n}.ratio"),
                format!(
                    "Frequency of the harmonic force {n} (node {node}) as a multiple of the running speed (e.g. 0.3 a vortex rope): its angle goes on from where it is at the change"
                ),
                Some("1"),
                frequency,
            )
        } else {
            (
                format!("forces.{n}.frequency"),
                format!(
                    "Fixed frequency of the harmonic force {n} (node {node}): its angle goes on from where it is at the change"
                ),
                Some("Hz"),
                frequency / std::f64::consts::TAU,
            )
        };
        t.push(
            name,
            description,
            Real,
            Parameter,
            Tunable,
            unit,
            None,
            Some(start),
            Binding::ForceFrequency(h),
        );
    }
}

/// Append the loads' variables to `t`.
pub(super) fn add(t: &mut Table) {
    let model = t.model;
    for (k, b) in model.bearings.iter().enumerate() {
        let Some(excitation) = b.kind.excitation() else {
            continue;
        };
        t.push(
            format!("magnetic_pull.{}.excitation", b.name),
            format!(
                "Field excitation of the magnetic pull {} (node {}): 0 field off, 1 nominal; the pull stiffness goes with its square",
                b.name,
                b.node + 1
            ),
            Real,
            Parameter,
            Tunable,
            Some("1"),
            None,
            Some(excitation),
            Binding::Excitation(k),
        );
    }
    // The channels in the order of RotorModel::load_inputs: forces, then ports.
    let mut channel = 0;
    let mut input = |t: &mut Table, name: String, description: String, start: f64| {
        t.push(
            name,
            description,
            Real,
            Input,
            Continuous,
            Some("N"),
            None,
            Some(start),
            Binding::Load(channel),
        );
        channel += 1;
    };
    for f in &model.forces {
        let (n, node) = (&f.name, f.node + 1);
        match f.kind {
            ForceKind::Static([fx, fy]) => {
                for (axis, start) in [("x", fx), ("y", fy)] {
                    input(
                        t,
                        format!("forces.{n}.f{axis}"),
                        format!("Static force {axis} of {n} on the rotor at node {node}"),
                        start,
                    );
                }
            }
            ForceKind::Harmonic { magnitude, .. } => input(
                t,
                format!("forces.{n}.magnitude"),
                format!(
                    "Amplitude of the rotating harmonic force {n} on the rotor at node {node} (its frequency and phase from the model file)"
                ),
                magnitude,
            ),
        }
    }
    for p in &model.ports {
        let (n, node) = (&p.name, p.node + 1);
        for axis in ["x", "y"] {
            input(
                t,
                format!("ports.{n}.f{axis}"),
                format!(
                    "Force {axis} another model applies to the rotor at port {n} (node {node}), held over the step or ramped by its input derivative"
                ),
                0.0,
            );
        }
    }
    for (k, p) in model.ports.iter().enumerate() {
        let (n, node) = (&p.name, p.node + 1);
        let specs: Vec<OutputSpec> = vec![
            (
                "x",
                format!("Displacement x of the rotor at port {n} (node {node})"),
                Some("m"),
                Some("um"),
                Binding::PortX(k),
            ),
            (
                "y",
                format!("Displacement y of the rotor at port {n} (node {node})"),
                Some("m"),
                Some("um"),
                Binding::PortY(k),
            ),
            (
                "vx",
                format!("Velocity x of the rotor at port {n} (node {node})"),
                Some("m/s"),
                None,
                Binding::PortVx(k),
            ),
            (
                "vy",
                format!("Velocity y of the rotor at port {n} (node {node})"),
                Some("m/s"),
                None,
                Binding::PortVy(k),
            ),
        ];
        t.outputs("ports", n, specs);
    }
    for (k, b) in model.bearings.iter().enumerate() {
        if !b.kind.is_magnetic_pull() {
            continue;
        }
        let (n, node) = (&b.name, b.node + 1);
        let specs: Vec<OutputSpec> = vec![
            (
                "fx",
                format!("Force x of the magnetic pull {n} (node {node}) on the rotor"),
                Some("N"),
                None,
                Binding::BearingFx(k),
            ),
            (
                "fy",
                format!("Force y of the magnetic pull {n} (node {node}) on the rotor"),
                Some("N"),
                None,
                Binding::BearingFy(k),
            ),
            (
                "contact_force",
                format!(
                    "Normal force of the rotor touching the stator across the air gap of {n} (0 while clear)"
                ),
                Some("N"),
                None,
                Binding::BearingContact(k),
            ),
        ];
        t.outputs("magnetic_pull", n, specs);
    }
}
