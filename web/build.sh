#!/usr/bin/env bash
# Builds the web version of One More Brick into target/web/ (or $WEB_OUT): a static folder
# any static server or GitHub Pages serves (bash web/serve.sh serves it locally):
#   index.html, onemorebrick.wasm (the game, release without debug information, shrunk by
#   binaryen's wasm-opt -Oz), gl.js (miniquad's loader, taken from the miniquad crate this
#   build used), onemorebrick.js (the game's loader plugin), the icons (drawn by
#   `onemorebrick icon` from the palette) and manifest.webmanifest ("add to home screen").
# Prints the .wasm's size, raw and gzipped, on standard output.
#
# Needs a wasm32 toolchain (web/cargo-wasm.sh says which: the rustup target, or Debian's
# rustc-web, cargo-web and rust-web-src) and binaryen's wasm-opt; the icons are drawn by the
# native onemorebrick command (built in the dev profile, like `cargo test`'s).
set -euo pipefail
cd "$(dirname "$0")/.."

target="${CARGO_TARGET_DIR:-target}"
out="${WEB_OUT:-$target/web}"
wasm_dir="${WASM_TARGET_DIR:-$target/wasm}"

if ! command -v wasm-opt >/dev/null; then
    echo "web/build.sh: wasm-opt not found: install binaryen (apt-get install binaryen)" >&2
    exit 1
fi

echo "web/build.sh: building the game for wasm32-unknown-unknown (profile web)" >&2
WASM_TARGET_DIR="$wasm_dir" bash web/cargo-wasm.sh --profile web -p onemorebrick-app --bin onemorebrick
built="$wasm_dir/wasm32-unknown-unknown/web/onemorebrick.wasm"

# miniquad's JavaScript loader is in the miniquad crate's source (js/gl.js), in the version
# Cargo.lock chose: cargo metadata says where that source is. (macroquad's mq_js_bundle.js
# adds its audio and networking plugins, which this build does not import, and one of them
# throws in strict mode; the game needs only miniquad's.)
miniquad_dir="$(cargo metadata --format-version 1 --locked | python3 -c '
import json, os, sys
packages = json.load(sys.stdin)["packages"]
dirs = [os.path.dirname(p["manifest_path"]) for p in packages if p["name"] == "miniquad"]
if len(dirs) != 1:
    sys.exit("web/build.sh: expected one miniquad package, found %d" % len(dirs))
print(dirs[0])
')"
loader="$miniquad_dir/js/gl.js"
if [ ! -f "$loader" ]; then
    echo "web/build.sh: $loader not found (the miniquad crate's loader)" >&2
    exit 1
fi

rm -rf "$out"
mkdir -p "$out"
# -Oz: smallest; the engine's floating point is untouched (wasm-opt never reassociates or
# fuses f64 arithmetic), so the game plays the same bits. The features are those Rust's
# wasm32-unknown-unknown target uses by default (since Rust 1.82), which every current
# browser has; wasm-opt must be told, or it rejects them.
wasm-opt -Oz --strip-debug --strip-producers \
    --enable-bulk-memory --enable-mutable-globals --enable-nontrapping-float-to-int \
    --enable-sign-ext --enable-reference-types --enable-multivalue \
    "$built" -o "$out/onemorebrick.wasm"
cp "$loader" "$out/gl.js"
cp web/index.html web/onemorebrick.js web/manifest.webmanifest "$out/"

echo "web/build.sh: drawing the icons" >&2
cargo build -q -p onemorebrick-app --bin onemorebrick
native="$target/debug/onemorebrick"
for size in 32 192 512; do
    "$native" icon --size "$size" --out "$out/icon-$size.png" >/dev/null
done
"$native" icon --size 180 --out "$out/apple-touch-icon.png" >/dev/null

raw=$(stat -c %s "$out/onemorebrick.wasm")
gz=$(gzip -9 -c "$out/onemorebrick.wasm" | wc -c)
unshrunk=$(stat -c %s "$built")
echo "wrote $out: onemorebrick.wasm $raw bytes ($((raw / 1024)) KiB; gzipped -9: $gz bytes, $((gz / 1024)) KiB; before wasm-opt $((unshrunk / 1024)) KiB)"
