//! Static colliders: a shape plus how balls respond to it.

use super::{CollisionGroups, Shape};

/// A handle to a collider in a [`World`](crate::World): an index and a generation, so a handle
/// to a removed collider never refers to a later one that reuses the slot.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct ColliderHandle {
    pub(crate) index: u32,
    pub(crate) generation: u32,
}

impl ColliderHandle {
    /// The slot index; unique among live colliders, reused after removal.
    #[must_use]
    pub fn index(self) -> u32 {
        self.index
    }

    /// The generation of the slot when this handle was made.
    #[must_use]
    pub fn generation(self) -> u32 {
        self.generation
    }
}

/// A static collider: a shape, whether it is solid or a sensor, its restitution, collision
/// groups, and a number the user chooses to recognise it by.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Collider {
    /// The shape.
    pub shape: Shape,
    /// Sensors are passed through; entering and leaving them are reported as events.
    pub sensor: bool,
    /// Coefficient of restitution in `[0, 1]`; a contact uses the product of the ball's and
    /// the collider's.
    pub restitution: f64,
    /// Which balls interact with this collider.
    pub groups: CollisionGroups,
    /// Free for the user: a brick id, an index into a game's table.
    pub user_data: u64,
    /// Coulomb's friction coefficient, `>= 0`; 0 (the default) is frictionless. A contact
    /// uses the geometric mean of the ball's and the collider's.
    pub friction: f64,
    /// Tangential restitution in `[-1, 1]` (see
    /// [`Roughness`](crate::Roughness)); default 0.
    pub tangential_restitution: f64,
    /// Rolling resistance, `>= 0`; default 0. A ball rolling on it uses the geometric mean of
    /// its own and the collider's.
    pub rolling_resistance: f64,
}

impl Collider {
    /// Its surface's roughness.
    #[must_use]
    pub fn roughness(&self) -> crate::Roughness {
        crate::Roughness {
            friction: self.friction,
            tangential_restitution: self.tangential_restitution,
            rolling_resistance: self.rolling_resistance,
        }
    }
}

/// A description of a collider to add: [`ColliderDesc::segment`] or [`ColliderDesc::circle`],
/// then the builder methods.
///
/// ```
/// use exact2d::{ColliderDesc, DVec2};
/// let wall = ColliderDesc::segment(DVec2::new(0.0, 0.0), DVec2::new(10.0, 0.0)).restitution(0.9);
/// let pickup = ColliderDesc::circle(DVec2::new(5.0, 5.0), 0.3).sensor(true).user_data(7);
/// # let _ = (wall, pickup);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ColliderDesc {
    pub(crate) kind: ShapeDesc,
    pub(crate) sensor: bool,
    pub(crate) restitution: f64,
    pub(crate) groups: CollisionGroups,
    pub(crate) user_data: u64,
    pub(crate) friction: f64,
    pub(crate) tangential_restitution: f64,
    pub(crate) rolling_resistance: f64,
}

/// A shape as given, before validation.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum ShapeDesc {
    Segment { a: glam::DVec2, b: glam::DVec2 },
    Circle { center: glam::DVec2, radius: f64 },
}

impl ColliderDesc {
    fn new(kind: ShapeDesc) -> Self {
        Self {
            kind,
            sensor: false,
            restitution: 1.0,
            groups: CollisionGroups::ALL,
            user_data: 0,
            friction: 0.0,
            tangential_restitution: 0.0,
            rolling_resistance: 0.0,
        }
    }

    /// A solid segment from `a` to `b`, perfectly elastic.
    ///
    /// [`World::add_collider`](crate::World::add_collider) refuses it with
    /// [`WorldError::DegenerateSegment`](crate::WorldError::DegenerateSegment) if [`Segment::new`](super::Segment::new)
    /// would: equal end points, or a squared length that is not a positive finite `f64` (a
    /// segment longer than about `1.3e154` or shorter than about `2.2e-162`).
    #[must_use]
    pub fn segment(a: glam::DVec2, b: glam::DVec2) -> Self {
        Self::new(ShapeDesc::Segment { a, b })
    }

    /// A solid disc, perfectly elastic. The radius must be positive and finite (any such
    /// `f64`, subnormal included), or [`World::add_collider`](crate::World::add_collider) refuses
    /// it with [`WorldError::InvalidRadius`](crate::WorldError::InvalidRadius).
    #[must_use]
    pub fn circle(center: glam::DVec2, radius: f64) -> Self {
        Self::new(ShapeDesc::Circle { center, radius })
    }

    /// Make it a sensor (balls pass through; entering and leaving are reported).
    #[must_use]
    pub fn sensor(mut self, sensor: bool) -> Self {
        self.sensor = sensor;
        self
    }

    /// Set the coefficient of restitution, in `[0, 1]`.
    #[must_use]
    pub fn restitution(mut self, restitution: f64) -> Self {
        self.restitution = restitution;
        self
    }

    /// Set the collision groups.
    #[must_use]
    pub fn groups(mut self, groups: CollisionGroups) -> Self {
        self.groups = groups;
        self
    }

    /// Set the user data.
    #[must_use]
    pub fn user_data(mut self, user_data: u64) -> Self {
        self.user_data = user_data;
        self
    }

    /// Set Coulomb's friction coefficient, `>= 0` (a contact has friction only if the ball
    /// has some too).
    #[must_use]
    pub fn friction(mut self, friction: f64) -> Self {
        self.friction = friction;
        self
    }

    /// Set the tangential restitution, in `[-1, 1]`.
    #[must_use]
    pub fn tangential_restitution(mut self, tangential_restitution: f64) -> Self {
        self.tangential_restitution = tangential_restitution;
        self
    }

    /// Set the rolling resistance, `>= 0` (a ball rolling on it needs some too).
    #[must_use]
    pub fn rolling_resistance(mut self, rolling_resistance: f64) -> Self {
        self.rolling_resistance = rolling_resistance;
        self
    }
}
