//! What a watched game does next: a bot's moves, or a saved game's commands turned into
//! moves the window plays out frame by frame. The same moves applied at once to a game
//! (`apply_at_once`) check, before a window opens, that a save's commands reproduce it.

use onemorebrick::{Aim, Bot, Command, Game, GameError, Phase, hash_game};

/// One step of a watched game.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Move {
    /// Show this aim a moment, then shoot along it.
    Shoot(Aim),
    /// Play the volley until its clock reaches this time (or it ends first).
    PlayTo(f64),
    /// Play the volley to its end (nothing if no volley is live).
    PlayOut,
    /// Recall every ball now.
    Recall,
    /// Stay on the game-over screen a moment, then restart from the checkpoint.
    Restart,
}

/// Where the moves of a watched game come from.
pub trait Script {
    /// The next move for `game`; `None` when there is nothing more to play.
    ///
    /// # Errors
    /// What the rules refuse (a bot that cannot simulate a shot: a bug).
    fn next(&mut self, game: &Game) -> Result<Option<Move>, GameError>;
}

/// A bot plays until the game is over or `rounds` shots (if given) were played out.
pub struct BotScript {
    bot: Box<dyn Bot>,
    rounds_left: Option<u32>,
}

impl BotScript {
    /// `bot` plays at most `rounds` rounds (for ever, until the game is over, if `None`).
    pub fn new(bot: Box<dyn Bot>, rounds: Option<u32>) -> Self {
        Self {
            bot,
            rounds_left: rounds,
        }
    }
}

impl Script for BotScript {
    fn next(&mut self, game: &Game) -> Result<Option<Move>, GameError> {
        match game.phase() {
            Phase::Volley => Ok(Some(Move::PlayOut)),
            Phase::GameOver => Ok(None),
            Phase::Aiming if self.rounds_left == Some(0) => Ok(None),
            Phase::Aiming => {
                self.rounds_left = self.rounds_left.map(|n| n - 1);
                Ok(Some(Move::Shoot(self.bot.choose(game)?)))
            }
        }
    }
}

/// A fixed list of moves, in order.
pub struct ListScript {
    moves: std::vec::IntoIter<Move>,
}

impl ListScript {
    /// Plays `moves`.
    pub fn new(moves: Vec<Move>) -> Self {
        Self {
            moves: moves.into_iter(),
        }
    }
}

impl Script for ListScript {
    fn next(&mut self, _game: &Game) -> Result<Option<Move>, GameError> {
        Ok(self.moves.next())
    }
}

/// The moves that play a game's `commands` again from its seed, ending at the saved volley
/// clock `live` if the game was saved mid-volley (else with the last volley played out).
///
/// A volley still live when a shot or a restart comes was played to its natural end; a
/// finish-now gives the same bits as playing the rest frame by frame, so the window plays
/// it out instead of jumping to its end.
pub fn moves(commands: &[Command], live: Option<f64>) -> Vec<Move> {
    let mut out = Vec::with_capacity(commands.len() * 2 + 1);
    for command in commands {
        match *command {
            Command::Shoot(aim) => out.extend([Move::PlayOut, Move::Shoot(aim)]),
            Command::Recall { at } => out.extend([Move::PlayTo(at), Move::Recall]),
            Command::Finish { at } => out.extend([Move::PlayTo(at), Move::PlayOut]),
            Command::Restart => out.extend([Move::PlayOut, Move::Restart]),
        }
    }
    out.push(live.map_or(Move::PlayOut, Move::PlayTo));
    out
}

/// Applies `moves` to `game` at once (no frames: the same bits, as the rules promise).
///
/// # Errors
/// The first move the game refuses.
pub fn apply_at_once(game: &mut Game, moves: &[Move]) -> Result<(), GameError> {
    for &m in moves {
        let live = game.phase() == Phase::Volley;
        match m {
            Move::Shoot(aim) => game.shoot(aim)?,
            Move::PlayTo(at) if live => {
                game.advance_to(at)?;
            }
            Move::PlayOut if live => {
                game.advance_to(f64::INFINITY)?;
            }
            Move::PlayTo(_) | Move::PlayOut => {}
            Move::Recall => {
                game.recall()?;
            }
            Move::Restart => game.restart()?,
        }
    }
    Ok(())
}

/// The moves that replay `saved` from its seed, checked: applied at once to a new game of
/// its seed and settings they must give `saved` bit for bit.
///
/// # Errors
/// A message when they do not (a game from a custom board, a file edited by hand), or
/// when the rules refuse a command.
pub fn replay_moves(saved: &Game) -> Result<Vec<Move>, String> {
    let moves = moves(saved.history(), saved.volley_time());
    let mut game = new_game_like(saved).map_err(|e| e.to_string())?;
    apply_at_once(&mut game, &moves)
        .map_err(|e| format!("its commands do not replay from its seed: {e}"))?;
    if hash_game(&game) != hash_game(saved) {
        return Err(
            "its commands, replayed from its seed, do not give the saved game (was it started on a custom board?)"
                .to_owned(),
        );
    }
    Ok(moves)
}

/// A new game with the seed and the settings of `game`.
///
/// # Errors
/// [`GameError::InvalidConfig`] (not for a game that loaded).
pub fn new_game_like(game: &Game) -> Result<Game, GameError> {
    Game::new(game.state().config().clone(), game.seed())
}

#[cfg(test)]
mod tests {
    use super::*;
    use onemorebrick::save::{from_json, to_json};
    use onemorebrick::{Config, RandomBot};

    /// A random-bot game of `seed` played to a game over, restarted, and played on `after`
    /// rounds; every third volley recalled, every third finished at once, the rest played
    /// in frames.
    fn eventful_game(seed: u64, after: u32) -> Game {
        let mut game = Game::new(Config::default(), seed).unwrap();
        let mut bot = RandomBot::new(seed);
        let (mut k, mut restarted, mut left) = (0, false, after);
        while !restarted || left > 0 {
            if game.phase() == Phase::GameOver {
                game.restart().unwrap();
                restarted = true;
                continue;
            }
            left -= u32::from(restarted);
            game.shoot(bot.choose(&game).unwrap()).unwrap();
            k += 1;
            match k % 3 {
                0 => {
                    game.advance_to(0.35).unwrap();
                    if game.phase() == Phase::Volley {
                        game.recall().unwrap();
                    }
                }
                1 => {
                    game.finish_round().unwrap();
                }
                _ => {
                    while game
                        .advance_to(game.volley_time().unwrap() + 0.05)
                        .unwrap()
                        .is_none()
                    {}
                }
            }
            assert!(k < 500, "the random bot loses within 500 rounds");
        }
        game
    }

    #[test]
    fn every_kind_of_command_becomes_its_moves() {
        let aim = Aim::new(0.1, 1.0);
        let commands = [
            Command::Shoot(aim),
            Command::Recall { at: 0.5 },
            Command::Shoot(aim),
            Command::Finish { at: 0.25 },
            Command::Restart,
            Command::Shoot(aim),
        ];
        assert_eq!(
            moves(&commands, Some(1.5)),
            [
                Move::PlayOut,
                Move::Shoot(aim),
                Move::PlayTo(0.5),
                Move::Recall,
                Move::PlayOut,
                Move::Shoot(aim),
                Move::PlayTo(0.25),
                Move::PlayOut,
                Move::PlayOut,
                Move::Restart,
                Move::PlayOut,
                Move::Shoot(aim),
                Move::PlayTo(1.5),
            ]
        );
    }

    #[test]
    fn a_save_with_recalls_finishes_and_a_restart_replays_to_itself() {
        let mut game = eventful_game(4, 3);
        assert!(game.history().contains(&Command::Restart));
        assert!(replay_moves(&game).is_ok());
        // Saved mid-volley: the replay stops at the saved clock.
        game.shoot(Aim::new(-0.2, 1.0)).unwrap();
        game.advance_to(0.7).unwrap();
        let saved = from_json(&to_json(&game), "memory".as_ref()).unwrap();
        let moves = replay_moves(&saved).unwrap();
        assert_eq!(moves.last(), Some(&Move::PlayTo(0.7)));
        let mut again = new_game_like(&saved).unwrap();
        apply_at_once(&mut again, &moves).unwrap();
        assert_eq!(again.balls(), game.balls());
        assert_eq!(hash_game(&again), hash_game(&game));
    }

    #[test]
    fn a_game_not_from_its_seed_is_refused() {
        use onemorebrick::{Board, GameState};
        let config = Config::default();
        let board = Board::new(config.columns, config.rows);
        let state = GameState::custom(config, board, 3, 2, 5).unwrap();
        let mut game = Game::from_state(5, state);
        game.shoot(Aim::new(0.3, 1.0)).unwrap();
        game.finish_round().unwrap();
        let err = replay_moves(&game).unwrap_err();
        assert!(err.contains("custom board"), "{err}");
    }

    #[test]
    fn the_bot_script_stops_after_its_rounds() {
        let mut game = Game::new(Config::default(), 2).unwrap();
        let mut script = BotScript::new(Box::new(RandomBot::new(2)), Some(2));
        let mut shots = 0;
        while let Some(m) = script.next(&game).unwrap() {
            shots += u32::from(matches!(m, Move::Shoot(_)));
            apply_at_once(&mut game, &[m]).unwrap();
        }
        assert_eq!((shots, game.state().totals().rounds), (2, 2));
        assert_eq!(game.phase(), Phase::Aiming);
    }
}
