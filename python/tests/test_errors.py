"""Every error class, with its message; bad input never panics."""

import json
import math

import exact2d
import numpy as np
import onemorebrick
import pytest
from conftest import box_world


def test_the_classes_subclass_value_error_for_bad_input():
    for cls in [
        exact2d.InvalidInputError,
        exact2d.OverlapError,
        exact2d.UnknownHandleError,
        exact2d.TimeBeforeNowError,
        exact2d.SceneError,
        onemorebrick.InvalidAimError,
        onemorebrick.InvalidConfigError,
        onemorebrick.SaveError,
    ]:
        assert issubclass(cls, ValueError) and issubclass(cls, exact2d.Error)
    assert issubclass(exact2d.StalledError, RuntimeError)
    assert issubclass(onemorebrick.WrongPhaseError, onemorebrick.GameError)
    assert issubclass(exact2d.UnknownHandleError, LookupError)


@pytest.mark.parametrize(
    "call, message",
    [
        (lambda w: w.add_ball((0, 0), (0, 0), -1.0), r"radius must be > 0 \(got -1\)"),
        (lambda w: w.add_ball((0, 0), (0, 0), math.nan), r"radius must be > 0 \(got NaN\)"),
        (lambda w: w.add_ball((math.nan, 0), (0, 0), 1.0), "ball position must be finite"),
        (lambda w: w.add_ball((0, 0), (math.inf, 0), 1.0), "ball velocity must be finite"),
        (lambda w: w.add_ball((0, 0), (0, 0), 1.0, mass=0.0), r"mass must be > 0 \(got 0\)"),
        (lambda w: w.add_ball((0, 0), (0, 0), 1.0, restitution=1.5), r"restitution must be in \[0, 1\] \(got 1.5\)"),
        (lambda w: w.add_ball((0, 0, 0), (0, 0), 1.0), r"pos must be a pair of numbers \(x, y\), got 3 numbers"),
        (lambda w: w.add_ball("ab", (0, 0), 1.0), r"pos must be a pair of numbers"),
        (lambda w: w.add_ball((0, 0), (0, 0), 1.0, groups=(-1, 0)), r"groups must be a pair of integers"),
        (lambda w: w.add_segment((1, 1), (1, 1)), "segment end points must be distinct"),
        (lambda w: w.add_circle((0, 0), 0.0), r"radius must be > 0 \(got 0\)"),
        (lambda w: setattr(w, "collapse_time", -1.0), r"collapse time must be finite and >= 0 \(got -1\)"),
        (lambda w: setattr(w, "gravity", (math.nan, 0.0)), "gravity must be finite"),
        (lambda w: w.bounce_path((0, 0), (1, 0), 0.1, -1), r"bounces must be in \[0, 1048576\] \(got -1\)"),
        (lambda w: w.cast_ball((0, 0), (1, 0), 0.1, max_time=-1.0), r"max_time must be >= 0"),
        (lambda w: exact2d.run_many([], 1.0, threads=0), r"threads must be in \[1, 1024\] \(got 0\)"),
    ],
)
def test_bad_numbers_raise_invalid_input_with_the_rust_message(call, message):
    with pytest.raises(exact2d.InvalidInputError, match=message):
        call(exact2d.World())


def test_add_balls_is_all_or_nothing_and_names_the_index():
    world = box_world()
    positions = np.array([[1.0, 1.0], [2.0, 1.0], [2.1, 1.0]])
    with pytest.raises(exact2d.OverlapError, match=r"balls\[2\]: overlaps ball 1"):
        world.add_balls(positions, np.zeros((3, 2)), np.full(3, 0.2))
    assert world.ball_count == 0
    with pytest.raises(exact2d.InvalidInputError, match=r"velocities must have shape \(3, 2\)"):
        world.add_balls(positions, np.zeros((2, 2)), np.full(3, 0.2))
    with pytest.raises(exact2d.InvalidInputError, match=r"radii must have shape \(3,\)"):
        world.add_balls(positions, np.zeros((3, 2)), np.full(2, 0.2))
    with pytest.raises(exact2d.InvalidInputError, match=r"positions must have shape \(n, 2\)"):
        world.add_balls(np.zeros((3, 3)), np.zeros((3, 2)), np.full(3, 0.2))


def test_overlaps_name_the_other_body_by_its_handle():
    world = box_world()
    world.add_ball((5.0, 3.0), (0.0, 0.0), 0.5)
    with pytest.raises(exact2d.OverlapError, match="overlaps ball 0"):
        world.add_ball((5.5, 3.0), (0.0, 0.0), 0.5)
    with pytest.raises(exact2d.OverlapError, match="overlaps collider 0"):
        world.add_ball((5.0, 0.1), (0.0, 0.0), 0.5)


def test_time_before_now():
    world = exact2d.World()
    world.advance_to(1.0)
    with pytest.raises(exact2d.TimeBeforeNowError, match="time 0.5 is before the world's time 1"):
        world.advance_to(0.5)
    with pytest.raises(exact2d.TimeBeforeNowError, match="time NaN is before"):
        world.step_until(math.nan)


def test_unknown_handles():
    world = exact2d.World()
    with pytest.raises(exact2d.UnknownHandleError, match="no ball with handle 3"):
        world.set_velocity(3, (0.0, 0.0))
    with pytest.raises(exact2d.UnknownHandleError, match="no collider with handle -7"):
        world.remove_collider(-7)


def test_scene_errors_carry_the_cli_messages(tmp_path):
    bad = {"balls": [{"id": 0, "pos": [0, 0], "vel": [0, 0], "radius": 0}]}
    with pytest.raises(exact2d.SceneError, match=r"^balls\[0\]\.radius must be > 0$"):
        exact2d.World.from_scene(bad)
    path = tmp_path / "scene.json"
    path.write_text(json.dumps(bad))
    with pytest.raises(exact2d.SceneError, match=r"scene\.json: balls\[0\]\.radius must be > 0"):
        exact2d.World.from_scene(path)
    overlapping = {
        "ball_ball": True,
        "balls": [
            {"id": 0, "pos": [0, 0], "vel": [0, 0], "radius": 1},
            {"id": 1, "pos": [1, 0], "vel": [0, 0], "radius": 1},
        ],
    }
    with pytest.raises(exact2d.SceneError, match=r"balls\[1\] overlaps balls\[0\]"):
        exact2d.World.from_scene(overlapping)
    with pytest.raises(exact2d.SceneError, match="unknown field"):
        exact2d.World.from_scene({"balls": [], "colour": 3})
    with pytest.raises(exact2d.InvalidInputError, match="a scene must be a dict or a path"):
        exact2d.World.from_scene(3)
    with pytest.raises(OSError, match="cannot read the scene"):
        exact2d.World.from_scene(tmp_path / "missing.json")


def test_game_errors():
    game = onemorebrick.Game(1)
    with pytest.raises(onemorebrick.InvalidAimError, match="invalid aim: flatter than the minimum elevation"):
        game.shoot((1.0, 0.01))
    with pytest.raises(onemorebrick.InvalidAimError, match="invalid aim: the aim must point upward"):
        game.shoot((0.0, -1.0))
    with pytest.raises(onemorebrick.InvalidAimError, match="invalid aim: components must be finite"):
        game.shoot((math.nan, 1.0))
    with pytest.raises(onemorebrick.InvalidAimError, match=r"the action must be in \[-1, 1\] \(got 1.5\)"):
        game.aim_for(1.5)
    with pytest.raises(onemorebrick.WrongPhaseError, match="this needs the Volley phase, the game is in Aiming"):
        game.finish_round()
    game.shoot((0.2, 1.0))
    with pytest.raises(onemorebrick.WrongPhaseError, match="this needs the Aiming phase, the game is in Volley"):
        game.shoot((0.2, 1.0))
    with pytest.raises(onemorebrick.InvalidConfigError, match="columns and rows must be in 3..=64"):
        onemorebrick.Game(1, {"columns": 2})
    with pytest.raises(onemorebrick.InvalidConfigError, match='unknown setting "colour"'):
        onemorebrick.Game(1, {"colour": 2})
    with pytest.raises(onemorebrick.SaveError, match="<text>"):
        onemorebrick.Game.from_json("{not json")
    with pytest.raises(exact2d.InvalidInputError, match=r"candidates must be in \[1, 4096\]"):
        onemorebrick.GreedyBot(0)


def test_seeds_and_frames_are_checked():
    with pytest.raises(exact2d.InvalidInputError, match=r"seed must be an integer in \[0, 2\*\*64 - 1\]"):
        onemorebrick.Game(-1)
    with pytest.raises(exact2d.InvalidInputError, match="seed must be an integer"):
        onemorebrick.RandomBot(2**64)
    with pytest.raises(exact2d.InvalidInputError, match=r"cell must be in \[4, 256\] \(got 456\)"):
        onemorebrick.Game(1).render(456)
    with pytest.raises(exact2d.InvalidInputError, match=r"cell must be in \[4, 256\] \(got -3\)"):
        onemorebrick.Game(1).render(-3)
    with pytest.raises(exact2d.InvalidInputError, match=r"cell must be in \[4, 256\] \(got 3\)"):
        onemorebrick.Game(1).render(3)
    big = onemorebrick.Game(1, {"columns": 64, "rows": 64})
    with pytest.raises(exact2d.InvalidInputError, match=r"cell must be at most 64 for a board 64 cells across \(got 65\)"):
        big.render(65)


def test_scene_dicts_may_hold_numpy_values_but_not_nan():
    scene = {
        "balls": [{"id": 0, "pos": np.array([1.0, 2.0]), "vel": [np.float64(1.0), 0], "radius": 0.5}]
    }
    world = exact2d.World.from_scene(scene)
    assert world.position(0) == (1.0, 2.0)
    scene["balls"][0]["pos"] = [1.0, math.nan]
    with pytest.raises(exact2d.SceneError, match=r"^balls\[0\]\.pos\[1\] must be finite$"):
        exact2d.World.from_scene(scene)
