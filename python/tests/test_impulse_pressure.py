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


def test_the_virial_pressure_of_a_dense_hard_disk_fluid_matches_henderson():
    # Henderson, Molecular Physics 30 (1975) 971: Z = (1 + eta^2 / 8) / (1 - eta)^2 for hard
    # disks, within about a percent in the fluid. Clausius' virial in 2D:
    # P A = N kT + (1 / 2t) sum over collisions of sigma J.
    n, radius, eta = 400, 0.5, 0.3
    side = np.sqrt(n * np.pi * radius**2 / eta)
    per_row = 20
    spacing = side / per_row
    k = np.arange(n)
    positions = np.stack([(k % per_row + 0.5) * spacing, (k // per_row + 0.5) * spacing], axis=1)
    velocities = np.random.default_rng(7).normal(size=(n, 2))
    velocities -= velocities.mean(axis=0)
    world = exact2d.World(gravity=(0.0, 0.0))
    corners = [(0.0, 0.0), (side, 0.0), (side, side), (0.0, side)]
    for a, b in zip(corners, corners[1:] + corners[:1]):
        world.add_segment(a, b)
    world.add_balls(positions, velocities, np.full(n, radius))
    kT = 0.5 * (world.velocities() ** 2).sum(axis=1).mean()
    world.advance_to(20.0)  # the lattice melts
    t = 150.0
    events = world.advance_to_collect(20.0 + t)
    pairs = events["kind"] == 1
    assert pairs.sum() > 50_000
    z = 1 + (2 * radius) * events["impulse"][pairs].sum() / (2 * t) / (n * kT)
    henderson = (1 + eta**2 / 8) / (1 - eta) ** 2
    assert abs(z / henderson - 1) < 0.03, (z, henderson)
