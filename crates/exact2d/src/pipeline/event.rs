//! The events the world reports to its caller.

use glam::DVec2;

use crate::dynamics::BallHandle;
use crate::geometry::{ColliderHandle, Feature};

/// A ball bounced off a solid collider.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ContactEvent {
    /// When.
    pub time: f64,
    /// The ball.
    pub ball: BallHandle,
    /// The collider.
    pub collider: ColliderHandle,
    /// The part of the collider touched.
    pub feature: Feature,
    /// The contact point, on the collider.
    pub point: DVec2,
    /// Unit contact normal, from the collider towards the ball's centre.
    pub normal: DVec2,
    /// The speed at which the ball approached along the normal, before the bounce (`>= 0`).
    pub normal_speed: f64,
    /// The impulse the collider gave the ball along `normal`: `m (v' - v) . normal`, its mass
    /// times the change of its normal velocity (`>= 0`; `(1 + e) m normal_speed` for a plain
    /// bounce of restitution `e`). Summed over the events on a wall and divided by the time
    /// and the wall's length, it is the pressure on the wall. In a jam (a simultaneous impact
    /// of several contacts, see [`World::instant_events`](crate::World::instant_events)) it is
    /// the ball's whole change of momentum along this normal.
    pub impulse: f64,
    /// The friction impulse the ball received along `normal.perp()` (0 without friction; see
    /// [`Roughness`](crate::Roughness)).
    pub tangential_impulse: f64,
}

/// Two balls collided.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BallContactEvent {
    /// When.
    pub time: f64,
    /// The ball with the smaller slot index.
    pub a: BallHandle,
    /// The other ball.
    pub b: BallHandle,
    /// The contact point.
    pub point: DVec2,
    /// Unit contact normal, from `a`'s centre towards `b`'s.
    pub normal: DVec2,
    /// The speed at which they approached along the normal, before the impact (`>= 0`).
    pub normal_speed: f64,
    /// The impulse `b` received along `normal` (and `a` the opposite one): `m_b (v_b' - v_b)
    /// . normal`, `b`'s mass times the change of its normal velocity (`>= 0` for a plain
    /// collision; in a jam, `b`'s whole change of momentum along this normal). Against a
    /// sleeping ball that takes the push, the impulse on the moving ball.
    pub impulse: f64,
    /// The friction impulse `b` received along `normal.perp()` (and `a` the opposite one);
    /// 0 without friction (see [`Roughness`](crate::Roughness)). Against a sleeping ball,
    /// the moving ball's along its own contact's `perp`, as for a collider.
    pub tangential_impulse: f64,
}

/// A ball started or stopped overlapping a sensor.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SensorEvent {
    /// When.
    pub time: f64,
    /// The ball.
    pub ball: BallHandle,
    /// The sensor.
    pub collider: ColliderHandle,
    /// The part of the sensor's boundary crossed.
    pub feature: Feature,
    /// The ball's centre at that moment.
    pub position: DVec2,
}

/// Something that happened at an exact time. The world hands events to its caller one at a
/// time ([`World::step_until`](crate::World::step_until)), so the caller can react (remove a
/// brick, change a velocity) before the world goes on.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Event {
    /// A ball bounced off a solid segment, end point or static circle.
    Contact(ContactEvent),
    /// Two balls collided.
    BallContact(BallContactEvent),
    /// A ball started overlapping a sensor.
    SensorEnter(SensorEvent),
    /// A ball stopped overlapping a sensor.
    SensorExit(SensorEvent),
}

impl Event {
    /// When the event happened.
    #[must_use]
    pub fn time(&self) -> f64 {
        match self {
            Event::Contact(e) => e.time,
            Event::BallContact(e) => e.time,
            Event::SensorEnter(e) | Event::SensorExit(e) => e.time,
        }
    }
}
