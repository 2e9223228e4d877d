//! What each pick-up does to the ball that enters it (the rules are stated on
//! [`PickupKind`]).

use exact2d::{BallDesc, BallHandle, DVec2, SensorEvent, WorldError};

use super::Volley;
use crate::GameError;
use crate::arena::BALL_GROUPS;
use crate::ball::Flight;
use crate::cell::Cell;
use crate::pickup::PickupKind;

impl Volley {
    pub(super) fn on_pickup(&mut self, sensor: &SensorEvent, cell: usize) -> Result<(), GameError> {
        let Cell::Pickup(pickup) = self.board.cell_mut(cell) else {
            return Ok(());
        };
        let kind = pickup.kind;
        pickup.used = true;
        let id = self
            .arena
            .ball_id(sensor.ball)
            .expect("the event's ball is live");
        let handle = sensor.ball;
        match kind {
            PickupKind::ExtraBall => {
                self.tally.extra_balls += 1;
                *self.board.cell_mut(cell) = Cell::Empty;
                self.arena.clear_cell(cell)?;
            }
            PickupKind::Split => self.split(id, handle)?,
            PickupKind::Hazard => self.hazard(id)?,
            PickupKind::FloorBounce => {
                let flight = &mut self.flights[id as usize];
                flight.floor_bounce = !flight.floor_bounced;
            }
            PickupKind::Shield => self.flights[id as usize].shield = true,
            PickupKind::LaserHorizontal | PickupKind::LaserVertical | PickupKind::LaserCross => {
                self.laser(id, cell, kind, sensor.time)?;
            }
            PickupKind::RandomDirection => self.random_direction(id, handle)?,
            PickupKind::Bigger => self.resize(id, handle, self.config.big_radius)?,
            PickupKind::Smaller => self.resize(id, handle, self.config.small_radius)?,
            PickupKind::Boost => self.boost(id, handle)?,
        }
        Ok(())
    }

    fn split(&mut self, id: u32, handle: BallHandle) -> Result<(), GameError> {
        let parent = self.flights[id as usize];
        if parent.clone || parent.split {
            return Ok(());
        }
        self.flights[id as usize].split = true;
        let ball = self
            .arena
            .world
            .ball(handle)
            .ok_or(WorldError::NoSuchBall(handle))?;
        let clone_id = self.flights.len() as u32;
        let desc = BallDesc::new(ball.position, ball.radius)
            .velocity(DVec2::new(-ball.velocity.x, ball.velocity.y))
            .groups(BALL_GROUPS)
            .user_data(u64::from(clone_id));
        // Same place and size as a ball that is in play, and balls ignore each other: the
        // engine accepts it.
        let clone_handle = self.arena.world.add_ball(desc)?;
        let deadline = self.time() + self.config.stall_seconds;
        let mut flight = Flight::new(clone_handle, parent.speed, parent.radius, deadline);
        flight.clone = true;
        flight.boosted = parent.boosted;
        self.flights.push(flight);
        self.deadlines.insert((deadline.to_bits(), clone_id));
        self.in_flight += 1;
        self.tally.clones += 1;
        Ok(())
    }

    fn hazard(&mut self, id: u32) -> Result<(), GameError> {
        let flight = &mut self.flights[id as usize];
        if flight.shield {
            flight.shield = false;
            self.tally.shield_saves += 1;
            return Ok(());
        }
        self.tally.hazards += 1;
        self.take_out(id)
    }

    /// One damage to every brick in the pick-up's row and/or column, in cell order.
    fn laser(
        &mut self,
        id: u32,
        cell: usize,
        kind: PickupKind,
        time: f64,
    ) -> Result<(), GameError> {
        let (column, row) = self.board.position(cell);
        let targets: Vec<usize> = self
            .board
            .bricks()
            .map(|(i, _)| i)
            .filter(|&i| {
                let (c, r) = self.board.position(i);
                (kind.hits_row() && r == row) || (kind.hits_column() && c == column)
            })
            .collect();
        for &target in &targets {
            self.tally.laser_damage += 1;
            self.damage(target)?;
        }
        if !targets.is_empty() {
            self.set_deadline(id, time + self.config.stall_seconds);
        }
        Ok(())
    }

    fn random_direction(&mut self, id: u32, handle: BallHandle) -> Result<(), GameError> {
        if self.flights[id as usize].redirected {
            return Ok(());
        }
        self.flights[id as usize].redirected = true;
        self.tally.redirects += 1;
        // (a, 1) with |a| <= 1/t is no flatter than the minimum elevation.
        let a = (2.0 * self.rng.unit() - 1.0) / self.config.min_elevation_tan;
        let speed = self.flights[id as usize].speed;
        let v = DVec2::new(a, 1.0) * (speed / (a * a + 1.0).sqrt());
        self.arena.world.set_ball_velocity(handle, v)?;
        Ok(())
    }

    fn boost(&mut self, id: u32, handle: BallHandle) -> Result<(), GameError> {
        let flight = &mut self.flights[id as usize];
        if flight.boosted {
            return Ok(());
        }
        flight.boosted = true;
        flight.speed *= self.config.boost_factor;
        let ball = self
            .arena
            .world
            .ball(handle)
            .ok_or(WorldError::NoSuchBall(handle))?;
        let v = ball.velocity * self.config.boost_factor;
        self.arena.world.set_ball_velocity(handle, v)?;
        Ok(())
    }

    /// A new ball of `radius` replaces this one at the same place and velocity. The new one is
    /// added first: if the engine refuses it (it would overlap geometry), nothing changes.
    fn resize(&mut self, id: u32, handle: BallHandle, radius: f64) -> Result<(), GameError> {
        let ball = self
            .arena
            .world
            .ball(handle)
            .ok_or(WorldError::NoSuchBall(handle))?;
        if ball.radius == radius {
            return Ok(());
        }
        let desc = BallDesc::new(ball.position, radius)
            .velocity(ball.velocity)
            .groups(BALL_GROUPS)
            .user_data(u64::from(id));
        match self.arena.world.add_ball(desc) {
            Ok(new_handle) => {
                self.arena.world.remove_ball(handle)?;
                let flight = &mut self.flights[id as usize];
                flight.handle = Some(new_handle);
                flight.radius = radius;
                Ok(())
            }
            Err(WorldError::OverlapsCollider(_)) => {
                self.tally.refused_resizes += 1;
                Ok(())
            }
            Err(e) => Err(e.into()),
        }
    }
}
