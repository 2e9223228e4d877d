"""The type stubs match the native module: mypy's stubtest compares every name, signature and
default of ``exact2d/_native.pyi`` with what the module exposes at run time."""

import subprocess
import sys


def test_the_stubs_match_the_native_module():
    result = subprocess.run(
        [sys.executable, "-m", "mypy.stubtest", "exact2d._native"],
        capture_output=True,
        text=True,
    )
    assert result.returncode == 0, result.stdout + result.stderr
