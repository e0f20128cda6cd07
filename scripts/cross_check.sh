#!/usr/bin/env bash
# The FMI Cross-Check layout of the packed FMUs, FMI 2.0 and FMI 3.0, checked
# with FMPy's cross-check validator (scripts/cross_check.py says what it writes):
#
#   bash scripts/cross_check.sh                  # every shipped model → out/cross-check
#   bash scripts/cross_check.sh DEST jeffcott    # chosen models into DEST
#
# Needs the FMUs in out/ (`fmu_pack.sh --fmi 2,3 --model models/<m>.toml`) and
# the venv of scripts/python_env.sh.
set -euo pipefail
cd "$(dirname "$0")/.."
[ -x .venv/bin/python ] || { echo "cross_check.sh: .venv missing: run scripts/python_env.sh" >&2; exit 2; }
dest=${1:-out/cross-check}
[ $# -eq 0 ] || shift
exec .venv/bin/python -W ignore::DeprecationWarning scripts/cross_check.py "$dest" "$@"
