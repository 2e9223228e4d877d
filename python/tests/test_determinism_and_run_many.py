"""The same inputs give the same bits; run_many agrees with running each world alone."""

import exact2d
import numpy as np
from conftest import gas_scene


def test_the_same_scene_twice_gives_the_same_events():
    a = exact2d.World.from_scene(gas_scene(40, seed=9)).advance_to_collect(10.0)
    b = exact2d.World.from_scene(gas_scene(40, seed=9)).advance_to_collect(10.0)
    for k in a:
        np.testing.assert_array_equal(a[k], b[k])


def test_frames_do_not_change_results():
    once = exact2d.World.from_scene(gas_scene(40, seed=2))
    once.advance_to(10.0)
    framed = exact2d.World.from_scene(gas_scene(40, seed=2))
    for k in range(1, 601):
        framed.advance_to(k / 60.0)
    np.testing.assert_array_equal(once.positions(), framed.positions())


def test_one_event_at_a_time_equals_the_collected_run():
    a = exact2d.World.from_scene(gas_scene(20, seed=4))
    times, impulses = [], []
    while (event := a.step_until(5.0)) is not None:
        times.append(event.time)
        impulses.append(event.impulse)
    b = exact2d.World.from_scene(gas_scene(20, seed=4)).advance_to_collect(5.0)
    np.testing.assert_array_equal(times, b["time"])
    np.testing.assert_array_equal(impulses, b["impulse"])


def test_run_many_matches_sequential_runs_on_any_number_of_threads():
    scenes = [gas_scene(30, seed=s) for s in range(6)]
    world = exact2d.World.from_scene(gas_scene(30, seed=99))
    before = world.positions().copy()
    items = scenes + [world]
    one = exact2d.run_many(items, 8.0, threads=1)
    two = exact2d.run_many(items, 8.0, threads=2)
    default = exact2d.run_many(items, 8.0)
    np.testing.assert_array_equal(world.positions(), before)  # the World was copied
    for i, scene in enumerate(scenes + [gas_scene(30, seed=99)]):
        alone = exact2d.World.from_scene(scene)
        events = alone.advance_to(8.0)
        for result in (one[i], two[i], default[i]):
            assert result["events"] == events and result["time"] == 8.0
            np.testing.assert_array_equal(result["handles"], alone.handles())
            np.testing.assert_array_equal(result["positions"], alone.positions())
            np.testing.assert_array_equal(result["velocities"], alone.velocities())
            # No periodic box: the unwrapped positions are the positions.
            np.testing.assert_array_equal(result["unwrapped"], result["positions"])
            np.testing.assert_array_equal(result["unwrapped"], alone.unwrapped_positions())
            assert result["collision_virial"] == alone.collision_virial
            assert result["observables_since"] == alone.observables_since == 0.0
    assert one[0]["positions"].dtype == np.float64 and one[0]["positions"].shape == (30, 2)
    assert one[0]["unwrapped"].dtype == np.float64 and one[0]["unwrapped"].shape == (30, 2)
    assert all(r["collision_virial"] > 0 for r in one)  # the balls met


def test_run_many_names_the_bad_scene():
    import pytest

    bad = {"balls": [{"id": 0, "pos": [0, 0], "vel": [0, 0], "radius": -1}]}
    with pytest.raises(exact2d.SceneError, match=r"scenes\[1\]: balls\[0\]\.radius must be > 0"):
        exact2d.run_many([gas_scene(3), bad], 1.0)
