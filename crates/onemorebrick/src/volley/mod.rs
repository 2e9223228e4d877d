//! A volley in play: launches, engine events turned into rules, deadlines, recall.
//!
//! The rules drive the engine with [`World::step_until`](exact2d::World::step_until) and act
//! only at engine events and at times the rules compute themselves (the next launch, the
//! earliest anti-stall deadline). Frames only move the clock between those, and the engine's
//! balls move in closed form, so playing a volley frame by frame or to its end in one call
//! gives the same bits (a test compares the two).

mod pickups;

use std::collections::BTreeSet;

use exact2d::{BallDesc, ContactEvent, DVec2, Event};

use crate::GameError;
use crate::aim::Aim;
use crate::anti_stall::{enforce_elevation, steer_down};
use crate::arena::{Arena, BALL_GROUPS, Role};
use crate::ball::{BallView, Flight};
use crate::board::Board;
use crate::cell::Cell;
use crate::config::Config;
use crate::rng::GameRng;

/// What happened during a volley, counted as it happened.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Tally {
    /// Bounces off bricks (one hit point each).
    pub hits: u64,
    /// Hit points taken by lasers.
    pub laser_damage: u64,
    /// Bricks that reached zero.
    pub bricks_destroyed: u32,
    /// +1 pick-ups taken.
    pub extra_balls: u32,
    /// Where the first ball collected at the floor line landed (its centre's x).
    pub first_back_x: Option<f64>,
    /// Balls (not clones) collected at the floor line.
    pub collected: u32,
    /// Clones made by split pick-ups.
    pub clones: u32,
    /// Anti-stall steers.
    pub steers: u32,
    /// Balls recalled by the anti-stall rule.
    pub stall_recalls: u32,
    /// Balls taken out by hazards.
    pub hazards: u32,
    /// Hazards a shield absorbed.
    pub shield_saves: u32,
    /// Random-direction turns (at most one per ball).
    pub redirects: u32,
    /// Size changes the engine refused (the grown ball would have overlapped geometry).
    pub refused_resizes: u32,
    /// The simulated time when the last ball left play.
    pub end_time: f64,
}

impl Tally {
    /// All damage dealt: hits plus laser damage.
    #[must_use]
    pub fn damage(&self) -> u64 {
        self.hits + self.laser_damage
    }
}

/// What one [`Game::step`](crate::Game::step) did.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Step {
    /// Handled an engine event.
    Event,
    /// Launched a ball or applied an anti-stall deadline.
    Action,
    /// Reached the requested time with nothing left to do before it.
    Reached,
    /// The volley is over: every ball has left play.
    Over,
}

/// A volley in play.
pub(crate) struct Volley {
    config: Config,
    arena: Arena,
    board: Board,
    rng: GameRng,
    flights: Vec<Flight>,
    /// Anti-stall deadlines as (time bits, ball id): times are non-negative, so their bit
    /// patterns sort as the times do, and the id breaks ties.
    deadlines: BTreeSet<(u64, u32)>,
    launch_position: DVec2,
    launch_velocity: DVec2,
    total: u32,
    fired: u32,
    in_flight: u32,
    tally: Tally,
}

impl Volley {
    /// A volley of `balls` balls aimed along `aim` from `launch_x`, on a world built from
    /// `board`. Nothing is launched before the first [`step`](Self::step).
    pub fn start(
        config: &Config,
        board: Board,
        rng: GameRng,
        launch_x: f64,
        aim: Aim,
        balls: u32,
    ) -> Result<Self, GameError> {
        aim.validate(config.min_elevation_tan)?;
        let arena = Arena::build(config, &board)?;
        Ok(Self {
            config: config.clone(),
            arena,
            board,
            rng,
            flights: Vec::new(),
            deadlines: BTreeSet::new(),
            launch_position: DVec2::new(launch_x, config.ball_radius),
            launch_velocity: aim.velocity(config.ball_speed),
            total: balls,
            fired: 0,
            in_flight: 0,
            tally: Tally::default(),
        })
    }

    /// The volley's clock (0 at the first launch).
    pub fn time(&self) -> f64 {
        self.arena.world.time()
    }

    /// Whether every ball has left play.
    pub fn is_over(&self) -> bool {
        self.fired == self.total && self.in_flight == 0
    }

    /// The board as it is now (bricks lose hit points during the volley).
    pub fn board(&self) -> &Board {
        &self.board
    }

    /// Counts so far.
    pub fn tally(&self) -> &Tally {
        &self.tally
    }

    /// Collisions the engine handled.
    pub fn collisions(&self) -> u64 {
        self.arena.world.event_counts().collisions()
    }

    /// Balls not launched yet.
    pub fn waiting(&self) -> u32 {
        self.total - self.fired
    }

    /// The board, the generator and the counts, once the volley is over.
    pub fn finish(self) -> (Board, GameRng, Tally) {
        (self.board, self.rng, self.tally)
    }

    /// Every ball in play, in id order.
    pub fn balls(&self) -> Vec<BallView> {
        let world = &self.arena.world;
        let view = |(id, f): (usize, &Flight)| {
            let ball = world.ball(f.handle?)?;
            Some(BallView {
                id: id as u32,
                position: ball.position,
                velocity: ball.velocity,
                radius: ball.radius,
                clone: f.clone,
                floor_bounce: f.floor_bounce,
                shield: f.shield,
            })
        };
        self.flights.iter().enumerate().filter_map(view).collect()
    }

    /// The time of the next launch or deadline, whichever is first (infinite if none).
    fn next_action(&self) -> f64 {
        let launch = if self.fired < self.total {
            f64::from(self.fired) * self.config.launch_interval()
        } else {
            f64::INFINITY
        };
        let deadline = self
            .deadlines
            .first()
            .map_or(f64::INFINITY, |&(bits, _)| f64::from_bits(bits));
        launch.min(deadline)
    }

    /// Does the next thing that happens at or before `limit`: an engine event, a launch or a
    /// deadline; or moves the clock to `limit` if nothing does.
    pub fn step(&mut self, limit: f64) -> Result<Step, GameError> {
        if self.is_over() {
            return Ok(Step::Over);
        }
        let now = self.time();
        if !(limit >= now) {
            return Err(GameError::TimeBeforeNow {
                requested: limit,
                now,
            });
        }
        let next = self.next_action();
        let target = limit.min(next);
        match self.arena.world.step_until(target)? {
            Some(event) => {
                self.handle(event)?;
                Ok(Step::Event)
            }
            None if target == next && next.is_finite() => {
                self.act(next)?;
                Ok(Step::Action)
            }
            None => Ok(Step::Reached),
        }
    }

    /// Every ball returns at once, the ones not launched yet too; the volley is over.
    pub fn recall(&mut self) -> Result<(), GameError> {
        self.fired = self.total;
        for id in 0..self.flights.len() as u32 {
            self.take_out(id)?;
        }
        self.tally.end_time = self.time();
        Ok(())
    }

    /// A launch or a deadline due at `time` (launches first).
    fn act(&mut self, time: f64) -> Result<(), GameError> {
        if self.fired < self.total && f64::from(self.fired) * self.config.launch_interval() == time
        {
            return self.launch(time);
        }
        match self.deadlines.pop_first() {
            Some((_, id)) => self.on_deadline(id, time),
            None => Ok(()),
        }
    }

    /// Anti-stall rule 2 (see [`crate::anti_stall`]): steer down, or recall after the steers.
    fn on_deadline(&mut self, id: u32, time: f64) -> Result<(), GameError> {
        let flight = self.flights[id as usize];
        let Some(handle) = flight.handle else {
            return Ok(());
        };
        if flight.steers >= self.config.stall_steers {
            self.tally.stall_recalls += 1;
            return self.take_out(id);
        }
        let velocity = self
            .arena
            .world
            .ball(handle)
            .map_or(DVec2::ZERO, |b| b.velocity);
        let steered = steer_down(velocity, flight.speed);
        self.arena.world.set_ball_velocity(handle, steered)?;
        self.flights[id as usize].steers += 1;
        self.tally.steers += 1;
        self.set_deadline(id, time + self.config.stall_seconds);
        Ok(())
    }

    fn launch(&mut self, time: f64) -> Result<(), GameError> {
        let id = self.flights.len() as u32;
        let desc = BallDesc::new(self.launch_position, self.config.ball_radius)
            .velocity(self.launch_velocity)
            .groups(BALL_GROUPS)
            .user_data(u64::from(id));
        let handle = self.arena.world.add_ball(desc)?;
        let deadline = time + self.config.stall_seconds;
        let speed = self.config.ball_speed;
        self.flights.push(Flight::new(
            handle,
            speed,
            self.config.ball_radius,
            deadline,
        ));
        self.deadlines.insert((deadline.to_bits(), id));
        self.fired += 1;
        self.in_flight += 1;
        Ok(())
    }

    /// Removes a ball from play, whatever the reason; no-op if it already left.
    fn take_out(&mut self, id: u32) -> Result<(), GameError> {
        let flight = &mut self.flights[id as usize];
        let Some(handle) = flight.handle.take() else {
            return Ok(());
        };
        self.deadlines.remove(&(flight.deadline.to_bits(), id));
        self.arena.world.remove_ball(handle)?;
        self.in_flight -= 1;
        if self.is_over() {
            self.tally.end_time = self.time();
        }
        Ok(())
    }

    fn set_deadline(&mut self, id: u32, deadline: f64) {
        let flight = &mut self.flights[id as usize];
        self.deadlines.remove(&(flight.deadline.to_bits(), id));
        flight.deadline = deadline;
        self.deadlines.insert((deadline.to_bits(), id));
    }

    fn handle(&mut self, event: Event) -> Result<(), GameError> {
        let role = self.arena.role(&event);
        match (event, role) {
            (Event::Contact(contact), Some(role)) => self.on_contact(&contact, role),
            (Event::SensorEnter(sensor), Some(Role::Pickup(cell))) => self.on_pickup(&sensor, cell),
            // Exits change nothing; ball-ball contacts cannot happen (collision groups).
            _ => Ok(()),
        }
    }

    fn on_contact(&mut self, contact: &ContactEvent, role: Role) -> Result<(), GameError> {
        let id = self
            .arena
            .ball_id(contact.ball)
            .expect("the event's ball is live");
        match role {
            Role::Floor if !self.flights[id as usize].floor_bounce => {
                return self.collect(id, contact);
            }
            Role::Floor => {
                let flight = &mut self.flights[id as usize];
                flight.floor_bounce = false;
                flight.floor_bounced = true;
            }
            Role::Brick(cell) => {
                self.tally.hits += 1;
                self.damage(cell)?;
                self.set_deadline(id, contact.time + self.config.stall_seconds);
            }
            Role::Wall | Role::Obstacle(_) | Role::Pickup(_) => {}
        }
        self.keep_elevation(id, contact.normal)
    }

    fn collect(&mut self, id: u32, contact: &ContactEvent) -> Result<(), GameError> {
        let flight = self.flights[id as usize];
        if !flight.clone {
            self.tally.collected += 1;
            if self.tally.first_back_x.is_none() {
                let x = contact.point.x;
                let r = self.config.ball_radius;
                self.tally.first_back_x = Some(x.clamp(r, self.config.width() - r));
            }
        }
        self.take_out(id)
    }

    /// Anti-stall rule 1 after a bounce off a surface with this normal.
    fn keep_elevation(&mut self, id: u32, normal: DVec2) -> Result<(), GameError> {
        let flight = self.flights[id as usize];
        let Some(handle) = flight.handle else {
            return Ok(());
        };
        let velocity = self
            .arena
            .world
            .ball(handle)
            .map_or(DVec2::ZERO, |b| b.velocity);
        let t = self.config.min_elevation_tan;
        if let Some(v) = enforce_elevation(velocity, normal, flight.speed, t) {
            self.arena.world.set_ball_velocity(handle, v)?;
        }
        Ok(())
    }

    /// One hit point off the brick in `cell`; at zero its colliders leave the world.
    fn damage(&mut self, cell: usize) -> Result<(), GameError> {
        let Cell::Brick(brick) = self.board.cell_mut(cell) else {
            return Ok(());
        };
        brick.hp -= 1;
        if brick.hp == 0 {
            *self.board.cell_mut(cell) = Cell::Empty;
            self.arena.clear_cell(cell)?;
            self.tally.bricks_destroyed += 1;
        }
        Ok(())
    }
}
