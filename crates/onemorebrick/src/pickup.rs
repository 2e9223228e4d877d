//! Pick-ups: the kinds and the rule each one applies when a ball enters it.
//!
//! A pick-up is a sensor circle ([`Config::pickup_radius`](crate::Config::pickup_radius))
//! centred in its cell: balls pass through it, and each *entry* of a ball applies the rule.
//! Every kind but [`PickupKind::ExtraBall`] stays for the rest of the round once used, acts on
//! every ball that enters, and leaves the board when the round ends.

use serde::{Deserialize, Serialize};

/// What a pick-up does to a ball that enters it.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Serialize, Deserialize)]
pub enum PickupKind {
    /// +1 ball from the next round on. Taken by the first ball (clones too) that enters; it
    /// leaves the board at once. One reaching the bottom row is granted as well.
    ExtraBall,
    /// A ball that is not a clone and has not split this round spawns a clone at its own
    /// position with its horizontal velocity mirrored (`(-vx, vy)`). Clones never split, are
    /// not counted in the ball total and never return as balls.
    Split,
    /// The ball leaves play for this round (it is not lost: the ball total is unchanged). A
    /// shielded ball loses its shield instead and flies on.
    Hazard,
    /// The ball gets one floor bounce (charges do not stack): the next time it reaches the
    /// floor line it bounces off it instead of being collected. One floor bounce per ball per
    /// round: a ball that already bounced off the floor gets no new charge (otherwise a ball
    /// shot straight through the pick-up would bounce forever).
    FloorBounce,
    /// One damage to every brick in the pick-up's row, each time a ball enters.
    LaserHorizontal,
    /// One damage to every brick in the pick-up's column, each time a ball enters.
    LaserVertical,
    /// Both lasers at once (the pick-up's own cell holds no brick, so nothing is hit twice).
    LaserCross,
    /// The ball's direction is drawn again, upward: `(a, 1)` normalised with `a` uniform in
    /// `[-1/t, 1/t]` (`t` the minimum elevation tangent), keeping its speed. Once per ball
    /// per round: a ball touching the top wall exactly at the pick-up's edge would otherwise
    /// be sent up into the wall, bounce back into the pick-up and be turned up again, a
    /// million times a second (found by the soak test, seed 95).
    RandomDirection,
    /// The ball's radius becomes [`Config::big_radius`](crate::Config::big_radius). If the
    /// grown ball would overlap a wall or a brick there (the engine refuses the placement),
    /// the ball keeps its size: a ball never sits inside geometry.
    Bigger,
    /// The ball's radius becomes [`Config::small_radius`](crate::Config::small_radius)
    /// (shrinking never overlaps anything).
    Smaller,
    /// The ball's speed is multiplied by [`Config::boost_factor`](crate::Config::boost_factor),
    /// once per ball per round.
    Boost,
    /// The ball gets a shield (charges do not stack): the next hazard it enters takes the
    /// shield instead of the ball.
    Shield,
}

impl PickupKind {
    /// Every kind, in a fixed order (the spawn draws from this list).
    pub const ALL: [PickupKind; 12] = [
        PickupKind::ExtraBall,
        PickupKind::Split,
        PickupKind::Hazard,
        PickupKind::FloorBounce,
        PickupKind::LaserHorizontal,
        PickupKind::LaserVertical,
        PickupKind::LaserCross,
        PickupKind::RandomDirection,
        PickupKind::Bigger,
        PickupKind::Smaller,
        PickupKind::Boost,
        PickupKind::Shield,
    ];

    /// Whether its laser hits the pick-up's row.
    #[must_use]
    pub fn hits_row(self) -> bool {
        matches!(self, PickupKind::LaserHorizontal | PickupKind::LaserCross)
    }

    /// Whether its laser hits the pick-up's column.
    #[must_use]
    pub fn hits_column(self) -> bool {
        matches!(self, PickupKind::LaserVertical | PickupKind::LaserCross)
    }
}

/// A pick-up on the board.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct Pickup {
    /// What it does.
    pub kind: PickupKind,
    /// Whether a ball entered it this round (used pick-ups leave when the round ends).
    pub used: bool,
}

impl Pickup {
    /// An unused pick-up.
    #[must_use]
    pub fn new(kind: PickupKind) -> Self {
        Self { kind, used: false }
    }
}
