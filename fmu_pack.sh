#!/usr/bin/env bash
# Pack the rotor-bearing simulator as an FMI 2.0 Co-Simulation FMU and validate it.
#
#   ./fmu_pack.sh                      # the default FMU: models/hydro_unit.toml → out/RotorBearing.fmu
#   ./fmu_pack.sh --model FILE.toml    # any model → out/<model name>.fmu
#   ./fmu_pack.sh --model F --out X.fmu
#   ./fmu_pack.sh --platforms linux64  # one platform only (default: linux64,win64)
#   ./fmu_pack.sh --fmi 3              # an FMI 3.0 FMU: out/<name>_fmi3.fmu (--out names it)
#   ./fmu_pack.sh --fmi 2,3            # both: out/<name>.fmu and out/<name>_fmi3.fmu
#                                      # (FMI 2.0 is the default; with --out X.fmu: X_fmi3.fmu)
#
# Builds the release library for each platform (linux64: the host toolchain;
# win64: the cross toolchain of scripts/setup.sh, docs/platforms.md; one library
# carries the fmi2* and the fmi3* functions, packed without its debug
# information), generates
# modelDescription.xml, resources/model.toml and documentation/index.html from
# the model (one source: the variable table in src/fmu/variables/), checks
# that every binary exports the 34 fmi2 functions of a co-simulation FMU (for
# FMI 3.0 the 75 fmi3 functions) and
# that the DLL imports system DLLs only (scripts/fmu_binary_check.sh), zips the
# FMU, then validates it with FMPy and fails on any problem.
set -euo pipefail
cd "$(dirname "$0")"
model=models/hydro_unit.toml
out=""
platforms=linux64,win64
fmi=2
while [ $# -gt 0 ]; do
  case "$1" in
    --model|--out|--platforms|--fmi) [ $# -ge 2 ] || { echo "fmu_pack.sh: $1 needs a value" >&2; exit 2; } ;;
  esac
  case "$1" in
    --model) model="$2"; shift 2 ;;
    --out) out="$2"; shift 2 ;;
    --platforms) platforms="$2"; shift 2 ;;
    --fmi) fmi="$2"; shift 2 ;;
    -h|--help) sed -n '2,20p' "$0"; exit 0 ;;
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
fmi2="" fmi3=""
IFS=, read -r -a versions <<< "$fmi"
for v in "${versions[@]}"; do
  case "$v" in
    2) fmi2=1 ;;
    3) fmi3=1 ;;
    *) echo "fmu_pack.sh: --fmi $fmi: unknown FMI version \"$v\" (2, 3)" >&2; exit 2 ;;
  esac
done
[ -n "$fmi2$fmi3" ] || { echo "fmu_pack.sh: --fmi \"$fmi\" names no FMI version (2, 3)" >&2; exit 2; }
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

# Exports and (for the DLL) imports of each binary (scripts/fmu_binary_check.sh).
checked=()
for v in ${fmi2:+2} ${fmi3:+3}; do
  if [ -n "$linux64" ]; then checked+=("$(bash scripts/fmu_binary_check.sh --fmi "$v" "$so")"); fi
  if [ -n "$win64" ]; then checked+=("$(bash scripts/fmu_binary_check.sh --fmi "$v" "$dll")"); fi
done
if [ -n "$linux64" ] && [ -n "$win64" ]; then
  packed="linux64 and win64"
else
  packed="${linux64:+linux64}${win64:+win64} only (--platforms $platforms)"
fi

# pack VERSION OUT: stage, copy the binaries (debug information stripped), zip,
# validate with FMPy.
pack() {
  local version=$1 target=$2 stage="$work/fmi$1" linux_dir win_dir name guid
  mkdir -p "$stage"
  read -r name guid < <(target/release/rotor fmu-stage --fmi "$version" "$model" "$stage" 2>/dev/null)
  rm -rf "$stage/binaries"
  if [ "$version" = 3 ]; then linux_dir=x86_64-linux win_dir=x86_64-windows; else linux_dir=linux64 win_dir=win64; fi
  if [ -n "$linux64" ]; then
    mkdir -p "$stage/binaries/$linux_dir"
    strip --strip-debug -o "$stage/binaries/$linux_dir/RotorBearing.so" "$so"
  fi
  if [ -n "$win64" ]; then
    mkdir -p "$stage/binaries/$win_dir"
    x86_64-w64-mingw32-strip --strip-debug -o "$stage/binaries/$win_dir/RotorBearing.dll" "$dll"
  fi
  mkdir -p "$(dirname "$target")"
  rm -f "$target"
  .venv/bin/python - "$stage" "$target" <<'PY'
import os, sys, zipfile
stage, out = sys.argv[1], sys.argv[2]
with zipfile.ZipFile(out, "w", zipfile.ZIP_DEFLATED) as z:
    for root, dirs, files in os.walk(stage):
        dirs.sort()
        for f in sorted(files):
            path = os.path.join(root, f)
            z.write(path, os.path.relpath(path, stage))
PY
  .venv/bin/python - "$target" <<'PY' || { rm -f "$target"; exit 1; }
import sys
from fmpy.validation import validate_fmu
problems = validate_fmu(sys.argv[1])
if problems:
    print("\n".join(problems), file=sys.stderr)
    sys.exit(f"fmu_pack.sh: FMPy validation of {sys.argv[1]} failed")
PY
  local token=GUID
  [ "$version" = 2 ] || token="FMI 3.0, instantiationToken"
  echo "packed $target ($name, $token $guid) for $packed, FMPy validation passed"
}

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
name=$(target/release/rotor fmu-stage "$model" "$work/name" 2>/dev/null | awk '{ print $1 }')
if [ -z "$out" ]; then
  if [ "$model" = models/hydro_unit.toml ]; then base=out/RotorBearing; else base="out/$name"; fi
  out2="$base.fmu" out3="${base}_fmi3.fmu"
elif [ -n "$fmi2" ] && [ -n "$fmi3" ]; then
  out2="$out" out3="${out%.fmu}_fmi3.fmu"
else
  out2="$out" out3="$out"
fi
if [ -n "$fmi2" ]; then pack 2 "$out2"; fi
if [ -n "$fmi3" ]; then pack 3 "$out3"; fi
printf '  %s\n' "${checked[@]}"
