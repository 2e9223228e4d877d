//! Errors returned by the world's API.

use std::fmt;

use glam::DVec2;

use crate::dynamics::BallHandle;
use crate::geometry::ColliderHandle;

/// Why the world refused a call. The world is unchanged when an error is returned.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum WorldError {
    /// A number that must be finite is NaN or infinite; names the parameter.
    NotFinite(&'static str),
    /// A radius is not positive.
    InvalidRadius(f64),
    /// A mass is not positive.
    InvalidMass(f64),
    /// A restitution is outside `[0, 1]`.
    InvalidRestitution(f64),
    /// A friction coefficient is negative or not finite.
    InvalidFriction(f64),
    /// A tangential restitution is outside `[-1, 1]`.
    InvalidTangentialRestitution(f64),
    /// A moment of inertia (a factor of `m r^2`) is outside `(0, 1]`.
    InvalidInertia(f64),
    /// A rolling resistance is negative or not finite.
    InvalidRollingResistance(f64),
    /// A table's value (see [`Table`](crate::Table)) is out of its range: its name, the value
    /// and the range.
    InvalidTable {
        /// The field.
        name: &'static str,
        /// Its value.
        value: f64,
        /// Its range.
        range: &'static str,
    },
    /// A table (seen from above) and gravity in the world's plane exclude each other.
    TableAndGravity,
    /// A ball was given a roll (see [`BallDesc::roll`](crate::BallDesc::roll)) in a world
    /// without a table.
    RollWithoutTable,
    /// A segment's end points are equal, or its length is too small or too large to work
    /// with (see [`Segment::new`](crate::Segment::new)).
    DegenerateSegment,
    /// A collapse time (see [`World::set_collapse_time`](crate::World::set_collapse_time)) is
    /// negative or not finite.
    InvalidCollapseTime(f64),
    /// The new body would overlap a ball (deeper than [`OVERLAP_TOLERANCE`](crate::OVERLAP_TOLERANCE)).
    OverlapsBall(BallHandle),
    /// The new body would overlap a solid collider.
    OverlapsCollider(ColliderHandle),
    /// No live ball has this handle.
    NoSuchBall(BallHandle),
    /// No live collider has this handle.
    NoSuchCollider(ColliderHandle),
    /// The clock stalled: more events at one instant than the engine's zero-time chains can
    /// take (see [`STALL_EVENTS_PER_BALL`](crate::STALL_EVENTS_PER_BALL)). A safety net that
    /// no scene should reach; the world stays consistent but would stall again. Names the
    /// bodies of the last event.
    Stalled {
        /// The instant.
        time: f64,
        /// Events handled at it.
        events: u64,
        /// The ball of the last event.
        ball: BallHandle,
        /// Its partner, if a ball.
        other_ball: Option<BallHandle>,
        /// Its partner, if a collider.
        collider: Option<ColliderHandle>,
    },
    /// A periodic box's side is not positive and finite (see
    /// [`World::set_periodic`](crate::World::set_periodic)).
    InvalidPeriodicBox(DVec2),
    /// A world is made periodic after balls were added to it, or twice.
    PeriodicNotEmpty,
    /// A periodic box and this (gravity, a table) exclude each other (for now).
    PeriodicWith(&'static str),
    /// A ball's position is outside the periodic box `[0, Lx) x [0, Ly)`.
    OutsidePeriodicBox(DVec2),
    /// A ball is too large for the periodic box: at most a third of its shorter side over 2.2.
    TooLargeForPeriodicBox {
        /// The ball's radius.
        radius: f64,
        /// The largest radius the box takes.
        largest: f64,
    },
    /// A static collider comes no farther from a periodic box's edge than a ball's radius
    /// (a ball would meet its image across the edge).
    NearPeriodicEdge {
        /// How far the collider keeps from the nearest edge (negative: beyond it).
        clearance: f64,
        /// The radius it must keep clear by more than: the largest ball's.
        radius: f64,
    },
    /// The requested time is before the world's current time (or NaN).
    TimeBeforeNow {
        /// The time asked for.
        requested: f64,
        /// The world's time.
        now: f64,
    },
}

impl fmt::Display for WorldError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            WorldError::NotFinite(what) => write!(f, "{what} must be finite"),
            WorldError::InvalidRadius(r) => write!(f, "radius must be > 0 (got {r})"),
            WorldError::InvalidMass(m) => write!(f, "mass must be > 0 (got {m})"),
            WorldError::InvalidRestitution(e) => {
                write!(f, "restitution must be in [0, 1] (got {e})")
            }
            WorldError::InvalidFriction(mu) => {
                write!(f, "friction must be finite and >= 0 (got {mu})")
            }
            WorldError::InvalidTangentialRestitution(beta) => {
                write!(f, "tangential restitution must be in [-1, 1] (got {beta})")
            }
            WorldError::InvalidInertia(k) => {
                write!(f, "inertia (a factor of m r^2) must be in (0, 1] (got {k})")
            }
            WorldError::InvalidRollingResistance(c) => {
                write!(f, "rolling resistance must be finite and >= 0 (got {c})")
            }
            WorldError::InvalidTable { name, value, range } => {
                write!(f, "table {name} must be {range} (got {value})")
            }
            WorldError::TableAndGravity => write!(
                f,
                "a table is seen from above: the world's gravity must be [0, 0] with a table"
            ),
            WorldError::RollWithoutTable => {
                write!(f, "a ball's roll needs a table (World::set_table)")
            }
            WorldError::DegenerateSegment => write!(
                f,
                "segment end points must be distinct, at a representable distance"
            ),
            WorldError::InvalidCollapseTime(t) => {
                write!(f, "collapse time must be finite and >= 0 (got {t})")
            }
            WorldError::OverlapsBall(h) => write!(f, "overlaps ball {}", h.index()),
            WorldError::OverlapsCollider(h) => write!(f, "overlaps collider {}", h.index()),
            WorldError::NoSuchBall(h) => write!(f, "no ball with handle {h:?}"),
            WorldError::NoSuchCollider(h) => write!(f, "no collider with handle {h:?}"),
            WorldError::Stalled {
                time,
                events,
                ball,
                other_ball,
                collider,
            } => {
                write!(
                    f,
                    "the clock stalled at t = {time:?} ({events} events there); last: ball {}",
                    ball.index()
                )?;
                if let Some(b) = other_ball {
                    write!(f, " and ball {}", b.index())?;
                }
                if let Some(c) = collider {
                    write!(f, " and collider {}", c.index())?;
                }
                Ok(())
            }
            WorldError::InvalidPeriodicBox(size) => write!(
                f,
                "a periodic box's sides must be finite and > 0 (got [{}, {}])",
                size.x, size.y
            ),
            WorldError::PeriodicNotEmpty => write!(
                f,
                "a world is made periodic before any ball is added, and once"
            ),
            WorldError::PeriodicWith(what) => {
                write!(f, "a periodic box does not take {what} (yet)")
            }
            WorldError::OutsidePeriodicBox(p) => write!(
                f,
                "a ball's position must be inside the periodic box [0, Lx) x [0, Ly) (got [{}, {}])",
                p.x, p.y
            ),
            WorldError::TooLargeForPeriodicBox { radius, largest } => write!(
                f,
                "a ball's radius must be at most {largest} in this periodic box (its shorter side / 6.6; got {radius})"
            ),
            WorldError::NearPeriodicEdge { clearance, radius } => write!(
                f,
                "a collider must keep clear of the periodic box's edges by more than the largest ball's radius {radius} (it keeps {clearance})"
            ),
            WorldError::TimeBeforeNow { requested, now } => {
                write!(f, "time {requested} is before the world's time {now}")
            }
        }
    }
}

impl std::error::Error for WorldError {}
