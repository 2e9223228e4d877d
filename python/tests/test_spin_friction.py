"""Spin and friction at impacts: the rough-disk model (``crates/exact2d/src/dynamics/rough.rs``)
checked against its closed forms, its conservation laws, its validation, and its round trips
through pickles, scenes and arrays.

The model, for a contact of unit normal ``n`` from body 1 to body 2 and ``t = (-n.y, n.x)``:
the contact points' tangential slip is ``g = (v1 - v2) . t + w1 r1 + w2 r2``; a tangential
impulse ``J`` (``+J t`` on body 2, ``-J t`` on body 1) changes it by ``-J K`` with
``K = (1 + 1/k1)/m1 + (1 + 1/k2)/m2`` (a static collider adds nothing) and each spin by
``-J / (k m r)``; ``J = sign(g) min((1 + beta) |g| / K, mu P)`` with ``P`` the normal impulse.
"""

import json
import math
import pickle

import exact2d
import numpy as np
import pytest

HUGE = 1e9  # a friction coefficient no impact reaches: contacts stick


def rough_box(width=10.0, height=10.0, friction=HUGE, tangential_restitution=0.0, restitution=1.0):
    """A closed box [0, width] x [0, height] of four rough segments, no gravity."""
    world = exact2d.World(gravity=(0.0, 0.0))
    corners = [(0.0, 0.0), (width, 0.0), (width, height), (0.0, height)]
    for a, b in zip(corners, corners[1:] + corners[:1]):
        world.add_segment(
            a,
            b,
            restitution=restitution,
            friction=friction,
            tangential_restitution=tangential_restitution,
        )
    return world


def lattice(n, width, seed):
    """n centres on a lattice inside [0, width]^2, random velocities and spins (seeded)."""
    rng = np.random.default_rng(seed)
    side = int(np.ceil(np.sqrt(n)))
    spacing = width / (side + 1)
    i = np.arange(n)
    positions = np.stack([(1 + i % side) * spacing, (1 + i // side) * spacing], axis=1)
    return positions, rng.normal(size=(n, 2)), rng.normal(scale=5.0, size=n), rng


def total_energy(world):
    """Translational plus rotational kinetic energy, from the arrays (not the engine's sum)."""
    m, r, k = world.masses(), world.radii(), world.inertias()
    v, w = world.velocities(), world.spins()
    return float(np.sum(0.5 * m * np.sum(v * v, axis=1) + 0.5 * k * m * r * r * w * w))


def angular_momentum(world):
    """Orbital plus spin angular momentum about the origin."""
    m, r, k = world.masses(), world.radii(), world.inertias()
    x, v, w = world.positions(), world.velocities(), world.spins()
    return float(np.sum(m * (x[:, 0] * v[:, 1] - x[:, 1] * v[:, 0]) + k * m * r * r * w))


@pytest.mark.parametrize(
    "inertia, beta, vy",
    [(0.5, 0.0, 0.0), (0.5, 0.0, 0.8), (1.0, 0.0, -0.3), (0.4, 0.5, 0.2), (0.5, 1.0, 0.0)],
)
def test_a_spinning_ball_hitting_a_rough_wall_leaves_as_the_sticking_impulse_says(inertia, beta, vy):
    # A ball of spin w moving at (vx, vy) meets the wall x = 5 (n = +x from ball to wall,
    # t = +y): g = vy + w r, K = (1 + 1/k)/m, J = (1 + beta) g / K (far below mu P).
    m, r, w, vx, e = 2.0, 0.5, 3.0, 2.0, 0.75
    world = exact2d.World(gravity=(0.0, 0.0))
    wall = world.add_segment((5.0, -50.0), (5.0, 50.0), friction=HUGE, tangential_restitution=beta)
    ball = world.add_ball(
        (0.0, 0.0), (vx, vy), r, mass=m, restitution=e,
        spin=w, inertia=inertia, friction=HUGE, tangential_restitution=beta,
    )
    event = world.step()
    assert (event.kind, event.collider, event.normal) == ("contact", wall, (-1.0, 0.0))
    g = vy + w * r
    j = (1.0 + beta) * g / ((1.0 + 1.0 / inertia) / m)
    (vx2, vy2), w2 = world.velocity(ball), world.spin(ball)
    assert vx2 == pytest.approx(-e * vx, abs=1e-12)
    assert vy2 == pytest.approx(vy - j / m, abs=1e-12)
    assert w2 == pytest.approx(w - j / (inertia * m * r), abs=1e-12)
    # The contact leaves with the slip -beta g: for beta = 0 the contact point sticks.
    assert vy2 + w2 * r == pytest.approx(-beta * g, abs=1e-12)
    if (inertia, beta, vy) == (0.5, 0.0, 0.0):
        # A uniform disk (K = 3/m): the tangential velocity changes by -g/3, the spin by -2g/(3r).
        assert vy2 == pytest.approx(-g / 3.0, abs=1e-12)
        assert w2 == pytest.approx(w - 2.0 * g / (3.0 * r), abs=1e-12)
    assert event.impulse == pytest.approx(m * (1.0 + e) * vx, abs=1e-12)
    # The friction impulse, along the normal turned a quarter counter-clockwise (-y here).
    assert event.tangential_impulse == pytest.approx(j, abs=1e-12)


def test_a_contact_that_friction_cannot_stop_slides_with_the_coulomb_cap_of_the_pairs_mean():
    # mu = sqrt(0.04 * 0.25) = 0.1 for the pair; P = m (1 + e) v = 1.5; sticking would take
    # g / K = 5 / 3, more than mu P = 0.15: the contact slides and the impulse is the cap.
    m, r, k, w, v, e = 1.0, 0.5, 0.5, 10.0, 1.0, 0.5
    world = exact2d.World(gravity=(0.0, 0.0))
    world.add_segment((5.0, -50.0), (5.0, 50.0), restitution=1.0, friction=0.25)
    ball = world.add_ball((0.0, 0.0), (v, 0.0), r, mass=m, restitution=e, spin=w, inertia=k, friction=0.04)
    events = world.advance_to_collect(10.0)
    cap = math.sqrt(0.04 * 0.25) * m * (1.0 + e) * v
    assert events["tangential_impulse"].tolist() == pytest.approx([cap], abs=1e-12)
    assert world.velocity(ball) == pytest.approx((-e * v, -cap / m), abs=1e-12)
    assert world.spin(ball) == pytest.approx(w - cap / (k * m * r), abs=1e-12)
    # Still slipping the same way: the contact did not stick.
    assert world.velocity(ball)[1] + world.spin(ball) * r > 0.0


@pytest.mark.parametrize(
    "ball_material, wall_material, slip_after",
    [
        # A frictionless ball makes a frictionless pair, however rough the wall.
        ((0.0, 0.0), (HUGE, 0.0), None),
        # A smooth wall (beta = -1) makes the pair smooth.
        ((HUGE, 0.5), (HUGE, -1.0), None),
        # 1 + beta = sqrt(1.44 * 1.0) = 1.2: the pair's beta is 0.2.
        ((HUGE, 0.44), (HUGE, 0.0), -0.2),
    ],
)
def test_a_pairs_material_mixes_as_documented(ball_material, wall_material, slip_after):
    r, w = 0.5, 4.0
    world = exact2d.World(gravity=(0.0, 0.0))
    mu, beta = wall_material
    world.add_segment((5.0, -50.0), (5.0, 50.0), friction=mu, tangential_restitution=beta)
    ball = world.add_ball(
        (0.0, 0.0), (1.0, 0.0), r, spin=w, friction=ball_material[0], tangential_restitution=ball_material[1]
    )
    world.step()
    (_, vy), w2 = world.velocity(ball), world.spin(ball)
    if slip_after is None:
        assert (vy, w2) == (0.0, w)
    else:
        assert vy + w2 * r == pytest.approx(slip_after * w * r, abs=1e-12)


def test_elastic_perfectly_rough_balls_conserve_energy_and_both_momenta_and_reverse_the_slip():
    # Two free balls of different masses, radii, inertias and spins meet obliquely.
    world = exact2d.World(gravity=(0.0, 0.0))
    a = world.add_ball(
        (0.0, 0.0), (1.5, 0.2), 0.5, mass=1.0, restitution=1.0, spin=7.0, inertia=0.5,
        friction=HUGE, tangential_restitution=1.0,
    )
    b = world.add_ball(
        (3.0, 0.7), (-0.5, -0.1), 0.8, mass=2.5, restitution=1.0, spin=-3.0, inertia=0.9,
        friction=HUGE, tangential_restitution=1.0,
    )
    m = world.masses()
    energy, momentum, spin_orbit = total_energy(world), m @ world.velocities(), angular_momentum(world)
    assert energy == pytest.approx(world.kinetic_energies().sum(), rel=1e-15)
    (va, vb), (wa, wb) = world.velocities(), world.spins()

    event = world.step()
    assert event.kind == "ball_contact" and {event.ball, event.other_ball} == {a, b}
    # The contact's tangent, from the centres at the impact (free flight until then).
    pa, pb = world.positions()
    n = (pb - pa) / np.linalg.norm(pb - pa)
    t = np.array([-n[1], n[0]])
    (va2, vb2), (wa2, wb2) = world.velocities(), world.spins()
    g_in = (va - vb) @ t + wa * 0.5 + wb * 0.8
    g_out = (va2 - vb2) @ t + wa2 * 0.5 + wb2 * 0.8
    assert abs(g_in) > 0.5 and g_out == pytest.approx(-g_in, abs=1e-12)  # beta = 1: reversed
    assert total_energy(world) == pytest.approx(energy, rel=1e-12, abs=0.0)
    assert world.kinetic_energies().sum() == pytest.approx(energy, rel=1e-12, abs=0.0)
    np.testing.assert_allclose(m @ world.velocities(), momentum, rtol=0.0, atol=1e-12)
    assert angular_momentum(world) == pytest.approx(spin_orbit, rel=1e-12, abs=1e-12)


def test_a_gas_of_elastic_perfectly_rough_disks_keeps_its_energy_over_many_collisions():
    n, width = 40, 10.0
    world = rough_box(width, width, tangential_restitution=1.0)
    positions, velocities, spins, rng = lattice(n, width, seed=7)
    world.add_balls(
        positions, velocities, np.full(n, 0.45), masses=rng.uniform(1.0, 2.0, n), spins=spins,
        inertias=rng.uniform(0.3, 1.0, n), frictions=np.full(n, HUGE), tangential_restitutions=np.ones(n),
    )
    energy = total_energy(world)
    events = world.advance_to_collect(100.0)
    assert len(events["time"]) > 5000
    assert np.count_nonzero(events["kind"] == 1) > 1000  # ball-ball collisions
    # Energy passes between translation and rotation, and the sum stays.
    assert total_energy(world) == pytest.approx(energy, rel=1e-12, abs=0.0)
    assert not np.allclose(world.spins(), spins)


@pytest.mark.parametrize(
    "restitution, beta, mu", [(0.9, 0.0, HUGE), (1.0, -0.5, 0.3), (0.8, 1.0, 0.05), (1.0, 0.7, HUGE)]
)
def test_energy_never_increases_at_a_rough_impact(restitution, beta, mu):
    n, width = 25, 8.0
    world = rough_box(width, width, friction=mu, tangential_restitution=beta, restitution=restitution)
    positions, velocities, spins, _ = lattice(n, width, seed=3)
    world.add_balls(
        positions, velocities, np.full(n, 0.3), restitutions=np.full(n, restitution), spins=spins,
        frictions=np.full(n, mu), tangential_restitutions=np.full(n, beta),
    )
    energy = total_energy(world)
    start = energy
    for _ in range(800):
        event = world.step()
        assert event is not None
        now = total_energy(world)
        assert now <= energy * (1.0 + 1e-13), (event, now, energy)
        energy = now
    assert energy < start * (1.0 - 1e-6)  # friction or restitution took some


def test_a_free_ball_turns_at_its_spin_and_set_spin_carries_the_angle_over():
    world = exact2d.World(gravity=(0.0, -9.81))
    ball = world.add_ball((0.0, 0.0), (1.0, 5.0), 0.2, spin=0.7)
    world.advance_to(3.0)
    assert world.angle(ball) == pytest.approx(2.1, abs=1e-12)
    world.advance_to(10.0)
    assert world.angle(ball) == pytest.approx(7.0 - 2.0 * math.pi, abs=1e-12)
    assert -math.pi <= world.angles()[0] <= math.pi
    world.set_spin(ball, -2.0)
    assert world.spin(ball) == -2.0 and world.velocity(ball) == pytest.approx((1.0, 5.0 - 98.1), abs=1e-12)
    world.advance_to(11.0)
    assert world.angle(ball) == pytest.approx(math.remainder(7.0 - 2.0, 2.0 * math.pi), abs=1e-12)
    state = world.ball(ball)
    assert (state["spin"], state["inertia"], state["friction"], state["tangential_restitution"]) == (-2.0, 0.5, 0.0, 0.0)
    assert state["angle"] == world.angle(ball)
    # An angle set now turns on at the spin from there; a bad one is refused.
    world.set_angle(ball, 1.0)
    assert world.angle(ball) == 1.0
    world.advance_to(11.25)
    assert world.angle(ball) == pytest.approx(0.5, abs=1e-12)
    with pytest.raises(ValueError):
        world.set_angle(ball, math.nan)


def test_add_balls_takes_the_new_columns_aligned_with_the_arrays():
    world = exact2d.World(gravity=(0.0, 0.0))
    n = 6
    positions = np.stack([np.arange(n) * 2.0, np.zeros(n)], axis=1)
    spins, inertias = np.linspace(-3, 3, n), np.linspace(0.2, 1.0, n)
    frictions, betas = np.linspace(0.0, 1.0, n), np.linspace(-1.0, 1.0, n)
    handles = world.add_balls(
        positions, np.zeros((n, 2)), np.full(n, 0.5), spins=spins, inertias=inertias,
        frictions=frictions, tangential_restitutions=betas,
    )
    order = np.argsort(world.handles())
    np.testing.assert_array_equal(world.spins()[order], spins)
    np.testing.assert_array_equal(world.inertias()[order], inertias)
    np.testing.assert_array_equal(world.angles(), np.zeros(n))
    for arr in (world.spins(), world.angles(), world.inertias(), world.kinetic_energies()):
        assert arr.dtype == np.float64 and arr.shape == (n,)
    for h, mu, beta in zip(handles, frictions, betas):
        assert (world.ball(h)["friction"], world.ball(h)["tangential_restitution"]) == (mu, beta)
    np.testing.assert_allclose(world.kinetic_energies()[order], 0.5 * inertias * 0.25 * spins**2, rtol=1e-15)
    # Defaults: no spin, a uniform disk, frictionless.
    plain = world.add_balls([[20.0, 0.0]], [[0.0, 0.0]], [0.5])
    assert world.ball(plain[0])["inertia"] == 0.5 and world.spin(plain[0]) == 0.0
    empty = exact2d.World()
    assert empty.spins().shape == (0,) and empty.angles().shape == (0,)


def adding_ball(**kwargs):
    """A call adding a ball of radius 1 at the origin with `kwargs`."""
    return lambda w: w.add_ball((0, 0), (0, 0), 1.0, **kwargs)


@pytest.mark.parametrize(
    "call, message",
    [
        (adding_ball(friction=-1.0), r"friction must be finite and >= 0 \(got -1\)"),
        (adding_ball(friction=math.inf), r"friction must be finite and >= 0 \(got inf\)"),
        (adding_ball(tangential_restitution=2.0), r"tangential restitution must be in \[-1, 1\] \(got 2\)"),
        (adding_ball(inertia=0.0), r"inertia \(a factor of m r\^2\) must be in \(0, 1\] \(got 0\)"),
        (adding_ball(inertia=1.5), r"inertia \(a factor of m r\^2\) must be in \(0, 1\] \(got 1.5\)"),
        (adding_ball(spin=math.nan), "ball spin must be finite"),
        (lambda w: w.add_segment((0, 0), (1, 0), friction=-0.5), r"friction must be finite and >= 0 \(got -0.5\)"),
        (
            lambda w: w.add_circle((0, 0), 1.0, tangential_restitution=-1.5),
            r"tangential restitution must be in \[-1, 1\] \(got -1.5\)",
        ),
        (lambda w: w.set_spin(w.add_ball((0, 0), (0, 0), 1.0), math.nan), "ball spin must be finite"),
        (
            lambda w: w.add_balls([[0, 0], [3, 0]], [[0, 0], [0, 0]], [1, 1], frictions=[0.5, -1.0]),
            r"balls\[1\]: friction must be finite and >= 0 \(got -1\)",
        ),
        (
            lambda w: w.add_balls([[0, 0], [3, 0]], [[0, 0], [0, 0]], [1, 1], inertias=[0.5, 0.5, 0.5]),
            r"inertias must have shape \(2,\) like positions, got \(3,\)",
        ),
        (lambda w: w.add_balls([[0, 0]], [[0, 0]], [1], spins=["x"]), "spins must be an array of numbers"),
    ],
)
def test_bad_spin_and_friction_raise_invalid_input_naming_the_range(call, message):
    world = exact2d.World()
    with pytest.raises(exact2d.InvalidInputError, match=message) as info:
        call(world)
    assert isinstance(info.value, ValueError)
    assert world.ball_count <= 1  # add_balls adds nothing when it refuses


def test_set_spin_on_an_unknown_ball():
    with pytest.raises(exact2d.UnknownHandleError, match="no ball with handle 4"):
        exact2d.World().set_spin(4, 1.0)


def spinning_world():
    """A rough floor and walls under gravity, balls with spin, materials of their own."""
    world = exact2d.World(gravity=(0.0, -9.81))
    world.add_segment((0.0, 0.0), (10.0, 0.0), restitution=0.8, friction=0.6, tangential_restitution=0.3)
    world.add_segment((0.0, 0.0), (0.0, 10.0), friction=0.2)
    world.add_segment((10.0, 0.0), (10.0, 10.0), friction=0.2, tangential_restitution=-0.4)
    world.add_circle((5.0, 4.0), 0.5, friction=1.0, tangential_restitution=0.9)
    for i in range(6):
        world.add_ball(
            (1.0 + 1.5 * i, 2.0 + 0.3 * i), (2.0 - 0.7 * i, 1.0), 0.3, mass=1.0 + 0.1 * i, restitution=0.9,
            spin=3.0 * (i - 2.5), inertia=0.4 + 0.1 * i, friction=0.5, tangential_restitution=0.2 * i - 0.5,
        )
    return world


def test_pickling_mid_run_keeps_spins_angles_and_materials_bit_for_bit():
    world = spinning_world()
    world.remove_ball(1)
    world.advance_to(1.2345)
    assert np.count_nonzero(world.angles()) == 5
    clone = pickle.loads(pickle.dumps(world))
    assert clone.time == world.time
    np.testing.assert_array_equal(clone.handles(), world.handles())
    for name in ("positions", "velocities", "spins", "angles", "inertias", "masses", "radii", "kinetic_energies"):
        a, b = getattr(world, name)(), getattr(clone, name)()
        assert a.tobytes() == b.tobytes(), name  # bit for bit, the sign of zeros included
    keys = ("spin", "angle", "inertia", "friction", "tangential_restitution", "mass", "restitution", "radius", "groups")
    for h in world.handles():
        assert {k: clone.ball(h)[k] for k in keys} == {k: world.ball(h)[k] for k in keys}
    for h in world.collider_handles():
        assert clone.collider(h) == world.collider(h)
    assert clone.ball_count == 5
    assert clone.add_ball((8.0, 8.0), (0, 0), 0.1) == world.add_ball((8.0, 8.0), (0, 0), 0.1) == 6
    # The future agrees to rounding (restated at the pickled instant), the angles turning on.
    world.advance_to(1.3)
    clone.advance_to(1.3)
    mine, theirs = np.argsort(world.handles()), np.argsort(clone.handles())
    np.testing.assert_allclose(clone.positions()[theirs], world.positions()[mine], atol=1e-6)
    np.testing.assert_allclose(clone.spins()[theirs], world.spins()[mine], atol=1e-6)
    np.testing.assert_allclose(clone.angles()[theirs], world.angles()[mine], atol=1e-6)


def test_a_spinning_world_pickled_before_its_first_step_continues_bit_for_bit():
    world = spinning_world()
    clone = pickle.loads(pickle.dumps(world))
    a, b = world.advance_to_collect(2.0), clone.advance_to_collect(2.0)
    assert len(a["time"]) > 20
    for k in a:
        np.testing.assert_array_equal(a[k], b[k], err_msg=k)
    for name in ("positions", "velocities", "spins", "angles"):
        assert getattr(world, name)().tobytes() == getattr(clone, name)().tobytes(), name


def test_a_pickle_of_version_1_still_loads_with_the_default_materials():
    world = exact2d.World(gravity=(0.0, 0.0))
    world.add_segment((0.0, 0.0), (1.0, 0.0))
    world.add_ball((0.5, 1.0), (0.0, 1.0), 0.2, mass=2.0)
    state = json.loads(world.__getstate__())
    assert state["version"] == 4
    state["version"] = 1
    del state["table"]
    for c in state["colliders"]:
        del c["friction"], c["tangential_restitution"], c["rolling_resistance"]
    for b in state["balls"]:
        for key in ("spin", "roll", "angle", "inertia", "friction", "tangential_restitution", "rolling_resistance"):
            del b[key]
    old = exact2d.World()
    old.__setstate__(json.dumps(state))
    assert old.ball(0)["mass"] == 2.0 and old.ball(0)["inertia"] == 0.5 and old.spin(0) == 0.0
    assert old.collider(0)["friction"] == 0.0
    state["version"] = 5
    with pytest.raises(exact2d.InvalidInputError, match="not a pickled exact2d world: version"):
        exact2d.World().__setstate__(json.dumps(state))


def test_scenes_with_spin_and_friction_load_round_trip_and_run_in_parallel():
    scene = {
        "gravity": [0.0, 0.0],
        "segments": [{"a": [5.0, -5.0], "b": [5.0, 5.0], "friction": 0.25, "tangential_restitution": 0.1}],
        "circles": [{"center": [-5.0, 0.0], "radius": 1.0, "friction": 0.5}],
        "balls": [
            {"id": 3, "pos": [0.0, 0.0], "vel": [1.0, 0.0], "radius": 0.5, "spin": 4.0,
             "inertia": 0.4, "friction": 0.04, "tangential_restitution": 0.3},
            {"id": 8, "pos": [0.0, 3.0], "vel": [0.0, 0.0], "radius": 0.5},
        ],
    }
    world = exact2d.World.from_scene(scene)
    state = world.ball(3)
    assert (state["spin"], state["inertia"], state["friction"], state["tangential_restitution"]) == (4.0, 0.4, 0.04, 0.3)
    assert world.collider(0)["friction"] == 0.25 and world.collider(0)["tangential_restitution"] == 0.1
    assert world.collider(1)["friction"] == 0.5
    back = world.to_scene()
    assert back["balls"][0]["spin"] == 4.0 and back["balls"][0]["inertia"] == 0.4
    assert back["segments"][0]["friction"] == 0.25 and back["circles"][0]["friction"] == 0.5
    # Default values are left out, as in the files the CLI writes.
    assert "spin" not in back["balls"][1] and "inertia" not in back["balls"][1]
    assert exact2d.World.from_scene(back).to_scene() == back
    world.step()  # the rough bounce off the wall: mu = sqrt(0.04 * 0.25) = 0.1, P = 2
    assert world.spin(3) == pytest.approx(4.0 - 0.2 / (0.4 * 0.5), abs=1e-12)
    results = exact2d.run_many([scene, world], 6.0, threads=1)
    assert results[0]["spins"].dtype == np.float64 and results[0]["spins"].shape == (2,)
    assert results[0]["spins"][0] == world.spin(3) and results[0]["spins"][1] == 0.0
    copy_ = pickle.loads(pickle.dumps(world))  # what run_many ran: a copy of the world
    copy_.advance_to(6.0)
    assert results[1]["spins"].tobytes() == copy_.spins().tobytes()
    assert results[1]["angles"].tobytes() == copy_.angles().tobytes()
    assert results[1]["angles"][0] != 0.0
    with pytest.raises(exact2d.SceneError, match=r"^balls\[0\]\.inertia must be in \(0, 1\]$"):
        exact2d.World.from_scene({"balls": [{"id": 0, "pos": [0, 0], "vel": [0, 0], "radius": 1, "inertia": 1.5}]})
    with pytest.raises(exact2d.SceneError, match=r"^segments\[0\]\.friction must be >= 0$"):
        exact2d.World.from_scene({"segments": [{"a": [0, 0], "b": [1, 0], "friction": -1}], "balls": []})
