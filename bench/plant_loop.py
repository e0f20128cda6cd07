"""The FMPy plant loop of issue 28: a plant study driving the FMU as FMPy's
FMU2Slave (not simulate_fmu), fmi2DoStep every 5 ms and every output read with
one fmi2GetReal after each step, on the shipped hydro units and the
three-guide-bearing unit at rated speed with their unbalance, from the settled
state the FMU initializes (fmi2ExitInitializationMode: static equilibrium at
the start speed, the unbalance applied at once).

    .venv/bin/python bench/plant_loop.py [--seconds 12] [--window 2] [--runs 3] [--units A,B] [--fmu-dir out]
        [--out bench/plant_loop_results.md]

Needs the FMUs in out/ (bench/run_all.sh packs them: `bash fmu_pack.sh
--platforms linux64 --model models/NAME.toml`) and a C compiler (`cc`) for the
no-op library of the FMPy ceiling.

Configurations: the internal step (`solver.time_step`) fixed at 1 ms and at
5 ms (`solver.local_error_tolerance` = 0 where the FMU declares it),
accuracy-controlled stepping when the FMU declares that parameter (its start
value when non-zero, else --tolerance; `solver.time_step`, the largest step,
at its start value), and the FMU's
defaults (no parameter set) unless they are one of these, which is then marked
"(FMU default)". Each is timed
over the whole loop (wall clock around doStep + getReal, median of --runs
runs) and gives:

- real-time factor: simulated seconds / wall seconds;
- µs per communication point, split into fmi2DoStep and fmi2GetReal of all
  outputs;
- orbit error: against a reference run with a 0.05 ms internal step on the
  same communication points (equal steps), the largest distance between the two journal
  positions (x, y of bearings.<name>) over the last --window seconds, over
  every bearing, divided by that bearing's reference orbit peak-to-peak
  amplitude there (the larger of the x and y ranges); the worst bearing is
  reported.

The FMPy ceiling: the same FMU2Slave.doStep and getReal calls (ctypes
marshalling, status check, the list of values) with the two C functions
replaced by ones that return fmi2OK at once (a no-op library compiled with
cc), measured in the same run: what FMPy itself costs per communication point.
"""
import argparse
import ctypes
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
import tomllib

from fmpy import extract, read_model_description
from fmpy.fmi2 import FMU2Slave

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), ".."))
COMM = 5e-3
REFERENCE_STEP = 5e-5
TOLERANCE_PARAMETER = "solver.local_error_tolerance"
# Model file and packed FMU (scripts/test.sh packs hydro_unit as RotorBearing.fmu).
UNITS = [
    ("hydro_unit", "RotorBearing.fmu"),
    ("hydro_unit_plain", "hydro_unit_plain.fmu"),
    ("hydro_unit_brackets", "hydro_unit_brackets.fmu"),
    ("hydro_unit_three_guide", "hydro_unit_three_guide.fmu"),
]

NOOP_C = """
int fmi2DoStep(void *c, double t, double h, int no_set) { return 0; }
int fmi2GetReal(void *c, const unsigned int *vr, unsigned long n, double *v) { return 0; }
"""


class Unit:
    """A packed FMU of a model file: its description, rated speed, outputs."""

    def __init__(self, model, fmu, folder):
        self.model = model
        self.path = os.path.join(folder, fmu)
        if not os.path.exists(self.path):
            sys.exit(f"plant_loop.py: {self.path} missing: bash fmu_pack.sh --platforms linux64 "
                     f"--model models/{model}.toml")
        with open(os.path.join(ROOT, "models", model + ".toml"), "rb") as f:
            self.rpm = float(tomllib.load(f)["speed_rpm"])
        self.md = read_model_description(self.path)
        self.vars = {v.name: v for v in self.md.modelVariables}
        self.outputs = [v.valueReference for v in self.md.modelVariables if v.causality == "output"]
        bearings = sorted({n.split(".")[1] for n in self.vars
                           if n.startswith("bearings.") and n.endswith(".x")
                           and n.replace(".x", ".y") in self.vars},
                          key=lambda b: self.vars[f"bearings.{b}.x"].valueReference)
        self.journal = [(self.outputs.index(self.vars[f"bearings.{b}.x"].valueReference),
                         self.outputs.index(self.vars[f"bearings.{b}.y"].valueReference)) for b in bearings]
        self.bearings = bearings
        self.dir = extract(self.path)

    def start(self, name):
        v = self.vars.get(name)
        return None if v is None or v.start is None else float(v.start)

    def instance(self, params):
        fmu = FMU2Slave(guid=self.md.guid, unzipDirectory=self.dir,
                        modelIdentifier=self.md.coSimulation.modelIdentifier, instanceName=self.model)
        fmu.instantiate()
        for name, value in params.items():
            fmu.setReal([self.vars[name].valueReference], [value])
        fmu.setReal([self.vars["shaft.speed"].valueReference], [self.rpm * 3.141592653589793 / 30.0])
        return fmu

    def run(self, params, seconds, keep=True):
        """The plant loop; returns (wall s, doStep s, getReal s, journal samples)."""
        fmu = self.instance(params)
        fmu.setupExperiment(startTime=0.0, stopTime=seconds + COMM)
        fmu.enterInitializationMode()
        fmu.exitInitializationMode()
        count = round(seconds / COMM)
        outs, journal = self.outputs, []
        do_step, get_real = fmu.doStep, fmu.getReal
        clock = time.perf_counter
        t_step = t_get = 0.0
        begin = clock()
        for k in range(count):
            a = clock()
            do_step(k * COMM, COMM)
            b = clock()
            values = get_real(outs)
            c = clock()
            t_step += b - a
            t_get += c - b
            if keep:
                journal.append([(values[i], values[j]) for i, j in self.journal])
        wall = clock() - begin
        fmu.terminate()
        fmu.freeInstance()
        return wall, t_step, t_get, journal

    def close(self):
        shutil.rmtree(self.dir, ignore_errors=True)


def orbit_error(run, reference, window):
    """Worst bearing's largest journal distance from the reference over the
    last `window` communication points, over its reference orbit's
    peak-to-peak amplitude."""
    worst = 0.0
    for b in range(len(reference[0])):
        ref = [p[b] for p in reference[-window:]]
        got = [p[b] for p in run[-window:]]
        p2p = max(max(x for x, _ in ref) - min(x for x, _ in ref),
                  max(y for _, y in ref) - min(y for _, y in ref))
        dist = max(((gx - rx) ** 2 + (gy - ry) ** 2) ** 0.5 for (gx, gy), (rx, ry) in zip(got, ref))
        worst = max(worst, dist / p2p)
    return worst


def fmpy_ceiling(unit, calls=20000):
    """µs per doStep + getReal(all outputs of `unit`) through FMPy onto C
    functions that return at once."""
    with tempfile.TemporaryDirectory() as tmp:
        src, lib = os.path.join(tmp, "noop.c"), os.path.join(tmp, "noop.so")
        with open(src, "w") as f:
            f.write(NOOP_C)
        subprocess.run(["cc", "-O2", "-shared", "-fPIC", "-o", lib, src], check=True)
        noop = ctypes.CDLL(lib)
        fmu = unit.instance({})
        fmu.setupExperiment(startTime=0.0)
        fmu.enterInitializationMode()
        fmu.exitInitializationMode()
        real = {name: fmu._functions[name] for name in ("fmi2DoStep", "fmi2GetReal")}
        for name in real:
            fake = getattr(noop, name)
            fake.argtypes, fake.restype = real[name].argtypes, real[name].restype
            fake.argnames = real[name].argnames
            fmu._functions[name] = fake
        outs = unit.outputs
        begin = time.perf_counter()
        for k in range(calls):
            fmu.doStep(k * COMM, COMM)
            fmu.getReal(outs)
        per = (time.perf_counter() - begin) / calls
        fmu._functions.update(real)
        fmu.terminate()
        fmu.freeInstance()
    return per * 1e6


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--seconds", type=float, default=12.0, help="simulated time per run (s)")
    p.add_argument("--window", type=float, default=2.0, help="last seconds the orbit error is taken over")
    p.add_argument("--runs", type=int, default=3, help="timed runs per configuration (median)")
    p.add_argument("--tolerance", type=float, default=1e-4,
                   help=f"{TOLERANCE_PARAMETER} when its start value is 0")
    p.add_argument("--units", default=",".join(m for m, _ in UNITS))
    p.add_argument("--fmu-dir", default=os.path.join(ROOT, "out"), help="where the packed FMUs are")
    p.add_argument("--out", default=os.path.join(ROOT, "bench", "plant_loop_results.md"))
    a = p.parse_args()
    chosen = a.units.split(",")
    units = [Unit(m, f, a.fmu_dir) for m, f in UNITS if m in chosen]
    window = round(a.window / COMM)
    rows = []
    ceilings = []
    for unit in units:
        fixed = {TOLERANCE_PARAMETER: 0.0} if TOLERANCE_PARAMETER in unit.vars else {}
        configs = [("fixed 1 ms", {"solver.time_step": 1e-3, **fixed}),
                   ("fixed 5 ms", {"solver.time_step": 5e-3, **fixed})]
        if TOLERANCE_PARAMETER in unit.vars:
            tol = unit.start(TOLERANCE_PARAMETER) or a.tolerance
            largest = unit.start("solver.time_step")
            configs.append((f"accuracy-controlled ({TOLERANCE_PARAMETER} = {tol:g}, steps up to {largest * 1e3:.3g} ms)",
                            {"solver.time_step": largest, TOLERANCE_PARAMETER: tol}))
        defaults = {"solver.time_step": unit.start("solver.time_step")}
        if TOLERANCE_PARAMETER in unit.vars:
            defaults[TOLERANCE_PARAMETER] = unit.start(TOLERANCE_PARAMETER) or 0.0
        chosen_defaults = [k for k, (_, params) in enumerate(configs)
                           if all(params.get(n, 0.0) == v for n, v in defaults.items())]
        if chosen_defaults:
            k = chosen_defaults[0]
            configs[k] = (configs[k][0] + " (FMU default)", configs[k][1])
        else:
            text = ", ".join(f"{n} = {v:g}" for n, v in defaults.items())
            configs.insert(0, (f"FMU defaults ({text})", {}))
        _, _, _, reference = unit.run({"solver.time_step": REFERENCE_STEP, **fixed}, a.seconds)
        for label, params in configs:
            runs = [unit.run(params, a.seconds, keep=(k == 0)) for k in range(a.runs)]
            journal = runs[0][3]
            wall, t_step, t_get, _ = sorted(runs, key=lambda r: r[0])[len(runs) // 2]
            n = round(a.seconds / COMM)
            row = dict(unit=unit.model, rpm=unit.rpm, config=label,
                       factor=a.seconds / wall, per=wall / n * 1e6, step=t_step / n * 1e6,
                       get=t_get / n * 1e6, outputs=len(unit.outputs),
                       error=orbit_error(journal, reference, window))
            rows.append(row)
            print(f"{row['unit']:24s} {row['config']:44s} {row['factor']:7.0f}x real time  "
                  f"{row['per']:7.1f} us/comm (doStep {row['step']:6.1f}, getReal {row['get']:5.1f})  "
                  f"orbit error {row['error']:.2e}", flush=True)
        ceiling = statistics.median(fmpy_ceiling(unit) for _ in range(3))
        ceilings.append((unit.model, len(unit.outputs), ceiling))
        print(f"{unit.model:24s} FMPy ceiling: {ceiling:.1f} us per doStep + getReal of {len(unit.outputs)} "
              f"outputs onto no-op C functions ({COMM / (ceiling * 1e-6):.0f}x real time at most)", flush=True)
        unit.close()
    with open(a.out, "w") as f:
        f.write(f"`bench/plant_loop.py --seconds {a.seconds:g} --window {a.window:g} --runs {a.runs}`: FMPy "
                f"`FMU2Slave`, fmi2DoStep every 5 ms, all outputs read with one fmi2GetReal after each, "
                f"{a.seconds:g} s from the settled state at rated speed with the model's unbalance; "
                f"median of {a.runs} runs. Orbit error: largest journal distance from a "
                f"{REFERENCE_STEP * 1e3:g} ms internal-step reference over the last {a.window:g} s, over the "
                f"reference orbit's peak-to-peak amplitude, worst bearing.\n\n")
        f.write("| unit | speed | internal step | real-time factor | µs per 5 ms | of it fmi2DoStep | "
                "fmi2GetReal (outputs) | orbit error |\n|---|---:|---|---:|---:|---:|---:|---:|\n")
        for r in rows:
            f.write(f"| {r['unit']} | {r['rpm']:g} rpm | {r['config']} | {r['factor']:.0f}× | {r['per']:.1f} | "
                    f"{r['step']:.1f} | {r['get']:.1f} ({r['outputs']}) | {r['error'] * 100:.3g} % |\n")
        f.write("\nFMPy's own cost per communication point, the ceiling of any FMU in this loop (same run): "
                "the same doStep + getReal calls onto C functions that return at once (median of 3 × 20 000).\n\n"
                "| unit | outputs | FMPy µs per doStep + getReal | real-time factor at most |\n"
                "|---|---:|---:|---:|\n")
        for model, n, ceiling in ceilings:
            f.write(f"| {model} | {n} | {ceiling:.1f} | {COMM / (ceiling * 1e-6):.0f}× |\n")
    print(f"wrote {a.out}")


if __name__ == "__main__":
    main()
