//! Replays: a seed, a configuration and the list of commands reproduce a game bit for bit.
//!
//! Shots keep their direction vectors exactly (see [`Aim`]); recalls and finishes keep the
//! volley clock they happened at. Frames are not recorded: they do not change any result.

use serde::{Deserialize, Serialize};

use crate::GameError;
use crate::aim::Aim;
use crate::config::Config;
use crate::game::Game;
use crate::round::Phase;

/// A player's command.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub enum Command {
    /// Fire a volley along this aim.
    Shoot(Aim),
    /// Recall every ball at this volley clock.
    Recall {
        /// The volley clock when the player recalled.
        at: f64,
    },
    /// Finish the round now (pressed at this volley clock; the outcome does not depend on it).
    Finish {
        /// The volley clock when the player pressed it.
        at: f64,
    },
    /// Restart after a game over.
    Restart,
}

/// Everything needed to play a game again.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Replay {
    /// The game's seed.
    pub seed: u64,
    /// Its settings.
    pub config: Config,
    /// Its commands, in order.
    pub commands: Vec<Command>,
}

impl Replay {
    /// The replay of a game so far.
    #[must_use]
    pub fn of(game: &Game) -> Self {
        Self {
            seed: game.seed(),
            config: game.state().config().clone(),
            commands: game.history().to_vec(),
        }
    }

    /// Plays the commands from a new game. A volley still live when a shot or a restart
    /// comes next was played out to its natural end in the original, so it is finished here;
    /// so is a volley still live after the last command: a replay describes whole rounds (a
    /// game stopped mid-volley is resumed from a save file instead, see [`crate::save`]).
    ///
    /// # Errors
    /// The first command the game refuses (a replay that does not fit this game).
    pub fn play(&self) -> Result<Game, GameError> {
        let mut game = Game::new(self.config.clone(), self.seed)?;
        for command in &self.commands {
            match *command {
                Command::Shoot(aim) => {
                    end_volley(&mut game)?;
                    game.shoot(aim)?;
                }
                Command::Recall { at } => {
                    game.advance_to(at)?;
                    game.recall()?;
                }
                Command::Finish { at } => {
                    game.advance_to(at)?;
                    game.finish_round()?;
                }
                Command::Restart => {
                    end_volley(&mut game)?;
                    game.restart()?;
                }
            }
        }
        end_volley(&mut game)?;
        Ok(game)
    }
}

/// Plays a live volley to its end without recording a command.
fn end_volley(game: &mut Game) -> Result<(), GameError> {
    if game.phase() == Phase::Volley {
        game.advance_to(f64::INFINITY)?;
    }
    Ok(())
}
