"""Parameter sweeps of a rotor-bearing FMU on Dask.

Every point is one FMPy simulation run inside a Dask worker: constant speed
(`shaft.speed` start value), optional parameter overrides (e.g. viscosity,
unbalance). Each point reports, per bearing, the peak orbit radius, the dominant
frequency of the full spectrum (sign = whirl direction) and the sub-synchronous
share. A failing point (e.g. the journal reaching the clearance) is a row with
its error, not the end of the sweep. Results: one CSV table and PNG figures
(waterfall of the spectrum against speed, peak amplitude against speed, and a
stability map: onset-of-whirl speed against the swept parameter).

    python system/sweep.py --fmu out/jeffcott.fmu --rpm 4000:16000:13 \
        --param bearings.left.viscosity,bearings.right.viscosity=0.01,0.02,0.04 \
        --duration 1.0 [--scheduler tcp://host:8786] [--workers 2] --out out/sweep
"""
import argparse
import csv
import itertools
import os
import sys

import numpy as np


def simulate_point(fmu, rpm, overrides, duration, output_interval, settle_fraction=0.5):
    """One sweep point; returns a flat dict (never raises)."""
    from fmpy import read_model_description, simulate_fmu
    row = {"rpm": rpm, **{k: v for k, v in overrides.items()}, "status": "ok"}
    messages = []

    def log(*args):
        text = args[-1]
        messages.append(text.decode(errors="replace") if isinstance(text, bytes) else str(text))

    try:
        md = read_model_description(fmu)
        bearings = sorted({v.name.split(".")[1] for v in md.modelVariables if v.name.startswith("bearings.")
                           and v.name.endswith(".x")})
        outputs = [f"bearings.{b}.{q}" for b in bearings for q in ("x", "y")]
        start = {"shaft.speed": rpm * np.pi / 30.0}
        for key, value in overrides.items():
            for name in key.split(","):
                start[name] = value
        res = simulate_fmu(fmu, stop_time=duration, output_interval=output_interval, start_values=start,
                           output=outputs, logger=log)
        t = res["time"]
        keep = t >= settle_fraction * duration
        f_spin = rpm / 60.0
        freqs = np.fft.fftfreq(int(keep.sum()), d=output_interval)
        for b in bearings:
            z = res[f"bearings.{b}.x"][keep] + 1j * res[f"bearings.{b}.y"][keep]
            z = z - z.mean()
            spectrum = np.abs(np.fft.fft(z * np.hanning(len(z)))) / (np.hanning(len(z)).sum())
            k = int(np.argmax(spectrum))
            sub = spectrum[(np.abs(freqs) > 0.05 * f_spin) & (np.abs(freqs) < 0.8 * f_spin)].max(initial=0.0)
            syn = spectrum[np.abs(freqs - f_spin) < 0.1 * f_spin].max(initial=0.0)
            row[f"{b}.peak_radius_m"] = float(np.max(np.abs(z)))
            row[f"{b}.dominant_hz"] = float(freqs[k])
            row[f"{b}.subsync_ratio"] = float(sub / max(syn, 1e-30))
        row["spectrum_hz"] = freqs.tolist()
        row["spectrum"] = spectrum.tolist()
    except Exception as e:  # a failed point is data, not the end of the sweep
        cause = messages[0] if messages else ""
        row["status"] = f"error: {cause} ({e})".replace("\n", " ")[:400]
    return row


def grid(rpms, params):
    names = list(params)
    for values in itertools.product(*[params[n] for n in names]):
        for rpm in rpms:
            yield rpm, dict(zip(names, values))


def run_sweep(fmu, rpms, params, duration, output_interval, client=None):
    points = list(grid(rpms, params))
    if client is None:
        return [simulate_point(fmu, rpm, ov, duration, output_interval) for rpm, ov in points]
    from dask.distributed import as_completed
    futures = [client.submit(simulate_point, fmu, rpm, ov, duration, output_interval, pure=False) for rpm, ov in points]
    index = {f.key: i for i, f in enumerate(futures)}
    rows = [None] * len(futures)
    for done, future in enumerate(as_completed(futures), start=1):
        rows[index[future.key]] = future.result()
        print(f"\rsweep: {done}/{len(futures)} points", end="", file=sys.stderr, flush=True)
    print(file=sys.stderr)
    return rows


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


def plot(rows, prefix, params):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    ok = [r for r in rows if r["status"] == "ok"]
    if not ok:
        return
    bearings = sorted({k.split(".")[0] for k in ok[0] if k.endswith(".peak_radius_m")})
    groups = {}
    for r in ok:
        key = tuple((k, r[k]) for k in params)
        groups.setdefault(key, []).append(r)
    # Peak amplitude against speed (Bode-like), per bearing and parameter set.
    fig, ax = plt.subplots(figsize=(9, 5))
    for key, rs in groups.items():
        rs = sorted(rs, key=lambda r: r["rpm"])
        for b in bearings:
            ax.plot([r["rpm"] for r in rs], [r[f"{b}.peak_radius_m"] * 1e6 for r in rs], "o-",
                    label=f"{b} " + ", ".join(f"{k.split('.')[-1]}={v}" for k, v in key))
    ax.set_xlabel("speed (rpm)")
    ax.set_ylabel("peak orbit radius (µm)")
    ax.set_yscale("log")
    ax.legend(fontsize=7)
    fig.savefig(prefix + "_peak.png", dpi=100)
    plt.close(fig)
    # Waterfall of the first parameter set.
    rs = sorted(next(iter(groups.values())), key=lambda r: r["rpm"])
    fig, ax = plt.subplots(figsize=(9, 7))
    top = max(max(r["spectrum"]) for r in rs)
    step = (rs[-1]["rpm"] - rs[0]["rpm"]) / max(len(rs) - 1, 1)
    for r in rs:
        f = np.fft.fftshift(r["spectrum_hz"])
        a = np.fft.fftshift(r["spectrum"])
        ax.plot(f, r["rpm"] + 3.0 * step * a / top, color="k", lw=0.7)
    s = np.array([r["rpm"] for r in rs])
    ax.plot(s / 60, s, "r--", lw=0.8, label="1×")
    ax.plot(s / 120, s, "b--", lw=0.8, label="0.5×")
    ax.set_xlim(-1.5 * s.max() / 60, 1.5 * s.max() / 60)
    ax.set_xlabel("frequency (Hz), positive = forward whirl")
    ax.set_ylabel("speed (rpm) + amplitude")
    ax.legend()
    fig.savefig(prefix + "_waterfall.png", dpi=100)
    plt.close(fig)
    # Stability map: lowest speed with a dominant sub-synchronous whirl, per parameter set.
    if params:
        first = list(params)[0]
        xs, ys = [], []
        for key, rs in groups.items():
            unstable = [r["rpm"] for r in rs if max(r[f"{b}.subsync_ratio"] for b in bearings) > 1.0]
            xs.append(dict(key)[first])
            ys.append(min(unstable) if unstable else np.nan)
        fig, ax = plt.subplots(figsize=(7, 5))
        ax.plot(xs, ys, "o-")
        ax.set_xlabel(first.split(",")[0])
        ax.set_ylabel("onset of whirl (rpm)")
        fig.savefig(prefix + "_stability.png", dpi=100)
        plt.close(fig)


def parse_range(text):
    a, b, n = text.split(":")
    return list(np.linspace(float(a), float(b), int(n)))


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--fmu", required=True)
    p.add_argument("--rpm", required=True, help="FROM:TO:COUNT")
    p.add_argument("--param", action="append", default=[], help="NAME[,NAME]=V1,V2,... (several allowed)")
    p.add_argument("--duration", type=float, default=1.0)
    p.add_argument("--output-interval", type=float, default=5e-4)
    p.add_argument("--scheduler", help="address of a Dask scheduler; default: a LocalCluster")
    p.add_argument("--workers", type=int, default=2)
    p.add_argument("--serial", action="store_true", help="no Dask, one process")
    p.add_argument("--out", default="out/sweep")
    a = p.parse_args(argv)
    params = {}
    for spec in a.param:
        name, values = spec.split("=")
        params[name] = [float(v) for v in values.split(",")]
    client = cluster = None
    if not a.serial:
        from dask.distributed import Client, LocalCluster
        if a.scheduler:
            client = Client(a.scheduler)
        else:
            cluster = LocalCluster(n_workers=a.workers, threads_per_worker=1, processes=True)
            client = Client(cluster)
    try:
        rows = run_sweep(os.path.abspath(a.fmu), parse_range(a.rpm), params, a.duration, a.output_interval, client)
    finally:
        if client is not None:
            client.close()
        if cluster is not None:
            cluster.close()
    os.makedirs(os.path.dirname(a.out) or ".", exist_ok=True)
    write_table(rows, a.out + ".csv")
    plot(rows, a.out, params)
    failed = sum(r["status"] != "ok" for r in rows)
    print(f"sweep: {len(rows)} points ({failed} failed) → {a.out}.csv, {a.out}_*.png")


if __name__ == "__main__":
    main()
