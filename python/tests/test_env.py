"""The Gymnasium environment: check_env, determinism, a random game to its end, vector envs."""

import warnings

import exact2d
import gymnasium
import numpy as np
import onemorebrick
import pytest
from gymnasium.utils.env_checker import check_env


def test_check_env_passes_without_warnings():
    env = gymnasium.make("OneMoreBrick-v0", render_mode="rgb_array").unwrapped
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        check_env(env)
    env.close()


def test_the_spaces_are_as_documented():
    env = onemorebrick.OneMoreBrickEnv()
    obs, info = env.reset(seed=0)
    assert obs["board"].shape == (9, 7, 2) and obs["board"].dtype == np.int32
    assert obs["balls"].tolist() == [1] and obs["launcher"].dtype == np.float64
    assert env.action_space.shape == (1,) and env.action_space.low[0] == -1.0
    assert obs in env.observation_space
    # The top row holds the new bricks; the launcher's row is empty.
    assert (obs["board"][-1, :, 0] > 0).any() and (obs["board"][0] == 0).all()
    assert info["level"] == 1


def test_the_action_interval_covers_exactly_the_legal_aims():
    game = onemorebrick.Game(0)
    t = game.min_elevation_tan
    for a in np.linspace(-1, 1, 101):
        dx, dy = game.aim_for(a)
        assert dy > 0 and dy >= t * abs(dx)
        assert np.sign(dx) == np.sign(a) or abs(dx) < 1e-15
    for a in (-1.0, 1.0):
        dx, dy = game.aim_for(a)
        assert dy == t * abs(dx)  # exactly the minimum elevation
    assert game.aim_for(0.0)[0] == 0.0
    elevation = [np.arctan2(*game.aim_for(a)[::-1]) for a in np.linspace(0, 1, 50)]
    assert np.all(np.diff(elevation) < 0)  # monotone from straight up to the flattest
    with pytest.raises(onemorebrick.InvalidAimError):
        onemorebrick.OneMoreBrickEnv().step(np.array([1.01], dtype=np.float32))


def rollout(seed, actions):
    env = onemorebrick.OneMoreBrickEnv()
    observations = [env.reset(seed=seed)[0]]
    rewards = []
    for a in actions:
        obs, reward, terminated, truncated, _ = env.step(np.array([a], dtype=np.float32))
        observations.append(obs)
        rewards.append(reward)
        if terminated:
            break
    return observations, rewards


def test_reset_with_a_seed_is_deterministic_bit_for_bit():
    actions = np.random.default_rng(3).uniform(-1, 1, size=15)
    a, ra = rollout(42, actions)
    b, rb = rollout(42, actions)
    c, _ = rollout(43, actions)
    assert ra == rb
    for x, y in zip(a, b):
        for key in x:
            np.testing.assert_array_equal(x[key], y[key])
    assert any(not np.array_equal(x["board"], y["board"]) for x, y in zip(a, c))


def test_a_random_policy_plays_to_game_over_and_rewards_add_up_to_the_score():
    env = onemorebrick.OneMoreBrickEnv()
    env.action_space.seed(5)
    obs, info = env.reset(seed=5)
    total, steps, terminated, truncated = 0.0, 0, False, False
    while not (terminated or truncated):
        obs, reward, terminated, truncated, info = env.step(env.action_space.sample())
        assert obs in env.observation_space and reward >= 0
        total += reward
        steps += 1
        assert steps < 10_000
    assert terminated and not truncated and env.game.game_over
    assert total == info["score"] == env.game.score
    # The level of the round that ended the game (one round per step from level 1).
    assert info["level"] == steps
    with pytest.raises(RuntimeError, match="reset"):
        env.step(env.action_space.sample())


def test_bricks_reward_and_round_limit():
    env = onemorebrick.OneMoreBrickEnv(reward="bricks", max_rounds=3)
    env.reset(seed=1)
    bricks, truncated = 0, False
    for _ in range(3):
        _, reward, terminated, truncated, info = env.step(np.array([0.3], dtype=np.float32))
        assert reward == info["bricks_destroyed"]
        bricks += reward
    assert truncated and not terminated


def test_render_returns_an_rgb_frame_that_shows_the_board():
    env = onemorebrick.OneMoreBrickEnv(render_mode="rgb_array", cell_pixels=20)
    env.reset(seed=0)
    frame = env.render()
    assert frame.shape == (9 * 20, 7 * 20, 3) and frame.dtype == np.uint8
    board = env.game.board()
    # A brick's cell centre is not the background colour; an empty cell's is.
    background = frame[0, 0].tolist()
    for row in range(9):
        for column in range(7):
            y, x = (8 - row) * 20 + 10, column * 20 + 10
            if board[row, column, 0] == 1:
                assert frame[y, x].tolist() != background
            if board[row, column, 0] == 0 and row > 0:
                assert frame[y, x].tolist() == background
    assert onemorebrick.OneMoreBrickEnv().render() is None
    with pytest.raises(exact2d.InvalidInputError, match=r"cell must be in \[4, 256\] \(got 2\)"):
        onemorebrick.OneMoreBrickEnv(render_mode="rgb_array", cell_pixels=2)


@pytest.mark.parametrize("vector", [gymnasium.vector.SyncVectorEnv, gymnasium.vector.AsyncVectorEnv])
def test_vector_envs(vector):
    envs = vector([lambda: gymnasium.make("OneMoreBrick-v0") for _ in range(2)])
    obs, _ = envs.reset(seed=[7, 8])
    assert obs["board"].shape == (2, 9, 7, 2)
    single, _ = onemorebrick.OneMoreBrickEnv().reset(seed=7)
    np.testing.assert_array_equal(obs["board"][0], single["board"])
    for _ in range(5):
        obs, rewards, terminated, truncated, _ = envs.step(np.array([[0.5], [-0.5]], dtype=np.float32))
        assert rewards.shape == (2,) and obs["launcher"].shape == (2, 1)
    envs.close()
