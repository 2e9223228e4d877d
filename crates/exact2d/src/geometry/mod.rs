//! What balls collide with: static segments and circles, solid or sensors.

mod circle;
mod collider;
mod collider_set;
mod feature;
mod groups;
mod segment;
mod shape;

pub use circle::Circle;
pub(crate) use collider::ShapeDesc;
pub use collider::{Collider, ColliderDesc, ColliderHandle};
pub(crate) use collider_set::ColliderSet;
pub use feature::Feature;
pub use groups::CollisionGroups;
pub use segment::Segment;
pub use shape::Shape;
