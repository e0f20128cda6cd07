#!/usr/bin/env bash
# Pack the rotor-bearing simulator as an FMI 2.0 Co-Simulation FMU and validate it.
#
#   ./fmu_pack.sh                      # the default FMU: models/hydro_unit.toml → out/RotorBearing.fmu
#   ./fmu_pack.sh --model FILE.toml    # any model → out/<model name>.fmu
#   ./fmu_pack.sh --model F --out X.fmu
#
# Builds the release library, generates modelDescription.xml, resources/model.toml
# and documentation/index.html from the model (one source: the variable table in
# src/fmi2/variables.rs), zips the FMU, then validates it with FMPy and fails on
# any problem.
set -euo pipefail
cd "$(dirname "$0")"
model=models/hydro_unit.toml
out=""
while [ $# -gt 0 ]; do
  case "$1" in
    --model) model="$2"; shift 2 ;;
    --out) out="$2"; shift 2 ;;
    -h|--help) sed -n '2,12p' "$0"; exit 0 ;;
    *) echo "fmu_pack.sh: unknown argument $1" >&2; exit 2 ;;
  esac
done
[ -f "$model" ] || { echo "fmu_pack.sh: model file $model not found" >&2; exit 2; }
# Packing installs nothing: scripts/setup.sh and scripts/python_env.sh (run by
# both README commands) provide the toolchain, libclang and the venv with FMPy.
for tool in cargo nm; do
  command -v "$tool" >/dev/null 2>&1 || { echo "fmu_pack.sh: $tool not found: run scripts/setup.sh" >&2; exit 2; }
done
[ -x .venv/bin/python ] || { echo "fmu_pack.sh: .venv missing: run scripts/python_env.sh" >&2; exit 2; }
cargo build --release --quiet --lib --bin rotor
stage=$(mktemp -d)
trap 'rm -rf "$stage"' EXIT
read -r name guid < <(target/release/rotor fmu-stage "$model" "$stage" 2>/dev/null)
cp target/release/librotor_bearing.so "$stage/binaries/linux64/RotorBearing.so"
if [ -z "$out" ]; then
  if [ "$model" = models/hydro_unit.toml ]; then out=out/RotorBearing.fmu; else out="out/$name.fmu"; fi
fi
mkdir -p "$(dirname "$out")"
rm -f "$out"
.venv/bin/python - "$stage" "$out" <<'PY'
import os, sys, zipfile
stage, out = sys.argv[1], sys.argv[2]
with zipfile.ZipFile(out, "w", zipfile.ZIP_DEFLATED) as z:
    for root, _, files in os.walk(stage):
        for f in sorted(files):
            path = os.path.join(root, f)
            z.write(path, os.path.relpath(path, stage))
PY
# Exported symbols: all fmi2* functions a co-simulation FMU must have.
count=$(nm -D --defined-only "$stage/binaries/linux64/RotorBearing.so" | grep -c ' T fmi2')
[ "$count" -ge 34 ] || { echo "fmu_pack.sh: only $count fmi2 functions exported" >&2; exit 1; }
.venv/bin/python - "$out" <<'PY'
import sys
from fmpy.validation import validate_fmu
problems = validate_fmu(sys.argv[1])
if problems:
    print("\n".join(problems), file=sys.stderr)
    sys.exit(f"fmu_pack.sh: FMPy validation of {sys.argv[1]} failed")
PY
echo "packed $out ($name, GUID $guid): $count fmi2 functions, FMPy validation passed"
