"""The exceptions of exact2d and onemorebrick.

Every refusal of the engine or the game is one of these, carrying the Rust message. Bad
input (a number out of range, an unknown handle, a malformed scene) is an
``InvalidInputError``, a ``ValueError``; nothing a caller passes can raise a Rust panic.
"""


class Exact2dError(Exception):
    """Base class of every exception raised by exact2d and onemorebrick."""


class InvalidInputError(Exact2dError, ValueError):
    """An argument out of range or of the wrong shape: the message names it and its range."""


class OverlapError(InvalidInputError):
    """A new body would overlap a body it interacts with (touching is allowed)."""


class UnknownHandleError(InvalidInputError, LookupError):
    """No live ball or collider has this handle (it was removed, or never existed)."""


class TimeBeforeNowError(InvalidInputError):
    """A time before the world's (or the volley's) clock, or NaN, was asked for."""


class SceneError(InvalidInputError):
    """A scene the format refuses; the message is the CLI's (prefixed by the file's path)."""


class StalledError(Exact2dError, RuntimeError):
    """The engine's safety net: more events at one instant than its zero-time chains allow."""


class GameError(Exact2dError):
    """A refusal of the One More Brick rules."""


class InvalidAimError(GameError, ValueError):
    """An aim that is not finite, points downward or is flatter than the minimum elevation."""


class InvalidConfigError(GameError, ValueError):
    """A game setting out of range, or an unknown one."""


class WrongPhaseError(GameError, RuntimeError):
    """The call needs another phase of the round (shoot while aiming, finish during a volley)."""


class SaveError(GameError, ValueError):
    """A save file (or text) that is not a readable One More Brick game."""


for _cls in list(globals().values()):
    if isinstance(_cls, type) and issubclass(_cls, Exact2dError):
        # Shown as exact2d.X or onemorebrick.X in tracebacks, where users import them from.
        _cls.__module__ = "onemorebrick" if issubclass(_cls, GameError) else "exact2d"
del _cls

__all__ = [
    "Exact2dError",
    "InvalidInputError",
    "OverlapError",
    "UnknownHandleError",
    "TimeBeforeNowError",
    "SceneError",
    "StalledError",
    "GameError",
    "InvalidAimError",
    "InvalidConfigError",
    "WrongPhaseError",
    "SaveError",
]
