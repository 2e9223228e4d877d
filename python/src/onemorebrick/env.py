"""``OneMoreBrickEnv``: One More Brick as a Gymnasium environment.

One step is one shot, simulated (in Rust, exactly) to the end of the round.

Observation (a ``spaces.Dict``):

- ``"board"``: int32, shape ``(rows, columns, 2)`` (9 x 7 by default); ``board[row, column]``
  is ``(kind, hit points)`` with row 0 (the launcher's) at the bottom. Kinds: 0 empty,
  1 square brick, 2-5 triangular bricks (open corner top-left, top-right, bottom-left,
  bottom-right), 6 round obstacle, 7-18 pick-ups in the order of
  ``onemorebrick.PICKUP_KINDS``. Hit points are 0 for anything but a brick.
- ``"balls"``: int32, shape ``(1,)``: the balls the next volley fires (at least 1).
- ``"launcher"``: float64, shape ``(1,)``: the launcher's x, in cells from the left wall,
  in ``[ball_radius, columns - ball_radius]``.

Action: float32, shape ``(1,)``, in ``[-1, 1]``: the aim. ``-1`` is the flattest legal aim
to the left (the minimum elevation, about 8.5 degrees), ``0`` straight up, ``1`` the
flattest to the right; the elevation grows monotonically between them (``Game.aim_for``),
so the interval covers exactly the legal directions. An action outside it (or NaN) raises
``InvalidAimError``.

Reward: the hit points taken off bricks this round (ball bounces and lasers), the game's
score increase; with ``reward="bricks"``, the number of bricks destroyed this round instead.

Episode end: ``terminated`` when a brick reaches the bottom row (game over);
``truncated`` after ``max_rounds`` rounds if given (default: never).

``reset(seed=s)`` starts ``Game(seed)`` with a game seed drawn from the environment's
generator seeded by ``s``: the same seed and actions give the same observations, bit for bit.
``render_mode="rgb_array"``: ``render()`` returns the board drawn in software (tiny-skia), an
RGB ``uint8`` array of shape ``(rows * cell, columns * cell, 3)``, in the desktop game's
colours: bricks with their hit points (shortened past four digits, "12.3k"), pick-ups with
their labels, the balls in flight or the launcher with its ball count ("x 35").

``info``: ``level``, ``score``, ``balls``, ``damage``, ``bricks_destroyed``, ``collisions``.
"""

from __future__ import annotations

from typing import Any, Mapping, Optional

import gymnasium
import numpy as np
from gymnasium import spaces

from exact2d._errors import InvalidAimError
from exact2d._native import CELL_KINDS, Game

_MAX_INT32 = np.iinfo(np.int32).max


class OneMoreBrickEnv(gymnasium.Env):
    """One More Brick: one step is one shot played to the end of its round.

    Parameters: ``render_mode`` (``None`` or ``"rgb_array"``), ``max_rounds`` (truncate
    after that many rounds; ``None``: never), ``reward`` (``"damage"``, the default, or
    ``"bricks"``), ``config`` (a dict of game settings, see ``onemorebrick.Game``),
    ``cell_pixels`` (the frame's cell size in pixels, 4 to 256, default 32).
    """

    metadata = {"render_modes": ["rgb_array"], "render_fps": 4}

    def __init__(
        self,
        render_mode: Optional[str] = None,
        max_rounds: Optional[int] = None,
        reward: str = "damage",
        config: Optional[dict] = None,
        cell_pixels: int = 32,
    ) -> None:
        if render_mode is not None and render_mode not in self.metadata["render_modes"]:
            raise ValueError(f"render_mode must be None or 'rgb_array' (got {render_mode!r})")
        if reward not in ("damage", "bricks"):
            raise ValueError(f"reward must be 'damage' or 'bricks' (got {reward!r})")
        if max_rounds is not None and not (isinstance(max_rounds, int) and max_rounds >= 1):
            raise ValueError(f"max_rounds must be None or an integer >= 1 (got {max_rounds!r})")
        self.render_mode = render_mode
        self.max_rounds = max_rounds
        self.reward_kind = reward
        self.config = dict(config) if config else None
        self.cell_pixels = cell_pixels
        self._game = Game(0, self.config)
        if render_mode is not None:
            # A frame's size is checked now, not at the first render().
            self._game.render(cell_pixels)
        rows, columns = self._game.rows, self._game.columns
        radius = self._ball_radius()
        low = np.zeros((rows, columns, 2), dtype=np.int32)
        high = np.empty((rows, columns, 2), dtype=np.int32)
        high[..., 0] = CELL_KINDS - 1
        high[..., 1] = _MAX_INT32
        self.observation_space = spaces.Dict(
            {
                "board": spaces.Box(low=low, high=high, dtype=np.int32),
                "balls": spaces.Box(low=1, high=_MAX_INT32, shape=(1,), dtype=np.int32),
                "launcher": spaces.Box(
                    low=radius, high=columns - radius, shape=(1,), dtype=np.float64
                ),
            }
        )
        self.action_space = spaces.Box(low=-1.0, high=1.0, shape=(1,), dtype=np.float32)
        self._rounds = 0

    def _ball_radius(self) -> float:
        config = self.config or {}
        return float(config.get("ball_radius", 0.15))

    @property
    def game(self) -> Game:
        """The game being played (read it; changing it breaks the episode's bookkeeping)."""
        return self._game

    def _observation(self) -> dict:
        return {
            "board": self._game.board(),
            "balls": np.array([min(self._game.balls, _MAX_INT32)], dtype=np.int32),
            "launcher": np.array([self._game.launch_x], dtype=np.float64),
        }

    def _info(self, report: Optional[Mapping[str, Any]] = None) -> dict:
        report = report or {}
        return {
            "level": self._game.level,
            "score": self._game.score,
            "balls": self._game.balls,
            "damage": report.get("damage", 0),
            "bricks_destroyed": report.get("bricks_destroyed", 0),
            "collisions": report.get("collisions", 0),
        }

    def reset(self, *, seed: Optional[int] = None, options: Optional[dict] = None):
        """Starts a new game; with ``seed``, the same one every time."""
        super().reset(seed=seed)
        game_seed = int(self.np_random.integers(0, 2**63 - 1))
        self._game = Game(game_seed, self.config)
        self._rounds = 0
        return self._observation(), self._info()

    def step(self, action: Any):
        """Shoots along ``action`` (see the module documentation) and plays the round out."""
        a = np.asarray(action, dtype=np.float64).reshape(-1)
        if a.shape != (1,):
            raise InvalidAimError(f"invalid aim: the action must have shape (1,) (got {np.shape(action)})")
        if self._game.game_over:
            raise RuntimeError("the episode is over: call reset()")
        report = self._game.play(self._game.aim_for(float(a[0])))
        self._rounds += 1
        reward = report["damage"] if self.reward_kind == "damage" else report["bricks_destroyed"]
        terminated = bool(report["game_over"])
        truncated = (
            not terminated and self.max_rounds is not None and self._rounds >= self.max_rounds
        )
        return self._observation(), float(reward), terminated, bool(truncated), self._info(report)

    def render(self):
        """The board as an RGB array (``render_mode="rgb_array"``); ``None`` otherwise."""
        if self.render_mode != "rgb_array":
            return None
        return self._game.render(self.cell_pixels)
