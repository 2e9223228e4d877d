"""Shared scenes for the tests."""

import math

import exact2d
import numpy as np


def box_world(width=10.0, height=6.0, gravity=(0.0, 0.0)):
    """A closed box [0, width] x [0, height] of four elastic segments (handles 0 to 3)."""
    world = exact2d.World(gravity=gravity)
    corners = [(0.0, 0.0), (width, 0.0), (width, height), (0.0, height)]
    for a, b in zip(corners, corners[1:] + corners[:1]):
        world.add_segment(a, b)
    return world


def gas_scene(n=40, seed=1, width=10.0, radius=0.1):
    """A scene dict: n balls on a lattice in a box, random velocities (seeded)."""
    rng = np.random.default_rng(seed)
    side = int(np.ceil(np.sqrt(n)))
    spacing = width / (side + 1)
    balls = []
    for i in range(n):
        x, y = (1 + i % side) * spacing, (1 + i // side) * spacing
        vx, vy = rng.normal(size=2)
        balls.append({"id": i, "pos": [x, y], "vel": [vx, vy], "radius": radius})
    corners = [[0.0, 0.0], [width, 0.0], [width, width], [0.0, width]]
    segments = [{"a": a, "b": b} for a, b in zip(corners, corners[1:] + corners[:1])]
    return {"ball_ball": True, "segments": segments, "balls": balls}


def periodic_lattice(n, radius, eta, seed):
    """n disks on a square lattice filling a square periodic box of packing fraction eta,
    velocities drawn from a normal distribution (seeded): (positions, velocities, side)."""
    side = math.sqrt(n * math.pi * radius**2 / eta)
    per_row = math.ceil(math.sqrt(n))
    spacing = side / per_row
    k = np.arange(n)
    positions = np.stack([(k % per_row + 0.5) * spacing, (k // per_row + 0.5) * spacing], axis=1)
    velocities = np.random.default_rng(seed).normal(size=(n, 2))
    return positions, velocities, side


def run_columns(world, t):
    """The events of advancing `world` to `t`, as columns copied out of the world's buffers."""
    events = world.advance_to_collect(t)
    return {k: v.copy() for k, v in events.items()}


def assert_same_columns(a, b):
    """Asserts two runs' event columns are equal, bit for bit."""
    assert a.keys() == b.keys()
    for k in a:
        np.testing.assert_array_equal(a[k], b[k], err_msg=k)
