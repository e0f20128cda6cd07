//! What `rotor info` prints: one line for every element of the model file,
//! each starting with what it is (`material`, `shaft section`, `disk`,
//! `bearing`, `seal`, `magnetic pull`, `force`, `port`, `coupling`, …) and
//! its name, in engineering units.

use std::fmt::Write;

use super::{coefficient_matrix, describe_bearing, short};
use crate::model::{
    CouplingJoint, Drive, ForceKind, HarmonicDirection, HarmonicFrequency, ReductionRequest,
    RotorModel,
};
use crate::rotor::Rotor;
use crate::rotor::torsion::TorsionalRotor;
use crate::units::RAD_S_TO_RPM;

/// What `rotor info` prints: sizes and node positions, then every element
/// of the model — materials, shaft sections, disks, point masses, bearings,
/// rubs, seals, magnetic pulls, pedestals, supports, unbalances, forces,
/// ports, probes, the drive, torques, couplings, thrust bearings, the
/// reduction — and gravity.
pub fn model_summary(rotor: &Rotor) -> String {
    let m = &rotor.model;
    let mut s = String::new();
    writeln!(s, "model {} ({})", m.name, m.source).ok();
    if !m.description.is_empty() {
        writeln!(s, "  {}", m.description).ok();
    }
    writeln!(
        s,
        "  {} nodes, {} shaft elements, {} free DOFs, length {:.4} m, rotating mass {:.3} kg",
        m.node_count(),
        m.elements.len(),
        rotor.dof_count(),
        m.node_z[m.node_z.len() - 1] - m.node_z[0],
        m.total_mass()
    )
    .ok();
    // Node positions, eight to a line: where `node = N` in the file sits.
    for (row, chunk) in m.node_z.chunks(8).enumerate() {
        let cells: Vec<String> = chunk
            .iter()
            .enumerate()
            .map(|(k, z)| format!("{}: {}", row * 8 + k + 1, short(*z)))
            .collect();
        let head = if row == 0 { "node z (m):" } else { "" };
        writeln!(s, "  {head:<11} {}", cells.join(", ")).ok();
    }
    shaft_summary(&mut s, m);
    for d in &m.disks {
        writeln!(
            s,
            "  disk {} at node {}: m = {:.4} kg, Ip = {:.5} kg·m², Id = {:.5} kg·m²",
            d.name,
            d.node + 1,
            d.disk.mass,
            d.disk.polar_inertia,
            d.disk.diametral_inertia
        )
        .ok();
    }
    for pm in &m.point_masses {
        writeln!(
            s,
            "  point mass {} at node {}: mx = {} kg, my = {} kg (not rotating)",
            pm.name,
            pm.node + 1,
            short(pm.mass[0]),
            short(pm.mass[1])
        )
        .ok();
    }
    for b in &m.bearings {
        let what = element_kind(&b.kind);
        let on = match b.pedestal {
            Some(p) => format!(" on pedestal {}", m.pedestals[p].name),
            None => String::new(),
        };
        // Its installed centre off the nominal axis (issue 49).
        let off = if b.offset == [0.0, 0.0] {
            String::new()
        } else {
            format!(
                ", centre offset ({}, {}) µm",
                short(b.offset[0] * 1e6),
                short(b.offset[1] * 1e6)
            )
        };
        writeln!(
            s,
            "  {what} {} at node {}{on}{off}: {}",
            b.name,
            b.node + 1,
            describe_bearing(&b.kind)
        )
        .ok();
    }
    for p in &m.pedestals {
        writeln!(s, "  pedestal {}: {}", p.name, describe_pedestal(m, p)).ok();
    }
    for sup in &m.supports {
        let mut fixed: Vec<&str> = ["x", "y", "rx", "ry"]
            .iter()
            .zip(sup.fixed)
            .filter(|(_, f)| *f)
            .map(|(name, _)| *name)
            .collect();
        if sup.twist {
            fixed.push("rz");
        }
        writeln!(
            s,
            "  support at node {}: fixes {}",
            sup.node + 1,
            fixed.join(", ")
        )
        .ok();
    }
    for u in &m.unbalances {
        writeln!(
            s,
            "  unbalance {} at node {}: {} kg·m at {:.1}°",
            u.name,
            u.node + 1,
            u.magnitude,
            u.phase.to_degrees()
        )
        .ok();
    }
    loads_summary(&mut s, m);
    for p in &m.probes {
        let from = p.relative_to.map_or(String::new(), |b| {
            format!(
                ", measuring from bearing {}'s installed centre",
                m.bearings[b].name
            )
        });
        writeln!(s, "  probe {} at node {}{from}", p.name, p.node + 1).ok();
    }
    drive_summary(&mut s, m);
    if let Some(r) = m.reduction {
        let modes = match r {
            ReductionRequest::Modes(n) => format!("{n} fixed-interface modes"),
            ReductionRequest::FromSpeedRange => {
                "as many fixed-interface modes as the speed range needs".to_string()
            }
        };
        writeln!(s, "  reduction: transients run on a reduced rotor, {modes}").ok();
    }
    if let Some(c) = &m.tolerance_cases {
        let mut ranges = Vec::new();
        if let (Some([lo, hi]), Some(oil)) = (c.temperature, c.oil) {
            let zero = crate::bearing::oil::CELSIUS_ZERO;
            ranges.push(format!(
                "oil {} to {} °C (ν40 {}, ν100 {} mm²/s)",
                short(lo - zero),
                short(hi - zero),
                short(oil.nu_40),
                short(oil.nu_100)
            ));
        }
        if let Some([lo, hi]) = c.clearance_factor {
            ranges.push(format!("clearance × {} to {}", short(lo), short(hi)));
        }
        if let Some([lo, hi]) = c.preload {
            ranges.push(format!("preload {} to {}", short(lo), short(hi)));
        }
        let count = c.cases().len();
        writeln!(
            s,
            "  tolerance cases: {}; {count} cases (rotor cases)",
            ranges.join(", ")
        )
        .ok();
    }
    if let Some(z) = &m.shaft_zones {
        let names: Vec<&str> = z
            .bearings
            .iter()
            .map(|&k| m.bearings[k].name.as_str())
            .collect();
        writeln!(
            s,
            "  shaft vibration zones: A/B, B/C, C/D at {} µm pk-pk at {} ({})",
            z.boundaries
                .iter()
                .map(|b| short(b * 1e6))
                .collect::<Vec<_>>()
                .join(" / "),
            names.join(", "),
            z.source
        )
        .ok();
    }
    let [gx, gy, gz] = m.gravity.map(short);
    writeln!(s, "  gravity ({gx}, {gy}, {gz}) m/s²").ok();
    s
}

/// The materials the shaft uses, then the shaft's uniform runs: elements of
/// one length, section, material and axial force between two nodes (a
/// `[[shaft]]` section, or adjacent equal ones).
fn shaft_summary(s: &mut String, m: &RotorModel) {
    let mut named: Vec<&crate::fe::section::Material> = Vec::new();
    for e in &m.elements {
        if !named.iter().any(|x| x.name == e.element.material.name) {
            named.push(&e.element.material);
        }
    }
    for mat in named {
        writeln!(
            s,
            "  material {}: E = {} Pa, G = {} Pa, ρ = {} kg/m³",
            mat.name,
            short(mat.youngs_modulus),
            short(mat.shear_modulus),
            short(mat.density)
        )
        .ok();
    }
    let mut start = 0;
    while start < m.elements.len() {
        let first = &m.elements[start];
        let end = start
            + m.elements[start..]
                .iter()
                .take_while(|e| e.element == first.element && e.axial_force == first.axial_force)
                .count();
        let section = &first.element.section;
        writeln!(
            s,
            "  shaft section nodes {}–{}: {} × {} m, outer diameter {} mm, inner {} mm, {}, axial force {} N",
            first.node + 1,
            m.elements[end - 1].node + 2,
            end - start,
            short(first.element.length),
            short(section.outer_diameter * 1e3),
            short(section.inner_diameter * 1e3),
            first.element.material.name,
            short(first.axial_force)
        )
        .ok();
        start = end;
    }
}

/// One line per external force and per force port.
fn loads_summary(s: &mut String, m: &RotorModel) {
    for f in &m.forces {
        writeln!(
            s,
            "  force {} at node {}: {}",
            f.name,
            f.node + 1,
            describe_force(f)
        )
        .ok();
    }
    for p in &m.ports {
        writeln!(
            s,
            "  port {} at node {}: FMU inputs ports.{0}.fx, fy (N), outputs x, y (m), vx, vy (m/s)",
            p.name,
            p.node + 1
        )
        .ok();
    }
}

/// What a `[[bearings]]`-kind element is: a seal, a rub, a magnetic pull or
/// a bearing.
pub fn element_kind(kind: &crate::bearing::BearingKind) -> &'static str {
    match kind {
        k if k.is_seal() => "seal",
        k if k.is_rub() => "rub",
        k if k.is_magnetic_pull() => "magnetic pull",
        _ => "bearing",
    }
}

/// A pedestal's mass, what it stands on, its stiffness and damping and what
/// it carries.
pub fn describe_pedestal(m: &RotorModel, p: &crate::model::Pedestal) -> String {
    let on = match p.on {
        Some(q) => format!("pedestal {}", m.pedestals[q].name),
        None => "ground".to_string(),
    };
    let carried: Vec<&str> = m
        .bearings
        .iter()
        .filter(|b| b.pedestal.is_some_and(|q| m.pedestals[q].name == p.name))
        .map(|b| b.name.as_str())
        .collect();
    format!(
        "m = {} kg on {on}, K = {} N/m, C = {} N·s/m, carrying {}",
        short(p.mass),
        coefficient_matrix(&p.stiffness),
        coefficient_matrix(&p.damping),
        if carried.is_empty() {
            "other pedestals".to_string()
        } else {
            carried.join(", ")
        }
    )
}

/// A static or harmonic external force.
pub fn describe_force(f: &crate::model::ExternalForce) -> String {
    match f.kind {
        ForceKind::Static([fx, fy]) => {
            format!("static, (fx, fy) = ({}, {}) N", short(fx), short(fy))
        }
        ForceKind::Harmonic {
            magnitude,
            phase,
            frequency,
            direction,
        } => {
            let frequency = match frequency {
                HarmonicFrequency::Ratio(r) => format!("{}× the running speed", short(r)),
                HarmonicFrequency::Fixed(w) => {
                    format!("{} Hz", short(w / std::f64::consts::TAU))
                }
            };
            let direction = match direction {
                HarmonicDirection::Forward => "forward".to_string(),
                HarmonicDirection::Backward => "backward".to_string(),
                HarmonicDirection::Fixed(a) => {
                    format!("along a fixed line at {}°", short(a.to_degrees()))
                }
            };
            format!(
                "harmonic, {} N at {frequency}, {direction}, phase {}°",
                short(magnitude),
                short(phase.to_degrees())
            )
        }
    }
}

/// A coupling in words: its lateral joint (rigid flange, or flexible with
/// its stiffnesses and dampings), its misalignment and its torsion.
pub fn describe_coupling(c: &crate::model::Coupling) -> String {
    let mut parts = vec![match c.joint {
        CouplingJoint::Flange => "rigid flange".to_string(),
        CouplingJoint::Flexible { lateral, angular } => format!(
            "flexible: lateral {} N/m ({} N·s/m), angular {} N·m/rad ({} N·m·s/rad)",
            short(lateral[0]),
            short(lateral[1]),
            short(angular[0]),
            short(angular[1])
        ),
    }];
    if c.is_misaligned() {
        let o = &c.misalignment;
        parts.push(format!(
            "misaligned by ({}, {}) µm and ({}, {}) mrad",
            short(o[0] * 1e6),
            short(o[1] * 1e6),
            short(o[3] * 1e3),
            short(-o[2] * 1e3)
        ));
    }
    parts.push(match c.stiffness {
        Some(k) => format!(
            "torsional stiffness {} N·m/rad, damping {} N·m·s/rad",
            short(k),
            short(c.damping)
        ),
        None => "torsion of its shaft element".to_string(),
    });
    parts.join("; ")
}

/// The drive, and the torsional chain's parts: for a torque-driven shaft
/// where the torques act and the polar inertia `J = Σ` (disks' `I_p` + shaft
/// elements' `ρ J_p L`) over the free twist DOFs (the inertia a plant model's
/// swing equation would need); each torque node, coupling and thrust bearing
/// (its load and breakaway torque `μ_b W R_m`).
fn drive_summary(s: &mut String, m: &RotorModel) {
    match m.drive {
        Drive::Torque => {
            let torques: Vec<String> = m
                .torques
                .iter()
                .map(|t| format!("{} at node {}", t.name, t.node + 1))
                .collect();
            writeln!(
                s,
                "  torque drive: {}; polar inertia {:.1} kg·m² (shaft and disks)",
                torques.join(", "),
                TorsionalRotor::new(m).total_inertia()
            )
            .ok();
        }
        Drive::Speed => {
            writeln!(
                s,
                "  speed drive: the shaft follows the prescribed speed (shaft.speed)"
            )
            .ok();
        }
    }
    for t in &m.torques {
        writeln!(
            s,
            "  torque {} at node {}: FMU input torques.{0} (N·m){}",
            t.name,
            t.node + 1,
            if m.drive == Drive::Torque {
                ""
            } else {
                ", used when the shaft is torque-driven"
            }
        )
        .ok();
    }
    for c in m.couplings.iter() {
        let node = m.elements[c.element].node;
        writeln!(
            s,
            "  coupling {} between nodes {} and {}: {}",
            c.name,
            node + 1,
            node + 2,
            describe_coupling(c)
        )
        .ok();
    }
    for t in &m.thrust_bearings {
        writeln!(
            s,
            "  thrust bearing {} at node {}: {}",
            t.name,
            t.node + 1,
            describe_thrust_bearing(t)
        )
        .ok();
    }
}

/// A thrust bearing's load, mean radius, breakaway torque and lift-off.
pub fn describe_thrust_bearing(t: &crate::model::PlacedThrustBearing) -> String {
    let b = &t.bearing;
    format!(
        "load W = {} N, R_m = {} m, breakaway torque μ_b W R_m = {} N·m{}, lift-off {} rpm",
        short(b.load),
        short(b.mean_radius()),
        short(b.breakaway_torque()),
        if b.oil_lift { " (oil lift)" } else { "" },
        short(b.lift_off_speed * RAD_S_TO_RPM)
    )
}
