//! The invariants a world must keep after every event, with the tolerances the engine states.
//!
//! - **Time** never goes back, and **moves on**: the events at one instant (internal ones
//!   included, as [`World::instant_events`] counts them) stay within [`EVENTS_PER_BALL`] per
//!   ball that had one, plus [`EVENTS_PER_BALL`]: at one instant each contact responds in
//!   sequence at most twice before its jam is resolved (ARCHITECTURE.md, zero-time chains).
//! - **No overlap** deeper than [`exact2d::overlap_bound`] between bodies that interact.
//! - **Containment**: no ball's centre leaves the closed box (by more than that bound); in a
//!   periodic box, the box itself, and pairs are measured through their nearest images.
//! - **Energy** (kinetic plus potential, measured from the box's lower corner so that an
//!   offset of 1e9 does not swamp it) never grows by more than the engine's floors allow: the
//!   micro-hop of each collision of two balls ([`exact2d::micro_hop`], times their mass and
//!   gravity), and rounding: 1e-9 of the energy's scale, and 16 units in the last place of
//!   each ball's coordinates, times its weight.

use std::fmt;

use exact2d::{DVec2, Event, Shape, World, micro_hop, overlap_bound};

/// Events at one instant allowed per ball that had one (and once more): 64.
///
/// Measured on the hunt's scenes: at most 14 events per ball at one instant (a ball pressed
/// into the corner of three segments meeting at a point). The bound is four times more.
pub const EVENTS_PER_BALL: u64 = 64;

/// A broken invariant.
#[derive(Clone, Debug, PartialEq)]
pub struct Finding {
    /// Which invariant.
    pub class: Class,
    /// The bodies, the time and the values.
    pub detail: String,
}

/// The invariants (and the two ways a run can fail to finish).
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Class {
    /// Time went back.
    TimeBack,
    /// Too many events at one instant, or the engine's own stall error.
    Stall,
    /// Two bodies overlap deeper than [`exact2d::overlap_bound`].
    Overlap,
    /// A ball left the closed box.
    Escape,
    /// The energy grew beyond the floors.
    Energy,
    /// The clock advanced less than 1e-9 of a second over 100,000 events, internal ones
    /// included, or 100,000 internal events came in a row (see `run::run_world`).
    Crawl,
}

impl Class {
    /// A short name.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Class::TimeBack => "time_back",
            Class::Stall => "stall",
            Class::Overlap => "overlap",
            Class::Escape => "escape",
            Class::Energy => "energy",
            Class::Crawl => "crawl",
        }
    }
}

impl fmt::Display for Finding {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}: {}", self.class.name(), self.detail)
    }
}

/// The state the checks carry from event to event.
pub struct Checker {
    bounds: (DVec2, DVec2),
    gravity: DVec2,
    last: exact2d::Time,
    /// The energy at the start and its scale.
    energy0: f64,
    scale: f64,
    /// What the micro-hops may have added so far.
    hops: f64,
    /// The most events at one instant per ball seen (events, balls).
    pub busiest: (u64, usize),
}

impl Checker {
    /// Checks for `world` (at the start of its run) in the closed box `bounds`.
    #[must_use]
    pub fn new(world: &World, bounds: (DVec2, DVec2)) -> Self {
        let gravity = world.gravity();
        let mass: f64 = world.balls().map(|(_, b)| b.mass).sum();
        let size = (bounds.1 - bounds.0).max_element();
        let energy0 = energy(world, bounds.0);
        Self {
            bounds,
            gravity,
            last: world.exact_time(),
            energy0,
            scale: energy0
                .abs()
                .max(mass * gravity.length() * size)
                .max(f64::MIN_POSITIVE),
            hops: 0.0,
            busiest: (0, 0),
        }
    }

    /// Checks every invariant after `event`.
    ///
    /// # Errors
    /// The first broken one.
    pub fn after(&mut self, world: &World, event: &Event) -> Result<(), Finding> {
        self.time(world)?;
        if let Event::BallContact(contact) = event {
            let (a, b) = (world.ball(contact.a), world.ball(contact.b));
            if let (Some(a), Some(b)) = (a, b) {
                let coordinates = a
                    .position
                    .abs()
                    .max_element()
                    .max(b.position.abs().max_element());
                let hop = micro_hop(coordinates, a.radius + b.radius);
                self.hops += (a.mass + b.mass) * self.gravity.length() * hop;
            }
        }
        overlap(world)?;
        self.containment(world)?;
        self.energy(world)
    }

    fn time(&mut self, world: &World) -> Result<(), Finding> {
        let now = world.exact_time();
        if now < self.last {
            return Err(Finding {
                class: Class::TimeBack,
                detail: format!("from {:?} to {now:?}", self.last),
            });
        }
        self.last = now;
        let (events, balls) = world.instant_events();
        if events * (self.busiest.1 as u64 + 1) > self.busiest.0 * (balls as u64 + 1) {
            self.busiest = (events, balls);
        }
        if events > EVENTS_PER_BALL * (balls as u64 + 1) {
            return Err(Finding {
                class: Class::Stall,
                detail: format!(
                    "{events} events at t = {:?} among {balls} balls",
                    now.seconds()
                ),
            });
        }
        Ok(())
    }

    fn containment(&self, world: &World) -> Result<(), Finding> {
        let (lo, hi) = self.bounds;
        for (h, b) in world.balls() {
            let slack = overlap_bound(b.position.abs().max_element(), b.radius);
            let out = (lo - b.position).max(b.position - hi).max_element();
            if out > slack {
                return Err(Finding {
                    class: Class::Escape,
                    detail: format!("ball {} at {:?}, {out:e} outside", h.index(), b.position),
                });
            }
        }
        Ok(())
    }

    fn energy(&self, world: &World) -> Result<(), Finding> {
        let e = energy(world, self.bounds.0);
        let rounding: f64 = world
            .balls()
            .map(|(_, b)| {
                let coordinates = b.position.abs().max_element() + b.radius;
                b.mass * self.gravity.length() * 16.0 * f64::EPSILON * coordinates
            })
            .sum();
        let allowed = self.energy0 + 1e-9 * self.scale + self.hops + rounding;
        if e > allowed {
            return Err(Finding {
                class: Class::Energy,
                detail: format!(
                    "{e:e} from {:e} (+{:e} of its scale) at t = {:?}",
                    self.energy0,
                    (e - self.energy0) / self.scale,
                    world.time()
                ),
            });
        }
        Ok(())
    }
}

/// Kinetic plus potential energy, the potential measured from `origin`.
#[must_use]
pub fn energy(world: &World, origin: DVec2) -> f64 {
    let g = world.gravity();
    world
        .balls()
        .map(|(_, b)| b.kinetic_energy() - b.mass * g.dot(b.position - origin))
        .sum()
}

/// The deepest overlap between interacting bodies beyond [`overlap_bound`], if any.
///
/// # Errors
/// The overlap, naming the bodies.
pub fn overlap(world: &World) -> Result<(), Finding> {
    let balls: Vec<_> = world.balls().collect();
    // In a periodic box, a pair's nearest images.
    let periodic = world.periodic_box();
    let apart = |p: DVec2, q: DVec2| {
        let d = q - p;
        match periodic {
            None => d.length(),
            Some(size) => (d - (d / size).round() * size).length(),
        }
    };
    for (i, (ha, a)) in balls.iter().enumerate() {
        let ca = a.position.abs().max_element();
        for (hb, b) in &balls[..i] {
            if !a.groups.interact(b.groups) {
                continue;
            }
            let reach = a.radius + b.radius;
            let depth = reach - apart(a.position, b.position);
            let coordinates = ca.max(b.position.abs().max_element());
            if depth > overlap_bound(coordinates, reach) {
                return Err(overlap_finding(
                    format!("balls {} and {}", hb.index(), ha.index()),
                    depth,
                    reach,
                    world,
                ));
            }
        }
        for (hc, c) in world.colliders() {
            if c.sensor || !c.groups.interact(a.groups) {
                continue;
            }
            let (depth, reach) = match c.shape {
                Shape::Segment(s) => (a.radius - s.distance(a.position), a.radius),
                Shape::Circle(k) => {
                    let reach = k.radius + a.radius;
                    (reach - a.position.distance(k.center), reach)
                }
            };
            if depth > overlap_bound(ca, reach) {
                let who = format!("ball {} and collider {}", ha.index(), hc.index());
                return Err(overlap_finding(who, depth, reach, world));
            }
        }
    }
    Ok(())
}

fn overlap_finding(who: String, depth: f64, reach: f64, world: &World) -> Finding {
    Finding {
        class: Class::Overlap,
        detail: format!(
            "{who} overlap {:e} of their contact distance at t = {:?}",
            depth / reach,
            world.time()
        ),
    }
}
