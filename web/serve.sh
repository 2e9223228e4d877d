#!/usr/bin/env bash
# Serves the web build (target/web/, made by web/build.sh) on http://127.0.0.1:PORT/
# (default 8000), with the types browsers insist on (.wasm as application/wasm for
# streaming compilation, the manifest as application/manifest+json). Ctrl-C stops it.
# Usage: bash web/serve.sh [PORT]
set -euo pipefail
cd "$(dirname "$0")/.."
dir="${WEB_OUT:-${CARGO_TARGET_DIR:-target}/web}"
port="${1:-8000}"
if [ ! -f "$dir/index.html" ]; then
    echo "web/serve.sh: $dir/index.html not found: run bash web/build.sh first" >&2
    exit 1
fi
echo "serving $dir on http://127.0.0.1:$port/" >&2
exec python3 - "$dir" "$port" <<'PY'
import functools, http.server, sys
directory, port = sys.argv[1], int(sys.argv[2])
class Handler(http.server.SimpleHTTPRequestHandler):
    extensions_map = {
        **http.server.SimpleHTTPRequestHandler.extensions_map,
        ".wasm": "application/wasm",
        ".webmanifest": "application/manifest+json",
        ".js": "text/javascript",
    }
handler = functools.partial(Handler, directory=directory)
http.server.ThreadingHTTPServer(("127.0.0.1", port), handler).serve_forever()
PY
