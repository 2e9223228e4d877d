"""Rolling and sliding on rough segments (``crates/exact2d/src/dynamics/rolling.rs``), checked
through the bindings against closed forms worked out here, and rolling resistance through
validation, pickles and scenes.

A ball of radius ``r`` and inertia factor ``k`` on a line with gravity ``g_t`` along it and
``g_n`` into it: sliding, kinetic friction ``mu g_n`` opposes the contact point's slip and
spins the ball up at ``mu g_n / (k r)``; the slip vanishes and the ball rolls, at
``dv/dt = g_t / (1 + k)`` while ``|g_t| k / (1 + k) <= mu g_n``; rolling resistance ``c``
takes ``c g_n`` of its speed a second until it stops. A pair's ``mu`` and ``c`` are the
geometric means of its two values. Every transition happens inside the engine, at its
analytic time, without an event.
"""

import json
import math
import pickle
import re

import exact2d
import numpy as np
import pytest

G = 10.0
R = 0.5  # every disk here: radius 0.5, k = 1/2 (a uniform disk, the default), mass 1


def close(a, b, tol=1e-12):
    return abs(a - b) <= tol * (1.0 + abs(b))


def floor_world(friction, rolling_resistance=0.0):
    """Gravity (0, -10) and a rough floor from x = -50 to x = 50."""
    world = exact2d.World(gravity=(0.0, -G))
    world.add_segment((-50.0, 0.0), (50.0, 0.0), friction=friction, rolling_resistance=rolling_resistance)
    return world


def disk_on_floor(world, x, v, spin, friction, rolling_resistance=0.0):
    """A uniform disk of radius 0.5 resting on the floor at x."""
    return world.add_ball(
        (x, R), (v, 0.0), R, spin=spin, friction=friction, rolling_resistance=rolling_resistance
    )


@pytest.mark.parametrize("ball_mu, floor_mu", [(0.2, 0.2), (0.1, 0.4), (0.4, 0.1)])
def test_a_disk_thrown_without_spin_slides_then_rolls_from_the_analytic_time(ball_mu, floor_mu):
    # mu = sqrt(ball_mu floor_mu) = 0.2. Sliding: v = 3 - mu g t = 3 - 2t, spin = -mu g t /
    # (k r) = -8t (clockwise, going right), slip v - (-spin) r = 3 - 6t: it sticks at t = 0.5,
    # at v = 2, spin -4, x = 3 (0.5) - (0.5) 2 (0.25) = 1.25, and rolls on at 2 (no resistance).
    world = floor_world(floor_mu)
    ball = disk_on_floor(world, 0.0, 3.0, 0.0, ball_mu)
    assert world.advance_to(0.25) == 0
    (x, y), (vx, vy) = world.position(ball), world.velocity(ball)
    assert close(x, 3.0 * 0.25 - 0.5 * 2.0 * 0.25**2) and close(vx, 2.5) and close(world.spin(ball), -2.0)
    assert (y, vy) == (R, 0.0)
    assert world.ball(ball)["support"] == 0
    assert world.advance_to(0.5) == 0
    assert close(world.position(ball)[0], 1.25) and close(world.velocity(ball)[0], 2.0)
    assert close(world.spin(ball), -4.0)
    assert world.advance_to(1.5) == 0
    assert close(world.position(ball)[0], 1.25 + 2.0)
    assert close(world.velocity(ball)[0], 2.0) and close(world.spin(ball), -4.0)
    # Rolling: the contact point is at rest.
    assert abs(world.velocity(ball)[0] + world.spin(ball) * R) < 1e-12
    # The angle turned: -4 t^2 while sliding (-1 at 0.5), then -4 a second: -5 at 1.5.
    assert close(world.angle(ball), math.remainder(-5.0, 2.0 * math.pi))
    # Energy: 9/2 thrown; rolling, m v^2 / 2 + k m r^2 w^2 / 2 = 2 + 1. Friction took 1.5.
    assert close(float(world.kinetic_energies()[0]), 3.0)
    assert world.event_counts()["contacts"] == 0


def test_friction_on_one_side_only_leaves_the_floor_frictionless():
    # No friction unless both have some: the rough ball slides on at 3, its spin untouched.
    world = floor_world(0.0)
    ball = disk_on_floor(world, 0.0, 3.0, 5.0, 0.2)
    world.advance_to(2.0)
    assert world.position(ball)[0] == 6.0 and world.velocity(ball)[0] == 3.0 and world.spin(ball) == 5.0


@pytest.mark.parametrize("ball_c, floor_c", [(0.05, 0.05), (0.025, 0.1)])
def test_rolling_resistance_stops_a_rolling_disk_at_its_analytic_time_and_place(ball_c, floor_c):
    # Rolling at 2 (spin -4, the contact point at rest), c = sqrt(ball_c floor_c) = 0.05: it
    # loses c g = 0.5 a second, x = 1 + 2t - t^2/4, and stops at t = 4, 4 further on.
    world = floor_world(0.2, floor_c)
    ball = disk_on_floor(world, 1.0, 2.0, -4.0, 0.2, ball_c)
    assert world.advance_to(2.0) == 0
    assert close(world.position(ball)[0], 1.0 + 4.0 - 1.0)
    assert close(world.velocity(ball)[0], 1.0) and close(world.spin(ball), -2.0)
    assert world.advance_to(4.0) == 0
    stopped = world.position(ball)
    assert close(stopped[0], 5.0) and stopped[1] == R
    assert world.velocity(ball) == (0.0, 0.0) and world.spin(ball) == 0.0
    # It stays: no event ever after.
    assert world.advance_to(1000.0) == 0
    assert world.position(ball) == stopped
    assert world.next_event_time() is None


@pytest.mark.parametrize("tan, rolls", [(0.5, True), (0.7, False)])
def test_a_disk_on_a_rough_incline_rolls_below_the_critical_slope_and_slides_above(tan, rolls):
    # mu = 0.2 holds a rolling disk on slopes up to tan a = mu (1 + 1/k) = 0.6: at tan a = 0.5
    # it rolls down at (2/3) g sin a, at 0.7 it slides at g (sin a - mu cos a).
    cos = 1.0 / math.hypot(1.0, tan)
    sin = tan * cos  # tan a = 0.5: sin a = 1 / sqrt(5), the rolling distance g / (3 sqrt(5))
    down, normal = np.array([cos, -sin]), np.array([sin, cos])
    world = exact2d.World(gravity=(0.0, -G))
    world.add_segment((0.0, 0.0), tuple(100.0 * down), friction=0.2)
    start = 5.0 * down + R * normal
    ball = world.add_ball(tuple(start), (0.0, 0.0), R, friction=0.2)
    assert world.advance_to(1.0) == 0
    accel = 2.0 / 3.0 * G * sin if rolls else G * (sin - 0.2 * cos)
    moved = np.array(world.position(ball)) - start
    assert abs(moved @ down - 0.5 * accel) < 1e-9
    assert abs(moved @ normal) < 1e-12  # on the slope all along
    speed = np.array(world.velocity(ball)) @ down
    assert close(speed, accel)
    # Rolling, the spin is -v / r (clockwise going down to the right); sliding, friction spins
    # it up at mu g cos a / (k r) only.
    assert close(world.spin(ball), -speed / R if rolls else -0.2 * G * cos / (0.5 * R))


@pytest.mark.parametrize("sleeping", [False, True])
def test_a_spin_given_to_a_resting_rough_disk_sets_it_sliding_then_rolling(sleeping):
    # Spin -4 at rest on mu = 0.5: the slip 0 - (-4)(0.5) = 2 drives it forward at mu g = 5
    # while the spin slows at mu g / (k r) = 20; the slip falls at 15 and vanishes after
    # 2/15 s, at v = 2/3, spin -4/3; x = 5 t^2 / 2 until then, 2/3 a second after.
    world = floor_world(0.5)
    world.sleeping = sleeping
    ball = disk_on_floor(world, 0.0, 0.0, 0.0, 0.5)
    world.advance_to(1.0)
    assert world.ball(ball)["asleep"] == sleeping
    world.set_spin(ball, -4.0)
    assert not world.ball(ball)["asleep"]
    assert world.advance_to(3.0) == 0
    t = 2.0 / 15.0
    assert close(world.velocity(ball)[0], 2.0 / 3.0) and close(world.spin(ball), -4.0 / 3.0)
    assert close(world.position(ball)[0], 2.5 * t * t + 2.0 / 3.0 * (2.0 - t))


def adding(method, **kwargs):
    """A call of `method` adding a body at the origin with `kwargs`."""
    calls = {
        "ball": lambda w: w.add_ball((0, 0), (0, 0), 1.0, **kwargs),
        "segment": lambda w: w.add_segment((0, 0), (1, 0), **kwargs),
        "circle": lambda w: w.add_circle((0, 0), 1.0, **kwargs),
    }
    return calls[method]


@pytest.mark.parametrize("method", ["ball", "segment", "circle"])
@pytest.mark.parametrize("value, shown", [(-1.0, "-1"), (math.inf, "inf"), (math.nan, "NaN")])
def test_a_bad_rolling_resistance_raises_invalid_input_naming_the_range(method, value, shown):
    world = exact2d.World()
    message = rf"^rolling resistance must be finite and >= 0 \(got {shown}\)$"
    with pytest.raises(exact2d.InvalidInputError, match=message) as info:
        adding(method, rolling_resistance=value)(world)
    assert isinstance(info.value, ValueError)
    assert world.ball_count == 0 and world.collider_count == 0


def test_add_balls_takes_a_rolling_resistance_column_all_or_nothing():
    world = exact2d.World(gravity=(0.0, 0.0))
    n = 4
    positions = np.stack([np.arange(n) * 3.0, np.zeros(n)], axis=1)
    cs = np.linspace(0.0, 0.3, n)
    handles = world.add_balls(positions, np.zeros((n, 2)), np.full(n, 0.5), rolling_resistances=cs)
    assert [world.ball(h)["rolling_resistance"] for h in handles] == list(cs)
    plain = world.add_balls([[20.0, 0.0]], [[0.0, 0.0]], [0.5])
    assert world.ball(plain[0])["rolling_resistance"] == 0.0
    refused = r"^balls\[1\]: rolling resistance must be finite and >= 0 \(got -1\)$"
    with pytest.raises(exact2d.InvalidInputError, match=refused):
        world.add_balls([[30, 0], [33, 0]], [[0, 0], [0, 0]], [1, 1], rolling_resistances=[0.5, -1.0])
    with pytest.raises(exact2d.InvalidInputError, match=r"rolling_resistances must have shape \(2,\) like positions"):
        world.add_balls([[30, 0], [33, 0]], [[0, 0], [0, 0]], [1, 1], rolling_resistances=[0.5])
    assert world.ball_count == n + 1


def rolling_world():
    """Two disks rolling under resistance on a rough floor, a rough circle and segment beside."""
    world = floor_world(0.2, 0.05)
    world.add_segment((-50.0, 0.0), (-50.0, 10.0), friction=0.3, rolling_resistance=0.125)
    world.add_circle((40.0, 5.0), 1.0, friction=0.1, tangential_restitution=0.5, rolling_resistance=0.0625)
    disk_on_floor(world, 1.0, 2.0, -4.0, 0.2, 0.05)
    disk_on_floor(world, -10.0, 3.0, 0.0, 0.2, 0.05)  # thrown: slides first
    return world


def test_pickling_keeps_rolling_resistance_and_the_stop_at_its_analytic_place():
    world = rolling_world()
    world.advance_to(0.25)  # ball 1 still sliding, ball 0 rolling
    clone = pickle.loads(pickle.dumps(world))
    # (The clone settles on the floor at its first step: its support and acceleration come
    # then.)
    def kept(state):
        return {k: v for k, v in state.items() if k not in ("support", "acceleration")}

    for h in world.handles():
        assert kept(clone.ball(h)) == kept(world.ball(h))
        assert clone.ball(h)["rolling_resistance"] == 0.05
    for h in world.collider_handles():
        assert clone.collider(h) == world.collider(h)
    assert [clone.collider(h)["rolling_resistance"] for h in clone.collider_handles()] == [0.05, 0.125, 0.0625]
    # Ball 0 stops at t = 4, 4 further on (see above), in the clone too; ball 1 slides until
    # t = 0.5, rolls at 2 from x = -10 + 1.25, and stops 4 s later, 4 further on.
    for w in (world, clone):
        assert w.advance_to(100.0) == 0
        assert close(w.position(0)[0], 5.0, 1e-9) and w.velocity(0) == (0.0, 0.0)
        assert close(w.position(1)[0], -10.0 + 1.25 + 4.0, 1e-9) and w.velocity(1) == (0.0, 0.0)
        assert w.next_event_time() is None
    np.testing.assert_allclose(clone.positions(), world.positions(), rtol=0.0, atol=1e-12)


def test_a_rolling_world_pickled_before_its_first_step_continues_bit_for_bit():
    world = rolling_world()
    clone = pickle.loads(pickle.dumps(world))
    world.advance_to(3.0)
    clone.advance_to(3.0)
    for name in ("positions", "velocities", "spins", "angles"):
        assert getattr(world, name)().tobytes() == getattr(clone, name)().tobytes(), name


def test_a_version_2_pickle_without_rolling_resistance_loads_with_none():
    world = rolling_world()
    state = json.loads(world.__getstate__())
    assert state["version"] == 4
    # Version 2 as first written: no table, no rolls, no rolling resistance.
    state["version"] = 2
    del state["table"]
    for b in state["balls"]:
        del b["roll"]
    assert state["balls"][0]["rolling_resistance"] == 0.05 and state["colliders"][1]["rolling_resistance"] == 0.125
    for item in state["balls"] + state["colliders"]:
        del item["rolling_resistance"]
    old = exact2d.World()
    old.__setstate__(json.dumps(state))
    assert old.ball(0)["rolling_resistance"] == 0.0 and old.collider(0)["rolling_resistance"] == 0.0
    assert old.ball(0)["friction"] == 0.2
    # Without resistance ball 0 rolls on at 2 for ever.
    old.advance_to(10.0)
    assert close(old.position(0)[0], 21.0) and close(old.velocity(0)[0], 2.0) and close(old.spin(0), -4.0)


def test_scenes_keep_rolling_resistance_and_validate_it():
    scene = {
        "gravity": [0.0, -G],
        "segments": [{"a": [-50.0, 0.0], "b": [50.0, 0.0], "friction": 0.2, "rolling_resistance": 0.1}],
        "circles": [{"center": [40.0, 5.0], "radius": 1.0, "rolling_resistance": 0.5}],
        "balls": [
            {"id": 4, "pos": [1.0, R], "vel": [2.0, 0.0], "radius": R, "spin": -4.0,
             "friction": 0.2, "rolling_resistance": 0.025},
            {"id": 9, "pos": [-20.0, R], "vel": [0.0, 0.0], "radius": R},
        ],
    }
    world = exact2d.World.from_scene(scene)
    assert world.ball(4)["rolling_resistance"] == 0.025 and world.ball(9)["rolling_resistance"] == 0.0
    assert world.collider(0)["rolling_resistance"] == 0.1 and world.collider(1)["rolling_resistance"] == 0.5
    back = world.to_scene()
    assert back["balls"][0]["rolling_resistance"] == 0.025
    assert back["segments"][0]["rolling_resistance"] == 0.1 and back["circles"][0]["rolling_resistance"] == 0.5
    assert "rolling_resistance" not in back["balls"][1]  # the default is left out
    assert exact2d.World.from_scene(back).to_scene() == back
    # c = sqrt(0.025 * 0.1) = 0.05: the stop at t = 4, x = 1 + 4, as above.
    world.advance_to(10.0)
    assert close(world.position(4)[0], 5.0, 1e-9) and world.velocity(4) == (0.0, 0.0)
    for where, bad in [
        ("balls[0]", {"balls": [dict(scene["balls"][0], rolling_resistance=-1)]}),
        ("segments[0]", {"segments": [dict(scene["segments"][0], rolling_resistance=-0.5)], "balls": []}),
        ("circles[0]", {"circles": [dict(scene["circles"][0], rolling_resistance=-2)], "balls": []}),
    ]:
        with pytest.raises(exact2d.SceneError, match=rf"^{re.escape(where)}\.rolling_resistance must be >= 0$"):
            exact2d.World.from_scene(bad)
