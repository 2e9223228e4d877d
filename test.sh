#!/usr/bin/env bash
# Every test of the repository: the Rust workspace (`cargo test`: the engine, the CLI, the
# rules and the game), then the Python packages: their pinned test packages in a venv
# (`python/requirements-test.txt`), the wheel built with maturin and installed there, and
# pytest on `python/tests`.
#
# The Python half needs python3 (3.9 or newer, with venv) and PyPI; without python3 it says
# SKIPPED, unless CI is set, when that is a failure.
set -euo pipefail
cd "$(dirname "$0")"

cargo test

target="${CARGO_TARGET_DIR:-target}"
if ! python3 -c 'import sys, venv, ensurepip; sys.exit(sys.version_info < (3, 9))' 2>/dev/null; then
    if [ -n "${CI:-}" ]; then
        echo "test.sh: the Python tests need python3 >= 3.9 with venv" >&2
        exit 1
    fi
    echo "SKIPPED: the Python tests (no python3 >= 3.9 with venv)" >&2
    exit 0
fi
mkdir -p "$target"
venv="$(cd "$target" && pwd)/py-venv"
if [ ! -x "$venv/bin/python" ]; then
    python3 -m venv "$venv"
fi
"$venv/bin/python" -m pip install --quiet --disable-pip-version-check -r python/requirements-test.txt
rm -rf "$target/wheels"
"$venv/bin/maturin" build --quiet --release --manifest-path python/Cargo.toml --out "$target/wheels"
"$venv/bin/python" -m pip install --quiet --disable-pip-version-check --no-deps --force-reinstall "$target"/wheels/exact2d-*.whl
# From python/ with `-p no:cacheprovider`: the tests import the installed wheel (python/src
# is not on the path) and leave no cache behind.
(cd python && "$venv/bin/python" -m pytest -q -p no:cacheprovider tests)
