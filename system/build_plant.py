"""Build the governor/turbine/generator FMUs with pythonfmu — HydroPlant.fmu
(speed-driven rotor: the plant integrates the swing equation) and
HydroPlantTorque.fmu (torque-driven rotor: no inertia of its own), both with
system/governor.py among their resources — complete each model
description (pythonfmu leaves ModelStructure/InitialUnknowns empty: every output
with initial="calculated" must be listed there) and validate it with FMPy.

usage: python system/build_plant.py [DEST_DIR]
"""
import os
import shutil
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET
import zipfile

from fmpy.validation import validate_fmu

here = os.path.dirname(os.path.abspath(__file__))
dest = sys.argv[1] if len(sys.argv) > 1 else os.path.join(here, "..", "out")
os.makedirs(dest, exist_ok=True)
pythonfmu = os.path.join(os.path.dirname(sys.executable), "pythonfmu")


def build(script, name):
    subprocess.run([pythonfmu, "build", "-f", os.path.join(here, script), os.path.join(here, "governor.py"),
                    "--dest", dest], check=True, capture_output=True)
    fmu = os.path.join(dest, name + ".fmu")
    with tempfile.TemporaryDirectory() as tmp:
        with zipfile.ZipFile(fmu) as z:
            z.extractall(tmp)
        path = os.path.join(tmp, "modelDescription.xml")
        tree = ET.parse(path)
        root = tree.getroot()
        variables = root.find("ModelVariables").findall("ScalarVariable")
        structure = root.find("ModelStructure")
        for old in structure.findall("InitialUnknowns"):
            structure.remove(old)
        unknowns = ET.SubElement(structure, "InitialUnknowns")
        for i, v in enumerate(variables, start=1):
            if v.get("causality") == "output" and v.get("initial", "calculated") in ("calculated", "approx"):
                ET.SubElement(unknowns, "Unknown", index=str(i))
        tree.write(path, encoding="UTF-8", xml_declaration=True)
        os.remove(fmu)
        with zipfile.ZipFile(fmu, "w", zipfile.ZIP_DEFLATED) as z:
            for base, _, files in os.walk(tmp):
                for f in files:
                    full = os.path.join(base, f)
                    z.write(full, os.path.relpath(full, tmp))
    problems = validate_fmu(fmu)
    if problems:
        sys.exit(f"{name}.fmu: " + "; ".join(problems))
    print(f"built and validated {fmu}")


build("hydro_plant.py", "HydroPlant")
build("hydro_plant_torque.py", "HydroPlantTorque")
