"""The win64 binary of every packed FMU, run under Wine, against its linux64 binary.

Run by tests/wine.rs with the project's venv; argv: repo root. Needs the FMUs in
out/ packed for both platforms (scripts/test.sh runs fmu_pack.sh for each model)
and the cross toolchain and Wine prefix of scripts/setup.sh.

1. Every packed FMU carries binaries/linux64/RotorBearing.so and
   binaries/win64/RotorBearing.dll.
2. FMPy simulates each FMU through its win64 binary (remote_platform="win64":
   FMPy's server_tcp.exe loads the DLL under Wine) and natively through its
   linux64 binary, with the same inputs: a run-up from standstill (journals on
   their bushings) to the model's speed, then the unbalance doubled; the hydro
   unit also on its reduced rotor, the Jeffcott rotor also up into oil whirl;
   equal internal steps. Every output must agree to 1e-9 relative to its largest magnitude in the run
   (an output that is zero throughout must be zero on both). The whirl run
   grows out of small perturbations and the last-bit differences grow with it
   and stay on the limit cycle: there the binaries may differ by three times
   what the linux64 run itself moves when its inputs are scaled by 1 + 1e-14
   (ROUNDOFF), where that exceeds 1e-9 (measured at 2735545 1.7e-10 between
   the binaries, 3.1e-10 for the scaled inputs; 1.04e-9 and 6.6e-10 before the
   film potential took one arc tangent per arc).
3. FMU states through both binaries with one C importer (tests/wine/fmu_state.c,
   compiled by gcc and by MinGW-w64): get/set state (rollback) and
   serialize/deserialize continue bit-identically on each platform; a state
   serialized by one platform's binary continues in the other's to 1e-6 (at
   the default accuracy-controlled steps; ADAPTIVE_STATE_TOLERANCE); bad
   states and inputs give fmi2Error.
4. Why the two binaries are not bit-identical: the math library calls of the
   binary (tests/wine/libm_probe.c) on both platforms agree to 1 ulp (sin and cos
   to 2.3e-16 absolute), but not bit for bit.

The Wine copy of each FMU is the packed FMU without binaries/linux64 (FMPy
remotes only an FMU its host cannot run) and with the stand-in
bcryptprimitives.dll next to RotorBearing.dll (Wine 8 lacks that system DLL;
tests/wine/bcryptprimitives.c). The shipped FMU is never changed.
"""
import fcntl
import json
import os
import shutil
import struct
import subprocess
import sys
import tempfile
import tomllib
import zipfile

import numpy as np

TOLERANCE = 1e-9
# The run-ups take equal internal steps (60 per revolution at the model's top
# speed, at most 1 ms), where the two binaries differ by round-off only. The state
# runs keep the FMU's default accuracy-controlled steps: there a last-bit
# difference of the math libraries moves the error estimate by more than an
# ulp and, where it sits near a threshold, a step size (measured 9.6e-9 of the
# largest output on the Jeffcott rotor, 1e-11 elsewhere; with a step decision
# flipped, runs differ by the local error tolerance, 3e-3).
ADAPTIVE_STATE_TOLERANCE = 1e-6
# An element torque is k (θ_k+1 − θ_k): a small difference of twist angles that
# grow to hundreds of radians in a run-up, so its round-off is that of the
# angles times the element stiffness (measured 5.7e-10 of the largest element
# torque on the torque-driven hydro unit, where every other output stays within
# TOLERANCE).
SHAFT_TORQUE_TOLERANCE = 1e-8
# The oil-whirl run grows out of small perturbations and amplifies round-off
# itself: its linux64 run again with every input scaled by 1 + ROUNDOFF (45
# ulp) measures by how much (3.1e-10 at 2735545; at 9b33860 6.6e-10, and
# 5.5e-10 with the unbalance alone 4 ulp off), and the binaries may differ
# there by ROUNDOFF_FACTOR times that where it exceeds TOLERANCE (measured
# 1.7e-10 at 2735545, 1.04e-9 at 9b33860). Not the other runs: a scaled speed
# or unbalance is also a physical change, which moves some of them far more
# than round-off does (1.9e-7 on the bracket unit at 9b33860, whose binaries
# differ by 2e-11).
ROUNDOFF = 1e-14
ROUNDOFF_FACTOR = 3.0
# Run-ups that amplify round-off themselves, judged as the oil whirl is: the
# compressor from rest to 11 500 rpm in 0.5 s (23 000 rpm/s) drags its ten
# finite-film pads off their contacts within milliseconds, and its linux64
# run with every input scaled by 1 + ROUNDOFF moves by 0.115 of an output's
# largest value (its binaries differ by 0.11).
CHAOTIC_RUN_UPS = {"compressor"}
# The unit on brackets' run-up passes its nearly unloaded pads through the
# slow-contraction rule of docs/solver.md (solver/slow_pads.rs), whose choice
# to extrapolate a pad follows the last digits of its contraction ratios: the
# binaries take different iterations to the same Newton tolerance, and agree
# to that tolerance's reach, not to round-off (measured 8.5e-8 of the largest
# relative housing displacement; Newton stops at 1e-8 of the displacement
# scale, at least the smallest clearance).
# The three-guide unit as installed (its turbine guide 0.12 mm off) runs up
# from rest with that guide's pads pressed and the others unloaded: its
# iterations follow the last digits the same way (measured 1.3e-9 of the
# largest turbine-guide displacement through FMI 2.0, 2.5e-9 through FMI 3.0,
# the straight unit 3.4e-13).
SLOW_PAD_RUNS = {"hydro_unit_brackets", "hydro_unit_three_guide_offset"}
SLOW_PAD_TOLERANCE = 1e-7
# The torque that drives a torque-driven model's run-up and state runs (N·m):
# past the breakaway torque of the shipped torque-driven unit's thrust bearing
# (1.16e6 N·m, models/hydro_unit_torque.toml), so that the shaft turns.
DRIVE_TORQUE = 2.0e6
RUN_TIMEOUT = 600  # s, per FMPy run under Wine (they take seconds)


def wine_env(root):
    """The cross toolchain's settings (scripts/win64_env.sh)."""
    script = ". scripts/win64_env.sh && printf '%s\\n' \"$WINEPREFIX\" \"$WIN64_CC\" \"$WIN64_CACHE\""
    out = subprocess.run(["bash", "-c", script], cwd=root, capture_output=True, text=True, check=True)
    prefix, cc, cache = out.stdout.split("\n")[:3]
    return prefix, cc, cache


def remote_run(job):
    """`--remote JOB.json`: one FMPy run through the win64 binary under Wine, in
    its own process (FMPy's remoting client cannot be loaded twice in one
    process: its RPC thread outlives the unloaded library). JOB: FMU folder,
    simulate_fmu keywords, input table (.npy), result (.npy)."""
    from fmpy import simulate_fmu
    spec = json.load(open(job))
    res = simulate_fmu(spec["fmu"], remote_platform="win64", input=np.load(spec["input"]), **spec["kwargs"])
    np.save(spec["result"], res)


BEARING_LOADS = (".dynamic_fx", ".dynamic_fy", ".dynamic_load", ".static_fx", ".static_fy")


def load_scale_source(name, names):
    """A bearing's static load is its force at the equilibrium, its dynamic
    load the force less the static one: their round-off is that of the force
    (a horizontal rotor's static_fx is zero to the Newton tolerance), so the
    force components (`.fx`, `.fy` of the same bearing, where output) set
    their scale; None for other outputs."""
    for suffix in BEARING_LOADS:
        if name.endswith(suffix):
            stem = name[: -len(suffix)]
            return [n for n in (stem + ".fx", stem + ".fy") if n in names]
    return None


def compare(a, b, names, floor=0.0):
    """Largest relative difference over `names` (relative to each output's largest
    magnitude in `b`, the shaft's element torques to the largest of them, a
    bearing's dynamic load to its force), the output where it is, bit-identical samples, samples,
    and the outputs that break the rules (a relative difference above its
    tolerance and above `floor`)."""
    worst, where, same, total, bad = 0.0, "", 0, 0, []
    # The element torques of a torque-driven shaft are one family: an element
    # near a free end carries a small part of what the shaft transmits, and
    # its round-off is that of the largest element torque, its scale.
    family = [n for n in names if n.startswith("shaft.torque[")]
    shaft_scale = max((float(np.max(np.abs(b[n]))) for n in family), default=0.0)
    for n in names:
        d = float(np.max(np.abs(a[n] - b[n])))
        s = shaft_scale if n in family else float(np.max(np.abs(b[n])))
        forces = load_scale_source(n, names)
        if forces:
            s = max([s] + [float(np.max(np.abs(b[f]))) for f in forces])
        same += int(np.sum(a[n] == b[n]))
        total += len(b[n])
        if not (np.all(np.isfinite(a[n])) and np.all(np.isfinite(b[n]))):
            bad.append(f"{n} not finite")
            continue
        if s == 0.0:
            if d != 0.0:
                bad.append(f"{n}: zero on linux64, up to {d:.3e} on win64")
            continue
        if d / s > worst:
            worst, where = d / s, n
        if d / s > max(floor, SHAFT_TORQUE_TOLERANCE if n in family else TOLERANCE):
            bad.append(f"{n}: differs by {d:.3e} ({d / s:.3e} of its largest value {s:.3e})")
    return worst, where, same, total, bad


def rel_diff(a, b, scale):
    """Largest |a - b| relative to each column's scale; infinite where a column
    with scale 0 (zero throughout) is not zero in both."""
    d = np.abs(a - b)
    if a.shape != b.shape or np.any(d[:, scale == 0.0] != 0.0):
        return float("inf")
    return float(np.max(d[:, scale > 0.0] / scale[scale > 0.0], initial=0.0))


def hex_rows(text, tag):
    """The rows a fmu_state run printed under `tag`, as an array (k → values)."""
    rows = {}
    for line in text.splitlines():
        p = line.split()
        if p and p[0] == tag:
            rows[int(p[1])] = [struct.unpack(">d", bytes.fromhex(x))[0] for x in p[2:]]
    return np.array([rows[k] for k in sorted(rows)]), min(rows) if rows else 0


def main(root):
    out = os.path.join(root, "out")
    failures = []
    prefix, cc, cache = wine_env(root)
    loader = "/usr/lib/wine/wine64"
    for need in (loader, os.path.join(prefix, "system.reg")):
        if not os.path.exists(need):
            sys.exit(f"{need} missing: run scripts/setup.sh")
    if os.path.realpath(os.path.join(prefix, "dosdevices", "z:")) != "/":
        sys.exit(f"{prefix}: drive Z: does not map to / (recreate the prefix: remove it, run scripts/setup.sh)")
    env = dict(os.environ, WINEPREFIX=prefix, WINEDEBUG="-all")

    def winpath(p):
        return "Z:" + os.path.abspath(p).replace("/", "\\")

    def wine(args, **kw):
        return subprocess.run([loader] + args, env=env, capture_output=True, text=True, timeout=RUN_TIMEOUT, **kw)

    tmp = tempfile.mkdtemp(prefix="rotor wine ")  # a space: URIs are percent-encoded
    try:
        # The test's tools: the stand-in DLL, the importer and the probe, for both platforms.
        tools = os.path.join(tmp, "tools")
        os.makedirs(tools)
        src = os.path.join(root, "tests", "wine")
        bcrypt = os.path.join(tools, "bcryptprimitives.dll")
        builds = [
            [cc, "-shared", "-O2", "-Wall", "-Wextra", "-Werror", "-o", bcrypt,
             os.path.join(src, "bcryptprimitives.c"), os.path.join(src, "bcryptprimitives.def"), "-ladvapi32"],
            [cc, "-O2", "-Wall", "-Wextra", "-Werror", "-o", os.path.join(tools, "fmu_state.exe"),
             os.path.join(src, "fmu_state.c")],
            ["cc", "-O2", "-Wall", "-Wextra", "-Werror", "-o", os.path.join(tools, "fmu_state"),
             os.path.join(src, "fmu_state.c"), "-ldl"],
            # As the DLL: msvcrt.dll's functions, then MinGW's own (sincos).
            [cc, "-O0", "-fno-builtin", "-Wall", "-Wextra", "-Werror", "-o", os.path.join(tools, "libm_probe.exe"),
             os.path.join(src, "libm_probe.c"), "-lmsvcrt"],
            ["cc", "-O0", "-fno-builtin", "-D_GNU_SOURCE", "-Wall", "-Wextra", "-Werror",
             "-o", os.path.join(tools, "libm_probe"), os.path.join(src, "libm_probe.c"), "-lm"],
        ]
        for cmd in builds:
            r = subprocess.run(cmd, capture_output=True, text=True)
            if r.returncode != 0:
                sys.exit(f"{' '.join(cmd)} failed:\n{r.stderr}")

        # 1. Both binaries in every packed FMU.
        stems = sorted(m[:-5] for m in os.listdir(os.path.join(root, "models")) if m.endswith(".toml"))
        fmus = {s: os.path.join(out, "RotorBearing.fmu" if s == "hydro_unit" else s + ".fmu") for s in stems}
        copies = {}
        for stem, fmu in fmus.items():
            if not os.path.exists(fmu):
                sys.exit(f"{fmu} missing: run fmu_pack.sh (scripts/test.sh packs every model)")
            names = zipfile.ZipFile(fmu).namelist()
            binaries = {"binaries/linux64/RotorBearing.so", "binaries/win64/RotorBearing.dll"}
            missing = sorted(binaries - set(names))
            if missing:
                sys.exit(f"{fmu} lacks {', '.join(missing)}: pack it for both platforms (fmu_pack.sh default)")
            extra = sorted(n for n in names if n.startswith("binaries/") and n not in binaries)
            if extra:  # such as the test's bcryptprimitives.dll stand-in
                failures.append(f"{fmu} carries more than its two binaries: {', '.join(extra)}")
            d = os.path.join(tmp, "fmu", stem)
            zipfile.ZipFile(fmu).extractall(d)
            shutil.copy(bcrypt, os.path.join(d, "binaries", "win64"))
            copies[stem] = d

        # 2. FMPy through the win64 binary under Wine against the linux64 binary.
        from fmpy import read_model_description, simulate_fmu
        runs = []
        for stem in stems:
            model = tomllib.load(open(os.path.join(root, "models", stem + ".toml"), "rb"))
            rpm = float(model.get("speed_rpm", 0.0))
            runs.append((stem, f"{stem}: run-up to {rpm:g} rpm", rpm, {}, stem in CHAOTIC_RUN_UPS))
            if stem == "hydro_unit":
                runs.append((stem, f"{stem}: reduced rotor (10 modes), run-up to {rpm:g} rpm", rpm,
                             {"solver.reduced_modes": 10}, False))
            if stem == "jeffcott":
                runs.append((stem, f"{stem}: run-up to 12000 rpm, into oil whirl", 12000.0, {}, True))
        jobs, plans = [], []
        for i, (stem, label, rpm, start, amplifies) in enumerate(runs):
            md = read_model_description(fmus[stem])
            variables = {v.name: v for v in md.modelVariables}
            outputs = [v.name for v in md.modelVariables if v.causality == "output"]
            # A torque-driven shaft (shaft.speed an output) runs up from rest
            # under its first torque input instead, ramped to DRIVE_TORQUE.
            drive = [v.name for v in md.modelVariables if v.causality == "input" and v.name.startswith("torques.")]
            unbalance = [v.name for v in md.modelVariables
                         if v.causality == "input" and v.name != "shaft.speed" and v.name not in drive]
            # 40 revolutions at speed, at least 1 s; 400 communication points.
            stop = max(1.0, 40.0 * 60.0 / rpm)
            t = np.array([0.0, stop / 2, stop])
            if drive:
                cols = [("time", t), (drive[0], np.array([0.0, DRIVE_TORQUE, DRIVE_TORQUE]))]
            else:
                cols = [("time", t), ("shaft.speed", np.array([0.0, rpm, rpm]) * np.pi / 30.0)]
            for u in unbalance:
                m_e = float(variables[u].start)
                cols.append((u, np.array([m_e, m_e, 2.0 * m_e])))
            table = np.array(list(zip(*[c for _, c in cols])), dtype=[(n, np.float64) for n, _ in cols])
            table_file = os.path.join(tmp, f"input{i}.npy")
            np.save(table_file, table)
            # Equal steps of 60 per revolution at the model's top speed (its
            # max_speed_rpm, else speed_rpm), at most 1 ms.
            spec = tomllib.load(open(os.path.join(root, "models", stem + ".toml"), "rb"))
            top = spec.get("max_speed_rpm", spec.get("speed_rpm", 0.0)) or 1000.0
            equal_steps = {"solver.local_error_tolerance": 0.0, "solver.time_step": min(1e-3, 1.0 / top)}
            kwargs = dict(stop_time=stop, output_interval=stop / 400, start_values={**equal_steps, **start},
                          output=outputs)
            # A fresh copy per run: FMPy adds its remoting client and server to the folder.
            run_dir = os.path.join(tmp, "run", f"{i} {stem}")
            shutil.copytree(copies[stem], run_dir)
            shutil.rmtree(os.path.join(run_dir, "binaries", "linux64"))
            jobs.append((run_dir, dict(kwargs), table_file, os.path.join(tmp, f"win{i}.npy")))
            plans.append((stem, label, kwargs, table, outputs, amplifies))

        # FMPy's remoting uses one TCP port (8080): one remoting run on this
        # machine at a time. tests/wine/wine64 stands in for Wine's loader; the
        # remoting chatter goes to a log, shown if a run fails.
        worker_env = dict(env, PATH=src + os.pathsep + os.environ["PATH"], TMPDIR=tmp)
        log = os.path.join(tmp, "remoting.log")
        with open(os.path.join(cache, "fmpy-remoting.lock"), "w") as lock, open(log, "w") as logf:
            fcntl.flock(lock, fcntl.LOCK_EX)
            for i, job in enumerate(jobs):
                spec = os.path.join(tmp, f"job{i}.json")
                json.dump(dict(zip(("fmu", "kwargs", "input", "result"), job)), open(spec, "w"))
                try:
                    r = subprocess.run([sys.executable, os.path.abspath(__file__), "--remote", spec], env=worker_env,
                                       stdout=logf, stderr=logf, timeout=RUN_TIMEOUT)
                    problem = None if r.returncode == 0 else f"exit status {r.returncode}"
                except subprocess.TimeoutExpired:
                    problem = f"no result within {RUN_TIMEOUT} s"
                if problem:
                    logf.flush()
                    tail = open(log, errors="replace").read()[-4000:]
                    sys.exit(f"{plans[i][1]}: FMPy under Wine failed ({problem})\n--- remoting log (end) ---\n{tail}")

        worst_all, where_all, same_all, total_all = 0.0, "", 0, 0
        for (stem, label, kwargs, table, outputs, amplifies), job in zip(plans, jobs):
            win = np.load(job[3])
            lin = simulate_fmu(fmus[stem], input=table, **dict(kwargs))
            if len(win) != len(lin) or np.any(win["time"] != lin["time"]):
                failures.append(f"{label}: {len(win)} win64 rows vs {len(lin)} linux64 rows (or other times)")
                continue
            # A self-excited run: how much it amplifies round-off itself,
            # linux64 again with every input scaled by 1 + ROUNDOFF.
            floor, note = 0.0, ""
            if amplifies:
                scaled = table.copy()
                for n in table.dtype.names[1:]:
                    scaled[n] = table[n] * (1.0 + ROUNDOFF)
                moved = compare(simulate_fmu(fmus[stem], input=scaled, **dict(kwargs)), lin, outputs)[0]
                floor = ROUNDOFF_FACTOR * moved
                note = f"; inputs scaled by 1 + {ROUNDOFF:g} move the linux64 run by {moved:.3e}"
            if stem in SLOW_PAD_RUNS:
                floor = max(floor, SLOW_PAD_TOLERANCE)
                note += f"; the slow-pad rule's iterations: {SLOW_PAD_TOLERANCE:g} allowed"
            worst, where, same, total, bad = compare(win, lin, outputs, floor=floor)
            print(f"{label}: {len(lin)} points × {len(outputs)} outputs, win64 (Wine) vs linux64: largest "
                  f"relative difference {worst:.3e} ({where}), {same} of {total} values bit-identical{note}")
            failures += [f"{label}: {b}" for b in bad]
            if worst > worst_all:
                worst_all, where_all = worst, f"{label}, {where}"
            same_all += same
            total_all += total

        # 3. FMU states through both binaries, and states exchanged between them.
        state_worst = 0.0
        for stem in stems:
            d = copies[stem]
            md = read_model_description(os.path.join(d, "modelDescription.xml"))
            model = tomllib.load(open(os.path.join(root, "models", stem + ".toml"), "rb"))
            # The importer ramps the speed by 20 %: within the model's trip
            # speed (the compressor's is 105 % of its speed_rpm).
            rpm = float(model.get("speed_rpm", 0.0))
            if "max_speed_rpm" in model:
                rpm = min(rpm, float(model["max_speed_rpm"]) / 1.2)
            w0 = rpm * np.pi / 30.0
            # The driven input: the speed, or a torque-driven shaft's first torque.
            drive = [v for v in md.modelVariables if v.causality == "input" and v.name.startswith("torques.")]
            if drive:
                speed_vr, w0 = str(drive[0].valueReference), DRIVE_TORQUE
            else:
                speed_vr = str(next(v.valueReference for v in md.modelVariables if v.name == "shaft.speed"))
            outs = [str(v.valueReference) for v in md.modelVariables if v.causality == "output"]
            steps, h = 100, 0.01
            uri_linux = "file://" + (d + "/resources").replace(" ", "%20")
            uri_win = "file:///Z:" + (d + "/resources").replace(" ", "%20")
            l_state, w_state = os.path.join(tmp, f"{stem}.linux64.state"), os.path.join(tmp, f"{stem}.win64.state")
            so, dll = os.path.join(d, "binaries/linux64/RotorBearing.so"), os.path.join(d, "binaries/win64/RotorBearing.dll")
            base = [md.guid]
            lin1 = subprocess.run([os.path.join(tools, "fmu_state"), so] + base + [uri_linux, speed_vr, repr(w0), repr(h),
                                  str(steps), l_state, "-"] + outs, capture_output=True, text=True, timeout=RUN_TIMEOUT)
            win = wine([os.path.join(tools, "fmu_state.exe"), winpath(dll)] + base + [uri_win, speed_vr, repr(w0), repr(h),
                       str(steps), winpath(w_state), winpath(l_state)] + outs)
            lin2 = subprocess.run([os.path.join(tools, "fmu_state"), so] + base + [uri_linux, speed_vr, repr(w0), repr(h),
                                  str(steps), l_state + ".again", w_state] + outs,
                                  capture_output=True, text=True, timeout=RUN_TIMEOUT)
            ok = True
            for name, r in (("linux64", lin1), ("win64", win), ("linux64, the win64 state", lin2)):
                if r.returncode != 0 or not r.stdout.rstrip().endswith("ok"):
                    failures.append(f"{stem} FMU states ({name}): exit {r.returncode}\n{r.stdout[-500:]}{r.stderr[-2000:]}")
                    ok = False
            if not ok:
                continue
            L, _ = hex_rows(lin1.stdout, "row")
            W, _ = hex_rows(win.stdout, "row")
            WL, half = hex_rows(win.stdout, "cont")   # the linux64 state continued by win64
            LW, _ = hex_rows(lin2.stdout, "cont")     # the win64 state continued by linux64
            scale = np.max(np.abs(L), axis=0)
            # A bearing load's scale is its bearing's force (load_scale_source).
            names = [v.name for v in md.modelVariables if v.causality == "output"]
            for j, n in enumerate(names):
                forces = load_scale_source(n, names)
                if forces:
                    scale[j] = max([scale[j]] + [scale[names.index(f)] for f in forces])
            pairs = {"win64 vs linux64": rel_diff(W, L, scale),
                     "linux64 state continued by win64": rel_diff(WL, L[half:], scale),
                     "win64 state continued by linux64": rel_diff(LW, W[half:], scale)}
            sizes = {os.path.getsize(l_state), os.path.getsize(w_state)}
            print(f"{stem} FMU states: rollback and deserialized continuation bit-identical on linux64 and on win64; "
                  + ", ".join(f"{k} {v:.3e}" for k, v in pairs.items()) + f"; serialized state {sizes.pop()} bytes")
            if sizes:
                failures.append(f"{stem}: the two binaries serialize states of different sizes")
            for k, v in pairs.items():
                state_worst = max(state_worst, v)
                if not v <= ADAPTIVE_STATE_TOLERANCE:
                    failures.append(f"{stem} FMU states: {k} differ by {v:.3e} relative")

        # 4. The math library calls of the binary on both platforms.
        lp = subprocess.run([os.path.join(tools, "libm_probe")], capture_output=True, text=True, check=True).stdout
        wp = wine([os.path.join(tools, "libm_probe.exe")]).stdout

        def probe(text):
            return {p[0]: np.array([int(x, 16) for x in p[1:]], dtype=np.uint64)
                    for p in (line.split() for line in text.splitlines()) if p}
        lp, wp = probe(lp), probe(wp)
        if set(lp) != set(wp) or any(len(lp[n]) != len(wp[n]) for n in lp):
            failures.append("libm probe: the two platforms printed different tables")
        else:
            parts = []
            for n in lp:
                a, b = lp[n].view(np.float64), wp[n].view(np.float64)
                ulps = int(np.max(np.abs(lp[n].view(np.int64) - wp[n].view(np.int64))))
                absd = float(np.max(np.abs(a - b)))
                differ = int(np.sum(lp[n] != wp[n]))
                trig = n in ("cos", "sincos.sin", "sincos.cos")
                parts.append(f"{n} {differ}/{len(a)} differ, " + (f"≤ {absd:.2e} absolute" if trig else f"≤ {ulps} ulp"))
                if (trig and absd > 2.3e-16) or (not trig and ulps > 1):
                    failures.append(f"libm probe: {n} differs by {ulps} ulp ({absd:.3e} absolute)")
            print("math library, glibc vs MinGW/msvcrt under Wine: " + "; ".join(parts))

        print(f"win64 under Wine vs linux64 over {len(plans)} FMPy runs: largest relative difference "
              f"{worst_all:.3e} ({where_all}); {same_all} of {total_all} values bit-identical; "
              f"FMU states exchanged between the binaries: largest relative difference {state_worst:.3e}")
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    if failures:
        print("\n".join(failures), file=sys.stderr)
        sys.exit(1)
    print(f"{len(stems)} FMUs: win64 binary under Wine equals linux64 to {TOLERANCE:g} (the oil whirl to "
          f"{ROUNDOFF_FACTOR:g}× what it moves under inputs scaled by 1 + {ROUNDOFF:g} where that is larger)")


if __name__ == "__main__":
    if sys.argv[1] == "--remote":
        remote_run(sys.argv[2])
    else:
        main(sys.argv[1])
