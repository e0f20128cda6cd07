"""An active magnetic bearing closed through the rotor FMU's force port under
libcosim, against the same rotor with the bearing built in.

    rotor.ports.amb.{x, y, vx, vy} → amb.{x, y, vx, vy}
    amb.{fx, fy}                   → rotor.ports.amb.{fx, fy}

The rotor is system/classic_disk_rotor_amb.toml (the damped classic rotor,
vertical, its non-drive-end bearing replaced by the port `amb`; the reduced
rotor with 4 fixed-interface modes), the controller the PD law of
system/amb_controller.py with k = 1 MN/m, c = 1000 N·s/m. The reference is
the rotor with that law built in as a linear bearing
(system/classic_disk_rotor_amb_reference.toml), run by FMPy at the rotor's
internal step (12.5 µs in every run). Both start at 1000 rpm with the
unbalance applied at t = 0; the communication steps are 25 µs and 12.5 µs
(the loop is stable up to 50 µs on this rotor, 10 µs on the full one:
docs/fmu.md, `--stability`).

The coupling error and its bound (docs/system.md). libcosim's fixed-step
master is a Jacobi scheme: it hands the outputs over after every step, so
over the step [t_n, t_n+1] the rotor holds the force the controller computed
from the rotor's state at t_n-1 — a lag τ between h and 2h (checked bit for
bit against `explicit_loop`). The coupled rotor is the reference rotor
driven by the force error

    δ(t) = K (x(t) − x(t − τ)) + C (v(t) − v(t − τ)),
    |δ| ≤ τ_max (K max|v| + C max|a|),  τ_max = 2h,

so (the rotor is linear and time-invariant at constant speed) the orbit error
is the convolution of δ with the reference rotor's impulse response g from a
force at the bearing to the journal's displacement there, and

    max|e| ≤ ∫₀ᵀ ‖g(s)‖ ds · 2h (K max|v| + C max|a|).

∫‖g‖ (m/N: the rotor's compliance summed over its whole response, at least
its static compliance 1/k) is the total variation of the reference's
response to unit step forces at the port (the 2×2 operator norm at every
internal step: the discrete rotor's exact ∞-to-∞ gain); max|v| and max|a|
are those of the reference run at every internal step, widened by the
relative orbit difference (the coupled run's own excess). A Gauss–Seidel
master (lag 0 … h) has τ_max = h.

usage: python system/amb_demo.py [--step S] [--duration S] [--out PREFIX]
       python system/amb_demo.py --stability   (the tight-loop map, docs/fmu.md)
"""
import argparse
import os
import shutil
import sys

import numpy as np
from fmpy import extract, read_model_description
from fmpy.fmi2 import FMU2Slave
from libcosimpy.CosimExecution import CosimExecution
from libcosimpy.CosimLogging import CosimLogLevel, log_output_level
from libcosimpy.CosimObserver import CosimObserver
from libcosimpy.CosimSlave import CosimLocalSlave

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
OUT = os.path.join(ROOT, "out")
ROTOR = os.path.join(OUT, "classic_disk_rotor_amb.fmu")
REFERENCE = os.path.join(OUT, "classic_disk_rotor_amb_reference.fmu")
CONTROLLER = os.path.join(OUT, "AmbController.fmu")

K = 1e6            # N/m, the bearing replaced (system/classic_disk_rotor_amb_reference.toml)
C = 1e3            # N·s/m
SPEED = 1000.0 * np.pi / 30.0  # rad/s (first critical 1113 rpm)
INTERNAL = 12.5e-6  # s, the rotor's internal step in every run
DURATION = 0.3      # s
STEP = 25e-6        # s, communication step of the demo (and STEP / 2)
AXES = ("x", "y", "vx", "vy")

# libcosim's debug log (every FMU load) off; warnings and errors still show.
log_output_level(CosimLogLevel.WARNING)


def coupled(h, duration=DURATION, k=K, c=C, internal=INTERNAL, speed=SPEED, modes=None):
    """The rotor FMU and the PD controller FMU under libcosim at communication
    step h (`modes`: the rotor's solver.reduced_modes, None: the model's);
    returns time, the port's motion (n × 4: x, y, vx, vy) at every
    communication point t_1 … t_n and the force the rotor held over each step
    (n × 2). A run whose orbit leaves 1 m (an unstable loop) stops there."""
    execution = CosimExecution.from_step_size(step_size=int(round(h * 1e9)))
    rotor = execution.add_local_slave(CosimLocalSlave(fmu_path=ROTOR, instance_name="rotor"))
    amb = execution.add_local_slave(CosimLocalSlave(fmu_path=CONTROLLER, instance_name="amb"))
    rv = {v.name.decode(): v.reference for v in execution.slave_variables(rotor)}
    av = {v.name.decode(): v.reference for v in execution.slave_variables(amb)}
    for name, value in [("solver.time_step", internal), ("unbalance_ramp_time", 0.0), ("shaft.speed", speed)]:
        execution.real_initial_value(rotor, rv[name], value)
    if modes is not None:
        execution.integer_initial_value(rotor, rv["solver.reduced_modes"], modes)
    execution.real_initial_value(amb, av["k"], k)
    execution.real_initial_value(amb, av["c"], c)
    for axis in AXES:
        execution.connect_real_variables(rotor, rv[f"ports.amb.{axis}"], amb, av[axis])
    for axis in ("fx", "fy"):
        execution.connect_real_variables(amb, av[axis], rotor, rv[f"ports.amb.{axis}"])
    observer = CosimObserver.create_last_value()
    execution.add_observer(observer)
    motion, force = [], []
    port = [rv[f"ports.amb.{a}"] for a in AXES]
    inputs = [rv["ports.amb.fx"], rv["ports.amb.fy"]]
    steps = int(round(duration / h))
    for n in range(steps):
        if not execution.step(1):
            if n > 0 and motion and np.max(np.abs(motion[-1][:2])) > 1e-4:
                # A diverging loop's force has left the range the rotor FMU
                # declares for its port (± 1000 g times the rotor's mass) and
                # the FMU refuses it: the loop diverged (a short record).
                break
            raise RuntimeError(f"co-simulation step {n} failed at t = {n * h:.4f} s")
        motion.append(observer.last_real_values(rotor, port))
        # The force the rotor held over this step (its input as observed after it).
        force.append(observer.last_real_values(rotor, inputs))
        if not np.all(np.isfinite(motion[-1])) or np.max(np.abs(motion[-1][:2])) > 1.0:
            break  # diverged (an unstable loop): the orbit left any physical size
    t = h * np.arange(1, len(motion) + 1)
    return t, np.array(motion), np.array(force)


class FmpyRotor:
    """A rotor FMU with a port, stepped by FMPy (an independent master) with
    the port force from a Python law."""

    def __init__(self, path, port):
        self.md = read_model_description(path)
        self.dir = extract(path)
        self.vr = {v.name: v.valueReference for v in self.md.modelVariables}
        self.port = port

    def run(self, law, duration=DURATION, step=INTERNAL, internal=INTERNAL, unbalance=True, speed=SPEED):
        """Time and port motion (x, y, vx, vy) at every communication point
        t_1 … t_n (step `step`); over the step [t_n, t_n+1] the port holds
        the force law(n, motion) (N, x and y), motion[m] being the port's
        state at t_m (motion[0] = 0: the rotor starts centred, at rest); the
        unbalance acts from t = 0 if `unbalance`."""
        fmu = FMU2Slave(guid=self.md.guid, unzipDirectory=self.dir,
                        modelIdentifier=self.md.coSimulation.modelIdentifier, instanceName="rotor")
        fmu.instantiate()
        fmu.setupExperiment(startTime=0.0)
        fmu.enterInitializationMode()
        values = {"solver.time_step": internal, "unbalance_ramp_time": 0.0, "shaft.speed": speed}
        if not unbalance:
            values["unbalance.disk"] = 0.0
        fmu.setReal([self.vr[n] for n in values], list(values.values()))
        fmu.exitInitializationMode()
        inputs = [self.vr[f"ports.{self.port}.fx"], self.vr[f"ports.{self.port}.fy"]]
        outputs = [self.vr[f"ports.{self.port}.{a}"] for a in AXES]
        steps = int(round(duration / step))
        motion = [np.zeros(4)]
        for n in range(steps):
            fmu.setReal(inputs, [float(f) for f in law(n, motion)])
            fmu.doStep(currentCommunicationPoint=n * step, communicationStepSize=step)
            motion.append(np.array(fmu.getReal(outputs)))
        fmu.terminate()
        fmu.freeInstance()
        return step * np.arange(1, steps + 1), np.array(motion[1:])

    def close(self):
        shutil.rmtree(self.dir, ignore_errors=True)


class Reference(FmpyRotor):
    """The reference rotor (the bearing built in), stepped at its internal
    step; its port `probe` applies a constant test force from t = 0+."""

    def __init__(self, path=REFERENCE):
        super().__init__(path, "probe")

    def run(self, duration=DURATION, unbalance=True, force=(0.0, 0.0), internal=INTERNAL, speed=SPEED):
        return super().run(lambda n, motion: force, duration, internal, internal, unbalance, speed)


def explicit_loop(h, delay, duration=DURATION, k=K, c=C, internal=INTERNAL):
    """The PD loop closed in Python around the rotor FMU (FMPy), the force
    over [t_n, t_n+1] computed from the port's state at t_(n−delay): delay 1
    is libcosim's fixed-step (Jacobi) coupling, delay 0 a Gauss–Seidel
    master (step the rotor, read it, set the force, step again)."""
    def law(n, motion):
        s = motion[n - delay] if n >= delay else motion[0]
        return -(k * s[0] + c * s[2]), -(k * s[1] + c * s[3])
    rotor = FmpyRotor(ROTOR, "amb")
    try:
        return rotor.run(law, duration, h, internal)
    finally:
        rotor.close()


def impulse_norm(reference, duration=DURATION, force=1.0):
    """∫₀ᵀ ‖g(s)‖ ds (m/N) of the reference rotor from a force at the port to
    the journal's displacement there: the total variation of the responses to
    unit step forces in x and in y, with the 2×2 operator norm at every
    internal step (the Newmark rotor is a linear time-invariant map of the
    held force sequence, so this sum is its exact ∞-to-∞ gain)."""
    _, sx = reference.run(duration, unbalance=False, force=(force, 0.0))
    _, sy = reference.run(duration, unbalance=False, force=(0.0, force))
    dx = np.diff(np.vstack([np.zeros(4), sx])[:, :2], axis=0) / force
    dy = np.diff(np.vstack([np.zeros(4), sy])[:, :2], axis=0) / force
    return float(sum(np.linalg.norm(np.column_stack([a, b]), 2) for a, b in zip(dx, dy)))


def compare(h, motion, reference_t, reference_motion, g1, lag=2):
    """A coupled run's port motion (at t_1 … t_n, step h) against the
    reference: the orbit difference, its max (m) and bound (m) for a force
    computed at most lag·h before it acts (2 for libcosim's fixed step, 1
    for a Gauss–Seidel master)."""
    stride = int(round(h / (reference_t[1] - reference_t[0])))
    ref = reference_motion[stride - 1::stride][: len(motion)]
    difference = np.linalg.norm(motion[:, :2] - ref[:, :2], axis=1)
    # Over a lag of m internal steps the displacement changes by at most
    # m · hi · max|v| (Newmark: x_j+1 − x_j = hi (v_j + v_j+1)/2) and the
    # velocity by m · max|v_j+1 − v_j|: max|a| is that difference over hi.
    v = np.linalg.norm(reference_motion[:, 2:], axis=1)
    states = np.vstack([np.zeros(4), reference_motion])
    a = np.linalg.norm(np.diff(states[:, 2:], axis=0), axis=1) / (reference_t[1] - reference_t[0])
    # The coupled motion's velocities and accelerations exceed the
    # reference's by its own difference: widened by the relative orbit
    # difference.
    widen = 1.0 + np.max(difference) / np.max(np.linalg.norm(ref[:, :2], axis=1))
    bound = g1 * lag * h * (K * np.max(v) + C * np.max(a)) * widen
    return dict(h=h, motion=motion, reference=ref, difference=difference,
                max_difference=float(np.max(difference)), bound=float(bound),
                max_v=float(np.max(v)), max_a=float(np.max(a)))


def stability(modes=(None, 0), ks=(1e6, 1e7, 1e8), steps=(2.5e-6, 5e-6, 1e-5, 2.5e-5, 5e-5, 1e-4, 2e-4),
              duration=0.2):
    """For the rotor as modelled (4 fixed-interface modes) and the full rotor,
    each PD stiffness k (c = 1000 N·s/m) and communication step h: the peak
    journal orbit over `duration` relative to the peak at the smallest step
    (inf: the orbit left 1 m). Past the first diverging step the row stops."""
    table = []
    for m in modes:
        for k in ks:
            base = None
            for h in steps:
                t, motion, _ = coupled(h, duration, k=k, c=C, internal=min(h, INTERNAL), modes=m)
                finished = len(t) == int(round(duration / h))
                peak = float(np.max(np.linalg.norm(motion[:, :2], axis=1))) if finished else np.inf
                base = base or peak
                table.append(("full" if m == 0 else "reduced", k, C, h, peak, peak / base))
                if peak / base > 10:
                    break
    return table


def plot(results, prefix):
    """Orbits of the reference and of each coupled run, the difference
    against time with its bound (PNG), and the series (CSV)."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(1, 2, figsize=(13, 5.5))
    first = results[0]
    ax[0].plot(first["reference"][:, 0] * 1e6, first["reference"][:, 1] * 1e6, "k", lw=1.6,
               label="built-in linear bearing (FMPy)")
    for r, color in zip(results, ["tab:red", "tab:blue", "tab:green"]):
        t = r["h"] * np.arange(1, len(r["motion"]) + 1)
        tag = f"h = {r['h'] * 1e6:g} µs"
        ax[0].plot(r["motion"][:, 0] * 1e6, r["motion"][:, 1] * 1e6, color=color, lw=0.8, ls="--",
                   label=f"AMB FMU through the port, {tag} (libcosim)")
        ax[1].semilogy(t, np.maximum(r["difference"], 1e-15) * 1e6, color=color,
                       label=f"{tag}: max {r['max_difference'] * 1e6:.3g} µm")
        ax[1].axhline(r["bound"] * 1e6, color=color, ls=":", label=f"bound at {tag}: {r['bound'] * 1e6:.3g} µm")
    ax[0].set_aspect("equal", "datalim")
    ax[0].set_xlabel("x at the bearing (µm)")
    ax[0].set_ylabel("y (µm)")
    ax[0].set_title("journal orbit at the magnetic bearing (node 7)")
    ax[0].legend(fontsize=8)
    ax[1].set_ylim(1e-4, None)
    ax[1].set_xlabel("time (s)")
    ax[1].set_ylabel("|orbit difference| (µm)")
    ax[1].set_title("coupled − built-in, and the bound from h")
    ax[1].legend(fontsize=8)
    fig.suptitle(f"PD magnetic bearing (k = {K:.0e} N/m, c = {C:g} N·s/m) on the damped classic rotor "
                 f"at {SPEED * 30 / np.pi:.0f} rpm")
    fig.tight_layout()
    fig.savefig(prefix + ".png", dpi=100)
    plt.close(fig)
    # One row per communication point of the finest run; a coarser run's
    # columns are empty between its points.
    fine = results[-1]
    with open(prefix + ".csv", "w") as f:
        f.write("time_s,x_reference_m,y_reference_m," + ",".join(
            f"x_h{r['h'] * 1e6:g}us_m,y_h{r['h'] * 1e6:g}us_m,difference_h{r['h'] * 1e6:g}us_m" for r in results) + "\n")
        for n in range(len(fine["motion"])):
            t = (n + 1) * fine["h"]
            row = [f"{t:.9g}"] + [f"{x:.17g}" for x in fine["reference"][n, :2]]
            for r in results:
                stride = int(round(r["h"] / fine["h"]))
                m = (n + 1) // stride - 1
                on = (n + 1) % stride == 0 and m < len(r["motion"])
                row += [f"{x:.17g}" for x in (*r["motion"][m, :2], r["difference"][m])] if on else ["", "", ""]
            f.write(",".join(row) + "\n")


def demo(h=STEP, duration=DURATION):
    """The libcosim coupling at h and h/2 and a Gauss–Seidel loop at h
    against the reference; returns the three comparisons and ∫‖g‖ (m/N)."""
    reference = Reference()
    try:
        g1 = impulse_norm(reference, duration)
        ref_t, ref_motion = reference.run(duration)
    finally:
        reference.close()
    results = [compare(step, coupled(step, duration)[1], ref_t, ref_motion, g1) for step in (h, h / 2)]
    results.append(compare(h, explicit_loop(h, 0, duration)[1], ref_t, ref_motion, g1, lag=1))
    return results, g1


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--step", type=float, default=STEP, help="communication step h (s); also runs h/2")
    parser.add_argument("--duration", type=float, default=DURATION)
    parser.add_argument("--out", default=os.path.join(OUT, "amb_demo"))
    parser.add_argument("--stability", action="store_true", help="print the tight-loop stability map")
    args = parser.parse_args()
    if args.stability:
        table = stability()
        with open(args.out + "_stability.csv", "w") as f:
            f.write("rotor,k_N_per_m,c_Ns_per_m,step_s,peak_orbit_m,peak_over_smallest_step\n")
            for row in table:
                f.write(",".join(str(x) for x in row) + "\n")
        print("rotor     k (N/m)  c (N·s/m)  h (µs)  peak orbit (µm)  / at the smallest h")
        for rotor, k, c, h, peak, ratio in table:
            print(f"{rotor:8}  {k:7.0e}  {c:9.0f}  {h * 1e6:6.1f}  {peak * 1e6:15.4g}  {ratio:10.4g}"
                  f"{'  unstable' if ratio > 10 else ''}")
        print(f"→ {args.out}_stability.csv")
        return 0
    results, g1 = demo(args.step, args.duration)
    plot(results[:2], args.out)
    print(f"impulse response ∫‖g‖ = {g1:.4g} m/N ({g1 * K:.3g} × the static compliance 1/k at the bearing)")
    names = ["libcosim", "libcosim", "Gauss–Seidel (FMPy loop)"]
    for name, r in zip(names, results):
        print(f"{name}, h = {r['h'] * 1e6:g} µs: max orbit difference {r['max_difference'] * 1e6:.4g} µm, "
              f"bound {r['bound'] * 1e6:.4g} µm (max|v| {r['max_v']:.4g} m/s, max|a| {r['max_a']:.4g} m/s²), "
              f"peak orbit {np.max(np.linalg.norm(r['reference'][:, :2], axis=1)) * 1e6:.4g} µm")
    print(f"halving h divides the difference by {results[0]['max_difference'] / results[1]['max_difference']:.3f} "
          f"→ {args.out}.png/.csv")
    return 0


if __name__ == "__main__":
    sys.exit(main())
