"""An independent, high-precision, event-driven simulator of balls among static shapes.

Written from the physics, not from the Rust engine: every formula below is derived in the
comments. All arithmetic is mpmath at ``mp.dps = 60`` (about 200 bits), so the trajectories it
produces are exact to far more digits than the 30 written to the fixtures.

Model
-----
* A ball is a disc of radius ``r`` and mass ``m``; its centre moves as
  ``p(t) = p + v t + g t^2 / 2`` under the uniform acceleration ``g`` (possibly zero).
* A segment ``[a, b]`` is two-sided and has its two end points: the set of centres at which a
  ball of radius ``r`` touches it is the boundary of the capsule of radius ``r`` around it.
* A static circle is a solid disc of radius ``R``: a ball touches it when its centre is at
  distance ``R + r`` from the disc's centre.
* Balls touch when their centres are ``r1 + r2`` apart.
* Every contact is instantaneous. The contact normal ``n`` is the direction from the touched
  feature to the ball's centre (segment interior: the line's normal on the ball's side; end
  point or circle: centre minus point; two balls: centre difference).
* Response with coefficient of restitution ``e`` (product of both parties' coefficients):
    - static: only the normal velocity changes, ``v.n -> -e v.n``:
      ``v' = v - (1 + e) (v.n / n.n) n``;
    - two balls: the impulse ``J n`` acts along ``n`` with opposite signs on the two balls
      (momentum conserved), and the relative normal velocity ``u = (v1 - v2).n / n.n``
      becomes ``-e u``:  ``J = (1 + e) u m1 m2 / (m1 + m2)``, hence
      ``v1' = v1 - (1 + e) u m2 / (m1 + m2) n`` and ``v2' = v2 + (1 + e) u m1 / (m1 + m2) n``.

Contacts
--------
A contact is the first time ``t > 0`` at which a *gap function* is zero *while decreasing*
(gap growing at a root means the bodies are separating, e.g. the root at t = 0 right after a
bounce). The gap functions, with ``w(t)`` a relative position:

* segment interior, side ``s = +-1``: ``s * d(t) - r`` with ``d(t) = nhat.(p(t) - a)`` the signed
  distance to the line: a polynomial of degree <= 2, valid only if the centre then projects onto
  the segment (``0 <= u(t) <= 1``, ``u = (b - a).(p - a) / |b - a|^2``);
* end point ``c`` (or static circle centre, or the other ball): ``|w(t)|^2 - D^2`` with
  ``w = p(t) - c``: ``|q + v t + g t^2/2|^2 - D^2`` is a quartic when ``g != 0``:

      (g.g/4) t^4 + (v.g) t^3 + (v.v + q.g) t^2 + 2 (q.v) t + (q.q - D^2)

  and a quadratic when ``g = 0``. For two balls the accelerations cancel (both fall alike), so
  it is always a quadratic in the relative motion. End-point contacts are valid only if the
  centre then projects beyond that end (``u <= 0`` for ``a``, ``u >= 1`` for ``b``): otherwise
  the interior is closer and the capsule was entered earlier.

Quadratics are solved in closed form (cancellation-free form). Quartics are solved with
``mpmath.polyroots`` (extra precision), every real root is polished with Newton's method on the
*geometric* form ``|w(t)|^2 - D^2``, and the first root > 0 with a negative derivative is taken.
That choice is then verified: the quartic's critical points (roots of its cubic derivative)
inside ``(0, t*)`` must all have a positive gap, and so must a grid of samples; since the gap
is monotone between critical points this proves there is no earlier contact with that feature.
On top of that, after every event the whole world is checked: no pair overlaps at the event
and at sample times of the flight that led to it.
"""

from __future__ import annotations

import random
from dataclasses import dataclass, field

from mpmath import mp, mpf, polyroots

mp.dps = 60

# Roots closer to t = 0 than this are the contact just handled (or a simultaneous one, which
# the scenes are chosen to avoid): they are not new events.
T_MIN = mpf("1e-40")


def f64(s: str) -> mpf:
    """The exact binary value of the f64 that the decimal string ``s`` rounds to.

    The fixtures write every input as Python's ``repr`` of a float (the shortest decimal that
    round-trips); Rust parses it to the same f64, and here we take that f64's exact value, so
    both simulations start from bit-identical numbers.
    """
    x = float(s)
    assert repr(x) == s, f"{s!r} is not the repr of a float ({x!r})"
    return mpf(x)  # exact: mpf holds any double exactly


class V:
    """A 2D vector of mpf."""

    __slots__ = ("x", "y")

    def __init__(self, x, y):
        self.x = mpf(x)
        self.y = mpf(y)

    def __add__(self, o):
        return V(self.x + o.x, self.y + o.y)

    def __sub__(self, o):
        return V(self.x - o.x, self.y - o.y)

    def __mul__(self, k):
        return V(self.x * k, self.y * k)

    __rmul__ = __mul__

    def __neg__(self):
        return V(-self.x, -self.y)

    def dot(self, o):
        return self.x * o.x + self.y * o.y

    def norm2(self):
        return self.dot(self)

    def norm(self):
        return mp.sqrt(self.norm2())

    def __repr__(self):
        return f"V({mp.nstr(self.x, 20)}, {mp.nstr(self.y, 20)})"


@dataclass
class Segment:
    a: V
    b: V

    def __post_init__(self):
        self.d = self.b - self.a
        self.len2 = self.d.norm2()
        length = mp.sqrt(self.len2)
        # Unit normal (left of a -> b). Its orientation does not matter: both sides are tried.
        self.n = V(-self.d.y / length, self.d.x / length)

    def u(self, p: V):
        """Projection parameter of p on the segment: 0 at a, 1 at b."""
        return self.d.dot(p - self.a) / self.len2


@dataclass
class Circle:
    c: V
    radius: mpf


@dataclass
class Ball:
    p: V
    v: V
    r: mpf
    m: mpf
    e: mpf = field(default_factory=lambda: mpf(1))


# --------------------------------------------------------------------------------------------
# Polynomial roots


def poly_eval(coeffs, t):
    """Horner; coefficients highest degree first."""
    acc = mpf(0)
    for c in coeffs:
        acc = acc * t + c
    return acc


def poly_deriv(coeffs):
    n = len(coeffs) - 1
    return [c * (n - i) for i, c in enumerate(coeffs[:-1])]


def strip(coeffs):
    """Drops exactly-zero leading coefficients."""
    i = 0
    while i < len(coeffs) - 1 and coeffs[i] == 0:
        i += 1
    return coeffs[i:]


def real_roots(coeffs, refine=None):
    """All real roots of the polynomial (highest degree first), ascending.

    Degree <= 2: closed form, in the form without cancellation. Higher degree: polyroots with
    generous extra precision; roots with a negligible imaginary part are kept and polished with
    Newton's method on ``refine`` (a function returning (value, derivative)), if given.
    """
    coeffs = strip(list(coeffs))
    deg = len(coeffs) - 1
    if deg <= 0:
        return []
    if deg == 1:
        return [-coeffs[1] / coeffs[0]]
    if deg == 2:
        a, b, c = coeffs
        disc = b * b - 4 * a * c
        if disc < 0:
            return []
        sq = mp.sqrt(disc)
        q = -(b + sq) / 2 if b >= 0 else -(b - sq) / 2
        if q == 0:
            return [mpf(0), mpf(0)]
        return sorted([q / a, c / q])
    roots = polyroots(coeffs, maxsteps=400, extraprec=mp.prec)
    scale = 1 + max(abs(r) for r in roots)
    out = []
    for z in roots:
        if abs(mp.im(z)) <= mpf("1e-25") * scale:
            t = mp.re(z)
            if refine is not None:
                t = newton(refine, t)
            out.append(t)
    return sorted(out)


def newton(fd, t, steps=60):
    """Polishes a simple root of f with Newton's method; fd(t) = (f, f')."""
    for _ in range(steps):
        f, d = fd(t)
        if d == 0:
            break
        step = f / d
        t -= step
        if abs(step) <= abs(t) * mpf(10) ** (-mp.dps + 3) + mpf(10) ** (-mp.dps - 20):
            break
    return t


# --------------------------------------------------------------------------------------------
# Gap functions and their first decreasing root


def point_gap_poly(q: V, v: V, g: V, dist):
    """Coefficients of |q + v t + g t^2/2|^2 - dist^2, highest degree first (degree 4 or 2)."""
    return [
        g.norm2() / 4,
        v.dot(g),
        v.norm2() + q.dot(g),
        2 * q.dot(v),
        q.norm2() - dist * dist,
    ]


def point_gap_fd(q: V, v: V, g: V, dist):
    """The same gap evaluated from the geometry, with its derivative: (|w|^2 - D^2, 2 w.w')."""

    def fd(t):
        w = q + v * t + g * (t * t / 2)
        dw = v + g * t
        return w.norm2() - dist * dist, 2 * w.dot(dw)

    return fd


def first_point_contact(q: V, v: V, g: V, dist, valid=lambda t: True):
    """First t > T_MIN with |q + v t + g t^2/2| = dist, the distance decreasing, and valid(t)."""
    coeffs = point_gap_poly(q, v, g, dist)
    fd = point_gap_fd(q, v, g, dist)
    first = True
    for t in real_roots(coeffs, refine=fd):
        if t <= T_MIN:
            continue
        f, d = fd(t)
        if d < 0:
            if first and len(strip(coeffs)) == 5:
                # The first decreasing root is the first root at all (the gap starts >= 0).
                verify_no_earlier_root(coeffs, fd, t)
            first = False
            if valid(t):
                return t
    return None


def verify_no_earlier_root(coeffs, fd, t_star):
    """Proves that the quartic gap has no root in (T_MIN, t_star): positive at every critical
    point there and at the ends of the monotone pieces (plus a sampling grid as a second
    opinion). Raises if not."""
    f0, _ = fd(T_MIN)
    crit = [c for c in real_roots(poly_deriv(coeffs)) if T_MIN < c < t_star]
    # At T_MIN the gap may be ~0 (the contact just handled, separating): then it grows.
    checks = crit + [t_star * k / 64 for k in range(1, 64)]
    for c in checks:
        fc, _ = fd(c)
        if not fc > 0:
            raise AssertionError(f"earlier quartic root before {t_star}: gap {fc} at {c}")
    if f0 < -mpf("1e-40"):
        raise AssertionError(f"gap negative at start: {f0}")


def first_line_contact(s0, sv, sg, r, valid):
    """First t > T_MIN at which the signed distance s(t) = s0 + sv t + sg t^2/2 reaches +-r with
    |s| decreasing, and valid(t). Returns (t, side)."""
    best = None
    for side in (1, -1):
        # side * s(t) - r = 0
        coeffs = [side * sg / 2, side * sv, side * s0 - r]
        for t in real_roots(coeffs):
            if t <= T_MIN:
                continue
            if side * (sv + sg * t) < 0 and valid(t):
                if best is None or t < best[0]:
                    best = (t, side)
                break
    return best


# --------------------------------------------------------------------------------------------
# The world


class World:
    def __init__(self, gravity: V, colliders, balls):
        self.g = gravity
        self.colliders = colliders
        self.balls = balls
        self.time = mpf(0)

    def pos_at(self, ball: Ball, dt):
        return ball.p + ball.v * dt + self.g * (dt * dt / 2)

    # -- candidates --------------------------------------------------------------------------

    def segment_candidates(self, i, j, seg: Segment, horizon):
        ball, g = self.balls[i], self.g
        out = []
        s0 = seg.n.dot(ball.p - seg.a)
        sv = seg.n.dot(ball.v)
        sg = seg.n.dot(g)
        hit = first_line_contact(
            s0, sv, sg, ball.r, lambda t: 0 <= seg.u(self.pos_at(ball, t)) <= 1
        )
        if hit is not None:
            out.append((hit[0], "contact", i, j, "interior"))
        for end, name, beyond in (
            (seg.a, "end_a", lambda u: u <= 0),
            (seg.b, "end_b", lambda u: u >= 1),
        ):
            if self.out_of_reach(ball, end, ball.r, horizon):
                continue
            t = first_point_contact(
                ball.p - end, ball.v, g, ball.r, lambda t: beyond(seg.u(self.pos_at(ball, t)))
            )
            if t is not None:
                out.append((t, "contact", i, j, name))
        return out

    def out_of_reach(self, ball: Ball, point: V, dist, horizon):
        """Whether the ball's centre certainly cannot come within dist of point before horizon:
        in time T it moves at most |v| T + |g| T^2 / 2. Only a speed-up for the quartics."""
        if horizon == mp.inf:
            return False
        travel = ball.v.norm() * horizon + self.g.norm() * horizon * horizon / 2
        return (ball.p - point).norm() - dist > travel

    def candidates(self):
        """Every pair's first contact from now, sorted by time. Candidates that certainly come
        later than the earliest line or ball-ball contact (plus a margin of 1e-20) are pruned
        without solving their quartic."""
        out = []
        # Pass 1: ball-ball contacts and segment interiors (degree <= 2 in t).
        for i, ball in enumerate(self.balls):
            for k in range(i + 1, len(self.balls)):
                other = self.balls[k]
                # Relative motion of k seen from i: gravity cancels.
                t = first_point_contact(
                    other.p - ball.p, other.v - ball.v, V(0, 0), ball.r + other.r
                )
                if t is not None:
                    out.append((t, "ball_contact", i, k, None))
        horizon = min([c[0] for c in out], default=mp.inf)
        # Pass 2: colliders (end points and circles may be quartics).
        for i, ball in enumerate(self.balls):
            for j, col in enumerate(self.colliders):
                if isinstance(col, Segment):
                    found = self.segment_candidates(i, j, col, horizon + mpf("1e-20"))
                else:
                    dist = col.radius + ball.r
                    if self.out_of_reach(ball, col.c, dist, horizon + mpf("1e-20")):
                        continue
                    t = first_point_contact(ball.p - col.c, ball.v, self.g, dist)
                    found = [] if t is None else [(t, "contact", i, j, "circle")]
                out += found
                horizon = min([horizon] + [c[0] for c in found])
        out.sort(key=lambda c: c[0])
        return out

    # -- stepping ----------------------------------------------------------------------------

    def advance(self, dt):
        for b in self.balls:
            b.p = self.pos_at(b, dt)
            b.v = b.v + self.g * dt
        self.time += dt

    def step(self):
        """Handles the next event; returns (event tuple, margin to the next candidate)."""
        cands = self.candidates()
        if not cands:
            return None, None
        dt, kind, i, j, feature = cands[0]
        # Every candidate within 1e-20 of the first was solved (see candidates()).
        margin = cands[1][0] - dt if len(cands) > 1 else mp.inf
        if margin < mpf("1e-30"):
            raise AssertionError(f"near-simultaneous events at t = {self.time + dt}: {cands[:2]}")
        self.check_energy()
        self.check_flight(dt)
        self.advance(dt)
        if kind == "contact":
            ball = self.balls[i]
            col = self.colliders[j]
            if feature == "interior":
                side = 1 if col.n.dot(ball.p - col.a) > 0 else -1
                n = col.n * side
            elif feature == "end_a":
                n = ball.p - col.a
            elif feature == "end_b":
                n = ball.p - col.b
            else:
                n = ball.p - col.c
            vn = ball.v.dot(n)
            assert vn < 0, "a contact must be approaching"
            ball.v = ball.v - n * ((1 + ball.e) * vn / n.norm2())  # colliders have e = 1
        else:
            b1, b2 = self.balls[i], self.balls[j]
            n = b2.p - b1.p
            u = (b1.v - b2.v).dot(n) / n.norm2()
            assert u > 0, "balls in contact must be approaching"
            e = b1.e * b2.e
            total = b1.m + b2.m
            b1.v = b1.v - n * ((1 + e) * u * b2.m / total)
            b2.v = b2.v + n * ((1 + e) * u * b1.m / total)
        self.check_no_overlap()
        self.check_energy()
        return (self.time, kind, i, j, feature), margin

    # -- independent sanity checks -----------------------------------------------------------

    def gaps(self, positions):
        """Every pairwise gap (>= 0 means not overlapping) for the given ball centres."""
        for i, (p, ball) in enumerate(zip(positions, self.balls)):
            for col in self.colliders:
                if isinstance(col, Segment):
                    u = col.u(p)
                    u = min(max(u, mpf(0)), mpf(1))
                    yield (p - (col.a + col.d * u)).norm() - ball.r
                else:
                    yield (p - col.c).norm() - col.radius - ball.r
            for k in range(i + 1, len(self.balls)):
                yield (positions[k] - p).norm() - ball.r - self.balls[k].r

    def energy(self):
        """Kinetic plus potential energy, sum of m (|v|^2 / 2 - g.p): constant when every
        restitution is 1."""
        return sum(b.m * (b.v.norm2() / 2 - self.g.dot(b.p)) for b in self.balls)

    def check_energy(self):
        if all(b.e == 1 for b in self.balls):
            if not hasattr(self, "energy0"):
                self.energy0 = self.energy()
            drift = abs(self.energy() - self.energy0)
            assert drift <= mpf("1e-50") * abs(self.energy0), f"energy drift {drift}"

    def check_no_overlap(self):
        tol = mpf("1e-45")
        worst = min(self.gaps([b.p for b in self.balls]))
        assert worst > -tol, f"overlap {worst} at t = {self.time}"

    def check_flight(self, dt, samples=32):
        """Nothing overlaps at sample times of the flight (0, dt): no contact was missed."""
        for k in range(1, samples):
            t = dt * k / samples
            worst = min(self.gaps([self.pos_at(b, t) for b in self.balls]))
            assert worst > 0, f"missed contact: overlap {worst} at t = {self.time + t}"


def state(world: World):
    return [(b.p, b.v) for b in world.balls]


def run(world: World, n_events: int):
    """Runs n_events events; returns [(event, margin, state after)]."""
    out = []
    for _ in range(n_events):
        ev, margin = world.step()
        if ev is None:
            break
        out.append((ev, margin, state(world)))
    return out


def perturb(world: World, size, seed=1):
    """Moves every ball's position and velocity by a pseudo-random vector of components in
    [-size, size] (deterministic)."""
    rng = random.Random(seed)

    def d():
        return mpf(rng.uniform(-1, 1)) * size

    for b in world.balls:
        b.p = b.p + V(d(), d())
        b.v = b.v + V(d(), d())
