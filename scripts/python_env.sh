#!/usr/bin/env bash
# Idempotent Python environment for FMU validation and tests: .venv with FMPy.
set -euo pipefail
cd "$(dirname "$0")/.."
if [ ! -x .venv/bin/python ]; then
  python3 -m venv .venv
fi
if ! .venv/bin/python -c "import fmpy, matplotlib, pythonfmu, libcosimpy, dask.distributed, scipy.ndimage" 2>/dev/null; then
  .venv/bin/pip install --quiet --upgrade pip
  .venv/bin/pip install --quiet "fmpy==0.3.32" matplotlib "pythonfmu==0.7.0" "libcosimpy==0.0.6" "dask[distributed]" "scipy<2"
fi
