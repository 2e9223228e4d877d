//! A rough ball on a straight surface: sliding, rolling, or held by rolling resistance, in
//! closed form, with the time each phase ends.
//!
//! # The maths
//!
//! A ball of radius `r`, mass `m`, moment of inertia `k m r^2` rests on a line of unit normal
//! `n` (from the surface to the centre) under gravity `g`; `t = perp(n)` runs along the line.
//! Gravity pulls it along at `g_t = g . t` and into the line at `g_n = -g . n > 0`, so the
//! surface pushes with `N = m g_n`. Its contact point sits at `-r n` from the centre and moves
//! along the line at the *slip*
//!
//! ```text
//! u = v . t - w r        (v the centre's velocity, w the spin, counter-clockwise positive)
//! ```
//!
//! (a ball rolling along `+t` turns clockwise: `w = v . t / r`). A friction force `F t` at the
//! contact point accelerates the centre by `F / m` and turns the ball by the torque
//! `(-r n) x (F t) = -r F`, that is `dw/dt = -F / (k m r)`.
//!
//! *Sliding* (`u != 0`): kinetic friction opposes the slip, `F = -s mu N` with `s = sign(u)`,
//! so
//!
//! ```text
//! dv/dt = g_t - s mu g_n,   dw/dt = s mu g_n / (k r),   du/dt = g_t - s mu g_n (1 + 1/k).
//! ```
//!
//! All three are constant: the motion stays a parabola. If `du/dt` opposes `u` the slip
//! vanishes at `|u| / |du/dt|` (on a level floor `|u0| / (mu g (1 + 1/k))`, `|u0| / (3 mu g)`
//! for a uniform disk) and the ball rolls from then on; otherwise it slides on.
//!
//! *Rolling* (`u = 0`): the friction `F` keeps the slip at zero,
//! `du/dt = (g_t + F / m) + F / (k m) = 0`, so `F = -g_t m k / (1 + k)` and
//! `dv/dt = g_t / (1 + k)` (`2/3 g sin a` down an incline for a disk). Static friction can give at most `mu N`: the ball rolls while
//! `|g_t| k / (1 + k) <= mu g_n`, `tan a <= mu (1 + 1/k)` on an incline (`3 mu` for a disk),
//! and beyond that slides, its slip growing the way gravity pulls.
//!
//! *Rolling resistance* `c` (optional, 0 by default): a rolling ball loses speed at `c g_n` on
//! top (its speed falls linearly on a level floor and it stops at `|v0| / (c g_n)`; pooltool's
//! rolling state is the same law). A ball rolling to a stop stays put if
//! `|g_t| / (1 + k) <= c g_n`, and rolls back otherwise.
//!
//! Every phase has constant `dv/dt` and `dw/dt`, so positions stay quadratic in time and each
//! transition is an event at its analytic time.

/// The motion of a rough ball on a line for one phase: its acceleration along the line,
/// its spin's rate of change, and how long the phase lasts.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Rub {
    /// `dv/dt` along `t`.
    pub accel: f64,
    /// `dw/dt`.
    pub alpha: f64,
    /// How long until the slip vanishes (sliding) or the ball stops (rolling under
    /// resistance), if ever.
    pub until: Option<f64>,
    /// Whether the ball rolls (its spin is then `v . t / r`).
    pub rolling: bool,
}

/// The ball and its surface along the line: velocity along `t` and spin now, radius, inertia
/// factor, gravity's pull along the line and into it, the pair's friction and rolling
/// resistance.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct OnLine {
    pub v: f64,
    pub w: f64,
    pub radius: f64,
    pub inertia: f64,
    pub g_t: f64,
    pub g_n: f64,
    pub friction: f64,
    pub resistance: f64,
}

impl OnLine {
    /// The slip of the contact point, `v - w r`.
    pub(crate) fn slip(&self) -> f64 {
        self.v - self.w * self.radius
    }

    /// Whether the slip is within the rounding of the velocities it is made of: rolling.
    pub(crate) fn rolls(&self) -> bool {
        let scale = self.v.abs() + (self.w * self.radius).abs();
        self.slip().abs() <= 8.0 * f64::EPSILON * scale
    }

    /// The phase the ball is in now and how it moves in it (see the module's maths).
    pub(crate) fn rub(&self) -> Rub {
        let (g_t, g_n, mu, k, r) = (self.g_t, self.g_n, self.friction, self.inertia, self.radius);
        let holds = g_t.abs() * k / (1.0 + k) <= mu * g_n;
        if self.rolls() && holds {
            return self.rolling();
        }
        // Sliding: the slip's sign, or where it rolls but friction cannot hold it, the way
        // gravity makes it grow.
        let u = self.slip();
        let s = if self.rolls() {
            g_t.signum()
        } else {
            u.signum()
        };
        let accel = g_t - s * mu * g_n;
        let alpha = s * mu * g_n / (k * r);
        let rate = g_t - s * mu * g_n * (1.0 + 1.0 / k);
        let until = (!self.rolls() && rate * s < 0.0).then(|| u.abs() / rate.abs());
        Rub {
            accel,
            alpha,
            until,
            rolling: false,
        }
    }

    /// Rolling, with the rolling resistance.
    fn rolling(&self) -> Rub {
        let (v, r) = (self.v, self.radius);
        let free = self.g_t / (1.0 + self.inertia);
        let drag = self.resistance * self.g_n;
        let (accel, until) = if v != 0.0 {
            let accel = free - v.signum() * drag;
            let stops = accel * v < 0.0 && drag > 0.0;
            (accel, stops.then(|| v.abs() / accel.abs()))
        } else if free.abs() <= drag {
            (0.0, None)
        } else {
            (free - free.signum() * drag, None)
        };
        Rub {
            accel,
            alpha: accel / r,
            until,
            rolling: true,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn disk(v: f64, w: f64, g_t: f64, g_n: f64, mu: f64) -> OnLine {
        OnLine {
            v,
            w,
            radius: 0.5,
            inertia: 0.5,
            g_t,
            g_n,
            friction: mu,
            resistance: 0.0,
        }
    }

    #[test]
    fn a_disk_thrown_sliding_rolls_after_a_third_of_its_slip_over_mu_g() {
        // v0 = 3, no spin, mu = 0.2, g = 10: the slip falls at 3 mu g = 6, so it rolls after
        // 0.5 s, at 3 - mu g 0.5 = 2 = v0 / (1 + k).
        let rub = disk(3.0, 0.0, 0.0, 10.0, 0.2).rub();
        assert!(!rub.rolling);
        assert_eq!(rub.until, Some(0.5));
        assert_eq!(rub.accel, -2.0);
        assert_eq!(3.0 + rub.accel * 0.5, 2.0);
        // Its spin then: alpha = mu g / (k r) = 8 (clockwise is negative: s = +1, so w grows
        // to 4 = v / r).
        assert_eq!(rub.alpha * 0.5, 4.0);
        // And then it rolls on at 2, level.
        let rolling = disk(2.0, 4.0, 0.0, 10.0, 0.2).rub();
        assert!(rolling.rolling && rolling.accel == 0.0 && rolling.until.is_none());
    }

    #[test]
    fn on_an_incline_it_rolls_below_the_critical_slope_and_slides_above() {
        // tan a = 3 mu is the limit for a disk: mu = 0.2 holds slopes up to tan a = 0.6.
        let g = 10.0;
        for (tan, rolls) in [(0.5, true), (0.7, false)] {
            let a = f64::atan(tan);
            let (g_t, g_n) = (g * a.sin(), g * a.cos());
            let rub = disk(0.0, 0.0, g_t, g_n, 0.2).rub();
            assert_eq!(rub.rolling, rolls, "tan {tan}");
            if rolls {
                assert!((rub.accel - 2.0 / 3.0 * g_t).abs() < 1e-14);
            } else {
                assert!((rub.accel - (g_t - 0.2 * g_n)).abs() < 1e-14);
                assert!(rub.until.is_none());
            }
        }
    }

    #[test]
    fn rolling_resistance_stops_a_rolling_ball_at_its_analytic_time() {
        let mut ball = disk(2.0, 4.0, 0.0, 10.0, 0.2);
        ball.resistance = 0.05;
        let rub = ball.rub();
        assert!(rub.rolling);
        assert_eq!(rub.accel, -0.5);
        assert_eq!(rub.until, Some(4.0));
        // Stopped, it stays on a level floor and on a slope the resistance holds.
        let still = OnLine {
            v: 0.0,
            w: 0.0,
            ..ball
        }
        .rub();
        assert_eq!((still.accel, still.until), (0.0, None));
        let slope = OnLine {
            v: 0.0,
            w: 0.0,
            g_t: 0.6,
            ..ball
        };
        assert_eq!(slope.rub().accel, 0.0);
        let steeper = OnLine { g_t: 0.9, ..slope };
        assert!((steeper.rub().accel - (0.6 - 0.5)).abs() < 1e-15);
    }
}
