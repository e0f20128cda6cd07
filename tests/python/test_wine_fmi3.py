"""The win64 binary of every packed FMI 3.0 FMU, run under Wine, against its linux64 binary.

Run by tests/wine.rs with the project's venv; argv: repo root. Needs the FMI 3.0
FMUs in out/ packed for both platforms (scripts/test.sh runs `fmu_pack.sh
--fmi 2,3` for each model) and the cross toolchain and Wine prefix of
scripts/setup.sh.

FMPy's remoting (how tests/python/test_wine.py runs the FMI 2.0 DLL under Wine)
serves FMI 2.0 only, so one C importer (tests/wine/fmi3_run.c, compiled by gcc
and by MinGW-w64) drives both binaries of each FMI 3.0 FMU through the same
calls: the runs of test_wine.py (a run-up from standstill to the model's speed,
then the unbalance doubled; the hydro unit also on its reduced rotor, the
Jeffcott rotor also up into oil whirl; equal internal steps of 60 per
revolution at the top speed, at most 1 ms; 400 communication steps), the
inputs sampled from the same tables at each communication point and held over
the step (FMI 3.0 has no input derivatives). Every output must agree by the
tolerance policy of test_wine.py (TOLERANCE relative to the output's largest
magnitude; the oil whirl to ROUNDOFF_FACTOR times what the linux64 run moves
under inputs scaled by 1 + ROUNDOFF; the slow-pad unit to SLOW_PAD_TOLERANCE;
element torques to SHAFT_TORQUE_TOLERANCE). Each FMU must carry both binaries.
"""
import os
import shutil
import struct
import subprocess
import sys
import tempfile
import tomllib
import zipfile

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import test_wine as w  # noqa: E402  (the FMI 2.0 test's policy and helpers)

STEPS = 400


def hexbits(x):
    return struct.pack(">d", float(x)).hex()


def entry(vr, value):
    """One value to set: an integer (Int32) as it is, a real as its bits."""
    if isinstance(value, int):
        return f"{vr} i {value}"
    return f"{vr} f {hexbits(value)}"


def plan_text(outputs, init, steps):
    """The plan fmi3_run.c reads: outputs, the values set before
    initialization, then each step (t, h, inputs)."""
    lines = [f"outputs {len(outputs)} " + " ".join(str(vr) for vr in outputs)]
    lines.append(f"init {len(init)} " + " ".join(entry(vr, v) for vr, v in init))
    for t, h, inputs in steps:
        lines.append(f"step {hexbits(t)} {hexbits(h)} {len(inputs)} "
                     + " ".join(entry(vr, v) for vr, v in inputs))
    return "\n".join(lines) + "\n"


def rows(text):
    """The rows fmi3_run printed, as an array (row k → output values)."""
    out = []
    for line in text.splitlines():
        p = line.split()
        if p and p[0] == "row":
            out.append([struct.unpack(">d", bytes.fromhex(x))[0] for x in p[2:]])
    return np.array(out)


def main(root):
    out = os.path.join(root, "out")
    failures = []
    prefix, cc, _ = w.wine_env(root)
    loader = "/usr/lib/wine/wine64"
    for need in (loader, os.path.join(prefix, "system.reg")):
        if not os.path.exists(need):
            sys.exit(f"{need} missing: run scripts/setup.sh")
    env = dict(os.environ, WINEPREFIX=prefix, WINEDEBUG="-all")

    def winpath(p):
        return "Z:" + os.path.abspath(p).replace("/", "\\")

    tmp = tempfile.mkdtemp(prefix="rotor wine3 ")  # a space, as in paths users have
    try:
        tools = os.path.join(tmp, "tools")
        os.makedirs(tools)
        src = os.path.join(root, "tests", "wine")
        bcrypt = os.path.join(tools, "bcryptprimitives.dll")
        for cmd in (
            [cc, "-shared", "-O2", "-Wall", "-Wextra", "-Werror", "-o", bcrypt,
             os.path.join(src, "bcryptprimitives.c"), os.path.join(src, "bcryptprimitives.def"), "-ladvapi32"],
            [cc, "-O2", "-Wall", "-Wextra", "-Werror", "-o", os.path.join(tools, "fmi3_run.exe"),
             os.path.join(src, "fmi3_run.c")],
            ["cc", "-O2", "-Wall", "-Wextra", "-Werror", "-o", os.path.join(tools, "fmi3_run"),
             os.path.join(src, "fmi3_run.c"), "-ldl"],
        ):
            r = subprocess.run(cmd, capture_output=True, text=True)
            if r.returncode != 0:
                sys.exit(f"{' '.join(cmd)} failed:\n{r.stderr}")

        from fmpy import read_model_description
        stems = sorted(m[:-5] for m in os.listdir(os.path.join(root, "models")) if m.endswith(".toml"))
        runs = []
        for stem in stems:
            model = tomllib.load(open(os.path.join(root, "models", stem + ".toml"), "rb"))
            rpm = float(model.get("speed_rpm", 0.0))
            runs.append((stem, f"{stem}: run-up to {rpm:g} rpm", rpm, {}, stem in w.CHAOTIC_RUN_UPS))
            if stem == "hydro_unit":
                runs.append((stem, f"{stem}: reduced rotor (10 modes), run-up to {rpm:g} rpm", rpm,
                             {"solver.reduced_modes": 10}, False))
            if stem == "jeffcott":
                runs.append((stem, f"{stem}: run-up to 12000 rpm, into oil whirl", 12000.0, {}, True))

        dirs = {}
        for stem in stems:
            fmu = os.path.join(out, ("RotorBearing" if stem == "hydro_unit" else stem) + "_fmi3.fmu")
            if not os.path.exists(fmu):
                sys.exit(f"{fmu} missing: run fmu_pack.sh --fmi 2,3 (scripts/test.sh packs every model)")
            names = set(zipfile.ZipFile(fmu).namelist())
            binaries = {"binaries/x86_64-linux/RotorBearing.so", "binaries/x86_64-windows/RotorBearing.dll"}
            if not binaries <= names:
                sys.exit(f"{fmu} lacks {', '.join(sorted(binaries - names))}: pack it for both platforms")
            d = os.path.join(tmp, "fmu", stem)
            zipfile.ZipFile(fmu).extractall(d)
            shutil.copy(bcrypt, os.path.join(d, "binaries", "x86_64-windows"))
            dirs[stem] = (fmu, d)

        worst_all, where_all, same_all, total_all = 0.0, "", 0, 0
        for i, (stem, label, rpm, start, amplifies) in enumerate(runs):
            fmu, d = dirs[stem]
            md = read_model_description(fmu)
            variables = {v.name: v for v in md.modelVariables}
            outputs = [v.name for v in md.modelVariables if v.causality == "output" and not v.dimensions]
            drive = [v.name for v in md.modelVariables
                     if v.causality == "input" and v.name.startswith("torques.") and not v.dimensions]
            unbalance = [v.name for v in md.modelVariables if v.causality == "input" and not v.dimensions
                         and v.name != "shaft.speed" and v.name not in drive]
            stop = max(1.0, 40.0 * 60.0 / rpm)
            t_table = np.array([0.0, stop / 2, stop])
            if drive:
                cols = [(drive[0], np.array([0.0, w.DRIVE_TORQUE, w.DRIVE_TORQUE]))]
            else:
                cols = [("shaft.speed", np.array([0.0, rpm, rpm]) * np.pi / 30.0)]
            for u in unbalance:
                m_e = float(variables[u].start)
                cols.append((u, np.array([m_e, m_e, 2.0 * m_e])))
            spec = tomllib.load(open(os.path.join(root, "models", stem + ".toml"), "rb"))
            top = spec.get("max_speed_rpm", spec.get("speed_rpm", 0.0)) or 1000.0
            params = {"solver.local_error_tolerance": 0.0, "solver.time_step": min(1e-3, 1.0 / top), **start}
            h = stop / STEPS

            def plan(scale):
                inputs = lambda t: [(variables[n].valueReference, float(np.interp(t, t_table, c)) * scale)
                                    for n, c in cols]
                init = [(variables[n].valueReference, v) for n, v in params.items()] + inputs(0.0)
                steps = [(k * h, h, inputs(k * h)) for k in range(STEPS)]
                return plan_text([variables[n].valueReference for n in outputs], init, steps)

            plan_file = os.path.join(tmp, f"plan{i}.txt")
            open(plan_file, "w").write(plan(1.0))
            token = md.instantiationToken
            so = os.path.join(d, "binaries", "x86_64-linux", "RotorBearing.so")
            dll = os.path.join(d, "binaries", "x86_64-windows", "RotorBearing.dll")
            resources = os.path.join(d, "resources")
            lin = subprocess.run([os.path.join(tools, "fmi3_run"), so, token, resources + "/", plan_file],
                                 capture_output=True, text=True, timeout=w.RUN_TIMEOUT)
            win = subprocess.run([loader, os.path.join(tools, "fmi3_run.exe"), winpath(dll), token,
                                  winpath(resources) + "\\", winpath(plan_file)],
                                 env=env, capture_output=True, text=True, timeout=w.RUN_TIMEOUT)
            bad_run = False
            for name, r in (("linux64", lin), ("win64", win)):
                if r.returncode != 0 or not r.stdout.rstrip().endswith("ok"):
                    failures.append(f"{label} ({name}): exit {r.returncode}\n{r.stderr[-2000:]}")
                    bad_run = True
            if bad_run:
                continue
            L, W = rows(lin.stdout), rows(win.stdout)
            if L.shape != (STEPS + 1, len(outputs)) or W.shape != L.shape:
                failures.append(f"{label}: {L.shape} linux64 rows vs {W.shape} win64 rows")
                continue
            lin_cols = {n: L[:, j] for j, n in enumerate(outputs)}
            win_cols = {n: W[:, j] for j, n in enumerate(outputs)}
            floor, note = 0.0, ""
            if amplifies:
                scaled_file = os.path.join(tmp, f"plan{i}.scaled.txt")
                open(scaled_file, "w").write(plan(1.0 + w.ROUNDOFF))
                r = subprocess.run([os.path.join(tools, "fmi3_run"), so, token, resources + "/", scaled_file],
                                   capture_output=True, text=True, timeout=w.RUN_TIMEOUT)
                if r.returncode != 0:
                    failures.append(f"{label} (linux64, scaled inputs): exit {r.returncode}\n{r.stderr[-2000:]}")
                    continue
                S = rows(r.stdout)
                moved = w.compare({n: S[:, j] for j, n in enumerate(outputs)}, lin_cols, outputs)[0]
                floor = w.ROUNDOFF_FACTOR * moved
                note = f"; inputs scaled by 1 + {w.ROUNDOFF:g} move the linux64 run by {moved:.3e}"
            if stem in w.SLOW_PAD_RUNS:
                floor = max(floor, w.SLOW_PAD_TOLERANCE)
                note += f"; the slow-pad rule's iterations: {w.SLOW_PAD_TOLERANCE:g} allowed"
            worst, where, same, total, bad = w.compare(win_cols, lin_cols, outputs, floor=floor)
            print(f"FMI 3.0 {label}: {STEPS + 1} points × {len(outputs)} outputs, win64 (Wine) vs linux64: "
                  f"largest relative difference {worst:.3e} ({where}), {same} of {total} values bit-identical{note}")
            failures += [f"FMI 3.0 {label}: {b}" for b in bad]
            if worst > worst_all:
                worst_all, where_all = worst, f"{label}, {where}"
            same_all += same
            total_all += total
        print(f"FMI 3.0 win64 under Wine vs linux64 over {len(runs)} runs: largest relative difference "
              f"{worst_all:.3e} ({where_all}); {same_all} of {total_all} values bit-identical")
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    if failures:
        print("\n".join(failures), file=sys.stderr)
        sys.exit(1)
    print(f"{len(dirs)} FMI 3.0 FMUs: win64 binary under Wine equals linux64 to {w.TOLERANCE:g} (the policy "
          f"of test_wine.py)")


if __name__ == "__main__":
    main(sys.argv[1])
