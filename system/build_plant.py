"""Build the governor/turbine/generator FMUs with pythonfmu — HydroPlant.fmu
(speed-driven rotor: the plant integrates the swing equation) and
HydroPlantTorque.fmu (torque-driven rotor: no inertia of its own), both with
system/governor.py among their resources — complete each model description
(system/pythonfmu_build.py) and validate it with FMPy.

usage: python system/build_plant.py [DEST_DIR]
"""
import os
import sys

from pythonfmu_build import build

here = os.path.dirname(os.path.abspath(__file__))
dest = sys.argv[1] if len(sys.argv) > 1 else os.path.join(here, "..", "out")
for script, name in [("hydro_plant.py", "HydroPlant"), ("hydro_plant_torque.py", "HydroPlantTorque")]:
    fmu = build(os.path.join(here, script), name, dest, extra=[os.path.join(here, "governor.py")])
    print(f"built and validated {fmu}")
