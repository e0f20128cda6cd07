#!/usr/bin/env bash
# Pack the rotor-bearing simulator as an FMI 2.0 Co-Simulation FMU and validate it.
#
#   ./fmu_pack.sh                      # the default FMU: models/hydro_unit.toml → out/RotorBearing.fmu
#   ./fmu_pack.sh --model FILE.toml    # any model → out/<model name>.fmu
#   ./fmu_pack.sh --model F --out X.fmu
#   ./fmu_pack.sh --platforms linux64  # one platform only (default: linux64,win64)
#
# Builds the release library for each platform (linux64: the host toolchain;
# win64: the cross toolchain of scripts/setup.sh, docs/platforms.md), generates
# modelDescription.xml, resources/model.toml and documentation/index.html from
# the model (one source: the variable table in src/fmi2/variables.rs), checks
# that every binary exports the 34 fmi2 functions of a co-simulation FMU and
# that the DLL imports system DLLs only, zips the FMU, then validates it with
# FMPy and fails on any problem.
set -euo pipefail
cd "$(dirname "$0")"
model=models/hydro_unit.toml
out=""
platforms=linux64,win64
while [ $# -gt 0 ]; do
  case "$1" in
    --model) model="$2"; shift 2 ;;
    --out) out="$2"; shift 2 ;;
    --platforms) platforms="$2"; shift 2 ;;
    -h|--help) sed -n '2,15p' "$0"; exit 0 ;;
    *) echo "fmu_pack.sh: unknown argument $1" >&2; exit 2 ;;
  esac
done
[ -f "$model" ] || { echo "fmu_pack.sh: model file $model not found" >&2; exit 2; }
linux64="" win64=""
IFS=, read -r -a chosen <<< "$platforms"
for p in "${chosen[@]}"; do
  case "$p" in
    linux64) linux64=1 ;;
    win64) win64=1 ;;
    *) echo "fmu_pack.sh: --platforms $platforms: unknown platform \"$p\" (linux64, win64)" >&2; exit 2 ;;
  esac
done
[ -n "$linux64$win64" ] || { echo "fmu_pack.sh: --platforms \"$platforms\" names no platform (linux64, win64)" >&2; exit 2; }
# Packing installs nothing: scripts/setup.sh and scripts/python_env.sh (run by
# both README commands) provide the toolchains, libclang and the venv with FMPy.
for tool in cargo nm; do
  command -v "$tool" >/dev/null 2>&1 || { echo "fmu_pack.sh: $tool not found: run scripts/setup.sh" >&2; exit 2; }
done
[ -x .venv/bin/python ] || { echo "fmu_pack.sh: .venv missing: run scripts/python_env.sh" >&2; exit 2; }
if [ -n "$win64" ]; then
  . scripts/win64_env.sh
  for tool in "$WIN64_CARGO" "$WIN64_RUSTC" "$WIN64_CC" x86_64-w64-mingw32-objdump; do
    command -v "$tool" >/dev/null 2>&1 || {
      echo "fmu_pack.sh: $tool not found: run scripts/setup.sh (or pack --platforms linux64)" >&2; exit 2; }
  done
  [ -f "$WIN64_SYSROOT/.complete" ] || {
    echo "fmu_pack.sh: no $WIN64_TARGET standard library for $("$WIN64_RUSTC" -V) in $WIN64_SYSROOT:" \
      "run scripts/setup.sh (or pack --platforms linux64)" >&2; exit 2; }
fi

# The rotor CLI writes the generated files, so the host build always runs.
cargo build --release --quiet --lib --bin rotor
so=target/release/librotor_bearing.so
if [ -n "$win64" ]; then
  # The library alone (no CLI, no plots) for Windows; Cargo.lock as it is.
  win64_cargo build --release --quiet --locked --lib --no-default-features --target "$WIN64_TARGET"
  dll="${WIN64_TARGET_DIR:-target/win64}/$WIN64_TARGET/release/rotor_bearing.dll"
fi

# The functions of an FMI 2.0 co-simulation FMU (fmi2Functions.h: 25 common, 9
# co-simulation).
required="fmi2GetTypesPlatform fmi2GetVersion fmi2SetDebugLogging fmi2Instantiate fmi2FreeInstance
fmi2SetupExperiment fmi2EnterInitializationMode fmi2ExitInitializationMode fmi2Terminate fmi2Reset
fmi2GetReal fmi2GetInteger fmi2GetBoolean fmi2GetString fmi2SetReal fmi2SetInteger fmi2SetBoolean
fmi2SetString fmi2GetFMUstate fmi2SetFMUstate fmi2FreeFMUstate fmi2SerializedFMUstateSize
fmi2SerializeFMUstate fmi2DeSerializeFMUstate fmi2GetDirectionalDerivative
fmi2SetRealInputDerivatives fmi2GetRealOutputDerivatives fmi2DoStep fmi2CancelStep fmi2GetStatus
fmi2GetRealStatus fmi2GetIntegerStatus fmi2GetBooleanStatus fmi2GetStringStatus"
# check_exports FILE EXPORTED_NAMES: every required function is exported.
check_exports() {
  local missing
  missing=$(comm -23 <(tr ' ' '\n' <<< "$required" | sort) <(sort -u <<< "$2") | tr '\n' ' ')
  [ -z "$missing" ] || { echo "fmu_pack.sh: $1 does not export $missing" >&2; exit 1; }
}
# DLLs every Windows 10 or later has (Rust's std needs Windows 10): anything
# else, such as MinGW's libgcc_s_seh-1.dll or libwinpthread-1.dll, would not
# be found on a user's machine.
system_dlls="kernel32.dll ntdll.dll msvcrt.dll userenv.dll ws2_32.dll advapi32.dll bcrypt.dll
bcryptprimitives.dll api-ms-win-core-synch-l1-2-0.dll"
if [ -n "$linux64" ]; then
  check_exports "$so" "$(nm -D --defined-only "$so" | awk '$2 == "T" && $3 ~ /^fmi2/ { print $3 }')"
fi
if [ -n "$win64" ]; then
  pe=$(x86_64-w64-mingw32-objdump -p "$dll")
  check_exports "$dll" "$(awk '/^\[Ordinal\/Name Pointer\] Table/ { t = 1; next } t && NF == 0 { t = 0 }
    t && $NF ~ /^fmi2/ { print $NF }' <<< "$pe")"
  imports=$(awk '/DLL Name:/ { print $3 }' <<< "$pe" | sort -fu | tr '\n' ' ')
  foreign=$(for d in $imports; do grep -qixF "$d" <(tr ' ' '\n' <<< "$system_dlls") || echo "$d"; done | tr '\n' ' ')
  [ -z "$foreign" ] || { echo "fmu_pack.sh: $dll imports non-system DLLs: $foreign" >&2; exit 1; }
fi

stage=$(mktemp -d)
trap 'rm -rf "$stage"' EXIT
read -r name guid < <(target/release/rotor fmu-stage "$model" "$stage" 2>/dev/null)
rm -rf "$stage/binaries"
if [ -n "$linux64" ]; then
  mkdir -p "$stage/binaries/linux64"
  cp "$so" "$stage/binaries/linux64/RotorBearing.so"
fi
if [ -n "$win64" ]; then
  mkdir -p "$stage/binaries/win64"
  cp "$dll" "$stage/binaries/win64/RotorBearing.dll"
fi
if [ -z "$out" ]; then
  if [ "$model" = models/hydro_unit.toml ]; then out=out/RotorBearing.fmu; else out="out/$name.fmu"; fi
fi
mkdir -p "$(dirname "$out")"
rm -f "$out"
.venv/bin/python - "$stage" "$out" <<'PY'
import os, sys, zipfile
stage, out = sys.argv[1], sys.argv[2]
with zipfile.ZipFile(out, "w", zipfile.ZIP_DEFLATED) as z:
    for root, dirs, files in os.walk(stage):
        dirs.sort()
        for f in sorted(files):
            path = os.path.join(root, f)
            z.write(path, os.path.relpath(path, stage))
PY
.venv/bin/python - "$out" <<'PY' || { rm -f "$out"; exit 1; }
import sys
from fmpy.validation import validate_fmu
problems = validate_fmu(sys.argv[1])
if problems:
    print("\n".join(problems), file=sys.stderr)
    sys.exit(f"fmu_pack.sh: FMPy validation of {sys.argv[1]} failed")
PY
if [ -n "$linux64" ] && [ -n "$win64" ]; then
  packed="linux64 and win64"
else
  packed="${linux64:+linux64}${win64:+win64} only (--platforms $platforms)"
fi
echo "packed $out ($name, GUID $guid) for $packed: 34 fmi2 functions exported${win64:+, the DLL imports system DLLs only (${imports% })}, FMPy validation passed"
