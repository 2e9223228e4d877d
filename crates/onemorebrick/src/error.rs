//! Why the game refused a call.

use std::fmt;

use exact2d::WorldError;

use crate::round::Phase;

/// An error from the game's API. The game is unchanged when one is returned, except for
/// [`GameError::Engine`], which means a rule broke an engine precondition (a bug).
#[derive(Clone, Debug, PartialEq)]
pub enum GameError {
    /// A configuration setting is out of range; names it.
    InvalidConfig(String),
    /// An aim is not finite, is zero, or is flatter than the minimum elevation; says which.
    InvalidAim(&'static str),
    /// The call needs another phase of the round.
    WrongPhase {
        /// The phase the call needs.
        needed: Phase,
        /// The phase the game is in.
        actual: Phase,
    },
    /// A time before the volley's clock (or NaN) was asked for.
    TimeBeforeNow {
        /// The time asked for.
        requested: f64,
        /// The volley's clock.
        now: f64,
    },
    /// A game state that breaks an invariant (from a file or a custom board); says which.
    InvalidState(String),
    /// The engine refused a call the rules made.
    Engine(WorldError),
}

impl fmt::Display for GameError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            GameError::InvalidConfig(what) => write!(f, "invalid configuration: {what}"),
            GameError::InvalidAim(what) => write!(f, "invalid aim: {what}"),
            GameError::WrongPhase { needed, actual } => {
                write!(
                    f,
                    "this needs the {needed:?} phase, the game is in {actual:?}"
                )
            }
            GameError::TimeBeforeNow { requested, now } => {
                write!(f, "time {requested} is before the volley's clock {now}")
            }
            GameError::InvalidState(what) => write!(f, "invalid game state: {what}"),
            GameError::Engine(e) => write!(f, "engine refused a rule's call: {e}"),
        }
    }
}

impl std::error::Error for GameError {}

impl From<WorldError> for GameError {
    fn from(e: WorldError) -> Self {
        GameError::Engine(e)
    }
}
