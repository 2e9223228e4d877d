//! The path of a ball over several bounces: a game's aim preview.

use glam::DVec2;

use super::cast::validate;
use super::{CastHit, CastOptions};
use crate::dynamics::reflect;
use crate::pipeline::{World, WorldError};

impl World {
    /// The first `max_hits` contacts of a ball of `radius` launched from `origin` with
    /// `velocity`, bouncing off the static colliders as the engine would bounce it (reflection
    /// with the product of `options.restitution` and the collider's), until `options.max_time`
    /// (counted from the launch) runs out.
    ///
    /// The path is `origin`, then each hit's `position`; times are from the launch. Balls are
    /// ignored and sensors are passed through (`options.include_sensors` does not apply).
    ///
    /// # Errors
    /// As [`World::cast_ball`].
    pub fn bounce_path(
        &self,
        origin: DVec2,
        velocity: DVec2,
        radius: f64,
        max_hits: usize,
        options: &CastOptions,
    ) -> Result<Vec<CastHit>, WorldError> {
        validate(origin, velocity, radius, options)?;
        let mut hits = Vec::with_capacity(max_hits.min(64));
        let (mut position, mut velocity, mut elapsed) = (origin, velocity, 0.0);
        let options = CastOptions {
            include_sensors: false,
            ..*options
        };
        while hits.len() < max_hits {
            let remaining = CastOptions {
                max_time: options.max_time - elapsed,
                ..options
            };
            if !(remaining.max_time >= 0.0) {
                break;
            }
            let Some(hit) = self.cast_ball(position, velocity, radius, &remaining)? else {
                break;
            };
            let restitution = self.collider(hit.collider).map_or(1.0, |c| c.restitution);
            elapsed += hit.time;
            position = hit.position;
            velocity = reflect(hit.velocity, hit.normal, options.restitution * restitution);
            hits.push(CastHit {
                time: elapsed,
                ..hit
            });
        }
        Ok(hits)
    }
}
