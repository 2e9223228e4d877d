#!/usr/bin/env bash
# Runs `cargo build` for wasm32-unknown-unknown with whichever toolchain this machine has:
#
# - the rustup toolchain, where its wasm32-unknown-unknown standard library is installed
#   (`rustup target add wasm32-unknown-unknown`);
# - otherwise Debian's `rustc-web`, `cargo-web` and `rust-web-src` packages, which build the
#   standard library for wasm32 from source (`-Zbuild-std`), linked by the `rust-lld` that
#   the rustup toolchain ships.
#
# Usage: bash web/cargo-wasm.sh [cargo build arguments...]   (for example `--release -p X`)
# The build goes to $WASM_TARGET_DIR (default target/wasm), apart from the native builds:
# the two routes use different compilers, which must not share build scripts' outputs.
# Prints the chosen route on standard error.
set -euo pipefail
cd "$(dirname "$0")/.."

target_dir="${WASM_TARGET_DIR:-${CARGO_TARGET_DIR:-target}/wasm}"

if command -v rustup >/dev/null \
    && rustup target list --installed 2>/dev/null | grep -qx wasm32-unknown-unknown; then
    echo "cargo-wasm: the rustup toolchain's wasm32-unknown-unknown target" >&2
    exec cargo build --target wasm32-unknown-unknown --target-dir "$target_dir" "$@"
fi

debian_rustc=/usr/bin/rustc
debian_cargo=/usr/bin/cargo
if [ ! -x "$debian_rustc" ] || [ ! -x "$debian_cargo" ] \
    || ! ls -d /usr/lib/rustlib/src/rust/library >/dev/null 2>&1; then
    echo "cargo-wasm: no wasm32 toolchain: either run" \
        "'rustup target add wasm32-unknown-unknown', or install Debian's rustc-web," \
        "cargo-web and rust-web-src packages (apt-get install rustc-web cargo-web rust-web-src)" >&2
    exit 1
fi

# rust-lld: on the PATH already, or the one inside the rustup toolchain.
if ! command -v rust-lld >/dev/null; then
    sysroot="$(rustc --print sysroot 2>/dev/null || true)"
    lld_dir="$sysroot/lib/rustlib/x86_64-unknown-linux-gnu/bin"
    if [ -z "$sysroot" ] || [ ! -x "$lld_dir/rust-lld" ]; then
        echo "cargo-wasm: rust-lld not found (on the PATH or in the rustup toolchain" \
            "under lib/rustlib/x86_64-unknown-linux-gnu/bin)" >&2
        exit 1
    fi
    export PATH="$lld_dir:$PATH"
fi

echo "cargo-wasm: Debian's rustc-web ($("$debian_rustc" --version)) with -Zbuild-std" >&2
export RUSTC="$debian_rustc"
export RUSTC_BOOTSTRAP=1
exec "$debian_cargo" build --target wasm32-unknown-unknown --target-dir "$target_dir" \
    -Zbuild-std=std,panic_abort "$@"
