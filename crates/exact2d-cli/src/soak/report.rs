//! What `exact2d soak` prints at the end: one JSON object on one line.
//!
//! Field order is part of the format (`serde` writes fields in declaration order).

use serde::Serialize;

/// Why the run stopped.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Stop {
    /// The events asked for were handled.
    Events,
    /// No event was left to handle (every ball at rest, or flying off for ever).
    NoEventsLeft,
    /// An invariant broke.
    Invariant,
}

/// The result of a soak run.
#[derive(Debug, Serialize)]
pub struct SoakReport {
    /// Events handled: collisions plus sensor events, each one `World::step`.
    pub events: u64,
    /// Collisions among them (with colliders and between balls).
    pub collisions: u64,
    /// Sensor entries and exits among them.
    pub sensor_events: u64,
    /// The simulated time at the end.
    pub time: f64,
    /// Why the run stopped.
    pub stopped: Stop,
    /// Wall-clock seconds of the run (stepping and checks; reading the scene excluded).
    pub wall_s: f64,
    /// `events / wall_s`.
    pub events_per_s: f64,
    /// Events between two checks.
    pub check_every: u64,
    /// Checks made (including those at the start and at the end).
    pub checks: u64,
    /// Wall-clock seconds spent in the checks.
    pub check_wall_s: f64,
    /// The deepest overlap seen, relative to the contact distance (0 if nothing overlapped).
    pub worst_overlap: f64,
    /// The largest relative energy drift seen; `null` unless every body is elastic. Once a
    /// simultaneous impact has been resolved as a jam (which may absorb energy), only gains
    /// count.
    pub worst_energy_drift: Option<f64>,
    /// The most balls seen outside the colliders' box at once; `null` without `--closed`.
    pub balls_escaped: Option<u64>,
    /// Whether every check passed.
    pub invariants_ok: bool,
}
