"""FMPy against the FMU: validation of every packed FMU, and a speed ramp given as
an input compared with the Rust simulator run directly (examples/reference_run).

Run by tests/fmpy.rs with the project's venv; argv: repo root, reference_run binary.
"""
import os
import subprocess
import sys
import tempfile

import numpy as np
from fmpy import read_model_description, simulate_fmu
from fmpy.validation import validate_fmu

root, reference_run = sys.argv[1], sys.argv[2]
out = os.path.join(root, "out")
failures = []

# 1. Validation of the default FMU and one packed from each shipped model.
fmus = ["RotorBearing.fmu"] + [m[:-5] + ".fmu" for m in sorted(os.listdir(os.path.join(root, "models")))
                               if m.endswith(".toml") and m != "hydro_unit.toml"]
for name in fmus:
    path = os.path.join(out, name)
    if not os.path.exists(path):
        failures.append(f"{path} missing: run fmu_pack.sh (scripts/test.sh packs every model)")
        continue
    problems = validate_fmu(path)
    if problems:
        failures.append(f"{name}: " + "; ".join(problems))

# 2. A speed ramp 150 → 165 rpm over 1 s as an input, against the direct run.
fmu = os.path.join(out, "RotorBearing.fmu")
md = read_model_description(fmu)
bearings = sorted({v.name.split(".")[1] for v in md.modelVariables if v.name.startswith("bearings.")},
                  key=lambda b: [v.name for v in md.modelVariables].index(f"bearings.{b}.x"))
names = [f"bearings.{b}.{q}" for b in bearings for q in ("x", "y", "fx", "fy")]
h, stop = 0.01, 1.0
t = np.arange(0, 101) * h
w = (150.0 + 15.0 * t) * np.pi / 30.0
signal = np.array(list(zip(t, w)), dtype=[("time", np.float64), ("shaft.speed", np.float64)])
res = simulate_fmu(fmu, stop_time=stop, output_interval=h, input=signal, output=names)
with tempfile.NamedTemporaryFile("w", suffix=".csv", delete=False) as f:
    for ti, wi in zip(t, w):
        f.write(f"{float(ti)!r},{float(wi)!r}\n")
    table = f.name
ref = subprocess.run([reference_run, os.path.join(root, "models", "hydro_unit.toml"), table, repr(stop), repr(h)],
                     capture_output=True, text=True)
os.unlink(table)
if ref.returncode != 0:
    failures.append("reference_run failed: " + ref.stderr)
else:
    rows = [list(map(float, line.split(","))) for line in ref.stdout.split()]
    if len(rows) != len(res):
        failures.append(f"{len(res)} FMPy rows vs {len(rows)} reference rows")
    worst = 0.0
    for k, (row, rec) in enumerate(zip(rows, res)):
        if abs(row[0] - rec["time"]) > 1e-12:
            failures.append(f"row {k}: time {rec['time']} vs {row[0]}")
            break
        for j, n in enumerate(names):
            a, b = rec[n], row[1 + j]
            scale = max(abs(b), 1e-9 if n.endswith(("x", "y")) else 1e-6)
            worst = max(worst, abs(a - b) / scale)
    print(f"FMPy vs direct simulator over {len(rows)} points, {len(names)} outputs: worst relative difference {worst:.3e}")
    if worst > 1e-12:
        failures.append(f"FMPy and the direct run differ by {worst:.3e} (relative)")

# 3. The default FMU from standstill, with no start value set: the vertical hydro
# unit at rest, journals centred in their bearings (no radial load), films open.
res = simulate_fmu(os.path.join(out, "RotorBearing.fmu"), stop_time=0.5)
still = [n for n in res.dtype.names if n.startswith("bearings.") and n.endswith((".x", ".y", ".contact_force"))]
if not (np.all(res["shaft.speed"] == 0.0) if "shaft.speed" in res.dtype.names else True) \
        or any(np.any(res[n] != 0.0) for n in still):
    failures.append("the default FMU from standstill is not at rest: "
                    + ", ".join(f"{n} {np.max(np.abs(res[n])):.3e}" for n in still))
print(f"default FMU from shaft.speed = 0: {len(res)} points at rest")

# 4. A rub: 1e3 kg·m of unbalance at 3000 rpm presses the journals of the Jeffcott
# and vertical rotors onto their bushings; the run continues in contact for 1 s
# (equal 1 ms steps), the orbit at the clearance plus the penetration of the
# largest contact force under the steel contact law k = (π/4) E/(2(1 − ν²)) L.
import tomllib  # noqa: E402
for stem in ("jeffcott", "vertical_rotor"):
    path = os.path.join(out, stem + ".fmu")
    model = tomllib.load(open(os.path.join(root, "models", stem + ".toml"), "rb"))
    md = read_model_description(path)
    planes = [u["name"] for u in model["unbalance"]]
    start = {f"unbalance.{p}": 1e3 for p in planes}
    start["shaft.speed"] = 3000.0 * np.pi / 30.0
    start["solver.local_error_tolerance"] = 0.0
    start["solver.time_step"] = 1e-3
    names = [v.name for v in md.modelVariables if v.name.startswith("bearings.")
             and v.name.endswith((".x", ".y", ".contact_force"))]
    try:
        res = simulate_fmu(path, stop_time=1.0, output_interval=1e-3, start_values=start, output=names)
    except Exception as e:  # noqa: BLE001
        failures.append(f"{stem} rub at 1e3 kg·m: {e}")
        continue
    for b in model["bearings"]:
        n = b["name"]
        k = np.pi / 4 * 2.1e11 / (2 * (1 - 0.3**2)) * b["length"]
        orbit = np.max(np.hypot(res[f"bearings.{n}.x"], res[f"bearings.{n}.y"]))
        force = np.max(res[f"bearings.{n}.contact_force"])
        allowed = b["clearance"] * (1 + 1e-3) + force / k
        print(f"{stem} rub, bearing {n}: orbit {orbit * 1e6:.1f} µm, clearance {b['clearance'] * 1e6:.0f} µm, "
              f"peak contact force {force:.3e} N, allowed {allowed * 1e6:.1f} µm")
        if not (force > 0.0 and b["clearance"] < orbit <= allowed):
            failures.append(f"{stem} rub, bearing {n}: orbit {orbit} m outside ({b['clearance']}, {allowed}] m")

if failures:
    print("\n".join(failures), file=sys.stderr)
    sys.exit(1)
print(f"{len(fmus)} FMUs valid; FMPy run matches the Rust simulator")
