//! Casting a ball against the static geometry.

use glam::DVec2;

use crate::geometry::{ColliderHandle, CollisionGroups, Feature, Shape};
use crate::pipeline::{World, WorldError};
use crate::toi::{Crossing, Motion, time_of_impact_ball_circle, time_of_impact_ball_segment};

/// Options for [`World::cast_ball`] and [`World::bounce_path`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CastOptions {
    /// Only hits at or before this time count; may be infinite (the default).
    pub max_time: f64,
    /// The cast ball's collision groups: colliders it does not interact with are ignored.
    pub groups: CollisionGroups,
    /// Whether sensors stop a cast (the default is no: sensors are passed through).
    pub include_sensors: bool,
    /// The cast ball's restitution, for [`World::bounce_path`]; each bounce uses its product with
    /// the collider's, as the engine does. Default 1.
    pub restitution: f64,
}

impl Default for CastOptions {
    fn default() -> Self {
        Self {
            max_time: f64::INFINITY,
            groups: CollisionGroups::ALL,
            include_sensors: false,
            restitution: 1.0,
        }
    }
}

/// Where a cast ball first touches a collider.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CastHit {
    /// Time from the start of the cast.
    pub time: f64,
    /// The ball's centre at the hit.
    pub position: DVec2,
    /// The ball's velocity just before the hit.
    pub velocity: DVec2,
    /// The contact point on the collider.
    pub point: DVec2,
    /// Unit contact normal, from the collider towards the ball's centre.
    pub normal: DVec2,
    /// The collider hit.
    pub collider: ColliderHandle,
    /// The part of the collider hit.
    pub feature: Feature,
}

impl World {
    /// The first collider a ball of `radius`, starting at `origin` with `velocity` (and the
    /// world's gravity), would touch; `None` if it touches none by `options.max_time`.
    ///
    /// Only static colliders are considered, not balls. The touching-contact policy applies: a
    /// ball that starts touching a collider and moving into it hits it at time 0; one that
    /// starts touching and moving away does not. Ties go to the smaller collider slot index.
    ///
    /// # Errors
    /// If a number is not finite, `radius` is not positive, or `max_time` is negative or NaN.
    pub fn cast_ball(
        &self,
        origin: DVec2,
        velocity: DVec2,
        radius: f64,
        options: &CastOptions,
    ) -> Result<Option<CastHit>, WorldError> {
        validate(origin, velocity, radius, options)?;
        let motion = Motion {
            position: origin,
            velocity,
            acceleration: self.gravity,
        };
        let mut best: Option<(f64, ColliderHandle, Feature)> = None;
        for (handle, collider) in self.colliders.iter() {
            if (collider.sensor && !options.include_sensors)
                || !collider.groups.interact(options.groups)
            {
                continue;
            }
            let horizon = best.map_or(options.max_time, |b| b.0);
            let hit = match &collider.shape {
                Shape::Segment(s) => {
                    time_of_impact_ball_segment(&motion, radius, s, Crossing::Enter, horizon)
                        .map(|c| (c.time, Feature::from(c.feature)))
                }
                Shape::Circle(c) => time_of_impact_ball_circle(
                    &motion,
                    radius,
                    c.center,
                    c.radius,
                    Crossing::Enter,
                    horizon,
                )
                .map(|t| (t, Feature::Circle)),
            };
            if let Some((time, feature)) = hit
                && best.is_none_or(|b| time < b.0)
            {
                best = Some((time, handle, feature));
            }
        }
        Ok(best.map(|(time, collider, feature)| {
            let position = motion.position_at(time);
            let shape = &self.colliders.get(collider).expect("live").shape;
            let (n, point) = shape.contact(feature, position);
            CastHit {
                time,
                position,
                velocity: motion.velocity_at(time),
                point,
                normal: n.normalize_or_zero(),
                collider,
                feature,
            }
        }))
    }
}

pub(super) fn validate(
    origin: DVec2,
    velocity: DVec2,
    radius: f64,
    options: &CastOptions,
) -> Result<(), WorldError> {
    if !origin.is_finite() {
        return Err(WorldError::NotFinite("cast origin"));
    }
    if !velocity.is_finite() {
        return Err(WorldError::NotFinite("cast velocity"));
    }
    if !(radius > 0.0 && radius.is_finite()) {
        return Err(WorldError::InvalidRadius(radius));
    }
    if !(options.max_time >= 0.0) {
        return Err(WorldError::NotFinite("cast max_time (must be >= 0)"));
    }
    if !(0.0..=1.0).contains(&options.restitution) {
        return Err(WorldError::InvalidRestitution(options.restitution));
    }
    Ok(())
}
