"""Parameter sweeps of a rotor-bearing FMU on Dask.

Every point is one FMPy simulation run inside a Dask worker at constant speed
(`shaft.speed` start value) with optional parameter overrides (viscosity,
unbalance, ...). The FMU is read once by the client and shipped to the workers,
so no shared file system is needed.

Per point and bearing the table gives the peak orbit radius, the peak contact
force (journal on its bushing or pads), the dominant
frequency of the full spectrum (sign = whirl direction) and its order (× running
speed), the sub-synchronous share and the growth rate of the sub-synchronous
whirl. A point whose analysed record is too short to tell 0.5× from 1× is
flagged `too_short` and never classified; a point at 0 rpm is a valid row
(at rest, no whirl, its contact forces the bearing loads). No point is lost:
- a solver failure (the FMU's static equilibrium or a step fails) is a row
  `error: solver: TYPE: message — FMU: its own message`;
- any other failure raises in the worker and is retried (`RETRIES` times, by
  Dask possibly on another worker); a point that still fails is a row
  `error: infrastructure: …` (unpacking, loading) or `error: refused: …` (a
  value the FMU refuses), and the command exits non-zero;
- the onset table names the failed grid points of each parameter set
  (`missing_rpm`), and the stability map marks them.
The onset of whirl of each parameter set is located by bisection between the
grid speeds where the classification changes, so the stability map gives
thresholds, not grid points.

Definitions (docs/system.md):
- analysed record: the outputs from `settle_fraction · duration` to the end;
  it must hold at least MIN_REVOLUTIONS revolutions;
- sub-synchronous share: the fraction of the spectral energy (Hann window, mean
  removed, both whirl directions) at |f| in [0.05, 0.8] × running speed;
- whirl growth rate σ (1/s): the exponential rate of the envelope of the
  sub-synchronous band of the orbit after the synchronous (1×, forward and
  backward) response is removed by least squares;
- a point whirls (is unstable) when its sub-synchronous band holds at least
  WHIRL_CONTENT of the orbit's RMS and either σ > 0 or the share is at least
  SATURATED_SHARE (a saturated whirl, a limit cycle that no longer grows).

    python system/sweep.py --fmu out/jeffcott.fmu --rpm 4000:16000:13 \\
        --param bearings.left.viscosity,bearings.right.viscosity=0.01,0.02,0.04 \\
        --duration 1.0 [--refine 6] [--scheduler tcp://host:8786 | --workers 2 | --serial] \\
        --out out/sweep
"""
import argparse
import csv
import hashlib
import itertools
import os
import sys
import tempfile
import time

import numpy as np

# The analysed record must hold this many revolutions: enough to put 0.5× and
# 1× ten frequency bins apart and to measure a whirl's growth over ten cycles.
MIN_REVOLUTIONS = 20
# Sub-synchronous band, in multiples of the running speed.
SUB_BAND = (0.05, 0.8)
# Share of the spectral energy above which a whirl counts as saturated (a limit
# cycle ten times the synchronous amplitude, no longer growing).
SATURATED_SHARE = 0.99
# A sub-synchronous band whose RMS is below this fraction of the orbit's RMS
# holds no whirl worth classifying (numerical noise, decayed transients).
WHIRL_CONTENT = 1e-2


def fmu_payload(path):
    """The FMU as (file name, SHA-256, bytes): read once, shipped to workers."""
    with open(path, "rb") as f:
        data = f.read()
    return os.path.basename(path), hashlib.sha256(data).hexdigest(), data


# Unpacked FMUs of this process, by SHA-256 (each worker process unpacks once).
_UNPACKED = {}


class InfrastructureError(RuntimeError):
    """A point that failed for a reason outside the FMU's solver (unpacking,
    loading, the file system): raised, so that Dask retries it elsewhere."""


class PointFailure(RuntimeError):
    """A point the FMU refused for a reason other than its solver (a value
    outside its declared range, a model it does not instantiate): deterministic,
    not retried, reported as a row and by a non-zero exit."""


def local_fmu(payload, root=None):
    """The folder holding the shipped FMU unpacked, once per host and content
    (the bytes checked against their SHA-256 first, once per process).

    Each process unpacks into a private temporary folder beside the final one
    (`root`, default the system temporary directory) and renames it into place
    in one step, so no process ever reads a half-written FMU: the final folder
    exists only complete. A process that loses the race to another removes its
    copy and uses the winner's."""
    import io
    import shutil
    import zipfile
    name, digest, data = payload
    if digest in _UNPACKED and os.path.isfile(os.path.join(_UNPACKED[digest], "modelDescription.xml")):
        return _UNPACKED[digest]
    if hashlib.sha256(data).hexdigest() != digest:
        raise InfrastructureError(f"{name}: the shipped bytes do not match their SHA-256 {digest[:16]}")
    root = root or tempfile.gettempdir()
    folder = os.path.join(root, f"rotor_sweep_{digest[:16]}")
    marker = os.path.join(folder, ".complete")
    if not os.path.isfile(marker):
        private = tempfile.mkdtemp(prefix=f"rotor_sweep_{digest[:16]}.", dir=root)
        try:
            with zipfile.ZipFile(io.BytesIO(data)) as z:
                z.extractall(private)
            open(os.path.join(private, ".complete"), "w").close()
            if os.path.isdir(folder) and not os.path.isfile(marker):
                # An incomplete folder left by an interrupted older unpacking: move it aside.
                try:
                    os.rename(folder, f"{private}.stale")
                except OSError:
                    pass  # another process moved it first
                shutil.rmtree(f"{private}.stale", ignore_errors=True)
            try:
                os.rename(private, folder)  # atomic; fails if another process was first
            except OSError:
                if not os.path.isfile(marker):
                    raise
        finally:
            shutil.rmtree(private, ignore_errors=True)
    _UNPACKED[digest] = folder
    return folder


def column_name(key):
    """A table column for a parameter that may set several variables at once."""
    return "+".join(key.split(","))


def whirl_metrics(t, x, y, f_spin):
    """Spectral metrics of one bearing's orbit over the analysed record.

    Returns dominant frequency (Hz, interpolated; negative = backward), its
    order, the sub-synchronous share and the growth rate σ (1/s) of the
    sub-synchronous whirl (-inf when the band holds only numerical noise)."""
    n = len(t)
    dt = (t[-1] - t[0]) / (n - 1)
    z = x + 1j * y
    z = z - z.mean()
    window = np.hanning(n)
    spectrum = np.abs(np.fft.fft(z * window)) / window.sum()
    freqs = np.fft.fftfreq(n, d=dt)
    energy = spectrum**2
    energy[0] = 0.0
    k = int(np.argmax(spectrum))
    # Parabolic interpolation of the log magnitude around the peak bin.
    a, b, c = (np.log(spectrum[(k + d) % n] + 1e-300) for d in (-1, 0, 1))
    shift = 0.5 * (a - c) / (a - 2 * b + c) if (a - 2 * b + c) != 0 else 0.0
    dominant = (k + shift) if k < n // 2 else (k - n + shift)
    dominant_hz = float(dominant / (n * dt))
    band = (np.abs(freqs) >= SUB_BAND[0] * f_spin) & (np.abs(freqs) <= SUB_BAND[1] * f_spin)
    total = energy.sum()
    share = float(energy[band].sum() / total) if total > 0 else 0.0
    # Growth of the sub-synchronous whirl: remove the synchronous response
    # (constant, e^{+iΩt}, e^{-iΩt}) by least squares, band-pass, fit log |envelope|.
    w = 2 * np.pi * f_spin
    basis = np.column_stack([np.ones(n), np.exp(1j * w * t), np.exp(-1j * w * t)])
    coef, *_ = np.linalg.lstsq(basis, x + 1j * y, rcond=None)
    residual = (x + 1j * y) - basis @ coef
    spec = np.fft.fft(residual)
    spec[~band] = 0.0
    sub = np.fft.ifft(spec)
    content = float(np.sqrt(np.mean(np.abs(sub) ** 2) / max(np.mean(np.abs(z) ** 2), 1e-300)))
    if content < WHIRL_CONTENT or not np.any(band):
        sigma = -np.inf
    else:
        inner = slice(n // 10, n - n // 10)  # away from the FFT's wrap-around
        envelope = np.abs(sub[inner])
        sigma = float(np.polyfit(t[inner], np.log(envelope + 1e-300), 1)[0])
    return {
        "dominant_hz": dominant_hz,
        "dominant_order": dominant_hz / f_spin if f_spin else float("nan"),
        "subsync_share": share,
        "growth_per_s": sigma,
        "whirl_content": content,
        "spectrum_hz": freqs,
        "spectrum": spectrum,
    }


# FMI calls whose failure is the solver's: the static equilibrium at the start
# speed (initialization) and the time steps.
SOLVER_CALLS = ("fmi2EnterInitializationMode", "fmi2ExitInitializationMode", "fmi2DoStep")
# Dask retries of a point that failed for an infrastructure reason.
RETRIES = 3


def failure_text(e, messages):
    """`Type: message` of an exception, with the FMU's own messages (never empty)."""
    text = str(e) or repr(e)
    fmu = " | ".join(messages)
    return f"{type(e).__name__}: {text}" + (f" — FMU: {fmu}" if fmu else "")


def simulate_point(payload, rpm, overrides, duration, output_interval, settle_fraction=0.5):
    """One sweep point as a flat dict. A solver failure (the FMU's static
    equilibrium or a step failing) is a row with status `error: solver: …`;
    a value or model the FMU refuses raises `PointFailure`; anything else
    (unpacking, loading, the file system) raises `InfrastructureError`, which
    Dask retries."""
    from fmpy import read_model_description, simulate_fmu
    from fmpy.fmi1 import FMICallException
    row = {"rpm": rpm, **{column_name(k): v for k, v in overrides.items()}, "status": "ok"}
    messages = []

    def log(*args):
        status, text = args[-3], args[-1]
        text = text.decode(errors="replace") if isinstance(text, bytes) else str(text)
        if status not in (0, 1):  # the FMU's discards and errors explain a failure
            messages.append(text)

    f_spin = rpm / 60.0
    record = (1.0 - settle_fraction) * duration
    revolutions = record * f_spin
    row["revolutions"] = revolutions
    try:
        folder = local_fmu(payload)
        md = read_model_description(folder)
    except InfrastructureError:
        raise
    except Exception as e:
        raise InfrastructureError(f"{payload[0]} at {rpm} rpm: {failure_text(e, [])}") from e
    bearings = sorted({v.name.split(".")[1] for v in md.modelVariables
                       if v.name.startswith("bearings.") and v.name.endswith(".x")})
    outputs = [f"bearings.{b}.{q}" for b in bearings for q in ("x", "y", "contact_force")]
    # Equal internal steps, 60 per revolution at the point's speed (at most
    # 1 ms): a whirl onset is a growth rate near zero, and accuracy-controlled
    # steps, whose size changes, bias it (the Jeffcott onset 1.2 % below the
    # linear threshold at tolerance 3e-3, against 0.6 % at equal steps).
    start = {"shaft.speed": rpm * np.pi / 30.0,
             "solver.local_error_tolerance": 0.0,
             "solver.time_step": min(1e-3, 1.0 / max(rpm, 1.0))}
    for key, value in overrides.items():
        for name in key.split(","):
            start[name] = value
    try:
        res = simulate_fmu(folder, stop_time=duration, output_interval=output_interval, start_values=start,
                           output=outputs, logger=log)
    except FMICallException as e:
        if e.function not in SOLVER_CALLS:
            raise PointFailure(f"{rpm} rpm, {overrides}: {failure_text(e, messages)}") from e
        row["status"] = f"error: solver: {failure_text(e, messages)}".replace("\n", " ")[:600]
        return row
    except Exception as e:
        if messages:  # the FMU said why (e.g. it refused the model at instantiation)
            raise PointFailure(f"{rpm} rpm, {overrides}: {failure_text(e, messages)}") from e
        raise InfrastructureError(f"{payload[0]} at {rpm} rpm: {failure_text(e, messages)}") from e
    t = res["time"]
    keep = t >= settle_fraction * duration - 1e-12
    whirls = False
    for b in bearings:
        x, y = res[f"bearings.{b}.x"], res[f"bearings.{b}.y"]
        row[f"{b}.peak_radius_m"] = float(np.max(np.hypot(x[keep] - x[keep].mean(), y[keep] - y[keep].mean())))
        row[f"{b}.peak_contact_force_N"] = float(np.max(res[f"bearings.{b}.contact_force"][keep]))
        if rpm == 0.0 or revolutions < MIN_REVOLUTIONS:
            continue
        m = whirl_metrics(t[keep], x[keep], y[keep], f_spin)
        for q in ("dominant_hz", "dominant_order", "subsync_share", "growth_per_s", "whirl_content"):
            row[f"{b}.{q}"] = m[q]
        whirls |= m["whirl_content"] >= WHIRL_CONTENT and (
            m["growth_per_s"] > 0 or m["subsync_share"] >= SATURATED_SHARE)
        row["spectrum_hz"] = m["spectrum_hz"].tolist()
        row["spectrum"] = m["spectrum"].tolist()
    if rpm == 0.0:
        row["whirl"] = False  # at standstill nothing whirls: the journals rest on their bearings
    elif revolutions < MIN_REVOLUTIONS:
        row["status"] = (f"too_short: {revolutions:.1f} revolutions analysed, at least {MIN_REVOLUTIONS} "
                         f"needed (duration ≥ {MIN_REVOLUTIONS / f_spin / (1 - settle_fraction):.3g} s)")
    else:
        row["whirl"] = bool(whirls)
    return row


def failed_row(rpm, overrides, kind, e):
    """The row of a point that failed outside the solver (after its retries)."""
    return {"rpm": rpm, **{column_name(k): v for k, v in overrides.items()},
            "status": f"error: {kind}: {failure_text(e, [])}".replace("\n", " ")[:600]}


def failed_outside_solver(row):
    """Whether a row is a point lost for a reason other than the FMU's solver."""
    return row["status"].startswith("error:") and not row["status"].startswith("error: solver:")


def grid(rpms, params):
    names = list(params)
    for values in itertools.product(*[params[n] for n in names]):
        for rpm in rpms:
            yield rpm, dict(zip(names, values))


class Progress:
    """Progress on stderr: one updating line on a terminal, else a line per 10 %."""

    def __init__(self, total, what):
        self.total, self.what, self.start, self.shown = total, what, time.monotonic(), -1

    def __call__(self, done):
        elapsed = time.monotonic() - self.start
        left = elapsed / done * (self.total - done) if done else float("nan")
        text = f"{self.what}: {done}/{self.total} points ({100 * done // self.total} %), {elapsed:.0f} s, ~{left:.0f} s left"
        if sys.stderr.isatty():
            print("\r" + text, end="" if done < self.total else "\n", file=sys.stderr, flush=True)
        elif 10 * done // self.total > self.shown:
            self.shown = 10 * done // self.total
            print(text, file=sys.stderr, flush=True)


def run_points(payload, points, duration, output_interval, client=None, what="sweep"):
    """Simulate (rpm, overrides) points, serially or on a Dask client, in order
    (progress on stderr when `what` names the job). A point that raises is
    retried (`RETRIES` times; on Dask by the scheduler, possibly on another
    worker); one that still fails is a row `error: infrastructure: …` or
    `error: refused: …`, never dropped."""
    progress = Progress(len(points), what) if points and what else (lambda done: None)

    def lost(rpm, ov, e):
        # By name: on Dask the exception class comes back through pickling.
        kind = "refused" if type(e).__name__ == "PointFailure" else "infrastructure"
        return failed_row(rpm, ov, kind, e)

    if client is None:
        rows = []
        for i, (rpm, ov) in enumerate(points, start=1):
            for attempt in range(RETRIES + 1):
                try:
                    rows.append(simulate_point(payload, rpm, ov, duration, output_interval))
                    break
                except InfrastructureError as e:
                    if attempt == RETRIES:
                        rows.append(lost(rpm, ov, e))
                except PointFailure as e:
                    rows.append(lost(rpm, ov, e))
                    break
            progress(i)
        return rows
    from dask.distributed import as_completed
    # A fresh key per call: re-scattering the same bytes under their content hash
    # can race with the release of the previous call's copy.
    shipped = client.scatter(payload, broadcast=True, hash=False)
    futures = [client.submit(simulate_point, shipped, rpm, ov, duration, output_interval, pure=False,
                             retries=RETRIES)
               for rpm, ov in points]
    index = {f.key: i for i, f in enumerate(futures)}
    rows = [None] * len(futures)
    for done, future in enumerate(as_completed(futures), start=1):
        i = index[future.key]
        try:
            rows[i] = future.result()
        except Exception as e:  # retries exhausted: the point is reported, not dropped
            rows[i] = lost(*points[i], e)
        progress(done)
    return rows


def run_sweep(fmu, rpms, params, duration, output_interval, client=None):
    """The grid: every speed for every parameter combination, in grid order."""
    return run_points(fmu_payload(fmu), list(grid(rpms, params)), duration, output_interval, client)


def parameter_sets(rows, params):
    keys = [column_name(k) for k in params]
    sets = {}
    for r in rows:
        sets.setdefault(tuple(r[k] for k in keys), []).append(r)
    return keys, sets


def find_onsets(fmu, rows, params, duration, output_interval, refine, client=None):
    """Onset of whirl per parameter set, refined by bisection between the last
    stable and the first whirling grid speed. Returns (onset rows, refinement rows)."""
    payload = fmu_payload(fmu)
    keys, sets = parameter_sets(rows, params)
    brackets = {}
    onsets = []
    for values, rs in sets.items():
        rs = sorted(rs, key=lambda r: r["rpm"])
        entry = dict(zip(keys, values))
        judged = [r for r in rs if r["status"] == "ok"]
        # Grid points that failed are named in the table: an onset next to one
        # is only as good as the points around it.
        missing = [r["rpm"] for r in rs if r["status"].startswith("error")]
        entry["missing_rpm"] = " ".join(f"{x:g}" for x in missing)
        first = next((i for i, r in enumerate(judged) if r["whirl"]), None)
        if first is None:
            entry.update(onset_rpm=float("nan"), bracket_rpm=float("nan"),
                         note=f"no whirl up to {judged[-1]['rpm'] if judged else float('nan'):.0f} rpm")
        elif first == 0:
            entry.update(onset_rpm=float("nan"), bracket_rpm=float("nan"),
                         note=f"whirl already at the lowest judged speed {judged[0]['rpm']:.0f} rpm")
        else:
            brackets[values] = [judged[first - 1]["rpm"], judged[first]["rpm"]]
            entry["note"] = "refined"
        if missing:
            # Between the last stable and the first whirling speed the bisection
            # judges anew; a failed point below that bracket may hide the onset.
            lo = judged[max(first - 1, 0)]["rpm"] if first is not None else None
            outside = first is None or any(x < lo for x in missing)
            entry["note"] += (f"; {len(missing)} grid point(s) failed ({entry['missing_rpm']} rpm)"
                              + (": the onset may lie there" if outside else ""))
        onsets.append(entry)
    overrides = {values: dict(zip(params, values)) for values in brackets}
    refinement = []
    for step in range(refine):
        live = list(brackets)
        if not live:
            break
        print(f"onset refinement: bisection step {step + 1}/{refine}, {len(live)} brackets", file=sys.stderr)
        points = [(0.5 * sum(brackets[v]), overrides[v]) for v in live]
        new = run_points(payload, points, duration, output_interval, client, what=None)
        for v, r in zip(live, new):
            r["refinement"] = True
            refinement.append(r)
            lo, hi = brackets[v]
            if r["status"] != "ok":
                del brackets[v]  # keep the bracket reached; the failure is in the table
                continue
            brackets[v] = [lo, r["rpm"]] if r["whirl"] else [r["rpm"], hi]
    for entry in onsets:
        values = tuple(entry[k] for k in keys)
        lo_hi = brackets.get(values)
        if lo_hi is None:
            # a refinement point failed: report the last bracket from the table
            rs = [r for r in refinement if tuple(r[k] for k in keys) == values and r["status"] == "ok"]
            if entry["note"].startswith("refined") and rs:
                stable = max((r["rpm"] for r in rs if not r["whirl"]), default=float("nan"))
                entry["note"] = entry["note"].replace("refined", "refinement stopped by a failed point", 1)
                entry["onset_rpm"], entry["bracket_rpm"] = stable, float("nan")
            continue
        lo, hi = lo_hi
        entry["onset_rpm"] = 0.5 * (lo + hi)
        entry["bracket_rpm"] = 0.5 * (hi - lo)
    return onsets, refinement


def write_table(rows, path):
    columns = []
    for r in rows:
        for k in r:
            if k not in columns and not k.startswith("spectrum"):
                columns.append(k)
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=columns, extrasaction="ignore")
        w.writeheader()
        w.writerows(rows)


def missing_onsets(onsets, first):
    """The stability map's words for the parameter sets without an onset of
    whirl (no whirl in the range, whirl from the lowest speed), one line each
    with the swept value and the reason; headed "no onset of whirl found" when
    no set has one, so the map is never blank axes. None when every set has one."""
    missing = [o for o in onsets if not np.isfinite(o["onset_rpm"])]
    if not missing:
        return None
    lines = [f"{first} = {o[first]:g}: {o['note']}" for o in missing]
    if len(missing) == len(onsets):
        lines.insert(0, "no onset of whirl found:")
    return "\n".join(lines)


def plot(rows, prefix, params, onsets, fmu_name):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    ok = [r for r in rows if r["status"] == "ok" and not r.get("refinement")]
    if not ok:
        return
    keys, sets = parameter_sets(ok, params)
    bearings = sorted({k.split(".")[0] for k in ok[0] if k.endswith(".peak_radius_m")})
    label = lambda values: ", ".join(f"{k}={v:g}" for k, v in zip(keys, values))
    # Peak amplitude against speed (Bode-like), per bearing and parameter set.
    fig, ax = plt.subplots(figsize=(9, 5))
    for values, rs in sets.items():
        rs = sorted(rs, key=lambda r: r["rpm"])
        for b in bearings:
            ax.plot([r["rpm"] for r in rs], [r[f"{b}.peak_radius_m"] * 1e6 for r in rs], "o-",
                    label=f"{b} {label(values)}")
    ax.set_xlabel("speed (rpm)")
    ax.set_ylabel("peak orbit radius (µm)")
    ax.set_yscale("log")
    ax.set_title(f"{fmu_name}: peak orbit radius at each bearing")
    ax.legend(fontsize=7)
    fig.savefig(prefix + "_peak.png", dpi=100)
    plt.close(fig)
    # Waterfall of the first parameter set, first bearing, with an amplitude scale bar.
    values, rs = next(iter(sets.items()))
    rs = sorted([r for r in rs if "spectrum" in r], key=lambda r: r["rpm"])
    if rs:
        fig, ax = plt.subplots(figsize=(9, 7))
        top = max(max(r["spectrum"]) for r in rs)
        step = (rs[-1]["rpm"] - rs[0]["rpm"]) / max(len(rs) - 1, 1)
        scale = 3.0 * step / top  # rpm of offset per metre of amplitude
        for r in rs:
            f = np.fft.fftshift(r["spectrum_hz"])
            a = np.fft.fftshift(r["spectrum"])
            ax.plot(f, r["rpm"] + scale * a, color="k", lw=0.7)
        s = np.array([r["rpm"] for r in rs])
        ax.plot(s / 60, s, "r--", lw=0.8, label="1×")
        ax.plot(s / 120, s, "b--", lw=0.8, label="0.5×")
        x0 = -1.4 * s.max() / 60
        ax.plot([x0, x0], [s[0], s[0] + scale * top], color="g", lw=3, label=f"{top * 1e6:.3g} µm amplitude")
        ax.set_xlim(-1.5 * s.max() / 60, 1.5 * s.max() / 60)
        ax.set_xlabel("frequency (Hz), positive = forward whirl")
        ax.set_ylabel("speed (rpm); traces: full-spectrum amplitude (scale bar)")
        ax.set_title(f"{fmu_name}: bearing {bearings[-1]} orbit spectrum, {label(values) or 'model values'}")
        ax.legend()
        fig.savefig(prefix + "_waterfall.png", dpi=100)
        plt.close(fig)
    # Stability map: refined onset of whirl against the first swept parameter.
    if params and onsets:
        first = keys[0]
        fig, ax = plt.subplots(figsize=(7, 5))
        found = [o for o in onsets if np.isfinite(o["onset_rpm"])]
        xs = [o[first] for o in found]
        ys = [o["onset_rpm"] for o in found]
        es = [o["bracket_rpm"] if np.isfinite(o["bracket_rpm"]) else 0.0 for o in found]
        if found:
            ax.errorbar(xs, ys, yerr=es, fmt="o-", capsize=4, label="onset of whirl")
        # Grid points that failed, where they would have been judged.
        lost = [(r[first], r["rpm"]) for r in rows if r["status"].startswith("error") and not r.get("refinement")]
        if lost:
            ax.plot(*zip(*lost), "rx", ms=9, mew=2, label=f"grid point failed ({len(lost)}, see the table)")
        # Sets without an onset are named on the map, never left as blank axes.
        text = missing_onsets(onsets, first)
        if found or lost:
            # Clear of the words on the sets without an onset (top left).
            ax.legend(fontsize=8, loc="lower right" if text else "best")
        if text:
            where = (0.5, 0.5) if not found else (0.02, 0.98)
            ax.text(*where, text, transform=ax.transAxes, ha="center" if not found else "left",
                    va="center" if not found else "top", fontsize=9)
            if not found:
                ax.set_xlim(min(o[first] for o in onsets) * 0.9, max(o[first] for o in onsets) * 1.1)
                if not lost:
                    ax.set_ylim(0, 1)
        ax.set_xlabel(first)
        ax.set_ylabel("onset of whirl (rpm), bisection bracket as error bar")
        ax.set_title(f"{fmu_name}: stability map")
        fig.savefig(prefix + "_stability.png", dpi=100)
        plt.close(fig)


def parse_range(text):
    a, b, n = text.split(":")
    return list(np.linspace(float(a), float(b), int(n)))


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--fmu", required=True, help="the packed FMU (read once, shipped to the workers)")
    p.add_argument("--rpm", required=True, help="speed grid FROM:TO:COUNT (rpm)")
    p.add_argument("--param", action="append", default=[],
                   help="NAME[,NAME...]=V1,V2,... in the FMU's units (several --param allowed; "
                        "several names set together are one column NAME+NAME)")
    p.add_argument("--duration", type=float, default=1.0,
                   help=f"simulated time per point (s); the last half is analysed and must hold "
                        f"{MIN_REVOLUTIONS} revolutions")
    p.add_argument("--output-interval", type=float, default=5e-4, help="output interval (s)")
    p.add_argument("--refine", type=int, default=6,
                   help="bisection steps locating each onset of whirl between grid speeds (0: none)")
    p.add_argument("--scheduler", help="address of a Dask scheduler (tcp://host:8786)")
    p.add_argument("--workers", type=int, help="worker processes of the local cluster (default 2)")
    p.add_argument("--serial", action="store_true", help="no Dask, one process")
    p.add_argument("--out", default="out/sweep", help="prefix of the CSV tables and PNG figures")
    a = p.parse_args(argv)
    if a.scheduler and a.workers is not None:
        p.error("--workers sets the size of a local cluster; with --scheduler the cluster has its own workers")
    if a.serial and (a.scheduler or a.workers is not None):
        p.error("--serial runs without Dask: drop --scheduler/--workers")
    if a.duration <= 0 or a.output_interval <= 0 or a.output_interval >= a.duration:
        p.error("need 0 < --output-interval < --duration (s)")
    params = {}
    for spec in a.param:
        name, _, values = spec.partition("=")
        if not values:
            p.error(f"--param {spec!r}: expected NAME=V1,V2,...")
        params[name] = [float(v) for v in values.split(",")]
    client = cluster = None
    if not a.serial:
        from dask.distributed import Client, LocalCluster
        if a.scheduler:
            client = Client(a.scheduler)
        else:
            cluster = LocalCluster(n_workers=a.workers or 2, threads_per_worker=1, processes=True)
            client = Client(cluster)
    fmu = os.path.abspath(a.fmu)
    try:
        rows = run_sweep(fmu, parse_range(a.rpm), params, a.duration, a.output_interval, client)
        onsets, refinement = (find_onsets(fmu, rows, params, a.duration, a.output_interval, a.refine, client)
                              if params or a.refine else ([], []))
    finally:
        if client is not None:
            client.close()
        if cluster is not None:
            cluster.close()
    os.makedirs(os.path.dirname(a.out) or ".", exist_ok=True)
    write_table(rows + refinement, a.out + ".csv")
    if onsets:
        write_table(onsets, a.out + "_onsets.csv")
    plot(rows, a.out, params, onsets, os.path.basename(fmu))
    failed = sum(r["status"].startswith("error") for r in rows)
    lost = [r for r in rows + refinement if failed_outside_solver(r)]
    short = sum(r["status"].startswith("too_short") for r in rows)
    for o in onsets:
        where = f"{o['onset_rpm']:.0f} ± {o['bracket_rpm']:.0f} rpm" if np.isfinite(o["onset_rpm"]) else o["note"]
        missing = f" (grid points failed: {o['missing_rpm']} rpm)" if o["missing_rpm"] else ""
        print("onset of whirl " + ", ".join(f"{k}={o[k]:g}" for k in o if k not in
                                            ("onset_rpm", "bracket_rpm", "note", "missing_rpm"))
              + f": {where}{missing}")
    print(f"sweep: {len(rows)} points ({failed} failed, {short} too short to classify) → {a.out}.csv, "
          f"{a.out}_*.png")
    if lost:
        for r in lost:
            print(f"sweep: {r['rpm']:g} rpm failed outside the solver: {r['status']}", file=sys.stderr)
        sys.exit(f"sweep: {len(lost)} point(s) failed for a reason other than the solver (see {a.out}.csv)")


if __name__ == "__main__":
    main()
