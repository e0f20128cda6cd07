#!/usr/bin/env bash
# Main job: build the project and run the analyses of the built-in default model
# (the classic disk-on-shaft rotor): static deflection, modes at 4000 rpm, and a
# Campbell diagram with critical speeds. Results land in out/.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
bash scripts/python_env.sh
cargo build --release --quiet
mkdir -p out
rotor=target/release/rotor
$rotor info
$rotor static --csv out/static_deflection.csv
$rotor modes --rpm 4000 --modes 8 --csv out/modes_4000rpm.csv
$rotor campbell --max-rpm 6000 --steps 60 --modes 8 --csv out/campbell.csv --png out/campbell.png
$rotor coefficients --csv out/plain_bearing_coefficients.csv --png out/plain_bearing_coefficients.png
# The analyst's set: unbalance response with amplification factors and API 684
# separation margins (damped classic rotor), and one HTML report of the Jeffcott
# rotor at 3000 rpm (operating point, unbalance response, modes and shapes,
# stability, critical speed map, drawing).
$rotor unbalance models/classic_disk_rotor_damped.toml --max-rpm 4000 --operating-rpm 2000:2500 \
  --csv out/unbalance_response.csv --png out/unbalance_response.png
$rotor report models/jeffcott.toml --rpm 3000 --out out/jeffcott_report.html
# Nonlinear transient: a Jeffcott rotor on plain bearings run up through oil whirl into oil whip.
$rotor simulate models/jeffcott.toml --ramp-rpm 3000:16000 --duration 8 --step 1e-4 --output-step 2e-4 \
  --csv out/jeffcott_run_up.csv --plots out/jeffcott_run_up > out/jeffcott_run_up_windows.txt
# The whole operating envelope: the Jeffcott rotor from rest on its bushings up to
# 3000 rpm (lift-off at 2.3 rpm) and a coast-down back to standstill.
$rotor simulate models/jeffcott.toml --ramp-rpm 0:3000 --duration 2 --step 1e-4 --output-step 5e-4 \
  --csv out/jeffcott_start_from_rest.csv
$rotor simulate models/jeffcott.toml --ramp-rpm 3000:0 --duration 2 --step 1e-4 --output-step 5e-4 \
  --csv out/jeffcott_coast_down.csv
# The hydro unit at 150 rpm on tilting-pad guide bearings.
$rotor simulate models/hydro_unit.toml --rpm 150 --duration 40 --step 5e-3 --output-step 5e-3 --ramp-time 2 \
  --csv out/hydro_unit.csv --plots out/hydro_unit > out/hydro_unit_windows.txt
# The same run on the Craig–Bampton reduced rotor (34 coordinates for 80 DOFs).
$rotor simulate models/hydro_unit.toml --rpm 150 --duration 40 --step 5e-3 --output-step 5e-3 --ramp-time 2 \
  --reduced-modes 10 --csv out/hydro_unit_reduced.csv
# A train of rotors (issue 49): a turbine, a flexible coupling, a generator and a
# flanged exciter on five bearings set on their catenary: the alignment (the
# bearing loads and the line's bending stress), the Campbell diagram and 0.5 s
# at 3000 rpm.
$rotor alignment models/turbine_generator_train.toml --rpm 3000 > out/turbine_generator_train_alignment.txt
$rotor campbell models/turbine_generator_train.toml --csv out/turbine_generator_train_campbell.csv \
  --png out/turbine_generator_train_campbell.png
$rotor simulate models/turbine_generator_train.toml --rpm 3000 --duration 0.5 \
  --csv out/turbine_generator_train.csv
# A six-stage centrifugal compressor on two five-pad tilting-pad bearings with
# finite-length films (issue 47; L/D 0.45, 60° pads, load between pads, preload
# 0.3; the films' force tables are built once and cached): its operating point,
# Campbell diagram, stability (API 617 Level I), a 3 s start-up from rest on its
# pads to the maximum continuous speed, and its design-review report judged as a
# compressor (issue 48: API 684 unbalance cases and margins over 8000-11500 rpm).
$rotor info models/compressor.toml > out/compressor_info.txt
$rotor operating-point models/compressor.toml > out/compressor_operating_point.txt
$rotor campbell models/compressor.toml --csv out/compressor_campbell.csv --png out/compressor_campbell.png
$rotor stability models/compressor.toml > out/compressor_stability.txt
$rotor simulate models/compressor.toml --ramp-rpm 0:11500 --duration 3 --step 1e-4 --output-step 1e-3 \
  --csv out/compressor_start_up.csv --plots out/compressor_start_up > out/compressor_start_up_windows.txt
$rotor report models/compressor.toml --out out/compressor_report.html
# The three-guide hydro unit as installed (issue 49): its turbine guide bearing
# 0.12 mm off the line of the generator guides (a plumb-line survey). A vertical
# shaft carries no weight on its guides: the offset alone loads them. Its
# alignment (load sharing, influence matrix, stability against the offsets)
# and 2 s at 300 rpm.
$rotor info models/hydro_unit_three_guide_offset.toml > out/hydro_unit_three_guide_offset_info.txt
$rotor alignment models/hydro_unit_three_guide_offset.toml --rpm 300 > out/hydro_unit_three_guide_offset_alignment.txt
$rotor simulate models/hydro_unit_three_guide_offset.toml --rpm 300 --duration 2 --step 5e-3 --output-step 0.02 \
  --csv out/hydro_unit_three_guide_offset.csv
# The whole machine: a 300 rpm Francis unit on its bearing brackets with a runner
# seal and the generator's magnetic pull (docs/machine.md): Campbell diagram and
# unbalance response as shipped (field off), operating point and a 10 s
# transient at 300 rpm synchronized (nominal field).
$rotor info models/hydro_unit_brackets.toml > out/hydro_unit_brackets_info.txt
$rotor draw models/hydro_unit_brackets.toml --png out/hydro_unit_brackets.png
$rotor campbell models/hydro_unit_brackets.toml --steps 40 --modes 8 --csv out/hydro_unit_brackets_campbell.csv \
  --png out/hydro_unit_brackets_campbell.png
$rotor unbalance models/hydro_unit_brackets.toml --min-rpm 30 --max-rpm 600 --points 120 \
  --csv out/hydro_unit_brackets_unbalance.csv --png out/hydro_unit_brackets_unbalance.png
$rotor operating-point models/hydro_unit_brackets.toml --rpm 300 --excitation 1 > out/hydro_unit_brackets_operating_point.txt
# Its design-review report, judged as a hydro unit (machine = "hydro_generator"):
# first critical against runaway, ISO 10816-5 group 4 housing zones.
$rotor report models/hydro_unit_brackets.toml --out out/hydro_unit_brackets_report.html
$rotor simulate models/hydro_unit_brackets.toml --excitation 1 --rpm 300 --duration 10 --step 2e-3 --output-step 2e-3 --ramp-time 1 \
  --csv out/hydro_unit_brackets.csv --plots out/hydro_unit_brackets > out/hydro_unit_brackets_windows.txt
# The FMU: build, pack, validate with FMPy, and simulate it with FMPy.
bash fmu_pack.sh
.venv/bin/python scripts/fmpy_demo.py out/RotorBearing.fmu out/fmpy_hydro_unit
# System level: the rotor FMU coupled to a governor/turbine/generator FMU by libcosim
# (start-up from standstill, emergency stop to rest and load rejection with tilting-pad
# and plain bearings, a breakaway start of the Jeffcott rotor, a run through a
# critical speed), and a Dask sweep.
.venv/bin/python system/build_plant.py out
bash fmu_pack.sh --model models/hydro_unit_plain.toml
bash fmu_pack.sh --model models/jeffcott.toml
bash fmu_pack.sh --model models/classic_disk_rotor_damped.toml
.venv/bin/python system/couple.py all 2>&1 | grep '→'
# The shaft as the plant's connector (docs/system.md): the torque-driven hydro
# unit (its own inertia, torsion and thrust bearing) with the torque plant FMU:
# start-up from standstill with breakaway and synchronization, load rejection,
# shut-down to rest and a three-phase short circuit; and the unit on brackets
# with its field switched on at synchronization and in a part-load run.
bash fmu_pack.sh --model models/hydro_unit_torque.toml
bash fmu_pack.sh --model models/hydro_unit_brackets.toml
.venv/bin/python system/couple_torque.py all 2>&1 | grep '→'
.venv/bin/python system/couple_brackets.py all 2>&1 | grep '→'
.venv/bin/python system/sweep.py --fmu out/jeffcott.fmu --rpm 4000:16000:13 \
  --param "bearings.left.viscosity,bearings.right.viscosity=0.01,0.02,0.04" --duration 0.6 --out out/sweep_jeffcott
# A PD magnetic bearing FMU (pythonfmu) closed through the rotor FMU's force port
# under libcosim, against the same rotor with the bearing built in: orbits, the
# difference and its bound from the communication step (docs/system.md), and the
# map of the communication steps that keep the loop stable (docs/fmu.md).
.venv/bin/python system/build_amb.py out
bash fmu_pack.sh --model system/classic_disk_rotor_amb.toml
bash fmu_pack.sh --model system/classic_disk_rotor_amb_reference.toml
.venv/bin/python system/amb_demo.py --out out/amb_demo
.venv/bin/python system/amb_demo.py --stability --out out/amb_demo | tee out/amb_demo_stability.txt | tail -n 1
echo "main: results in out/ (hydro_unit_brackets*, modes_4000rpm.csv, campbell.csv/png, plain_bearing_coefficients.csv/png, unbalance_response.csv/png, jeffcott_report.html, hydro_unit_brackets_report.html, jeffcott_run_up*, jeffcott_start_from_rest.csv, jeffcott_coast_down.csv, hydro_unit*, RotorBearing.fmu, fmpy_hydro_unit.csv/_orbits.png, coupled_*.csv/png, torque_*.csv/png, brackets_*.csv/png, sweep_jeffcott*, amb_demo.csv/png, amb_demo_stability.csv/txt)"
