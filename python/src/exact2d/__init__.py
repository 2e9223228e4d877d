"""exact2d: exact, event-driven 2D physics for balls.

There are no time steps: balls move in closed form (straight lines, or parabolas under
gravity) and every collision, against segments, their end points, static circles and other
balls, is solved at its exact time of impact. Nothing tunnels at any speed, nothing is pushed
apart after the fact, and the same inputs give the same bits on every run.

>>> import exact2d
>>> world = exact2d.World(gravity=(0.0, 0.0))
>>> wall = world.add_segment((10.0, -5.0), (10.0, 5.0))
>>> ball = world.add_ball((0.0, 0.0), (1024.0, 0.0), 0.5)
>>> event = world.step()
>>> event.kind, event.time == 9.5 / 1024, event.collider == wall
('contact', True, True)

Scaling out: ``run_many(scenes, until, threads)`` runs independent worlds on every core of
one machine. Worlds pickle (their full state, as JSON), so they can be shipped to other
processes with ``multiprocessing`` or to a cluster with Ray or Dask (each task unpickles a
world, runs it with ``advance_to``, and returns arrays).
"""

from exact2d._errors import (
    Exact2dError,
    InvalidInputError,
    OverlapError,
    SceneError,
    StalledError,
    TimeBeforeNowError,
    UnknownHandleError,
)
from exact2d._native import EVENT_KINDS, CastHit, Event, World, run_many

Error = Exact2dError

try:
    from importlib.metadata import version as _version

    __version__ = _version("exact2d")
except Exception:  # not installed from a wheel (a source tree on the path)
    __version__ = "0.1.0"

__all__ = [
    "World",
    "Event",
    "CastHit",
    "run_many",
    "EVENT_KINDS",
    "Error",
    "Exact2dError",
    "InvalidInputError",
    "OverlapError",
    "SceneError",
    "StalledError",
    "TimeBeforeNowError",
    "UnknownHandleError",
]
