//! Where a ball's centre can be over a span of time: per-axis ranges, entry and exit times of
//! boxes, and chunking a path into pieces about one cell long.
//!
//! The broad phase only needs these to be *conservative*: a box said to hold the path must hold
//! it, up to a rounding error far below the margins the grids keep. Exact times of impact are
//! never computed here; they come from [`crate::toi`] for the candidates these functions select.

use glam::DVec2;

use crate::toi::Motion;

/// An axis-aligned box.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Aabb {
    pub min: DVec2,
    pub max: DVec2,
}

impl Aabb {
    /// The box grown by `by` on every side.
    pub(crate) fn inflated(self, by: f64) -> Self {
        Self {
            min: self.min - by,
            max: self.max + by,
        }
    }

    /// The smallest box holding both.
    pub(crate) fn union(self, other: Self) -> Self {
        Self {
            min: self.min.min(other.min),
            max: self.max.max(other.max),
        }
    }

    /// Whether the two boxes share a point.
    pub(crate) fn overlaps(&self, other: &Self) -> bool {
        self.min.cmple(other.max).all() && other.min.cmple(self.max).all()
    }

    /// Whether `other` lies inside this box.
    pub(crate) fn contains(&self, other: &Self) -> bool {
        self.min.cmple(other.min).all() && other.max.cmple(self.max).all()
    }

    /// Whether point `p` lies inside this box.
    pub(crate) fn contains_point(&self, p: DVec2) -> bool {
        self.min.cmple(p).all() && p.cmple(self.max).all()
    }

    /// The largest magnitude of a coordinate of the box: the scale of its rounding errors.
    pub(crate) fn magnitude(&self) -> f64 {
        self.min.abs().max(self.max.abs()).max_element()
    }

    /// The box grown on every side by `fraction` of its [magnitude](Self::magnitude) (shrunk
    /// if `fraction` is negative): room for the rounding of what is tested against it.
    pub(crate) fn inflated_relative(self, fraction: f64) -> Self {
        self.inflated(fraction * self.magnitude())
    }
}

/// `x.floor()` (equal in value; the sign of a zero may differ), without the library call that `f64::floor` is on baseline x86-64 (no SSE4.1):
/// the broad phase floors a few coordinates per prediction. Exact: below `2^52` in magnitude
/// the truncation through `i64` is exact, and larger values (and NaN) take the library path.
#[inline]
pub(crate) fn floor(x: f64) -> f64 {
    const EXACT: f64 = (1u64 << 52) as f64;
    if x.abs() < EXACT {
        let t = x as i64 as f64;
        if t > x { t - 1.0 } else { t }
    } else {
        x.floor()
    }
}

/// One coordinate of a motion: `p + v t + a t^2 / 2`.
#[derive(Clone, Copy, Debug)]
struct Axis {
    p: f64,
    v: f64,
    a: f64,
}

impl Axis {
    fn of(motion: &Motion) -> [Axis; 2] {
        let (p, v, a) = (motion.position, motion.velocity, motion.acceleration);
        [
            Axis {
                p: p.x,
                v: v.x,
                a: a.x,
            },
            Axis {
                p: p.y,
                v: v.y,
                a: a.y,
            },
        ]
    }

    fn at(self, t: f64) -> f64 {
        if self.a == 0.0 {
            self.p + self.v * t
        } else {
            self.p + self.v * t + 0.5 * self.a * t * t
        }
    }

    /// The real roots of `at(t) = c`, in increasing order (none, one or two).
    fn roots(self, c: f64) -> ([f64; 2], usize) {
        let (qa, qb, qc) = (0.5 * self.a, self.v, self.p - c);
        if qa == 0.0 {
            return if qb == 0.0 {
                ([0.0; 2], 0)
            } else {
                ([-qc / qb, 0.0], 1)
            };
        }
        let disc = qb * qb - 4.0 * qa * qc;
        if !(disc >= 0.0) {
            return ([0.0; 2], 0);
        }
        let q = -0.5 * (qb + disc.sqrt().copysign(qb));
        if q == 0.0 {
            return ([0.0, 0.0], 2);
        }
        let (r1, r2) = (q / qa, qc / q);
        ([r1.min(r2), r1.max(r2)], 2)
    }

    /// The range of the coordinate over `[t0, t1]`.
    fn range(self, t0: f64, t1: f64) -> (f64, f64) {
        let (x0, x1) = (self.at(t0), self.at(t1));
        let (mut lo, mut hi) = (x0.min(x1), x0.max(x1));
        if self.a != 0.0 {
            let vertex = -self.v / self.a;
            if vertex > t0 && vertex < t1 {
                let x = self.at(vertex);
                lo = lo.min(x);
                hi = hi.max(x);
            }
        }
        (lo, hi)
    }

    /// A time interval holding every `t` at which the coordinate is in `[lo, hi]` (its hull;
    /// `None` if it never is).
    fn within(self, lo: f64, hi: f64) -> Option<(f64, f64)> {
        if self.a == 0.0 {
            if self.v == 0.0 {
                return (lo <= self.p && self.p <= hi)
                    .then_some((f64::NEG_INFINITY, f64::INFINITY));
            }
            let (t1, t2) = ((lo - self.p) / self.v, (hi - self.p) / self.v);
            return Some((t1.min(t2), t1.max(t2)));
        }
        // A parabola spends a bounded time in the slab; its hull is spanned by the roots.
        let (mut first, mut last) = (f64::INFINITY, f64::NEG_INFINITY);
        for c in [lo, hi] {
            let (roots, n) = self.roots(c);
            for &r in &roots[..n] {
                first = first.min(r);
                last = last.max(r);
            }
        }
        (first <= last).then_some((first, last))
    }

    /// The first time after `start` at which the coordinate reaches `lo` or `hi`.
    fn first_reach(self, lo: f64, hi: f64, start: f64) -> f64 {
        if self.a == 0.0 {
            // Straight: the roots below, one per side, without the general case's loop.
            if self.v == 0.0 {
                return f64::INFINITY;
            }
            let (r_lo, r_hi) = (-(self.p - lo) / self.v, -(self.p - hi) / self.v);
            let pick = |r: f64| if r > start { r } else { f64::INFINITY };
            return pick(r_lo).min(pick(r_hi));
        }
        let mut first = f64::INFINITY;
        for c in [lo, hi] {
            let (roots, n) = self.roots(c);
            for &r in &roots[..n] {
                if r > start {
                    first = first.min(r);
                }
            }
        }
        first
    }
}

/// The box holding the motion's centre over `[t0, t1]` (`t1` finite, or the motion at rest).
pub(crate) fn path_aabb(motion: &Motion, t0: f64, t1: f64) -> Aabb {
    let [x, y] = Axis::of(motion);
    let (x0, x1) = x.range(t0, t1);
    let (y0, y1) = y.range(t0, t1);
    Aabb {
        min: DVec2::new(x0, y0),
        max: DVec2::new(x1, y1),
    }
}

/// A time interval holding every time at which the centre is inside `bounds` (the hull of
/// the per-axis intervals' intersection), or `None` if it never is.
pub(crate) fn time_within(motion: &Motion, bounds: &Aabb) -> Option<(f64, f64)> {
    let [x, y] = Axis::of(motion);
    let (a0, a1) = x.within(bounds.min.x, bounds.max.x)?;
    let (b0, b1) = y.within(bounds.min.y, bounds.max.y)?;
    let (t0, t1) = (a0.max(b0), a1.min(b1));
    (t0 <= t1).then_some((t0, t1))
}

/// The first time after `start` at which the centre reaches a side line of `bounds`: for a
/// centre inside it at `start`, the time it leaves (infinite if it never does).
pub(crate) fn time_of_exit(motion: &Motion, bounds: &Aabb, start: f64) -> f64 {
    let [x, y] = Axis::of(motion);
    x.first_reach(bounds.min.x, bounds.max.x, start)
        .min(y.first_reach(bounds.min.y, bounds.max.y, start))
}

/// A duration from `t` over which the centre moves at most `length` (infinite for a ball at
/// rest without acceleration).
pub(crate) fn span_for_length(motion: &Motion, t: f64, length: f64) -> f64 {
    let speed = motion.velocity_at(t).length();
    let accel = motion.acceleration.length();
    // speed dt + accel dt^2 / 2 = length, solved without cancellation.
    let denominator = speed + (speed * speed + 2.0 * accel * length).sqrt();
    if denominator > 0.0 {
        2.0 * length / denominator
    } else {
        f64::INFINITY
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn bounds(x0: f64, y0: f64, x1: f64, y1: f64) -> Aabb {
        Aabb {
            min: DVec2::new(x0, y0),
            max: DVec2::new(x1, y1),
        }
    }

    #[test]
    fn floor_agrees_with_the_library_everywhere() {
        let cases = [
            0.0,
            -0.0,
            0.5,
            -0.5,
            1.0,
            -1.0,
            2.999_999_999_999_999_6,
            -2.000_000_000_000_000_4,
            4503599627370495.5,
            -4503599627370495.5,
            4503599627370496.0,
            1e300,
            -1e300,
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::MIN_POSITIVE,
            -f64::MIN_POSITIVE,
        ];
        for x in cases {
            assert_eq!(floor(x), x.floor(), "{x}");
        }
        assert!(floor(f64::NAN).is_nan());
    }

    #[test]
    fn a_straight_path_is_inside_a_box_between_its_entry_and_exit() {
        let m = Motion::linear(DVec2::new(-2.0, 0.5), DVec2::new(1.0, 0.0));
        assert_eq!(
            time_within(&m, &bounds(0.0, 0.0, 1.0, 1.0)),
            Some((2.0, 3.0))
        );
        assert_eq!(time_within(&m, &bounds(0.0, 1.0, 1.0, 2.0)), None);
        assert_eq!(time_of_exit(&m, &bounds(-3.0, 0.0, 1.0, 1.0), 0.0), 3.0);
    }

    #[test]
    fn a_parabola_is_bounded_by_its_vertex() {
        // y = 2 t - t^2 / 2 * 2 = 2t - t^2: vertex at t = 1, height 1.
        let m = Motion {
            position: DVec2::ZERO,
            velocity: DVec2::new(1.0, 2.0),
            acceleration: DVec2::new(0.0, -2.0),
        };
        let b = path_aabb(&m, 0.0, 2.0);
        assert_eq!(b, bounds(0.0, 0.0, 2.0, 1.0));
        // It is above y = 0.75 for t in [0.5, 1.5].
        let (t0, t1) = time_within(&m, &bounds(-10.0, 0.75, 10.0, 5.0)).unwrap();
        assert!((t0 - 0.5).abs() < 1e-15 && (t1 - 1.5).abs() < 1e-15);
        // It leaves y < 0.75 at t = 0.5 and, started after that, falls back through it at 1.5.
        assert!((time_of_exit(&m, &bounds(-10.0, -10.0, 10.0, 0.75), 0.0) - 0.5).abs() < 1e-15);
        assert!((time_of_exit(&m, &bounds(-10.0, 0.5, 10.0, 0.75), 1.0) - 1.5).abs() < 1e-15);
        // It never reaches y = 2.
        assert_eq!(time_within(&m, &bounds(-10.0, 2.0, 10.0, 3.0)), None);
    }

    #[test]
    fn a_span_covers_the_requested_length() {
        let m = Motion {
            position: DVec2::ZERO,
            velocity: DVec2::new(3.0, 4.0),
            acceleration: DVec2::new(0.0, -10.0),
        };
        let dt = span_for_length(&m, 0.0, 1.0);
        assert!((5.0 * dt + 5.0 * dt * dt - 1.0).abs() < 1e-15);
        let rest = Motion::linear(DVec2::ZERO, DVec2::ZERO);
        assert_eq!(span_for_length(&rest, 0.0, 1.0), f64::INFINITY);
    }
}
