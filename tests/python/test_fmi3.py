"""FMPy against the FMI 3.0 FMUs: validation, a simulate_fmu run, the FMI 3.0
FMU's outputs against the FMI 2.0 FMU's to the bit under the same inputs, and
FMU states (get, set, serialize, deserialize) bit-exact across instances.

Run by tests/fmi3.rs with the project's venv; argv: repo root, then the model
stems to check (each packed by `fmu_pack.sh --fmi 2,3` as out/<stem>.fmu and
out/<stem>_fmi3.fmu; hydro_unit is out/RotorBearing*.fmu).
"""
import os
import shutil
import struct
import sys

from fmpy import extract, read_model_description, simulate_fmu
from fmpy.fmi2 import FMU2Slave
from fmpy.fmi3 import FMU3Slave
from fmpy.validation import validate_fmu

root, stems = sys.argv[1], sys.argv[2:]
out = os.path.join(root, "out")
failures = []
H, STEPS = 0.01, 20


def bits(x):
    return struct.pack("<d", x)


def speed_at(t):
    """A speed ramp 150 → 165 rpm/s, held over each step (rad/s)."""
    return (150.0 + 15.0 * t) * 3.141592653589793 / 30.0


class Run:
    """One instance of an FMU of either version, stepped by hand."""

    def __init__(self, path, version, name):
        self.md = read_model_description(path)
        self.dir = extract(path)
        self.version = version
        ident = self.md.coSimulation.modelIdentifier
        if version == 3:
            self.fmu = FMU3Slave(guid=self.md.instantiationToken, unzipDirectory=self.dir,
                                 modelIdentifier=ident, instanceName=name)
        else:
            self.fmu = FMU2Slave(guid=self.md.guid, unzipDirectory=self.dir,
                                 modelIdentifier=ident, instanceName=name)
        self.vr = {v.name: v.valueReference for v in self.md.modelVariables}
        self.outputs = [v.name for v in self.md.modelVariables if v.causality == "output" and not v.dimensions]
        self.speed = self.vr.get("shaft.speed") if any(
            v.name == "shaft.speed" and v.causality == "input" for v in self.md.modelVariables) else None
        self.fmu.instantiate()

    def set(self, refs, values):
        (self.fmu.setFloat64 if self.version == 3 else self.fmu.setReal)(refs, values)

    def get(self, refs):
        return list((self.fmu.getFloat64 if self.version == 3 else self.fmu.getReal)(refs))

    def initialize(self):
        if self.version == 2:
            self.fmu.setupExperiment(startTime=0.0)
        if self.speed is not None:
            self.set([self.speed], [speed_at(0.0)])
        if self.version == 3:
            self.fmu.enterInitializationMode(startTime=0.0)
        else:
            self.fmu.enterInitializationMode()
        self.fmu.exitInitializationMode()

    def step(self, k):
        """Step k (from k h to (k + 1) h) with its input; the outputs after it."""
        t = k * H
        if self.speed is not None:
            self.set([self.speed], [speed_at(t)])
        result = self.fmu.doStep(currentCommunicationPoint=t, communicationStepSize=H)
        if self.version == 3:
            event, terminate, early, last = result
            if event or terminate or early or last != t + H:
                failures.append(f"{self.md.modelName}: fmi3DoStep at {t} s: event {event}, terminate "
                                f"{terminate}, early return {early}, last successful time {last!r}")
        return self.get([self.vr[n] for n in self.outputs])

    def close(self, terminate=True):
        if terminate:
            self.fmu.terminate()
        self.fmu.freeInstance()
        shutil.rmtree(self.dir, ignore_errors=True)


def fmu_paths(stem):
    base = "RotorBearing" if stem == "hydro_unit" else stem
    return os.path.join(out, base + ".fmu"), os.path.join(out, base + "_fmi3.fmu")


for stem in stems:
    fmu2, fmu3 = fmu_paths(stem)
    if not (os.path.exists(fmu2) and os.path.exists(fmu3)):
        failures.append(f"{fmu2} or {fmu3} missing: run fmu_pack.sh --fmi 2,3 (scripts/test.sh does)")
        continue

    # 0. The FMI Cross-Check rules cap an FMU at 10 MB.
    for path in (fmu2, fmu3):
        size = os.path.getsize(path)
        print(f"{os.path.basename(path)}: {size / 1e6:.2f} MB")
        if size > 10e6:
            failures.append(f"{path} is {size / 1e6:.2f} MB, over the 10 MB of the cross-check rules")

    # 1. FMPy's validation and simulate_fmu.
    problems = validate_fmu(fmu3)
    if problems:
        failures.append(f"{fmu3}: " + "; ".join(problems))
    res = simulate_fmu(fmu3, stop_time=0.05, output_interval=H)
    print(f"{stem}: FMI 3.0 FMU valid, simulate_fmu ran {len(res)} points")
    if len(res) != 6:
        failures.append(f"{stem}: simulate_fmu of the FMI 3.0 FMU gave {len(res)} points, not 6")

    # 2. The FMI 3.0 FMU's outputs equal the FMI 2.0 FMU's to the bit.
    a, b = Run(fmu2, 2, "fmi2"), Run(fmu3, 3, "fmi3")
    if a.outputs != b.outputs or any(a.vr[n] != b.vr[n] for n in a.outputs):
        failures.append(f"{stem}: the two versions' outputs differ in names or value references")
        continue
    a.initialize()
    b.initialize()
    differ = 0
    for k in range(STEPS):
        ya, yb = a.step(k), b.step(k)
        differ += sum(bits(x) != bits(y) for x, y in zip(ya, yb))
    print(f"{stem}: {STEPS} steps of {H} s, {len(a.outputs)} outputs: {differ} values differ "
          "between FMI 2.0 and FMI 3.0")
    # The arrays read (and write) as their elements, to the bit.
    arrays = [v for v in b.md.modelVariables if v.dimensions]
    wrong = []
    for arr in arrays:
        n = int(arr.dimensions[0].start)
        names = [x.strip() for x in arr.description[len("Array of "):].split(",")]
        whole = b.fmu.getFloat64([arr.valueReference], nValues=n)
        parts = b.get([b.vr[x] for x in names])
        if len(names) != n or [bits(x) for x in whole] != [bits(x) for x in parts]:
            wrong.append(arr.name)
        if arr.causality == "input":
            # A change within every element's declared range (a pull's
            # dynamic eccentricity stays inside its air gap).
            by_name = {v.name: v for v in b.md.modelVariables}
            room = [float(by_name[x].max) - p for x, p in zip(names, parts)
                    if by_name[x].max is not None]
            step = min([1.0] + [r / 2 for r in room])
            changed = [x + step for x in parts]
            b.fmu.setFloat64([arr.valueReference], changed)
            if b.get([b.vr[x] for x in names]) != changed:
                wrong.append(arr.name + " (set)")
            b.fmu.setFloat64([arr.valueReference], parts)
    print(f"{stem}: {len(arrays)} arrays ({', '.join(a.name for a in arrays[:4])}, ...) read as their elements")
    if wrong or not arrays:
        failures.append(f"{stem}: arrays {wrong} differ from their elements (of {len(arrays)})")
    if differ:
        failures.append(f"{stem}: {differ} output values differ between the FMI 2.0 and FMI 3.0 FMUs")
    a.close()

    # 3. FMU states: saved by one FMI 3.0 instance, serialized, deserialized into
    # a fresh one, which then runs on as the first did, to the bit.
    half = STEPS // 2
    c = Run(fmu3, 3, "first")
    c.initialize()
    for k in range(half):
        c.step(k)
    state = c.fmu.getFMUState()
    image = c.fmu.serializeFMUState(state)
    ahead = [c.step(k) for k in range(half, STEPS)]
    c.fmu.setFMUState(state)
    again = [c.step(k) for k in range(half, STEPS)]
    d = Run(fmu3, 3, "second")
    restored = d.fmu.deserializeFMUState(image)
    d.fmu.setFMUState(restored)
    if d.fmu.serializeFMUState(d.fmu.getFMUState()) != image:
        failures.append(f"{stem}: the restored instance serializes to another image")
    moved = [d.step(k) for k in range(half, STEPS)]
    flat = lambda rows: [bits(x) for row in rows for x in row]  # noqa: E731
    if flat(again) != flat(ahead):
        failures.append(f"{stem}: the rollback with fmi3SetFMUState does not repeat the run to the bit")
    if flat(moved) != flat(ahead):
        failures.append(f"{stem}: the deserialized state does not continue the run to the bit")
    print(f"{stem}: FMU state of {len(image)} bytes continues the run to the bit in a second instance")
    # A state of the FMI 2.0 FMU is another model description's: refused.
    e = Run(fmu2, 2, "fmi2 state")
    e.initialize()
    image2 = e.fmu.serializeFMUstate(e.fmu.getFMUstate())
    try:
        d.fmu.deserializeFMUState(image2)
        failures.append(f"{stem}: the FMI 3.0 FMU took an FMI 2.0 FMU's state")
    except Exception as err:  # noqa: BLE001 (FMPy raises on fmi3Error)
        print(f"{stem}: an FMI 2.0 state is refused ({err})")
    for run in (b, c, e):
        run.close()
    d.close(terminate=False)  # in the error state since the refusal: only freed

# 4. An FMPy master that allows early return: the Jeffcott rotor at 3000 rpm with
# 0.5 kg·m of unbalance on equal 1 ms steps, 10 ms communication steps; its
# journals reach their bearings at 42 ms, where fmi3DoStep returns early and
# FMPy records a sample (tests/fmi3_abi.rs finds the same time on 1 ms steps).
if "jeffcott" in stems:
    _, fmu3 = fmu_paths("jeffcott")
    start = {"shaft.speed": 3000.0 * 3.141592653589793 / 30.0, "unbalance.disk": 0.5,
             "solver.local_error_tolerance": 0.0, "solver.time_step": 1e-3}
    forces = ["bearings.left.contact_force", "bearings.right.contact_force"]
    res = simulate_fmu(fmu3, stop_time=0.1, output_interval=0.01, start_values=start, output=forces,
                       early_return_allowed=True)
    off_grid = [float(t) for t in res["time"] if abs(t / 0.01 - round(t / 0.01)) > 1e-6]
    print(f"jeffcott with early return: samples off the 10 ms grid at {off_grid} s")
    if not off_grid or abs(off_grid[0] - 0.042) > 1e-9:
        failures.append(f"jeffcott: early returns at {off_grid} s, expected the first at 0.042 s")
    else:
        k = [float(t) for t in res["time"]].index(off_grid[0])
        if not max(res[f][k] for f in forces) > 0.0 or max(res[f][k - 1] for f in forces) != 0.0:
            failures.append("jeffcott: the early return is not where the contact begins")

if failures:
    print("\n".join(failures), file=sys.stderr)
    sys.exit(1)
print(f"{len(stems)} models: FMI 3.0 FMUs valid, bit-identical to FMI 2.0, states bit-exact")
