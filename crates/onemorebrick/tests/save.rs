//! Save files: round trips, corrupt and future files, refusing to overwrite, setting aside,
//! and atomic writes.

use std::fs;
use std::path::PathBuf;

use onemorebrick::save::{SAVE_VERSION, from_json, temp_path, to_json};
use onemorebrick::{
    Bot, Config, Game, GreedyBot, SaveError, hash_game, load_game, save_game, set_aside,
};

/// A fresh directory under Cargo's per-test temporary directory.
fn scratch(name: &str) -> PathBuf {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR"))
        .join("save-tests")
        .join(name);
    let _ = fs::remove_dir_all(&dir);
    fs::create_dir_all(&dir).unwrap();
    dir
}

fn some_game() -> Game {
    let mut game = Game::new(Config::default(), 17).unwrap();
    let mut bot = GreedyBot::new(4);
    for _ in 0..4 {
        let aim = bot.choose(&game).unwrap();
        game.shoot(aim).unwrap();
        game.finish_round().unwrap();
    }
    game
}

#[test]
fn a_saved_game_loads_identical_and_plays_on_identically() {
    let path = scratch("round-trip").join("game.json");
    let mut game = some_game();
    save_game(&game, &path).unwrap();
    let mut loaded = load_game(&path).unwrap();
    assert_eq!(hash_game(&loaded), hash_game(&game));
    assert_eq!(loaded.state(), game.state());
    assert_eq!(loaded.history(), game.history());
    let aim = onemorebrick::Aim::new(-0.3, 1.0);
    for g in [&mut game, &mut loaded] {
        g.shoot(aim).unwrap();
        g.finish_round().unwrap();
    }
    assert_eq!(hash_game(&loaded), hash_game(&game));
    // Saving over a good save is fine.
    save_game(&loaded, &path).unwrap();
    assert!(!temp_path(&path).exists(), "the temporary file was renamed");
}

#[test]
fn a_mid_volley_save_on_disk_resumes_the_volley() {
    let path = scratch("mid-volley").join("game.json");
    let mut game = some_game();
    game.shoot(onemorebrick::Aim::new(0.2, 1.0)).unwrap();
    game.advance_to(0.5).unwrap();
    save_game(&game, &path).unwrap();
    let mut loaded = load_game(&path).unwrap();
    assert_eq!(loaded.volley_time(), Some(0.5));
    assert_eq!(loaded.balls(), game.balls());
    game.finish_round().unwrap();
    loaded.finish_round().unwrap();
    assert_eq!(hash_game(&loaded), hash_game(&game));
}

#[test]
fn corrupt_files_are_reported_with_their_path_and_problem() {
    let dir = scratch("corrupt");
    let good = to_json(&some_game());
    let cases = [
        ("garbage.json", "not json at all".to_owned()),
        ("truncated.json", good[..good.len() / 2].to_owned()),
        (
            "other.json",
            good.replace("onemorebrick-save", "something-else"),
        ),
        ("fields.json", good.replace("\"level\"", "\"levle\"")),
        ("empty.json", String::new()),
    ];
    for (name, text) in cases {
        let path = dir.join(name);
        fs::write(&path, text).unwrap();
        let err = load_game(&path).err().expect("must fail");
        assert!(matches!(err, SaveError::Corrupt { .. }), "{name}: {err}");
        assert!(err.to_string().contains(name), "{err}");
    }
}

#[test]
fn a_file_from_a_future_version_says_so() {
    let path = scratch("future").join("game.json");
    let current = format!("\"version\": {SAVE_VERSION}");
    let text = to_json(&some_game()).replace(&current, "\"version\": 7");
    fs::write(&path, text).unwrap();
    let err = load_game(&path).err().expect("must fail");
    assert!(
        matches!(
            err,
            SaveError::FutureVersion {
                found: 7,
                supported: SAVE_VERSION,
                ..
            }
        ),
        "{err}"
    );
    assert!(err.to_string().contains("newer version"), "{err}");
}

#[test]
fn an_inconsistent_game_is_invalid() {
    let good = to_json(&some_game());
    // A brick with no hit points left is impossible.
    let value: serde_json::Value = serde_json::from_str(&good).unwrap();
    let mut value = value;
    let cells = value["state"]["board"]["cells"].as_array_mut().unwrap();
    let brick = cells.iter_mut().find(|c| c.get("Brick").is_some()).unwrap();
    brick["Brick"]["hp"] = 0.into();
    let err = from_json(&value.to_string(), "bad.json".as_ref())
        .err()
        .expect("must fail");
    assert!(matches!(err, SaveError::Invalid { .. }), "{err}");
}

#[test]
fn an_unreadable_file_is_never_overwritten_silently_and_can_be_set_aside() {
    let path = scratch("overwrite").join("game.json");
    fs::write(&path, "{ broken").unwrap();
    let game = some_game();
    let err = save_game(&game, &path).expect_err("must refuse");
    assert!(matches!(err, SaveError::WouldOverwrite { .. }), "{err}");
    assert_eq!(fs::read_to_string(&path).unwrap(), "{ broken");
    let aside = set_aside(&path).unwrap();
    assert!(aside.to_string_lossy().ends_with("game.json.bad-1"));
    assert_eq!(fs::read_to_string(&aside).unwrap(), "{ broken");
    save_game(&game, &path).unwrap();
    assert!(load_game(&path).is_ok());
    // A second bad file goes to the next free name.
    fs::write(&path, "again").unwrap();
    assert!(
        set_aside(&path)
            .unwrap()
            .to_string_lossy()
            .ends_with(".bad-2")
    );
}

/// The write fails half-way (the temporary file's name is taken by a directory): the old
/// file is untouched and still loads.
#[test]
fn a_failed_write_leaves_the_old_file() {
    let path = scratch("atomic").join("game.json");
    let old = some_game();
    save_game(&old, &path).unwrap();
    let before = fs::read_to_string(&path).unwrap();
    fs::create_dir(temp_path(&path)).unwrap();
    let mut newer = some_game();
    newer.shoot(onemorebrick::Aim::new(0.0, 1.0)).unwrap();
    newer.finish_round().unwrap();
    let err = save_game(&newer, &path).expect_err("the write must fail");
    assert!(matches!(err, SaveError::Io { .. }), "{err}");
    assert_eq!(fs::read_to_string(&path).unwrap(), before);
    assert_eq!(hash_game(&load_game(&path).unwrap()), hash_game(&old));
}

#[test]
fn a_missing_file_is_an_io_error_naming_it() {
    let path = scratch("missing").join("nothing.json");
    let err = load_game(&path).err().expect("must fail");
    assert!(matches!(err, SaveError::Io { action: "read", .. }));
    assert!(err.to_string().contains("nothing.json"));
}

/// A game at level 5 that one round ends: a brick with more hit points than a ball can take
/// sits one row above the bottom.
fn a_game_over_at_level_5() -> Game {
    use onemorebrick::{Board, Brick, Cell, GameState, Shape};
    let config = Config::default();
    let mut board = Board::new(config.columns, config.rows);
    let brick = Cell::Brick(Brick {
        shape: Shape::Square,
        hp: 9999,
    });
    board.set(0, 1, brick).unwrap();
    let state = GameState::custom(config, board, 5, 1, 3).unwrap();
    let mut game = Game::from_state(3, state);
    game.shoot(onemorebrick::Aim::new(-0.3, 1.0)).unwrap();
    let report = game.finish_round().unwrap();
    assert!(report.game_over);
    game
}

#[test]
fn the_level_of_a_game_over_is_the_last_round_played() {
    let game = a_game_over_at_level_5();
    assert_eq!(game.last_report().unwrap().level, 5);
    assert_eq!(game.state().level(), 5);
    let loaded = from_json(&to_json(&game), "memory".as_ref()).unwrap();
    assert_eq!(loaded.state().level(), 5, "saved with the same number");
}

/// Version 1 counted one level more after a game over: such a file loads as the game it
/// was, with the level of its last round; a version-1 game that is not over is unchanged.
#[test]
fn a_version_1_save_loads_with_the_level_of_its_last_round() {
    let to_v1 = |game: &Game, level_then: u32| {
        let mut value: serde_json::Value = serde_json::from_str(&to_json(game)).unwrap();
        value["version"] = 1.into();
        value["state"]["level"] = level_then.into();
        value.to_string()
    };
    let over = a_game_over_at_level_5();
    let loaded = from_json(&to_v1(&over, 6), "old.json".as_ref()).unwrap();
    assert_eq!(loaded.state(), over.state());
    assert_eq!(hash_game(&loaded), hash_game(&over));
    let playing = some_game();
    let level = playing.state().level();
    let loaded = from_json(&to_v1(&playing, level), "old.json".as_ref()).unwrap();
    assert_eq!(hash_game(&loaded), hash_game(&playing));
}
