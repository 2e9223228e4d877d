//! Game settings: board size, ball size and speed, volley spacing, anti-stall limits.

use serde::{Deserialize, Serialize};

use crate::GameError;

/// Every tunable number of the rules. Units are grid cells and simulated seconds.
///
/// The defaults are the thesis version's: 7 x 9 cells, ball radius 0.15, balls 1.5 diameters
/// apart. The speed, 10 cells per second, crosses the board's height in under a second, which
/// keeps a volley of a hundred balls under ten seconds of play.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Config {
    /// Columns (at least 3: a new row needs two pick-up cells and one brick).
    pub columns: u32,
    /// Rows, the launcher's row (row 0) included (at least 3).
    pub rows: u32,
    /// Radius of a launched ball.
    pub ball_radius: f64,
    /// Speed of a launched ball, cells per second.
    pub ball_speed: f64,
    /// Distance between consecutive balls of a volley, in ball diameters.
    pub spacing_diameters: f64,
    /// The smallest elevation of an aim and of a ball after a bounce, as a tangent
    /// (`|vy| / |vx|`): 0.15 is about 8.5 degrees. Stored as a tangent so that no rule needs
    /// `sin` or `cos`, whose last bits differ between platforms' maths libraries.
    pub min_elevation_tan: f64,
    /// Anti-stall period: simulated seconds a ball may fly without damaging a brick before it
    /// is steered down.
    pub stall_seconds: f64,
    /// How many times a ball is steered down; at the next period without damage it is recalled.
    pub stall_steers: u32,
    /// `Some(x)`: every volley leaves from `x`; `None`: the first ball back sets the next launch.
    pub fixed_launcher: Option<f64>,
    /// Radius of a round obstacle, centred in its cell.
    pub obstacle_radius: f64,
    /// Radius of a pick-up's sensor circle, centred in its cell.
    pub pickup_radius: f64,
    /// Radius of a ball after the "bigger" pick-up.
    pub big_radius: f64,
    /// Radius of a ball after the "smaller" pick-up.
    pub small_radius: f64,
    /// Speed factor of the "boost" pick-up (applied once per ball).
    pub boost_factor: f64,
}

impl Default for Config {
    fn default() -> Self {
        Self {
            columns: 7,
            rows: 9,
            ball_radius: 0.15,
            ball_speed: 10.0,
            spacing_diameters: 1.5,
            min_elevation_tan: 0.15,
            stall_seconds: 6.0,
            stall_steers: 2,
            fixed_launcher: None,
            obstacle_radius: 0.42,
            pickup_radius: 0.3,
            big_radius: 0.225,
            small_radius: 0.1,
            boost_factor: 1.5,
        }
    }
}

impl Config {
    /// Board width in cells.
    #[must_use]
    pub fn width(&self) -> f64 {
        f64::from(self.columns)
    }

    /// Board height in cells.
    #[must_use]
    pub fn height(&self) -> f64 {
        f64::from(self.rows)
    }

    /// Simulated seconds between two launches of a volley.
    #[must_use]
    pub fn launch_interval(&self) -> f64 {
        self.spacing_diameters * 2.0 * self.ball_radius / self.ball_speed
    }

    /// Checks every setting; the game refuses a configuration that fails.
    ///
    /// # Errors
    /// [`GameError::InvalidConfig`] naming the first bad setting.
    pub fn validate(&self) -> Result<(), GameError> {
        let bad = |what: &str| Err(GameError::InvalidConfig(what.to_owned()));
        if !(3..=64).contains(&self.columns) || !(3..=64).contains(&self.rows) {
            return bad("columns and rows must be in 3..=64");
        }
        // Every ball size must fit in a cell with room to pass between two obstacles.
        let radii = [self.ball_radius, self.big_radius, self.small_radius];
        if radii.iter().any(|&r| !(r > 0.0 && r < 0.25)) {
            return bad("ball radii must be in (0, 0.25)");
        }
        if !(self.obstacle_radius > 0.0 && self.obstacle_radius <= 0.45) {
            return bad("obstacle_radius must be in (0, 0.45]");
        }
        if !(self.pickup_radius > 0.0 && self.pickup_radius <= 0.5) {
            return bad("pickup_radius must be in (0, 0.5]");
        }
        self.validate_motion()?;
        if let Some(x) = self.fixed_launcher {
            let r = self.ball_radius;
            if !(x >= r && x <= self.width() - r) {
                return bad("fixed_launcher must keep the ball inside the board");
            }
        }
        Ok(())
    }

    fn validate_motion(&self) -> Result<(), GameError> {
        let bad = |what: &str| Err(GameError::InvalidConfig(what.to_owned()));
        if !(self.ball_speed > 0.0 && self.ball_speed <= 1e4) {
            return bad("ball_speed must be in (0, 1e4]");
        }
        if !(self.spacing_diameters > 0.0 && self.spacing_diameters <= 100.0) {
            return bad("spacing_diameters must be in (0, 100]");
        }
        if !(self.min_elevation_tan > 0.0 && self.min_elevation_tan <= 10.0) {
            return bad("min_elevation_tan must be in (0, 10]");
        }
        if !(self.stall_seconds > 0.0 && self.stall_seconds <= 1e4) {
            return bad("stall_seconds must be in (0, 1e4]");
        }
        if self.stall_steers > 100 {
            return bad("stall_steers must be at most 100");
        }
        if !(self.boost_factor >= 1.0 && self.boost_factor <= 10.0) {
            return bad("boost_factor must be in [1, 10]");
        }
        Ok(())
    }
}
