"""Periodic boxes and observables, against answers independent of the engine: a lone ball's
free flight, the hard-disk equation of state (Henderson), the momentum a wall takes from
elastic bounces (2 m v each), and the event impulses; their errors, scenes, pickles and
run_many."""

import json
import math
import pickle

import exact2d
import numpy as np
import pytest
from conftest import assert_same_columns, box_world, periodic_lattice, run_columns


def periodic_gas(n=100, radius=0.5, eta=0.3, seed=7):
    """n disks on a square lattice in a periodic box of packing fraction eta, velocities
    drawn from a normal distribution (seeded) with zero total momentum; and the box's side."""
    positions, velocities, side = periodic_lattice(n, radius, eta, seed)
    velocities -= velocities.mean(axis=0)
    world = exact2d.World(periodic=(side, side))
    world.add_balls(positions, velocities, np.full(n, radius))
    return world, side


def test_a_lone_ball_wraps_into_the_box_and_unwraps_to_its_free_flight():
    size = np.array([10.0, 6.0])
    world = exact2d.World(periodic=tuple(size))
    assert world.periodic == (10.0, 6.0) and world.gravity == (0.0, 0.0)
    p0, v = np.array([1.0, 2.0]), np.array([3.7, -1.3])
    ball = world.add_ball(tuple(p0), tuple(v), 0.2)
    crossings = 0
    for t in np.linspace(0.37, 200.0, 97):
        assert world.advance_to(t) == 0  # a wrap is no event
        free = p0 + v * t
        unwrapped = world.unwrapped_positions()
        np.testing.assert_allclose(unwrapped[0], free, rtol=0, atol=1e-9)
        assert world.unwrapped_position(ball) == tuple(unwrapped[0])
        position = world.positions()[0]
        assert np.all(position >= 0) and np.all(position < size)
        assert world.position(ball) == tuple(position)
        # The free flight folded into the box (on an edge, either side of it will do).
        folded = position - np.mod(free, size)
        np.testing.assert_allclose(folded - size * np.round(folded / size), 0.0, rtol=0, atol=1e-9)
        # Unwrapped minus wrapped: whole box lengths.
        images = (unwrapped[0] - position) / size
        np.testing.assert_allclose(images, np.round(images), rtol=0, atol=1e-12)
        crossings = np.abs(np.round(images)).sum()
    assert crossings > 100  # 74 through x, 43 through y


def test_a_ball_wrapping_through_zero_now_is_unwrapped_where_it_is():
    # At t = 2 the ball reaches x = 0 moving left (exactly): it wraps now, its path restated
    # on the far edge x = 10, reported at x = 0 in the box; unwrapped, it is at x = 0 too.
    world = exact2d.World(periodic=(10.0, 6.0))
    ball = world.add_ball((1.0, 2.0), (-0.5, 0.0), 0.2)
    world.advance_to(2.0)
    assert world.position(ball) == (0.0, 2.0)
    assert world.unwrapped_position(ball) == (0.0, 2.0)
    clone = pickle.loads(pickle.dumps(world))
    assert clone.unwrapped_position(ball) == (0.0, 2.0)
    for w in (world, clone):
        w.advance_to(6.0)
        assert w.unwrapped_position(ball) == (-2.0, 2.0)
        assert w.position(ball) == (8.0, 2.0)
    # Without a periodic box the unwrapped positions are the positions.
    closed = box_world()
    closed.add_ball((5.0, 3.0), (3.0, 1.0), 0.5)
    closed.advance_to(7.0)
    assert closed.periodic is None
    np.testing.assert_array_equal(closed.unwrapped_positions(), closed.positions())


def test_hard_disks_in_a_periodic_box_follow_hendersons_equation_of_state():
    # Henderson, Mol. Phys. 30, 971 (1975): Z = (1 + eta^2 / 8) / (1 - eta)^2 for hard
    # disks, to 0.1 % at eta = 0.3. The virial theorem in 2D with the collision virial W
    # (contact distance times impulse, summed) over a time t: Z = 1 + W / (2 t N kT), with
    # kT = K / (N - 1) at zero total momentum.
    n, radius, eta = 100, 0.5, 0.3
    world, side = periodic_gas(n, radius, eta)
    energy = world.kinetic_energies().sum()
    world.advance_to(20.0)  # the lattice melts
    world.reset_observables()
    assert (world.collision_virial, world.observables_since) == (0.0, 20.0)
    t = 1000.0
    events = world.advance_to_collect(20.0 + t)
    pairs = events["kind"] == 1
    assert pairs.sum() > 100_000 and pairs.all()  # no collider, no wall: only disks
    kT = world.kinetic_energies().sum() / (n - 1)
    w = world.collision_virial
    z = 1 + w / (2 * t * n * kT)
    henderson = (1 + eta**2 / 8) / (1 - eta) ** 2
    assert abs(z / henderson - 1) < 0.03, (z, henderson)
    # The virial is the contact distance times the impulses the events report.
    np.testing.assert_allclose(w, 2 * radius * events["impulse"][pairs].sum(), rtol=1e-9)
    # Energy and momentum are kept; every ball is in the box, its unwrapped position whole
    # box lengths away, in the order of positions().
    np.testing.assert_allclose(kT * (n - 1), energy, rtol=1e-12)
    np.testing.assert_allclose(world.velocities().sum(axis=0), 0.0, atol=1e-10)
    positions, unwrapped = world.positions(), world.unwrapped_positions()
    assert unwrapped.shape == (n, 2) and np.all((positions >= 0) & (positions < side))
    images = (unwrapped - positions) / side
    np.testing.assert_allclose(images, np.round(images), rtol=0, atol=1e-9)
    assert np.abs(images).max() >= 1  # the disks have diffused across the box
    for i, h in enumerate(world.handles()):
        assert world.unwrapped_position(h) == tuple(unwrapped[i])


def test_walls_of_a_closed_box_take_two_m_v_per_impact():
    world = box_world(width=10.0, height=6.0)  # bottom 0, right 1, top 2, left 3
    m, v = 2.0, 3.0
    ball = world.add_ball((5.0, 3.0), (v, 0.0), 0.5, mass=m)
    # Between x = 0.5 and 9.5: the right wall at t = 1.5, 7.5, 13.5, 19.5, the left one at
    # 4.5, 10.5, 16.5.
    events = run_columns(world, 20.0)
    assert (world.collider_impacts(1), world.collider_impacts(3)) == (4, 3)
    assert world.collider_impacts(0) == world.collider_impacts(2) == 0
    assert world.collider_momentum(1) == pytest.approx((4 * 2 * m * v, 0.0), rel=1e-12, abs=1e-12)
    assert world.collider_momentum(3) == pytest.approx((-3 * 2 * m * v, 0.0), rel=1e-12, abs=1e-12)
    assert world.collider_momentum(0) == (0.0, 0.0)
    for wall in (1, 3):
        mine = events["collider"] == wall
        assert abs(world.collider_momentum(wall)[0]) == pytest.approx(events["impulse"][mine].sum(), rel=1e-12)
    assert world.collision_virial == 0.0 and world.observables_since == 0.0
    # Counted again from a reset: 22.5 on the left, 25.5 on the right.
    world.reset_observables()
    assert world.collider_momentum(1) == (0.0, 0.0) and world.collider_impacts(1) == 0
    world.advance_to(26.0)
    assert world.observables_since == 20.0
    assert (world.collider_impacts(1), world.collider_impacts(3)) == (1, 1)
    assert world.collider_momentum(1) == pytest.approx((2 * m * v, 0.0), rel=1e-12, abs=1e-12)
    assert world.velocity(ball) == (-v, 0.0)
    with pytest.raises(exact2d.UnknownHandleError, match="no collider with handle 9"):
        world.collider_momentum(9)
    world.remove_collider(0)
    with pytest.raises(exact2d.UnknownHandleError, match="no collider with handle 0"):
        world.collider_impacts(0)


def periodic_world():
    return exact2d.World(periodic=(10.0, 10.0))


@pytest.mark.parametrize(
    "call, message",
    [
        (lambda: setattr(exact2d.World(), "periodic", (10.0, 10.0)),
         r"^a periodic box does not take gravity \(yet\): the world's gravity must be \(0, 0\)$"),
        (lambda: exact2d.World(gravity=(0.0, -1.0), periodic=(10.0, 10.0)),
         r"^a periodic box does not take gravity \(yet\)"),
        (lambda: setattr(periodic_world(), "gravity", (0.0, -9.81)),
         r"^a periodic box does not take gravity \(yet\)"),
        (lambda: exact2d.World(table={}, periodic=(10.0, 10.0)),
         r"^a periodic box does not take a table \(yet\)"),
        (lambda: periodic_world().set_table(),
         r"^a periodic box does not take a table \(yet\)"),
        (lambda: periodic_world().add_ball((10.0, 5.0), (0.0, 0.0), 0.1),
         r"^a ball's position must be inside the periodic box \[0, Lx\) x \[0, Ly\) \(got \[10, 5\]\); "
         r"this box is \[0, 10\) x \[0, 10\)$"),
        (lambda: periodic_world().add_ball((5.0, -1e-300), (0.0, 0.0), 0.1),
         r"^a ball's position must be inside the periodic box"),
        (lambda: periodic_world().add_ball((5.0, 5.0), (0.0, 0.0), 2.0),
         r"^a ball's radius must be at most 1.5151515151515151 in this periodic box "
         r"\(its shorter side / 6.6; got 2\)$"),
        (lambda: exact2d.World(periodic=(0.0, 10.0)),
         r"^a periodic box's sides must be finite and > 0 \(got \[0, 10\]\)$"),
        (lambda: exact2d.World(periodic=(math.inf, 10.0)),
         r"^a periodic box's sides must be finite and > 0 \(got \[inf, 10\]\)$"),
        (lambda: exact2d.World(periodic=(1.0, 2.0, 3.0)),
         r"^periodic must be a pair of numbers \(x, y\), got 3 numbers$"),
        (lambda: periodic_world().add_segment((0.0, 5.0), (3.0, 5.0)),
         r"^a collider must keep clear of the periodic box's edges by more than the largest "
         r"ball's radius 0 \(it keeps 0\)$"),
        (lambda: setattr(periodic_world(), "periodic", None),
         r"^a periodic box cannot be taken away"),
        (lambda: setattr(periodic_world(), "periodic", (10.0, 10.0)),
         r"^a world is made periodic before any ball is added, and once"),
    ],
)
def test_periodic_errors_raise_the_packages_exceptions_with_the_engines_message(call, message):
    with pytest.raises(exact2d.InvalidInputError, match=message) as info:
        call()
    assert type(info.value) is exact2d.InvalidInputError


def test_periodic_refusals_of_balls_and_worlds_with_balls():
    world = exact2d.World(gravity=(0.0, 0.0))
    world.add_ball((1.0, 1.0), (0.0, 0.0), 0.1)
    with pytest.raises(exact2d.InvalidInputError, match=r"^a world is made periodic before any ball is added"):
        world.periodic = (10.0, 10.0)
    assert world.periodic is None
    world.periodic = None  # nothing to take away
    periodic = periodic_world()
    periodic.add_segment((1.0, 5.0), (3.0, 5.0))  # 1 from the edges
    periodic.add_ball((8.0, 8.0), (0.0, 0.0), 0.9)
    with pytest.raises(exact2d.InvalidInputError, match=r"radius 1.2 \(it keeps 1\)$"):
        periodic.add_ball((5.0, 8.0), (0.0, 0.0), 1.2)  # one near it would meet its image
    with pytest.raises(exact2d.InvalidInputError, match=r"^balls\[1\]: a ball's position must be inside"):
        periodic.add_balls([[6.0, 2.0], [8.0, 10.5]], np.zeros((2, 2)), [0.1, 0.1])
    assert periodic.ball_count == 1  # all or nothing
    scene = {"gravity": [0.0, 0.0], "periodic": [10.0, 10.0],
             "balls": [{"id": 0, "pos": [10.0, 1.0], "vel": [0.0, 0.0], "radius": 0.1}]}
    with pytest.raises(exact2d.SceneError, match=r"balls\[0\]\.pos"):
        exact2d.World.from_scene(scene)


def periodic_scene():
    rng = np.random.default_rng(11)
    balls = [
        {"id": 3 * i + 1, "pos": [1.0 + (i % 5) * 2.0, 1.0 + (i // 5) * 2.0],
         "vel": rng.normal(size=2).tolist(), "radius": 0.3}
        for i in range(15)
    ]
    return {
        "gravity": [0.0, 0.0],
        "ball_ball": True,
        "periodic": [10.0, 7.0],
        "circles": [{"center": [6.0, 4.0], "radius": 0.5}],
        "balls": [b for b in balls if math.dist(b["pos"], [6.0, 4.0]) > 1.0],
    }


def test_a_periodic_scene_round_trips(tmp_path):
    scene = periodic_scene()
    world = exact2d.World.from_scene(scene)
    assert world.periodic == (10.0, 7.0)
    back = world.to_scene()
    assert back["periodic"] == [10.0, 7.0]
    assert [b["pos"] for b in back["balls"]] == [b["pos"] for b in scene["balls"]]
    again = exact2d.World.from_scene(back)
    assert again.to_scene() == back
    path = tmp_path / "periodic.json"
    path.write_text(json.dumps(back))
    from_file = exact2d.World.from_scene(str(path))
    a, b, c = (run_columns(w, 40.0) for w in (world, again, from_file))
    assert len(a["time"]) > 100
    assert_same_columns(a, b)
    assert_same_columns(a, c)
    np.testing.assert_array_equal(world.unwrapped_positions(), again.unwrapped_positions())
    # A world run on is written at its instant: positions in the box, the box kept.
    later = world.to_scene()
    assert later["periodic"] == [10.0, 7.0]
    assert all(0 <= b["pos"][0] < 10.0 and 0 <= b["pos"][1] < 7.0 for b in later["balls"])
    assert exact2d.World.from_scene(later).periodic == (10.0, 7.0)
    assert "periodic" not in box_world().to_scene()


def test_a_periodic_world_pickled_before_its_first_step_continues_bit_for_bit():
    world = exact2d.World.from_scene(periodic_scene())
    clone = pickle.loads(pickle.dumps(world))
    assert clone.periodic == world.periodic
    assert_same_columns(run_columns(world, 30.0), run_columns(clone, 30.0))
    for f in ("positions", "velocities", "unwrapped_positions"):
        np.testing.assert_array_equal(getattr(clone, f)(), getattr(world, f)(), err_msg=f)
    assert clone.collision_virial == world.collision_virial > 0
    assert clone.collider_momentum(0) == world.collider_momentum(0)
    assert clone.collider_impacts(0) == world.collider_impacts(0) > 0
    # run_many copies a World through the same state.
    fresh = exact2d.World.from_scene(periodic_scene())
    (result,) = exact2d.run_many([fresh], 30.0)
    np.testing.assert_array_equal(result["positions"], world.positions())
    assert fresh.time == 0.0


def test_a_periodic_world_pickled_mid_run_keeps_its_box_images_and_observables():
    world = exact2d.World.from_scene(periodic_scene())
    world.advance_to(3.0)
    world.reset_observables()
    world.advance_to(27.3)
    clone = pickle.loads(pickle.dumps(world))
    # The state now, bit for bit: the box, positions, velocities, the box lengths each ball
    # has crossed, and the observables counted since 3.0.
    assert (clone.time, clone.periodic, clone.observables_since) == (27.3, (10.0, 7.0), 3.0)
    for f in ("handles", "positions", "velocities", "unwrapped_positions"):
        np.testing.assert_array_equal(getattr(clone, f)(), getattr(world, f)(), err_msg=f)
    assert np.abs(world.unwrapped_positions() - world.positions()).max() >= 7.0
    assert clone.collision_virial == world.collision_virial > 0
    assert clone.collider_momentum(0) == world.collider_momentum(0) != (0.0, 0.0)
    assert clone.collider_impacts(0) == world.collider_impacts(0) > 0
    again = pickle.loads(pickle.dumps(clone))
    np.testing.assert_array_equal(again.unwrapped_positions(), world.unwrapped_positions())
    assert again.collision_virial == world.collision_virial
    # The future: restated at the pickled instant, it agrees to rounding (not bit for bit;
    # see the README), the carried images and observables added to the new ones.
    world.advance_to(28.0)
    clone.advance_to(28.0)
    np.testing.assert_allclose(clone.unwrapped_positions(), world.unwrapped_positions(), rtol=0, atol=1e-9)
    np.testing.assert_allclose(clone.collision_virial, world.collision_virial, rtol=1e-12)
    np.testing.assert_allclose(clone.collider_momentum(0), world.collider_momentum(0), rtol=1e-12)
    assert clone.collider_impacts(0) == world.collider_impacts(0)
    # A reset drops what the pickle carried; the images stay.
    clone.reset_observables()
    assert (clone.collision_virial, clone.observables_since, clone.collider_impacts(0)) == (0.0, 28.0, 0)
    np.testing.assert_allclose(clone.unwrapped_positions(), world.unwrapped_positions(), rtol=0, atol=1e-9)
    assert "periodic=(10.0, 7.0)" in repr(clone)


def test_pickles_of_version_4_carry_the_box_images_and_observables_and_older_ones_load():
    world = box_world(width=10.0, height=6.0)
    world.add_ball((5.0, 3.0), (3.0, 0.0), 0.5)  # the right wall at 1.5, the left at 4.5
    world.advance_to(5.0)
    state = json.loads(world.__getstate__())
    assert state["version"] == 4 and state["periodic"] is None and "images" not in state["balls"][0]
    assert state["observables"] == {"since": 0.0, "virial": 0.0}
    assert [(c["momentum"], c["impacts"]) for c in state["colliders"]] == [
        ([0.0, 0.0], 0), ([6.0, 0.0], 1), ([0.0, 0.0], 0), ([-6.0, 0.0], 1)]
    periodic = exact2d.World(periodic=(10.0, 10.0))
    periodic.add_ball((9.0, 5.0), (1.0, 0.0), 0.1)
    periodic.advance_to(3.0)
    moved = json.loads(periodic.__getstate__())
    assert moved["periodic"] == [10.0, 10.0] and moved["balls"][0]["images"] == [1, 0]
    assert moved["balls"][0]["pos"] == [2.0, 5.0]
    # A version-3 pickle (no box, no observables): its observables start at its instant.
    state["version"] = 3
    del state["periodic"], state["observables"]
    for c in state["colliders"]:
        del c["momentum"], c["impacts"]
    old = exact2d.World()
    old.__setstate__(json.dumps(state))
    assert (old.observables_since, old.collision_virial, old.collider_impacts(1)) == (5.0, 0.0, 0)
    assert old.periodic is None
    state["version"] = 4
    state["balls"][0]["images"] = [1, 0]
    with pytest.raises(exact2d.InvalidInputError, match="not a pickled exact2d world: images without a periodic box"):
        exact2d.World().__setstate__(json.dumps(state))


def test_run_many_gives_the_unwrapped_positions_and_observables_of_a_world_run_alone():
    # The same periodic worlds run in parallel and one by one, each stepped to `until` on
    # its own: the same unwrapped positions, virial and start of the observables, bit for
    # bit, row for row in the order of the handles (3 i + 1, not 0 to n - 1).
    gas, _ = periodic_gas(n=49, radius=0.5, eta=0.3, seed=5)
    gas_alone, _ = periodic_gas(n=49, radius=0.5, eta=0.3, seed=5)
    items = [periodic_scene(), gas]
    until = 40.0
    alone = [exact2d.World.from_scene(periodic_scene()), gas_alone]
    for world in alone:
        world.advance_to(until)
    assert gas.time == 0.0  # run_many runs a copy
    for threads in (1, 2):
        results = exact2d.run_many(items, until, threads=threads)
        for result, world in zip(results, alone):
            assert result["time"] == world.time == until
            np.testing.assert_array_equal(result["handles"], world.handles())
            np.testing.assert_array_equal(result["positions"], world.positions())
            np.testing.assert_array_equal(result["unwrapped"], world.unwrapped_positions())
            assert result["unwrapped"].dtype == np.float64
            assert result["unwrapped"].shape == (world.ball_count, 2)
            for h, row in zip(result["handles"], result["unwrapped"]):
                assert world.unwrapped_position(int(h)) == tuple(row)
            assert result["collision_virial"] == world.collision_virial > 0
            assert result["observables_since"] == world.observables_since == 0.0
            # Balls have crossed the box's edges: unwrapped is not positions.
            assert np.any(result["unwrapped"] != result["positions"])


def test_run_many_keeps_the_images_and_observables_a_world_carries():
    # A World run mid-way, its observables reset at 3.0: run_many copies it exactly (the
    # engine's clone), so it matches the original stepped on alone, bit for bit, the box
    # lengths crossed and the virial before the copy included; a pickled copy (restated at its
    # instant) carries the same images and observables, and goes on to rounding.
    world = exact2d.World.from_scene(periodic_scene())
    world.advance_to(3.0)
    world.reset_observables()
    world.advance_to(27.3)
    virial = world.collision_virial
    assert np.abs(world.unwrapped_positions() - world.positions()).max() >= 7.0 and virial > 0
    pickled = pickle.loads(pickle.dumps(world))
    (result,) = exact2d.run_many([world], 28.0)
    assert world.time == 27.3  # the original is not changed
    world.advance_to(28.0)
    np.testing.assert_array_equal(result["positions"], world.positions())
    np.testing.assert_array_equal(result["unwrapped"], world.unwrapped_positions())
    assert result["collision_virial"] == world.collision_virial >= virial
    assert result["observables_since"] == world.observables_since == 3.0
    pickled.advance_to(28.0)
    assert pickled.observables_since == 3.0
    np.testing.assert_allclose(pickled.unwrapped_positions(), world.unwrapped_positions(), rtol=0, atol=1e-9)
    np.testing.assert_allclose(pickled.collision_virial, world.collision_virial, rtol=1e-12)
