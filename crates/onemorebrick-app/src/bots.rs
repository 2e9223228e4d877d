//! The bot options every command that lets a bot play takes (`sim`, `screenshot`, `watch`),
//! with the same defaults, so the same seed and options give the same game in each.

use clap::{Args, ValueEnum};
use onemorebrick::{Bot, Config, Game, GameError, GreedyBot, Phase, RandomBot};

/// Which bot plays.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum BotName {
    /// Random directions (its own generator seeded from the game's seed).
    Random,
    /// Tries a fan of shots with the exact engine and takes the best.
    Greedy,
}

/// Candidate shots the greedy bot tries when `--candidates` is not given.
pub const DEFAULT_CANDIDATES: u32 = 32;

/// `--bot` and `--candidates`.
#[derive(Args, Clone, Copy, Debug, PartialEq, Eq)]
pub struct BotArgs {
    /// Which bot plays.
    #[arg(long, value_enum, default_value_t = BotName::Greedy)]
    pub bot: BotName,
    /// Candidate shots the greedy bot tries per round (2 to 1024).
    #[arg(long, default_value_t = DEFAULT_CANDIDATES, value_parser = clap::value_parser!(u32).range(2..=1024), allow_negative_numbers = true)]
    pub candidates: u32,
}

impl BotArgs {
    /// The bot for a game of seed `seed` (the random bot's generator starts from it).
    pub fn make(&self, seed: u64) -> Box<dyn Bot> {
        match self.bot {
            BotName::Random => Box::new(RandomBot::new(seed)),
            BotName::Greedy => Box::new(GreedyBot::new(self.candidates)),
        }
    }

    /// The bot's name as the command line spells it.
    pub fn name(&self) -> &'static str {
        match self.bot {
            BotName::Random => "random",
            BotName::Greedy => "greedy",
        }
    }
}

/// A new game of `seed` after `bot` played `rounds` rounds (fewer if the game ended), each
/// finished at once; returns the bot too, to go on playing the same game.
///
/// # Errors
/// What the rules refuse (a bug).
pub fn play_rounds(
    args: &BotArgs,
    seed: u64,
    rounds: u32,
) -> Result<(Game, Box<dyn Bot>), GameError> {
    let mut game = Game::new(Config::default(), seed)?;
    let mut bot = args.make(seed);
    for _ in 0..rounds {
        if game.phase() != Phase::Aiming {
            break;
        }
        let aim = bot.choose(&game)?;
        game.shoot(aim)?;
        game.finish_round()?;
    }
    Ok((game, bot))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_bots_play_the_rounds_asked() {
        for bot in [BotName::Random, BotName::Greedy] {
            let args = BotArgs { bot, candidates: 4 };
            let (game, _) = play_rounds(&args, 7, 3).unwrap();
            assert_eq!(game.state().totals().rounds, 3);
            assert_eq!(game.state().level(), 4);
        }
    }

    #[test]
    fn the_same_options_play_the_same_game() {
        let args = BotArgs {
            bot: BotName::Greedy,
            candidates: 6,
        };
        let (a, _) = play_rounds(&args, 11, 4).unwrap();
        let (b, _) = play_rounds(&args, 11, 4).unwrap();
        assert_eq!(onemorebrick::hash_game(&a), onemorebrick::hash_game(&b));
        let other = BotArgs {
            candidates: 7,
            ..args
        };
        let (c, _) = play_rounds(&other, 11, 4).unwrap();
        assert_ne!(a.history(), c.history(), "the options change the game");
    }
}
