//! `onemorebrick.Game` and the bots: the game's rules, driven from Python.

use std::path::Path;

use numpy::ndarray::Array3;
use numpy::{IntoPyArray, PyArray1, PyArray2, PyArray3};
use onemorebrick::bot::aim_at;
use onemorebrick::save::{from_json, to_json};
use onemorebrick::{
    Aim, Bot, Cell, Config, Corner, Game, GameError, GreedyBot, Phase, PickupKind, RandomBot,
    RoundReport, SaveError, Shape,
};
use pyo3::prelude::*;
use pyo3::types::PyDict;

use crate::args::pair;
use crate::errors::{Class, error};
use crate::render;
use crate::world::pairs_array;

/// Cell kind codes of `Game.board()`: 0 empty, 1 square brick, 2 to 5 triangular bricks
/// (open corner top-left, top-right, bottom-left, bottom-right), 6 round obstacle, 7 to 18
/// pick-ups (in the order of `PICKUP_KINDS`).
pub const CELL_KINDS: u32 = 19;

/// The largest side of a frame, in pixels (a 64 MB RGBA frame).
const MAX_FRAME_SIDE: usize = 4096;

/// Pick-up names, in the order of their codes (7 + index).
pub const PICKUP_NAMES: [&str; 12] = [
    "extra_ball",
    "split",
    "hazard",
    "floor_bounce",
    "laser_horizontal",
    "laser_vertical",
    "laser_cross",
    "random_direction",
    "bigger",
    "smaller",
    "boost",
    "shield",
];

/// The code of a cell.
pub fn cell_code(cell: &Cell) -> (i32, i32) {
    match cell {
        Cell::Empty => (0, 0),
        Cell::Brick(b) => {
            let kind = match b.shape {
                Shape::Square => 1,
                Shape::Triangle(Corner::TopLeft) => 2,
                Shape::Triangle(Corner::TopRight) => 3,
                Shape::Triangle(Corner::BottomLeft) => 4,
                Shape::Triangle(Corner::BottomRight) => 5,
            };
            (kind, i32::try_from(b.hp).unwrap_or(i32::MAX))
        }
        Cell::Obstacle => (6, 0),
        Cell::Pickup(p) => {
            let index = PickupKind::ALL
                .iter()
                .position(|k| *k == p.kind)
                .unwrap_or(0);
            (7 + index as i32, 0)
        }
    }
}

/// The Python exception for a game error.
pub fn game_error(e: GameError) -> PyErr {
    let class = match e {
        GameError::InvalidAim(_) => Class::InvalidAim,
        GameError::InvalidConfig(_) => Class::InvalidConfig,
        GameError::WrongPhase { .. } => Class::WrongPhase,
        GameError::TimeBeforeNow { .. } => Class::TimeBeforeNow,
        GameError::InvalidState(_) => Class::Save,
        _ => Class::Game,
    };
    error(class, e.to_string())
}

fn save_error(e: SaveError) -> PyErr {
    match e {
        SaveError::Io { .. } => pyo3::exceptions::PyOSError::new_err(e.to_string()),
        _ => error(Class::Save, e.to_string()),
    }
}

fn phase_name(phase: Phase) -> &'static str {
    match phase {
        Phase::Aiming => "aiming",
        Phase::Volley => "volley",
        Phase::GameOver => "game_over",
    }
}

fn report_dict<'py>(py: Python<'py>, r: &RoundReport) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    d.set_item("level", r.level)?;
    d.set_item("balls", r.balls)?;
    d.set_item("damage", r.tally.damage())?;
    d.set_item("hits", r.tally.hits)?;
    d.set_item("laser_damage", r.tally.laser_damage)?;
    d.set_item("bricks_destroyed", r.tally.bricks_destroyed)?;
    d.set_item("extra_balls", r.tally.extra_balls)?;
    d.set_item("collisions", r.collisions)?;
    d.set_item("end_time", r.tally.end_time)?;
    d.set_item("checkpoint_set", r.checkpoint_set)?;
    d.set_item("game_over", r.game_over)?;
    Ok(d)
}

/// The aim for an action `a` in [-1, 1]: `-1` the flattest legal aim to the left, `0`
/// straight up, `1` the flattest to the right; the elevation grows monotonically (and without
/// trigonometry, so on every platform with the same bits) from the minimum elevation at
/// `|a| = 1` to 90 degrees at `a = 0`.
pub fn aim_for_action(a: f64, min_elevation_tan: f64) -> Option<Aim> {
    if !(-1.0..=1.0).contains(&a) {
        return None;
    }
    aim_at(1.0 - a.abs(), a < 0.0, min_elevation_tan).clamped(min_elevation_tan)
}

/// A game of One More Brick: aim, shoot a volley, and the board moves down a row each round.
///
/// `Game(seed, config=None)`: the same seed and shots give the same game, bit for bit.
/// `config` is a dict of settings (`columns`, `rows`, `ball_radius`, `ball_speed`, ...;
/// see the Rust `Config`), missing keys keeping their defaults.
#[pyclass(module = "onemorebrick", name = "Game")]
pub struct PyGame {
    pub(crate) game: Game,
}

impl PyGame {
    fn config(&self) -> &Config {
        self.game.state().config()
    }

    fn aim(&self, direction: &Bound<'_, PyAny>) -> PyResult<Aim> {
        let d = pair(direction, "direction")?;
        Ok(Aim::new(d.x, d.y))
    }
}

fn parse_config(py: Python<'_>, config: Option<&Bound<'_, PyDict>>) -> PyResult<Config> {
    let Some(config) = config else {
        return Ok(Config::default());
    };
    let mut value = serde_json::to_value(Config::default())
        .map_err(|e| error(Class::Game, format!("internal error: {e}")))?;
    let text: String = py
        .import("json")?
        .call_method1("dumps", (config,))?
        .extract()?;
    let given: serde_json::Value = serde_json::from_str(&text)
        .map_err(|e| error(Class::InvalidConfig, format!("invalid configuration: {e}")))?;
    for (key, v) in given.as_object().into_iter().flatten() {
        if value.get(key).is_none() {
            return Err(error(
                Class::InvalidConfig,
                format!("invalid configuration: unknown setting {key:?}"),
            ));
        }
        value[key] = v.clone();
    }
    serde_json::from_value(value)
        .map_err(|e| error(Class::InvalidConfig, format!("invalid configuration: {e}")))
}

#[pymethods]
impl PyGame {
    #[new]
    #[pyo3(signature = (seed = None, config = None))]
    fn py_new(
        py: Python<'_>,
        seed: Option<&Bound<'_, PyAny>>,
        config: Option<&Bound<'_, PyDict>>,
    ) -> PyResult<Self> {
        let seed = seed.map_or(Ok(0), |s| crate::args::seed(s, "seed"))?;
        let config = parse_config(py, config)?;
        let game = Game::new(config, seed).map_err(game_error)?;
        Ok(Self { game })
    }

    /// The seed the game was created with.
    #[getter]
    fn seed(&self) -> u64 {
        self.game.seed()
    }

    /// `"aiming"`, `"volley"` or `"game_over"`.
    #[getter]
    fn phase(&self) -> &'static str {
        phase_name(self.game.phase())
    }

    /// Whether a brick reached the bottom row.
    #[getter]
    fn game_over(&self) -> bool {
        self.game.phase() == Phase::GameOver
    }

    /// The level (the round number; 1 at the start).
    #[getter]
    fn level(&self) -> u32 {
        self.game.state().level()
    }

    /// The score: hit points taken off bricks so far.
    #[getter]
    fn score(&self) -> u64 {
        self.game.state().score()
    }

    /// The best score of this game (kept across restarts).
    #[getter]
    fn best_score(&self) -> u64 {
        self.game.state().best_score()
    }

    /// The balls the next volley fires.
    #[getter]
    fn balls(&self) -> u32 {
        self.game.state().balls()
    }

    /// The launcher's x (cells from the left wall; the launcher is on the floor line).
    #[getter]
    fn launch_x(&self) -> f64 {
        self.game.state().launch_x()
    }

    /// Board columns.
    #[getter]
    fn columns(&self) -> u32 {
        self.config().columns
    }

    /// Board rows (row 0, the launcher's, at the bottom).
    #[getter]
    fn rows(&self) -> u32 {
        self.config().rows
    }

    /// The minimum elevation of an aim, as a tangent `dy / |dx|`.
    #[getter]
    fn min_elevation_tan(&self) -> f64 {
        self.config().min_elevation_tan
    }

    /// The volley's clock, if a volley is live.
    #[getter]
    fn volley_time(&self) -> Option<f64> {
        self.game.volley_time()
    }

    /// The board now (during a volley, with the damage so far): int32, shape
    /// `(rows, columns, 2)`, `board[row, column] = (kind, hit points)`, row 0 at the bottom.
    /// Kinds: 0 empty, 1 square brick, 2-5 triangles (open corner top-left, top-right,
    /// bottom-left, bottom-right), 6 obstacle, 7-18 pick-ups (`PICKUP_KINDS`).
    fn board<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray3<i32>> {
        let board = self.game.board();
        let (columns, rows) = (board.columns() as usize, board.rows() as usize);
        let mut a = Array3::<i32>::zeros((rows, columns, 2));
        for (i, cell) in board.cells().iter().enumerate() {
            let (column, row) = board.position(i);
            let (kind, hp) = cell_code(cell);
            a[[row as usize, column as usize, 0]] = kind;
            a[[row as usize, column as usize, 1]] = hp;
        }
        a.into_pyarray(py)
    }

    /// The balls in flight: centres (float64, (n, 2)) and radii ((n,)); empty between volleys.
    fn balls_in_flight<'py>(
        &self,
        py: Python<'py>,
    ) -> (Bound<'py, PyArray2<f64>>, Bound<'py, PyArray1<f64>>) {
        let balls = self.game.balls();
        let p: Vec<f64> = balls.iter().flat_map(|b| b.position.to_array()).collect();
        let r: Vec<f64> = balls.iter().map(|b| b.radius).collect();
        (pairs_array(py, p), r.into_pyarray(py))
    }

    /// The aim `(dx, dy)` for an action in [-1, 1] (see `OneMoreBrickEnv`): -1 the flattest
    /// legal aim to the left, 0 straight up, 1 the flattest to the right.
    fn aim_for(&self, action: f64) -> PyResult<(f64, f64)> {
        let aim = aim_for_action(action, self.config().min_elevation_tan).ok_or_else(|| {
            error(
                Class::InvalidAim,
                format!("invalid aim: the action must be in [-1, 1] (got {action})"),
            )
        })?;
        Ok((aim.dx, aim.dy))
    }

    /// Fires a volley of every ball along `direction` `(dx, dy)` (upward, no flatter than the
    /// minimum elevation), from the launcher.
    fn shoot(&mut self, direction: &Bound<'_, PyAny>) -> PyResult<()> {
        let aim = self.aim(direction)?;
        self.game.shoot(aim).map_err(game_error)
    }

    /// Plays the volley to the end at once and returns the round's report (a dict: `level`,
    /// `balls`, `damage`, `hits`, `laser_damage`, `bricks_destroyed`, `extra_balls`,
    /// `collisions`, `end_time`, `checkpoint_set`, `game_over`). Releases the GIL.
    fn finish_round<'py>(&mut self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let game = &mut self.game;
        let report = py
            .allow_threads(|| game.finish_round())
            .map_err(game_error)?;
        report_dict(py, &report)
    }

    /// `shoot(direction)` then `finish_round()`.
    fn play<'py>(
        &mut self,
        py: Python<'py>,
        direction: &Bound<'_, PyAny>,
    ) -> PyResult<Bound<'py, PyDict>> {
        self.shoot(direction)?;
        self.finish_round(py)
    }

    /// Plays the volley until its clock reaches `time` or the round ends; returns the report
    /// if it ended, else `None`.
    fn advance_to<'py>(
        &mut self,
        py: Python<'py>,
        time: f64,
    ) -> PyResult<Option<Bound<'py, PyDict>>> {
        let game = &mut self.game;
        let report = py
            .allow_threads(|| game.advance_to(time))
            .map_err(game_error)?;
        report.map(|r| report_dict(py, &r)).transpose()
    }

    /// Every ball returns at once and the round ends; returns the report.
    fn recall<'py>(&mut self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let report = self.game.recall().map_err(game_error)?;
        report_dict(py, &report)
    }

    /// After a game over: starts again from the last checkpoint.
    fn restart(&mut self) -> PyResult<()> {
        self.game.restart().map_err(game_error)
    }

    /// What shooting along `direction` now would report, played on a copy.
    fn preview<'py>(
        &self,
        py: Python<'py>,
        direction: &Bound<'_, PyAny>,
    ) -> PyResult<Bound<'py, PyDict>> {
        let aim = self.aim(direction)?;
        let (report, _) = self.game.preview(aim).map_err(game_error)?;
        report_dict(py, &report)
    }

    /// The aim preview: the launch point, then the first ball's centre at each of its first
    /// `bounces` bounces (float64, (k, 2)).
    fn aim_preview<'py>(
        &self,
        py: Python<'py>,
        direction: &Bound<'_, PyAny>,
        bounces: i64,
    ) -> PyResult<Bound<'py, PyArray2<f64>>> {
        let bounces = crate::args::count(bounces, "bounces", 1 << 16)?;
        let aim = self.aim(direction)?;
        let points = self.game.aim_preview(aim, bounces).map_err(game_error)?;
        Ok(pairs_array(
            py,
            points.iter().flat_map(|p| p.to_array()).collect(),
        ))
    }

    /// The game as save-file JSON text (mid-volley too).
    fn to_json(&self) -> String {
        to_json(&self.game)
    }

    /// A game from save-file JSON text; `SaveError` if it is not one.
    #[staticmethod]
    fn from_json(text: &str) -> PyResult<Self> {
        let game = from_json(text, Path::new("<text>")).map_err(save_error)?;
        Ok(Self { game })
    }

    /// Saves the game to `path` (atomically: a temporary file, then a rename).
    fn save(&self, path: std::path::PathBuf) -> PyResult<()> {
        onemorebrick::save_game(&self.game, &path).map_err(save_error)
    }

    /// Loads a game saved with `save`; `SaveError` names the file and the problem.
    #[staticmethod]
    fn load(path: std::path::PathBuf) -> PyResult<Self> {
        let game = onemorebrick::load_game(&path).map_err(save_error)?;
        Ok(Self { game })
    }

    /// An RGB frame of the board (uint8, shape `(height, width, 3)`), drawn in software
    /// (tiny-skia) in the game's colours; `cell` pixels per cell (4 to 256).
    #[pyo3(signature = (cell = 32))]
    fn render<'py>(&self, py: Python<'py>, cell: i64) -> PyResult<Bound<'py, PyArray3<u8>>> {
        let cell = crate::args::count_in(cell, "cell", 4, 256)?;
        let side = self.config().columns.max(self.config().rows) as usize;
        if cell * side > MAX_FRAME_SIDE {
            return Err(crate::errors::invalid(format!(
                "cell must be at most {} for a board {side} cells across (got {cell})",
                MAX_FRAME_SIDE / side
            )));
        }
        let frame = render::frame(&self.game, cell as u32)
            .ok_or_else(|| error(Class::Game, "internal error: cannot allocate the frame"))?;
        Ok(frame.into_pyarray(py))
    }

    fn __getstate__(&self) -> String {
        to_json(&self.game)
    }

    fn __setstate__(&mut self, text: &str) -> PyResult<()> {
        self.game = from_json(text, Path::new("<pickle>")).map_err(save_error)?;
        Ok(())
    }

    fn __reduce__<'py>(
        slf: &Bound<'py, Self>,
    ) -> PyResult<(Bound<'py, pyo3::types::PyType>, (u64,), String)> {
        let text = slf.borrow().__getstate__();
        Ok((slf.get_type(), (0,), text))
    }

    fn __repr__(&self) -> String {
        format!(
            "Game(seed={}, level={}, score={}, balls={}, phase={:?})",
            self.game.seed(),
            self.level(),
            self.score(),
            self.balls(),
            self.phase()
        )
    }
}

/// The random bot: a uniformly drawn side and elevation, from its own seeded generator.
#[pyclass(module = "onemorebrick", name = "RandomBot")]
pub struct PyRandomBot {
    bot: RandomBot,
}

#[pymethods]
impl PyRandomBot {
    #[new]
    #[pyo3(signature = (seed = None))]
    fn py_new(seed: Option<&Bound<'_, PyAny>>) -> PyResult<Self> {
        let seed = seed.map_or(Ok(0), |s| crate::args::seed(s, "seed"))?;
        Ok(Self {
            bot: RandomBot::new(seed),
        })
    }

    /// The aim `(dx, dy)` to shoot now.
    fn choose(&mut self, game: &PyGame) -> PyResult<(f64, f64)> {
        let aim = self.bot.choose(&game.game).map_err(game_error)?;
        Ok((aim.dx, aim.dy))
    }
}

/// The greedy bot: tries `candidates` shots with the exact engine and keeps the best.
#[pyclass(module = "onemorebrick", name = "GreedyBot")]
pub struct PyGreedyBot {
    bot: GreedyBot,
}

#[pymethods]
impl PyGreedyBot {
    #[new]
    #[pyo3(signature = (candidates = 32))]
    fn py_new(candidates: i64) -> PyResult<Self> {
        let n = crate::args::count(candidates, "candidates", 4096)?;
        if n == 0 {
            return Err(crate::errors::invalid(
                "candidates must be in [1, 4096] (got 0)",
            ));
        }
        Ok(Self {
            bot: GreedyBot::new(n as u32),
        })
    }

    /// The aim `(dx, dy)` to shoot now (releases the GIL while it simulates).
    fn choose(&mut self, py: Python<'_>, game: &PyGame) -> PyResult<(f64, f64)> {
        let (bot, game) = (&mut self.bot, &game.game);
        let aim = py.allow_threads(|| bot.choose(game)).map_err(game_error)?;
        Ok((aim.dx, aim.dy))
    }
}
