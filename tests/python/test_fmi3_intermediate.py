"""The intermediate-update example of docs/fmu.md, run as written through FMPy.

Run by tests/fmi3.rs with the project's venv; argv: repo root. Needs
out/jeffcott_fmi3.fmu (`fmu_pack.sh --fmi 2,3 --model models/jeffcott.toml`).

The block after "<!-- example: intermediate updates -->" in docs/fmu.md runs
from the repo root; then:
1. its callback was told of every internal step once: 100 times in 0.1 s of
   1 ms steps, in order, each on the 1 ms grid;
2. it tripped once, at the first internal step whose eccentricity passed 0.9,
   inside a communication step (an early return, not a communication point),
   and every eccentricity before it was at most 0.9, at the communication
   points too (a master sampling there would not have tripped);
3. the eccentricities the callback read equal, bit for bit, those of a second
   FMPy instance without a callback stepped by 1 ms up to the trip;
4. after the trip (speed 0) the journal settles: its eccentricity at 0.1 s is
   below the trip limit.
"""
import math
import os
import struct
import sys

from fmpy import extract, read_model_description
from fmpy.fmi3 import FMU3Slave

root = sys.argv[1]
os.chdir(root)
text = open(os.path.join("docs", "fmu.md")).read()
marker = "<!-- example: intermediate updates -->"
if marker not in text:
    sys.exit(f"docs/fmu.md: no {marker!r}")
block = text.split(marker, 1)[1].split("```python\n", 1)[1].split("```", 1)[0]
scope = {}
exec(compile(block, "docs/fmu.md (intermediate updates)", "exec"), scope)
orbit, trips = scope["orbit"], scope["trips"]
failures = []

# 1. Every internal step once, in order, on the 1 ms grid.
times = [t for t, _ in orbit]
if len(orbit) != 100:
    failures.append(f"{len(orbit)} intermediate updates in 0.1 s of 1 ms steps, not 100")
if any(b <= a for a, b in zip(times, times[1:])):
    failures.append("intermediate update times not increasing")
off = max(abs(t - round(t / 1e-3) * 1e-3) for t in times)
if off > 1e-12:
    failures.append(f"an intermediate update {off:.2e} s off the 1 ms grid")

# 2. One trip, at the first step past 0.9, inside a communication step.
first = next((t for t, e in orbit if e > 0.9), None)
if len(trips) != 1 or trips[0] != first:
    failures.append(f"trips {trips}, first eccentricity above 0.9 at {first}")
else:
    k = times.index(first)
    if max(e for _, e in orbit[:k]) > 0.9:
        failures.append("an eccentricity above 0.9 before the trip")
    if abs(first / 0.01 - round(first / 0.01)) < 1e-6:
        failures.append(f"the trip at {first} s is a communication point, not an early return")

    # 3. A second instance without a callback, stepped by 1 ms to the trip.
    path = "out/jeffcott_fmi3.fmu"
    md = read_model_description(path)
    vr = {v.name: v.valueReference for v in md.modelVariables}
    ecc = vr["bearings.left.eccentricity"]
    plain = FMU3Slave(guid=md.instantiationToken, unzipDirectory=extract(path),
                      modelIdentifier=md.coSimulation.modelIdentifier, instanceName="plain")
    plain.instantiate()
    start = scope["start"]
    plain.setFloat64([vr[n] for n in start], list(start.values()))
    plain.enterInitializationMode(startTime=0.0)
    plain.exitInitializationMode()
    t, differ = 0.0, 0
    for time, e in orbit[:k + 1]:
        _, _, _, t = plain.doStep(t, time - t)
        mine = plain.getFloat64([ecc])[0]
        differ += struct.pack("<d", mine) != struct.pack("<d", e)
    plain.terminate()
    plain.freeInstance()
    if differ:
        failures.append(f"{differ} of {k + 1} eccentricities read in the callback differ from a plain run's")

    # 4. The journal settles after the trip.
    last = orbit[-1][1]
    if not (math.isfinite(last) and last < 0.9):
        failures.append(f"eccentricity {last} at 0.1 s, after the trip at {first} s")
    print(f"docs/fmu.md intermediate-update example: {len(orbit)} updates, trip at {first:.3f} s "
          f"(eccentricity {orbit[k][1]:.3f}), bit-identical to a plain 1 ms run up to it; "
          f"eccentricity {last:.3f} at 0.1 s")

if failures:
    print("\n".join(failures), file=sys.stderr)
    sys.exit(1)
