"""Build an FMU from a pythonfmu slave script, complete its model description
and validate it with FMPy.

pythonfmu 0.7 leaves ModelStructure/InitialUnknowns empty (every output with
initial="calculated" must be listed there) and lists the outputs without their
dependencies (then an output counts as depending on every input). `build`
adds the InitialUnknowns and, where `dependencies` names them, the inputs each
output depends on (a direct feedthrough), in both lists.
"""
import os
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET
import zipfile

from fmpy.validation import validate_fmu


def build(script, name, dest, dependencies=None, extra=()):
    """Build `script` (class `name`) into `dest`/`name`.fmu; returns its path.
    `dependencies`: {output name: [input names]} for the outputs that depend
    on some inputs only; `extra`: further files the script imports, packed
    among its resources."""
    dependencies = dependencies or {}
    os.makedirs(dest, exist_ok=True)
    pythonfmu = os.path.join(os.path.dirname(sys.executable), "pythonfmu")
    subprocess.run([pythonfmu, "build", "-f", script, *extra, "--dest", dest], check=True, capture_output=True)
    fmu = os.path.join(dest, f"{name}.fmu")
    with tempfile.TemporaryDirectory() as tmp:
        with zipfile.ZipFile(fmu) as z:
            z.extractall(tmp)
        path = os.path.join(tmp, "modelDescription.xml")
        tree = ET.parse(path)
        root = tree.getroot()
        variables = root.find("ModelVariables").findall("ScalarVariable")
        index = {v.get("name"): i for i, v in enumerate(variables, start=1)}
        unknown_dependencies = {}
        for output, inputs in dependencies.items():
            for i in inputs:
                if variables[index[i] - 1].get("causality") != "input":
                    raise ValueError(f"{name}: dependency {i} of {output} is not an input")
            unknown_dependencies[str(index[output])] = " ".join(str(index[i]) for i in inputs)
        structure = root.find("ModelStructure")
        outputs = structure.find("Outputs")
        if outputs is not None:
            for unknown in outputs.findall("Unknown"):
                if unknown.get("index") in unknown_dependencies:
                    unknown.set("dependencies", unknown_dependencies[unknown.get("index")])
        for old in structure.findall("InitialUnknowns"):
            structure.remove(old)
        unknowns = ET.SubElement(structure, "InitialUnknowns")
        for i, v in enumerate(variables, start=1):
            if v.get("causality") == "output" and v.get("initial", "calculated") in ("calculated", "approx"):
                unknown = ET.SubElement(unknowns, "Unknown", index=str(i))
                if str(i) in unknown_dependencies:
                    unknown.set("dependencies", unknown_dependencies[str(i)])
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
    return fmu
