"""The whole machine of models/hydro_unit_brackets.toml (300 rpm Francis unit on
bearing brackets, runner seal, the generator's magnetic pull, hydraulic forces:
docs/machine.md) in its plant under libcosim, speed-driven: the governor/turbine/
generator FMU (system/hydro_plant.py, scaled to the 40 MW, 300 rpm unit)
gives the speed and, at synchronization, the field:

    plant.speed           → rotor.shaft.speed
    rotor.friction_torque → plant.friction_torque
    plant.excitation      → rotor.magnetic_pull.generator.excitation  (tunable)

Scenarios (CSV + PNG each, out/brackets_<name>.csv/.png):
  synchronization  at 300 rpm, no load; the field comes on at t = 6 s (a 1 s
                   rise): the magnetic pull's negative stiffness softens the
                   generator's support and the orbit grows
  part_load        0.4 per unit load, the field on at 1–2 s, then the runner's
                   part-load vortex rope (2e4 N forward at 0.3x) and radial
                   hydraulic thrust (4e4 N along x), the rotor FMU's inputs,
                   ramped in over 3–5 s by the master

usage: python system/couple_brackets.py [NAME|all] [--duration S]
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from couple import OUT, run, scenario_cli, write_csv  # noqa: E402

ROTOR = os.path.join(OUT, "hydro_unit_brackets.fmu")
PLANT = os.path.join(OUT, "HydroPlant.fmu")
RATED = 300.0 * np.pi / 30.0
# The plant scaled to the unit: 40 MW at 300 rpm; the rotating inertia of the
# model (generator 1.94e5, runner 1.44e4, shaft 1.5e3 kg·m²).
UNIT = {"rated_speed": RATED, "rated_torque": 40e6 / RATED, "inertia": 2.1e5, "start_speed": RATED,
        "ramp_time": 0.0}
ROTOR_PARAMS = {"solver.time_step": 2e-3, "unbalance_ramp_time": 1.0}
RECORD = ["probes.generator.x", "probes.generator.y", "probes.runner.x", "probes.runner.y"]
FIELD = [("excitation", "magnetic_pull.generator.excitation")]
VORTEX_ROPE, HYDRAULIC_THRUST = 2.0e4, 4.0e4
SCENARIOS = {
    "synchronization": dict(duration=12.0, plant=dict(UNIT, load=0.0, field_time=6.0, field_ramp=1.0),
                            rotor=ROTOR_PARAMS),
    "part_load": dict(duration=20.0, plant=dict(UNIT, load=0.4, field_time=1.0, field_ramp=1.0),
                      rotor=ROTOR_PARAMS, forces=(3.0, 5.0)),
}


def hydraulic_forces(start, end):
    """The part-load forces ramped in linearly from `start` to `end` (s): the
    rotor FMU's inputs forces.vortex_rope.magnitude and forces.hydraulic_thrust.fx."""
    def values(t):
        s = min(1.0, max(0.0, (t - start) / (end - start)))
        return {"forces.vortex_rope.magnitude": s * VORTEX_ROPE, "forces.hydraulic_thrust.fx": s * HYDRAULIC_THRUST}
    return values


def simulate(name, duration=None):
    spec = SCENARIOS[name]
    schedule = hydraulic_forces(*spec["forces"]) if "forces" in spec else None
    return run(ROTOR, PLANT, duration or spec["duration"], spec["plant"], step=0.01, rotor_params=spec["rotor"],
               connections=FIELD, record=RECORD, schedule=schedule)


def line(t, z, frequency):
    """Complex amplitude of the circular component z(t) ∋ c e^{i 2π f t} at
    each frequency of `frequency` (Hz, signed: negative = backward) with a
    constant, by least squares over the samples."""
    basis = np.column_stack([np.ones_like(t)] + [np.exp(2j * np.pi * f * t) for f in frequency])
    coef, *_ = np.linalg.lstsq(basis, z, rcond=None)
    return coef[1:]


def full_spectrum(t, z):
    """Frequencies (Hz, signed) and one-sided circular amplitudes (m) of the
    Hann-windowed full spectrum of z = x + i y."""
    w = np.hanning(len(z))
    spectrum = np.fft.fftshift(np.fft.fft((z - np.mean(z)) * w)) / np.sum(w)
    return np.fft.fftshift(np.fft.fftfreq(len(z), t[1] - t[0])), np.abs(spectrum)


def save(result, prefix, title):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    write_csv(result, prefix + ".csv")
    t = result["time"]
    fig, ax = plt.subplots(2, 2, figsize=(12, 8))
    for probe in ("generator", "runner"):
        x, y = result[f"rotor.probes.{probe}.x"], result[f"rotor.probes.{probe}.y"]
        ax[0, 0].plot(t, np.hypot(x - np.mean(x[t > t[-1] / 2]), y - np.mean(y[t > t[-1] / 2])) * 1e6, lw=0.7,
                      label=f"probe {probe}")
        last = t > t[-1] - 2.0
        ax[1, 0].plot(x[last] * 1e6, y[last] * 1e6, lw=0.7, label=probe)
        late = t > t[-1] / 2
        f, a = full_spectrum(t[late], (x + 1j * y)[late])
        ax[1, 1].semilogy(f / (RATED / (2 * np.pi)), a * 1e6, lw=0.8, label=probe)
    ax[0, 0].set_ylabel("distance from the mean position of the second half (µm)")
    ax[0, 0].set_xlabel("time (s)")
    ax[0, 0].legend()
    ax01 = ax[0, 1]
    ax01.plot(t, result["plant.excitation"], label="field excitation")
    ax01.plot(t, result["plant.gate"], label="gate")
    ax01.set_ylabel("per unit")
    ax01.set_xlabel("time (s)")
    ax01.legend()
    ax[1, 0].set_aspect("equal", "datalim")
    ax[1, 0].set_title("orbits, last 2 s")
    ax[1, 0].set_xlabel("x (µm)")
    ax[1, 0].legend()
    ax[1, 1].set_xlim(-2.5, 2.5)
    ax[1, 1].set_xlabel("order (frequency / running speed; negative: backward)")
    ax[1, 1].set_ylabel("full-spectrum amplitude, second half (µm)")
    ax[1, 1].legend()
    fig.suptitle(title)
    fig.tight_layout()
    fig.savefig(prefix + ".png", dpi=100)
    plt.close(fig)


def run_scenario(name, duration):
    """Run one scenario; CSV and PNG into out/."""
    result = simulate(name, duration)
    prefix = os.path.join(OUT, f"brackets_{name}")
    save(result, prefix, f"hydro_unit_brackets: {name.replace('_', ' ')} (speed-driven, libcosim)")
    t = result["time"]
    late = t > t[-1] / 2
    z = (result["rotor.probes.runner.x"] + 1j * result["rotor.probes.runner.y"])[late]
    f0 = RATED / (2 * np.pi)
    a = np.abs(line(t[late], z, [f0, 0.3 * f0]))
    print(f"brackets {name}: runner probe 1x {a[0] * 1e6:.2f} µm, 0.3x forward {a[1] * 1e6:.2f} µm → {prefix}.csv/.png")


def main():
    scenario_cli(__doc__, SCENARIOS, run_scenario)

if __name__ == "__main__":
    sys.exit(main())
