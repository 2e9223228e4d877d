//! A ball of a volley: its engine handle and the state the rules attach to it.

use exact2d::{BallHandle, DVec2};

/// The rules' record of one ball of the current volley (or a clone).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Flight {
    /// The engine's handle while the ball is in play.
    pub handle: Option<BallHandle>,
    /// A clone from a split pick-up.
    pub clone: bool,
    /// Whether it already split this round.
    pub split: bool,
    /// A floor-bounce charge.
    pub floor_bounce: bool,
    /// Whether it already bounced off the floor this round (one floor bounce per ball).
    pub floor_bounced: bool,
    /// A shield charge.
    pub shield: bool,
    /// Whether it took a boost.
    pub boosted: bool,
    /// Whether a random-direction pick-up already turned it this round.
    pub redirected: bool,
    /// Its nominal speed (anti-stall rotations keep it; `|v|` would drift by rounding).
    pub speed: f64,
    /// Its radius.
    pub radius: f64,
    /// When the anti-stall rule acts on it next (see [`crate::anti_stall`]).
    pub deadline: f64,
    /// How many times it was steered down.
    pub steers: u32,
}

impl Flight {
    pub fn new(handle: BallHandle, speed: f64, radius: f64, deadline: f64) -> Self {
        Self {
            handle: Some(handle),
            clone: false,
            split: false,
            floor_bounce: false,
            floor_bounced: false,
            shield: false,
            boosted: false,
            redirected: false,
            speed,
            radius,
            deadline,
            steers: 0,
        }
    }
}

/// A ball in play, as a front end or a test sees it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BallView {
    /// The game's id of the ball within this volley (launch order, then clones).
    pub id: u32,
    /// Centre, at the volley's clock.
    pub position: DVec2,
    /// Velocity.
    pub velocity: DVec2,
    /// Radius.
    pub radius: f64,
    /// Whether it is a clone from a split.
    pub clone: bool,
    /// Whether it carries a floor-bounce charge.
    pub floor_bounce: bool,
    /// Whether it carries a shield.
    pub shield: bool,
}
