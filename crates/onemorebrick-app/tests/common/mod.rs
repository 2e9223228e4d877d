//! Helpers shared by the window tests: temporary folders, the virtual display, running
//! `onemorebrick screenshot` under `xvfb-run`, decoding its PNG, and the bot's game.
// Each test file uses its own subset of these helpers.
#![allow(dead_code)]

use std::fs::File;
use std::io::Write;
use std::path::{Path, PathBuf};
use std::process::{Child, Command, Output};
use std::thread::sleep;
use std::time::{Duration, Instant};

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

/// One X server starting at a time: two starting together may pick the same display number.
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

/// The board's rectangle in pixels, from the PNG's `board` text chunk ("x y w h").
pub fn board_rect(png: &Path) -> [f32; 4] {
    let reader = png::Decoder::new(File::open(png).unwrap())
        .read_info()
        .unwrap();
    let chunk = reader
        .info()
        .uncompressed_latin1_text
        .iter()
        .find(|c| c.keyword == "board")
        .expect("a board text chunk");
    let v: Vec<f32> = chunk.text.split(' ').map(|x| x.parse().unwrap()).collect();
    assert_eq!(v.len(), 4, "{:?}", chunk.text);
    [v[0], v[1], v[2], v[3]]
}

/// Checks that standard output is the one line the command promises.
pub fn only_wrote_line(stdout: &str, png: &Path, width: u32, height: u32) {
    assert_eq!(
        stdout,
        format!("wrote {} ({width}x{height})\n", png.display()),
        "standard output holds more than the promised line"
    );
}

/// A saved game at `level` on a board of the default size with `bricks` (column, row, brick)
/// and the given score and best score (written into the save as a long game would leave
/// them).
pub fn custom_save(
    path: &Path,
    level: u32,
    bricks: &[(u32, u32, onemorebrick::Brick)],
    score: u64,
    best: u64,
) -> Game {
    let config = Config::default();
    let mut board = onemorebrick::Board::new(config.columns, config.rows);
    for (column, row, brick) in bricks {
        board
            .set(*column, *row, onemorebrick::Cell::Brick(*brick))
            .unwrap();
    }
    let state = onemorebrick::GameState::custom(config, board, level, 3, 1).unwrap();
    let game = Game::from_state(1, state);
    onemorebrick::save_game(&game, path).unwrap();
    let mut json: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap();
    json["state"]["score"] = score.into();
    json["state"]["best_score"] = best.into();
    std::fs::write(path, serde_json::to_string_pretty(&json).unwrap()).unwrap();
    onemorebrick::load_game(path).expect("the edited save loads")
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

/// The named rectangles a screenshot carries in its `tEXt` chunks (`board`, `card`, ...):
/// `x y width height` in pixels.
pub fn regions(path: &Path) -> Vec<(String, [f32; 4])> {
    let reader = png::Decoder::new(File::open(path).unwrap())
        .read_info()
        .unwrap();
    reader
        .info()
        .uncompressed_latin1_text
        .iter()
        .map(|chunk| {
            let v: Vec<f32> = chunk.text.split(' ').map(|x| x.parse().unwrap()).collect();
            (chunk.keyword.clone(), [v[0], v[1], v[2], v[3]])
        })
        .collect()
}

/// The rectangle named `name` on the screenshot at `path`.
pub fn region(path: &Path, name: &str) -> [f32; 4] {
    regions(path)
        .into_iter()
        .find(|(n, _)| n == name)
        .unwrap_or_else(|| panic!("{}: no region {name}", path.display()))
        .1
}

/// Kills a child process when dropped (a failed assertion must not leave it running).
pub struct Guard(pub Child);

impl Drop for Guard {
    fn drop(&mut self) {
        let _ = self.0.kill();
        let _ = self.0.wait();
    }
}

/// A virtual X server (`Xvfb`, 1280 x 1024) on a display it chose itself (`-displayfd`: it
/// passes over displays whose lock a live server holds and takes over stale ones), killed on
/// drop with its socket and lock removed. A killed server cannot remove them itself, and
/// left behind they piled up in `/tmp` run after run until a test found no display free.
pub struct XServer {
    server: Guard,
    /// The display's name, `:N`.
    pub display: String,
    number: u32,
}

impl XServer {
    /// Starts one, with `extra` arguments (`-fbdir DIR`, say), and waits until it accepts
    /// clients (up to `seconds`).
    pub fn start(extra: &[&std::ffi::OsStr], seconds: u64) -> Self {
        let mut child = Command::new("Xvfb")
            .args([
                "-displayfd",
                "1",
                "-screen",
                "0",
                "1280x1024x24",
                "-nolisten",
                "tcp",
            ])
            .args(extra)
            .stdout(std::process::Stdio::piped())
            .stderr(std::process::Stdio::null())
            .spawn()
            .expect("Xvfb starts");
        // The display number comes on standard output once the server is ready; read on a
        // thread of its own, so that a server that never says gives a clear failure.
        let stdout = child.stdout.take().expect("Xvfb's standard output");
        let (tx, rx) = std::sync::mpsc::channel();
        std::thread::spawn(move || {
            let mut line = String::new();
            let _ = std::io::BufRead::read_line(&mut std::io::BufReader::new(stdout), &mut line);
            let _ = tx.send(line);
        });
        let server = Guard(child);
        let line = rx
            .recv_timeout(Duration::from_secs(seconds))
            .expect("Xvfb names its display in time");
        let number = line
            .trim()
            .parse()
            .unwrap_or_else(|_| panic!("Xvfb's display number, got {line:?}"));
        Self {
            server,
            display: format!(":{number}"),
            number,
        }
    }
}

impl Drop for XServer {
    fn drop(&mut self) {
        let _ = self.server.0.kill();
        let _ = self.server.0.wait();
        let _ = std::fs::remove_file(format!("/tmp/.X11-unix/X{}", self.number));
        let _ = std::fs::remove_file(format!("/tmp/.X{}-lock", self.number));
    }
}

/// Whether the window tests that drive a window can run here (`Xvfb` and `xdotool`); panics
/// when they must (CI) but cannot.
pub fn tools_available() -> bool {
    if on_path("Xvfb") && on_path("xdotool") {
        return true;
    }
    let ci = std::env::var("CI").is_ok_and(|v| !v.is_empty() && v != "false" && v != "0");
    assert!(
        !ci,
        "CI is set but Xvfb or xdotool is missing: .ci/run installs them"
    );
    // Straight to standard error: the test harness captures `eprintln!` of passing tests.
    let _ = writeln!(
        std::io::stderr(),
        "SKIPPED: Xvfb or xdotool is not installed"
    );
    false
}

/// One window test at a time in a test file (see [`ONE_SERVER_AT_A_TIME`]).
pub fn one_at_a_time() -> std::sync::MutexGuard<'static, ()> {
    ONE_SERVER_AT_A_TIME
        .lock()
        .unwrap_or_else(std::sync::PoisonError::into_inner)
}

/// Polls `f` every 50 ms until it gives a value, for up to `seconds`.
pub fn wait_up_to<T>(seconds: u64, what: &str, mut f: impl FnMut() -> Option<T>) -> T {
    let start = Instant::now();
    loop {
        if let Some(v) = f() {
            return v;
        }
        assert!(
            start.elapsed() < Duration::from_secs(seconds),
            "timed out waiting for {what}"
        );
        sleep(Duration::from_millis(50));
    }
}
