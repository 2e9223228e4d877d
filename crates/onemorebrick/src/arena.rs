//! The physical world of one round: walls, floor, and the board's cells as exact2d colliders.
//!
//! Each collider's `user_data` says what it is ([`Role`]), so an engine event maps straight
//! back to a rule. The world is built afresh at the start of every volley: rows only move
//! between rounds, when no ball is in flight.

use exact2d::{
    BallHandle, ColliderDesc, ColliderHandle, CollisionGroups, DVec2, Event, World, WorldError,
};

use crate::board::Board;
use crate::cell::{Cell, outline};
use crate::config::Config;

/// The collision group of balls. Balls filter out their own group: they never meet each
/// other, only walls, bricks, obstacles and pick-ups (which keep the default groups).
pub const BALLS: u32 = 1;

/// Collision groups of every ball.
pub const BALL_GROUPS: CollisionGroups = CollisionGroups::new(BALLS, !BALLS);

/// What a collider stands for.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Role {
    /// The left, right or top wall.
    Wall,
    /// The floor line, where balls are collected.
    Floor,
    /// One segment of the brick in this cell.
    Brick(usize),
    /// The obstacle in this cell.
    Obstacle(usize),
    /// The pick-up sensor in this cell.
    Pickup(usize),
}

impl Role {
    fn encode(self) -> u64 {
        let (tag, cell) = match self {
            Role::Wall => (0, 0),
            Role::Floor => (1, 0),
            Role::Brick(c) => (2, c),
            Role::Obstacle(c) => (3, c),
            Role::Pickup(c) => (4, c),
        };
        (tag << 32) | cell as u64
    }

    fn decode(data: u64) -> Role {
        let cell = (data & 0xffff_ffff) as usize;
        match data >> 32 {
            0 => Role::Wall,
            1 => Role::Floor,
            2 => Role::Brick(cell),
            3 => Role::Obstacle(cell),
            _ => Role::Pickup(cell),
        }
    }
}

/// A world for one round, and each cell's colliders (to remove a brick or a pick-up).
pub(crate) struct Arena {
    pub world: World,
    pub cell_colliders: Vec<Vec<ColliderHandle>>,
}

impl Arena {
    /// The walls, the floor and every cell of `board`.
    pub fn build(config: &Config, board: &Board) -> Result<Self, WorldError> {
        let mut world = World::new();
        let (w, h) = (config.width(), config.height());
        let corners = [
            DVec2::ZERO,
            DVec2::new(w, 0.0),
            DVec2::new(w, h),
            DVec2::new(0.0, h),
        ];
        world.add_collider(segment(corners[0], corners[1], Role::Floor))?;
        for i in 1..4 {
            world.add_collider(segment(corners[i], corners[(i + 1) % 4], Role::Wall))?;
        }
        let mut cell_colliders = vec![Vec::new(); board.cells().len()];
        for (index, cell) in board.cells().iter().enumerate() {
            cell_colliders[index] = add_cell(&mut world, config, board, index, cell)?;
        }
        Ok(Self {
            world,
            cell_colliders,
        })
    }

    /// The role of an event's collider (`None` for ball-ball events, which the groups rule out).
    pub fn role(&self, event: &Event) -> Option<Role> {
        let handle = match event {
            Event::Contact(c) => c.collider,
            Event::SensorEnter(s) | Event::SensorExit(s) => s.collider,
            Event::BallContact(_) => return None,
        };
        self.world
            .collider(handle)
            .map(|c| Role::decode(c.user_data))
    }

    /// Removes every collider of a cell (a destroyed brick, a taken pick-up).
    pub fn clear_cell(&mut self, index: usize) -> Result<(), WorldError> {
        for handle in std::mem::take(&mut self.cell_colliders[index]) {
            self.world.remove_collider(handle)?;
        }
        Ok(())
    }

    /// The game's id of a ball (its `user_data`).
    pub fn ball_id(&self, handle: BallHandle) -> Option<u32> {
        self.world.ball(handle).map(|b| b.user_data as u32)
    }
}

fn segment(a: DVec2, b: DVec2, role: Role) -> ColliderDesc {
    ColliderDesc::segment(a, b).user_data(role.encode())
}

fn add_cell(
    world: &mut World,
    config: &Config,
    board: &Board,
    index: usize,
    cell: &Cell,
) -> Result<Vec<ColliderHandle>, WorldError> {
    let origin = board.origin(index);
    let centre = origin + DVec2::splat(0.5);
    match cell {
        Cell::Empty => Ok(Vec::new()),
        Cell::Brick(brick) => {
            let points = outline(brick.shape, origin);
            let n = points.len();
            (0..n)
                .map(|i| {
                    let desc = segment(points[i], points[(i + 1) % n], Role::Brick(index));
                    world.add_collider(desc)
                })
                .collect()
        }
        Cell::Obstacle => {
            let desc = ColliderDesc::circle(centre, config.obstacle_radius)
                .user_data(Role::Obstacle(index).encode());
            Ok(vec![world.add_collider(desc)?])
        }
        Cell::Pickup(_) => {
            let desc = ColliderDesc::circle(centre, config.pickup_radius)
                .sensor(true)
                .user_data(Role::Pickup(index).encode());
            Ok(vec![world.add_collider(desc)?])
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn roles_survive_encoding() {
        for role in [
            Role::Wall,
            Role::Floor,
            Role::Brick(62),
            Role::Obstacle(0),
            Role::Pickup(7),
        ] {
            assert_eq!(Role::decode(role.encode()), role);
        }
    }
}
