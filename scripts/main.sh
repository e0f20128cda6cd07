#!/usr/bin/env bash
# Main job: build the project and run the analyses of the built-in default model
# (the classic disk-on-shaft rotor): static deflection, modes at 4000 rpm, and a
# Campbell diagram with critical speeds. Results land in out/.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
cargo build --release --quiet
mkdir -p out
rotor=target/release/rotor
$rotor info
$rotor static --csv out/static_deflection.csv
$rotor modes --rpm 4000 --modes 8 --csv out/modes_4000rpm.csv
$rotor campbell --max-rpm 6000 --steps 60 --modes 8 --csv out/campbell.csv --png out/campbell.png
$rotor coefficients --csv out/plain_bearing_coefficients.csv --png out/plain_bearing_coefficients.png
echo "main: results in out/ (static_deflection.csv, modes_4000rpm.csv, campbell.csv/png, plain_bearing_coefficients.csv/png)"
