//! Which of the surfaces a resting ball touches hold it against gravity.
//!
//! A ball at rest against several frictionless surfaces, with unit normals `n_i` from each
//! surface to its centre, under gravity `g`: each surface can push the ball, never pull it.
//! Its acceleration is the one nearest `g` that moves it into none of them,
//!
//! ```text
//! a = g + sum_i l_i n_i,   l_i >= 0,   a . n_i >= 0,   l_i (a . n_i) = 0,
//! ```
//!
//! the projection of `g` onto the cone `{a : a . n_i >= 0}` (the unilateral constraints of a
//! rigid body in contact, Moreau 1988, "Unilateral contact and dry friction in finite freedom
//! dynamics"). In the plane the projection is one of three things:
//!
//! - `g` itself, if no surface is pulled into (`g . n_i >= 0` for all): nothing holds it;
//! - `g` without its part along one normal, `g - (g . n_k) n_k`, if that moves it into no
//!   other surface: it slides on surface `k`, and slides *along* the others (an exact-fit
//!   channel: the two walls' normals are opposite, and gravity's part along the channel is
//!   what is left);
//! - zero otherwise: two surfaces at an angle, between which `-g` lies, hold it at rest (a
//!   wedge), since two independent constraints on a plane vector pin it.
//!
//! The tests `a . n_i >= 0` allow `PARALLEL |g|` of rounding: two walls of an exact-fit
//! channel written at an angle have normals that are opposite only to a rounding error, and a
//! strict test would find the slide along one pulling the ball into the other by that error
//! (and the other the same way back): the ball would be handed between them for ever.

use glam::DVec2;

/// Below this sine of the angle between them, two surfaces count as parallel: `1e-9`, far
/// above the rounding of unit normals (`1e-16`), far below any angle a scene means.
pub(crate) const PARALLEL: f64 = 1e-9;

/// What holds a ball against gravity (see the module documentation); indices are into the
/// normals given to [`Hold::of`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Hold {
    /// No surface is pulled into: the ball flies.
    Free,
    /// It slides on surface `k` (gravity without its part along `n_k`), touching the others.
    Slide(usize),
    /// Surfaces `k` and `j` hold it at rest.
    Rest(usize, usize),
}

impl Hold {
    /// What holds a ball touching surfaces of unit normals `normals` under `gravity`. The
    /// earliest surface that can hold it alone is the one it slides on; for a rest, the
    /// earliest surface pulled into and the one its slide would cut into most deeply.
    pub(crate) fn of(gravity: DVec2, normals: &[DVec2]) -> Self {
        let slack = PARALLEL * gravity.length();
        let pulled = |n: DVec2| gravity.dot(n) < -slack;
        let Some(first) = normals.iter().position(|&n| pulled(n)) else {
            return Hold::Free;
        };
        for (k, &n) in normals.iter().enumerate() {
            if !pulled(n) {
                continue;
            }
            let slide = gravity - n * gravity.dot(n);
            if normals.iter().all(|&m| slide.dot(m) >= -slack) {
                return Hold::Slide(k);
            }
        }
        let slide = gravity - normals[first] * gravity.dot(normals[first]);
        let deepest = (0..normals.len())
            .filter(|&j| j != first)
            .min_by(|&i, &j| slide.dot(normals[i]).total_cmp(&slide.dot(normals[j])))
            .unwrap_or(first);
        Hold::Rest(first, deepest)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn unit(degrees: f64) -> DVec2 {
        let a = degrees.to_radians();
        DVec2::new(a.cos(), a.sin())
    }

    const G: DVec2 = DVec2::new(0.0, -10.0);

    #[test]
    fn a_floor_holds_a_ball_that_slides_nowhere() {
        assert_eq!(Hold::of(G, &[DVec2::Y]), Hold::Slide(0));
        assert_eq!(Hold::of(G, &[-DVec2::Y]), Hold::Free);
        assert_eq!(Hold::of(G, &[DVec2::X]), Hold::Free);
    }

    #[test]
    fn a_ramp_beside_a_wall_it_slides_away_from_holds_alone() {
        // A ramp falling to the right, a wall on the left: the slide goes away from the wall.
        let ramp = unit(90.0 - 30.0);
        assert_eq!(Hold::of(G, &[DVec2::X, ramp]), Hold::Slide(1));
    }

    #[test]
    fn a_wedge_holds_a_ball_at_rest() {
        // The walls of a V of 10 degrees: each slide runs into the other.
        let (left, right) = (unit(5.0), unit(180.0 - 5.0));
        assert_eq!(Hold::of(G, &[left, right]), Hold::Rest(0, 1));
        // Tilted so that -g lies outside the V: it slides along the flatter wall.
        let (steep, flat) = (unit(30.0), unit(80.0));
        assert_eq!(Hold::of(G, &[steep, flat]), Hold::Slide(1));
    }

    #[test]
    fn an_exact_fit_channel_written_at_an_angle_lets_the_ball_slide_along_it() {
        // Walls of a channel at 17 degrees whose normals are opposite only to rounding.
        let a = unit(17.0);
        let b = DVec2::new(-a.x, -a.y * (1.0 + 4.0 * f64::EPSILON));
        let hold = Hold::of(G, &[a, b]);
        assert!(matches!(hold, Hold::Slide(_)), "{hold:?}");
        // Upright, gravity runs along both walls: nothing holds it.
        assert_eq!(Hold::of(G, &[DVec2::X, -DVec2::X]), Hold::Free);
    }
}
