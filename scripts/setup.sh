#!/usr/bin/env bash
# Idempotent set-up of a fresh machine: system packages for the build (bindgen's
# libclang, fontconfig/freetype and a font for the PNG plots), the Rust
# toolchain's components, headless Chromium for the report test, and the
# Windows (win64) cross toolchain of the FMU: Debian's rustc-web/cargo-web/
# rust-web-src, MinGW-w64 and Wine from Debian's packages, the standard library
# for x86_64-pc-windows-gnu built once into a cache outside the work tree, and
# the Wine prefix of the tests (docs/platforms.md). Safe to run again: it does
# only what is missing, and says what it did and how long it took.
set -euo pipefail
cd "$(dirname "$0")/.."
. scripts/win64_env.sh

SUDO=""
[ "$(id -u)" -ne 0 ] && SUDO="sudo"
apt_updated=""
apt_update() {
  if [ -z "$apt_updated" ]; then
    $SUDO apt-get update -qq
    apt_updated=1
  fi
}

# The Debian Rust packages: one version for compiler, cargo and std sources (a
# std only fits the compiler it was built with), at least the crate's
# rust-version. bookworm's own 1.85 is too old; bookworm-security carries a
# current one. apt takes its candidate; no security revision is pinned.
rust_version=$(sed -n 's/^rust-version *= *"\(.*\)"/\1/p' Cargo.toml)
rust_pkgs=(rustc-web cargo-web rust-web-src)
upstream() { local v=${1#*:}; echo "${v%%[+~-]*}"; }
rust_pkgs_ok() {
  local first="" v
  for pkg in "${rust_pkgs[@]}"; do
    v=$(dpkg-query -W -f='${db:Status-Status} ${Version}' "$pkg" 2>/dev/null) || return 1
    [ "${v%% *}" = installed ] || return 1
    v=${v#* }
    [ -z "$first" ] && first=$v
    [ "$v" = "$first" ] || return 1
  done
  dpkg --compare-versions "$(upstream "$first")" ge "$rust_version"
}

need=()
for pkg in pkg-config libclang-dev libfontconfig1-dev libfreetype-dev fonts-dejavu-core valgrind \
  gcc-mingw-w64-x86-64 wine64; do
  dpkg -s "$pkg" >/dev/null 2>&1 || need+=("$pkg")
done
rust_pkgs_ok || need+=("${rust_pkgs[@]}")
if [ ${#need[@]} -gt 0 ]; then
  start=$SECONDS
  echo "setup: installing ${need[*]}"
  apt_update
  if ! rust_pkgs_ok; then
    candidate=$(apt-cache policy rustc-web | awk '/Candidate:/ { print $2 }')
    if [ -z "$candidate" ] || [ "$candidate" = "(none)" ] \
      || ! dpkg --compare-versions "$(upstream "$candidate")" ge "$rust_version"; then
      echo "setup: apt's candidate for rustc-web is ${candidate:-none}, older than the crate's" \
        "rust-version $rust_version (Cargo.toml), so the win64 binary cannot be built: Debian" \
        "carries a current Rust in bookworm-security (is that suite in the apt sources?)." \
        "Without it, pack the FMU for linux64 only (fmu_pack.sh --platforms linux64)." >&2
      exit 1
    fi
    echo "setup: Debian Rust for the win64 build: rustc-web $candidate (rust-version $rust_version)"
  fi
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${need[@]}" >/dev/null
  rust_pkgs_ok || { echo "setup: rustc-web, cargo-web and rust-web-src differ in version after the install" >&2; exit 1; }
  echo "setup: installed ${#need[@]} packages in $((SECONDS - start)) s"
  # WIN64_SYSROOT is keyed by Debian's compiler, which may have just arrived.
  . scripts/win64_env.sh
fi
[ -n "$WIN64_SYSROOT" ] || { echo "setup: $WIN64_RUSTC missing after the install (rustc-web)" >&2; exit 1; }

# Headless Chromium (Debian's package) for the test that renders the HTML
# report in a real browser (tests/analyst_report.rs), with a font for its text.
chromium=()
for pkg in chromium fonts-dejavu-core; do
  dpkg -s "$pkg" >/dev/null 2>&1 || chromium+=("$pkg")
done
if [ ${#chromium[@]} -gt 0 ]; then
  start=$SECONDS
  echo "setup: installing ${chromium[*]}"
  apt_update
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq "${chromium[@]}" >/dev/null
  echo "setup: installed ${#chromium[@]} packages in $((SECONDS - start)) s"
fi

if ! command -v rustup >/dev/null 2>&1; then
  echo "setup: rustup not found; install the Rust toolchain (rustup) first" >&2
  exit 1
fi
for comp in rustfmt clippy; do
  rustup component list --installed 2>/dev/null | grep -q "^$comp" || rustup component add "$comp"
done

# The standard library for x86_64-pc-windows-gnu, built once per Debian
# compiler from rust-web-src (its vendored crates: offline) by -Zbuild-std on an
# empty crate, then kept as a sysroot so that every later build is a plain
# `cargo build --target x86_64-pc-windows-gnu` (win64_cargo). panic=unwind, as
# the FMU's catch_unwind at the C boundary needs.
mkdir -p "$WIN64_CACHE/win64-std"
exec 9> "$WIN64_CACHE/win64-std/.lock"
flock 9  # one build at a time when several work trees set up at once
if [ ! -f "$WIN64_SYSROOT/.complete" ]; then
  start=$SECONDS
  library="$("$WIN64_RUSTC" --print sysroot)/lib/rustlib/src/rust/library"
  [ -d "$library/vendor" ] || { echo "setup: $library/vendor missing (rust-web-src)" >&2; exit 1; }
  echo "setup: building the Rust standard library for $WIN64_TARGET with $("$WIN64_RUSTC" -V)" \
    "into $WIN64_SYSROOT (once per compiler; a few minutes of CPU)"
  work=$(mktemp -d "$WIN64_CACHE/win64-std/build.XXXXXX")
  trap 'rm -rf "$work"' EXIT
  mkdir -p "$work/probe/src" "$work/probe/.cargo"
  cat > "$work/probe/Cargo.toml" <<'TOML'
[package]
name = "win64_std_probe"
version = "0.0.0"
edition = "2021"

[profile.release]
debug = 1

# As in the std's own workspace: every compiler intrinsic in its own object so
# that none clashes with MinGW's libgcc.
[profile.release.package.compiler_builtins]
codegen-units = 10000
TOML
  : > "$work/probe/src/lib.rs"
  cat > "$work/probe/.cargo/config.toml" <<TOML
[source.crates-io]
replace-with = "rust-library-vendor"

[source.rust-library-vendor]
directory = "$library/vendor"
TOML
  (cd "$work/probe" && env -u RUSTFLAGS -u CARGO_ENCODED_RUSTFLAGS \
    RUSTC="$WIN64_RUSTC" RUSTC_BOOTSTRAP=1 CARGO_TARGET_DIR="$work/target" \
    CARGO_TARGET_X86_64_PC_WINDOWS_GNU_LINKER="$WIN64_CC" \
    nice "$WIN64_CARGO" build --quiet --offline --release -Zbuild-std=std,panic_unwind,panic_abort \
    --target "$WIN64_TARGET")
  lib="$work/sysroot/lib/rustlib/$WIN64_TARGET/lib"
  mkdir -p "$lib"
  cp "$work/target/$WIN64_TARGET/release/deps/"lib*.rlib "$lib/"
  rm -f "$lib"/libwin64_std_probe-*.rlib
  "$WIN64_RUSTC" -vV > "$work/sysroot/.complete"
  for old in "$WIN64_CACHE/win64-std"/*/; do
    case "$old" in
      "$work/") ;;
      */build.*/ | "$WIN64_SYSROOT/") rm -rf "$old" ;;  # left by an interrupted build
      *) rm -rf "$old"; echo "setup: removed ${old%/}, the std of an earlier compiler" ;;
    esac
  done
  mv "$work/sysroot" "$WIN64_SYSROOT"
  echo "setup: the $WIN64_TARGET standard library ($(ls "$WIN64_SYSROOT/lib/rustlib/$WIN64_TARGET/lib" | wc -l) rlibs) built in $((SECONDS - start)) s"
fi
exec 9>&-

# The Wine prefix the Wine tests run in (created once; wine would otherwise
# create ~/.wine on first use).
if [ ! -f "$WINEPREFIX/system.reg" ]; then
  start=$SECONDS
  echo "setup: creating the Wine prefix $WINEPREFIX"
  mkdir -p "$WIN64_CACHE"
  WINEDEBUG=-all /usr/lib/wine/wine64 wineboot --init >/dev/null 2>&1
  /usr/lib/wine/wineserver -w 2>/dev/null || true
  [ -f "$WINEPREFIX/system.reg" ] || { echo "setup: wineboot did not create $WINEPREFIX" >&2; exit 1; }
  echo "setup: Wine prefix created in $((SECONDS - start)) s"
fi
