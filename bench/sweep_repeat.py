"""The main job's Dask sweep, run RUNS times, each from a fresh empty temporary
directory on a fresh 2-worker LocalCluster (nothing unpacked before), as on a
fresh machine. Issue 22: 9 of 15 such runs lost 1–3 points to the unpacking
race, and one moved the μ = 0.01 onset off 6711 rpm.

    .venv/bin/python bench/sweep_repeat.py [RUNS] [--out bench/sweep_repeat_results.md]

Needs out/jeffcott.fmu (`bash fmu_pack.sh --model models/jeffcott.toml`).
Prints one line per run and writes the table; exits non-zero if any run lost
a point, exited non-zero, or gave an onset outside 6711 ± 8 / 6477 ± 8 /
6617 ± 8 rpm (the bisection bracket: the onsets of a complete sweep)."""
import argparse
import csv
import os
import re
import subprocess
import sys
import tempfile
import time

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), ".."))
FMU = os.path.join(ROOT, "out", "jeffcott.fmu")
# The main job's sweep (scripts/main.sh).
ARGS = ["--fmu", FMU, "--rpm", "4000:16000:13",
        "--param", "bearings.left.viscosity,bearings.right.viscosity=0.01,0.02,0.04", "--duration", "0.6"]
# Onset of whirl (rpm) and half bracket of a complete sweep, per viscosity (Pa·s).
EXPECTED = {0.01: 6711.0, 0.02: 6477.0, 0.04: 6617.0}
BRACKET = 8.0


def one_run(k):
    with tempfile.TemporaryDirectory() as tmp:
        env = dict(os.environ, TMPDIR=tmp)
        out = os.path.join(tmp, "results", "sweep")
        start = time.monotonic()
        run = subprocess.run([sys.executable, os.path.join(ROOT, "system", "sweep.py"), *ARGS, "--out", out],
                             capture_output=True, text=True, env=env, cwd=ROOT)
        seconds = time.monotonic() - start
        rows = list(csv.DictReader(open(out + ".csv"))) if os.path.exists(out + ".csv") else []
    grid = [r for r in rows if not r.get("refinement")]
    failed = [f"{float(r['rpm']):g} rpm: {r['status'][:80]}" for r in rows if r["status"] != "ok"]
    onsets = {}
    for line in run.stdout.splitlines():
        m = re.match(r"onset of whirl .*=([0-9.]+): ([0-9]+) ± ([0-9]+) rpm", line)
        if m:
            onsets[float(m.group(1))] = (float(m.group(2)), float(m.group(3)))
    good = (run.returncode == 0 and len(grid) == 39 and not failed and set(onsets) == set(EXPECTED)
            and all(abs(onsets[mu][0] - EXPECTED[mu]) <= BRACKET and onsets[mu][1] <= BRACKET for mu in EXPECTED))
    return {"run": k, "exit": run.returncode, "grid": len(grid), "points": len(rows), "failed": failed,
            "onsets": onsets, "seconds": seconds, "good": good}


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("runs", type=int, nargs="?", default=10)
    p.add_argument("--out", default=os.path.join(ROOT, "bench", "sweep_repeat_results.md"))
    a = p.parse_args()
    if not os.path.exists(FMU):
        sys.exit(f"{FMU} missing: bash fmu_pack.sh --model models/jeffcott.toml")
    results = []
    for k in range(1, a.runs + 1):
        r = one_run(k)
        results.append(r)
        text = ", ".join(f"μ={mu:g}: {o:.0f} ± {b:.0f}" for mu, (o, b) in sorted(r["onsets"].items()))
        print(f"run {k}: exit {r['exit']}, {r['grid']} grid + {r['points'] - r['grid']} bisection points, "
              f"{len(r['failed'])} failed, onsets {text} rpm, {r['seconds']:.0f} s", flush=True)
    lost = sum(len(r["failed"]) for r in results)
    bad = [r["run"] for r in results if not r["good"]]
    lines = [
        "# The main job's sweep, repeated from fresh temporary directories",
        "",
        f"`bench/sweep_repeat.py {a.runs}`: `system/sweep.py {' '.join(ARGS[2:])}` (2-worker LocalCluster),",
        "each run from an empty `TMPDIR` on a fresh cluster, so both workers unpack the shipped FMU at once.",
        "",
        "| run | exit | grid points | bisection points | failed | onset μ=0.01 | μ=0.02 | μ=0.04 | s |",
        "|---:|---:|---:|---:|---:|---:|---:|---:|---:|",
    ]
    for r in results:
        cell = lambda mu: "{:.0f} ± {:.0f}".format(*r["onsets"][mu]) if mu in r["onsets"] else "–"
        lines.append(f"| {r['run']} | {r['exit']} | {r['grid']} | {r['points'] - r['grid']} | {len(r['failed'])} "
                     f"| {cell(0.01)} | {cell(0.02)} | {cell(0.04)} | {r['seconds']:.0f} |")
    lines += ["", f"Points lost: {lost} of {sum(r['points'] for r in results)}; runs off the expected onsets "
                  f"(6711 / 6477 / 6617 ± {BRACKET:.0f} rpm) or exiting non-zero: {bad or 'none'}."]
    for r in results:
        for f in r["failed"]:
            lines.append(f"- run {r['run']}: {f}")
    with open(a.out, "w") as f:
        f.write("\n".join(lines) + "\n")
    print(f"sweep_repeat: {a.runs} runs, {lost} points lost, bad runs {bad or 'none'} → {a.out}")
    sys.exit(1 if bad else 0)


if __name__ == "__main__":
    main()
