"""The torque-driven hydro unit under libcosim: the rotor FMU carries the
inertia (models/hydro_unit_torque.toml → out/hydro_unit_torque.fmu), the plant
FMU (system/hydro_plant_torque.py → out/HydroPlantTorque.fmu) gives the
torques and carries none.

    plant.turbine_torque            → rotor.torques.turbine
    plant.generator_torque          → rotor.torques.generator
    rotor.torques.turbine.speed     → plant.turbine_speed
    rotor.torques.generator.speed   → plant.generator_speed
    rotor.torques.generator.angle   → plant.generator_angle

Scenarios (CSV + PNG each, out/torque_<name>.csv/.png):
  startup        from standstill: breakaway against the thrust bearing, run-up,
                 synchronization (breaker closes in phase), load ramp to 0.5
  rejection      full load rejection from 0.9 per unit at rated speed
  shutdown       shut-down at rated speed, no load: gate closed, brake, coast-down
                 to rest (held there by the thrust bearing)
  short_circuit  three-phase terminal short circuit at 0.9 per unit load, cleared
                 at 1.5 s (after the 1 s settling of the connected start),
                 cleared by the generator breaker after 0.5 s (1 ms communication step)

usage: python system/couple_torque.py [NAME|all] [--duration S]
"""
import os
import sys

import numpy as np
from libcosimpy.CosimObserver import CosimObserver

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from couple import OUT, RATED, execution_of, scenario_cli, write_csv  # noqa: E402

ROTOR = os.path.join(OUT, "hydro_unit_torque.fmu")
PLANT = os.path.join(OUT, "HydroPlantTorque.fmu")
# The shaft element whose torque is plotted: element 12 (nodes 12–13), in the
# main shaft between the generator (node 5) and the runner (node 20).
SECTION = 12
SCENARIOS = {
    "startup": dict(duration=55.0, step=0.005,
                    plant={"start_speed": 0.0, "ramp_time": 30.0, "sync_time": 30.0, "load": 0.5,
                           "load_ramp_time": 5.0}),
    "rejection": dict(duration=25.0, step=0.005,
                      plant={"start_speed": RATED, "ramp_time": 0.0, "connected": 1.0, "load": 0.9,
                             "rejection_time": 5.0}),
    "shutdown": dict(duration=40.0, step=0.005,
                     plant={"start_speed": RATED, "ramp_time": 0.0, "load": 0.0, "shutdown_time": 2.0,
                            "brake_speed": 1.0, "brake_torque": 0.2}),
    "short_circuit": dict(duration=3.5, step=1e-3, rotor={"solver.time_step": 1e-3},
                          plant={"start_speed": RATED, "ramp_time": 0.0, "connected": 1.0, "load": 0.9,
                                 "fault_time": 1.5, "fault_duration": 0.5}),
}
ROTOR_NAMES = ["shaft.speed", "torques.turbine.speed", "torques.generator.speed", "torques.generator.angle",
               "torques.turbine", "torques.generator", f"shaft.torque[{SECTION}]", "friction_torque",
               "thrust_bearings.thrust.friction_torque", "power_loss"]
PLANT_NAMES = ["turbine_torque", "generator_torque", "electric_torque", "gate", "setpoint", "load_angle", "breaker"]


def run(duration, plant_params, step=0.005, rotor_params=None, rotor_fmu=ROTOR, plant_fmu=PLANT):
    """Co-simulate; returns a dict of arrays sampled after every communication step."""
    params = {"solver.time_step": 5e-3, "unbalance_ramp_time": 2.0,
              "shaft.initial_speed": float(plant_params.get("start_speed", 0.0))}
    params.update(rotor_params or {})
    execution, rotor, plant, rv, pv = execution_of(rotor_fmu, plant_fmu, step, plant_params, params)
    for source, target in [("turbine_torque", "torques.turbine"), ("generator_torque", "torques.generator")]:
        execution.connect_real_variables(plant, pv[source], rotor, rv[target])
    for source, target in [("torques.turbine.speed", "turbine_speed"), ("torques.generator.speed", "generator_speed"),
                           ("torques.generator.angle", "generator_angle")]:
        execution.connect_real_variables(rotor, rv[source], plant, pv[target])
    observer = CosimObserver.create_last_value()
    execution.add_observer(observer)
    bearings = sorted({n.split(".")[1] for n in rv if n.startswith("bearings.") and n.endswith(".x")})
    rotor_names = ROTOR_NAMES + [f"bearings.{b}.{q}" for b in bearings for q in ("x", "y")]
    rows = []
    for k in range(int(round(duration / step))):
        if not execution.step(1):
            raise RuntimeError(f"co-simulation step {k} failed at t = {k * step:.3f} s")
        r = observer.last_real_values(rotor, [rv[n] for n in rotor_names])
        p = observer.last_real_values(plant, [pv[n] for n in PLANT_NAMES])
        rows.append([(k + 1) * step] + list(r) + list(p))
    names = ["time"] + [f"rotor.{n}" for n in rotor_names] + [f"plant.{n}" for n in PLANT_NAMES]
    data = np.array(rows)
    return {n: data[:, i] for i, n in enumerate(names)}


def save(result, prefix, title):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    write_csv(result, prefix + ".csv")
    t = result["time"]
    rpm = 30.0 / np.pi
    fig, ax = plt.subplots(2, 2, figsize=(12, 8))
    ax[0, 0].plot(t, result["rotor.shaft.speed"] * rpm, label="mean speed (rotor FMU)")
    ax[0, 0].plot(t, result["rotor.torques.turbine.speed"] * rpm, lw=0.7, label="runner")
    ax[0, 0].plot(t, result["rotor.torques.generator.speed"] * rpm, lw=0.7, label="generator")
    ax[0, 0].plot(t, result["plant.setpoint"] * rpm, "--", label="set point")
    ax[0, 0].set_ylabel("speed (rpm)")
    ax[0, 0].legend()
    ax[0, 1].plot(t, result["plant.turbine_torque"] / 1e6, label="turbine (runner, node 20)")
    ax[0, 1].plot(t, result["plant.generator_torque"] / 1e6, label="generator (node 5): −(T_e + brake)")
    ax[0, 1].plot(t, -result["rotor.thrust_bearings.thrust.friction_torque"] / 1e6, label="thrust bearing friction")
    ax[0, 1].set_ylabel("torque on the shaft (MN·m)")
    ax[0, 1].legend()
    ax[1, 0].plot(t, result[f"rotor.shaft.torque[{SECTION}]"] / 1e6, color="tab:purple")
    ax[1, 0].set_ylabel(f"shaft torque, element {SECTION} (MN·m)")
    ax[1, 0].set_xlabel("time (s)")
    ax[1, 0].set_title("main shaft between generator and runner")
    ax[1, 1].plot(t, result["plant.gate"], label="gate")
    ax[1, 1].plot(t, result["plant.breaker"], label="breaker closed")
    ax[1, 1].set_ylabel("per unit")
    ax[1, 1].set_xlabel("time (s)")
    ax11 = ax[1, 1].twinx()
    delta = np.where(result["plant.breaker"] > 0.5, result["plant.load_angle"], np.nan)
    ax11.plot(t, np.degrees(np.arctan2(np.sin(delta), np.cos(delta))), color="tab:gray", lw=0.7)
    ax11.set_ylabel("load angle δ, wrapped (°el)", color="tab:gray")
    ax[1, 1].legend(loc="center left")
    fig.suptitle(title)
    fig.tight_layout()
    fig.savefig(prefix + ".png", dpi=100)
    plt.close(fig)


def run_scenario(name, duration):
    """Run one scenario; CSV and PNG into out/."""
    spec = SCENARIOS[name]
    result = run(duration or spec["duration"], spec["plant"], spec["step"], spec.get("rotor"))
    prefix = os.path.join(OUT, f"torque_{name}")
    save(result, prefix, f"hydro_unit_torque: {name.replace('_', ' ')} (torque-driven rotor FMU, libcosim)")
    speed = result["rotor.shaft.speed"] * 30 / np.pi
    shaft = result[f"rotor.shaft.torque[{SECTION}]"]
    print(f"torque {name}: final speed {speed[-1]:.2f} rpm, peak {np.max(speed):.2f} rpm, "
          f"shaft torque {np.min(shaft) / 1e6:.2f} … {np.max(shaft) / 1e6:.2f} MN·m → {prefix}.csv/.png")


def main():
    scenario_cli(__doc__, SCENARIOS, run_scenario)

if __name__ == "__main__":
    sys.exit(main())
