"""Build the governor/turbine/generator FMU with pythonfmu, complete its model
description (system/pythonfmu_build.py) and validate it with FMPy.

usage: python system/build_plant.py [DEST_DIR]
"""
import os
import sys

from pythonfmu_build import build

here = os.path.dirname(os.path.abspath(__file__))
dest = sys.argv[1] if len(sys.argv) > 1 else os.path.join(here, "..", "out")
fmu = build(os.path.join(here, "hydro_plant.py"), "HydroPlant", dest)
print(f"built and validated {fmu}")
