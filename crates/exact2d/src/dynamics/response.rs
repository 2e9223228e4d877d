//! Collision response: reflection off static shapes, impulse exchange between balls.
//!
//! Both take contact normals that need not be unit vectors. Dividing by `n.n` instead of
//! normalising first keeps each formula exactly energy-conserving in real arithmetic for any
//! `n`: with a normalised `n` whose length is `1 + δ`, every elastic bounce off the same wall
//! would change the energy by about `4δ` times the normal part, always with the same sign, a
//! drift that adds up over millions of bounces instead of averaging out.

use glam::DVec2;

/// The velocity after a ball with velocity `v` hits a static surface with normal `n` (pointing
/// from the surface to the ball, any length) and coefficient of restitution `restitution`.
///
/// `v' = v - (1 + e) (v.n / n.n) n`: the normal component is reversed and scaled by `e`, the
/// tangential one is kept. A ball that is not approaching (`v.n >= 0`) is returned unchanged,
/// so a response can never pull a ball into a surface or add energy.
#[must_use]
#[inline]
pub fn reflect(v: DVec2, n: DVec2, restitution: f64) -> DVec2 {
    let vn = v.dot(n);
    if vn >= 0.0 {
        return v;
    }
    v - n * ((1.0 + restitution) * vn / n.dot(n))
}

/// The velocities after two balls collide: `v1`, `m1` and `v2`, `m2`, with `n` pointing from
/// ball 1's centre to ball 2's (any length) and coefficient of restitution `restitution`.
///
/// The impulse acts along `n`. With `u = (v1 - v2).n / n.n` the approach rate, the relative
/// normal velocity goes from `u n` to `-e u n`, and momentum is conserved:
///
/// ```text
/// v1' = v1 - (1 + e) u  m2 / (m1 + m2)  n
/// v2' = v2 + (1 + e) u  m1 / (m1 + m2)  n
/// ```
///
/// With `e = 1` this conserves kinetic energy too. Balls that are not approaching (`u <= 0`)
/// are returned unchanged.
#[must_use]
#[inline]
pub fn collide_balls(
    v1: DVec2,
    m1: f64,
    v2: DVec2,
    m2: f64,
    n: DVec2,
    restitution: f64,
) -> (DVec2, DVec2) {
    let approach = (v1 - v2).dot(n);
    if approach <= 0.0 {
        return (v1, v2);
    }
    let k = (1.0 + restitution) * approach / n.dot(n);
    let (m1, m2) = finite_sum(m1, m2);
    let total = m1 + m2;
    (v1 - n * (k * (m2 / total)), v2 + n * (k * (m1 / total)))
}

#[must_use]
/// A collision of ball 1 (touching a wall of unit normal `wall`, from the wall to the ball)
/// with ball 2, resolved together with the wall's contact if the collision alone would drive
/// ball 1 into the wall: then the pair separates at `restitution` times their approach and
/// ball 1 stops moving into the wall (two impulses solving both conditions at once).
///
/// The world uses it in inelastic zero-time chains (a ball collided with the wall at this very
/// instant): in sequence, the two contacts would repeat at one instant, the pair's approach
/// shrinking by a factor near `m2 / (m1 + m2)` a round: millions of events for a light ball
/// pressed by a heavy one (measured: more than 3e6 for masses 1e-3 and 1).
pub fn collide_balls_backed(
    v1: DVec2,
    m1: f64,
    v2: DVec2,
    m2: f64,
    n: DVec2,
    restitution: f64,
    wall: DVec2,
) -> (DVec2, DVec2) {
    rebound_backed(v1, m1, v2, m2, n, restitution, 0.0, wall)
}

/// Two masses halved (exactly) if their sum would overflow, so that the ratios `m / (m1 + m2)`
/// stay right for masses near `f64::MAX`; unchanged otherwise.
#[inline]
fn finite_sum(m1: f64, m2: f64) -> (f64, f64) {
    if (m1 + m2).is_finite() {
        (m1, m2)
    } else {
        (m1 * 0.5, m2 * 0.5)
    }
}

/// [`collide_balls`], with the balls leaving each other at least at `floor` (the impulse may
/// then add a little energy: the world's micro-hop floor, `MICRO_HOP`).
pub(crate) fn rebound(
    v1: DVec2,
    m1: f64,
    v2: DVec2,
    m2: f64,
    n: DVec2,
    restitution: f64,
    floor: f64,
) -> (DVec2, DVec2) {
    if !(floor > 0.0) {
        return collide_balls(v1, m1, v2, m2, n, restitution);
    }
    let unit = n / n.length();
    let approach = (v1 - v2).dot(unit);
    let target = (restitution * approach).max(floor);
    // The change of the relative normal velocity, from -approach to target.
    let change = target + approach;
    if !(change > 0.0) {
        return (v1, v2);
    }
    let (m1, m2) = finite_sum(m1, m2);
    let total = m1 + m2;
    (
        v1 - unit * (change * (m2 / total)),
        v2 + unit * (change * (m1 / total)),
    )
}

/// [`collide_balls_backed`] with the separation floor of [`rebound`].
#[allow(clippy::too_many_arguments)]
pub(crate) fn rebound_backed(
    v1: DVec2,
    m1: f64,
    v2: DVec2,
    m2: f64,
    n: DVec2,
    restitution: f64,
    floor: f64,
    wall: DVec2,
) -> (DVec2, DVec2) {
    let alone = rebound(v1, m1, v2, m2, n, restitution, floor);
    if alone.0.dot(wall) >= 0.0 {
        // The collision alone leaves ball 1 off the wall: the wall does nothing.
        return alone;
    }
    let unit = n / n.length();
    let approach = (v1 - v2).dot(unit);
    let change = approach + (restitution * approach).max(floor);
    let (c, into) = (unit.dot(wall), v1.dot(wall));
    let denominator = 1.0 / m1 + 1.0 / m2 - c * c / m1;
    let pair = (change - c * into) / denominator;
    let push = pair * c - m1 * into;
    if !(pair > 0.0 && push >= 0.0 && denominator > 0.0) {
        return alone;
    }
    let after = (
        v1 + (wall * push - unit * pair) / m1,
        v2 + unit * (pair / m2),
    );
    // Asked to separate at the restitution times an approach that the wall then takes part
    // of (ball 1 moving off the wall into ball 2), the pair could leave with more energy than
    // it came with: then the impact is perfectly plastic, which never adds any.
    let kinetic = |a: DVec2, b: DVec2| m1 * a.length_squared() + m2 * b.length_squared();
    if restitution > 0.0 && kinetic(after.0, after.1) > kinetic(v1, v2) {
        return rebound_backed(v1, m1, v2, m2, n, 0.0, floor, wall);
    }
    after
}

/// The velocity of a ball that leaves a surface at `v` into free flight under `acceleration`
/// (gravity: a ball that bounces leaves its support), restated at `offset` from the contact
/// point (its centre minus the point, as [`Shape::contact`](crate::Shape::contact) gives it),
/// with contact normal `n` (from the surface to the ball, any length) and radius `radius`:
/// with `u` the normal speed along the unit normal `n / |n|`, `gap = offset . n / |n| -
/// radius` how far the restated centre is off the exact contact line (positive: beyond it),
/// and `g_n = -acceleration . n / |n|` the pull into the surface, the normal speed becomes
/// `sqrt(u^2 - 2 g_n gap)`: the energy of the same bounce from the line, counted at the
/// restated position. Only for a centre beyond the line by a rounding, `0 < gap <= rounding`
/// (the engine passes 8
/// ulps of the contact's coordinates, `8 eps (max |p_i| + radius)`, as for a contact taken
/// now): a ball met farther off the line (a sleeping ball's circle is met within the two
/// balls' micro-hop) is there, not rounded there.
///
/// A trajectory restated at its contact is a rounding off the line, and the hop that starts
/// there lands on the line itself. An elastic ball hopping 8.5e-13 high at y = 1, restated
/// 7e-17 above the line at every bounce, fell those 7e-17 more at every hop and gained their
/// energy: 3,283 hops in 3 s, energy up 1.9e-9 of its scale (`--rough` hunt seed 285473).
/// `v` is returned unchanged when nothing pulls the ball into the surface, when it does not
/// leave it, when it is on the line or farther off it than `rounding`, or when its hop is
/// lower than `gap` (the settling rule takes such a ball); and for a centre restated below
/// the line, which loses that rounding of energy, as a bounce may. (Given back, it kept
/// poured piles bouncing: 16 frictionless 100-ball piles took 1.7 times the wall to rest.)
#[must_use]
pub fn restated_bounce(
    v: DVec2,
    n: DVec2,
    offset: DVec2,
    radius: f64,
    acceleration: DVec2,
    rounding: f64,
) -> DVec2 {
    // Most bounces have nothing pulling them in (no gravity): decided before any root.
    if !(acceleration.dot(n) < 0.0 && v.dot(n) > 0.0) {
        return v;
    }
    let unit = n / n.length();
    let gap = offset.dot(unit) - radius;
    let pull = -acceleration.dot(unit);
    let u = v.dot(unit);
    if !(pull > 0.0 && u > 0.0 && gap > 0.0 && gap <= rounding) {
        return v;
    }
    let squared = u * u - 2.0 * pull * gap;
    if !(squared > 0.0) {
        return v;
    }
    v + unit * (squared.sqrt() - u)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reflection_off_an_axis_aligned_wall_is_exact() {
        let v = reflect(DVec2::new(0.3, -0.7), DVec2::new(0.0, 1.0), 1.0);
        assert_eq!(v, DVec2::new(0.3, 0.7));
    }

    #[test]
    fn restitution_scales_the_normal_component_only() {
        let v = reflect(DVec2::new(2.0, -4.0), DVec2::new(0.0, 3.0), 0.5);
        assert_eq!(v, DVec2::new(2.0, 2.0));
    }

    #[test]
    fn a_separating_ball_is_left_alone() {
        let v = DVec2::new(1.0, 1.0);
        assert_eq!(reflect(v, DVec2::Y, 1.0), v);
    }

    #[test]
    fn a_ball_backed_by_a_wall_stops_the_ball_that_hits_it_when_perfectly_inelastic() {
        // Ball 1 touches a wall above it (normal -y); ball 2 hits it from below at 1.
        let wall = DVec2::new(0.0, -1.0);
        let (a, b) = collide_balls_backed(DVec2::ZERO, 0.001, DVec2::Y, 1.0, -DVec2::Y, 0.0, wall);
        assert_eq!((a, b), (DVec2::ZERO, DVec2::ZERO));
        // With restitution 1/2 the pair separates at half its approach; ball 1 stays put.
        let (a, b) = collide_balls_backed(DVec2::ZERO, 1.0, DVec2::Y, 1.0, -DVec2::Y, 0.5, wall);
        assert!(a.length() < 1e-15 && (b.y + 0.5).abs() < 1e-15, "{a} {b}");
        // Hit sideways, it is not pushed into the wall: an ordinary collision.
        let (a, b) = collide_balls_backed(DVec2::ZERO, 1.0, DVec2::X, 1.0, -DVec2::X, 1.0, wall);
        assert_eq!(
            (a, b),
            collide_balls(DVec2::ZERO, 1.0, DVec2::X, 1.0, -DVec2::X, 1.0)
        );
    }

    #[test]
    fn a_backed_collision_never_adds_energy() {
        // Ball 1 touches a wall behind it (normal +x) but moves off it, into ball 2, which
        // comes the other way: asked to separate at 0.9 of their approach of 1 with ball 1
        // pinned, ball 2 would leave at 0.9 where it came at 0.5.
        let wall = DVec2::X;
        let (v1, v2) = (DVec2::new(0.5, 0.0), DVec2::new(-0.5, 0.0));
        let (a, b) = collide_balls_backed(v1, 1.0, v2, 1.0, DVec2::X, 0.9, wall);
        let energy = |a: DVec2, b: DVec2| a.length_squared() + b.length_squared();
        assert!(energy(a, b) <= energy(v1, v2), "{a} {b}");
        assert!(a.x >= 0.0 && b.x - a.x >= -1e-15, "{a} {b}");
    }

    #[test]
    fn equal_masses_head_on_exchange_velocities_exactly() {
        let (a, b) = collide_balls(DVec2::X, 1.0, -DVec2::X, 1.0, DVec2::new(2.0, 0.0), 1.0);
        assert_eq!((a, b), (-DVec2::X, DVec2::X));
    }

    #[test]
    fn unequal_masses_follow_the_textbook_one_dimensional_formula() {
        // v1' = (m1 - m2) / (m1 + m2) v1 = -1/3, v2' = 2 m1 / (m1 + m2) v1 = 2/3.
        let (a, b) = collide_balls(DVec2::X, 1.0, DVec2::ZERO, 2.0, DVec2::X, 1.0);
        assert!((a.x + 1.0 / 3.0).abs() < 1e-15 && (b.x - 2.0 / 3.0).abs() < 1e-15);
        let momentum = a.x + 2.0 * b.x;
        let energy = a.x * a.x + 2.0 * b.x * b.x;
        assert!((momentum - 1.0).abs() < 1e-15 && (energy - 1.0).abs() < 1e-15);
    }

    const G: DVec2 = DVec2::new(0.0, -9.81);

    /// A ball leaving a level floor from a height `h` above its contact line leaves with the
    /// normal speed that gives it the energy of the same bounce from the line: `u^2 - 2 g h`,
    /// so its apex is the bounce's.
    #[test]
    fn a_hop_from_above_the_line_keeps_the_bounce_s_energy() {
        let r = 1.0 / 1024.0;
        for (u, h) in [(1e-3, 3e-17), (2.0, 1e-9), (0.5, 2e-12)] {
            let v = DVec2::new(0.3, u);
            let w = restated_bounce(v, DVec2::Y, DVec2::Y * (r + h), r, G, 1.0);
            // The height off the line as the restated centre has it (exact: Sterbenz).
            let gap = (r + h) - r;
            assert_eq!(w.x, v.x);
            assert_ne!(w.y, u, "{u} {h}");
            let expected = u * u - 2.0 * 9.81 * gap;
            assert!(
                (w.y * w.y - expected).abs() <= 4.0 * f64::EPSILON * u * u,
                "{u} {h}: {} {expected}",
                w.y * w.y
            );
            let apex = gap + w.y * w.y / (2.0 * 9.81);
            let exact = u * u / (2.0 * 9.81);
            assert!(
                (apex - exact).abs() <= 4.0 * f64::EPSILON * exact,
                "{apex} {exact}"
            );
        }
    }

    /// Nothing pulling the ball into the surface, a ball not leaving it, a position on the
    /// line, or a hop smaller than the height: the velocity is left as it is.
    #[test]
    fn only_a_leaving_ball_pulled_in_changes() {
        let v = DVec2::new(0.3, 1e-3);
        // A ceiling (normal down), a wall (normal across gravity), no gravity.
        assert_eq!(
            restated_bounce(v, DVec2::NEG_Y, DVec2::NEG_Y * (0.5 + 1e-12), 0.5, G, 1.0),
            v
        );
        assert_eq!(
            restated_bounce(v, DVec2::X, DVec2::X * (0.5 + 1e-12), 0.5, G, 1.0),
            v
        );
        assert_eq!(
            restated_bounce(v, DVec2::Y, DVec2::Y * (0.5 + 1e-12), 0.5, DVec2::ZERO, 1.0),
            v
        );
        // Arriving, not leaving; on the line; a hop lower than the height off the line.
        let arriving = DVec2::new(0.3, -1e-3);
        assert_eq!(
            restated_bounce(arriving, DVec2::Y, DVec2::Y * (0.5 + 1e-12), 0.5, G, 1.0),
            arriving
        );
        assert_eq!(
            restated_bounce(v, DVec2::Y, DVec2::Y * (0.5 + 0.0), 0.5, G, 1.0),
            v
        );
        assert_eq!(
            restated_bounce(v, DVec2::Y, DVec2::Y * (0.5 + 1e-6), 0.5, G, 1.0),
            v
        );
        // Below the line: it loses that rounding of energy, as a bounce may.
        let below = DVec2::Y * (0.5 - 1e-12);
        assert_eq!(restated_bounce(v, DVec2::Y, below, 0.5, G, 1.0), v);
        // Farther off the line than the rounding: there, not rounded there.
        let up = DVec2::Y * (0.5 + 1e-12);
        assert_eq!(restated_bounce(v, DVec2::Y, up, 0.5, G, 1e-13), v);
        assert_ne!(restated_bounce(v, DVec2::Y, up, 0.5, G, 1e-11), v);
    }
}
