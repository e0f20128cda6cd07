//! `documentation/index.html` of the FMU, generated from the same variable table.

use super::variables::{Causality, variables};
use crate::model::RotorModel;

fn escape(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

/// The FMU's HTML documentation for `model`.
pub fn index_html(model: &RotorModel) -> String {
    let mut rows = String::new();
    for v in variables(model) {
        let causality = match v.causality {
            Causality::Parameter => "parameter",
            Causality::Input => "input",
            Causality::Output => "output",
        };
        rows.push_str(&format!(
            "<tr><td>{}</td><td><code>{}</code></td><td>{causality}</td><td>{}</td><td>{}</td><td>{}</td></tr>\n",
            v.value_reference,
            escape(&v.name),
            v.unit.unwrap_or(""),
            v.start.map(|s| format!("{s}")).unwrap_or_default(),
            escape(&v.description)
        ));
    }
    let bearings: Vec<String> = model
        .bearings
        .iter()
        .map(|b| {
            format!(
                "<li><code>{}</code> at node {}: {:?}</li>",
                escape(&b.name),
                b.node + 1,
                b.kind
            )
            .replace("\n", " ")
        })
        .collect();
    format!(
        r#"<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8"><title>{name} — rotor-bearing FMU</title>
<style>body{{font-family:sans-serif;max-width:70em;margin:2em auto}}td,th{{border-bottom:1px solid #ccc;padding:.2em .6em;text-align:left}}</style></head>
<body>
<h1>{name}</h1>
<p>{description}</p>
<h2>What it simulates</h2>
<p>A finite-element rotor ({elements} Timoshenko shaft elements, {nodes} nodes, 4 DOF per node: x, y, θx, θy;
lumped disks with gyroscopic inertia) on its bearings: linear spring–dampers, plain short journal bearings
(Ocvirk theory, Gümbel π-film cavitation) and tilting-pad journal bearings (short-bearing film per pad, massless
pads whose tilts are extra unknowns). Each <code>fmi2DoStep</code> integrates the nonlinear equations of motion
with Newmark's average-acceleration method (β = 1/4, γ = 1/2) and modified Newton–Raphson iterations in equal
internal sub-steps no longer than <code>solver.time_step</code>. At <code>fmi2ExitInitializationMode</code> the rotor is put in
static equilibrium under gravity at the start speed.</p>
<p>With <code>solver.reduced_modes</code> &gt; 0 (start value from the model's <code>[reduction]</code>) the transient runs on a
Craig–Bampton reduced rotor: the nodes of nonlinear bearings, rubs, probes and unbalance planes stay physical
coordinates, the rest of the shaft follows them statically plus that many fixed-interface modes. Bearing forces act
exactly as in the full model and static equilibria are the full model's; the orbits converge to the full model's as
modes are added. The FMU logs which rotor runs (<code>logAll</code>) and up to which frequency it is valid: the kept
modes must reach ten times the highest frequency of the motion. When the running speed or the motion at the kept nodes
leaves that range, the step returns fmi2Warning once per excursion, with the error estimate there against the full
rotor. A state saved with another mode count is restored onto the rotor it was saved on.</p>
<h2>Bearings</h2><ul>{bearings}</ul>
<h2>Conventions and assumptions</h2>
<ul>
<li>SI units; the shaft axis is z, spin positive about +z (from +x toward +y).</li>
<li>Bearing forces act on the journal. The journal position is relative to the bearing centre.</li>
<li>A journal reaching its bushing or pads goes on in metal-to-metal contact (penalty normal force, Coulomb friction).
A step whose Newton iterations fail even after halving returns <code>fmi2Discard</code>; roll back with
<code>fmi2SetFMUstate</code>.</li>
<li>Unbalance force of a plane: m e (Ω² cos φ + Ω̇ sin φ, Ω² sin φ − Ω̇ cos φ), φ = spin angle + phase.</li>
<li>Inputs are held constant over a step unless a first-order derivative is given
(<code>fmi2SetRealInputDerivatives</code>, e.g. a speed ramp).</li>
</ul>
<h2>Coupling</h2>
<p>Drive <code>shaft.speed</code> from a generator or governor model and feed <code>friction_torque</code> back into its torque
balance. The machine starts at standstill (<code>shaft.speed</code> = 0), its journals resting on their bearings;
<code>friction_torque</code> is the film shear plus the contact friction &mu;NR, at standstill the breakaway torque the drive
must overcome (treat it as Coulomb friction: it holds the shaft, it never turns it backwards). Journals that reach their
bushing, pads or a rub's stator go on in contact (<code>bearings.*.contact_force</code>, <code>rubs.*.contact_force</code>).
The FMU supports variable communication steps, rollback (<code>fmi2GetFMUstate</code>/<code>fmi2SetFMUstate</code>) and serialized
states, and it can be instantiated many times in one process.</p>
<h2>Variables</h2>
<table><tr><th>VR</th><th>name</th><th>causality</th><th>unit</th><th>start</th><th>description</th></tr>
{rows}</table>
</body></html>
"#,
        name = escape(&model.name),
        description = escape(&model.description),
        elements = model.elements.len(),
        nodes = model.node_count(),
        bearings = bearings.join("\n"),
    )
}
