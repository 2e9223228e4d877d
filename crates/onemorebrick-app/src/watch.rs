//! `onemorebrick watch` (a bot plays) and `onemorebrick replay FILE` (a saved game's
//! commands played again from its seed), in the window, animated as in play, at a speed the
//! viewer changes with the keys. Nobody's save is read or written but the replayed file's,
//! which is only read.
//!
//! Keys: Up, Right, F or + faster; Down, Left, S or - slower (x1 to x64); Space or P pause;
//! Escape or Q quit (closing the window too). Standard output: the `sim` lines of each round
//! as it ends, then `sim`'s summary line (and with `--json` its JSON object) when the game
//! or the replay is over, or on quitting before: a bot's watched game prints exactly what
//! `sim` prints for the same seed and options.

use std::io::{self, Write};
use std::path::PathBuf;

use clap::Args;
use macroquad::input::{KeyCode, is_key_pressed, is_quit_requested, prevent_quit};
use macroquad::time::get_frame_time;
use macroquad::window::next_frame;
use onemorebrick::{Config, Game, Phase, load_game};

use crate::app::App;
use crate::bots::BotArgs;
use crate::failure::Failure;
use crate::input::Action;
use crate::playback::{BotScript, ListScript, Move, Script, new_game_like, replay_moves};
use crate::sim::{Summary, round_line};
use crate::sound::Sounds;
use crate::storage::Seeds;

/// The speeds the viewer steps through (times play speed).
pub const SPEEDS: [u32; 7] = [1, 2, 4, 8, 16, 32, 64];
/// Seconds of play the bot's aim shows before its shot.
const AIM_SECONDS: f32 = 0.6;
/// Seconds of play the game-over screen shows before a replayed restart.
const GAME_OVER_SECONDS: f32 = 1.5;

/// Arguments of `onemorebrick watch`.
#[derive(Args, Debug)]
pub struct WatchArgs {
    /// The game's seed (the random bot's too); drawn from the system's generator if not
    /// given, and shown under the board.
    #[arg(long, value_parser = crate::parse_seed, allow_negative_numbers = true)]
    seed: Option<u64>,
    /// The bot (the same options and defaults as `sim`).
    #[command(flatten)]
    bot: BotArgs,
    /// Quit (exit 0) once this many rounds are played, or at the game over if sooner;
    /// without it the window stays open on the game over until closed.
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=100_000), allow_negative_numbers = true)]
    rounds: Option<u32>,
    #[command(flatten)]
    view: ViewArgs,
}

/// Arguments of `onemorebrick replay`.
#[derive(Args, Debug)]
pub struct ReplayArgs {
    /// A save file (the game's `game.json`): its seed and commands are played again, to the
    /// state it holds (mid-volley if it was saved so). It is only read.
    file: PathBuf,
    #[command(flatten)]
    view: ViewArgs,
}

/// What both commands show and print.
#[derive(Args, Debug)]
struct ViewArgs {
    /// The speed to start at: 1, 2, 4, 8, 16, 32 or 64 times play speed (the keys change it).
    #[arg(long, default_value_t = 1, value_parser = parse_speed, allow_negative_numbers = true)]
    speed: u32,
    /// End with `sim`'s JSON object of the game on the last line (its hash included).
    #[arg(long)]
    json: bool,
}

/// `--speed`: one of [`SPEEDS`].
fn parse_speed(text: &str) -> Result<u32, String> {
    text.trim()
        .parse::<u32>()
        .ok()
        .filter(|s| SPEEDS.contains(s))
        .ok_or_else(|| "the speed is one of 1, 2, 4, 8, 16, 32, 64".to_owned())
}

/// Runs `watch`: a bot plays a new game in the window.
///
/// # Errors
/// When the system's generator fails without `--seed`, or no window can open.
pub fn run_watch(args: &WatchArgs) -> Result<(), Failure> {
    let seed = match args.seed {
        Some(seed) => seed,
        None => Seeds::Os.draw().map_err(Failure::Message)?,
    };
    let game = Game::new(Config::default(), seed)?;
    let script = BotScript::new(args.bot.make(seed), args.rounds);
    let label = format!("{} bot, seed {seed}", capitalised(args.bot.name()));
    let mut viewer = Viewer::new(game, Box::new(script), &args.view, label, args.bot.name());
    viewer.quit_when_finished = args.rounds.is_some();
    open("One More Brick: watch", viewer)
}

/// Runs `replay`: the file is read and its replay checked before any window opens.
///
/// # Errors
/// [`Failure::Usage`] for a file that is not a save, or whose commands do not replay to it;
/// a message when no window can open.
pub fn run_replay(args: &ReplayArgs) -> Result<(), Failure> {
    let shown = args.file.display();
    let saved = load_game(&args.file).map_err(|e| Failure::Usage(e.to_string()))?;
    let moves = replay_moves(&saved).map_err(|e| Failure::Usage(format!("{shown}: {e}")))?;
    let game = new_game_like(&saved)?;
    let name = args.file.file_name().unwrap_or_default().to_string_lossy();
    let label = format!("Replay of {name}, seed {}", saved.seed());
    let viewer = Viewer::new(
        game,
        Box::new(ListScript::new(moves)),
        &args.view,
        label,
        "replay",
    );
    open("One More Brick: replay", viewer)
}

fn capitalised(word: &str) -> String {
    let mut chars = word.chars();
    chars.next().map_or_else(String::new, |c| {
        c.to_uppercase().chain(chars).collect::<String>()
    })
}

fn open(title: &str, viewer: Viewer) -> Result<(), Failure> {
    crate::play::check_display().map_err(Failure::Message)?;
    crate::sound::check_device();
    let conf = crate::play::conf(title, 540, 860, true);
    macroquad::Window::from_config(conf, viewer.run());
    Ok(())
}

/// A watched game: the front end, driven by a script instead of a player.
struct Viewer {
    app: App,
    script: Box<dyn Script>,
    /// The move being played, and the seconds of play it still waits (an aim shown, the
    /// game-over screen before a restart).
    current: Option<(Move, f32)>,
    speed: usize,
    paused: bool,
    finished: bool,
    quit_when_finished: bool,
    label: String,
    bot: &'static str,
    json: bool,
}

impl Viewer {
    fn new(
        game: Game,
        script: Box<dyn Script>,
        view: &ViewArgs,
        label: String,
        bot: &'static str,
    ) -> Self {
        Self {
            app: App::new(game, None, 0, Vec::new()),
            script,
            current: None,
            speed: SPEEDS.iter().position(|&s| s == view.speed).unwrap_or(0),
            paused: false,
            finished: false,
            quit_when_finished: false,
            label,
            bot,
            json: view.json,
        }
    }

    async fn run(mut self) {
        if cfg!(feature = "audio") {
            self.app.set_sounds(Sounds::load().await);
        }
        prevent_quit();
        loop {
            if self.keys() || is_quit_requested() {
                // Quit early: the summary of the rounds played so far.
                if !self.finished {
                    let summed = self.finish();
                    fail_on(summed);
                }
                break;
            }
            let played = self.frame(get_frame_time());
            fail_on(played);
            if self.finished && self.quit_when_finished {
                break;
            }
            self.app.set_caption(Some(self.caption()));
            let layout = self.app.layout();
            self.app.draw(&layout);
            next_frame().await;
        }
        std::process::exit(0);
    }

    /// Reads the viewer's keys; true to quit.
    fn keys(&mut self) -> bool {
        use KeyCode as K;
        let pressed = |keys: &[KeyCode]| keys.iter().any(|&k| is_key_pressed(k));
        if pressed(&[K::Up, K::Right, K::F, K::Equal, K::KpAdd]) {
            self.speed = (self.speed + 1).min(SPEEDS.len() - 1);
        }
        if pressed(&[K::Down, K::Left, K::S, K::Minus, K::KpSubtract]) {
            self.speed = self.speed.saturating_sub(1);
        }
        if pressed(&[K::Space, K::P]) {
            self.paused = !self.paused;
        }
        pressed(&[K::Escape, K::Q])
    }

    fn caption(&self) -> String {
        let state = if self.finished {
            "finished".to_owned()
        } else if self.paused {
            "paused".to_owned()
        } else {
            format!("x{}", SPEEDS[self.speed])
        };
        format!(
            "{} - {state} - Up/Down speed, Space pause, Esc quit",
            self.label
        )
    }

    /// Plays `dt` seconds of the script; prints the rounds that end and, when the script
    /// is over, the summary.
    fn frame(&mut self, dt: f32) -> Result<(), Failure> {
        if self.paused {
            return Ok(());
        }
        if self.finished {
            self.app.tick(dt);
            return Ok(());
        }
        self.app.set_speed(SPEEDS[self.speed]);
        loop {
            let (m, wait) = match self.current {
                Some(current) => current,
                None => match self.script.next(self.app.game())? {
                    Some(m) => self.start(m),
                    None => return self.finish(),
                },
            };
            let rounds = self.app.game().state().totals().rounds;
            let done = self.act(m, wait, dt);
            self.print_round(rounds)?;
            if !done {
                return Ok(());
            }
            self.current = None;
        }
    }

    fn start(&mut self, m: Move) -> (Move, f32) {
        let wait = match m {
            Move::Shoot(aim) => {
                self.app.show_aim(aim);
                AIM_SECONDS
            }
            Move::Restart => GAME_OVER_SECONDS,
            Move::PlayTo(_) | Move::PlayOut | Move::Recall => 0.0,
        };
        self.current = Some((m, wait));
        (m, wait)
    }

    /// Plays the move `m` this frame; true when it is done.
    fn act(&mut self, m: Move, wait: f32, dt: f32) -> bool {
        let game = self.app.game();
        let live = game.phase() == Phase::Volley;
        let clock = game.volley_time().unwrap_or(0.0);
        if wait > 0.0 {
            self.app.tick(dt);
            self.current = Some((m, wait - dt * SPEEDS[self.speed] as f32));
            return false;
        }
        match m {
            Move::Shoot(aim) => self.app.apply(Action::Shoot(aim)),
            Move::Recall => self.app.apply(Action::Recall),
            Move::Restart => self.app.apply(Action::RestartCheckpoint),
            Move::PlayTo(at) if live && clock < at => {
                self.app.tick_until(dt, at);
                let game = self.app.game();
                return game.phase() != Phase::Volley || game.volley_time() >= Some(at);
            }
            Move::PlayOut if live => {
                self.app.tick(dt);
                return self.app.game().phase() != Phase::Volley;
            }
            Move::PlayTo(_) | Move::PlayOut => {}
        }
        true
    }

    /// Prints the round just resolved, if one was since `rounds` were counted.
    fn print_round(&self, rounds: u32) -> Result<(), Failure> {
        let game = self.app.game();
        let now = game.state().totals().rounds;
        match game.last_report() {
            Some(report) if now > rounds => print(&[round_line(now, report, game)]),
            _ => Ok(()),
        }
    }

    fn finish(&mut self) -> Result<(), Failure> {
        self.finished = true;
        let game = self.app.game();
        let summary = Summary::of(game, game.seed(), self.bot);
        let mut lines = vec![summary.line()];
        if self.json {
            lines.push(summary.json());
        }
        print(&lines)
    }
}

/// Exits with a message on a failure (standard output gone away is not one).
fn fail_on(result: Result<(), Failure>) {
    match result {
        Err(e) if e.is_broken_pipe() => std::process::exit(0),
        Err(e) => {
            eprintln!("onemorebrick: {e}");
            std::process::exit(1);
        }
        Ok(()) => {}
    }
}

/// Writes `lines` to standard output at once (a reader sees each round as it ends).
fn print(lines: &[String]) -> Result<(), Failure> {
    let mut out = io::stdout().lock();
    for line in lines {
        writeln!(out, "{line}")?;
    }
    out.flush()?;
    Ok(())
}
