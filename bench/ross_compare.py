"""Speed comparison with ROSS (ross-rotordynamics, Python) on the same work.

1. Linear: the classic disk-on-shaft rotor with bearing damping 1000 N·s/m,
   1000 rpm, unbalance 0.001 kg·m at the disk, 2 s with Δt = 1e-4 s. ROSS's
   Newmark time response and its state-space default, against `rotor simulate`.
   Checks that the steady disk orbits agree within 1 %.
2. Nonlinear: the same rotor on two plain short bearings (R = 50 mm, L = 30 mm,
   C = 0.1 mm, μ = 0.02 Pa·s) with gravity, 0.001 kg·m at 1000 rpm, 0.5 s. ROSS
   integrates with its robust Newmark and the short-bearing force injected through
   `add_to_RHS` (computed here by Gauss quadrature of the cavitated short-bearing
   pressure, the same physics as the Rust closed form). Checks that the bearing
   orbits agree within 1 % of the clearance.

Both cases run again on the Craig–Bampton reduced rotor (`--reduced-modes
10`, the documented default): its orbits must agree with the full model's
within 1 % (of the orbit radius, linear; of the clearance, nonlinear).

Prints the wall-clock times (medians: 5 runs of rotor_bearing and of ROSS's
linear solvers, 3 of ROSS's nonlinear run) and their ratios, and writes
bench/ross_results.md.
usage: .venv-ross/bin/python bench/ross_compare.py target/release/rotor
"""
import os
import subprocess
import sys
import tempfile
import time

import numpy as np
import ross as rs

rotor_cli = sys.argv[1]
here = os.path.dirname(os.path.abspath(__file__))
rpm = 1000.0
MODES = 10  # fixed-interface modes of the reduced rotor (the documented default)
w = rpm * np.pi / 30.0
me = 1e-3
dt = 1e-4

steel = rs.Material(name="steel_bench", rho=7810, E=211e9, G_s=81.2e9)


def ross_rotor(k, c):
    shaft = [rs.ShaftElement(L=0.25, idl=0.0, odl=0.05, material=steel, shear_effects=True,
                             rotary_inertia=True, gyroscopic=True) for _ in range(6)]
    disk = rs.DiskElement.from_geometry(n=3, material=steel, width=0.07, i_d=0.05, o_d=0.28)
    bearings = [rs.BearingElement(n=n, kxx=k, kyy=k, cxx=c, cyy=c) for n in (0, 6)]
    return rs.Rotor(shaft, [disk], bearings)


def median_time(run, repeats):
    """Median wall-clock time of `run()` over `repeats` calls, and its last result."""
    times, result = [], None
    for _ in range(repeats):
        t0 = time.perf_counter()
        result = run()
        times.append(time.perf_counter() - t0)
    return float(np.median(times)), result


def rust_run(model_text, duration, extra, repeats=5):
    """Median integration time of `rotor simulate` over `repeats` runs, and its outputs."""
    walls = [rust_run_once(model_text, duration, extra) for _ in range(repeats)]
    return walls[-1][0], float(np.median([w for _, w in walls]))


def rust_run_once(model_text, duration, extra):
    with tempfile.TemporaryDirectory() as tmp:
        path = os.path.join(tmp, "model.toml")
        with open(path, "w") as f:
            f.write(model_text)
        csv = os.path.join(tmp, "out.csv")
        args = [rotor_cli, "simulate", path, "--rpm", str(rpm), "--duration", str(duration), "--step", str(dt),
                "--output-step", str(dt), "--csv", csv] + extra
        run = subprocess.run(args, capture_output=True, text=True)
        if run.returncode != 0:
            sys.exit(run.stderr)
        # The CLI reports the integration time (outputs recorded every step, as
        # ROSS keeps its response at every step), without start-up and CSV writing.
        line = next(l for l in run.stderr.splitlines() if "wall-clock" in l)
        wall = float(line.split(" in ")[1].split(" s wall-clock")[0])
        data = np.genfromtxt(csv, delimiter=",", names=True)
        return data, wall


base = open(os.path.join(here, "..", "models", "classic_disk_rotor.toml")).read()
results = []

# ---------------------------------------------------------------- 1. linear
linear_model = base.replace("kyy = 1e6\n", "kyy = 1e6\ncxx = 1000.0\ncyy = 1000.0\n")
data, rust_wall = rust_run(linear_model, 2.0, ["--no-gravity", "--no-settle"])
rotor = ross_rotor(1e6, 1000.0)
t = np.arange(0.0, 2.0 + dt / 2, dt)
F = np.zeros((len(t), rotor.ndof))
ndof = rotor.number_dof
F[:, ndof * 3 + 0] = me * w**2 * np.cos(w * t)
F[:, ndof * 3 + 1] = me * w**2 * np.sin(w * t)
# Warm up numba outside the timing.
rotor.run_time_response(w, F[:200], t[:200], method="newmark")
ross_newmark, newmark = median_time(lambda: rotor.run_time_response(w, F, t, method="newmark"), 5)
ross_ss, state_space = median_time(lambda: rotor.run_time_response(w, F, t), 5)
last = t > 1.9
amp_ross = np.max(np.hypot(newmark.yout[last, ndof * 3], newmark.yout[last, ndof * 3 + 1]))
amp_ss = np.max(np.hypot(state_space.yout[last, ndof * 3], state_space.yout[last, ndof * 3 + 1]))
rl = data["time_s"] > 1.9
amp_rust = np.max(np.hypot(data["disk_x_m"][rl], data["disk_y_m"][rl]))
agree = abs(amp_rust / amp_ross - 1.0)
print(f"linear: disk orbit radius Rust {amp_rust:.6e} m, ROSS Newmark {amp_ross:.6e} m, ROSS state space {amp_ss:.6e} m (diff {agree:.2e})")
if agree > 0.01:
    sys.exit("linear orbits differ by more than 1 %")
reduced, rust_wall_red = rust_run(linear_model, 2.0, ["--no-gravity", "--no-settle", "--reduced-modes", str(MODES)])
amp_red = np.max(np.hypot(reduced["disk_x_m"][rl], reduced["disk_y_m"][rl]))
diff_red = np.max(np.hypot(reduced["disk_x_m"] - data["disk_x_m"], reduced["disk_y_m"] - data["disk_y_m"])) / amp_rust
print(f"linear: reduced rotor ({MODES} modes) disk orbit radius {amp_red:.6e} m, largest difference from the full model {diff_red:.2e} of the orbit radius")
if diff_red > 0.01:
    sys.exit("reduced linear orbit differs from the full model by more than 1 %")
results.append(("Linear classic rotor, 2 s, Δt = 1e-4 s: ROSS Newmark", ross_newmark, rust_wall))
results.append(("Linear classic rotor, 2 s, Δt = 1e-4 s: ROSS state space (default)", ross_ss, rust_wall))
results.append((f"Linear classic rotor, reduced ({MODES} modes): ROSS Newmark", ross_newmark, rust_wall_red))
results.append((f"Linear classic rotor, reduced ({MODES} modes): ROSS state space (default)", ross_ss, rust_wall_red))

# ------------------------------------------------------------- 2. nonlinear
R, L, C, MU = 0.05, 0.03, 1e-4, 0.02  # a 50 mm journal (collar) on the 25 mm-radius shaft, as in ROSS, whose bearing radius is its own
nodes = np.polynomial.legendre.leggauss(200)
theta = np.pi * (nodes[0] + 1.0)  # [0, 2π]
weight = np.pi * nodes[1]


def short_bearing(x, y, vx, vy):
    """Force on the journal: short bearing, Gümbel cavitation, by quadrature."""
    h = C - x * np.cos(theta) - y * np.sin(theta)
    s = w * (x * np.sin(theta) - y * np.cos(theta)) - 2.0 * (vx * np.cos(theta) + vy * np.sin(theta))
    p = np.maximum(-MU * L**3 * s / (2.0 * h**3), 0.0)  # ∫ p dz
    return -R * np.sum(weight * p * np.cos(theta)), -R * np.sum(weight * p * np.sin(theta))


nl_model = base.split("[[bearings]]")[0]
for node, name in ((1, "drive_end"), (7, "non_drive_end")):
    nl_model += (f'[[bearings]]\nname = "{name}"\ntype = "plain"\nnode = {node}\nradius = {R}\nlength = {L}\n'
                 f'clearance = {C}\nviscosity = {MU}\njournal_collar = true\n')
nl_model += base[base.index("[[unbalance]]"):]
data, rust_wall_nl = rust_run(nl_model, 0.5, ["--no-settle"])

rotor = ross_rotor(0.0, 0.0)
t = np.arange(0.0, 0.5 + dt / 2, dt)
F = np.zeros((len(t), rotor.ndof))
F[:, ndof * 3 + 0] = me * w**2 * np.cos(w * t)
F[:, ndof * 3 + 1] = me * w**2 * np.sin(w * t)
gravity = np.zeros(rotor.ndof)
gravity[1::ndof] = -9.81
F += rotor.M(w) @ gravity
bearing_dofs = [ndof * 0, ndof * 6]


def add_to_rhs(step, **state):
    u, v = state["disp_resp"], state["velc_resp"]
    extra = np.zeros(rotor.ndof)
    for d in bearing_dofs:
        fx, fy = short_bearing(u[d], u[d + 1], v[d], v[d + 1])
        extra[d], extra[d + 1] = fx, fy
    return extra


rotor.run_time_response(w, F[:50], t[:50], method="newmark", add_to_RHS=add_to_rhs, newmark_type="robust")
ross_nl, nl = median_time(
    lambda: rotor.run_time_response(w, F, t, method="newmark", add_to_RHS=add_to_rhs, newmark_type="robust"), 3)
last = t > 0.4
rl = data["time_s"] > 0.4


def worst_against(rust):
    """Largest bearing orbit difference (of the clearance) of a Rust run from
    ROSS over the last 0.1 s, and from the full Rust run over the whole run."""
    from_ross, from_full = 0.0, 0.0
    for k, name in enumerate(["drive_end", "non_drive_end"]):
        d = bearing_dofs[k]
        xr, yr = nl.yout[last, d], nl.yout[last, d + 1]
        xo, yo = rust[f"{name}_x_m"][rl], rust[f"{name}_y_m"][rl]
        n = min(len(xr), len(xo))
        from_ross = max(from_ross, np.max(np.hypot(xr[:n] - xo[:n], yr[:n] - yo[:n])) / C)
        dx, dy = rust[f"{name}_x_m"] - data[f"{name}_x_m"], rust[f"{name}_y_m"] - data[f"{name}_y_m"]
        from_full = max(from_full, np.max(np.hypot(dx, dy)) / C)
    return from_ross, from_full


worst, _ = worst_against(data)
print(f"nonlinear: largest bearing orbit difference {worst:.2e} of the clearance")
if worst > 0.01:
    sys.exit("nonlinear orbits differ by more than 1 % of the clearance")
reduced, rust_wall_nl_red = rust_run(nl_model, 0.5, ["--no-settle", "--reduced-modes", str(MODES)])
worst_red, worst_full = worst_against(reduced)
print(f"nonlinear: reduced rotor ({MODES} modes) largest bearing orbit difference {worst_red:.2e} of the clearance from ROSS, {worst_full:.2e} from the full model")
if max(worst_red, worst_full) > 0.01:
    sys.exit("reduced nonlinear orbits differ by more than 1 % of the clearance")
results.append(("Nonlinear short bearings, 0.5 s, Δt = 1e-4 s: ROSS robust Newmark + add_to_RHS", ross_nl, rust_wall_nl))
results.append((f"Nonlinear short bearings, reduced ({MODES} modes): ROSS robust Newmark + add_to_RHS", ross_nl, rust_wall_nl_red))

lines = ["| case | ROSS (s) | rotor_bearing (s) | ratio |", "|---|---:|---:|---:|"]
for name, ross_t, rust_t in results:
    lines.append(f"| {name} | {ross_t:.3f} | {rust_t:.4f} | {ross_t / rust_t:.0f}× |")
table = "\n".join(lines)
print(table)
with open(os.path.join(here, "ross_results.md"), "w") as f:
    f.write(table + "\n")
