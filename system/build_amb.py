"""Build the PD magnetic-bearing FMU (system/amb_controller.py) with
pythonfmu, complete its model description (each force depends on its own
axis's displacement and velocity only: a direct feedthrough) and validate it
with FMPy.

usage: python system/build_amb.py [DEST_DIR]
"""
import os
import sys

from pythonfmu_build import build

here = os.path.dirname(os.path.abspath(__file__))
dest = sys.argv[1] if len(sys.argv) > 1 else os.path.join(here, "..", "out")
fmu = build(os.path.join(here, "amb_controller.py"), "AmbController", dest,
            dependencies={"fx": ["x", "vx"], "fy": ["y", "vy"]})
print(f"built and validated {fmu}")
