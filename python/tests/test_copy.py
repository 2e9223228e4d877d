"""Copies: ``World.copy()``, ``copy.copy`` and ``copy.deepcopy`` branch a running world
exactly. Given the same calls, a copy and its original go on with the same events and bits
(every event's fields compared as bits, step by step), and each is independent of the other.

A pickle is the contrast: a world pickled mid-run is rebuilt from its public state, restated
at that instant, so its state then is the original's bit for bit but its future only to
rounding (``test_pickle_and_scenes.py``). In the pile below, its first event differs: in the
time's last bit when pickled at t = 0.3, and at t = 1.5 (balls asleep, groups held together)
it is another event altogether. Nothing here depends on timing: runs are to simulated times."""

import copy
import pickle

import exact2d
import numpy as np
import pytest
from conftest import assert_same_columns, box_world, periodic_lattice, run_columns

FIELDS = (
    "time",
    "kind",
    "ball",
    "other_ball",
    "collider",
    "feature",
    "point",
    "normal",
    "impulse",
    "normal_speed",
    "tangential_impulse",
)


def bits(value):
    """A value with its floats as their bits (``float.hex``: -0.0 and NaN compare too)."""
    if isinstance(value, float):
        return value.hex()
    if isinstance(value, tuple):
        return tuple(bits(v) for v in value)
    return value


def record(event):
    """Every field of an event (or ``None``), floats as bits."""
    return None if event is None else tuple(bits(getattr(event, f)) for f in FIELDS)


def array_bits(a):
    return (a.dtype.str, a.shape, a.tobytes())


def snapshot(world):
    """What a world shows, as bits; reading it changes nothing (`next_event_time` would
    predict, so it is left out)."""
    colliders = [
        (int(h), bits(world.collider_momentum(h)), world.collider_impacts(h))
        for h in world.collider_handles()
    ]
    return {
        "time": bits(world.time),
        "handles": array_bits(world.handles()),
        "positions": array_bits(world.positions()),
        "unwrapped": array_bits(world.unwrapped_positions()),
        "velocities": array_bits(world.velocities()),
        "spins": array_bits(world.spins()),
        "angles": array_bits(world.angles()),
        "rolls": array_bits(world.rolls()),
        "counts": world.event_counts(),
        "sleeping": world.sleeping_count,
        "instant": world.instant_events(),
        "virial": bits(world.collision_virial),
        "since": bits(world.observables_since),
        "colliders": colliders,
    }


def lockstep(a, b, until):
    """Steps both worlds to `until` one event at a time, asserting each pair of events equal
    to the bit; returns the number of events."""
    n = 0
    while True:
        ea, eb = a.step_until(until), b.step_until(until)
        assert record(ea) == record(eb), f"event {n}"
        if ea is None:
            return n
        n += 1


def dropped_pile(n=24, seed=5):
    """Rough balls dropped into a narrow box under gravity with sleeping on: ball-ball
    contacts, jams, groups held together, and balls falling asleep from about t = 1 until the
    pile is at rest by t = 3.5 (some 7,300 events)."""
    world = box_world(width=4.0, height=8.0, gravity=(0.0, -9.81))
    world.sleeping = True
    rng = np.random.default_rng(seed)
    for i in range(n):
        x = 0.5 + (i % 6) * 0.6 + rng.uniform(-0.05, 0.05)
        y = 1.0 + (i // 6) * 0.7
        vel = tuple(rng.normal(size=2))
        world.add_ball((x, y), vel, 0.2, restitution=0.6, friction=0.3, tangential_restitution=0.2)
    return world


def periodic_gas(n=100, radius=0.5, eta=0.4, e=0.97, seed=11):
    """Slightly inelastic disks (restitution `e`, the TC model) on a lattice in a periodic
    box of packing fraction `eta`, seeded velocities."""
    positions, velocities, side = periodic_lattice(n, radius, eta, seed)
    world = exact2d.World(periodic=(side, side))
    world.collapse_time = 1e-3
    world.add_balls(positions, velocities, np.full(n, radius), restitutions=np.full(n, e))
    return world


def test_a_copy_of_a_settling_pile_goes_on_with_the_originals_events_and_bits():
    world = dropped_pile()
    world.remove_ball(3)
    world.advance_to(1.5)
    assert 0 < world.sleeping_count < world.ball_count  # some asleep, some moving
    branch = world.copy()
    assert type(branch) is exact2d.World and branch is not world
    assert snapshot(branch) == snapshot(world)
    # Handles are copied too: the removed ball is unknown to both, the next one is the same.
    with pytest.raises(exact2d.UnknownHandleError):
        branch.position(3)

    # The same calls, one event at a time: every event equal, to the pile's rest.
    n = lockstep(world, branch, 4.0)
    assert n > 800
    counts = world.event_counts()
    assert counts["ball_contacts"] > 0 and counts["sleeps"] > 0 and counts["jams"] > 0
    assert world.sleeping_count == world.ball_count
    assert snapshot(branch) == snapshot(world)

    # More of the same calls: a ball dropped onto the sleeping pile wakes it.
    for w in (world, branch):
        assert w.add_ball((2.0, 6.0), (0.4, 0.0), 0.2, restitution=0.6, friction=0.3) == 24
        w.set_spin(10, 3.0)
    assert_same_columns(run_columns(world, 4.0), run_columns(branch, 4.0))
    assert world.event_counts()["wakes"] > counts["wakes"]
    assert snapshot(branch) == snapshot(world)


def test_copies_taken_between_any_two_events_go_on_bit_for_bit():
    # Every 61st event, inside zero-time chains and jams too: each copy's next 30 events are
    # the original's.
    world = dropped_pile()
    records, copies = [], []
    while (event := world.step()) is not None:
        if len(records) % 61 == 0:
            copies.append((len(records), world.copy()))
        records.append(record(event))
    # (The pile takes some 7,300 events to rest since a jam takes a group's members as
    # touching up to the group gap, stop 53: 7,278; 9,043 since a slow pair falling freely
    # together stops against each other, stop 49; 13,165 in stop 48, 19,897 in stop 47,
    # 20,000 and more before.)
    assert len(records) > 6000 and len(copies) > 100
    assert any(c.instant_events()[0] > 0 for _, c in copies)  # some taken mid-instant
    for start, branch in copies:
        for i in range(start + 1, min(start + 31, len(records))):
            assert record(branch.step()) == records[i], (start, i)


def test_a_copy_is_independent_of_its_original():
    world = dropped_pile()
    world.advance_to(1.2)
    branch = world.copy()
    before = snapshot(world)
    # Stepping and changing the copy leaves the original as it was...
    branch.set_velocity(0, (5.0, 5.0))
    branch.remove_ball(1)
    branch.add_ball((2.0, 7.0), (0.0, 0.0), 0.3)
    branch.gravity = (0.0, -1.0)
    branch.reset_observables()
    branch.advance_to(3.0)
    assert snapshot(world) == before
    # ...and the original's run is the one it would have had without the copy.
    alone = dropped_pile()
    alone.advance_to(1.2)
    assert_same_columns(run_columns(world, 2.5), run_columns(alone, 2.5))
    assert snapshot(world) == snapshot(alone)
    # Stepping the original leaves the copy as it was.
    mine = snapshot(branch)
    world.advance_to(5.0)
    assert snapshot(branch) == mine
    assert branch.gravity == (0.0, -1.0) and world.gravity == (0.0, -9.81)


def test_a_copy_of_a_periodic_box_keeps_its_unwrapped_positions_and_observables():
    world = periodic_gas()
    world.advance_to(2.0)
    world.reset_observables()
    world.advance_to(5.0)
    branch = world.copy()
    assert snapshot(branch) == snapshot(world)
    n = lockstep(world, branch, 9.0)
    assert n > 250
    # Both went on together: the unwrapped positions (balls have crossed the box), the
    # virial and when it started counting, bit for bit.
    assert np.any(world.unwrapped_positions() != world.positions())
    assert world.observables_since == branch.observables_since == 2.0
    assert world.collision_virial > 0
    assert world.collision_virial.hex() == branch.collision_virial.hex()
    assert world.unwrapped_positions().tobytes() == branch.unwrapped_positions().tobytes()
    assert snapshot(branch) == snapshot(world)
    assert_same_columns(run_columns(world, 12.0), run_columns(branch, 12.0))
    assert snapshot(branch) == snapshot(world)


def test_a_copy_of_an_unpickled_world_keeps_what_the_pickle_carried():
    # A world loaded from a pickle carries its images and observables beside the engine; a
    # copy carries them too.
    world = periodic_gas()
    world.advance_to(2.0)
    world.reset_observables()
    world.advance_to(5.0)
    loaded = pickle.loads(pickle.dumps(world))
    loaded.advance_to(6.0)
    branch = loaded.copy()
    assert np.any(branch.unwrapped_positions() != branch.positions())
    assert branch.observables_since == 2.0
    assert snapshot(branch) == snapshot(loaded)
    assert lockstep(loaded, branch, 9.0) > 150
    assert snapshot(branch) == snapshot(loaded)
    branch.reset_observables()
    assert loaded.observables_since == 2.0 and branch.observables_since == 9.0


@pytest.mark.parametrize("scene", ["pile", "periodic"])
def test_copy_copy_and_deepcopy_are_copy(scene):
    world = dropped_pile() if scene == "pile" else periodic_gas()
    # The pile mid-fall (some 3,000 events to go), the gas well mixed.
    world.advance_to(0.8 if scene == "pile" else 5.0)
    until = 3.0 if scene == "pile" else 8.0
    copies = [world.copy(), copy.copy(world), copy.deepcopy(world)]
    for c in copies:
        assert type(c) is exact2d.World and c is not world
        assert snapshot(c) == snapshot(world)
    # Not through the pickle: every one goes on with the original's events and bits.
    runs = [run_columns(w, until) for w in [world, *copies]]
    assert len(runs[0]["time"]) > 200
    for run, c in zip(runs[1:], copies):
        assert_same_columns(runs[0], run)
        assert snapshot(c) == snapshot(world)
    # deepcopy's memo: a world met twice is copied once.
    a, b = copy.deepcopy([world, world])
    assert a is b and a is not world


def test_a_pickle_mid_run_is_the_originals_state_now_and_its_future_to_rounding():
    # The contrast (not asserted: to rounding means the bits may or may not differ): the
    # pickle's state at the pickled instant is the original's, bit for bit; its future is
    # close, while a copy's is equal.
    world = dropped_pile()
    world.advance_to(0.3)
    loaded, branch = pickle.loads(pickle.dumps(world)), world.copy()
    for w in (loaded, branch):
        assert w.positions().tobytes() == world.positions().tobytes()
        assert w.velocities().tobytes() == world.velocities().tobytes()
    for w in (world, loaded, branch):
        w.advance_to(0.4)
    assert branch.positions().tobytes() == world.positions().tobytes()
    np.testing.assert_allclose(loaded.positions(), world.positions(), rtol=0, atol=1e-6)
