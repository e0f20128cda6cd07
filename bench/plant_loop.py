"""The FMPy plant loop of issue 51, in ratio form: a plant study driving each
shipped unit as FMPy's FMU2Slave (not simulate_fmu), fmi2DoStep every 5 ms and
every output read with one fmi2GetReal after each, at the FMU defaults (no
solver parameter set), at rated speed with the model's unbalance, from the
settled state the FMU initializes (fmi2ExitInitializationMode: static
equilibrium at the start speed, the unbalance applied at once); a unit with a
magnetic pull runs with the field off (excitation 0) and on (1).

    .venv/bin/python bench/plant_loop.py [--seconds 12] [--window 2] [--runs 3] [--units A,B]
        [--fmu-dir out] [--out bench/plant_loop_results.md]

Needs the FMUs in --fmu-dir, `<model>.fmu` for every models/*.toml (bench/run_all.sh
packs them: `bash fmu_pack.sh --platforms linux64 --model models/NAME.toml`)
and a C compiler (`cc`) for the no-op library of FMPy's own cost. The
28-pad three-guide unit with unpreloaded pads (`hydro_unit_three_guide` with
`preload = 0`) is packed by run_all.sh from the model file this script writes
with --write-variants DIR.

Per unit and field, all measured in the same run:

- FMPy own: µs per doStep + getReal(all outputs) through FMPy onto C functions
  that return fmi2OK at once (a no-op library compiled with cc): what FMPy
  itself costs per communication point, measured just before each run of
  the loop with as many calls;
- FMU own: the loop's wall clock per point minus FMPy own; the ratio FMU own
  / FMPy own is the figure issue 51 targets (≤ 1.5); of --runs pairs of a
  run and its FMPy own, the pair of the median ratio gives the row;
- real-time factor: simulated seconds / wall seconds of the loop;
- orbit error: against a reference run with a fixed internal step of
  --reference-step on the same communication points, the largest distance
  between the two journal positions (x, y of bearings.<name>) over the last
  --window seconds, over every bearing, divided by that bearing's reference
  orbit peak-to-peak amplitude there (the larger of the x and y ranges);
  the worst bearing is reported; and the orbit amplitude error, the
  relative difference of the orbit's peak-to-peak amplitude from the
  reference's, which a self-excited whirl (the vertical rotor's oil whip)
  or an undamped free vibration (the classic rotor) keeps while its phase
  drifts from the reference's.
"""
import argparse
import ctypes
import glob
import os
import re
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
TOLERANCE_PARAMETER = "solver.local_error_tolerance"
UNPRELOADED = "hydro_unit_three_guide_unpreloaded"
# fmu_pack.sh without --model packs hydro_unit as the default FMU.
DEFAULT_FMU = {"hydro_unit": "RotorBearing.fmu"}

NOOP_C = """
int fmi2DoStep(void *c, double t, double h, int no_set) { return 0; }
int fmi2GetReal(void *c, const unsigned int *vr, unsigned long n, double *v) { return 0; }
"""


def shipped_units():
    """(model name, model file, FMU file name) of every shipped model and the
    unpreloaded 28-pad variant."""
    units = []
    for path in sorted(glob.glob(os.path.join(ROOT, "models", "*.toml"))):
        name = os.path.splitext(os.path.basename(path))[0]
        units.append((name, path, f"{name}.fmu"))
    return units


def write_variants(folder):
    """The 28-pad three-guide unit with unpreloaded pads: the shipped model
    with every `preload = 0.3` set to 0."""
    os.makedirs(folder, exist_ok=True)
    with open(os.path.join(ROOT, "models", "hydro_unit_three_guide.toml")) as f:
        text = f.read()
    text, n = re.subn(r"(?m)^preload = 0\.3", "preload = 0.0", text)
    if n != 3:
        sys.exit(f"plant_loop.py: expected 3 pad preloads in hydro_unit_three_guide.toml, found {n}")
    path = os.path.join(folder, UNPRELOADED + ".toml")
    with open(path, "w") as f:
        f.write(text)
    print(path)


class Unit:
    """A packed FMU of a model file: its description, rated speed, outputs."""

    def __init__(self, model, model_file, fmu, folder):
        self.model = model
        self.path = os.path.join(folder, fmu)
        if not os.path.exists(self.path) and model in DEFAULT_FMU:
            self.path = os.path.join(folder, DEFAULT_FMU[model])
        if not os.path.exists(self.path):
            sys.exit(f"plant_loop.py: {self.path} missing: bash fmu_pack.sh --platforms linux64 "
                     f"--model {os.path.relpath(model_file, ROOT)}")
        with open(model_file, "rb") as f:
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
        self.fields = [n for n in self.vars if n.startswith("magnetic_pull.") and n.endswith(".excitation")]
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
        speed = self.rpm * 3.141592653589793 / 30.0
        if self.vars.get("shaft.speed") is not None and self.vars["shaft.speed"].causality == "input":
            fmu.setReal([self.vars["shaft.speed"].valueReference], [speed])
        elif "shaft.initial_speed" in self.vars:
            fmu.setReal([self.vars["shaft.initial_speed"].valueReference], [speed])
        return fmu

    def run(self, params, seconds, keep=True):
        """The plant loop; returns (wall s, journal samples)."""
        fmu = self.instance(params)
        fmu.setupExperiment(startTime=0.0, stopTime=seconds + COMM)
        fmu.enterInitializationMode()
        fmu.exitInitializationMode()
        count = round(seconds / COMM)
        outs, journal = self.outputs, []
        do_step, get_real = fmu.doStep, fmu.getReal
        clock = time.perf_counter
        begin = clock()
        for k in range(count):
            do_step(k * COMM, COMM)
            values = get_real(outs)
            if keep:
                journal.append([(values[i], values[j]) for i, j in self.journal])
        wall = clock() - begin
        fmu.terminate()
        fmu.freeInstance()
        return wall, journal

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
        worst = max(worst, dist / p2p if p2p > 0 else (0.0 if dist == 0 else float("inf")))
    return worst


def amplitude_error(run, reference, window):
    """Worst bearing's relative difference of the orbit's peak-to-peak
    amplitude (the larger of its x and y ranges) from the reference's over
    the last `window` communication points: the size of the orbit, which a
    self-excited whirl (oil whip, an undamped free vibration) keeps while its
    phase drifts."""
    worst = 0.0
    for b in range(len(reference[0])):
        def p2p(samples):
            pts = [p[b] for p in samples[-window:]]
            return max(max(x for x, _ in pts) - min(x for x, _ in pts),
                       max(y for _, y in pts) - min(y for _, y in pts))
        ref, got = p2p(reference), p2p(run)
        worst = max(worst, abs(got - ref) / ref if ref > 0 else (0.0 if got == 0 else float("inf")))
    return worst


def fmpy_own(unit, calls=20000):
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
    p.add_argument("--reference-step", type=float, default=5e-5, help="internal step of the reference (s)")
    p.add_argument("--units", default="", help="comma-separated model names (default: all)")
    p.add_argument("--fmu-dir", default=os.path.join(ROOT, "out"), help="where the packed FMUs are")
    p.add_argument("--variant-dir", default=os.path.join(ROOT, "out", "bench_models"),
                   help="where --write-variants put the unpreloaded three-guide model")
    p.add_argument("--write-variants", metavar="DIR", help="write the variant model files into DIR and exit")
    p.add_argument("--out", default=os.path.join(ROOT, "bench", "plant_loop_results.md"))
    a = p.parse_args()
    if a.write_variants:
        write_variants(a.write_variants)
        return
    catalogue = shipped_units() + [(UNPRELOADED, os.path.join(a.variant_dir, UNPRELOADED + ".toml"),
                                    UNPRELOADED + ".fmu")]
    chosen = a.units.split(",") if a.units else [m for m, _, _ in catalogue]
    window = round(a.window / COMM)
    rows = []
    for model, model_file, fmu in catalogue:
        if model not in chosen:
            continue
        unit = Unit(model, model_file, fmu, a.fmu_dir)
        fixed = {TOLERANCE_PARAMETER: 0.0} if TOLERANCE_PARAMETER in unit.vars else {}
        fields = [("", {})]
        if unit.fields:
            fields = [(f"field {label}", {n: value for n in unit.fields}) for label, value in (("off", 0.0), ("on", 1.0))]
        for field, params in fields:
            _, reference = unit.run({"solver.time_step": a.reference_step, **fixed, **params}, a.seconds)
            n = round(a.seconds / COMM)
            # Each run paired with FMPy's own cost measured just before it
            # (the same number of calls), so that a load on the machine
            # weighs on both sides of the ratio; medians of the pairs.
            pairs = []
            for k in range(a.runs):
                own = fmpy_own(unit, calls=n)
                pairs.append((own, unit.run(params, a.seconds, keep=(k == 0))))
            journal = pairs[0][1][1]
            # The pair of the median ratio gives every figure of the row.
            ranked = sorted(pairs, key=lambda p: (p[1][0] / n * 1e6 - p[0]) / p[0])
            own, (wall, _) = ranked[len(ranked) // 2]
            per = wall / n * 1e6
            ratio = (per - own) / own
            row = dict(unit=unit.model, field=field, rpm=unit.rpm, outputs=len(unit.outputs),
                       factor=a.seconds / wall, per=per, fmpy=own, ratio=ratio,
                       error=orbit_error(journal, reference, window),
                       amplitude=amplitude_error(journal, reference, window),
                       step=unit.start("solver.time_step"), tol=unit.start(TOLERANCE_PARAMETER))
            rows.append(row)
            print(f"{row['unit']:36s} {field:9s} FMU own / FMPy own {row['ratio']:5.2f}  "
                  f"({per:7.1f} us/point, FMPy {own:5.1f})  {row['factor']:6.0f}x real time  "
                  f"orbit error {row['error']:.2e} (amplitude {row['amplitude']:.2e})", flush=True)
        unit.close()
    with open(a.out, "w") as f:
        f.write(f"`bench/plant_loop.py --seconds {a.seconds:g} --window {a.window:g} --runs {a.runs}`: FMPy "
                f"`FMU2Slave`, fmi2DoStep every 5 ms, all outputs read with one fmi2GetReal after each, "
                f"{a.seconds:g} s at the FMU defaults from the settled state at rated speed with the model's "
                f"unbalance, field off and on where the unit has a magnetic pull; medians of {a.runs} runs, "
                f"all in one run of the script. FMPy own: the same doStep + getReal calls onto C functions "
                f"that return at once, as many, measured just before each run. FMU own = the loop's time per "
                f"point − FMPy own; each row is the run of the median ratio. "
                f"Orbit error: largest journal distance from a {a.reference_step * 1e3:g} ms fixed-step "
                f"reference over the last {a.window:g} s, over the reference orbit's peak-to-peak amplitude, "
                f"worst bearing; orbit amplitude error: the relative difference of its peak-to-peak amplitude, "
                f"worst bearing (a self-excited whirl or an undamped free vibration keeps its size while its phase "
                f"drifts). `{UNPRELOADED}`: the shipped three-guide unit (28 pads) with preload 0.\n\n")
        f.write("| unit | speed | field | FMU default step (tolerance) | outputs | FMPy own µs | FMU own µs | "
                "**FMU own / FMPy own** | real-time factor | orbit error | orbit amplitude error |\n"
                "|---|---:|---|---|---:|---:|---:|---:|---:|---:|---:|\n")
        for r in rows:
            tol = "" if not r["tol"] else f" ({r['tol']:g})"
            f.write(f"| {r['unit']} | {r['rpm']:g} rpm | {r['field'] or '—'} | {r['step'] * 1e3:.3g} ms{tol} | "
                    f"{r['outputs']} | {r['fmpy']:.1f} | {r['per'] - r['fmpy']:.1f} | **{r['ratio']:.2f}** | "
                    f"{r['factor']:.0f}× | {r['error'] * 100:.3g} % | {r['amplitude'] * 100:.3g} % |\n")
    print(f"wrote {a.out}")


if __name__ == "__main__":
    main()
