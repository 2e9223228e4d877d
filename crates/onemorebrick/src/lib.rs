//! # One More Brick: the rules
//!
//! A brick breaker in the style of One More Brick and Ballz: aim from the launcher at the
//! bottom, and a volley of balls flies out one after another; they bounce off the walls,
//! bricks and round obstacles (not off each other), pass through pick-ups, and each bounce
//! off a brick takes one hit point. When every ball is back at the floor line, the rows move
//! down one step, a new row enters at the top, and the game is over when a brick reaches the
//! bottom row.
//!
//! This crate is the whole game without a window or a clock: every ball moves in the exact2d
//! engine, whose events (a bounce, a sensor entered) come back to the rules one at a time
//! so the rules react (take a hit point, remove a brick, split a ball) before the world goes
//! on. Data flows one way: command -> rules -> engine -> events -> rules. Everything is
//! deterministic: no wall clock, no hash map iteration, a seeded generator saved with the
//! game. A game played frame by frame, finished at once, saved and loaded mid-volley, or
//! replayed from its seed and commands gives the same bits.
//!
//! ```
//! use onemorebrick::{Bot, Config, Game, GreedyBot, Phase};
//!
//! let mut game = Game::new(Config::default(), 42)?;
//! let mut bot = GreedyBot::new(8);
//! for _ in 0..3 {
//!     let aim = bot.choose(&game)?;
//!     game.shoot(aim)?;
//!     while game.advance_to(game.volley_time().unwrap() + 1.0 / 60.0)?.is_none() {}
//! }
//! assert_eq!(game.state().level(), 4);
//! assert_eq!(game.phase(), Phase::Aiming);
//! # Ok::<(), onemorebrick::GameError>(())
//! ```
//!
//! ## The rules in short (`RULES.md` has them all)
//!
//! - **Board**: [`Config::columns`] x [`Config::rows`] cells (7 x 9), unit cells, row 0 at
//!   the bottom is the launcher's. Cells ([`Cell`]): empty, square brick (4 segments),
//!   triangular brick (3 segments, one open [`Corner`]), round obstacle (indestructible),
//!   pick-up ([`PickupKind`]: each kind documents its rule).
//! - **Round** ([`round`]): aim ([`Aim`], rejected below the minimum elevation; preview
//!   with [`Game::aim_preview`]), volley, resolution; spawn and difficulty curve in
//!   [`spawn`].
//! - **Never stuck** ([`anti_stall`]): minimum elevation after bounces, damage deadlines, and
//!   a proven bound on a round's simulated time; plus [`Game::recall`] and
//!   [`Game::finish_round`].
//! - **State** ([`save`]): versioned JSON, atomic writes; **replays** ([`Replay`]) and a
//!   stable hash ([`hash_game`]); **bots** ([`RandomBot`], [`GreedyBot`]).

pub mod aim;
pub mod anti_stall;
mod arena;
mod ball;
pub mod board;
pub mod bot;
pub mod cell;
pub mod config;
mod error;
pub mod game;
pub mod hash;
pub mod pickup;
pub mod replay;
pub mod rng;
pub mod round;
pub mod save;
pub mod spawn;
pub mod state;
mod volley;

pub use aim::Aim;
pub use arena::{BALL_GROUPS, BALLS};
pub use ball::BallView;
pub use board::{Board, ShiftOutcome};
pub use bot::{Bot, GreedyBot, RandomBot};
pub use cell::{Brick, Cell, Corner, Shape};
pub use config::Config;
pub use error::GameError;
pub use exact2d::DVec2;
pub use game::Game;
pub use hash::{Fnv1a, hash_game};
pub use pickup::{Pickup, PickupKind};
pub use replay::{Command, Replay};
pub use rng::GameRng;
pub use round::{Phase, RoundReport};
pub use save::{SaveError, load_game, save_game, set_aside};
pub use state::{Checkpoint, GameState, Totals};
pub use volley::{Step, Tally};
