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

# Start-up from standstill: the rotor FMU starts at shaft.speed = 0 with its
# journals at rest; the speed follows the governor's set-point ramp to rated speed.
r = run(rotor, plant, 75.0, SCENARIOS["startup"]["plant"])
speed, t = r["plant.speed"], r["time"]
check(SCENARIOS["startup"]["plant"]["start_speed"] == 0.0 and r["rotor.shaft.speed"][0] == 0.0,
      "start-up from standstill: the rotor FMU's first step is at 0 rpm")
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

# Emergency stop to rest, tilting-pad and plain guide bearings: gate closed,
# brake b = 0.2 per unit on, windage l = 0.05 (ω/ω_r)²: with the gate shut,
# J dω/dt = −T_r (b + l u²), u = ω/ω_r, stops after
# t = J ω_r / (T_r √(b l)) · atan(√(l/b)) = 34.3 s (bearing friction ~1e-4 of it).
spec = SCENARIOS["shutdown"]
J, T_r, b, l = 4.8e6, 1.02e7, spec["plant"]["brake_torque"], 0.05
stop_time = J * RATED / (T_r * np.sqrt(b * l)) * np.arctan(np.sqrt(l / b))
for bearing, fmu in spec["rotors"].items():
    r = run(os.path.join(OUT, fmu), plant, spec["duration"], spec["plant"])
    speed, t = r["plant.speed"], r["time"]
    rest = np.flatnonzero(speed == 0.0)
    stopped = t[rest[0]] - spec["plant"]["shutdown_time"] if rest.size else np.inf
    check(rest.size > 0 and np.all(speed[rest[0]:] == 0.0) and np.all(r["rotor.shaft.speed"][rest[0] + 1:] == 0.0),
          f"{bearing}: the unit comes to rest and stays there (rotor FMU at 0 rpm)")
    check(abs(stopped / stop_time - 1.0) < 0.03,
          f"{bearing}: stops {stopped:.2f} s after the trip, braking analysis {stop_time:.2f} s")
    check(np.all(r["rotor.friction_torque"] >= 0.0), f"{bearing}: bearing friction torque never drives the unit")

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

# Breakaway: the horizontal Jeffcott rotor at rest on its plain bearings feeds its
# breakaway torque μ N R to the plant (μ = 0.2, R = 20 mm, N = the rotor's weight
# 244.6 N: a 20 kg disk on 0.5 m of 40 mm steel shaft), which holds the unit at
# standstill until the turbine torque exceeds it; once the journals lift off,
# only the film's shear is left.
spec = SCENARIOS["breakaway"]
r = run(os.path.join(OUT, "jeffcott.fmu"), plant, spec["duration"], spec["plant"], rotor_params=spec["rotor_params"])
speed, torque, friction = r["plant.speed"], r["plant.turbine_torque"], r["rotor.friction_torque"]
weight = (20.0 + 7850.0 * np.pi * 0.02**2 * 0.5) * 9.81
breakaway = 0.2 * weight * 0.02
check(abs(friction[0] / breakaway - 1.0) < 1e-6, f"friction torque at rest {friction[0]:.6f} N·m = μ N R = {breakaway:.6f} N·m")
k = int(np.flatnonzero(speed > 0.0)[0])
check(np.all(speed[:k] == 0.0) and torque[k - 1] <= breakaway and torque[k] >= 0.97 * breakaway,
      f"held at rest until the turbine torque ({torque[k - 1]:.4f} → {torque[k]:.4f} N·m) exceeds the breakaway torque")
# Film shear only (Petroff, two bearings): 4π μ_oil ω R³ L / C at the end speed, within the
# eccentricity factor 1/√(1 − ε²) ≤ 1.3 of the run.
petroff = 4 * np.pi * 0.02 * speed[-1] * 0.02**3 * 0.02 / 100e-6
check(np.min(friction[k:]) < 0.05 * breakaway and petroff <= friction[-1] <= 1.3 * petroff,
      f"after lift-off only film shear is left: minimum {np.min(friction[k:]):.4f} N·m, "
      f"{friction[-1]:.4f} N·m at {speed[-1] * 30 / np.pi:.0f} rpm (Petroff {petroff:.4f} N·m)")

if failures:
    sys.exit(f"{len(failures)} coupled-system checks failed")
print("coupled system: all checks passed")
