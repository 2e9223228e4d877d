#!/usr/bin/env python3
"""Writes the example scenes under examples/ (scene format v1, docs/scene-format.md).

Run from the repository root: python3 tools/example_scenes.py
Every scene is checked with `exact2d simulate examples/X.json --until 10` by the CLI tests.
"""

import json
import math
from pathlib import Path

OUT = Path(__file__).resolve().parent.parent / "examples"


def num(x):
    """Rounded to 9 decimals, so files stay short and readable; integers stay integers."""
    x = round(x, 9)
    return int(x) if x == int(x) else x


def pt(x, y):
    return [num(x), num(y)]


def box(x0, y0, x1, y1):
    """Four walls, counter-clockwise from the bottom left corner."""
    c = [(x0, y0), (x1, y0), (x1, y1), (x0, y1)]
    return [{"a": pt(*c[i]), "b": pt(*c[(i + 1) % 4])} for i in range(4)]


def polygon(points):
    return [{"a": pt(*points[i]), "b": pt(*points[(i + 1) % len(points)])} for i in range(len(points))]


def ball(id, pos, vel, radius, **extra):
    """Velocities keep every digit: rounding them would change the speeds by ~1e-10."""
    vel = [v if v != int(v) else int(v) for v in vel]
    return {"id": id, "pos": pt(*pos), "vel": vel, "radius": radius, **extra}


def write(name, scene):
    lines = ["{"]
    keys = [k for k in ("gravity", "ball_ball", "segments", "circles", "balls") if k in scene]
    for n, key in enumerate(keys):
        comma = "," if n + 1 < len(keys) else ""
        value = scene[key]
        if isinstance(value, list) and value and isinstance(value[0], dict):
            items = [f"    {json.dumps(v)}" for v in value]
            lines.append(f'  "{key}": [\n' + ",\n".join(items) + f"\n  ]{comma}")
        else:
            lines.append(f'  "{key}": {json.dumps(value)}{comma}')
    lines.append("}")
    (OUT / name).write_text("\n".join(lines) + "\n")


def sinai():
    """Sinai billiard: the unit square with a disc in the middle; one small ball, chaotic."""
    return {
        "segments": box(0, 0, 1, 1),
        "circles": [{"center": [0.5, 0.5], "radius": 0.25}],
        "balls": [ball(0, (0.1, 0.15), (0.8, 0.6), 0.01)],
    }


def newton_cradle():
    """Five touching balls resting on a floor line, hit by a sixth: the momentum passes
    down the row in one instant and the last ball flies off, then comes back from the wall."""
    row = [ball(i + 1, (6 + i, 1), (0, 0), 0.5) for i in range(5)]
    return {
        "ball_ball": True,
        "segments": box(0, 0.5, 12, 2.5),
        "balls": [ball(0, (2, 1), (1, 0), 0.5)] + row,
    }


def brick_board():
    """A One More Brick board of 7 x 9 cells: square bricks, right triangles, round
    obstacles; 50 balls fired upwards from one point (they pass through each other)."""
    layout = [  # top row first; S square, T triangle, C circle
        "S.T.SCS",
        ".C.S.T.",
        "T.S.C.S",
        ".S.T.S.",
        "C..S..T",
    ]
    segments, circles = box(0, 0, 7, 9), []
    inset, turn = 0.05, 0
    for r, row in enumerate(layout):
        y = 8 - r
        for x, cell in enumerate(row):
            x0, y0, x1, y1 = x + inset, y + inset, x + 1 - inset, y + 1 - inset
            if cell == "S":
                segments += polygon([(x0, y0), (x1, y0), (x1, y1), (x0, y1)])
            elif cell == "T":
                corners = [(x0, y0), (x1, y0), (x1, y1), (x0, y1)]
                corners.pop(turn % 4)  # the right angle is the corner opposite the one left out
                turn += 1
                segments += polygon(corners)
            elif cell == "C":
                circles.append({"center": pt(x + 0.5, y + 0.5), "radius": 0.3})
    balls = []
    for i in range(50):
        angle = math.radians(15 + 150 * i / 49)
        balls.append(ball(i, (3.5, 0.3), (10 * math.cos(angle), 10 * math.sin(angle)), 0.15))
    return {"segments": segments, "circles": circles, "balls": balls}


def pegs_gravity():
    """A closed box under gravity with a triangular lattice of pegs; 20 balls dropped
    from the top, perfectly elastic, colliding with each other too."""
    circles = []
    for r in range(7):
        y = 2 + r
        offset = 0.5 if r % 2 == 0 else 1.0
        x = offset
        while x < 9.6:
            circles.append({"center": pt(x, y), "radius": 0.15})
            x += 1
    balls = [ball(i, (0.5 + 0.45 * i + 0.013 * (i % 3), 11), (0, 0), 0.1) for i in range(20)]
    return {
        "gravity": [0, -9.81],
        "ball_ball": True,
        "segments": box(0, 0, 10, 12),
        "circles": circles,
        "balls": balls,
    }


if __name__ == "__main__":
    OUT.mkdir(exist_ok=True)
    write("sinai.json", sinai())
    write("newton_cradle.json", newton_cradle())
    write("brick_board.json", brick_board())
    write("pegs_gravity.json", pegs_gravity())
