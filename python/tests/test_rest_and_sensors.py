"""Resting, sleeping and sensors from Python, against analytic answers."""

import math

import exact2d
import pytest


def test_a_bouncing_ball_comes_to_rest_at_the_accumulation_time_and_sleeps():
    g, e, r, h = 9.81, 0.8, 0.25, 2.0
    world = exact2d.World(gravity=(0.0, -g))
    world.sleeping = True
    floor = world.add_segment((-5.0, 0.0), (5.0, 0.0))
    ball = world.add_ball((0.0, r + h), (0.0, 0.0), r, restitution=e)
    # Falls for t0 = sqrt(2h/g), then hops of 2 e^k v0 / g: they add up to a finite time.
    t0 = math.sqrt(2 * h / g)
    rest = t0 + 2 * e * (g * t0) / (g * (1 - e))
    world.advance_to(rest + 1.0)
    state = world.ball(ball)
    assert state["position"][1] == pytest.approx(r, abs=1e-9)
    assert state["velocity"] == (0.0, 0.0)
    assert state["asleep"] and world.sleeping_count == 1
    assert world.ball_holders(ball) == [("collider", floor)]
    assert world.ball_asleep_since(ball) == pytest.approx(rest, abs=1e-6)
    assert world.next_event_time() is None  # asleep, it costs nothing more
    world.set_velocity(ball, (0.0, 1.0))  # woken by a new velocity
    assert not world.ball(ball)["asleep"]


def test_sensor_entry_and_exit_times():
    world = exact2d.World(gravity=(0.0, 0.0))
    sensor = world.add_circle((10.0, 0.0), 2.0, sensor=True)
    ball = world.add_ball((0.0, 0.0), (2.0, 0.0), 0.5)
    enter = world.step()
    # Overlap begins when the centres are 2.5 apart (x = 7.5) and ends at x = 12.5.
    assert (enter.kind, enter.collider, enter.ball) == ("sensor_enter", sensor, ball)
    assert enter.time == pytest.approx(3.75) and enter.impulse == 0.0 and enter.normal is None
    assert world.ball_sensors(ball) == [sensor]
    leave = world.step()
    assert leave.kind == "sensor_exit" and leave.time == pytest.approx(6.25)
    assert world.ball_sensors(ball) == []
    assert world.velocity(ball) == (2.0, 0.0)  # passed through
    assert world.event_counts()["sensor_enters"] == 1


def test_groups_let_balls_pass_through_each_other_but_not_walls():
    world = exact2d.World(gravity=(0.0, 0.0))
    wall = world.add_segment((10.0, -5.0), (10.0, 5.0))
    ghosts = (1, ~1 & 0xFFFFFFFF)
    a = world.add_ball((0.0, 0.0), (1.0, 0.0), 0.5, groups=ghosts)
    world.add_ball((3.0, 0.0), (-1.0, 0.0), 0.5, groups=ghosts)
    event = world.step()
    assert (event.kind, event.ball, event.collider) == ("contact", a, wall)
    assert event.time == pytest.approx(9.5)


def test_cast_ball_and_bounce_path_follow_the_reflection_law():
    world = exact2d.World(gravity=(0.0, 0.0))
    world.add_segment((0.0, 0.0), (10.0, 0.0))
    top = world.add_segment((0.0, 4.0), (10.0, 4.0))
    hit = world.cast_ball((1.0, 2.0), (1.0, 1.0), 0.5)
    assert hit.collider == top and hit.time == pytest.approx(1.5)
    assert hit.position == pytest.approx((2.5, 3.5)) and hit.normal == (0.0, -1.0)
    path = world.bounce_path((1.0, 2.0), (1.0, 1.0), 0.5, 3)
    # Between the lines y = 0.5 and y = 3.5 a 45-degree path advances 3 in x per bounce.
    assert [p.position[0] for p in path] == pytest.approx([2.5, 5.5, 8.5])
    assert world.cast_ball((1.0, 2.0), (1.0, 1.0), 0.5, max_time=1.0) is None


def test_a_sliding_stack_takes_a_strike_from_above_as_one_body():
    # Two balls stacked on a frictionless floor slide together as a group; a ball dropped
    # fast onto the top one bounces off the stack as off the floor (the pair's restitution
    # times its speed) and the stack slides on, held: one rigid hit, counted.
    g, r, u, e = 9.81, 0.2, 0.5, 0.5
    world = exact2d.World(gravity=(0.0, -g))
    world.sleeping = True
    world.add_segment((-100.0, 0.0), (100.0, 0.0))
    world.add_ball((0.0, r), (u, 0.0), r, restitution=e)
    top = world.add_ball((0.0, 3 * r), (u, 0.0), r, restitution=e)
    world.advance_to(0.5)
    t0 = world.time
    h, w0 = 1.0, 2.0
    striker = world.add_ball((u * t0, 5 * r + h), (u, -w0), r, restitution=e)
    fall = 2 * h / (w0 + math.sqrt(w0 * w0 + 2 * g * h))
    w = w0 + g * fall
    event = world.step_until(t0 + 1.0)
    while event is not None and event.kind != "ball_contact":
        event = world.step_until(t0 + 1.0)
    assert event is not None and event.time == pytest.approx(t0 + fall, abs=1e-12)
    assert world.event_counts()["rigid_hits"] == 1
    assert world.velocity(striker) == pytest.approx((u, e * e * w), abs=1e-12)
    assert world.velocity(top) == pytest.approx((u, 0.0), abs=1e-12)
