"""The PD magnetic bearing closed through the rotor FMU's port under libcosim
(system/amb_demo.py): checks of the coupling scheme, the reference, the
orbit against its error bound at h and h/2, and the communication steps at
which the loop stays stable. Run by tests/system_amb.rs; argv: repo root.
Needs out/AmbController.fmu, out/classic_disk_rotor_amb*.fmu and
out/classic_disk_rotor_damped.fmu (scripts/test.sh builds them)."""
import os
import sys

import numpy as np
from fmpy import simulate_fmu

sys.path.insert(0, os.path.join(sys.argv[1], "system"))
import amb_demo as amb  # noqa: E402

failures = []


def check(ok, text):
    print(("ok   " if ok else "FAIL ") + text, flush=True)
    if not ok:
        failures.append(text)


# The reference is the damped classic rotor: standing vertical (axial
# gravity) with its port idle, it runs as the shipped horizontal model with
# gravity off (full rotors, 50 ms at 1000 rpm, unbalance from t = 0).
common = {"shaft.speed": amb.SPEED, "solver.time_step": amb.INTERNAL, "unbalance_ramp_time": 0.0,
          "solver.reduced_modes": 0}
ref = simulate_fmu(amb.REFERENCE, stop_time=0.05, output_interval=amb.INTERNAL, start_values=common,
                   output=["ports.probe.x", "ports.probe.y"])
shipped = simulate_fmu(os.path.join(amb.OUT, "classic_disk_rotor_damped.fmu"), stop_time=0.05,
                       output_interval=amb.INTERNAL, start_values=dict(common, gravity=False),
                       output=["bearings.non_drive_end.x", "bearings.non_drive_end.y"])
peak = np.max(np.abs(ref["ports.probe.x"]))
diff = max(np.max(np.abs(ref["ports.probe.x"] - shipped["bearings.non_drive_end.x"])),
           np.max(np.abs(ref["ports.probe.y"] - shipped["bearings.non_drive_end.y"])))
check(peak > 1e-6 and diff <= 1e-12 * peak,
      f"the reference rotor is models/classic_disk_rotor_damped.toml: journal at node 7 equal to {diff / peak:.1e} of {peak * 1e6:.2f} µm")

# libcosim's fixed-step coupling is the PD loop with the force over
# [t_n, t_n+1] computed from the rotor's state at t_(n-1): its force is that
# law of its own motion bit for bit, and its motion the explicit loop's in
# FMPy to round-off. Not bit for bit: libcosim computes the communication
# points from integer nanoseconds, FMPy as n h, and where they differ in the
# last bit the rotor's accuracy-controlled steps are planned from a span that
# differs in its last bits (8.6e-13 m of a 45 µm orbit, measured); the bound
# is 1e-6 of each coordinate's range, against the difference between this Jacobi loop
# and a Gauss-Seidel one (about 6e-3 of the orbit, below).
h = amb.STEP
t, motion, force = amb.coupled(h, 0.05)
_, replica = amb.explicit_loop(h, 1, 0.05)
law = -(amb.K * motion[:, :2] + amb.C * motion[:, 2:])
gap = float(np.max(np.abs(motion - replica) / np.max(np.abs(replica), axis=0)))
check(gap <= 1e-6 and np.array_equal(force[2:], law[:-2]) and not force[:2].any(),
      "libcosim holds over each step the PD force of the state one step earlier (lag h … 2h), bit for bit; "
      f"its orbit is the explicit loop's in FMPy to {gap:.1e} of each coordinate's range")

# The orbit at h and h/2 within the bound derived from h; first order; the
# bound not vacuous; a Gauss–Seidel master (lag 0 … h) within its own bound.
(r1, r2, gs), g1 = amb.demo()
check(g1 > 1.0 / amb.K, f"∫‖g‖ = {g1:.4g} m/N exceeds the static compliance 1/k = {1 / amb.K:.1e} m/N at the bearing")
peak = np.max(np.linalg.norm(r1["reference"][:, :2], axis=1))
for r in (r1, r2):
    check(r["max_difference"] <= r["bound"],
          f"h = {r['h'] * 1e6:g} µs: max orbit difference {r['max_difference'] * 1e6:.4g} µm within the bound "
          f"{r['bound'] * 1e6:.4g} µm (peak orbit {peak * 1e6:.2f} µm)")
    check(r["max_difference"] >= 0.1 * r["bound"],
          f"h = {r['h'] * 1e6:g} µs: the bound is not vacuous (difference {r['max_difference'] / r['bound']:.2f} of it)")
ratio = r1["max_difference"] / r2["max_difference"]
check(1.6 <= ratio <= 2.3, f"halving h divides the difference by {ratio:.3f} (first order: 2)")
check(gs["max_difference"] <= gs["bound"] and gs["max_difference"] < 0.6 * r1["max_difference"],
      f"a Gauss–Seidel loop at h = {h * 1e6:g} µs: {gs['max_difference'] * 1e6:.4g} µm, within its bound "
      f"{gs['bound'] * 1e6:.4g} µm and below libcosim's {r1['max_difference'] * 1e6:.4g} µm")


def peak_orbit(h, duration, k, modes):
    t, motion, _ = amb.coupled(h, duration, k=k, internal=min(h, amb.INTERNAL), modes=modes)
    if len(t) < int(round(duration / h)):
        return np.inf
    return float(np.max(np.linalg.norm(motion[:, :2], axis=1)))


# Stability (docs/fmu.md): the delayed damping destabilizes the rotor's
# highest modes past 1.5 h ω_max ≈ π/2, the delayed stiffness the loop past
# 1.5 h k ≈ c (c = 1000 N·s/m). Stable: the peak orbit over 0.2 s within
# 10 % of the one at h = 12.5 µs; unstable: ten times it or diverged.
cases = [("reduced (4 modes), k = 1e6", 1e6, None, 12.5e-6, 50e-6, 100e-6),
         ("reduced (4 modes), k = 1e7", 1e7, None, 12.5e-6, 25e-6, 50e-6),
         ("full rotor, k = 1e6", 1e6, 0, 12.5e-6, 10e-6, 25e-6)]
for name, k, modes, base_step, stable, unstable in cases:
    base = peak_orbit(base_step, 0.2, k, modes)
    a, b = peak_orbit(stable, 0.2, k, modes), peak_orbit(unstable, 0.2, k, modes)
    check(abs(a / base - 1.0) < 0.1 and b > 10.0 * base,
          f"{name}: stable at h = {stable * 1e6:g} µs (peak {a / base:.3f} of h = {base_step * 1e6:g} µs), "
          f"unstable at {unstable * 1e6:g} µs (peak {b / base:.3g} of it)")
    if k == 1e7:
        # The recommended step h = c/(3k) (docs/fmu.md), the stiffness limit
        # halved: between the stable 25 µs and the diverging 50 µs.
        rule = amb.C / (3.0 * k)
        r = peak_orbit(rule, 0.2, k, modes) / base
        check(abs(r - 1.0) < 0.01, f"{name}: the recommended step c/(3k) = {rule * 1e6:.1f} µs is stable (peak {r:.4f})")

if failures:
    sys.exit(f"{len(failures)} magnetic-bearing checks failed")
print("magnetic bearing through the port: all checks passed")
