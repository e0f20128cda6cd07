#!/usr/bin/env bash
# Idempotent set-up of a fresh machine: system packages for the build (bindgen's
# libclang, fontconfig/freetype and a font for the PNG plots), headless
# Chromium for the report test, and the Rust toolchain's components. Safe to
# run again: it installs only what is missing.
set -euo pipefail

need=()
for pkg in pkg-config libclang-dev libfontconfig1-dev libfreetype-dev fonts-dejavu-core valgrind; do
  dpkg -s "$pkg" >/dev/null 2>&1 || need+=("$pkg")
done
if [ ${#need[@]} -gt 0 ]; then
  echo "setup: installing ${need[*]}"
  SUDO=""
  [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq "${need[@]}" >/dev/null
fi

# Headless Chromium (Debian's package) for the test that renders the HTML
# report in a real browser (tests/analyst_report.rs), with a font for its text.
chromium=()
for pkg in chromium fonts-dejavu-core; do
  dpkg -s "$pkg" >/dev/null 2>&1 || chromium+=("$pkg")
done
if [ ${#chromium[@]} -gt 0 ]; then
  echo "setup: installing ${chromium[*]}"
  SUDO=""
  [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq "${chromium[@]}" >/dev/null
fi

if ! command -v cargo >/dev/null 2>&1; then
  echo "setup: cargo not found; install the Rust toolchain (rustup) first" >&2
  exit 1
fi
for comp in rustfmt clippy; do
  rustup component list --installed 2>/dev/null | grep -q "^$comp" || rustup component add "$comp"
done
