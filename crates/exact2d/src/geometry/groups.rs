//! Collision filtering by group bit masks.

/// Which bodies interact: a body is in the groups `memberships`, and interacts only with
/// bodies that are in one of its `filter` groups. Two bodies interact if each one's
/// memberships meet the other's filter (the rule of Box2D's category and mask bits).
///
/// The default is every group in both masks: everything interacts. A brick breaker whose balls
/// pass through each other gives balls `CollisionGroups::new(BALLS, !BALLS)`; walls keep the
/// default and still collide with every ball.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct CollisionGroups {
    /// The groups this body belongs to.
    pub memberships: u32,
    /// The groups this body interacts with.
    pub filter: u32,
}

impl CollisionGroups {
    /// Every group, interacting with every group.
    pub const ALL: Self = Self {
        memberships: u32::MAX,
        filter: u32::MAX,
    };

    /// Groups from explicit masks.
    #[must_use]
    pub const fn new(memberships: u32, filter: u32) -> Self {
        Self {
            memberships,
            filter,
        }
    }

    /// Whether bodies with these two group settings interact.
    #[must_use]
    #[inline]
    pub const fn interact(self, other: Self) -> bool {
        (self.memberships & other.filter) != 0 && (other.memberships & self.filter) != 0
    }
}

impl Default for CollisionGroups {
    fn default() -> Self {
        Self::ALL
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn balls_that_filter_out_their_own_group_ignore_each_other_but_not_walls() {
        const BALLS: u32 = 1;
        let ball = CollisionGroups::new(BALLS, !BALLS);
        assert!(!ball.interact(ball));
        assert!(ball.interact(CollisionGroups::ALL));
    }
}
