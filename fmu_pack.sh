#!/usr/bin/env bash
# Packs the FMI 2.0 Co-Simulation FMU. The FMI layer (src/fmi2) does not exist
# yet: until it lands with the FMU issue this script builds the release library
# and stops with an error rather than produce an FMU that cannot be loaded.
set -euo pipefail
cd "$(dirname "$0")"
cargo build --release --lib --quiet
echo "fmu_pack.sh: the FMI 2.0 layer is not implemented yet (FMU issue); no FMU was packed" >&2
exit 2
