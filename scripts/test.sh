#!/usr/bin/env bash
# Every check: formatting, lints (warnings are errors) and all tests, closing
# with one summary line "tests: N passed, M failed".
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
bash scripts/python_env.sh
cargo fmt --all -- --check
cargo clippy --all-targets --quiet -- -D warnings
# The FMU library alone (no CLI, no plots), as the win64 DLL is built.
cargo clippy --lib --no-default-features --quiet -- -D warnings
# The FMU tests load the cdylib, which `cargo test` does not relink; the Python
# tests use the packed FMU (fmu_pack.sh builds the linux64 and win64 binaries,
# packs and validates it with FMPy; tests/wine.rs runs the win64 one under Wine).
cargo build --lib --examples --quiet
# Every shipped model as an FMI 2.0 and an FMI 3.0 FMU (out/<name>.fmu,
# out/<name>_fmi3.fmu; tests/fmi3.rs compares them).
bash fmu_pack.sh --fmi 2,3
for model in models/*.toml; do
  [ "$model" = models/hydro_unit.toml ] || bash fmu_pack.sh --fmi 2,3 --model "$model"
done
bash fmu_pack.sh --model tests/data/torque_ports.toml
# The torque-driven hydro unit's speed-driven twin (the same model file with
# drive = "speed") for the load-rejection comparison of tests/system_plant.rs.
sed 's/^drive = "torque"$/drive = "speed"/' models/hydro_unit_torque.toml > out/hydro_unit_torque_speed.toml
grep -q '^drive = "speed"$' out/hydro_unit_torque_speed.toml
bash fmu_pack.sh --model out/hydro_unit_torque_speed.toml --out out/hydro_unit_torque_speed.fmu
# The governor/turbine/generator FMUs (speed- and torque-driven) for the coupled-system
# tests; the magnetic bearing FMU and the rotors it is coupled with (tests/system_amb.rs).
.venv/bin/python system/build_plant.py out
.venv/bin/python system/build_amb.py out
bash fmu_pack.sh --model system/classic_disk_rotor_amb.toml
bash fmu_pack.sh --model system/classic_disk_rotor_amb_reference.toml
log=$(mktemp)
trap 'rm -f "$log"' EXIT
status=0
# --no-fail-fast: every test binary runs even when an earlier one fails; the
# exit status is still non-zero on any failure.
cargo test --all-targets --no-fail-fast 2>&1 | tee "$log" || status=$?
# The doctests (how a library user calls each public module) are not all-targets.
cargo test --doc --no-fail-fast 2>&1 | tee -a "$log" || status=$?
awk '/^test result:/ { for (i = 1; i <= NF; i++) { if ($(i+1) ~ /^passed/) p += $i; if ($(i+1) ~ /^failed/) f += $i } }
     END { printf "tests: %d passed, %d failed\n", p, f }' "$log"
exit "$status"
