"""onemorebrick: the rules of One More Brick, and a Gymnasium environment for them.

A brick breaker in the style of One More Brick and Ballz: aim from the launcher, a volley of
balls flies out, each bounce off a brick takes one hit point, and when every ball is back
the rows move down; the game is over when a brick reaches the bottom row. Every ball moves
in the exact2d engine, so the game is deterministic: the same seed and shots give the same
game, bit for bit.

>>> import onemorebrick
>>> game = onemorebrick.Game(seed=7)
>>> report = game.play(game.aim_for(0.3))
>>> game.level
2

Importing the package registers the environment ``OneMoreBrick-v0`` with Gymnasium
(``gymnasium.make("OneMoreBrick-v0")``); see ``OneMoreBrickEnv``.
"""

from exact2d._errors import (
    GameError,
    InvalidAimError,
    InvalidConfigError,
    SaveError,
    TimeBeforeNowError,
    WrongPhaseError,
)
from exact2d._native import CELL_KINDS, PICKUP_KINDS, Game, GreedyBot, RandomBot
from onemorebrick.env import OneMoreBrickEnv

__all__ = [
    "Game",
    "RandomBot",
    "GreedyBot",
    "OneMoreBrickEnv",
    "CELL_KINDS",
    "PICKUP_KINDS",
    "GameError",
    "InvalidAimError",
    "InvalidConfigError",
    "SaveError",
    "TimeBeforeNowError",
    "WrongPhaseError",
]


def _register() -> None:
    import gymnasium

    if "OneMoreBrick-v0" not in gymnasium.registry:
        gymnasium.register(id="OneMoreBrick-v0", entry_point="onemorebrick.env:OneMoreBrickEnv")


_register()
