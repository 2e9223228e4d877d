//! The rules of the scene format, checked in a fixed order so the error reported is always
//! the same one.

use super::overlap::first_overlap;
use super::{Scene, SceneBall, SceneCircle, SceneError, SceneSegment, SceneTable};
use crate::{DVec2, Segment};

impl Scene {
    /// Checks every rule of the format and reports the first violation.
    ///
    /// The rules: every number is finite; radii and masses are > 0; restitutions are in
    /// `[0, 1]`, tangential restitutions in `[-1, 1]`, frictions and rolling resistances `>= 0`,
    /// inertias in `(0, 1]`; segments have distinct end points; ball ids are unique; a ball may touch but
    /// not overlap (deeper than [`OVERLAP_TOLERANCE`](crate::OVERLAP_TOLERANCE) of the
    /// contact distance) a static shape, or another ball if `ball_ball` is set.
    ///
    /// "First" is, in order: the numbers, item by item in file order (`gravity`, `segments`,
    /// `circles`, `balls`; within a ball: `pos`, `vel`, `radius`, `mass`, `restitution`, `spin`,
    /// `roll`, `inertia`, `friction`, `tangential_restitution`, `rolling_resistance`; a
    /// `table` is checked after `gravity`, and a ball's `roll` without one after its numbers);
    /// then
    /// the first ball whose id an earlier ball has; then the first ball that overlaps a static
    /// shape or an earlier ball (naming the first segment, else circle, else the earliest
    /// ball), which is what [`World::add_ball`](crate::World::add_ball) would refuse.
    ///
    /// Runs in O(n log n) for n items of similar sizes (no test of all pairs).
    ///
    /// # Errors
    /// The first violation, naming the item.
    pub fn validate(&self) -> Result<(), SceneError> {
        check_pair(self.gravity, || "gravity".to_owned())?;
        if let Some(table) = &self.table {
            check_table(table, self.gravity)?;
        }
        for (index, segment) in self.segments.iter().enumerate() {
            check_segment(index, segment)?;
        }
        for (index, circle) in self.circles.iter().enumerate() {
            check_circle(index, circle)?;
        }
        for (index, ball) in self.balls.iter().enumerate() {
            check_ball(index, ball)?;
            if self.table.is_none() && ball.roll != [0.0, 0.0] {
                return Err(SceneError::OutOfRange {
                    path: format!("balls[{index}].roll"),
                    range: "[0, 0] without a table",
                });
            }
        }
        check_unique_ids(&self.balls)?;
        if let Some(size) = self.periodic {
            check_periodic(self, size)?;
        }
        match first_overlap(self) {
            Some((ball, other)) => Err(SceneError::Overlap { ball, other }),
            None => Ok(()),
        }
    }
}

/// A periodic box (`World::set_periodic`): its sides, what it excludes, every ball inside it
/// and small enough, every collider clear of its edges by more than the largest radius.
fn check_periodic(scene: &Scene, size: [f64; 2]) -> Result<(), SceneError> {
    check_pair(size, || "periodic".to_owned())?;
    if !(size[0] > 0.0 && size[1] > 0.0) {
        return Err(SceneError::OutOfRange {
            path: "periodic".to_owned(),
            range: "> 0 on both sides",
        });
    }
    if scene.gravity != [0.0, 0.0] {
        return Err(SceneError::OutOfRange {
            path: "gravity".to_owned(),
            range: "[0, 0] in a periodic box",
        });
    }
    if scene.table.is_some() {
        return Err(SceneError::OutOfRange {
            path: "table".to_owned(),
            range: "absent in a periodic box",
        });
    }
    let largest = crate::broad::largest_periodic_radius(DVec2::from(size));
    let mut widest: f64 = 0.0;
    for (index, ball) in scene.balls.iter().enumerate() {
        let [x, y] = ball.pos;
        if !(x >= 0.0 && y >= 0.0 && x < size[0] && y < size[1]) {
            return Err(SceneError::OutOfRange {
                path: format!("balls[{index}].pos"),
                range: "inside the periodic box [0, Lx) x [0, Ly)",
            });
        }
        if ball.radius > largest {
            return Err(SceneError::OutOfRange {
                path: format!("balls[{index}].radius"),
                range: "at most min(Lx, Ly) / 6.6 in a periodic box",
            });
        }
        widest = widest.max(ball.radius);
    }
    let clear = |min: [f64; 2], max: [f64; 2]| {
        min[0]
            .min(min[1])
            .min(size[0] - max[0])
            .min(size[1] - max[1])
            > widest
    };
    const RANGE: &str = "clear of the periodic box's edges by more than the largest ball's radius";
    for (index, s) in scene.segments.iter().enumerate() {
        let min = [s.a[0].min(s.b[0]), s.a[1].min(s.b[1])];
        let max = [s.a[0].max(s.b[0]), s.a[1].max(s.b[1])];
        if !clear(min, max) {
            return Err(SceneError::OutOfRange {
                path: format!("segments[{index}]"),
                range: RANGE,
            });
        }
    }
    for (index, c) in scene.circles.iter().enumerate() {
        let [x, y] = c.center;
        if !clear([x - c.radius, y - c.radius], [x + c.radius, y + c.radius]) {
            return Err(SceneError::OutOfRange {
                path: format!("circles[{index}]"),
                range: RANGE,
            });
        }
    }
    Ok(())
}

/// The table's values (`gravity > 0`, frictions `>= 0`), then the world's gravity, which
/// must be `[0, 0]` with a table.
fn check_table(table: &SceneTable, gravity: [f64; 2]) -> Result<(), SceneError> {
    let key = |key: &str| format!("table.{key}");
    check_range(table.gravity, "> 0", |x| x > 0.0, || key("gravity"))?;
    let frictions = [
        ("sliding_friction", table.sliding_friction),
        ("rolling_friction", table.rolling_friction),
        ("spinning_friction", table.spinning_friction),
    ];
    for (name, x) in frictions {
        check_range(x, ">= 0", |x| x >= 0.0, || key(name))?;
    }
    if gravity != [0.0, 0.0] {
        return Err(SceneError::OutOfRange {
            path: "gravity".to_owned(),
            range: "[0, 0] with a table (seen from above)",
        });
    }
    Ok(())
}

fn check_segment(index: usize, segment: &SceneSegment) -> Result<(), SceneError> {
    let key = |key: &str| format!("segments[{index}].{key}");
    check_pair(segment.a, || key("a"))?;
    check_pair(segment.b, || key("b"))?;
    check_restitution(segment.restitution, || key("restitution"))?;
    check_roughness(
        [
            segment.friction,
            segment.tangential_restitution,
            segment.rolling_resistance,
        ],
        &key,
    )?;
    let (a, b) = (DVec2::from(segment.a), DVec2::from(segment.b));
    if a == b {
        return Err(SceneError::DegenerateSegment { index });
    }
    // The engine's own test: it also refuses a segment whose squared length overflows or
    // underflows.
    if Segment::new(a, b).is_none() {
        return Err(SceneError::SegmentLengthOutOfRange { index });
    }
    Ok(())
}

fn check_circle(index: usize, circle: &SceneCircle) -> Result<(), SceneError> {
    let key = |key: &str| format!("circles[{index}].{key}");
    check_pair(circle.center, || key("center"))?;
    check_positive(circle.radius, || key("radius"))?;
    check_restitution(circle.restitution, || key("restitution"))?;
    check_roughness(
        [
            circle.friction,
            circle.tangential_restitution,
            circle.rolling_resistance,
        ],
        &key,
    )
}

fn check_ball(index: usize, ball: &SceneBall) -> Result<(), SceneError> {
    let key = |key: &str| format!("balls[{index}].{key}");
    check_pair(ball.pos, || key("pos"))?;
    check_pair(ball.vel, || key("vel"))?;
    check_positive(ball.radius, || key("radius"))?;
    check_positive(ball.mass, || key("mass"))?;
    check_restitution(ball.restitution, || key("restitution"))?;
    check_finite(ball.spin, || key("spin"))?;
    check_pair(ball.roll, || key("roll"))?;
    check_range(
        ball.inertia,
        "in (0, 1]",
        |x| x > 0.0 && x <= 1.0,
        || key("inertia"),
    )?;
    check_roughness(
        [
            ball.friction,
            ball.tangential_restitution,
            ball.rolling_resistance,
        ],
        &key,
    )
}

/// `friction` (`>= 0`), `tangential_restitution` (`[-1, 1]`) and `rolling_resistance`
/// (`>= 0`), in that order.
fn check_roughness(
    [friction, tangential_restitution, rolling_resistance]: [f64; 3],
    key: &impl Fn(&str) -> String,
) -> Result<(), SceneError> {
    check_range(friction, ">= 0", |x| x >= 0.0, || key("friction"))?;
    check_range(
        tangential_restitution,
        "in [-1, 1]",
        |x| (-1.0..=1.0).contains(&x),
        || key("tangential_restitution"),
    )?;
    check_range(
        rolling_resistance,
        ">= 0",
        |x| x >= 0.0,
        || key("rolling_resistance"),
    )
}

fn check_range(
    x: f64,
    range: &'static str,
    within: impl Fn(f64) -> bool,
    path: impl Fn() -> String,
) -> Result<(), SceneError> {
    check_finite(x, &path)?;
    if within(x) {
        Ok(())
    } else {
        Err(SceneError::OutOfRange {
            path: path(),
            range,
        })
    }
}

/// The first ball (by index) whose id an earlier ball has, found by sorting (id, index).
fn check_unique_ids(balls: &[SceneBall]) -> Result<(), SceneError> {
    let mut order: Vec<usize> = (0..balls.len()).collect();
    order.sort_unstable_by_key(|&i| (balls[i].id, i));
    // In a run of equal ids, the smallest second element of a window is the run's second
    // index, paired with the run's first.
    let duplicate = order
        .windows(2)
        .filter(|w| balls[w[0]].id == balls[w[1]].id)
        .min_by_key(|w| w[1]);
    match duplicate {
        Some(w) => Err(SceneError::DuplicateId {
            index: w[1],
            first: w[0],
            id: balls[w[1]].id,
        }),
        None => Ok(()),
    }
}

/// Paths are built only on failure: validating 10^6 balls formats no string.
fn check_finite(x: f64, path: impl FnOnce() -> String) -> Result<(), SceneError> {
    if x.is_finite() {
        Ok(())
    } else {
        Err(SceneError::NotFinite { path: path() })
    }
}

fn check_pair(v: [f64; 2], path: impl FnOnce() -> String) -> Result<(), SceneError> {
    match v.iter().position(|x| !x.is_finite()) {
        Some(k) => Err(SceneError::NotFinite {
            path: format!("{}[{k}]", path()),
        }),
        None => Ok(()),
    }
}

fn check_positive(x: f64, path: impl Fn() -> String) -> Result<(), SceneError> {
    check_finite(x, &path)?;
    if x > 0.0 {
        Ok(())
    } else {
        Err(SceneError::NotPositive { path: path() })
    }
}

fn check_restitution(x: f64, path: impl Fn() -> String) -> Result<(), SceneError> {
    check_finite(x, &path)?;
    if (0.0..=1.0).contains(&x) {
        Ok(())
    } else {
        Err(SceneError::RestitutionOutOfRange { path: path() })
    }
}
