//! Where the destabilizing cross-coupling of a stability check acts
//! ([`super::stability`]): API 617's placement (mid-span between the
//! bearings, or the overhung impellers), the earlier placement at the disks
//! and seals, and the label of a site for messages.

use crate::rotor::Rotor;

/// The node nearest the middle between the outermost bearings (the shaft's
/// middle with fewer than two bearings).
pub fn mid_span_node(rotor: &Rotor) -> usize {
    let m = &rotor.model;
    let zs: Vec<f64> = m.bearings.iter().map(|b| m.node_z[b.node]).collect();
    let (lo, hi) = if zs.len() >= 2 {
        (
            zs.iter().copied().fold(f64::INFINITY, f64::min),
            zs.iter().copied().fold(f64::NEG_INFINITY, f64::max),
        )
    } else {
        (m.node_z[0], m.node_z[m.node_count() - 1])
    };
    m.nearest_node(0.5 * (lo + hi))
}

/// Where the cross-coupling acts by default: [`api617_placement`].
pub fn default_sites(rotor: &Rotor) -> Vec<usize> {
    api617_placement(rotor).0
}

/// Where API 617 (7th ed., 2.6.5; API 684 Level I) places the anticipated
/// cross-coupling, with the reason stated: at the rotor's mid-span for a
/// rotor between bearings ([`mid_span_node`]); for an overhung rotor at its
/// overhung impellers, each at once (a double-overhung rotor at both ends).
/// The impellers are the disks with `role = "impeller"`, else every disk; a
/// disk is overhung outside the span of the supporting bearings (seals,
/// pulls and rubs are not supports).
pub fn api617_placement(rotor: &Rotor) -> (Vec<usize>, String) {
    let m = &rotor.model;
    let supports: Vec<f64> = m
        .bearings
        .iter()
        .filter(|b| b.kind.is_bearing())
        .map(|b| m.node_z[b.node])
        .collect();
    let tagged = m.disks.iter().any(|d| d.impeller);
    let mut overhung: Vec<usize> = Vec::new();
    if supports.len() >= 2 {
        let lo = supports.iter().copied().fold(f64::INFINITY, f64::min);
        let hi = supports.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        overhung = m
            .disks
            .iter()
            .filter(|d| d.impeller || !tagged)
            .map(|d| d.node)
            .filter(|&n| m.node_z[n] < lo || m.node_z[n] > hi)
            .collect();
        overhung.sort_unstable();
        overhung.dedup();
    }
    let impellers = if tagged {
        "impellers (role = \"impeller\")"
    } else {
        "disks (no disk has role = \"impeller\")"
    };
    if overhung.is_empty() {
        (
            vec![mid_span_node(rotor)],
            "API 617: mid-span, the rotor's impellers lie between its bearings".to_string(),
        )
    } else {
        (
            overhung,
            format!("API 617: at the overhung {impellers}, the rotor is overhung"),
        )
    }
}

/// The default placement from 2026-12-01 to 2026-12-05, kept so that a
/// figure published then can be traced: the nodes of the disks and of the
/// seals, else the node nearest mid-span.
pub fn disks_and_seals(rotor: &Rotor) -> Vec<usize> {
    let seals = rotor.model.bearings.iter().filter(|b| b.kind.is_seal());
    let mut nodes: Vec<usize> = rotor
        .model
        .disks
        .iter()
        .map(|d| d.node)
        .chain(seals.map(|b| b.node))
        .collect();
    nodes.sort_unstable();
    nodes.dedup();
    if nodes.is_empty() {
        nodes.push(mid_span_node(rotor));
    }
    nodes
}

/// What is at `node` (0-based), for messages: its disks and seals, else
/// "mid-span".
pub fn site_label(rotor: &Rotor, node: usize) -> String {
    let m = &rotor.model;
    let parts: Vec<String> = m
        .disks
        .iter()
        .filter(|d| d.node == node)
        .map(|d| format!("disk {}", d.name))
        .chain(
            m.bearings
                .iter()
                .filter(|b| b.node == node && b.kind.is_seal())
                .map(|b| format!("seal {}", b.name)),
        )
        .collect();
    if !parts.is_empty() {
        format!("node {} ({})", node + 1, parts.join(", "))
    } else if node == mid_span_node(rotor) {
        format!("node {} (mid-span between the bearings)", node + 1)
    } else {
        format!("node {}", node + 1)
    }
}
