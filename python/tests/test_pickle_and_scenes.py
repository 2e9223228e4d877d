"""Pickling and scenes: round trips keep every bit of the state (and, before the first step,
of the future)."""

import copy
import json
import pickle

import exact2d
import numpy as np
import onemorebrick
import pytest
from conftest import assert_same_columns, box_world, gas_scene, run_columns


def test_a_world_pickled_before_its_first_step_continues_bit_for_bit():
    world = exact2d.World.from_scene(gas_scene(30, seed=3))
    world.add_circle((5.0, 5.0), 0.3, sensor=True)
    copy_ = pickle.loads(pickle.dumps(world))
    a, b = run_columns(world, 20.0), run_columns(copy_, 20.0)
    assert len(a["time"]) > 150
    assert_same_columns(a, b)
    np.testing.assert_array_equal(world.positions(), copy_.positions())


def test_a_world_pickled_mid_run_keeps_its_state_handles_and_settings():
    world = box_world(gravity=(0.0, -9.81))
    world.add_circle((5.0, 3.0), 0.5, restitution=0.5, groups=(1, 3))
    world.add_segment((2.0, 5.0), (3.0, 5.0), sensor=True)
    world.collapse_time = 1e-6
    world.sleeping = True
    for i in range(5):
        world.add_ball((1.0 + i, 4.0), (0.3 * i, 0.0), 0.2, mass=1.0 + i, restitution=0.9)
    world.remove_ball(2)
    world.advance_to(1.234)
    clone = pickle.loads(pickle.dumps(world))
    assert clone.time == world.time
    assert clone.gravity == world.gravity and clone.collapse_time == 1e-6 and clone.sleeping
    np.testing.assert_array_equal(clone.handles(), world.handles())
    np.testing.assert_array_equal(clone.positions(), world.positions())
    np.testing.assert_array_equal(clone.velocities(), world.velocities())
    np.testing.assert_array_equal(clone.masses(), world.masses())
    assert list(clone.collider_handles()) == list(world.collider_handles())
    for h in world.collider_handles():
        assert clone.collider(h) == world.collider(h)
    assert clone.add_ball((8.0, 5.0), (0, 0), 0.1) == world.add_ball((8.0, 5.0), (0, 0), 0.1) == 5
    # The future agrees to rounding (restated at the pickled instant, not bit for bit).
    # Arrays follow each world's slot order (handles() gives it): compare by handle.
    world.advance_to(1.5)
    clone.advance_to(1.5)
    mine, theirs = np.argsort(world.handles()), np.argsort(clone.handles())
    np.testing.assert_array_equal(world.handles()[mine], clone.handles()[theirs])
    np.testing.assert_allclose(clone.positions()[theirs], world.positions()[mine], atol=1e-6)
    assert copy.deepcopy(world).positions().shape == world.positions().shape


def test_to_scene_and_from_scene_round_trip():
    scene = gas_scene(12, seed=5)
    world = exact2d.World.from_scene(scene)
    again = exact2d.World.from_scene(world.to_scene())
    assert world.to_scene() == again.to_scene()
    back = world.to_scene()
    assert back["ball_ball"] is True
    assert [b["id"] for b in back["balls"]] == [b["id"] for b in scene["balls"]]
    assert [b["pos"] for b in back["balls"]] == [b["pos"] for b in scene["balls"]]
    assert_same_columns(run_columns(world, 5.0), run_columns(again, 5.0))
    with pytest.raises(exact2d.InvalidInputError, match="collider 0 is a sensor"):
        w = exact2d.World()
        w.add_circle((0, 0), 1.0, sensor=True)
        w.to_scene()


def test_from_scene_reads_the_repository_examples_like_the_cli(tmp_path):
    scene = {
        "segments": [{"a": [10.0, -5.0], "b": [10.0, 5.0]}],
        "balls": [{"id": 7, "pos": [0.0, 0.0], "vel": [2.0, 0.0], "radius": 0.5}],
    }
    path = tmp_path / "s.json"
    path.write_text(json.dumps(scene))
    world = exact2d.World.from_scene(str(path))
    event = world.step()
    # The scene module's own doctest: the ball reaches x = 9.5 at t = 4.75.
    assert (event.time, event.ball, event.collider) == (4.75, 7, 0)


def test_games_pickle_and_save_mid_volley(tmp_path):
    game = onemorebrick.Game(11)
    for _ in range(3):
        game.play(game.aim_for(0.4))
    game.shoot(game.aim_for(-0.2))
    game.advance_to(0.7)
    clone = pickle.loads(pickle.dumps(game))
    path = tmp_path / "game.json"
    game.save(path)
    loaded = onemorebrick.Game.load(path)
    reports = [g.finish_round() for g in (game, clone, loaded)]
    assert reports[0] == reports[1] == reports[2]
    for g in (clone, loaded):
        np.testing.assert_array_equal(g.board(), game.board())
        assert (g.level, g.score, g.balls, g.launch_x) == (game.level, game.score, game.balls, game.launch_x)
