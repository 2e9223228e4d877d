"""Type stubs of the native module ``exact2d._native`` (the engine and the game's rules).

Import ``exact2d`` and ``onemorebrick`` rather than this module.
"""

import os
from typing import Any, Literal, Mapping, Optional, Sequence, Tuple, TypedDict, Union, final

import numpy as np
import numpy.typing as npt

_Pair = Union[Tuple[float, float], Sequence[float], npt.NDArray[np.float64]]
_Groups = Tuple[int, int]
_ScenePath = Union[str, "os.PathLike[str]"]
_F64 = npt.NDArray[np.float64]
_I64 = npt.NDArray[np.int64]

EVENT_KINDS: list[str]
PICKUP_KINDS: list[str]
CELL_KINDS: int

@final
class Event:
    """Something that happened at an exact time (see ``World.step``)."""

    time: float
    kind: Literal["contact", "ball_contact", "sensor_enter", "sensor_exit"]
    ball: int
    other_ball: Optional[int]
    collider: Optional[int]
    feature: Optional[Literal["segment", "end_a", "end_b", "circle"]]
    point: Tuple[float, float]
    normal: Optional[Tuple[float, float]]
    impulse: float
    normal_speed: float
    tangential_impulse: float
    @property
    def bodies(self) -> Tuple[int, int]:
        """``(ball, other_ball)`` or ``(ball, collider)``."""

@final
class CastHit:
    """Where a cast ball touches a collider."""

    time: float
    position: Tuple[float, float]
    velocity: Tuple[float, float]
    point: Tuple[float, float]
    normal: Tuple[float, float]
    collider: int

class _EventColumns(TypedDict):
    """A run's events as NumPy columns, one row per event."""

    time: _F64
    kind: npt.NDArray[np.int8]
    ball: _I64
    other_ball: _I64
    collider: _I64
    point: _F64
    normal: _F64
    impulse: _F64
    normal_speed: _F64
    tangential_impulse: _F64

class _BallState(TypedDict):
    position: Tuple[float, float]
    velocity: Tuple[float, float]
    acceleration: Tuple[float, float]
    radius: float
    mass: float
    restitution: float
    groups: Tuple[int, int]
    asleep: bool
    support: Optional[int]
    spin: float
    roll: Tuple[float, float]
    angle: float
    inertia: float
    friction: float
    tangential_restitution: float
    rolling_resistance: float

class _Table(TypedDict):
    """A table's cloth (see ``World.set_table``)."""

    gravity: float
    sliding_friction: float
    rolling_friction: float
    spinning_friction: float

_TableLike = Mapping[str, float]

class _RunResult(TypedDict):
    """One world at ``until`` (see ``run_many``), every array in the order of ``handles``.

    ``unwrapped`` is ``World.unwrapped_positions()`` (``positions`` outside a periodic box),
    ``collision_virial`` and ``observables_since`` the ``World`` properties.
    """

    handles: _I64
    positions: _F64
    velocities: _F64
    spins: _F64
    angles: _F64
    rolls: _F64
    unwrapped: _F64
    collision_virial: float
    observables_since: float
    events: int
    time: float

@final
class World:
    """An exact, event-driven 2D world of balls and static colliders."""

    def __init__(
        self,
        gravity: Optional[_Pair] = None,
        table: Optional[_TableLike] = None,
        periodic: Optional[_Pair] = None,
    ) -> None:
        """An empty world at time 0; gravity defaults to ``(0.0, -9.81)``, or ``(0, 0)`` with a table or a periodic box.

        ``table``: a dict of some of ``gravity``, ``sliding_friction``, ``rolling_friction``
        and ``spinning_friction`` (the others a pool table's; ``{}`` is a pool table) makes
        the world a table seen from above (see ``set_table``). ``periodic``: ``(Lx, Ly)``
        makes it a periodic box (see ``periodic``).
        """
    @property
    def time(self) -> float: ...
    gravity: Tuple[float, float]
    @property
    def table(self) -> Optional[_Table]:
        """The table's cloth (a dict of its four values), or ``None`` without a table."""
    def set_table(
        self,
        table: Optional[_TableLike] = ...,
        *,
        gravity: Optional[float] = None,
        sliding_friction: Optional[float] = None,
        rolling_friction: Optional[float] = None,
        spinning_friction: Optional[float] = None,
    ) -> None:
        """Makes the world a table seen from above (billiards, pool), or ``set_table(None)`` not.

        The world's plane is the cloth; ``gravity`` (> 0) pulls every ball into it and each
        ball slides, rolls and spins to rest under the cloth's friction, each change at its
        analytic time (counted in ``event_counts()["phase_ends"]``): sliding, friction
        ``sliding_friction * gravity`` acts against the contact point's slip
        ``u = v + r (-roll_y, roll_x)`` until it vanishes (after ``2 |u| / (7 mu_s g)`` for a
        sphere, ``inertia=0.4``); rolling, the ball loses ``rolling_friction * gravity`` of
        speed a second; its spin loses ``spinning_friction * gravity / (k r)`` a second.

        ``table``: a dict of some of the four values (the others a pool table's: gravity
        9.81, sliding_friction 0.2, rolling_friction 0.01, spinning_friction 0.0127); not
        given, a pool table; ``None`` takes the table away (balls keep their velocities and
        lose their rolls). Keywords set single values on top. The world's gravity must be
        ``(0, 0)``; a value out of range raises ``InvalidInputError`` naming it.
        """
    @property
    def periodic(self) -> Optional[Tuple[float, float]]:
        """The periodic box ``(Lx, Ly)``, or ``None``; set once, on a world without balls, gravity or table.

        The box ``[0, Lx) x [0, Ly)`` has its opposite edges glued: a ball leaving through one
        comes back through the other and balls meet through their nearest images. Positions
        come out in the box; ``unwrapped_positions()`` adds the box lengths each ball has
        crossed. Balls must be inside the box and of radius at most ``min(Lx, Ly) / 6.6``;
        colliders keep clear of its edges by more than the largest ball's radius
        (``InvalidInputError`` otherwise, naming the problem). ``None`` on a periodic world
        raises: a box cannot be taken away.
        """
    @periodic.setter
    def periodic(self, size: Optional[_Pair]) -> None: ...
    @property
    def collision_virial(self) -> float:
        """The sum over ball-ball impulses of ``(p_i - p_j) . J_i`` since ``observables_since`` (kg m^2/s).

        Without gravity, over a time ``t``, ``N`` balls of mean kinetic energy ``kT``:
        ``P A = N kT + W / (2 t)``, so ``Z = 1 + W / (2 t N kT)``.
        """
    @property
    def observables_since(self) -> float:
        """When the observables started counting: 0, or the last ``reset_observables()``."""
    def reset_observables(self) -> None:
        """Zeroes the virial and every collider's momentum and impacts; they count from now."""
    def collider_momentum(self, handle: int) -> Tuple[float, float]:
        """The momentum the balls gave a collider since ``observables_since`` (an elastic bounce: ``2 m u``)."""
    def collider_impacts(self, handle: int) -> int:
        """The number of ``contact`` events on a collider since ``observables_since``."""
    collapse_time: float
    sleeping: bool
    @property
    def ball_count(self) -> int: ...
    @property
    def collider_count(self) -> int: ...
    @property
    def sleeping_count(self) -> int: ...
    def event_counts(self) -> dict[str, int]:
        """Events handled so far by kind, the internal ones (``settles``, ``phase_ends``, ...) too."""
    def add_ball(
        self,
        pos: _Pair,
        vel: _Pair,
        radius: float,
        mass: float = 1.0,
        restitution: float = 1.0,
        groups: Optional[_Groups] = None,
        spin: float = 0.0,
        inertia: float = 0.5,
        friction: float = 0.0,
        tangential_restitution: float = 0.0,
        rolling_resistance: float = 0.0,
        roll: Optional[_Pair] = None,
    ) -> int:
        """Adds a ball now; returns its handle (never reused).

        ``spin``: angular velocity (rad/s, counter-clockwise positive); ``inertia``: the
        moment of inertia over ``m r**2``, in (0, 1]; ``friction``: Coulomb's ``mu >= 0``;
        ``tangential_restitution``: ``beta`` in [-1, 1] (-1 smooth, 0 sticking, 1 perfectly
        rough); ``rolling_resistance``: ``c >= 0``, a rolling ball loses ``c g_n`` of speed a
        second. A pair's ``mu`` is the geometric mean of its two, its ``1 + beta`` and its
        ``c`` too. Friction acts at impacts and on the surface a ball rests on, where it slides
        until its contact point sticks and then rolls; and among balls pressed together under
        gravity (a group), on their centres, which slide against kinetic friction and stick
        while friction can hold them (spin kept), and so do a jam's impulses (a zero-time
        chain resolved as one impact). A ball touching a ball alone stays frictionless.

        ``roll`` (on a table only, see ``set_table``): the angular velocity about the
        horizontal axes ``(w_x, w_y)`` in rad/s; rolling along ``+x`` at speed ``v`` is
        ``(0, v / radius)``.
        """
    def add_balls(
        self,
        positions: npt.ArrayLike,
        velocities: npt.ArrayLike,
        radii: npt.ArrayLike,
        masses: Optional[npt.ArrayLike] = None,
        restitutions: Optional[npt.ArrayLike] = None,
        groups: Optional[_Groups] = None,
        spins: Optional[npt.ArrayLike] = None,
        inertias: Optional[npt.ArrayLike] = None,
        frictions: Optional[npt.ArrayLike] = None,
        tangential_restitutions: Optional[npt.ArrayLike] = None,
        rolling_resistances: Optional[npt.ArrayLike] = None,
        rolls: Optional[npt.ArrayLike] = None,
    ) -> _I64:
        """Adds many balls from arrays, all or nothing; returns their handles.

        ``rolls`` (on a table): shape (n, 2), as ``add_ball``'s ``roll``.
        """
    def add_segment(
        self,
        a: _Pair,
        b: _Pair,
        restitution: float = 1.0,
        sensor: bool = False,
        groups: Optional[_Groups] = None,
        friction: float = 0.0,
        tangential_restitution: float = 0.0,
        rolling_resistance: float = 0.0,
    ) -> int: ...
    def add_circle(
        self,
        center: _Pair,
        radius: float,
        restitution: float = 1.0,
        sensor: bool = False,
        groups: Optional[_Groups] = None,
        friction: float = 0.0,
        tangential_restitution: float = 0.0,
        rolling_resistance: float = 0.0,
    ) -> int: ...
    def remove_ball(self, handle: int) -> None: ...
    def remove_collider(self, handle: int) -> None: ...
    def set_velocity(self, handle: int, vel: _Pair) -> None: ...
    def set_spin(self, handle: int, spin: float) -> None:
        """Sets a ball's angular velocity (rad/s, counter-clockwise positive) from now on.

        A rough ball resting on a rough segment wakes and slides, then rolls.
        """
    def set_roll(self, handle: int, roll: _Pair) -> None:
        """Sets a ball's roll ``(w_x, w_y)`` (rad/s, on a table only) from now on.

        Its phase on the cloth (sliding, rolling) is taken again from its new state.
        """
    def set_angle(self, handle: int, angle: float) -> None:
        """Sets a ball's angle (radians, brought into [-pi, pi]) now; it turns on at its spin."""
    def has_ball(self, handle: int) -> bool: ...
    def has_collider(self, handle: int) -> bool: ...
    def ball(self, handle: int) -> _BallState: ...
    def ball_holders(self, handle: int) -> list[Tuple[Literal["collider", "ball"], int]]: ...
    def ball_sensors(self, handle: int) -> list[int]: ...
    def ball_asleep_since(self, handle: int) -> Optional[float]: ...
    def instant_events(self) -> Tuple[int, int]: ...
    def reserve_balls(self, additional: int) -> None: ...
    def position(self, handle: int) -> Tuple[float, float]: ...
    def unwrapped_position(self, handle: int) -> Tuple[float, float]:
        """The position plus the box lengths crossed since the ball was added (a periodic box)."""
    def velocity(self, handle: int) -> Tuple[float, float]: ...
    def spin(self, handle: int) -> float: ...
    def roll(self, handle: int) -> Tuple[float, float]:
        """A ball's roll now ``(w_x, w_y)`` (rad/s about the horizontal axes; zeros without a table)."""
    def angle(self, handle: int) -> float:
        """Radians turned since the ball was added, wrapped to [-pi, pi]."""
    def collider(self, handle: int) -> dict[str, Any]: ...
    def handles(self) -> _I64: ...
    def collider_handles(self) -> _I64: ...
    def positions(self) -> _F64:
        """Centres now, float64 (n, 2), in the order of ``handles()``."""
    def unwrapped_positions(self) -> _F64:
        """Positions plus the box lengths each ball has crossed (a periodic box), float64 (n, 2), in the order of ``positions()``."""
    def velocities(self) -> _F64: ...
    def radii(self) -> _F64: ...
    def masses(self) -> _F64: ...
    def spins(self) -> _F64:
        """Angular velocities now (rad/s, counter-clockwise positive), float64 (n,)."""
    def rolls(self) -> _F64:
        """Rolls now (rad/s about the horizontal axes, on a table), float64 (n, 2)."""
    def angles(self) -> _F64:
        """Angles now (radians turned since added, in [-pi, pi]), float64 (n,)."""
    def inertias(self) -> _F64:
        """Moments of inertia over ``m r**2``, float64 (n,)."""
    def kinetic_energies(self) -> _F64:
        """Kinetic energies now, translational plus rotational (spin and roll), float64 (n,)."""
    def step(self) -> Optional[Event]: ...
    def step_until(self, until: float) -> Optional[Event]: ...
    def advance_to(self, t: float) -> int:
        """Runs to ``t`` (GIL released, Ctrl-C checked); returns the number of events."""
    def advance_to_collect(self, t: float) -> _EventColumns:
        """Runs to ``t``, returning every event as NumPy columns."""
    def next_event_time(self) -> Optional[float]: ...
    def cast_ball(
        self,
        origin: _Pair,
        velocity: _Pair,
        radius: float,
        max_time: float = ...,
        groups: Optional[_Groups] = None,
        include_sensors: bool = False,
    ) -> Optional[CastHit]: ...
    def bounce_path(
        self,
        origin: _Pair,
        velocity: _Pair,
        radius: float,
        bounces: int,
        max_time: float = ...,
        groups: Optional[_Groups] = None,
        restitution: float = 1.0,
    ) -> list[CastHit]: ...
    @staticmethod
    def from_scene(scene: Union[dict[str, Any], _ScenePath]) -> "World":
        """A world from a scene file or dict, validated with the CLI's messages."""
    def to_scene(self) -> dict[str, Any]: ...
    def copy(self) -> "World":
        """An independent world in the same state, bit for bit: an exact branch of a run.

        Given the same calls, the copy and the original go on with the same events and
        bits, from any instant (mid-run, balls asleep): a tree search or a perturbation
        study branches a run with it. A pickle is not this: a world pickled mid-run is
        rebuilt from its state, restated at that instant, and its future matches only to
        rounding.
        """
    def __copy__(self) -> "World":
        """``copy.copy(world)``: ``world.copy()``, exact (not through the pickle)."""
    def __deepcopy__(self, memo: dict[int, Any]) -> "World":
        """``copy.deepcopy(world)``: ``world.copy()``, exact (not through the pickle)."""
    def __getstate__(self) -> str:
        """The whole state as JSON (pickling): exact now, but a world rebuilt from it mid-run goes on to rounding (``copy()`` is exact)."""
    def __setstate__(self, state: str) -> None: ...

def run_many(
    scenes: Sequence[Union[dict[str, Any], _ScenePath, World]],
    until: float,
    threads: Optional[int] = None,
) -> list[_RunResult]:
    """Runs independent worlds to ``until`` in parallel (rayon); one result per scene.

    Each result holds ``handles``, ``positions``, ``velocities``, ``spins``, ``angles``,
    ``rolls``, ``unwrapped`` (as ``World.unwrapped_positions()``), ``collision_virial`` and
    ``observables_since`` (as the ``World`` properties), ``events`` (the number handled) and
    ``time``. A ``World`` is copied exactly (as ``World.copy()``), the original unchanged:
    its result is what the original would reach, bit for bit.
    """

class _Report(TypedDict):
    level: int
    balls: int
    damage: int
    hits: int
    laser_damage: int
    bricks_destroyed: int
    extra_balls: int
    collisions: int
    end_time: float
    checkpoint_set: bool
    game_over: bool

@final
class Game:
    """A game of One More Brick."""

    def __init__(self, seed: int = 0, config: Optional[dict[str, Any]] = None) -> None: ...
    @property
    def seed(self) -> int: ...
    @property
    def phase(self) -> Literal["aiming", "volley", "game_over"]: ...
    @property
    def game_over(self) -> bool: ...
    @property
    def level(self) -> int: ...
    @property
    def score(self) -> int: ...
    @property
    def best_score(self) -> int: ...
    @property
    def balls(self) -> int: ...
    @property
    def launch_x(self) -> float: ...
    @property
    def columns(self) -> int: ...
    @property
    def rows(self) -> int: ...
    @property
    def min_elevation_tan(self) -> float: ...
    @property
    def volley_time(self) -> Optional[float]: ...
    def board(self) -> npt.NDArray[np.int32]:
        """int32 (rows, columns, 2): (kind, hit points) per cell, row 0 at the bottom."""
    def balls_in_flight(self) -> Tuple[_F64, _F64]: ...
    def aim_for(self, action: float) -> Tuple[float, float]: ...
    def shoot(self, direction: _Pair) -> None: ...
    def finish_round(self) -> _Report: ...
    def play(self, direction: _Pair) -> _Report: ...
    def advance_to(self, time: float) -> Optional[_Report]: ...
    def recall(self) -> _Report: ...
    def restart(self) -> None: ...
    def preview(self, direction: _Pair) -> _Report: ...
    def aim_preview(self, direction: _Pair, bounces: int) -> _F64: ...
    def to_json(self) -> str: ...
    @staticmethod
    def from_json(text: str) -> "Game": ...
    def save(self, path: _ScenePath) -> None: ...
    @staticmethod
    def load(path: _ScenePath) -> "Game": ...
    def render(self, cell: int = 32) -> npt.NDArray[np.uint8]:
        """The board now as an RGB frame, ``uint8`` of shape ``(rows * cell, columns * cell, 3)``.

        Drawn in software (tiny-skia) as the desktop game draws it: bricks in the ramp's
        colours with their hit points ("12.3k" past four digits), pick-ups with their labels,
        the balls in flight or the launcher with its ball count. ``cell`` is 4 to 256 pixels.
        """
        ...

@final
class RandomBot:
    def __init__(self, seed: int = 0) -> None: ...
    def choose(self, game: Game) -> Tuple[float, float]: ...

@final
class GreedyBot:
    def __init__(self, candidates: int = 32) -> None: ...
    def choose(self, game: Game) -> Tuple[float, float]: ...
