//! Exact times of impact, one shape pair per file.
//!
//! Every function here answers one question: given the motion of a ball *now* (`t = 0`), at
//! what time `t` in `[0, horizon]` does it first touch (or, for sensors, first leave) a shape?
//! Times are relative to the moment the motion describes.
//!
//! # The touching-contact policy
//!
//! Shapes that touch exactly, or overlap by a rounding error, are common: right after a bounce
//! the ball touches the wall it left. Every function here decides such contacts the same way:
//!
//! - touching (or overlapping) and **approaching**, at first order (the gap is shrinking) or
//!   at second (the gap is momentarily constant and its acceleration pulls in: a ball at rest
//!   on a floor, under gravity): contact **now**, `Some(0.0)`;
//! - overlapping and separating **too slowly to get clear** (the gap's maximum is not above
//!   zero): contact at that maximum, where it stops separating without ever having come
//!   apart;
//! - touching and **separating for good, or tangential with no pull**: **no event now**; a
//!   later contact, if the motion comes back, is found as usual.
//!
//! So a ball that has just been reflected is never reported against the same shape again, and a
//! ball that touches or overlaps a shape is never left moving into it without a contact (a ball
//! placed `1e-12` into a floor under gravity fell through it with no event, once). A grazing
//! pass (a double root) is tangential and is not a contact. (`segment_crossing` and
//! `point_crossing` can also solve with the policy off: only a genuine crossing from outside
//! counts, for a contact the world has already resolved at this instant.)
//!
//! # Exactness
//!
//! Straight motion gives quadratic gaps, solved in closed form without cancellation
//! ([`crate::roots::first_contact`]). Under gravity, the gap to a segment's line is still
//! quadratic, but the gap to a point or a circle is a quartic, isolated and refined to the
//! first representable time of contact ([`crate::roots::ParabolicGap`]). Ball-ball contacts
//! stay quadratic under gravity, since both balls fall alike.
//!
//! # Domain
//!
//! The kernels take raw numbers and never panic; they do not validate them (the
//! [`World`](crate::World) refuses NaN and infinities before they reach a kernel). For any input:
//!
//! - a `Some(t)` is finite and `0 <= t <= horizon`; a negative or NaN `horizon` gives `None`;
//! - NaN in any position, velocity, acceleration or radius gives `None`; an infinite one gives
//!   `None` or whatever the IEEE arithmetic of the formulas decides (an infinitely fast ball
//!   touching a shape and moving into it is in contact now), never a panic;
//! - a contact time too large for an `f64` is `None`.
//!
//! The gaps are squared distances, so the kernels are exact only while the squares and
//! products they form stay finite: the quadratic's discriminant multiplies `|q|^2` by `|v|^2`
//! (position relative to the shape, velocity), so `|q| |v|`, `|q|`, `|v|` and the contact
//! distance `R` must stay below about `1e150`; beyond that a contact can be missed (`None`).
//!
//! Straight-line contacts with a point or a ball are found from `|q|^2 - R^2`, which keeps
//! `R^2` only to the precision of `|q|^2`: the contact position is accurate to about
//! `eps |q|^2 / R` (`eps` = 2.2e-16). That is far below any tolerance for a contact distance
//! that is not tiny against the distance travelled (`|q| / R < 1e3` gives `2e-10 R`), but a
//! ball of radius `1e-9` one unit from another is below it: for `R < 1e-8 |q|` a head-on
//! contact can be missed entirely (the discriminant rounds to a double root, a graze).

mod ball_ball;
mod ball_circle;
mod ball_point;
mod ball_segment;
mod crossing;
mod motion;

pub use ball_ball::time_of_impact_ball_ball;
pub use ball_circle::time_of_impact_ball_circle;
pub(crate) use ball_point::point_crossing;
pub use ball_point::time_of_impact_ball_point;
pub use ball_segment::{SegmentContact, SegmentFeature, time_of_impact_ball_segment};
pub(crate) use ball_segment::{feature_overlap, segment_crossing};
pub use crossing::Crossing;
pub use motion::Motion;
