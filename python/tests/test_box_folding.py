"""A ball in a box of elastic walls: its position at any time is its free flight folded back
into the box (the method of images), an answer that owes nothing to the engine."""

import math

import numpy as np
import pytest
from conftest import box_world


def fold(u, low, high):
    """Free-flight coordinate u folded into [low, high] by mirror images."""
    width = high - low
    s = math.fmod(u - low, 2 * width)
    if s < 0:
        s += 2 * width
    return low + (s if s <= width else 2 * width - s)


def crossings(u0, u, low, high):
    """How many walls the unfolded path from u0 to u crosses."""
    width = high - low
    return abs(math.floor((u - low) / width) - math.floor((u0 - low) / width))


@pytest.mark.parametrize("velocity", [(3.1, 1.7), (-7.3, 0.9), (11.3, -5.9)])
def test_positions_follow_mirror_folding(velocity):
    width, height, r = 10.0, 6.0, 0.25
    world = box_world(width, height)
    x0, y0 = 2.0, 3.0
    ball = world.add_ball((x0, y0), velocity, r)
    vx, vy = velocity
    for t in [0.5, 1.0, 7.25, 20.0, 100.0]:
        world.advance_to(t)
        x, y = world.position(ball)
        assert x == pytest.approx(fold(x0 + vx * t, r, width - r), abs=1e-9)
        assert y == pytest.approx(fold(y0 + vy * t, r, height - r), abs=1e-9)


def test_collected_events_count_every_wall_crossing_and_reverse_the_normal_velocity():
    width, height, r = 10.0, 6.0, 0.25
    world = box_world(width, height)
    vx, vy = 13.7, -4.3
    ball = world.add_ball((2.0, 3.0), (vx, vy), r, mass=2.0)
    t = 50.0
    events = world.advance_to_collect(t)
    expected = crossings(2.0, 2.0 + vx * t, r, width - r) + crossings(
        3.0, 3.0 + vy * t, r, height - r
    )
    assert len(events["time"]) == expected
    assert np.all(events["kind"] == 0)
    assert np.all(events["ball"] == ball)
    assert np.all(np.diff(events["time"]) > 0)
    # Elastic: each bounce reverses the normal velocity, impulse 2 m |v.n|.
    speeds = np.where(np.abs(events["normal"][:, 0]) == 1.0, abs(vx), abs(vy))
    np.testing.assert_allclose(events["impulse"], 2 * 2.0 * speeds, rtol=1e-12)
    np.testing.assert_allclose(events["normal_speed"], speeds, rtol=1e-12)
    # Contacts happen on the walls, at the ball's centre's distance r.
    x, y = events["point"][:, 0], events["point"][:, 1]
    on_wall = np.isclose(x, 0) | np.isclose(x, width) | np.isclose(y, 0) | np.isclose(y, height)
    assert on_wall.all()


def test_step_until_returns_events_one_by_one_then_none():
    world = box_world()
    world.add_ball((5.0, 3.0), (1.0, 0.0), 0.5)
    event = world.step_until(10.0)
    assert event.kind == "contact" and event.time == pytest.approx(4.5)
    assert event.normal == (-1.0, 0.0) and event.feature == "segment"
    assert world.step_until(10.0) is None
    assert world.time == 10.0
