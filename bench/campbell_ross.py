"""Campbell diagram against ROSS (ross-rotordynamics 3.x), and its scaling.

The rotor: a 3 m, 80 mm steel shaft in N Timoshenko elements (shear, rotary
inertia, gyroscopics), steel disks of 400 and 500 mm (80 mm wide) at 1 m and
2 m, isotropic linear bearings (1e7 N/m, 1e3 N·s/m) at both ends. The diagram:
8 modes at 20 speeds from 0 to 10 000 rpm.

1. For N = 30, 120, 480, 1000: ROSS `Rotor.run_campbell(speeds, frequencies=8)`
   against `rotor campbell --max-rpm 10000 --steps 19 --modes 8` (the time of
   the diagram the CLI reports on stderr, without start-up, critical speeds and
   output; median of 5 runs). ROSS's eigen-solve per speed grows like N³, so at
   N = 480 and 1000 it is timed on a subset of the speeds (evenly spread,
   `ROSS_SPEEDS`) and its time scaled to 20 speeds; the table says so. The
   damped frequencies are compared at every speed ROSS computed: each of ROSS's
   is matched to the nearest of ours within 1e-4 (worst difference printed);
   ROSS's nodes also carry axial and torsion DOFs, so its list holds a
   non-lateral mode, constant in speed, which is printed apart. The run fails
   if more than two ROSS frequencies per speed, or more than two distinct
   values overall, are unmatched.
   The same runs also time the whole command as a user meets it: the wall
   clock of the `rotor campbell` subprocess (start-up, model assembly, the
   diagram, the refinement of the critical speeds, text and CSV output;
   median of the 5 runs), against the same ROSS `run_campbell` time, the
   ratio measured in the same run.
2. Time per speed of `rotor campbell` from 100 to 5000 elements, and the
   exponent of a least-squares fit of log(time per speed) against log(N).

Prints everything and writes bench/campbell_results.md.
usage: .venv-ross/bin/python bench/campbell_ross.py target/release/rotor
"""
import csv
import os
import subprocess
import sys
import tempfile
import time

import numpy as np
import ross as rs

rotor_cli = sys.argv[1]
here = os.path.dirname(os.path.abspath(__file__))
TOP_RPM = 10000.0
SPEEDS = 20
MODES = 8
ROSS_SPEEDS = {30: SPEEDS, 120: SPEEDS, 480: 2, 1000: 1}
E, G, RHO = 211e9, 81.2e9, 7810.0
K_B, C_B = 1e7, 1e3
DISKS = ((1.0, 0.4), (2.0, 0.5))  # position (m), outer diameter (m); bore 80 mm, width 80 mm


def disk_nodes(n):
    return [round(z / 3.0 * n) for z, _ in DISKS]


def model_text(n):
    text = (f'name = "long_shaft_{n}"\ngravity = [0.0, -9.81, 0.0]\n\n'
            f'[[materials]]\nname = "steel"\nyoungs_modulus = {E}\nshear_modulus = {G}\ndensity = {RHO}\n\n'
            f'[[shaft]]\nlength = 3.0\nouter_diameter = 0.08\nmaterial = "steel"\nelements = {n}\n\n')
    for k, (node, (_, od)) in enumerate(zip(disk_nodes(n), DISKS)):
        text += (f'[[disks]]\nname = "disk{k + 1}"\nnode = {node + 1}\nmaterial = "steel"\n'
                 f'outer_diameter = {od}\ninner_diameter = 0.08\nwidth = 0.08\n\n')
    for name, node in (("de", 1), ("nde", n + 1)):
        text += (f'[[bearings]]\nname = "{name}"\ntype = "linear"\nnode = {node}\n'
                 f'kxx = {K_B}\nkyy = {K_B}\ncxx = {C_B}\ncyy = {C_B}\n\n')
    return text


def rust_campbell(n, repeats=5):
    """Median seconds of the diagram over `repeats` runs, its frequencies (speeds × modes), and
    the median wall-clock seconds of the whole command (the subprocess from start to exit)."""
    with tempfile.TemporaryDirectory() as tmp:
        path = os.path.join(tmp, "model.toml")
        with open(path, "w") as f:
            f.write(model_text(n))
        out = os.path.join(tmp, "campbell.csv")
        walls, wholes = [], []
        for _ in range(repeats):
            t0 = time.perf_counter()
            run = subprocess.run([rotor_cli, "campbell", path, "--max-rpm", str(TOP_RPM), "--steps",
                                  str(SPEEDS - 1), "--modes", str(MODES), "--csv", out],
                                 capture_output=True, text=True)
            wholes.append(time.perf_counter() - t0)
            if run.returncode != 0:
                sys.exit(run.stderr)
            line = next(l for l in run.stderr.splitlines() if l.startswith("campbell diagram:"))
            walls.append(float(line.split(" in ")[1].split(" s wall-clock")[0]))
        rows = list(csv.DictReader(open(out)))
    freqs = np.array([float(r["damped_frequency_rad_s"]) for r in rows]).reshape(SPEEDS, MODES)
    return float(np.median(walls)), freqs, float(np.median(wholes))


def ross_rotor(n):
    steel = rs.Material(name="steel_campbell", rho=RHO, E=E, G_s=G)
    shaft = [rs.ShaftElement(L=3.0 / n, idl=0.0, odl=0.08, material=steel, shear_effects=True,
                             rotary_inertia=True, gyroscopic=True) for _ in range(n)]
    disks = [rs.DiskElement.from_geometry(n=node, material=steel, width=0.08, i_d=0.08, o_d=od)
             for node, (_, od) in zip(disk_nodes(n), DISKS)]
    bearings = [rs.BearingElement(n=node, kxx=K_B, kyy=K_B, cxx=C_B, cyy=C_B) for node in (0, n)]
    return rs.Rotor(shaft, disks, bearings)


speeds = np.linspace(0.0, TOP_RPM * np.pi / 30.0, SPEEDS)
rows, checks = [], []
for n in ROSS_SPEEDS:
    rust_t, rust_f, whole_t = rust_campbell(n)
    k = ROSS_SPEEDS[n]
    pick = np.round(np.linspace(SPEEDS - 1, 0, k)).astype(int)[::-1] if k < SPEEDS else np.arange(SPEEDS)
    rotor = ross_rotor(n)
    t0 = time.perf_counter()
    result = rotor.run_campbell(speeds[pick], frequencies=MODES)
    ross_t = (time.perf_counter() - t0) * SPEEDS / k
    # ROSS's nodes carry axial and torsion DOFs too: its 8 lowest frequencies
    # include a non-lateral mode (constant with speed) that this lateral model
    # does not have. Each ROSS frequency is matched to the nearest of ours.
    ross_f = np.asarray(result.wd)
    near = np.abs(ross_f[:, :, None] / rust_f[pick][:, None, :] - 1.0).min(axis=2)
    matched = near < 1e-4
    diff = float(near[matched].max())
    others = sorted({f"{x:.2f}" for x in ross_f[~matched]})
    checks.append(f"N = {n}: {len(pick)} speeds, {matched.sum()} of {near.size} ROSS frequencies matched, "
                  f"largest relative difference {diff:.1e}; unmatched (ROSS axial/torsion, rad/s): {', '.join(others)}")
    print(checks[-1], flush=True)
    if matched.sum(axis=1).min() < MODES - 2 or len(others) > 2:
        sys.exit(f"N = {n}: frequencies differ from ROSS")
    rows.append((n, 4 * (n + 1), k, ross_t, rust_t, whole_t))
    print(f"N = {n}: ROSS {ross_t:.2f} s (timed on {k} speeds), rotor_bearing {rust_t:.4f} s, {ross_t / rust_t:.0f}×",
          flush=True)
    print(f"N = {n}: whole `rotor campbell` command {whole_t:.4f} s wall-clock, {ross_t / whole_t:.0f}× ROSS",
          flush=True)

scaling = []
for n in (100, 200, 500, 1000, 2000, 5000):
    t, _, _ = rust_campbell(n)
    scaling.append((n, 4 * (n + 1), t / SPEEDS))
    print(f"N = {n}: {1e3 * t / SPEEDS:.2f} ms per speed", flush=True)
slope = np.polyfit(np.log([s[0] for s in scaling]), np.log([s[2] for s in scaling]), 1)[0]

lines = ["| elements | DOFs | ROSS speeds timed | ROSS (s, 20 speeds) | rotor_bearing (s) | ratio |",
         "|---:|---:|---:|---:|---:|---:|"]
for n, dofs, k, ross_t, rust_t, _ in rows:
    timed = f"{k}" if k == SPEEDS else f"{k} (scaled ×{SPEEDS // k})"
    lines.append(f"| {n} | {dofs} | {timed} | {ross_t:.2f} | {rust_t:.4f} | {ross_t / rust_t:.0f}× |")
lines += ["", "The whole command as a user meets it (wall clock of the `rotor campbell` subprocess: start-up, "
          "diagram, critical speeds, text and CSV output; median of 5 runs) against the same ROSS time:", "",
          "| elements | DOFs | ROSS (s, 20 speeds) | rotor campbell, whole command (s) | ratio |",
          "|---:|---:|---:|---:|---:|"]
for n, dofs, _, ross_t, _, whole_t in rows:
    lines.append(f"| {n} | {dofs} | {ross_t:.2f} | {whole_t:.4f} | {ross_t / whole_t:.0f}× |")
lines += ["", "| elements | DOFs | ms per speed |", "|---:|---:|---:|"]
for n, dofs, t in scaling:
    lines.append(f"| {n} | {dofs} | {1e3 * t:.2f} |")
lines += ["", f"fitted exponent of time per speed against elements (100–5000): {slope:.3f}"]
table = "\n".join(lines)
print("\n".join(checks))
print(table)
with open(os.path.join(here, "campbell_results.md"), "w") as f:
    f.write("```\n" + "\n".join(checks) + "\n```\n\n" + table + "\n")
