//! An aim: the direction of a volley, kept exactly as given.

use exact2d::DVec2;
use serde::{Deserialize, Serialize};

use crate::GameError;

/// The direction a volley leaves in, as the vector the player (or a bot) gave. It is never
/// converted to an angle and back: replays and saves store these two doubles (JSON keeps
/// doubles exactly with `float_roundtrip`), so the volley is rebuilt from the same bits.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Aim {
    /// Horizontal component (any sign).
    pub dx: f64,
    /// Vertical component (upward, so positive).
    pub dy: f64,
}

impl Aim {
    /// An aim from a direction vector (any positive length).
    #[must_use]
    pub fn new(dx: f64, dy: f64) -> Self {
        Self { dx, dy }
    }

    /// Checks the aim against the minimum elevation (as a tangent, see
    /// [`Config::min_elevation_tan`](crate::Config::min_elevation_tan)). An aim flatter than
    /// that is *rejected*, not clamped: a silent change would make the preview lie. A front
    /// end clamps before calling, with [`Aim::clamped`].
    ///
    /// # Errors
    /// [`GameError::InvalidAim`] if a component is not finite, the vector is zero or points
    /// downward, or `dy < min_elevation_tan * |dx|`.
    pub fn validate(&self, min_elevation_tan: f64) -> Result<(), GameError> {
        if !(self.dx.is_finite() && self.dy.is_finite()) {
            return Err(GameError::InvalidAim("components must be finite"));
        }
        if !(self.dy > 0.0) {
            return Err(GameError::InvalidAim("the aim must point upward"));
        }
        if self.dy < min_elevation_tan * self.dx.abs() {
            return Err(GameError::InvalidAim("flatter than the minimum elevation"));
        }
        Ok(())
    }

    /// The nearest valid aim: upward, and no flatter than the minimum elevation (a flatter
    /// aim gets `dy = min_elevation_tan * |dx|`, keeping `dx`). `None` if not finite or zero.
    #[must_use]
    pub fn clamped(self, min_elevation_tan: f64) -> Option<Aim> {
        if !(self.dx.is_finite() && self.dy.is_finite()) || (self.dx == 0.0 && self.dy == 0.0) {
            return None;
        }
        let floor = min_elevation_tan * self.dx.abs();
        let aim = Aim::new(self.dx, self.dy.max(floor));
        if aim.dy > 0.0 {
            Some(aim)
        } else {
            Some(Aim::new(0.0, 1.0))
        }
    }

    /// The launch velocity at `speed`: the direction scaled to that length.
    #[must_use]
    pub fn velocity(&self, speed: f64) -> DVec2 {
        let d = DVec2::new(self.dx, self.dy);
        d * (speed / d.length())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn flat_downward_and_non_finite_aims_are_rejected() {
        let t = 0.15;
        assert!(Aim::new(1.0, 0.149).validate(t).is_err());
        assert!(Aim::new(-1.0, 0.15).validate(t).is_ok());
        assert!(Aim::new(0.0, -1.0).validate(t).is_err());
        assert!(Aim::new(0.0, 0.0).validate(t).is_err());
        assert!(Aim::new(f64::NAN, 1.0).validate(t).is_err());
        assert!(Aim::new(1.0, f64::INFINITY).validate(t).is_err());
    }

    #[test]
    fn clamping_lifts_a_flat_aim_to_the_minimum_elevation() {
        let aim = Aim::new(-2.0, -5.0).clamped(0.15).expect("finite");
        assert_eq!(aim, Aim::new(-2.0, 0.3));
        assert!(aim.validate(0.15).is_ok());
        assert_eq!(Aim::new(0.0, -1.0).clamped(0.15), Some(Aim::new(0.0, 1.0)));
        assert_eq!(Aim::new(0.0, 0.0).clamped(0.15), None);
    }

    #[test]
    fn velocity_has_the_requested_speed() {
        let v = Aim::new(3.0, 4.0).velocity(10.0);
        assert_eq!(v, DVec2::new(6.0, 8.0));
    }
}
