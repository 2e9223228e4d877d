"""Handles are integers never reused: removal makes a handle unknown, others stay valid."""

import exact2d
import pytest
from conftest import box_world


def test_handles_after_removal():
    world = box_world()
    a = world.add_ball((1.0, 1.0), (0.0, 0.0), 0.2)
    b = world.add_ball((3.0, 1.0), (0.0, 0.0), 0.2)
    c = world.add_ball((5.0, 1.0), (1.0, 0.0), 0.2)
    world.remove_ball(b)
    assert not world.has_ball(b) and world.has_ball(a) and world.has_ball(c)
    with pytest.raises(exact2d.UnknownHandleError, match=f"no ball with handle {b}"):
        world.position(b)
    with pytest.raises(exact2d.UnknownHandleError):
        world.remove_ball(b)
    d = world.add_ball((3.0, 1.0), (0.0, 0.0), 0.2)
    assert d not in (a, b, c)  # the engine reuses b's slot, Python never reuses b's handle
    assert sorted(world.handles()) == sorted([a, c, d])
    assert world.position(a) == (1.0, 1.0)
    assert world.position(d) == (3.0, 1.0)
    # Events name balls by their Python handles.
    event = world.step()
    assert event.ball == c


def test_collider_removal_lets_balls_through():
    world = exact2d.World(gravity=(0.0, 0.0))
    wall = world.add_segment((5.0, -1.0), (5.0, 1.0))
    far = world.add_segment((20.0, -1.0), (20.0, 1.0))
    ball = world.add_ball((0.0, 0.0), (1.0, 0.0), 0.5)
    world.remove_collider(wall)
    with pytest.raises(exact2d.UnknownHandleError, match=f"no collider with handle {wall}"):
        world.collider(wall)
    event = world.step()
    assert event.collider == far and event.time == pytest.approx(19.5)
    assert list(world.collider_handles()) == [far]
    assert world.ball(ball)["velocity"] == (-1.0, 0.0)
