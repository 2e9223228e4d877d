//! Helpers shared by the window tests: temporary folders, the virtual display, running
//! `onemorebrick screenshot` under `xvfb-run`, decoding its PNG, and the bot's game.
// Each test file uses its own subset of these helpers.
#![allow(dead_code)]

use std::fs::File;
use std::io::Write;
use std::path::{Path, PathBuf};
use std::process::{Command, Output};

use onemorebrick::{Bot, Config, Game, GreedyBot, Phase};

pub const BIN: &str = env!("CARGO_BIN_EXE_onemorebrick");

pub fn temp_dir(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("omb-shot-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

pub fn on_path(program: &str) -> bool {
    std::env::var_os("PATH")
        .is_some_and(|paths| std::env::split_paths(&paths).any(|dir| dir.join(program).is_file()))
}

/// Whether the rendering tests can run here; panics when they must (CI) but cannot.
pub fn display_available() -> bool {
    if on_path("xvfb-run") {
        return true;
    }
    let ci = std::env::var("CI").is_ok_and(|v| !v.is_empty() && v != "false" && v != "0");
    assert!(
        !ci,
        "CI is set but xvfb-run is missing: .ci/run installs it (apt-get install xvfb xauth)"
    );
    // Straight to standard error: the test harness captures `eprintln!` of passing tests.
    let _ = writeln!(
        std::io::stderr(),
        "SKIPPED: xvfb-run is not installed, so no display server can be started"
    );
    false
}

/// One `xvfb-run -a` at a time: two starting together may pick the same display number.
pub static ONE_SERVER_AT_A_TIME: std::sync::Mutex<()> = std::sync::Mutex::new(());

pub fn screenshot(args: &[&str]) -> Output {
    let _turn = ONE_SERVER_AT_A_TIME
        .lock()
        .unwrap_or_else(std::sync::PoisonError::into_inner);
    Command::new("xvfb-run")
        .args(["-a", "-s", "-screen 0 1280x1024x24", BIN, "screenshot"])
        .args(args)
        .output()
        .expect("xvfb-run runs")
}

/// Runs `screenshot` with `args`, checks it succeeded, and returns its standard output.
pub fn screenshot_ok(args: &[&str]) -> String {
    let run = screenshot(args);
    let stdout = String::from_utf8_lossy(&run.stdout).into_owned();
    assert!(
        run.status.success(),
        "{stdout}\n{}",
        String::from_utf8_lossy(&run.stderr)
    );
    stdout
}

/// The image's pixels (RGBA, top row first), width and height.
pub fn decode(path: &Path) -> (Vec<u8>, u32, u32) {
    let mut reader = png::Decoder::new(File::open(path).unwrap())
        .read_info()
        .unwrap();
    let mut buf = vec![0; reader.output_buffer_size()];
    let info = reader.next_frame(&mut buf).unwrap();
    assert_eq!(info.color_type, png::ColorType::Rgba);
    buf.truncate(info.buffer_size());
    (buf, info.width, info.height)
}

/// The `board X Y W H` line: the board's rectangle in pixels.
pub fn board_rect(stdout: &str) -> [f32; 4] {
    let line = stdout
        .lines()
        .find(|l| l.starts_with("board "))
        .expect("a board line");
    let v: Vec<f32> = line[6..].split(' ').map(|x| x.parse().unwrap()).collect();
    [v[0], v[1], v[2], v[3]]
}

/// The greedy bot's candidate shots when `--candidates` is not given (every command's
/// default).
pub const CANDIDATES: u32 = 32;

/// The same game the command's bot plays (greedy, the default options).
pub fn bot_game(seed: u64, rounds: u32) -> Game {
    let mut game = Game::new(Config::default(), seed).unwrap();
    let mut bot = GreedyBot::new(CANDIDATES);
    for _ in 0..rounds {
        if game.phase() != Phase::Aiming {
            break;
        }
        game.shoot(bot.choose(&game).unwrap()).unwrap();
        game.finish_round().unwrap();
    }
    game
}
