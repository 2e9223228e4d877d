"""Scene dicts to JSON text for the Rust reader (``World.from_scene``, ``run_many``).

NumPy arrays and scalars become lists and numbers. JSON cannot spell NaN or infinity, so a
non-finite number is refused here, by its path in the scene, with the words of the Rust
validator (``balls[0].pos[1] must be finite``).
"""

import json
import math

from exact2d._errors import SceneError


def _plain(value, path):
    if hasattr(value, "tolist") and not isinstance(value, (str, bytes)):
        value = value.tolist()
    if isinstance(value, dict):
        return {k: _plain(v, f"{path}.{k}" if path else str(k)) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [_plain(v, f"{path}[{i}]") for i, v in enumerate(value)]
    if isinstance(value, float) and not math.isfinite(value):
        raise SceneError(f"{path} must be finite")
    return value


def dumps(scene: dict) -> str:
    """The JSON text of a scene dict."""
    return json.dumps(_plain(scene, ""))
