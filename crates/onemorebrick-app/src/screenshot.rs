//! `onemorebrick screenshot`: a bot plays some rounds headlessly (or a save is loaded), then
//! one real frame is rendered, with the aim preview showing, and written as a PNG.

use std::fs::File;
use std::io::BufWriter;
use std::path::{Path, PathBuf};

use clap::{Args, ValueEnum};
use macroquad::texture::get_screen_data;
use macroquad::window::next_frame;
use onemorebrick::{Aim, Phase, load_game};

use crate::app::App;
use crate::bots::{BotArgs, play_rounds};
use crate::input::{Action, View};

/// Arguments of `onemorebrick screenshot`.
#[derive(Args, Debug)]
#[command(
    after_help = "Standard output: one line, \"wrote PATH (WIDTHxHEIGHT)\". The PNG's text chunk \"board\" holds the board's rectangle in the frame, \"x y w h\" in pixels (top-left origin)."
)]
pub struct ScreenshotArgs {
    /// Seed of the game the bot plays.
    #[arg(long, default_value_t = 7, value_parser = crate::parse_seed, allow_negative_numbers = true)]
    pub seed: u64,
    /// Rounds the bot plays first (it stops early at a game over).
    #[arg(long, default_value_t = 10, value_parser = clap::value_parser!(u32).range(0..=100_000), allow_negative_numbers = true)]
    pub rounds: u32,
    /// The bot (the same options and defaults as `sim`); its next aim is the one shown.
    #[command(flatten)]
    pub bot: BotArgs,
    /// The PNG to write (with a text chunk "board" = "x y w h": the board's rectangle).
    #[arg(long)]
    pub out: PathBuf,
    /// Render this saved game instead of a bot's game.
    #[arg(long)]
    pub state: Option<PathBuf>,
    /// Shoot the aim shown and render the volley this many seconds of play later (60
    /// frames a second, effects included).
    #[arg(long, value_parser = parse_volley, allow_negative_numbers = true)]
    pub volley: Option<f64>,
    /// Window width in pixels (64 to 8192).
    #[arg(long, default_value_t = 540, value_parser = clap::value_parser!(u32).range(64..=8192), allow_negative_numbers = true)]
    pub width: u32,
    /// Window height in pixels (64 to 8192).
    #[arg(long, default_value_t = 860, value_parser = clap::value_parser!(u32).range(64..=8192), allow_negative_numbers = true)]
    pub height: u32,
    /// The screen to render: the board as it is, or a menu over it (game-over needs a game
    /// that is over: a --state file).
    #[arg(long, value_enum, default_value_t = ShotView::Play)]
    pub view: ShotView,
}

/// The screens `screenshot --view` renders.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum ShotView {
    /// The board as the game is: aiming, in a volley, or over (with the game-over card).
    Play,
    /// The pause menu.
    Pause,
    /// The settings.
    Settings,
    /// The help screen (every pick-up).
    Help,
    /// The game-over card.
    GameOver,
    /// "New game?"
    Confirm,
}

impl ShotView {
    /// The view to open, if not the game's own.
    fn view(self) -> Option<View> {
        match self {
            ShotView::Play => None,
            ShotView::Pause => Some(View::Paused),
            ShotView::Settings => Some(View::Settings),
            ShotView::Help => Some(View::Help),
            ShotView::GameOver => Some(View::GameOver),
            ShotView::Confirm => Some(View::Confirm),
        }
    }
}

/// Prepares the game (before any window opens, so bad input fails fast), then renders.
pub fn run(args: &ScreenshotArgs) -> Result<(), String> {
    let (mut game, mut bot) = match &args.state {
        Some(path) => {
            let game = load_game(path).map_err(|e| e.to_string())?;
            let bot = args.bot.make(game.seed());
            (game, bot)
        }
        None => play_rounds(&args.bot, args.seed, args.rounds).map_err(|e| e.to_string())?,
    };
    let aim = if game.phase() == Phase::Aiming {
        Some(bot.choose(&game).map_err(|e| e.to_string())?)
    } else {
        None
    };
    if game.phase() == Phase::Volley && game.balls().is_empty() {
        // A volley saved at its very start: show its first balls in flight.
        let t = game.volley_time().unwrap_or(0.0) + 0.5;
        game.advance_to(t).map_err(|e| e.to_string())?;
    }
    let mut app = App::new(game, None, 0, Vec::new());
    if let Some(aim) = aim {
        app.show_aim(aim);
    }
    if let Some(seconds) = args.volley {
        play_volley(&mut app, aim, seconds)?;
    }
    if let Some(view) = args.view.view() {
        if let Err(e) = app.set_view(view) {
            // A usage error, as clap reports them (exit code 2), before any window opens.
            let name = args
                .view
                .to_possible_value()
                .map(|v| v.get_name().to_owned());
            let message = format!(
                "--view {}: the game is {e}; a game that is over comes from --state\n",
                name.unwrap_or_default()
            );
            clap::Error::raw(clap::error::ErrorKind::ValueValidation, message).exit();
        }
    }
    crate::play::check_display()?;
    let out = args.out.clone();
    let conf = crate::play::conf(
        "One More Brick screenshot",
        args.width as i32,
        args.height as i32,
        false,
    );
    macroquad::Window::from_config(conf, render(app, out));
    Ok(())
}

/// Shoots `aim` and plays `seconds` of frames.
/// `--volley`: seconds in `(0, 600]`.
fn parse_volley(text: &str) -> Result<f64, String> {
    match text.trim().parse::<f64>() {
        Ok(s) if s > 0.0 && s <= 600.0 => Ok(s),
        _ => Err("must be more than 0 and at most 600 seconds".to_owned()),
    }
}

fn play_volley(app: &mut App, aim: Option<Aim>, seconds: f64) -> Result<(), String> {
    let aim = aim.ok_or("--volley needs a game that is aiming (not mid-volley or over)")?;
    app.apply(Action::Shoot(aim));
    for _ in 0..(seconds * 60.0).round() as u32 {
        app.tick(1.0 / 60.0);
    }
    Ok(())
}

async fn render(mut app: App, out: PathBuf) {
    // A few frames so the window has its final size before the one that is kept.
    for _ in 0..3 {
        let layout = app.layout();
        app.draw(&layout);
        next_frame().await;
    }
    let layout = app.layout();
    app.draw(&layout);
    let image = get_screen_data();
    let regions: Vec<(String, String)> = app
        .regions(&layout)
        .into_iter()
        .map(|(name, r)| (name, format!("{} {} {} {}", r.x, r.y, r.w, r.h)))
        .collect();
    let (w, h) = (image.width as u32, image.height as u32);
    let result = write_png(&out, w, h, &image.bytes, &regions);
    match result {
        Ok(()) => {
            println!("wrote {} ({}x{})", out.display(), image.width, image.height);
            std::process::exit(0);
        }
        Err(e) => {
            eprintln!("onemorebrick: {e}");
            std::process::exit(1);
        }
    }
}

/// Writes RGBA pixels stored bottom row first (as OpenGL reads them) as a PNG, top row
/// first, with `text` as `tEXt` chunks (keyword, text): the screenshot names where things
/// are on it (`board`, `card`, ... as `x y width height` in pixels).
pub fn write_png(
    path: &Path,
    width: u32,
    height: u32,
    rgba: &[u8],
    text: &[(String, String)],
) -> Result<(), String> {
    let fail =
        |e: &dyn std::fmt::Display| format!("{}: could not write the PNG: {e}", path.display());
    let row = width as usize * 4;
    if rgba.len() != row * height as usize {
        return Err(fail(&"the frame has the wrong size"));
    }
    let flipped: Vec<u8> = rgba.chunks_exact(row).rev().flatten().copied().collect();
    let file = File::create(path).map_err(|e| fail(&e))?;
    let mut encoder = png::Encoder::new(BufWriter::new(file), width, height);
    encoder.set_color(png::ColorType::Rgba);
    encoder.set_depth(png::BitDepth::Eight);
    for (keyword, value) in text {
        encoder
            .add_text_chunk(keyword.clone(), value.clone())
            .map_err(|e| fail(&e))?;
    }
    let mut writer = encoder.write_header().map_err(|e| fail(&e))?;
    writer.write_image_data(&flipped).map_err(|e| fail(&e))?;
    writer.finish().map_err(|e| fail(&e))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_png_is_written_top_row_first() {
        let path = std::env::temp_dir().join(format!("omb-flip-{}.png", std::process::id()));
        // Two rows: the bottom one (first in memory) red, the top one blue.
        let pixels = [255, 0, 0, 255, 0, 0, 255, 255];
        let text = [("card".to_owned(), "1 2 3 4".to_owned())];
        write_png(&path, 1, 2, &pixels, &text).unwrap();
        let decoder = png::Decoder::new(File::open(&path).unwrap());
        let mut reader = decoder.read_info().unwrap();
        let chunks = &reader.info().uncompressed_latin1_text;
        assert_eq!(
            (chunks[0].keyword.as_str(), chunks[0].text.as_str()),
            ("card", "1 2 3 4")
        );
        let mut buf = vec![0; reader.output_buffer_size()];
        reader.next_frame(&mut buf).unwrap();
        assert_eq!(&buf[..8], &[0, 0, 255, 255, 255, 0, 0, 255]);
        std::fs::remove_file(path).unwrap();
    }

    #[test]
    fn a_wrong_sized_frame_is_an_error() {
        let path = std::env::temp_dir().join("omb-never-written.png");
        assert!(write_png(&path, 2, 2, &[0; 8], &[]).is_err());
    }
}
