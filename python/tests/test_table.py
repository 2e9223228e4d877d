"""A table seen from above (billiards, pool: ``crates/exact2d/src/dynamics/table.rs``),
checked through the bindings against closed forms worked out here, and through validation,
pickles, scenes and arrays.

The world's plane is the cloth; gravity ``g`` pulls into it. A ball of radius ``r`` and
inertia factor ``k`` (a solid sphere: 0.4) has a velocity ``v``, a spin ``w`` about the
vertical and a roll ``(w_x, w_y)`` about the horizontal axes; its contact point slips at
``u = v + r (-w_y, w_x)``. Sliding, friction ``mu_s g`` against ``u`` slows the ball and
spins the roll up at ``mu_s g / k`` (as a contact velocity), so ``u`` shrinks at
``mu_s g (1 + 1/k)``; once it vanishes the ball rolls, losing ``mu_r g`` of speed a second,
until it stops. The spin loses ``mu_sp g / (k r)`` a second. Mass 1 everywhere.
"""

import json
import math
import pickle

import exact2d
import numpy as np
import pytest

R = 0.5
SPHERE = 0.4
POOL = {"gravity": 9.81, "sliding_friction": 0.2, "rolling_friction": 0.01, "spinning_friction": 0.0127}


def close(a, b, tol=1e-12):
    return abs(a - b) <= tol * (1.0 + abs(b))


def close_pair(a, b, tol=1e-12):
    return close(a[0], b[0], tol) and close(a[1], b[1], tol)


def cloth(sliding=0.2, rolling=0.01, spinning=0.0):
    """A table with g = 10."""
    return exact2d.World(
        table={"gravity": 10.0, "sliding_friction": sliding, "rolling_friction": rolling, "spinning_friction": spinning}
    )


def test_a_stun_shot_slides_then_rolls_at_five_sevenths_and_stops_where_rolling_friction_says():
    # v0 = 3.5 along x, no roll: u = 3.5, shrinking at 0.2 * 10 * (1 + 2.5) = 7 a second, so it
    # slides until t = 0.5 (v = 3.5 - 2 t = 2.5 = 5/7 v0, x = 3.5 t - t^2 = 1.5), then rolls,
    # losing 0.1 a second: it stops 25 s later at 1.5 + 2.5^2 / (2 * 0.1) = 32.75.
    world = cloth(0.2, 0.01)
    ball = world.add_ball((0.0, 0.0), (3.5, 0.0), R, inertia=SPHERE)
    assert close(float(world.kinetic_energies()[0]), 0.5 * 3.5**2)
    assert world.advance_to(0.25) == 0
    # Sliding: v = 3, x = 0.8125; the contact velocity of the roll, -5 t = -1.25 along x, is a
    # roll (0, 1.25 / r) = (0, 2.5).
    assert close_pair(world.position(ball), (0.8125, 0.0)) and close_pair(world.velocity(ball), (3.0, 0.0))
    assert close_pair(world.roll(ball), (0.0, 2.5))
    assert world.event_counts()["phase_ends"] == 0
    assert world.advance_to(0.5) == 0
    assert close_pair(world.position(ball), (1.5, 0.0)) and close_pair(world.velocity(ball), (2.5, 0.0))
    # Rolling: roll (0, v / r).
    assert close_pair(world.roll(ball), (0.0, 5.0))
    assert close(world.ball(ball)["roll"][1], 5.0)
    # m v^2 / 2 + k m r^2 |roll|^2 / 2 = 3.125 + 1.25 = 4.375, 5/7 of the 6.125 thrown.
    assert close(float(world.kinetic_energies()[0]), 4.375)
    world.advance_to(10.0)  # rolling for 9.5 s: v = 2.5 - 0.95, x = 1.5 + 23.75 - 4.5125
    assert close_pair(world.position(ball), (20.7375, 0.0)) and close_pair(world.velocity(ball), (1.55, 0.0))
    assert close_pair(world.roll(ball), (0.0, 3.1))
    world.advance_to(25.5)
    assert close(world.position(ball)[0], 32.75) and world.velocity(ball) == (0.0, 0.0)
    assert world.roll(ball) == (0.0, 0.0)
    world.advance_to(100.0)
    assert close(world.position(ball)[0], 32.75) and world.velocity(ball) == (0.0, 0.0)
    counts = world.event_counts()
    assert counts["phase_ends"] == 2  # the slip vanished, then the ball stopped
    assert counts["contacts"] == counts["ball_contacts"] == 0
    assert world.next_event_time() is None
    assert world.spin(ball) == 0.0


def test_a_stun_shot_at_an_angle_rolls_with_the_roll_about_the_axis_across_its_path():
    # The same shot along (0.6, 0.8): it rolls at 2.5 along it from t = 0.5, with the roll
    # (-v_y, v_x) / r = (-4, 3).
    world = cloth(0.2, 0.01)
    ball = world.add_ball((0.0, 0.0), (2.1, 2.8), R, inertia=SPHERE)
    world.advance_to(0.5)
    assert close_pair(world.position(ball), (0.9, 1.2)) and close_pair(world.velocity(ball), (1.5, 2.0))
    assert close_pair(world.roll(ball), (-4.0, 3.0))
    world.advance_to(30.0)
    assert close_pair(world.position(ball), (0.6 * 32.75, 0.8 * 32.75), 1e-12)


def test_a_ball_given_only_a_roll_is_set_moving_and_ends_rolling():
    # Roll (0, 7), radius 0.5: the contact point slips at r (-7, 0) = (-3.5, 0), so friction
    # pushes the ball along +x at 2 while the slip shrinks at 7: it vanishes at t = 0.5, the
    # ball rolling at 1.0 (roll (0, 2)) from x = 0.25. Without rolling friction it rolls on.
    world = cloth(0.2, 0.0)
    ball = world.add_ball((0.0, 0.0), (0.0, 0.0), R, inertia=SPHERE, roll=(0.0, 7.0))
    assert world.roll(ball) == (0.0, 7.0)
    assert close(float(world.kinetic_energies()[0]), 0.5 * SPHERE * R**2 * 49.0)
    world.advance_to(0.5)
    assert close_pair(world.velocity(ball), (1.0, 0.0)) and close_pair(world.position(ball), (0.25, 0.0))
    assert close_pair(world.roll(ball), (0.0, 2.0))
    world.advance_to(10.5)
    assert close_pair(world.velocity(ball), (1.0, 0.0)) and close_pair(world.position(ball), (10.25, 0.0))
    assert close_pair(world.roll(ball), (0.0, 2.0))
    assert world.event_counts()["phase_ends"] == 1 and world.spin(ball) == 0.0


def test_set_roll_restarts_the_phase_and_a_rolling_ball_does_not_slide():
    # Rolling from the start (roll (0, v / r)): no sliding, the stop after 2 / 0.1 = 20 s at
    # 2^2 / 0.2 = 20.
    world = cloth(0.2, 0.01)
    ball = world.add_ball((0.0, 0.0), (2.0, 0.0), R, inertia=SPHERE, roll=(0.0, 4.0))
    world.advance_to(1.0)
    assert close_pair(world.velocity(ball), (1.9, 0.0)) and close_pair(world.roll(ball), (0.0, 3.8))
    world.advance_to(25.0)
    assert close(world.position(ball)[0], 20.0) and world.velocity(ball) == (0.0, 0.0)
    assert world.event_counts()["phase_ends"] == 1
    # A roll set on the resting ball: as the roll-only ball above, rolling at 1.0 after 0.5 s
    # (then slowed by rolling friction: 0.1 a second).
    world.set_roll(ball, (0.0, 7.0))
    assert world.roll(ball) == (0.0, 7.0)
    world.advance_to(25.5)
    assert close_pair(world.velocity(ball), (1.0, 0.0)) and close(world.position(ball)[0], 20.25)


def test_set_velocity_and_set_spin_on_the_cloth_take_the_phase_again():
    world = cloth(0.2, 0.01, 0.02)
    ball = world.add_ball((0.0, 0.0), (3.5, 0.0), R, inertia=SPHERE)
    world.advance_to(0.25)
    # Its own velocity again: the stun shot goes on as it was (slip 3 - 1.25 = 1.75, gone
    # after 0.25 s).
    world.set_velocity(ball, (3.0, 0.0))
    world.advance_to(0.5)
    assert close_pair(world.position(ball), (1.5, 0.0)) and close_pair(world.velocity(ball), (2.5, 0.0))
    assert close_pair(world.roll(ball), (0.0, 5.0))
    # A spin of 3 while rolling: it loses 0.02 * 10 / (0.4 * 0.5) = 1 a second, the ball
    # rolls on (losing 0.1 a second); the spin stops at t = 3.5.
    world.set_spin(ball, 3.0)
    world.advance_to(1.5)
    assert close_pair(world.position(ball), (3.95, 0.0)) and close_pair(world.velocity(ball), (2.4, 0.0))
    assert close(world.spin(ball), 2.0) and close_pair(world.roll(ball), (0.0, 4.8))
    world.advance_to(3.5)
    assert world.spin(ball) == 0.0


def test_spinning_friction_stops_a_spin_at_its_analytic_time():
    # mu_sp g / (k r) = 0.02 * 10 / 0.2 = 1 rad/s^2: a spin of 3 stops at t = 3, having turned
    # 3 * 3 - 3^2 / 2 = 4.5 radians; the ball does not move.
    world = cloth(0.2, 0.01, 0.02)
    ball = world.add_ball((1.0, 2.0), (0.0, 0.0), R, inertia=SPHERE, spin=3.0)
    world.advance_to(1.0)
    assert close(world.spin(ball), 2.0) and close(world.angle(ball), 2.5)
    world.advance_to(10.0)
    assert world.spin(ball) == 0.0 and close(world.angle(ball), math.remainder(4.5, 2.0 * math.pi))
    assert world.position(ball) == (1.0, 2.0) and world.velocity(ball) == (0.0, 0.0)
    assert world.event_counts()["phase_ends"] == 1


def test_set_table_restates_moving_balls_and_taking_it_away_keeps_their_velocities():
    world = exact2d.World(gravity=(0.0, 0.0))
    assert world.table is None
    ball = world.add_ball((0.0, 0.0), (3.5, 0.0), R, inertia=SPHERE)
    world.advance_to(1.0)  # free: x = 3.5
    world.set_table({"gravity": 10.0}, sliding_friction=0.2, rolling_friction=0.01, spinning_friction=0.0)
    assert world.table == {"gravity": 10.0, "sliding_friction": 0.2, "rolling_friction": 0.01, "spinning_friction": 0.0}
    # The stun shot from t = 1, x = 3.5.
    world.advance_to(1.5)
    assert close_pair(world.position(ball), (5.0, 0.0)) and close_pair(world.velocity(ball), (2.5, 0.0))
    world.set_table(None)
    assert world.table is None and world.roll(ball) == (0.0, 0.0)
    assert close_pair(world.velocity(ball), (2.5, 0.0))
    world.advance_to(3.5)
    assert close_pair(world.position(ball), (10.0, 0.0)) and close_pair(world.velocity(ball), (2.5, 0.0))
    # Defaults: a pool table, single values on top, a table's dict back in.
    world.set_table()
    assert world.table == POOL
    world.set_table(sliding_friction=0.3)
    assert world.table == dict(POOL, sliding_friction=0.3)
    other = exact2d.World(table=world.table)
    assert other.table == world.table and other.gravity == (0.0, 0.0)
    assert exact2d.World(table={}).table == POOL
    assert exact2d.World(table=None).table is None and exact2d.World().gravity == (0.0, -9.81)


def adding(**kwargs):
    """A call adding a ball of radius 1 at the origin with `kwargs`."""
    return lambda w: w.add_ball((0, 0), (0, 0), 1.0, **kwargs)


@pytest.mark.parametrize(
    "make, call, message",
    [
        (lambda: exact2d.World(table={"sliding_friction": -1.0}), None,
         r"^table sliding_friction must be finite and >= 0 \(got -1\)$"),
        (lambda: exact2d.World(table={"rolling_friction": math.inf}), None,
         r"^table rolling_friction must be finite and >= 0 \(got inf\)$"),
        (lambda: exact2d.World(table={"spinning_friction": math.nan}), None,
         r"^table spinning_friction must be finite and >= 0 \(got NaN\)$"),
        (lambda: exact2d.World(table={"gravity": 0.0}), None, r"^table gravity must be finite and > 0 \(got 0\)$"),
        (lambda: exact2d.World(table={"gravity": -9.81}), None, r"table gravity must be finite and > 0"),
        (lambda: exact2d.World(gravity=(0.0, -9.81), table={}), None, r"the world's gravity must be \(0, 0\) with a table"),
        (lambda: exact2d.World(table={"mu": 0.2}), None, r'table has no key "mu"'),
        (lambda: exact2d.World(table={"gravity": "x"}), None, r'table\["gravity"\] must be a number'),
        (lambda: exact2d.World(table=0.2), None, "table must be None or a dict"),
        (lambda: exact2d.World(), lambda w: w.set_table(), r"the world's gravity must be \(0, 0\) with a table"),
        (exact2d.World, lambda w: w.set_table(gravity=-1.0), "table gravity must be finite and > 0"),
        (lambda: exact2d.World(table={}), lambda w: setattr(w, "gravity", (0.0, -1.0)),
         r"the world's gravity must be \(0, 0\) with a table"),
        (lambda: exact2d.World(table={}), lambda w: w.set_table(sliding_friction=-0.5),
         r"table sliding_friction must be finite and >= 0 \(got -0.5\)"),
        (lambda: exact2d.World(table={}), lambda w: w.set_table(None, sliding_friction=0.3), "takes no values"),
        (lambda: exact2d.World(gravity=(0.0, 0.0)), adding(roll=(0.0, 1.0)), r"roll needs a table \(World.set_table\)"),
        (lambda: exact2d.World(gravity=(0.0, 0.0)), lambda w: w.set_roll(w.add_ball((0, 0), (0, 0), 1.0), (1.0, 0.0)),
         "roll needs a table"),
        (lambda: exact2d.World(gravity=(0.0, 0.0)),
         lambda w: w.add_balls([[0, 0], [3, 0]], [[0, 0], [0, 0]], [1, 1], rolls=[[0, 0], [0, 1]]),
         r"^balls\[1\]: a ball's roll needs a table"),
        (lambda: exact2d.World(table={}), adding(roll=(0.0, math.nan)), "ball roll must be finite"),
        (lambda: exact2d.World(table={}), adding(roll=(1.0, 2.0, 3.0)), r"roll must be a pair of numbers \(x, y\)"),
        (lambda: exact2d.World(table={}), lambda w: w.set_roll(w.add_ball((0, 0), (0, 0), 1.0), (math.inf, 0.0)),
         "ball roll must be finite"),
        (lambda: exact2d.World(table={}),
         lambda w: w.add_balls([[0, 0], [3, 0]], [[0, 0], [0, 0]], [1, 1], rolls=[[0, 0]]),
         r"rolls must have shape \(2, 2\) like positions, got \(1, 2\)"),
        (lambda: exact2d.World(table={}),
         lambda w: w.add_balls([[0, 0], [3, 0]], [[0, 0], [0, 0]], [1, 1], rolls=[0.0, 1.0]),
         r"rolls must have shape \(n, 2\)"),
    ],
)
def test_bad_tables_and_rolls_raise_invalid_input_naming_the_value_and_range(make, call, message):
    with pytest.raises(exact2d.InvalidInputError, match=message) as info:
        world = make()
        call(world)
    assert isinstance(info.value, ValueError)


def test_refusals_change_nothing():
    world = exact2d.World(table={})
    with pytest.raises(ValueError):
        world.set_table(rolling_friction=-1.0)
    assert world.table == POOL
    with pytest.raises(ValueError):
        world.gravity = (0.0, -9.81)
    assert world.gravity == (0.0, 0.0)
    with pytest.raises(ValueError):
        world.add_balls([[0, 0], [3, 0]], [[0, 0], [0, 0]], [1, 1], rolls=[[0, 0], [0, math.nan]])
    assert world.ball_count == 0
    with pytest.raises(exact2d.UnknownHandleError, match="no ball with handle 3"):
        world.set_roll(3, (0.0, 1.0))
    with pytest.raises(exact2d.UnknownHandleError):
        world.roll(3)


def test_rolls_is_an_n_by_2_float64_array_in_the_order_of_the_other_arrays():
    world = cloth()
    n = 5
    positions = np.stack([np.arange(n) * 3.0, np.zeros(n)], axis=1)
    rolls = np.stack([np.linspace(-2, 2, n), np.linspace(1, 5, n)], axis=1)
    handles = world.add_balls(positions, np.zeros((n, 2)), np.full(n, R), inertias=np.full(n, SPHERE), rolls=rolls)
    assert world.rolls().dtype == np.float64 and world.rolls().shape == (n, 2)
    order = np.argsort(world.handles())
    np.testing.assert_array_equal(world.rolls()[order], rolls)
    for h, roll in zip(handles, rolls):
        assert world.roll(h) == tuple(roll) and world.ball(h)["roll"] == tuple(roll)
    k = SPHERE * R**2 * np.sum(rolls**2, axis=1) / 2
    np.testing.assert_allclose(world.kinetic_energies()[order], k, rtol=1e-15)
    world.remove_ball(int(handles[1]))
    assert world.rolls().shape == (n - 1, 2)
    for i, h in enumerate(world.handles()):
        assert tuple(world.rolls()[i]) == world.roll(int(h))
        assert tuple(world.positions()[i]) == world.position(int(h))
    # Without a table (or a roll): zeros, positive ones.
    plain = exact2d.World(gravity=(0.0, 0.0))
    assert plain.rolls().shape == (0, 2) and plain.rolls().dtype == np.float64
    plain.add_balls([[0.0, 0.0], [5.0, 0.0]], [[1.0, 0.0], [0.0, 2.0]], [1.0, 1.0], spins=[3.0, -1.0])
    plain.advance_to(1.0)
    assert plain.rolls().tobytes() == np.zeros((2, 2)).tobytes()
    assert plain.event_counts()["phase_ends"] == 0


def pool_world():
    """A pool table 2.54 x 1.27 with cushions, balls thrown with spins and rolls."""
    world = exact2d.World(table={})
    corners = [(0.0, 0.0), (2.54, 0.0), (2.54, 1.27), (0.0, 1.27)]
    for a, b in zip(corners, corners[1:] + corners[:1]):
        world.add_segment(a, b, restitution=0.9)
    rng = np.random.default_rng(4)
    for i in range(8):
        pos = (0.3 + 0.25 * i, 0.3 + 0.08 * (i % 5))
        world.add_ball(
            pos, tuple(rng.normal(size=2) * 2.0), 0.028575, mass=0.17, restitution=0.95, inertia=SPHERE,
            spin=float(rng.normal() * 20.0), roll=tuple(rng.normal(size=2) * 30.0),
        )
    return world


STATE = ("positions", "velocities", "spins", "rolls", "angles", "kinetic_energies")


def test_a_table_world_pickled_before_its_first_step_continues_bit_for_bit():
    world = pool_world()
    clone = pickle.loads(pickle.dumps(world))
    assert clone.table == world.table == POOL and clone.gravity == (0.0, 0.0)
    a, b = world.advance_to_collect(20.0), clone.advance_to_collect(20.0)
    assert len(a["time"]) > 20
    for k in a:
        np.testing.assert_array_equal(a[k], b[k], err_msg=k)
    for name in STATE:
        assert getattr(world, name)().tobytes() == getattr(clone, name)().tobytes(), name
    assert world.event_counts() == clone.event_counts()
    assert world.event_counts()["phase_ends"] > 8


def test_a_table_world_pickled_mid_run_keeps_its_state_bit_for_bit_and_its_future_to_rounding():
    world = pool_world()
    world.advance_to(0.37)
    clone = pickle.loads(pickle.dumps(world))
    assert clone.time == world.time and clone.table == world.table
    for name in STATE:
        assert getattr(world, name)().tobytes() == getattr(clone, name)().tobytes(), name
    assert json.loads(clone.__getstate__()) == json.loads(world.__getstate__())
    # Every ball on the cloth takes its phase afresh from its state at the pickled instant
    # (its trajectory restated there, the phase's end computed from the slip then), so the
    # future matches to rounding: the same events in the same order, at times within 1e-9.
    a, b = world.advance_to_collect(20.0), clone.advance_to_collect(20.0)
    assert len(a["time"]) == len(b["time"]) > 10
    for k in ("kind", "ball", "other_ball", "collider"):
        np.testing.assert_array_equal(a[k], b[k], err_msg=k)
    np.testing.assert_allclose(a["time"], b["time"], rtol=0.0, atol=1e-8)
    np.testing.assert_allclose(clone.positions(), world.positions(), rtol=0.0, atol=1e-8)
    assert not world.velocities().any() and not clone.velocities().any()  # all at rest by now


def test_a_stun_shot_pickled_mid_slide_still_stops_at_its_analytic_place():
    world = cloth(0.2, 0.01)
    ball = world.add_ball((0.0, 0.0), (3.5, 0.0), R, inertia=SPHERE)
    world.advance_to(0.3)
    clone = pickle.loads(pickle.dumps(world))
    assert clone.roll(ball) == world.roll(ball) and clone.velocity(ball) == world.velocity(ball)
    for w in (world, clone):
        w.advance_to(0.5)
        assert close_pair(w.velocity(ball), (2.5, 0.0)) and close_pair(w.roll(ball), (0.0, 5.0))
        w.advance_to(30.0)
        assert close(w.position(ball)[0], 32.75) and w.velocity(ball) == (0.0, 0.0)


def test_pickles_of_version_3_carry_the_table_and_older_ones_load_without():
    world = cloth(0.25, 0.02, 0.03)
    world.add_ball((0.0, 0.0), (1.0, 0.0), R, roll=(0.5, -1.5))
    state = json.loads(world.__getstate__())
    assert state["version"] == 4
    assert state["table"] == {"gravity": 10.0, "sliding_friction": 0.25, "rolling_friction": 0.02, "spinning_friction": 0.03}
    assert state["balls"][0]["roll"] == [0.5, -1.5]
    assert json.loads(exact2d.World(gravity=(0.0, 0.0)).__getstate__())["table"] is None
    # A version-2 pickle (no table, no rolls): a world without a table.
    plain = exact2d.World(gravity=(0.0, 0.0))
    plain.add_ball((0.0, 0.0), (1.0, 0.0), R, spin=2.0)
    old = json.loads(plain.__getstate__())
    old["version"] = 2
    del old["table"]
    for b in old["balls"]:
        del b["roll"]
    for version in (1, 2):
        old["version"] = version
        loaded = exact2d.World()
        loaded.__setstate__(json.dumps(old))
        assert loaded.table is None and loaded.roll(0) == (0.0, 0.0) and loaded.spin(0) == 2.0
        loaded.advance_to(2.0)
        assert loaded.position(0) == (2.0, 0.0)
    bad = dict(state, table={"gravity": 10.0})
    with pytest.raises(exact2d.InvalidInputError, match="not a pickled exact2d world: table.sliding_friction"):
        exact2d.World().__setstate__(json.dumps(bad))


def test_run_many_copies_table_worlds_and_returns_their_rolls():
    world = pool_world()
    results = exact2d.run_many([world, world], 3.0, threads=1)
    assert world.time == 0.0  # the originals are not changed
    copy_ = pickle.loads(pickle.dumps(world))
    copy_.advance_to(3.0)
    for r in results:
        assert r["rolls"].dtype == np.float64 and r["rolls"].shape == (8, 2)
        assert r["rolls"].tobytes() == copy_.rolls().tobytes()
        assert r["positions"].tobytes() == copy_.positions().tobytes()


def table_scene():
    return {
        "gravity": [0.0, 0.0],
        "table": {"gravity": 10.0, "sliding_friction": 0.2, "rolling_friction": 0.01},
        "segments": [{"a": [40.0, -5.0], "b": [40.0, 5.0]}],
        "balls": [
            {"id": 3, "pos": [0.0, 0.0], "vel": [3.5, 0.0], "radius": R, "inertia": SPHERE},
            {"id": 8, "pos": [0.0, 3.0], "vel": [0.0, 0.0], "radius": R, "inertia": SPHERE, "roll": [0.0, 7.0]},
        ],
    }


def test_scenes_with_a_table_and_rolls_load_round_trip_and_run():
    scene = table_scene()
    world = exact2d.World.from_scene(scene)
    # The missing key takes the pool table's value.
    assert world.table == {"gravity": 10.0, "sliding_friction": 0.2, "rolling_friction": 0.01, "spinning_friction": 0.0127}
    assert world.gravity == (0.0, 0.0)
    assert world.roll(8) == (0.0, 7.0) and world.roll(3) == (0.0, 0.0)
    back = world.to_scene()
    assert back["table"] == world.table
    assert back["balls"][1]["roll"] == [0.0, 7.0]
    assert "roll" not in back["balls"][0]  # the default is left out
    assert exact2d.World.from_scene(back).to_scene() == back
    assert "table" not in exact2d.World(gravity=(0.0, 0.0)).to_scene()
    # The stun shot and the roll-only ball, as above (rolling friction now slows the second).
    world.advance_to(0.5)
    assert close_pair(world.velocity(3), (2.5, 0.0)) and close_pair(world.position(3), (1.5, 0.0))
    assert close_pair(world.velocity(8), (1.0, 0.0)) and close_pair(world.position(8), (0.25, 3.0))
    world.advance_to(30.0)
    assert close(world.position(3)[0], 32.75) and world.velocity(3) == (0.0, 0.0)
    assert close(world.position(8)[0], 0.25 + 1.0 / 0.2) and world.velocity(8) == (0.0, 0.0)
    results = exact2d.run_many([scene], 30.0, threads=1)
    assert results[0]["positions"].tobytes() == world.positions().tobytes()
    assert results[0]["rolls"].tobytes() == world.rolls().tobytes()


def test_scene_validation_refuses_bad_tables_and_rolls_without_one():
    scene = table_scene()
    with pytest.raises(exact2d.SceneError, match=r"^table\.sliding_friction must be >= 0$"):
        exact2d.World.from_scene(dict(scene, table={"sliding_friction": -0.1}))
    with pytest.raises(exact2d.SceneError, match=r"^table\.gravity must be > 0$"):
        exact2d.World.from_scene(dict(scene, table={"gravity": 0.0}))
    with pytest.raises(exact2d.SceneError, match=r"^gravity must be \[0, 0\] with a table"):
        exact2d.World.from_scene(dict(scene, gravity=[0.0, -9.81]))
    without = {k: v for k, v in scene.items() if k != "table"}
    with pytest.raises(exact2d.SceneError, match=r"^balls\[1\]\.roll must be \[0, 0\] without a table$"):
        exact2d.World.from_scene(without)
