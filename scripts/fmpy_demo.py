"""Simulate the packed FMU with FMPy as a user would: a run-up of the hydro unit
from 140 to 160 rpm with the speed given as an input signal; writes a CSV of all
outputs and a PNG of the bearing and probe orbits.

usage: .venv/bin/python scripts/fmpy_demo.py out/RotorBearing.fmu out/fmpy_hydro_unit
"""
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
from fmpy import read_model_description, simulate_fmu
from fmpy.util import write_csv

fmu, prefix = sys.argv[1], sys.argv[2]
md = read_model_description(fmu)
outputs = [v.name for v in md.modelVariables if v.causality == "output"]
t = np.linspace(0.0, 30.0, 61)
rpm = np.interp(t, [0.0, 5.0, 25.0, 30.0], [140.0, 140.0, 160.0, 160.0])
signal = np.array(list(zip(t, rpm * np.pi / 30.0)), dtype=[("time", np.float64), ("shaft.speed", np.float64)])
res = simulate_fmu(fmu, stop_time=30.0, output_interval=0.005, input=signal, output=outputs,
                   start_values={"unbalance_ramp_time": 2.0})
write_csv(prefix + ".csv", res)
pairs = sorted({n.rsplit(".", 1)[0] for n in outputs if n.endswith(".x")})
fig, axes = plt.subplots(1, len(pairs), figsize=(4.2 * len(pairs), 4.4))
late = res["time"] > 20.0
for ax, p in zip(np.atleast_1d(axes), pairs):
    ax.plot(res[p + ".x"][late] * 1e6, res[p + ".y"][late] * 1e6, lw=0.8)
    ax.set_title(p, fontsize=9)
    ax.set_xlabel("x (µm)")
    ax.set_ylabel("y (µm)")
    ax.set_aspect("equal", "datalim")
fig.suptitle(f"{md.modelName}: orbits from FMPy, 20–30 s")
fig.tight_layout()
fig.savefig(prefix + "_orbits.png", dpi=110)
print(f"FMPy: {len(res)} samples of {len(outputs)} outputs → {prefix}.csv, {prefix}_orbits.png")
