#!/usr/bin/env python3
"""Regenerates the high-precision fixtures of crates/exact2d/tests/high_precision.rs.

    python3 tools/reference/generate.py            # every scene
    python3 tools/reference/generate.py sinai      # one scene

Each scene is simulated by refsim.py (mpmath, 60 significant digits) from initial conditions
that are f64 values, and written to crates/exact2d/tests/data/high_precision_<name>.json.
See README.md for the fields.
"""

from __future__ import annotations

import json
import pathlib
import sys
import time

from mpmath import mp, mpf

import refsim
from refsim import Ball, Circle, Segment, V, World, f64

ROOT = pathlib.Path(__file__).resolve().parents[2]
OUT = ROOT / "crates" / "exact2d" / "tests" / "data"

DIGITS = 30
# Size of the perturbation used to measure how the reference itself amplifies a tiny change of
# the initial state (a finite-difference Lyapunov measurement). Rounding noise at 60 digits is
# ~1e-60, so 1e-45 keeps 15 clean digits; amplification is recorded while the difference
# stays below AMP_LIMIT (linear regime).
PERTURBATION = mpf("1e-45")
AMP_LIMIT = mpf("1e-12")


def box(x0, y0, x1, y1):
    """Four segments, counter-clockwise: bottom, right, top, left."""
    return [
        {"type": "segment", "a": [x0, y0], "b": [x1, y0]},
        {"type": "segment", "a": [x1, y0], "b": [x1, y1]},
        {"type": "segment", "a": [x1, y1], "b": [x0, y1]},
        {"type": "segment", "a": [x0, y1], "b": [x0, y0]},
    ]


# Every number is written as repr(float): Rust parses it to the same f64, and refsim takes that
# f64's exact binary value.
SCENES = {
    # a. Sinai billiard: unit square with a central disc, one small ball.
    "sinai": {
        "description": "Sinai billiard: unit box, static disc r=0.25 at the centre, one ball r=0.01",
        "gravity": ["0.0", "0.0"],
        "colliders": box("0.0", "0.0", "1.0", "1.0")
        + [{"type": "circle", "center": ["0.5", "0.5"], "radius": "0.25"}],
        "balls": [
            {
                "position": ["0.1", "0.2"],
                "velocity": ["0.7071067811865476", "0.3090169943749474"],
                "radius": "0.01",
                "mass": "1.0",
            }
        ],
        "events": 60,
    },
    # b. Four balls of different sizes and masses in a box, with a free-standing segment
    #    (hit on both sides and at its end points).
    "balls": {
        "description": "4 balls (r 0.05..0.1, unequal masses) in a unit box with a free segment",
        "gravity": ["0.0", "0.0"],
        "colliders": box("0.0", "0.0", "1.0", "1.0")
        + [{"type": "segment", "a": ["0.38", "0.52"], "b": ["0.63", "0.43"]}],
        "balls": [
            {"position": ["0.2", "0.2"], "velocity": ["0.83", "0.41"],
             "radius": "0.05", "mass": "1.0"},
            {"position": ["0.76", "0.23"], "velocity": ["-0.37", "0.92"],
             "radius": "0.07", "mass": "2.5"},
            {"position": ["0.24", "0.79"], "velocity": ["0.55", "-0.71"],
             "radius": "0.08", "mass": "0.7"},
            {"position": ["0.74", "0.77"], "velocity": ["-0.66", "-0.29"],
             "radius": "0.1", "mass": "4.0"},
        ],
        "events": 60,
    },
    # c. Balls under gravity in a closed box with pegs and a free segment: ball-peg and
    #    ball-end-point contacts are quartics in time.
    "gravity": {
        "description": "3 balls under gravity (0,-9.81) in a closed 2x1.5 box with 4 pegs "
        "and a free segment",
        "gravity": ["0.0", "-9.81"],
        "colliders": box("0.0", "0.0", "2.0", "1.5")
        + [
            {"type": "circle", "center": ["0.5", "0.6"], "radius": "0.1"},
            {"type": "circle", "center": ["1.0", "0.9"], "radius": "0.12"},
            {"type": "circle", "center": ["1.5", "0.55"], "radius": "0.1"},
            {"type": "circle", "center": ["1.05", "0.33"], "radius": "0.08"},
            {"type": "segment", "a": ["1.2", "0.75"], "b": ["1.35", "1.1"]},
        ],
        "balls": [
            {"position": ["0.31", "0.93"], "velocity": ["1.9", "1.2"],
             "radius": "0.07", "mass": "1.0"},
            {"position": ["1.62", "1.2"], "velocity": ["-2.4", "-0.6"],
             "radius": "0.08", "mass": "1.6"},
            {"position": ["0.8", "0.2"], "velocity": ["2.3", "3.1"],
             "radius": "0.06", "mass": "0.6"},
        ],
        "events": 40,
    },
}


def build(scene) -> World:
    colliders = []
    for c in scene["colliders"]:
        if c["type"] == "segment":
            colliders.append(Segment(V(*map(f64, c["a"])), V(*map(f64, c["b"]))))
        else:
            colliders.append(Circle(V(*map(f64, c["center"])), f64(c["radius"])))
    balls = [
        Ball(V(*map(f64, b["position"])), V(*map(f64, b["velocity"])), f64(b["radius"]),
             f64(b["mass"]))
        for b in scene["balls"]
    ]
    return World(V(*map(f64, scene["gravity"])), colliders, balls)


def dec(x) -> str:
    """A 30-significant-digit decimal string that Rust's f64 parser accepts."""
    if x == 0:
        return "0.0"
    s = mp.nstr(x, DIGITS, min_fixed=-6, max_fixed=9)
    return s if any(ch in s for ch in ".e") else s + ".0"


def distance(ev_a, st_a, ev_b, st_b):
    d = abs(ev_a[0] - ev_b[0])
    for (pa, _), (pb, _) in zip(st_a, st_b):
        d = max(d, (pa - pb).norm())
    return d


def dump(fixture) -> str:
    """JSON with one collider, ball or event per line."""
    lines = ["{"]
    items = list(fixture.items())
    for n, (key, value) in enumerate(items):
        comma = "," if n + 1 < len(items) else ""
        if isinstance(value, list) and value and isinstance(value[0], dict):
            lines.append(f"  {json.dumps(key)}: [")
            for m, item in enumerate(value):
                tail = "," if m + 1 < len(value) else ""
                lines.append(f"    {json.dumps(item)}{tail}")
            lines.append(f"  ]{comma}")
        else:
            lines.append(f"  {json.dumps(key)}: {json.dumps(value)}{comma}")
    lines.append("}")
    return "\n".join(lines) + "\n"


def generate(name, scene):
    started = time.time()
    n = scene["events"]
    base = refsim.run(build(scene), n)
    perturbed_world = build(scene)
    refsim.perturb(perturbed_world, PERTURBATION)
    perturbed = refsim.run(perturbed_world, n)
    events = []
    for k, (ev, _margin, st) in enumerate(base):
        t, kind, i, j, feature = ev
        amp = None
        if k < len(perturbed) and perturbed[k][0][1:] == ev[1:]:
            d = distance(ev, st, perturbed[k][0], perturbed[k][2])
            if d < AMP_LIMIT:
                amp = d / PERTURBATION
        record = {"k": k + 1, "time": dec(t), "kind": kind}
        if kind == "contact":
            record.update({"ball": i, "collider": j, "feature": feature})
        else:
            record.update({"a": i, "b": j})
        record["balls"] = [
            {"p": [dec(p.x), dec(p.y)], "v": [dec(v.x), dec(v.y)]} for p, v in st
        ]
        record["amplification"] = dec(amp) if amp is not None else None
        events.append(record)
    fixture = {
        "generator": "tools/reference/generate.py (mpmath, mp.dps = 60)",
        "name": name,
        "description": scene["description"],
        "gravity": scene["gravity"],
        "colliders": scene["colliders"],
        "balls": scene["balls"],
        "events": events,
    }
    OUT.mkdir(parents=True, exist_ok=True)
    path = OUT / f"high_precision_{name}.json"
    path.write_text(dump(fixture))
    kinds = {}
    for e in events:
        key = e["kind"] if e["kind"] == "ball_contact" else e["feature"]
        kinds[key] = kinds.get(key, 0) + 1
    print(f"{name}: {len(events)} events {kinds}, {time.time() - started:.1f} s -> {path}")
    for e in events:
        if e["k"] % 10 == 0:
            print(f"  event {e['k']:3}: t = {e['time'][:14]}  amplification {e['amplification']}")


def main(argv):
    names = argv[1:] or list(SCENES)
    for name in names:
        generate(name, SCENES[name])


if __name__ == "__main__":
    main(sys.argv)
