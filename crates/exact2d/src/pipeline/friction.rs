//! Friction at impacts: the tangential impulse of a rough contact (`dynamics/rough.rs`),
//! applied after the normal response of a two-body collision.
//!
//! Of the impacts, only binary ones of free flight carry it: a ball bouncing off a collider
//! (or a sleeping ball's circle) and two balls colliding that are not pulled together with
//! one of them supported. Groups, jams, micro-hops, backed collisions and the responses of a
//! zero-time chain (which the collapse floor makes elastic) stay frictionless for now, and a
//! ball's spin passes through them unchanged; friction on the surface a ball rests on is
//! `pipeline/rolling.rs`'s. The tangential impulse changes no
//! normal velocity (`t` is perpendicular to `n`), so the normal response's guarantees (the
//! pair separates, no contact is left approaching) stand; it never adds energy.

use glam::DVec2;

use super::World;
use crate::dynamics::{Roughness, SpinningBody, apply_friction, friction_impulse};

impl World {
    /// Ball `index`'s spinning body moving at `velocity`, if the world keeps spins (inlined:
    /// a frictionless world's collisions pay one test for it).
    #[inline]
    fn spinning_body(&self, index: u32, velocity: DVec2) -> Option<(SpinningBody, Roughness)> {
        let spin = self.balls.spin(index)?;
        let (mass, _) = self.balls.mass_and_restitution(index).expect("live ball");
        let radius = self.balls.kinematics(index).expect("live ball").radius;
        let body = SpinningBody {
            velocity,
            spin: spin.omega_at(self.time),
            mass,
            inertia: spin.inertia,
            radius,
        };
        Some((body, spin.roughness))
    }

    /// Ball `index`, leaving a surface of roughness `surface` at `velocity` after a normal
    /// impulse `impulse` along `normal` (unit, from the surface to the ball): its velocity
    /// after the friction impulse, and that impulse along `normal.perp()`; its spin set.
    pub(crate) fn rub_on_surface(
        &mut self,
        index: u32,
        velocity: DVec2,
        normal: DVec2,
        impulse: f64,
        surface: Roughness,
    ) -> (DVec2, f64) {
        let Some((body, own)) = self.spinning_body(index, velocity) else {
            return (velocity, 0.0);
        };
        let n = DVec2::ZERO - normal;
        let j = friction_impulse(&body, None, n, impulse, own.pair(surface));
        if j == 0.0 {
            return (velocity, 0.0);
        }
        let (after, _) = apply_friction(&body, None, n, j);
        let time = self.time;
        self.balls.spin_mut(index).set_omega(time, after.spin);
        // Body 1 (the ball) took `-j` along `perp(-normal)`: `j` along `normal.perp()`.
        (after.velocity, j)
    }

    /// Balls `i` and `j`, leaving each other at `vi` and `vj` after a normal impulse
    /// `impulse` along `normal` (unit, from `i` to `j`): their velocities after the friction
    /// impulse, and the impulse `j` received along `normal.perp()`; their spins set.
    pub(crate) fn rub_pair(
        &mut self,
        (i, vi): (u32, DVec2),
        (j, vj): (u32, DVec2),
        normal: DVec2,
        impulse: f64,
    ) -> (DVec2, DVec2, f64) {
        let (Some((a, ra)), Some((b, rb))) = (self.spinning_body(i, vi), self.spinning_body(j, vj))
        else {
            return (vi, vj, 0.0);
        };
        let jt = friction_impulse(&a, Some(&b), normal, impulse, ra.pair(rb));
        if jt == 0.0 {
            return (vi, vj, 0.0);
        }
        let (a2, b2) = apply_friction(&a, Some(&b), normal, jt);
        let b2 = b2.expect("two bodies");
        let time = self.time;
        self.balls.spin_mut(i).set_omega(time, a2.spin);
        self.balls.spin_mut(j).set_omega(time, b2.spin);
        (a2.velocity, b2.velocity, jt)
    }
}
