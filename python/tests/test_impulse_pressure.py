"""Impulses on events: momentum bookkeeping, and the pressure of a dilute gas from kinetic
theory (2D ideal gas: P A = N <m |v|^2> / 2), an answer independent of the engine."""

import exact2d
import numpy as np
from conftest import gas_scene


def test_ball_ball_impulses_account_for_every_change_of_momentum():
    world = exact2d.World(gravity=(0.0, 0.0))
    a = world.add_ball((0.0, 0.0), (2.0, 0.3), 0.5, mass=3.0)
    b = world.add_ball((4.0, 0.5), (-1.0, 0.0), 0.5, mass=1.0)
    event = world.step()
    assert event.kind == "ball_contact" and (event.ball, event.other_ball) == (a, b)
    n = np.array(event.normal)
    dv_b = np.array(world.velocity(b)) - np.array([-1.0, 0.0])
    dv_a = np.array(world.velocity(a)) - np.array([2.0, 0.3])
    np.testing.assert_allclose(1.0 * dv_b, event.impulse * n, atol=1e-12)
    np.testing.assert_allclose(3.0 * dv_a, -event.impulse * n, atol=1e-12)


def test_wall_pressure_from_impulses_matches_the_ideal_gas():
    side, n, radius = 100.0, 100, 0.05  # area fraction 8e-5: ideal to far better than 1 %
    world = exact2d.World.from_scene(gas_scene(n, seed=12, width=side, radius=radius))
    speeds2 = (world.velocities() ** 2).sum(axis=1)
    t = 8000.0
    events = world.advance_to_collect(t)
    walls = events["kind"] == 0
    pressure = events["impulse"][walls].sum() / (t * 4 * side)
    # Walls are met at distance r, so the free area is (L - 2r)^2.
    ideal = 0.5 * speeds2.sum() / (side - 2 * radius) ** 2
    assert walls.sum() > 10_000
    assert abs(pressure / ideal - 1) < 0.03, (pressure, ideal)
