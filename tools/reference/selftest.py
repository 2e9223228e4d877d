#!/usr/bin/env python3
"""Checks of the reference simulator against answers obtained another way.

    python3 tools/reference/selftest.py

1. Quartic contacts (a ball on a parabola against a point): the first contact found by
   refsim.first_point_contact (polyroots + Newton + critical-point verification) is compared
   with a brute-force answer: the gap sampled densely, the first sign change bracketed and
   bisected to 55 digits.
2. Straight flights: a ball in a box against walls, whose times are (distance / speed).
3. Responses: a ball-ball collision conserves momentum and (elastic) energy, and a head-on
   collision of unequal masses matches the textbook 1D formula.
"""

from __future__ import annotations

import random
import sys

from mpmath import mp, mpf

import refsim
from refsim import Ball, Segment, V, World, first_point_contact


def brute_first_contact(q, v, g, dist, t_max, samples=3000):
    fd = refsim.point_gap_fd(q, v, g, dist)
    prev_t, prev_f = mpf(0), fd(mpf(0))[0]
    for k in range(1, samples + 1):
        t = t_max * k / samples
        f = fd(t)[0]
        if prev_f > 0 and f <= 0:
            lo, hi = prev_t, t
            for _ in range(200):
                mid = (lo + hi) / 2
                if fd(mid)[0] > 0:
                    lo = mid
                else:
                    hi = mid
            return (lo + hi) / 2
        prev_t, prev_f = t, f
    return None


def check_quartics(count=60, seed=7):
    rng = random.Random(seed)
    checked = 0
    for n in range(count):
        q = V(rng.uniform(-2, 2), rng.uniform(-2, 2))
        g = V(rng.uniform(-1, 1), rng.uniform(-12, -5))
        dist = mpf(rng.uniform(0.05, 0.6))
        if q.norm() <= dist:
            continue
        if n % 3 == 2:
            # Free shot: may miss, or hit after going around.
            v = V(rng.uniform(-4, 4), rng.uniform(-4, 4))
        else:
            # Aimed: passes through a point at distance 0..1.2 dist of the centre at time T,
            # so near-grazing contacts and misses are included.
            T = mpf(rng.uniform(0.2, 1.5))
            angle = rng.uniform(0, 6.283)
            aim = V(mp.cos(angle), mp.sin(angle)) * (dist * mpf(rng.uniform(0, 1.2)))
            v = (aim - q - g * (T * T / 2)) * (1 / T)
        t_max = mpf(3)
        brute = brute_first_contact(q, v, g, dist, t_max)
        found = first_point_contact(q, v, g, dist)
        if brute is None:
            assert found is None or found > t_max * (1 - mpf(1) / 3000), (q, v, g, dist, found)
            continue
        assert found is not None, (q, v, g, dist, brute)
        assert abs(found - brute) < mpf("1e-50"), (found, brute)
        checked += 1
    print(f"quartic contacts: {checked} of {count} cases hit; all agree with dense sampling + bisection to 1e-50")


def check_box():
    # A ball of radius 0.1 at (0.5, 0.3) moving at (0.3, -0.4) in the unit box: it hits the
    # floor (y = 0.1) at t = 0.5, then the right wall (x = 0.9) at t = 0.4/0.3.
    walls = [
        Segment(V(0, 0), V(1, 0)),
        Segment(V(1, 0), V(1, 1)),
        Segment(V(1, 1), V(0, 1)),
        Segment(V(0, 1), V(0, 0)),
    ]
    w = World(V(0, 0), walls, [Ball(V("0.5", "0.3"), V("0.3", "-0.4"), mpf("0.1"), mpf(1))])
    (t1, _, _, j1, f1), _ = w.step()
    (t2, _, _, j2, f2), _ = w.step()
    assert (j1, f1, j2, f2) == (0, "interior", 1, "interior")
    assert abs(t1 - mpf("0.5")) < mpf("1e-55") and abs(t2 - mpf(4) / 3) < mpf("1e-55")
    print("straight flights in a box: exact wall times")


def check_responses():
    walls = [Segment(V(-10, -10), V(10, -10))]
    a = Ball(V(0, 0), V(1, 0), mpf("0.5"), mpf(1))
    b = Ball(V(2, 0), V(0, 0), mpf("0.5"), mpf(2))
    w = World(V(0, 0), walls, [a, b])
    (t, kind, i, j, _), _ = w.step()
    assert kind == "ball_contact" and (i, j) == (0, 1) and abs(t - 1) < mpf("1e-55")
    # 1D elastic: v1' = (m1 - m2)/(m1 + m2) v1 = -1/3, v2' = 2 m1/(m1 + m2) v1 = 2/3.
    assert abs(a.v.x + mpf(1) / 3) < mpf("1e-55") and abs(b.v.x - mpf(2) / 3) < mpf("1e-55")
    # Oblique, unequal masses: momentum and energy conserved.
    a = Ball(V(0, 0), V("1.3", "0.2"), mpf("0.3"), mpf("0.7"))
    b = Ball(V(2, "0.25"), V("-0.4", "0.1"), mpf("0.2"), mpf("2.9"))
    p0 = a.v * a.m + b.v * b.m
    e0 = a.m * a.v.norm2() + b.m * b.v.norm2()
    w = World(V(0, 0), walls, [a, b])
    (_, kind, _, _, _), _ = w.step()
    assert kind == "ball_contact"
    p1 = a.v * a.m + b.v * b.m
    e1 = a.m * a.v.norm2() + b.m * b.v.norm2()
    assert (p1 - p0).norm() < mpf("1e-55") and abs(e1 - e0) < mpf("1e-55")
    print("ball-ball response: textbook 1D result; momentum and energy conserved")


def main():
    check_quartics()
    check_box()
    check_responses()
    print(f"all reference self-tests passed (mp.dps = {mp.dps})")


if __name__ == "__main__":
    sys.exit(main())
