"""NumPy in and out: dtypes, shapes, alignment with handles, vectorised adds."""

import exact2d
import numpy as np
import pytest
from conftest import box_world


def test_an_empty_world_gives_empty_arrays_of_the_right_shapes():
    world = exact2d.World()
    assert world.positions().shape == (0, 2) and world.positions().dtype == np.float64
    assert world.velocities().shape == (0, 2) and world.velocities().dtype == np.float64
    assert world.radii().shape == (0,) and world.radii().dtype == np.float64
    assert world.handles().shape == (0,) and world.handles().dtype == np.int64


def test_add_balls_takes_arrays_and_returns_handles_aligned_with_every_array():
    world = box_world(20.0, 20.0)
    n = 50
    x = np.linspace(1.0, 19.0, n)
    positions = np.stack([x, np.full(n, 10.0)], axis=1)
    velocities = np.stack([np.zeros(n), np.linspace(-1, 1, n)], axis=1)
    radii = np.full(n, 0.1)
    masses = np.linspace(1.0, 2.0, n)
    handles = world.add_balls(positions, velocities, radii, masses=masses)
    assert handles.dtype == np.int64 and handles.shape == (n,)
    assert list(handles) == list(range(n))
    order = np.argsort(world.handles())
    np.testing.assert_array_equal(world.positions()[order], positions)
    np.testing.assert_array_equal(world.velocities()[order], velocities)
    np.testing.assert_array_equal(world.radii()[order], radii)
    np.testing.assert_array_equal(world.masses()[order], masses)
    for arr, shape in [(world.positions(), (n, 2)), (world.velocities(), (n, 2))]:
        assert arr.shape == shape and arr.dtype == np.float64 and arr.flags.c_contiguous


def test_positions_move_in_closed_form_between_events():
    world = exact2d.World(gravity=(0.0, -2.0))
    ball = world.add_ball((0.0, 0.0), (1.0, 3.0), 0.1)
    world.advance_to(1.5)
    # x = t, y = 3 t - t^2 (no collider: free flight).
    np.testing.assert_allclose(world.positions(), [[1.5, 4.5 - 2.25]], rtol=0, atol=1e-15)
    np.testing.assert_allclose(world.velocities(), [[1.0, 0.0]], atol=1e-15)
    assert world.ball(ball)["acceleration"] == (0.0, -2.0)


def test_add_balls_accepts_lists_and_integer_arrays():
    world = exact2d.World(gravity=(0.0, 0.0))
    handles = world.add_balls([[0, 0], [3, 0]], np.array([[1, 0], [0, 1]]), [0.5, 0.5], masses=[1, 2])
    assert list(handles) == [0, 1]
    np.testing.assert_array_equal(world.masses(), [1.0, 2.0])
    assert world.velocity(1) == (0.0, 1.0)
    with pytest.raises(exact2d.InvalidInputError, match="positions must be an array of numbers"):
        world.add_balls([["a", "b"]], [[0, 0]], [1.0])
