//! Balls: handles, descriptions to add them, and a snapshot of one.

use glam::DVec2;

use super::DEFAULT_INERTIA;
use crate::geometry::CollisionGroups;

/// A handle to a ball in a [`World`](crate::World): a slot index and a generation, so a handle
/// to a removed ball never refers to a later ball that reuses the slot.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct BallHandle {
    pub(crate) index: u32,
    pub(crate) generation: u32,
}

impl BallHandle {
    /// The slot index; unique among live balls, reused after removal.
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

/// A description of a ball to add to a world.
///
/// ```
/// use exact2d::{BallDesc, DVec2};
/// let ball = BallDesc::new(DVec2::new(1.0, 2.0), 0.25)
///     .velocity(DVec2::new(3.0, 0.0))
///     .mass(2.0)
///     .user_data(42);
/// # let _ = ball;
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BallDesc {
    /// Position of the centre.
    pub position: DVec2,
    /// Velocity.
    pub velocity: DVec2,
    /// Radius, `> 0`.
    pub radius: f64,
    /// Mass, `> 0`.
    pub mass: f64,
    /// Coefficient of restitution in `[0, 1]`; a contact uses the product of both parties'.
    pub restitution: f64,
    /// Which balls and colliders it interacts with.
    pub groups: CollisionGroups,
    /// Free for the user.
    pub user_data: u64,
    /// Angular velocity in radians per second, counter-clockwise positive; default 0.
    pub spin: f64,
    /// Moment of inertia as a factor of `m r^2`, in `(0, 1]`; default
    /// [`DEFAULT_INERTIA`], 1/2, a uniform disk (a ring is 1).
    pub inertia: f64,
    /// Coulomb's friction coefficient `mu`, `>= 0`; default 0, frictionless. A contact uses
    /// the geometric mean of both parties' (see [`Roughness::pair`](crate::Roughness::pair)),
    /// so it has friction only if both have.
    pub friction: f64,
    /// Tangential restitution `beta` in `[-1, 1]` (-1 smooth, 0 a sticking contact ends
    /// without slip, 1 perfectly rough); default 0. Matters only with friction.
    pub tangential_restitution: f64,
    /// Rolling resistance, `>= 0`; default 0: rolling on a surface (with friction), the ball
    /// loses speed at this times the surface's normal pull (the geometric mean of its own and
    /// the surface's).
    pub rolling_resistance: f64,
    /// On a table (see [`Table`](crate::Table)): the angular velocity about the horizontal
    /// axes, `(w_x, w_y)` in radians per second (a ball rolling along `+x` at speed `v` has
    /// `(0, v / r)`); default zero. Only a world with a table may have one.
    pub roll: DVec2,
}

impl BallDesc {
    /// A ball at rest at `position`, of unit mass, perfectly elastic, in every group.
    #[must_use]
    pub fn new(position: DVec2, radius: f64) -> Self {
        Self {
            position,
            velocity: DVec2::ZERO,
            radius,
            mass: 1.0,
            restitution: 1.0,
            groups: CollisionGroups::ALL,
            user_data: 0,
            spin: 0.0,
            inertia: DEFAULT_INERTIA,
            friction: 0.0,
            tangential_restitution: 0.0,
            rolling_resistance: 0.0,
            roll: DVec2::ZERO,
        }
    }

    /// Set the velocity.
    #[must_use]
    pub fn velocity(mut self, velocity: DVec2) -> Self {
        self.velocity = velocity;
        self
    }

    /// Set the mass.
    #[must_use]
    pub fn mass(mut self, mass: f64) -> Self {
        self.mass = mass;
        self
    }

    /// Set the coefficient of restitution.
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

    /// Set the angular velocity (radians per second, counter-clockwise positive).
    #[must_use]
    pub fn spin(mut self, spin: f64) -> Self {
        self.spin = spin;
        self
    }

    /// Set the roll (on a table): the angular velocity about the horizontal axes.
    #[must_use]
    pub fn roll(mut self, roll: DVec2) -> Self {
        self.roll = roll;
        self
    }

    /// Set the moment of inertia, as a factor of `m r^2`.
    #[must_use]
    pub fn inertia(mut self, inertia: f64) -> Self {
        self.inertia = inertia;
        self
    }

    /// Set Coulomb's friction coefficient.
    #[must_use]
    pub fn friction(mut self, friction: f64) -> Self {
        self.friction = friction;
        self
    }

    /// Set the tangential restitution.
    #[must_use]
    pub fn tangential_restitution(mut self, tangential_restitution: f64) -> Self {
        self.tangential_restitution = tangential_restitution;
        self
    }

    /// Set the rolling resistance.
    #[must_use]
    pub fn rolling_resistance(mut self, rolling_resistance: f64) -> Self {
        self.rolling_resistance = rolling_resistance;
        self
    }
}

/// A snapshot of a ball at the world's current time.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ball {
    /// Position of the centre.
    pub position: DVec2,
    /// Velocity.
    pub velocity: DVec2,
    /// Radius.
    pub radius: f64,
    /// Mass.
    pub mass: f64,
    /// Coefficient of restitution.
    pub restitution: f64,
    /// Collision groups.
    pub groups: CollisionGroups,
    /// The user's data.
    pub user_data: u64,
    /// Angular velocity, counter-clockwise positive.
    pub spin: f64,
    /// The angle the ball has turned through since it was added, in `[-pi, pi]`.
    pub angle: f64,
    /// Moment of inertia as a factor of `m r^2`.
    pub inertia: f64,
    /// Coulomb's friction coefficient.
    pub friction: f64,
    /// Tangential restitution.
    pub tangential_restitution: f64,
    /// Rolling resistance.
    pub rolling_resistance: f64,
    /// On a table: the angular velocity about the horizontal axes (zero elsewhere).
    pub roll: DVec2,
}

impl Ball {
    /// Kinetic energy: translational and rotational,
    /// `m |v|^2 / 2 + k m r^2 (w^2 + |roll|^2) / 2`.
    #[must_use]
    pub fn kinetic_energy(&self) -> f64 {
        let turning = self.inertia
            * self.radius
            * self.radius
            * (self.spin * self.spin + self.roll.length_squared());
        0.5 * self.mass * (self.velocity.length_squared() + turning)
    }
}
