//! `onemorebrick watch` and `onemorebrick replay`, run as a viewer would: in a real window
//! on a virtual X server, quitting after its rounds or on Escape (sent with `xdotool`). What
//! they print is checked against `sim` and the rules; the player's save must not change.
//!
//! The window tests are skipped with a message when `Xvfb`, `xvfb-run` or `xdotool` is
//! missing, unless `CI` is set (`.ci/run` installs them). Bad arguments and files are
//! checked without a display: they must fail before any window opens.

mod common;

use std::io::{BufRead, BufReader};
use std::path::{Path, PathBuf};
use std::process::{Command, Output, Stdio};
use std::sync::mpsc::{Receiver, channel};
use std::time::{Duration, SystemTime};

use common::{
    BIN, Guard, XServer, display_available, one_at_a_time, temp_dir, tools_available, wait_up_to,
};
use onemorebrick::{Aim, Bot, Config, Game, GreedyBot, Phase, hash_game, save_game};

/// Polls `f` every 50 ms for up to 30 s.
fn wait_for<T>(what: &str, f: impl FnMut() -> Option<T>) -> T {
    wait_up_to(30, what, f)
}

fn start_xvfb() -> (XServer, String) {
    let server = XServer::start(&[], 30);
    let display = server.display.clone();
    (server, display)
}

/// Finds the window titled `title` and sends it `key`.
fn press(display: &str, title: &str, key: &str) {
    let run = |args: &[&str]| {
        let out = Command::new("timeout")
            .args(["20", "xdotool"])
            .env("DISPLAY", display)
            .args(args)
            .output()
            .unwrap();
        assert!(out.status.success(), "xdotool {args:?}");
        String::from_utf8_lossy(&out.stdout).trim().to_owned()
    };
    let found = run(&["search", "--sync", "--name", title]);
    let window = found.lines().next().unwrap().to_owned();
    run(&["windowfocus", "--sync", &window]);
    run(&["key", key]);
}

/// A data folder holding a player's save and best score, as the game writes them.
fn player_data(name: &str) -> (PathBuf, Vec<(PathBuf, Vec<u8>, SystemTime)>) {
    let home = temp_dir(name);
    let data = home.join("data/onemorebrick");
    std::fs::create_dir_all(&data).unwrap();
    let mut game = Game::new(Config::default(), 77).unwrap();
    game.shoot(Aim::new(0.3, 1.0)).unwrap();
    game.finish_round().unwrap();
    save_game(&game, &data.join("game.json")).unwrap();
    std::fs::write(data.join("best-score.txt"), "5\n").unwrap();
    let files = snapshot(&data);
    (home, files)
}

/// Every file of `dir`: path, bytes, modification time.
fn snapshot(dir: &Path) -> Vec<(PathBuf, Vec<u8>, SystemTime)> {
    let mut files: Vec<_> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| {
            let path = e.unwrap().path();
            let modified = std::fs::metadata(&path).unwrap().modified().unwrap();
            (path.clone(), std::fs::read(&path).unwrap(), modified)
        })
        .collect();
    files.sort();
    files
}

fn untouched(home: &Path, before: &[(PathBuf, Vec<u8>, SystemTime)]) {
    let after = snapshot(&home.join("data/onemorebrick"));
    assert!(after == before, "the player's files changed");
}

fn sim(args: &[&str]) -> String {
    let out = Command::new(BIN).arg("sim").args(args).output().unwrap();
    assert!(out.status.success());
    String::from_utf8(out.stdout).unwrap()
}

/// Starts `onemorebrick ARGS` on `display` with `home` as its home; its standard output
/// comes line by line on the receiver.
fn spawn(display: &str, home: &Path, args: &[&str]) -> (Guard, Receiver<String>) {
    let mut child = Command::new(BIN)
        .args(args)
        .env("DISPLAY", display)
        .env("HOME", home)
        .env("XDG_DATA_HOME", home.join("data"))
        .stdout(Stdio::piped())
        .spawn()
        .expect("the game starts");
    let stdout = child.stdout.take().unwrap();
    let (send, receive) = channel();
    std::thread::spawn(move || {
        for line in BufReader::new(stdout).lines() {
            if send.send(line.unwrap()).is_err() {
                break;
            }
        }
    });
    (Guard(child), receive)
}

/// Lines from `lines` until one satisfies `last` (included).
fn read_until(lines: &Receiver<String>, last: impl Fn(&str) -> bool) -> Vec<String> {
    let mut out = Vec::new();
    loop {
        let line = lines
            .recv_timeout(Duration::from_secs(60))
            .unwrap_or_else(|e| panic!("no more output ({e}) after {out:?}"));
        let done = last(&line);
        out.push(line);
        if done {
            return out;
        }
    }
}

fn exits_cleanly(child: &mut Guard) {
    let status = wait_for("the window to quit", || child.0.try_wait().unwrap());
    assert!(status.success(), "{status}");
}

/// `watch --rounds 3` plays three rounds in the window, frame by frame, and prints exactly
/// what `sim` prints for the same seed and bot (the rounds, the summary, the JSON with the
/// game's hash), then quits; the player's save is neither read nor written.
#[test]
fn watch_plays_what_sim_plays_then_quits_and_the_save_is_untouched() {
    if !display_available() {
        return;
    }
    let (home, before) = player_data("watch-rounds");
    let args = [
        "--seed",
        "5",
        "--candidates",
        "4",
        "--rounds",
        "3",
        "--json",
    ];
    let out = {
        let _turn = one_at_a_time();
        Command::new("xvfb-run")
            .args(["-a", "-s", "-screen 0 1280x1024x24", BIN, "watch"])
            .args(args)
            .args(["--speed", "16"])
            .env("HOME", &home)
            .env("XDG_DATA_HOME", home.join("data"))
            .output()
            .unwrap()
    };
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "{stderr}");
    assert!(!stderr.contains("panicked"), "{stderr}");
    let watched = String::from_utf8(out.stdout).unwrap();
    assert_eq!(watched, sim(&args));
    assert_eq!(
        watched.lines().filter(|l| l.starts_with("round ")).count(),
        3
    );
    untouched(&home, &before);
    std::fs::remove_dir_all(&home).unwrap();
}

/// Without `--rounds` the bot plays on until the viewer presses Escape: it quits cleanly,
/// and what it showed and summed up is what `sim` plays in as many rounds.
#[test]
fn watch_quits_on_escape() {
    if !tools_available() {
        return;
    }
    let _turn = one_at_a_time();
    let (home, before) = player_data("watch-escape");
    let (_xvfb, display) = start_xvfb();
    let (mut child, lines) = spawn(
        &display,
        &home,
        &["watch", "--seed", "9", "--bot", "random", "--speed", "8"],
    );
    let mut shown = read_until(&lines, |l| l.starts_with("round 2:"));
    press(&display, "^One More Brick: watch$", "Escape");
    exits_cleanly(&mut child);
    // The rest: the summary of the rounds played when Escape came (a third may have ended).
    shown.extend(lines.iter());
    let summary = shown.pop().unwrap();
    let rounds = shown.len().to_string();
    let played = sim(&["--seed", "9", "--bot", "random", "--rounds", &rounds]);
    let mut expected: Vec<&str> = played.lines().collect();
    assert_eq!(summary, expected.pop().unwrap());
    assert_eq!(shown, expected);
    untouched(&home, &before);
    std::fs::remove_dir_all(&home).unwrap();
}

/// A save with a recalled round and a volley in flight: `replay` plays its commands from
/// its seed in the window up to the saved volley clock, and its JSON has the saved game's
/// hash (balls in flight included); Escape quits; the file is only read.
#[test]
fn replay_plays_a_save_to_its_saved_state_and_quits() {
    if !tools_available() {
        return;
    }
    let _turn = one_at_a_time();
    let (home, _) = player_data("replay");
    let file = home.join("kept.json");
    let mut game = Game::new(Config::default(), 31).unwrap();
    let mut bot = GreedyBot::new(4);
    for round in 0..3 {
        game.shoot(bot.choose(&game).unwrap()).unwrap();
        if round == 1 {
            assert!(game.advance_to(0.3).unwrap().is_none(), "still in flight");
            game.recall().unwrap();
        } else {
            game.finish_round().unwrap();
        }
    }
    game.shoot(bot.choose(&game).unwrap()).unwrap();
    game.advance_to(1.25).unwrap();
    assert_eq!(game.phase(), Phase::Volley);
    save_game(&game, &file).unwrap();
    let bytes = std::fs::read(&file).unwrap();

    let (_xvfb, display) = start_xvfb();
    let path = file.to_str().unwrap();
    let (mut child, lines) = spawn(&display, &home, &["replay", path, "--speed", "4", "--json"]);
    let shown = read_until(&lines, |l| l.starts_with('{'));
    press(&display, "^One More Brick: replay$", "Escape");
    exits_cleanly(&mut child);
    let rounds: Vec<&String> = shown.iter().filter(|l| l.starts_with("round ")).collect();
    assert_eq!(rounds.len(), 3, "{shown:?}");
    assert!(rounds[2].starts_with("round 3: level 3"), "{shown:?}");
    let json: serde_json::Value = serde_json::from_str(shown.last().unwrap()).unwrap();
    assert_eq!(json["seed"].as_u64(), Some(31));
    assert_eq!(json["level"].as_u64(), Some(4));
    assert_eq!(json["score"].as_u64(), Some(game.state().score()));
    let hash = format!("{:016x}", hash_game(&game));
    assert_eq!(json["hash"].as_str(), Some(hash.as_str()), "{shown:?}");
    assert_eq!(
        std::fs::read(&file).unwrap(),
        bytes,
        "the file is only read"
    );
    std::fs::remove_dir_all(&home).unwrap();
}

fn without_display(args: &[&str]) -> Output {
    Command::new(BIN)
        .args(args)
        .env_remove("DISPLAY")
        .output()
        .unwrap()
}

/// Bad arguments and files fail with a message naming the problem and exit 2, before any
/// window opens (without a display, opening one would fail with exit 1 instead).
#[test]
fn bad_arguments_and_files_fail_before_a_window_opens() {
    let dir = temp_dir("replay-bad");
    let garbage = dir.join("garbage.json");
    std::fs::write(&garbage, "{ not a save").unwrap();
    let custom = dir.join("custom.json");
    let config = Config::default();
    let board = onemorebrick::Board::new(config.columns, config.rows);
    let state = onemorebrick::GameState::custom(config, board, 4, 2, 6).unwrap();
    let mut game = Game::from_state(6, state);
    game.shoot(Aim::new(0.2, 1.0)).unwrap();
    game.finish_round().unwrap();
    save_game(&game, &custom).unwrap();
    let missing = dir.join("missing.json");
    let cases: [(Vec<&str>, &str); 9] = [
        (
            vec!["play", "--seed", "-1"],
            "a seed is a whole number in [0, ",
        ),
        (vec!["--seed", "abc"], "a seed is a whole number in [0, "),
        (vec!["watch", "--speed", "3"], "the speed is one of 1, 2, 4"),
        (vec!["watch", "--rounds", "0"], "0 is not in 1..=100000"),
        (vec!["watch", "--seed", "-2"], "a seed is a whole number"),
        (vec!["watch", "--bot", "clever"], "invalid value 'clever'"),
        (
            vec!["replay", missing.to_str().unwrap()],
            "missing.json: could not read",
        ),
        (
            vec!["replay", garbage.to_str().unwrap()],
            "garbage.json: not a valid save file",
        ),
        (vec!["replay", custom.to_str().unwrap()], "custom board"),
    ];
    for (args, message) in cases {
        let out = without_display(&args);
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {err}");
        assert!(err.contains(message), "{args:?}: {err}");
        assert!(!err.contains("panicked"), "{args:?}: {err}");
        assert!(out.stdout.is_empty(), "{args:?}");
    }
    let out = without_display(&["replay"]);
    assert_eq!(out.status.code(), Some(2), "the file is required");
    std::fs::remove_dir_all(&dir).unwrap();
}

/// Built with the `audio` feature, on a machine without a sound device (as CI's): the game
/// says once, in one line, that sound is off, and prints no panic or backtrace, whether there
/// is no sound server at all or only a server's socket that nobody serves (the sound library
/// would try it, and its thread's failure raced the game's first sounds: the library then
/// printed "Audio thread died" on standard output, once, on a busy CI machine).
#[cfg(feature = "audio")]
#[test]
fn without_a_sound_device_one_line_says_sound_is_off() {
    if !display_available() {
        return;
    }
    let no_card = !std::fs::read_to_string("/proc/asound/cards").is_ok_and(|t| {
        t.lines()
            .any(|l| l.trim_start().starts_with(|c: char| c.is_ascii_digit()))
    });
    let home = temp_dir("audio");
    let fake = home.join("run");
    std::fs::create_dir_all(fake.join("pulse")).unwrap();
    std::fs::write(fake.join("pulse/native"), "").unwrap();
    for (runtime, why) in [(None, "no sound device"), (Some(&fake), "no sound device")] {
        let mut command = Command::new("xvfb-run");
        command
            .args(["-a", "-s", "-screen 0 1280x1024x24", BIN, "watch"])
            .args([
                "--seed",
                "3",
                "--candidates",
                "2",
                "--rounds",
                "2",
                "--speed",
                "4",
            ])
            .env("HOME", &home)
            .env("XDG_DATA_HOME", home.join("data"))
            .env("RUST_BACKTRACE", "1")
            .env_remove("PULSE_SERVER");
        match runtime {
            Some(dir) => command.env("XDG_RUNTIME_DIR", dir),
            None => command.env_remove("XDG_RUNTIME_DIR"),
        };
        let out = {
            let _turn = one_at_a_time();
            command.output().unwrap()
        };
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert!(out.status.success(), "{stderr}");
        assert!(!stderr.contains("panicked"), "{stderr}");
        assert!(!stderr.contains("backtrace"), "{stderr}");
        let said: Vec<&str> = stderr
            .lines()
            .filter(|l| l.contains("sound is off"))
            .collect();
        assert!(said.len() <= 1, "{stderr}");
        let configured = Path::new("/etc/asound.conf").exists() || home.join(".asoundrc").exists();
        if no_card && !configured {
            assert_eq!(said.len(), 1, "{stderr}");
            assert!(
                said[0].starts_with("onemorebrick: sound is off: "),
                "{stderr}"
            );
            assert!(said[0].contains(why), "{stderr}");
        }
        let stdout = String::from_utf8(out.stdout).unwrap();
        assert_eq!(
            stdout.lines().filter(|l| l.starts_with("round ")).count(),
            2,
            "{stdout}"
        );
        assert!(!stdout.contains("Audio thread died"), "{stdout}");
    }
    std::fs::remove_dir_all(&home).unwrap();
}
