//! The game's runs: whole games of random-bot rounds from a seed, driven by frames, at once or
//! recalled; a replay of a game from its JSON text; a dense board (every cell kind, every
//! pick-up) with a 40-ball volley; a game saved mid-volley and loaded. Each gives
//! [`hash_game`] values (FNV-1a over the rules' state and every ball in play).

use onemorebrick::save::{from_json, to_json};
use onemorebrick::{
    Aim, Board, Bot, Brick, Cell, Config, Corner, Game, GameState, Phase, Pickup, PickupKind,
    RandomBot, Replay, Shape, hash_game,
};

/// Plays `rounds` random-bot rounds of a new game of `seed` (restarting after a game over),
/// each volley driven by `drive`; returns the game and its hash after every round.
///
/// # Panics
/// If the rules refuse one of the bot's aims, or `drive` leaves a volley in flight.
pub fn play(seed: u64, rounds: u32, mut drive: impl FnMut(&mut Game)) -> (Game, Vec<u64>) {
    let mut game = Game::new(Config::default(), seed).expect("the default config is valid");
    let mut bot = RandomBot::new(seed);
    let mut hashes = Vec::new();
    for _ in 0..rounds {
        if game.phase() == Phase::GameOver {
            game.restart().expect("a game over restarts");
        }
        let aim = bot.choose(&game).expect("the bot finds an aim");
        game.shoot(aim).expect("the bot's aim is valid");
        drive(&mut game);
        assert_ne!(game.phase(), Phase::Volley, "the round ended");
        hashes.push(hash_game(&game));
    }
    (game, hashes)
}

/// Finishes the volley at once.
///
/// # Panics
/// If the rules refuse (no volley in flight).
pub fn finish(game: &mut Game) {
    game.finish_round().expect("a volley to finish");
}

/// Frames of `dt` until the round ends.
///
/// # Panics
/// If the rules refuse a frame time.
pub fn frames(dt: f64) -> impl FnMut(&mut Game) {
    move |game: &mut Game| {
        let mut k = 1.0;
        while game.advance_to(k * dt).expect("a later frame").is_none() {
            k += 1.0;
        }
    }
}

/// The last round's hash of `rounds` rounds from `seed`, each finished at once.
#[must_use]
pub fn golden_game(seed: u64, rounds: u32) -> u64 {
    let (_, hashes) = play(seed, rounds, finish);
    *hashes.last().expect("at least one round")
}

/// 25 rounds from seed 21, driven three ways in turn: advanced to 0.4 s and recalled (if
/// still in flight), played in frames of 1/30 s, finished at once.
#[must_use]
pub fn mixed_game() -> Game {
    let mut k = 0;
    let (game, _) = play(21, 25, |game| {
        k += 1;
        match k % 3 {
            0 => {
                game.advance_to(0.4).expect("a later time");
                if game.phase() == Phase::Volley {
                    game.recall().expect("a volley to recall");
                }
            }
            1 => frames(1.0 / 30.0)(game),
            _ => finish(game),
        }
    });
    game
}

/// [`mixed_game`]'s replay, written as JSON, read back and played from its seed.
///
/// # Panics
/// If the replay does not read back or does not fit the game.
#[must_use]
pub fn replayed_mixed_game() -> Game {
    let text = serde_json::to_string(&Replay::of(&mixed_game())).expect("a replay serialises");
    let replay: Replay = serde_json::from_str(&text).expect("the replay reads back");
    replay.play().expect("the replay fits the game")
}

/// A dense board with every cell kind and every pick-up, and a 40-ball volley to come.
#[must_use]
pub fn dense_game() -> Game {
    let config = Config::default();
    let mut board = Board::new(config.columns, config.rows);
    let mut kinds = PickupKind::ALL.iter().cycle();
    for row in 2..config.rows {
        for column in 0..config.columns {
            let cell = match (row * 3 + column * 2) % 6 {
                0 => Cell::Obstacle,
                1 => Cell::Pickup(Pickup::new(*kinds.next().expect("a cycle never ends"))),
                2 => Cell::Brick(Brick {
                    shape: Shape::Triangle(Corner::ALL[(row % 4) as usize]),
                    hp: 7,
                }),
                3 => Cell::Empty,
                _ => Cell::Brick(Brick {
                    shape: Shape::Square,
                    hp: 9,
                }),
            };
            board.set(column, row, cell).expect("a cell on the board");
        }
    }
    Game::from_state(
        3,
        GameState::custom(config, board, 9, 40, 3).expect("a valid state"),
    )
}

/// The aim of the dense volley.
pub const DENSE_AIM: Aim = Aim { dx: 0.31, dy: 1.0 };

/// The dense volley finished at once.
#[must_use]
pub fn dense_volley_at_once() -> Game {
    let mut game = dense_game();
    game.shoot(DENSE_AIM).expect("a valid aim");
    finish(&mut game);
    game
}

/// The dense volley played in frames of 1/60 s.
#[must_use]
pub fn dense_volley_in_frames() -> Game {
    let mut game = dense_game();
    game.shoot(DENSE_AIM).expect("a valid aim");
    frames(1.0 / 60.0)(&mut game);
    game
}

/// The dense volley stepped through its first 500 engine events (the clock at an event
/// time, not a frame time), saved, loaded, and finished; also returns the game that was
/// saved, finished in place.
///
/// # Panics
/// If the volley ends within 500 events or the save does not load.
#[must_use]
pub fn dense_volley_reloaded() -> (Game, Game) {
    let mut stepped = dense_game();
    stepped.shoot(DENSE_AIM).expect("a valid aim");
    for _ in 0..500 {
        stepped.step(f64::INFINITY).expect("a step");
    }
    assert_eq!(stepped.phase(), Phase::Volley, "still in flight");
    let mut loaded = from_json(&to_json(&stepped), "memory".as_ref()).expect("the save loads");
    finish(&mut loaded);
    finish(&mut stepped);
    (loaded, stepped)
}

/// The game of `seed` after 8 rounds finished at once (restarted after a game over), then a
/// volley aimed by `RandomBot::new(99)` and advanced to `at` seconds: still in flight.
///
/// # Panics
/// If the volley has ended by `at`.
#[must_use]
pub fn mid_volley(seed: u64, at: f64) -> Game {
    let (mut game, _) = play(seed, 8, finish);
    if game.phase() == Phase::GameOver {
        game.restart().expect("a game over restarts");
    }
    let aim = RandomBot::new(99)
        .choose(&game)
        .expect("the bot finds an aim");
    game.shoot(aim).expect("the bot's aim is valid");
    game.advance_to(at).expect("a later time");
    assert_eq!(game.phase(), Phase::Volley, "seed {seed}: still in flight");
    game
}

/// [`mid_volley`] saved to JSON, loaded and finished.
///
/// # Panics
/// If the save does not load.
#[must_use]
pub fn mid_volley_reloaded(seed: u64, at: f64) -> Game {
    let json = to_json(&mid_volley(seed, at));
    let mut loaded = from_json(&json, "memory".as_ref()).expect("the save loads");
    finish(&mut loaded);
    loaded
}
