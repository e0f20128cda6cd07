"""Coupled plant + rotor-bearing FMUs under libcosim: physics checks on short
scenarios. Run by tests/system.rs; argv: repo root. Needs out/HydroPlant.fmu and
the packed rotor FMUs (scripts/test.sh builds them)."""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(sys.argv[1], "system"))
from couple import OUT, RATED, SCENARIOS, run  # noqa: E402

failures = []


def check(ok, text):
    print(("ok   " if ok else "FAIL ") + text)
    if not ok:
        failures.append(text)


plant = os.path.join(OUT, "HydroPlant.fmu")
rotor = os.path.join(OUT, "RotorBearing.fmu")

# Start-up: the speed follows the governor's set-point ramp to rated speed.
r = run(rotor, plant, 75.0, SCENARIOS["startup"]["plant"])
speed, t = r["plant.speed"], r["time"]
check(abs(speed[-1] / RATED - 1.0) < 0.01, f"start-up ends at rated speed: {speed[-1] * 30 / np.pi:.2f} rpm")
check(np.max(speed) < 1.05 * RATED, f"start-up overshoot below 5 %: peak {np.max(speed) * 30 / np.pi:.2f} rpm")
# libcosim hands outputs over at communication points: the rotor runs at the
# plant's speed of the previous step.
check(np.allclose(r["rotor.shaft.speed"][1:], speed[:-1], rtol=1e-12), "the rotor FMU runs at the plant's speed (one step later)")
# The rotor's friction torque is positive and grows with speed (shear ∝ ω).
f = r["rotor.friction_torque"]
check(np.all(f >= 0.0) and f[-1] > 5.0 * f[np.searchsorted(t, 10.0)], f"friction torque positive and growing: {f[np.searchsorted(t, 10.0)]:.1f} → {f[-1]:.1f} N·m")
# The unbalance response grows as the speed rises (forcing ∝ ω²; the run passes 0 → 150 rpm).
radius = np.hypot(r["rotor.bearings.generator_guide.x"], r["rotor.bearings.generator_guide.y"])
early = np.max(radius[(t > 15) & (t < 20)])
mid = np.max(radius[(t > 35) & (t < 40)])
late = np.max(radius[t > 65])
check(late > 1.3 * mid > 1.3 * 1.3 * early,
      f"bearing response grows with speed: {early * 1e6:.3f} → {mid * 1e6:.3f} → {late * 1e6:.3f} µm")

# Load rejection: overspeed while the gate closes, then the governor recovers.
r = run(rotor, plant, 60.0, SCENARIOS["rejection"]["plant"])
speed, t, gate = r["plant.speed"], r["time"], r["plant.gate"]
check(np.max(speed) > 1.1 * RATED, f"overspeed after rejection: {np.max(speed) * 30 / np.pi:.1f} rpm")
check(gate[np.searchsorted(t, 12.0)] < 0.1, f"gate closed after rejection: {gate[np.searchsorted(t, 12.0)]:.3f}")
check(abs(speed[-1] / RATED - 1.0) < 0.02, f"governor recovers rated speed: {speed[-1] * 30 / np.pi:.2f} rpm")
# Torque signs: after rejection the electrical torque is zero and turbine torque drives the deceleration.
after = t > 6.0
check(np.all(np.abs(r["plant.electric_torque"][after]) < 1e-9), "no electrical torque after rejection")

# Run-up from standstill through a critical speed (damped classic rotor, first critical
# 116.4 rad/s = 1111 rpm): the orbit peaks near the critical and falls after it.
spec = SCENARIOS["critical"]
r = run(os.path.join(OUT, "classic_disk_rotor_damped.fmu"), plant, spec["duration"], spec["plant"],
        rotor_params=spec["rotor_params"])
speed = r["plant.speed"] * 30 / np.pi
# Orbit about the static (gravity) position of the journal.
x, y = r["rotor.bearings.drive_end.x"], r["rotor.bearings.drive_end.y"]
radius = np.hypot(x - x[0], y - y[0])
k = int(np.argmax(radius))
check(speed[0] < 1.0 and speed[-1] > 1900.0, f"run-up from standstill to {speed[-1]:.0f} rpm")
check(abs(speed[k] / 1111.3 - 1.0) < 0.1, f"orbit peaks at {speed[k]:.0f} rpm, near the 1111 rpm critical")
check(radius[-1] < 0.5 * radius[k] and radius[k] > 3.0 * radius[np.searchsorted(speed, 700.0)],
      f"response rises into and falls after the critical: {radius[np.searchsorted(speed, 700.0)] * 1e6:.2f} → {radius[k] * 1e6:.2f} → {radius[-1] * 1e6:.2f} µm")

if failures:
    sys.exit(f"{len(failures)} coupled-system checks failed")
print("coupled system: all checks passed")
