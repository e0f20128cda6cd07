"""Couple the rotor-bearing FMU with the governor/turbine/generator FMU using
libcosim (libcosimpy, the Open Simulation Platform's FMI 2.0 master).

    plant.speed           → rotor.shaft.speed
    rotor.friction_torque → plant.friction_torque

Scenarios (CSV + PNG each, into out/):
  startup   run-up of the hydro unit from standstill to 150 rpm, no load
  shutdown  emergency stop at rated speed: gate closed, brake on, coast-down to rest
  rejection full load rejection at rated speed: overspeed, then governor recovery
            (both for the tilting-pad and the plain-bearing hydro unit)
  critical  run-up from standstill through the first critical speed (classic rotor)
  breakaway start-up of the horizontal Jeffcott rotor from rest on its plain bearings:
            held by the journals' breakaway torque μ N R until the turbine exceeds it

usage: python system/couple.py [startup|shutdown|rejection|critical|all] [--duration S]
"""
import argparse
import csv
import os
import sys

import numpy as np
from libcosimpy.CosimExecution import CosimExecution
from libcosimpy.CosimManipulator import CosimManipulator
from libcosimpy.CosimObserver import CosimObserver
from libcosimpy.CosimSlave import CosimLocalSlave

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
OUT = os.path.join(ROOT, "out")
RATED = 150.0 * np.pi / 30.0

HYDRO = {"tilting_pad": "RotorBearing.fmu", "plain": "hydro_unit_plain.fmu"}
SCENARIOS = {
    "startup": dict(duration=90.0, rotors=HYDRO, rotor_params={},
                    plant={"start_speed": 0.0, "ramp_time": 60.0, "load": 0.0}),
    "shutdown": dict(duration=40.0, rotors=HYDRO, rotor_params={},
                     plant={"start_speed": RATED, "ramp_time": 0.0, "load": 0.0, "shutdown_time": 5.0,
                            "brake_speed": 1.0, "brake_torque": 0.2}),
    "rejection": dict(duration=60.0, rotors=HYDRO, rotor_params={},
                      plant={"start_speed": RATED, "ramp_time": 0.0, "load": 0.9, "rejection_time": 5.0}),
    # A run-up from standstill through a critical speed: the classic disk rotor on
    # damped bearings (first critical 1111 rpm) driven by the same governor/turbine
    # model scaled to a 2000 rpm, 0.5 kg·m² drive.
    "critical": dict(duration=30.0, rotors={"linear": "classic_disk_rotor_damped.fmu"},
                     rotor_params={"solver.time_step": 1e-3, "unbalance_ramp_time": 0.0},
                     plant={"start_speed": 0.0, "ramp_time": 20.0, "load": 0.0, "inertia": 0.5,
                            "rated_speed": 2000.0 * np.pi / 30.0, "rated_torque": 30.0, "loss": 0.02}),
    # The Jeffcott rotor (20 kg disk, journals resting on their plain bearings)
    # driven by the governor/turbine model scaled to a 3000 rpm, 0.05 kg·m² drive.
    "breakaway": dict(duration=5.0, rotors={"plain": "jeffcott.fmu"},
                      rotor_params={"solver.time_step": 2e-4, "unbalance_ramp_time": 0.0},
                      plant={"start_speed": 0.0, "ramp_time": 4.0, "load": 0.0, "inertia": 0.05,
                             "rated_speed": 3000.0 * np.pi / 30.0, "rated_torque": 10.0, "loss": 0.02,
                             "kp": 0.5, "ki": 0.1}),
}


def references(execution, index):
    return {v.name.decode(): v.reference for v in execution.slave_variables(index)}


def execution_of(rotor_fmu, plant_fmu, step, plant_params, rotor_params):
    """A libcosim execution of the rotor and plant FMUs at communication step
    `step` (s) with their start values; returns it, the two slave indices and
    their variables' references by name."""
    execution = CosimExecution.from_step_size(step_size=int(round(step * 1e9)))
    rotor = execution.add_local_slave(CosimLocalSlave(fmu_path=rotor_fmu, instance_name="rotor"))
    plant = execution.add_local_slave(CosimLocalSlave(fmu_path=plant_fmu, instance_name="plant"))
    rv, pv = references(execution, rotor), references(execution, plant)
    for name, value in plant_params.items():
        execution.real_initial_value(plant, pv[name], float(value))
    for name, value in rotor_params.items():
        execution.real_initial_value(rotor, rv[name], float(value))
    return execution, rotor, plant, rv, pv


def run(rotor_fmu, plant_fmu, duration, plant_params, step=0.02, rotor_params=None, connections=(), record=(),
        schedule=None):
    """Co-simulate; returns a dict of arrays sampled at every communication step.
    `rotor_params`: start values of rotor variables (parameters and inputs);
    `connections`: (plant output, rotor tunable parameter) pairs, e.g. the field
    into magnetic_pull.<m>.excitation: libcosim connects inputs only, so the
    master passes each value on at every communication point through an
    override manipulator; `record`: further rotor outputs; `schedule(t)`: a dict
    of rotor input values to set for the step from t (e.g. hydraulic forces ramped in)."""
    params = {"solver.time_step": 5e-3, "unbalance_ramp_time": 2.0}
    params.update(rotor_params or {})
    execution, rotor, plant, rv, pv = execution_of(rotor_fmu, plant_fmu, step, plant_params, params)
    execution.real_initial_value(rotor, rv["shaft.speed"], float(plant_params.get("start_speed", 0.0)))
    execution.connect_real_variables(plant, pv["speed"], rotor, rv["shaft.speed"])
    execution.connect_real_variables(rotor, rv["friction_torque"], plant, pv["friction_torque"])
    observer = CosimObserver.create_last_value()
    execution.add_observer(observer)
    override = CosimManipulator.create_override()
    execution.add_manipulator(override)
    bearings = sorted({n.split(".")[1] for n in rv if n.startswith("bearings.")})
    rotor_names = ["shaft.speed", "friction_torque"] + [f"bearings.{b}.{q}" for b in bearings for q in ("x", "y", "fx", "fy", "eccentricity")]
    rotor_names += list(record)
    plant_names = ["speed", "gate", "setpoint", "turbine_torque", "electric_torque"]
    plant_names += [source for source, _ in connections]
    rows = []
    steps = int(round(duration / step))
    for k in range(steps):
        if schedule is not None:
            values = schedule(k * step)
            override.slave_real_values(rotor, [rv[n] for n in values], list(values.values()))
        if not execution.step(1):
            raise RuntimeError(f"co-simulation step {k} failed at t = {k * step:.3f} s")
        r = observer.last_real_values(rotor, [rv[n] for n in rotor_names])
        p = observer.last_real_values(plant, [pv[n] for n in plant_names])
        rows.append([(k + 1) * step] + list(r) + list(p))
        if connections:
            values = observer.last_real_values(plant, [pv[source] for source, _ in connections])
            override.slave_real_values(rotor, [rv[target] for _, target in connections], values)
    names = ["time"] + [f"rotor.{n}" for n in rotor_names] + [f"plant.{n}" for n in plant_names]
    data = np.array(rows)
    return {n: data[:, i] for i, n in enumerate(names)}


def write_csv(result, path):
    """One column per array of `result`, headed by its name."""
    names = list(result)
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(names)
        w.writerows(zip(*[result[n] for n in names]))


def save(result, prefix, title):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    names = list(result)
    write_csv(result, prefix + ".csv")
    t = result["time"]
    bearings = sorted({n.split(".")[2] for n in names if n.startswith("rotor.bearings.")})
    fig, ax = plt.subplots(2, 2, figsize=(12, 8))
    ax[0, 0].plot(t, result["plant.speed"] * 30 / np.pi, label="speed")
    ax[0, 0].plot(t, result["plant.setpoint"] * 30 / np.pi, "--", label="set point")
    ax[0, 0].set_ylabel("rpm")
    ax[0, 0].legend()
    ax[0, 1].plot(t, result["plant.gate"], label="gate")
    ax[0, 1].set_ylabel("gate opening (1)")
    ax01 = ax[0, 1].twinx()
    ax01.plot(t, result["rotor.friction_torque"] / 1e3, color="tab:red", label="bearing friction")
    ax01.set_ylabel("bearing friction torque (kN·m)", color="tab:red")
    for b in bearings:
        r = np.hypot(result[f"rotor.bearings.{b}.x"], result[f"rotor.bearings.{b}.y"]) * 1e6
        ax[1, 0].plot(t, r, label=b)
        ax[1, 1].plot(result[f"rotor.bearings.{b}.x"][t > t[-1] * 0.8] * 1e6,
                      result[f"rotor.bearings.{b}.y"][t > t[-1] * 0.8] * 1e6, lw=0.7, label=b)
    ax[1, 0].set_ylabel("journal displacement (µm)")
    ax[1, 0].set_xlabel("time (s)")
    ax[1, 0].legend()
    ax[1, 1].set_aspect("equal", "datalim")
    ax[1, 1].set_title("orbits, last 20 % of the run")
    ax[1, 1].set_xlabel("x (µm)")
    ax[1, 1].legend()
    fig.suptitle(title)
    fig.tight_layout()
    fig.savefig(prefix + ".png", dpi=100)
    plt.close(fig)


def scenario_cli(doc, scenarios, one):
    """The command line of the scenario scripts: `[NAME|all] [--duration S]`;
    calls `one(name, duration or None)` for each scenario chosen."""
    parser = argparse.ArgumentParser(description=doc.split("\n")[0])
    parser.add_argument("scenario", nargs="?", default="all", choices=["all"] + list(scenarios))
    parser.add_argument("--duration", type=float, default=None)
    args = parser.parse_args()
    for name in ([args.scenario] if args.scenario != "all" else list(scenarios)):
        one(name, args.duration)


def run_scenario(name, duration):
    """Run one scenario with each of its rotors; CSV and PNG into out/."""
    plant_fmu = os.path.join(OUT, "HydroPlant.fmu")
    spec = SCENARIOS[name]
    for bearing, fmu in spec["rotors"].items():
        result = run(os.path.join(OUT, fmu), plant_fmu, duration or spec["duration"], spec["plant"],
                     rotor_params=spec["rotor_params"])
        prefix = os.path.join(OUT, f"coupled_{name}_{bearing}")
        save(result, prefix, f"{os.path.splitext(fmu)[0]}: {name}, {bearing.replace('_', '-')} bearings (libcosim)")
        peak = max(result[f"plant.speed"]) * 30 / np.pi
        print(f"{name} / {bearing}: final speed {result['plant.speed'][-1] * 30 / np.pi:.1f} rpm, peak {peak:.1f} rpm → {prefix}.csv/.png")


def main():
    scenario_cli(__doc__, SCENARIOS, run_scenario)


if __name__ == "__main__":
    sys.exit(main())
