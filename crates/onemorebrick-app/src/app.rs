//! The play loop's state: the game, what the player is doing (aiming, a menu), effects and
//! saving. Each frame: input -> commands for the rules -> advance the volley clock -> draw.

use macroquad::input::{
    KeyCode, MouseButton, is_key_down, is_mouse_button_pressed, is_mouse_button_released,
    mouse_position,
};
use macroquad::math::Vec2;
use macroquad::shapes::draw_rectangle;
use macroquad::window::{clear_background, screen_height, screen_width};
use onemorebrick::{Aim, DVec2, Game, Phase};

use crate::card::{self, Card, Score};
use crate::draw_board;
use crate::draw_play;
use crate::effects::{
    Effects, broken_at_round_end, broken_bricks, count_up, lasers_touched, raised, taken_out,
};
use crate::help;
use crate::hud;
use crate::input::{
    Action, Hold, KEYS, Presses, TAP_STEP, View, aim_toward, hold_step, key_action, turn, turn_sign,
};
use crate::layout::Layout;
use crate::menus::{self, Context};
use crate::palette;
use crate::sound::{Sounds, cues};
use crate::storage::{Seeds, Settings, Storage, next_seed};
use crate::warning;
use crate::widgets::{Button, hit};

/// Bounces the short preview computes (the first contact and the stub's direction).
const SHORT_BOUNCES: usize = 2;
/// Bounces the long preview shows.
const LONG_BOUNCES: usize = 6;
/// The longest frame step the volley clock takes (a stall of the window is not a jump).
const MAX_FRAME: f32 = 1.0 / 20.0;
/// The longest frame step a held key's clock takes: a slow frame counts as held time (the
/// player's hold is real time), a stall does not swing the aim round.
const MAX_HOLD_FRAME: f32 = 0.25;

/// A menu over the board.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Overlay {
    None,
    Paused,
    Settings,
    Confirm,
    Help,
}

/// The front end's state.
pub struct App {
    game: Game,
    storage: Option<Storage>,
    best: u64,
    notices: Vec<String>,
    overlay: Overlay,
    dragging: bool,
    aim: Option<Aim>,
    key_aim: Aim,
    hold: Option<Hold>,
    /// The subscription to every key event (each press counts), from the first frame.
    key_events: Option<usize>,
    speed: u32,
    speed_shown: bool,
    long_preview: bool,
    preview: Option<(Aim, bool, Vec<DVec2>)>,
    effects: Effects,
    /// The score and the best score as the HUD shows them: counting up to the real ones.
    shown_score: f64,
    shown_best: f64,
    notice_area: Option<macroquad::math::Rect>,
    sounds: Option<Sounds>,
    seeds: Seeds,
    caption: Option<String>,
    quit: bool,
    /// Whether the player has seen the help screen (saved in the settings).
    help_seen: bool,
    /// Where closing the help screen goes back to.
    help_return: Overlay,
    /// Seconds since the window opened: animation only (the warning's pulse, the
    /// celebration), never the rules.
    clock: f32,
}

impl App {
    /// The front end for `game`; saves go to `storage` (none: nothing is saved).
    pub fn new(game: Game, storage: Option<Storage>, best: u64, notices: Vec<String>) -> Self {
        let shown_score = game.state().score() as f64;
        let shown_best = best.max(game.state().best_score()) as f64;
        Self {
            game,
            storage,
            best,
            notices,
            overlay: Overlay::None,
            dragging: false,
            aim: None,
            key_aim: Aim::new(0.0, 1.0),
            hold: None,
            key_events: None,
            speed: 1,
            speed_shown: false,
            long_preview: false,
            preview: None,
            effects: Effects::default(),
            shown_score,
            shown_best,
            notice_area: None,
            sounds: None,
            seeds: Seeds::Os,
            caption: None,
            quit: false,
            help_seen: false,
            help_return: Overlay::None,
            clock: 0.0,
        }
    }

    /// Plays these sounds from now on (they sound with the `audio` feature only).
    pub fn set_sounds(&mut self, sounds: Option<Sounds>) {
        self.sounds = sounds;
    }

    fn play(&self, hits: u64, broken: usize, round_over: bool) {
        if let Some(sounds) = &self.sounds {
            for cue in cues(hits, broken, round_over) {
                sounds.play(cue);
            }
        }
    }

    /// Where the seeds of new games come from (the system's generator unless `--seed`).
    pub fn set_seeds(&mut self, seeds: Seeds) {
        self.seeds = seeds;
    }

    /// Shows `aim` as if the player were aiming (screenshots).
    pub fn show_aim(&mut self, aim: Aim) {
        self.aim = Some(aim);
    }

    /// The game.
    pub fn game(&self) -> &Game {
        &self.game
    }

    /// Sets the speed factor of the volley clock (`watch` and `replay` keep the viewer's).
    pub fn set_speed(&mut self, speed: u32) {
        self.speed = speed;
    }

    /// Shows `caption` under the board instead of the player's hint and buttons (`watch`,
    /// `replay`: nobody plays, so nothing to press).
    pub fn set_caption(&mut self, caption: Option<String>) {
        self.caption = caption;
    }

    /// Whether the player asked to quit.
    pub fn wants_quit(&self) -> bool {
        self.quit
    }

    /// What the player sees.
    pub fn view(&self) -> View {
        match (self.overlay, self.game.phase()) {
            (Overlay::Paused, _) => View::Paused,
            (Overlay::Settings, _) => View::Settings,
            (Overlay::Confirm, _) => View::Confirm,
            (Overlay::Help, _) => View::Help,
            (Overlay::None, Phase::Aiming) => View::Aiming,
            (Overlay::None, Phase::Volley) => View::Volley,
            (Overlay::None, Phase::GameOver) => View::GameOver,
        }
    }

    /// The layout for the window as it is now.
    pub fn layout(&self) -> Layout {
        let board = self.game.board();
        Layout::new(
            screen_width(),
            screen_height(),
            board.columns(),
            board.rows(),
        )
    }

    fn buttons(&self, layout: &Layout) -> Vec<Button> {
        let ctx = Context {
            volley_time: self.game.volley_time(),
            speed: self.speed,
            speed_shown: self.speed_shown,
            long_preview: self.long_preview,
            restart_level: self.game.state().checkpoint().map_or(1, |c| c.level),
        };
        menus::buttons(self.view(), layout, &ctx)
    }

    /// One frame: input, the volley clock moved by `dt` seconds (times the speed), drawing.
    pub fn frame(&mut self, dt: f32) {
        let layout = self.layout();
        let buttons = self.buttons(&layout);
        self.handle_input(&layout, &buttons, dt);
        self.clock += dt;
        self.advance(dt.min(MAX_FRAME), f64::INFINITY);
        self.animate(dt);
        self.draw(&layout);
    }

    /// The view's animations move on by `dt` seconds of frame time: the effects and the
    /// score counting up.
    fn animate(&mut self, dt: f32) {
        self.effects.update(dt);
        let state = self.game.state();
        self.shown_score = count_up(self.shown_score, state.score(), dt);
        let best = self.best.max(state.best_score());
        self.shown_best = count_up(self.shown_best, best, dt);
    }

    fn handle_input(&mut self, layout: &Layout, buttons: &[Button], dt: f32) {
        let presses = self.presses();
        let pointer = Vec2::from(mouse_position());
        if !self.notices.is_empty() {
            let on_panel = self.notice_area.is_some_and(|r| r.contains(pointer));
            if !presses.is_empty() || (is_mouse_button_pressed(MouseButton::Left) && on_panel) {
                self.notices.clear();
                return;
            }
        }
        self.keys(&presses);
        self.keyboard_hold(&presses, dt);
        self.pointer(layout, buttons, pointer);
    }

    /// Carries out the frame's key presses in order: Left and Right turn the keyboard's aim
    /// by a step each (every tap counts, however short, however many in a slow frame), the
    /// others do what they do on the view of the moment (`input::key_action`).
    fn keys(&mut self, presses: &[KeyCode]) {
        for &key in presses.iter().filter(|k| KEYS.contains(k)) {
            let turning = self.view() == View::Aiming && !self.dragging;
            match turn_sign(key) {
                Some(sign) if turning => self.turn_key_aim(sign * TAP_STEP),
                Some(_) => {}
                None => {
                    if let Some(action) = key_action(self.view(), key) {
                        self.apply(action);
                    }
                }
            }
        }
    }

    /// A key held down turns the aim on, faster and faster (`input::hold_step`); the frame's
    /// `presses` restart the hold.
    fn keyboard_hold(&mut self, presses: &[KeyCode], dt: f32) {
        if self.view() != View::Aiming || self.dragging {
            self.hold = None;
            return;
        }
        let down = match (is_key_down(KeyCode::Left), is_key_down(KeyCode::Right)) {
            (true, false) => 1.0,
            (false, true) => -1.0,
            _ => 0.0,
        };
        let again = presses.iter().any(|&k| turn_sign(k) == Some(down));
        let dt = f64::from(dt.min(MAX_HOLD_FRAME));
        let (hold, angle) = hold_step(self.hold, again, down, dt);
        self.hold = hold;
        if angle != 0.0 {
            self.turn_key_aim(angle);
        }
    }

    /// The keys pressed since the last frame, in order (the subscription to the key events
    /// starts at the first frame).
    fn presses(&mut self) -> Vec<KeyCode> {
        use macroquad::input::utils::{register_input_subscriber, repeat_all_miniquad_input};
        let events = *self
            .key_events
            .get_or_insert_with(register_input_subscriber);
        let mut presses = Presses::default();
        repeat_all_miniquad_input(&mut presses, events);
        presses.keys
    }

    fn turn_key_aim(&mut self, radians: f64) {
        let tan = self.game.state().config().min_elevation_tan;
        self.key_aim = turn(self.key_aim, radians, tan);
        self.aim = Some(self.key_aim);
    }

    fn pointer(&mut self, layout: &Layout, buttons: &[Button], p: Vec2) {
        if is_mouse_button_pressed(MouseButton::Left) {
            if let Some(b) = hit(buttons, p) {
                self.apply(b.action);
                return;
            }
            // Anywhere off the buttons: the aim points from the launcher to the pointer.
            self.dragging = self.view() == View::Aiming;
        }
        if !self.dragging {
            return;
        }
        let state = self.game.state();
        let launch = DVec2::new(state.launch_x(), state.config().ball_radius);
        self.aim = aim_toward(launch, layout.to_board(p), state.config().min_elevation_tan);
        if is_mouse_button_released(MouseButton::Left) {
            self.dragging = false;
            if let Some(aim) = self.aim {
                self.apply(Action::Shoot(aim));
            }
        }
    }

    /// Carries out a player's command.
    pub fn apply(&mut self, action: Action) {
        match action {
            Action::Shoot(aim) => self.shoot(aim),
            // The first press shows the keyboard's aim; a shot needs an aim on screen.
            Action::ShootKeyboardAim => match self.aim {
                Some(aim) => self.shoot(aim),
                None => self.aim = Some(self.key_aim),
            },
            Action::SpeedUp => {
                self.speed = menus::next_speed(self.speed);
                self.speed_shown = true;
            }
            Action::Recall => self.recall(),
            Action::Pause => {
                self.dragging = false;
                self.overlay = Overlay::Paused;
            }
            Action::Resume => self.overlay = Overlay::None,
            Action::NewGame => self.overlay = Overlay::Confirm,
            Action::ConfirmNewGame => self.new_game(),
            Action::RestartCheckpoint => self.restart(),
            Action::Settings => self.overlay = Overlay::Settings,
            Action::Help => self.open_help(),
            Action::TogglePreview => {
                self.long_preview = !self.long_preview;
                self.save_settings();
            }
            Action::Back => self.back(),
            Action::Quit => self.quit = true,
        }
    }

    /// The rules recall every ball (and end the round); then, in the view only, the balls
    /// that were in flight fly home to the launcher.
    fn recall(&mut self) {
        let balls = self.game.balls();
        match self.game.recall() {
            Ok(_) => {
                let state = self.game.state();
                let home = DVec2::new(state.launch_x(), state.config().ball_radius);
                self.effects.recall(&balls, home, draw_play::ball_colour);
                self.play(0, 0, true);
                self.round_over();
            }
            Err(e) => self.notice(e.to_string()),
        }
    }

    fn restart(&mut self) {
        match self.game.restart() {
            Ok(()) => {
                self.effects.clear();
                self.save();
            }
            Err(e) => self.notice(e.to_string()),
        }
    }

    /// Shows the help screen; closing it comes back here.
    fn open_help(&mut self) {
        self.dragging = false;
        self.help_return = self.overlay;
        self.overlay = Overlay::Help;
    }

    /// Closes the help screen, and remembers that the player saw it.
    fn close_help(&mut self) {
        self.overlay = self.help_return;
        if !self.help_seen {
            self.help_seen = true;
            self.save_settings();
        }
    }

    /// Leaves a sub-menu: the help screen to where it was opened, to the pause menu, or
    /// from "new game?" on the game-over screen back to it.
    fn back(&mut self) {
        if self.overlay == Overlay::Help {
            return self.close_help();
        }
        let over = self.game.phase() == Phase::GameOver;
        self.overlay = if self.overlay == Overlay::Confirm && over {
            Overlay::None
        } else {
            Overlay::Paused
        };
    }

    fn shoot(&mut self, aim: Aim) {
        match self.game.shoot(aim) {
            Ok(()) => {
                self.speed = 1;
                self.speed_shown = false;
                // The board drawn where the balls will meet it.
                self.effects.slide = None;
                self.aim = None;
                self.preview = None;
                // Saved with the volley: quitting now cannot be used to retry the shot.
                self.save();
            }
            Err(e) => self.notice(e.to_string()),
        }
    }

    fn new_game(&mut self) {
        self.best = self.best.max(self.game.state().best_score());
        let fallback = next_seed(self.game.seed(), self.game.history().len());
        let (seed, trouble) = self.seeds.draw_or(fallback);
        if let Some(text) = trouble {
            self.notice(text);
        }
        let config = self.game.state().config().clone();
        match Game::new(config, seed) {
            Ok(game) => self.game = game,
            Err(e) => return self.notice(e.to_string()),
        }
        self.overlay = Overlay::None;
        self.effects.clear();
        self.aim = None;
        self.save();
    }

    fn round_over(&mut self) {
        self.speed = 1;
        self.speed_shown = false;
        self.effects.flashes.clear();
        self.effects.start_slide();
        self.save();
    }

    /// A frame without input or drawing: the volley clock and the effects move by `dt`
    /// seconds (benchmarks, screenshots of a volley).
    pub fn tick(&mut self, dt: f32) {
        self.tick_until(dt, f64::INFINITY);
    }

    /// As [`tick`](Self::tick), with the volley clock stopped at `limit` (a replay's recall
    /// happens at its own clock).
    pub fn tick_until(&mut self, dt: f32, limit: f64) {
        self.advance(dt.min(MAX_FRAME), limit);
        self.animate(dt);
    }

    /// How many balls are in play.
    pub fn balls_in_flight(&self) -> usize {
        self.game.balls().len()
    }

    /// Moves the volley clock by `dt` seconds of play (times the speed factor), not past
    /// `limit`.
    fn advance(&mut self, dt: f32, limit: f64) {
        if self.overlay != Overlay::None || self.game.phase() != Phase::Volley {
            return;
        }
        let now = self.game.volley_time().unwrap_or(0.0);
        let until = (now + f64::from(dt) * f64::from(self.speed))
            .min(limit)
            .max(now);
        let before = self.game.board().clone();
        let hits_before = self.game.volley_tally().map_or(0, |t| t.hits);
        let hazards_before = self.game.volley_tally().map_or(0, |t| t.hazards);
        let balls_before = self.game.balls();
        match self.game.advance_to(until) {
            Ok(Some(report)) => {
                let broken = broken_at_round_end(&before, self.game.board());
                self.bursts(&before, &broken);
                let hits = report.tally.hits.saturating_sub(hits_before);
                self.play(hits, broken.len(), true);
                self.round_over();
            }
            Ok(None) => {
                let hazards = self.game.volley_tally().map_or(0, |t| t.hazards);
                let radius = self.game.state().config().pickup_radius;
                let balls = self.game.balls();
                let new = hazards.saturating_sub(hazards_before);
                for at in taken_out(&balls_before, &balls, &before, radius, new) {
                    self.effects.take_out(at);
                }
                let broken = self.frame_effects(&before);
                let hits = self.game.volley_tally().map_or(0, |t| t.hits);
                self.play(hits.saturating_sub(hits_before), broken, false);
            }
            Err(e) => self.notice(e.to_string()),
        }
    }

    /// A burst for each of these bricks of `before`.
    fn bursts(&mut self, before: &onemorebrick::Board, broken: &[(usize, onemorebrick::Brick)]) {
        let top = onemorebrick_look::palette::ramp_top(before, self.game.state().level());
        for (index, brick) in broken {
            let colour = palette::brick(brick.hp.max(1), top);
            self.effects.burst(brick, before.origin(*index), colour);
        }
    }

    /// Starts the effects of what changed since `before`; returns how many bricks broke.
    fn frame_effects(&mut self, before: &onemorebrick::Board) -> usize {
        let broken = broken_bricks(before, self.game.board());
        self.bursts(before, &broken);
        let radius = self.game.state().config().pickup_radius;
        for (cell, kind) in lasers_touched(self.game.board(), &self.game.balls(), radius) {
            self.effects.flash(cell, kind);
        }
        broken.len()
    }

    /// Shows `text` to the player (once, however often it comes) until a key or a click.
    pub fn notice(&mut self, text: String) {
        if !self.notices.contains(&text) {
            self.notices.push(text);
        }
    }

    /// The notices shown, and where their panel was drawn last (the web build tells the
    /// page).
    #[cfg(target_arch = "wasm32")]
    pub fn notices(&self) -> (&[String], Option<macroquad::math::Rect>) {
        (&self.notices, self.notice_area)
    }

    /// Starts with these settings; the help screen opens if the player has never seen it.
    pub fn set_settings(&mut self, settings: Settings) {
        self.long_preview = settings.long_preview;
        self.help_seen = settings.help_seen;
        if !self.help_seen && self.overlay == Overlay::None {
            self.open_help();
        }
    }

    fn save_settings(&mut self) {
        let settings = Settings {
            long_preview: self.long_preview,
            help_seen: self.help_seen,
        };
        if let Some(storage) = &self.storage {
            if let Err(e) = storage.save_settings(settings) {
                self.notice(format!("Settings could not be saved: {e}"));
            }
        }
    }

    /// Saves the game and the best score (the notices tell if that failed).
    pub fn save(&mut self) {
        self.best = self.best.max(self.game.state().best_score());
        if let Some(storage) = &self.storage {
            if let Err(e) = storage.save(&self.game, self.best) {
                self.notice(format!("Progress could not be saved: {e}"));
            }
        }
    }

    fn preview_path(&mut self, aim: Aim) -> Option<&[DVec2]> {
        let long = self.long_preview;
        let fresh = matches!(&self.preview, Some((a, l, _)) if *a == aim && *l == long);
        if !fresh {
            let bounces = if long { LONG_BOUNCES } else { SHORT_BOUNCES };
            let path = self.game.aim_preview(aim, bounces).ok()?;
            self.preview = Some((aim, long, path));
        }
        self.preview.as_ref().map(|(_, _, p)| p.as_slice())
    }

    /// Draws the whole frame.
    pub fn draw(&mut self, layout: &Layout) {
        clear_background(palette::BACKGROUND);
        let state = self.game.state();
        let config = state.config().clone();
        self.draw_board(layout, &config);
        // A new best counts up with the score (never shown below it).
        let (score, best) = (self.shown_score as u64, self.shown_best as u64);
        hud::draw_hud(layout, state.level(), score, best.max(score));
        self.effects.draw(layout, self.game.board());
        if self.game.phase() != Phase::GameOver {
            warning::draw(layout, self.game.board(), self.clock);
        }
        self.draw_moving(layout, &config);
        self.draw_controls(layout);
        self.draw_overlay(layout);
        if self.caption.is_none() {
            for b in self.buttons(layout) {
                b.draw(b.contains(Vec2::from(mouse_position())));
            }
        }
        self.notice_area = hud::draw_notices(layout, &self.notices);
    }

    /// The board, raised while it slides down a row (the strip it covers above the board
    /// is cleared again for the HUD, drawn after it).
    fn draw_board(&self, layout: &Layout, config: &onemorebrick::Config) {
        let level = self.game.state().level();
        let offset = self.effects.board_offset();
        if offset == 0.0 {
            return draw_board::draw(layout, self.game.board(), config, level);
        }
        let b = layout.board;
        draw_rectangle(b.x, b.y, b.w, b.h, palette::BOARD);
        draw_board::draw(&raised(layout, offset), self.game.board(), config, level);
        let strip = layout.px(offset);
        draw_rectangle(b.x, b.y - strip, b.w, strip, palette::BACKGROUND);
    }

    fn draw_moving(&mut self, layout: &Layout, config: &onemorebrick::Config) {
        let radius = config.ball_radius;
        let launch_x = self.game.state().launch_x();
        match self.game.phase() {
            Phase::Aiming => {
                if let Some(aim) = self.aim {
                    if let Some(path) = self.preview_path(aim) {
                        let path = path.to_vec();
                        draw_play::draw_preview(layout, &path, self.long_preview, radius);
                    }
                }
                let dx = self.aim.map_or(0.0, |a| a.dx);
                draw_play::draw_launcher(layout, launch_x, radius, self.game.state().balls(), dx);
            }
            Phase::Volley => {
                if let Some(x) = self.game.volley_tally().and_then(|t| t.first_back_x) {
                    draw_play::draw_next_launch(layout, x, radius);
                }
                let waiting = self.game.balls_waiting();
                if waiting > 0 {
                    let dx = self.game.volley_aim().map_or(0.0, |a| a.dx);
                    draw_play::draw_launcher(layout, launch_x, radius, waiting, dx);
                }
                draw_play::draw_balls(layout, &self.game.balls());
            }
            Phase::GameOver => {}
        }
        self.effects.draw_homing(layout);
    }

    fn draw_controls(&self, layout: &Layout) {
        if let Some(caption) = &self.caption {
            return hud::draw_hint(layout, caption);
        }
        match self.view() {
            View::Aiming if self.aim.is_none() => {
                hud::draw_hint(layout, "Drag to aim, release to shoot (or arrows, Space)");
            }
            View::Aiming => {
                hud::draw_hint(layout, "Release to shoot; drag below the ball to cancel")
            }
            View::Volley if self.speed > 1 => {
                hud::draw_hint(layout, &format!("x{}", self.speed));
            }
            _ => {}
        }
    }

    /// The card of the view on screen, if it has one.
    fn card(&self) -> Option<Card> {
        let state = self.game.state();
        let best = self.best.max(state.best_score());
        let card = |title: &str, lines: Vec<String>| Card {
            title: title.to_owned(),
            score: None,
            lines,
        };
        match self.view() {
            View::Paused => Some(card("Paused", self.pause_lines())),
            View::Settings => Some(card("Settings", Vec::new())),
            View::Confirm => Some(card(
                "New game?",
                vec![
                    "This game will be lost;".to_owned(),
                    "the best score is kept.".to_owned(),
                ],
            )),
            View::GameOver => Some(Card {
                score: Some(Score {
                    score: state.score(),
                    best,
                    // A tie with an earlier best counts: the score is the best there is.
                    new_best: state.score() > 0 && state.score() >= best,
                }),
                ..card("Game over", Vec::new())
            }),
            View::Aiming | View::Volley | View::Help => None,
        }
    }

    /// The pause card's lines of information.
    fn pause_lines(&self) -> Vec<String> {
        let state = self.game.state();
        vec![
            format!("Level {}   Score {}", state.level(), state.score()),
            format!("Game seed {}", self.game.seed()),
        ]
    }

    fn draw_overlay(&self, layout: &Layout) {
        if self.view() == View::Help {
            help::draw(layout);
        } else if let Some(card) = self.card() {
            card::draw(layout, &card, self.buttons(layout).len(), self.clock);
        }
    }

    /// Shows `view` (screenshots). A menu opens over the game as it is; the game's own views
    /// (aiming, volley, game over) must be the game's phase.
    ///
    /// # Errors
    /// The game's phase in words ("aiming"), when `view` is a phase it is not in.
    pub fn set_view(&mut self, view: View) -> Result<(), String> {
        self.overlay = match view {
            View::Paused => Overlay::Paused,
            View::Settings => Overlay::Settings,
            View::Confirm => Overlay::Confirm,
            View::Help => Overlay::Help,
            View::Aiming | View::Volley | View::GameOver => Overlay::None,
        };
        self.help_return = Overlay::None;
        let phase = match self.game.phase() {
            Phase::Aiming => "aiming",
            Phase::Volley => "in a volley",
            Phase::GameOver => "over",
        };
        match self.view() {
            shown if shown == view => Ok(()),
            _ => Err(phase.to_owned()),
        }
    }

    /// Named rectangles of what is on screen, for tests reading a screenshot: the board, the
    /// card, and on the help screen each pick-up's row and icon (`help-row-K`, `help-icon-K`,
    /// `K` its place in `PickupKind::ALL`).
    pub fn regions(&self, layout: &Layout) -> Vec<(String, macroquad::math::Rect)> {
        let mut out = vec![("board".to_owned(), layout.board)];
        if self.view() == View::Help {
            out.push(("card".to_owned(), help::card_rect(layout)));
            for (k, row) in help::rows(layout).iter().enumerate() {
                out.push((format!("help-row-{k}"), row.rect));
                out.push((format!("help-icon-{k}"), row.icon));
            }
        } else if let Some(card) = self.card() {
            let buttons = self.buttons(layout).len();
            let rect = card::card_rect(layout, card.score.is_some(), buttons);
            out.push(("card".to_owned(), rect));
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use onemorebrick::{Board, Brick, Cell, Config, GameState, Shape};

    fn temp_dir(name: &str) -> std::path::PathBuf {
        let dir = std::env::temp_dir().join(format!("omb-app-{}-{name}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        dir
    }

    /// Starts the app as `play` does, past the help screen of a first start.
    fn start(dir: &std::path::Path) -> App {
        let mut app = start_fresh(dir);
        if app.view() == View::Help {
            app.apply(Action::Back);
        }
        app
    }

    /// Starts the app as `play` does: whatever the storage holds, or a new game.
    fn start_fresh(dir: &std::path::Path) -> App {
        let storage = Storage::at(dir);
        let loaded = storage.load();
        let game = loaded
            .game
            .unwrap_or_else(|| Game::new(Config::default(), 1).unwrap());
        let mut app = App::new(game, Some(storage), loaded.best, loaded.notices);
        app.set_settings(loaded.settings);
        app.save();
        app
    }

    fn saved(dir: &std::path::Path) -> Game {
        Storage::at(dir).load().game.expect("a saved game")
    }

    #[test]
    fn a_player_shoots_speeds_up_recalls_pauses_quits_and_resumes() {
        let dir = temp_dir("flow");
        let mut app = start(&dir);
        assert_eq!(app.view(), View::Aiming);
        app.apply(Action::Shoot(Aim::new(0.2, 1.0)));
        assert_eq!(app.view(), View::Volley);
        assert_eq!(
            saved(&dir).phase(),
            Phase::Volley,
            "saved as soon as it was shot"
        );
        app.tick(0.05);
        let t = app.game.volley_time().unwrap();
        app.apply(Action::SpeedUp);
        app.tick(0.01);
        assert!((app.game.volley_time().unwrap() - (t + 0.02)).abs() < 1e-6);
        app.apply(Action::Recall);
        assert_eq!(app.view(), View::Aiming);
        assert_eq!(saved(&dir).state().level(), 2);
        app.apply(Action::Pause);
        assert_eq!(app.view(), View::Paused);
        app.apply(Action::Settings);
        app.apply(Action::TogglePreview);
        assert!(app.long_preview);
        assert!(start(&dir).long_preview, "the setting is kept");
        app.apply(Action::Back);
        app.apply(Action::Resume);
        assert_eq!(app.view(), View::Aiming);
        app.apply(Action::ShootKeyboardAim);
        assert_eq!(
            app.view(),
            View::Aiming,
            "the first press only shows the aim"
        );
        assert!(app.aim.is_some());
        app.apply(Action::ShootKeyboardAim);
        assert_eq!(app.view(), View::Volley);
        app.tick(0.05);
        app.apply(Action::Pause);
        let before = app.game.volley_time();
        app.tick(0.05);
        assert_eq!(
            app.game.volley_time(),
            before,
            "paused: the clock stands still"
        );
        app.apply(Action::Quit);
        assert!(app.wants_quit());
        app.save();
        let resumed = start(&dir);
        assert_eq!(resumed.view(), View::Volley);
        assert_eq!(resumed.game.volley_time(), before);
        assert_eq!(resumed.game.balls(), app.game.balls());
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn after_a_game_over_the_player_restarts_and_the_best_score_stays() {
        let dir = temp_dir("over");
        let config = Config::default();
        let mut board = Board::new(config.columns, config.rows);
        let low = Cell::Brick(Brick {
            shape: Shape::Square,
            hp: 9999,
        });
        board.set(0, 1, low).unwrap();
        let state = GameState::custom(config, board, 1, 1, 3).unwrap();
        let mut app = App::new(
            Game::from_state(3, state),
            Some(Storage::at(&dir)),
            0,
            Vec::new(),
        );
        app.apply(Action::Shoot(Aim::new(-0.3, 1.0)));
        app.apply(Action::Recall);
        assert_eq!(app.view(), View::GameOver);
        assert_eq!(saved(&dir).phase(), Phase::GameOver);
        app.apply(Action::NewGame);
        app.apply(Action::Back);
        assert_eq!(app.view(), View::GameOver, "back to the game-over screen");
        app.apply(Action::RestartCheckpoint);
        assert_eq!(app.view(), View::Aiming);
        assert_eq!(saved(&dir).phase(), Phase::Aiming);
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn a_new_game_keeps_the_best_score() {
        let dir = temp_dir("new");
        let mut app = start(&dir);
        let aim = onemorebrick::Bot::choose(&mut onemorebrick::GreedyBot::new(8), &app.game);
        app.apply(Action::Shoot(aim.unwrap()));
        app.game.finish_round().unwrap();
        app.save();
        let best = app.game.state().best_score();
        assert!(best > 0);
        let seed = app.game.seed();
        app.apply(Action::Pause);
        app.apply(Action::NewGame);
        assert_eq!(app.view(), View::Confirm);
        app.apply(Action::Back);
        assert_eq!(
            (app.view(), app.game.seed()),
            (View::Paused, seed),
            "not confirmed"
        );
        app.apply(Action::NewGame);
        app.apply(Action::ConfirmNewGame);
        assert_ne!(app.game.seed(), seed);
        assert_eq!((app.view(), app.game.state().level()), (View::Aiming, 1));
        assert_eq!(start(&dir).best, best, "the best score survives a new game");
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn the_help_shows_once_on_the_first_game_and_opens_from_the_pause_menu() {
        let dir = temp_dir("help");
        let mut app = start_fresh(&dir);
        assert_eq!(app.view(), View::Help, "a first start shows the help");
        app.tick(0.1);
        app.apply(Action::Back);
        assert_eq!(app.view(), View::Aiming, "closed: back to the game");
        assert!(Storage::at(&dir).load().settings.help_seen, "remembered");
        assert_eq!(start_fresh(&dir).view(), View::Aiming, "only once");
        app.apply(Action::Pause);
        app.apply(Action::Help);
        assert_eq!(app.view(), View::Help);
        app.apply(Action::Back);
        assert_eq!(app.view(), View::Paused, "back to the pause menu");
        app.apply(Action::Resume);
        assert_eq!(app.view(), View::Aiming);
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn the_help_stops_the_volley_clock() {
        let dir = temp_dir("help-clock");
        let mut app = start(&dir);
        app.apply(Action::Shoot(Aim::new(0.2, 1.0)));
        app.tick(0.05);
        app.apply(Action::Pause);
        app.apply(Action::Help);
        let before = app.game.volley_time();
        app.tick(0.05);
        assert_eq!(app.game.volley_time(), before);
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn a_damaged_settings_file_shows_the_help_and_loses_no_progress() {
        let dir = temp_dir("bad-settings");
        let mut app = start(&dir);
        app.apply(Action::Shoot(Aim::new(0.2, 1.0)));
        app.apply(Action::Recall);
        std::fs::write(Storage::at(&dir).settings_path(), "help_seen = perhaps\n").unwrap();
        let again = start_fresh(&dir);
        assert_eq!(again.view(), View::Help);
        assert_eq!(again.game.state().level(), 2, "the game is kept");
        assert!(
            dir.join("settings.txt.bad-1").exists(),
            "the bad file is kept aside"
        );
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn cards_show_the_score_and_celebrate_only_a_new_best() {
        let config = Config::default();
        let mut board = Board::new(config.columns, config.rows);
        let low = Cell::Brick(Brick {
            shape: Shape::Square,
            hp: 9999,
        });
        board.set(3, 1, low).unwrap();
        let state = GameState::custom(config, board, 1, 1, 3).unwrap();
        let mut app = App::new(Game::from_state(3, state), None, 0, Vec::new());
        assert_eq!(app.card(), None, "no card while aiming");
        app.apply(Action::Shoot(Aim::new(0.0, 1.0)));
        app.game.finish_round().unwrap();
        let card = app.card().expect("the game-over card");
        let score = card.score.expect("with the score");
        assert!(score.score > 0 && score.new_best, "{score:?}");
        app.best = score.score + 1;
        assert!(
            !app.card().unwrap().score.unwrap().new_best,
            "below the best"
        );
        app.apply(Action::NewGame);
        assert_eq!(app.card().unwrap().title, "New game?");
    }

    #[test]
    fn a_screenshot_opens_menus_but_not_a_phase_the_game_is_not_in() {
        let mut app = App::new(
            Game::new(Config::default(), 1).unwrap(),
            None,
            0,
            Vec::new(),
        );
        assert_eq!(app.set_view(View::GameOver), Err("aiming".to_owned()));
        app.set_view(View::Help).unwrap();
        assert_eq!(app.view(), View::Help);
        let layout = Layout::new(540.0, 860.0, 7, 9);
        let names: Vec<String> = app.regions(&layout).into_iter().map(|(n, _)| n).collect();
        assert!(names.contains(&"card".to_owned()));
        for k in 0..onemorebrick::PickupKind::ALL.len() {
            assert!(names.contains(&format!("help-icon-{k}")), "{names:?}");
        }
        app.set_view(View::Paused).unwrap();
        let regions = app.regions(&layout);
        assert_eq!(regions.len(), 2, "the board and the card");
        assert_eq!(regions[1].1, card::card_rect(&layout, false, 5));
        app.set_view(View::Aiming).unwrap();
        assert_eq!(app.regions(&layout).len(), 1, "no card while aiming");
    }

    #[test]
    fn recalled_balls_fly_home_in_the_view_only() {
        let dir = temp_dir("home");
        let mut app = start(&dir);
        let mut rules = Game::new(Config::default(), app.game.seed()).unwrap();
        let aim = Aim::new(0.1, 1.0);
        app.apply(Action::Shoot(aim));
        rules.shoot(aim).unwrap();
        for _ in 0..20 {
            app.tick(1.0 / 60.0);
        }
        let balls = app.game.balls();
        assert!(!balls.is_empty());
        rules.advance_to(app.game.volley_time().unwrap()).unwrap();
        app.apply(Action::Recall);
        rules.recall().unwrap();
        assert_eq!(
            app.game.history(),
            rules.history(),
            "the rules saw a recall only"
        );
        assert_eq!(app.game.state(), rules.state());
        assert_eq!(saved(&dir).history(), rules.history());
        let home = DVec2::new(rules.state().launch_x(), rules.state().config().ball_radius);
        let starts: Vec<DVec2> = app.effects.homing.iter().map(|h| h.start).collect();
        let was: Vec<DVec2> = balls.iter().map(|b| b.position).collect();
        assert_eq!(starts, was, "each flies from where it was");
        assert!(app.effects.homing.iter().all(|h| h.target == home));
        app.tick(crate::effects::HOMING_SECONDS * 0.5);
        assert!(!app.effects.homing.is_empty(), "on the way home");
        app.tick(crate::effects::HOMING_SECONDS * 0.5);
        assert!(app.effects.homing.is_empty(), "home");
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn a_round_end_slides_the_board_and_counts_the_score_up() {
        let dir = temp_dir("slide");
        let mut app = start(&dir);
        app.apply(Action::Shoot(Aim::new(-0.2, 1.0)));
        assert_eq!(app.effects.board_offset(), 0.0);
        let mut frames = 0;
        while app.view() == View::Volley {
            app.tick(1.0 / 60.0);
            frames += 1;
            assert!(frames < 60 * 60, "the volley ends");
        }
        let score = app.game.state().score();
        assert!(score > 0, "some damage done");
        // A row up, less the one frame the slide has aged.
        assert!(
            app.effects.board_offset() > 0.8,
            "the board starts a row up"
        );
        assert!(app.shown_score < score as f64, "the counter lags behind");
        for _ in 0..120 {
            let before = app.shown_score;
            app.tick(1.0 / 60.0);
            assert!(app.shown_score >= before && app.shown_score <= score as f64);
        }
        assert_eq!(app.shown_score, score as f64, "counted up to the score");
        assert_eq!(
            app.shown_best, score as f64,
            "a new best counted up with it"
        );
        assert_eq!(app.effects.board_offset(), 0.0, "the slide is over");
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn the_speed_button_stays_after_cycling_back_to_x1() {
        let dir = temp_dir("speed");
        let mut app = start(&dir);
        let layout = Layout::new(540.0, 860.0, 7, 9);
        let speed_button = |app: &App| {
            app.buttons(&layout)
                .iter()
                .any(|b| b.action == Action::SpeedUp)
        };
        app.apply(Action::Shoot(Aim::new(0.3, 1.0)));
        app.tick(0.1);
        assert!(!speed_button(&app), "not before 3 s");
        for _ in 0..3 {
            app.apply(Action::SpeedUp);
            assert!(speed_button(&app));
        }
        assert_eq!(app.speed, 1);
        assert!(app.game.volley_time().unwrap() < menus::SPEED_BUTTON_AFTER);
        assert!(speed_button(&app), "still there at x1");
        app.apply(Action::Recall);
        app.apply(Action::Shoot(Aim::new(0.3, 1.0)));
        assert!(!speed_button(&app), "a new volley starts without it");
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn every_key_press_of_a_frame_counts_in_order() {
        use macroquad::input::KeyCode as K;
        let dir = temp_dir("keys");
        let mut app = start(&dir);
        // One slow frame: three taps left, one right, then the shot.
        app.keys(&[K::Left, K::Left, K::Left, K::Right, K::Space]);
        assert_eq!(app.view(), View::Volley, "shot in the same frame");
        let aim = saved(&dir).volley_aim().unwrap();
        let degrees = aim.dy.atan2(aim.dx).to_degrees();
        assert!(
            (degrees - 92.0).abs() < 1e-9,
            "turned before the shot: {degrees}"
        );
        // Taps in a volley do nothing; R recalls.
        app.keys(&[K::Left, K::R]);
        assert_eq!(app.view(), View::Aiming);
        assert_eq!(app.key_aim, aim, "not turned during the volley");
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn commands_out_of_place_are_reported_not_fatal() {
        let dir = temp_dir("wrong");
        let mut app = start(&dir);
        app.apply(Action::Recall);
        app.apply(Action::RestartCheckpoint);
        assert_eq!(app.view(), View::Aiming);
        assert_eq!(app.notices.len(), 2);
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
