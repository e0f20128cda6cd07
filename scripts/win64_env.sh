# Sourced by scripts/setup.sh, fmu_pack.sh and the Wine tests: where the Windows
# (win64) cross toolchain lives and the environment of a cross build.
#
# The FMU's win64 binary is built on Linux with Debian's own Rust (rustc-web and
# cargo-web from bookworm-security, in /usr/bin) and MinGW-w64 (posix variant).
# Debian ships no std for x86_64-pc-windows-gnu, so scripts/setup.sh builds it
# once from rust-web-src into a sysroot in the cache below; a std only fits the
# compiler it was built with (E0514 otherwise), so the sysroot is keyed by that
# compiler's release and commit. Nothing here lives in the work tree.
#
# Exports (after `. scripts/win64_env.sh`):
#   WIN64_TARGET    x86_64-pc-windows-gnu
#   WIN64_RUSTC     /usr/bin/rustc (Debian's; rustup's rustc is earlier on PATH)
#   WIN64_CARGO     /usr/bin/cargo
#   WIN64_CC        x86_64-w64-mingw32-gcc-posix
#   WIN64_CACHE     ${ROTOR_BEARING_CACHE:-${XDG_CACHE_HOME:-~/.cache}/rotor_bearing}
#   WIN64_SYSROOT   $WIN64_CACHE/win64-std/<release>-<commit> (empty without rustc)
#   WINEPREFIX      $WIN64_CACHE/wine (the Wine tests' prefix, made by setup.sh)
# and defines win64_cargo (Debian's cargo with the cross environment set; its
# target folder is ${WIN64_TARGET_DIR:-target/win64}).

WIN64_TARGET=x86_64-pc-windows-gnu
WIN64_RUSTC=/usr/bin/rustc
WIN64_CARGO=/usr/bin/cargo
WIN64_CC=x86_64-w64-mingw32-gcc-posix
WIN64_CACHE=${ROTOR_BEARING_CACHE:-${XDG_CACHE_HOME:-$HOME/.cache}/rotor_bearing}
WIN64_SYSROOT=""
if [ -x "$WIN64_RUSTC" ]; then
  WIN64_SYSROOT="$WIN64_CACHE/win64-std/$("$WIN64_RUSTC" -vV | awk '
    /^release:/ { r = $2 } /^commit-hash:/ { c = substr($2, 1, 12) } END { print r "-" c }')"
fi
WINEPREFIX="$WIN64_CACHE/wine"
export WIN64_TARGET WIN64_RUSTC WIN64_CARGO WIN64_CC WIN64_CACHE WIN64_SYSROOT WINEPREFIX

# Debian's cargo building for win64 against the cached sysroot: the compiler is
# Debian's (RUSTC), the target crates see the sysroot through
# CARGO_ENCODED_RUSTFLAGS (with --target these flags reach no build script or
# proc macro), bindgen (fmi-sys) gets the MinGW headers, and the build goes to
# its own target directory so that the two compilers never share artifacts.
# The release profile's line tables (debug = 1, for profiling on Linux) are left
# out: Windows debuggers do not read DWARF, and they would double the DLL.
win64_cargo() {
  local gcc_include
  gcc_include=$(dirname "$("$WIN64_CC" -print-libgcc-file-name)")/include
  env -u RUSTFLAGS \
    RUSTC="$WIN64_RUSTC" RUSTDOC=/usr/bin/rustdoc \
    CARGO_ENCODED_RUSTFLAGS="--sysroot=$WIN64_SYSROOT" \
    CARGO_PROFILE_RELEASE_DEBUG=0 \
    CARGO_TARGET_X86_64_PC_WINDOWS_GNU_LINKER="$WIN64_CC" \
    CC_x86_64_pc_windows_gnu="$WIN64_CC" \
    AR_x86_64_pc_windows_gnu=x86_64-w64-mingw32-ar \
    BINDGEN_EXTRA_CLANG_ARGS_x86_64_pc_windows_gnu="-I$gcc_include -I/usr/x86_64-w64-mingw32/include" \
    CARGO_TARGET_DIR="${WIN64_TARGET_DIR:-target/win64}" \
    "$WIN64_CARGO" "$@"
}
