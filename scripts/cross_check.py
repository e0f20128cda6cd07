"""The FMI Cross-Check layout of the packed FMUs, FMI 2.0 and FMI 3.0, checked
with FMPy's cross-check validator (fmpy.cross_check).

    .venv/bin/python scripts/cross_check.py DEST [MODEL_STEM ...]

For each model (default: every shipped one; the FMUs come from out/, packed by
`fmu_pack.sh --fmi 2,3`), writes

    DEST/fmus/<2.0|3.0>/cs/<linux64|x86_64-linux>/RotorBearing/<version>/<model>/
        <model>.fmu       the FMU
        <model>_in.csv    the input (a speed ramp from 90 % to 100 % of the
                          operating speed; only where shaft.speed is an input)
        <model>_ref.csv   the reference: the simulator itself at a finer step
                          (1 ms communication steps, local error tolerance 3e-4
                          instead of 3e-3), sampled every StepSize
        <model>_ref.opt   StartTime, StopTime, StepSize, RelTol

and the result of FMPy simulating each FMU at the options' StepSize under

    DEST/results/<version>/cs/<platform>/FMPy/<fmpy version>/RotorBearing/<version>/<model>/
        <model>_out.csv, passed (when it passes the rule)

then validates every FMU folder (fmpy's validate_test_fmu: sizes, model
description, options, CSVs) and every result (validate_cross_check_result: the
rule of fewer than 10 % of samples outside a band of ±10 % of the reference's
range). Exits 1 on any problem.
"""
import os
import shutil
import sys
import tomllib

import fmpy
import numpy as np
from fmpy import read_model_description, simulate_fmu
from fmpy.cross_check import validate_result
from fmpy.cross_check.validate_vendor_repo import (read_csv, validate_cross_check_result,
                                                   validate_test_fmu)

root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
dest = os.path.abspath(sys.argv[1])
stems = sys.argv[2:] or sorted(m[:-5] for m in os.listdir(os.path.join(root, "models")) if m.endswith(".toml"))
START, STOP, STEP, REF_STEP = 0.0, 0.5, 0.01, 0.001
PLATFORM = {"2.0": "linux64", "3.0": "x86_64-linux"}
problems = []


def write_csv(path, table):
    names = table.dtype.names
    with open(path, "w") as f:
        f.write(",".join(f'"{n}"' if n != "time" else n for n in names) + "\n")
        for row in table:
            f.write(",".join(repr(float(row[n])) for n in names) + "\n")


for stem in stems:
    model = tomllib.load(open(os.path.join(root, "models", stem + ".toml"), "rb"))
    base = "RotorBearing" if stem == "hydro_unit" else stem
    for version, packed in (("2.0", base + ".fmu"), ("3.0", base + "_fmi3.fmu")):
        source = os.path.join(root, "out", packed)
        if not os.path.exists(source):
            problems.append(f"{source} missing: run fmu_pack.sh --fmi 2,3 --model models/{stem}.toml")
            continue
        md = read_model_description(source)
        tool_version = md.generationTool.split()[-1]
        platform = PLATFORM[version]
        fmu_dir = os.path.join(dest, "fmus", version, "cs", platform, "RotorBearing", tool_version, stem)
        shutil.rmtree(fmu_dir, ignore_errors=True)
        os.makedirs(fmu_dir)
        fmu = os.path.join(fmu_dir, stem + ".fmu")
        shutil.copy(source, fmu)
        outputs = [v.name for v in md.modelVariables if v.causality == "output" and not v.dimensions]
        signal = None
        if any(v.name == "shaft.speed" and v.causality == "input" for v in md.modelVariables):
            w = model["speed_rpm"] * np.pi / 30.0
            signal = np.array([(START, 0.9 * w), (STOP, w)],
                              dtype=[("time", np.float64), ("shaft.speed", np.float64)])
            write_csv(os.path.join(fmu_dir, stem + "_in.csv"), signal)
        fine = simulate_fmu(fmu, start_time=START, stop_time=STOP, output_interval=REF_STEP, input=signal,
                            output=outputs, start_values={"solver.local_error_tolerance": 3e-4})
        every = int(round(STEP / REF_STEP))
        write_csv(os.path.join(fmu_dir, stem + "_ref.csv"), fine[::every])
        with open(os.path.join(fmu_dir, stem + "_ref.opt"), "w") as f:
            f.write(f"StartTime, {START!r}\nStopTime, {STOP!r}\nStepSize, {STEP!r}\nRelTol, 0.0001\n")
        found = validate_test_fmu(fmu_dir)
        problems += found

        # FMPy as the importing tool, at the options' step, against the reference.
        result_dir = os.path.join(dest, "results", version, "cs", platform, "FMPy", fmpy.__version__,
                                  "RotorBearing", tool_version, stem)
        shutil.rmtree(result_dir, ignore_errors=True)
        os.makedirs(result_dir)
        inputs = os.path.join(fmu_dir, stem + "_in.csv")
        res = simulate_fmu(fmu, start_time=START, stop_time=STOP, output_interval=STEP,
                           input=read_csv(inputs) if os.path.exists(inputs) else None, output=outputs)
        write_csv(os.path.join(result_dir, stem + "_out.csv"), res)
        reference = read_csv(os.path.join(fmu_dir, stem + "_ref.csv"))
        verdict = validate_result(res, reference, START, STOP)
        if verdict is None:
            open(os.path.join(result_dir, "passed"), "w").close()
        else:
            problems.append(f"{stem} FMI {version}: {verdict}")
        problems += validate_cross_check_result(result_dir)
        size = os.path.getsize(fmu) / 1e6
        print(f"{stem} FMI {version}: {fmu_dir} ({size:.2f} MB, {len(outputs)} outputs, "
              f"{'input ' if signal is not None else 'no input '}file): layout "
              f"{'valid' if not found else 'INVALID'}, FMPy result {'passes' if verdict is None else 'FAILS'} "
              "the cross-check rule")

if problems:
    print("\n".join(problems), file=sys.stderr)
    sys.exit(1)
print(f"cross-check layout of {len(stems)} models, FMI 2.0 and 3.0, valid and passed")
