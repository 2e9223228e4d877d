//! Seeded, deterministic benchmark scenes.
//!
//! Every generator returns an [`exact2d::scene::Scene`] that passes [`Scene::validate`], and
//! the same arguments always give the same scene, bit for bit (the random numbers come from
//! [`SplitMix64`], and only `+ - * /` and `sqrt` turn them into coordinates). Lengths are in
//! metres, times in seconds, masses in kilograms; restitutions are 1 (elastic) unless a
//! generator says otherwise.
//!
//! | generator | geometry | balls |
//! | --- | --- | --- |
//! | [`gas`] | square box of side `sqrt(N)` (4 segments) | equal, unit mass, unit speed, colliding |
//! | [`gas_with_large`] | [`gas`]'s box | [`gas`]'s balls, one of them `k` times the radius |
//! | [`brick_board`] | 7 x 9 cells of side 1 above a launch area, closed container | radius 0.1, speed 10, passing through each other |
//! | [`free_balls_in_box`] | 16 x 9 box (4 segments) | radius 0.05 to 0.15, speed 1 to 5, passing through each other |
//! | [`pegs_gravity`] | 10 m wide box, 8 staggered rows of pegs, gravity 9.81 down | radius 0.1, colliding |
//! | [`pile`] | 10 x 30 box, optionally a lattice of pegs, gravity 9.81 down | radius 0.2, poured, inelastic |
//! | [`hopper`] | a funnel over a row of bins, gravity 9.81 down | radius 0.1, inelastic |
//! | [`galton`] | a triangle of pegs over bins, gravity 9.81 down | radius 0.1, inelastic |
//! | [`pool_break`] | a 9-foot pool table seen from above, 4 cushions, cloth friction | 16 pool balls, a break |

use exact2d::scene::{Scene, SceneBall, SceneCircle, SceneSegment};

use crate::rng::SplitMix64;

/// Gas: the box side is `sqrt(N)`, so there is one ball per unit area whatever `N`.
pub const GAS_NUMBER_DENSITY: f64 = 1.0;
/// Gas: the speed of every ball at time 0.
pub const GAS_SPEED: f64 = 1.0;

/// Brick board: columns of cells.
pub const BRICK_COLUMNS: usize = 7;
/// Brick board: rows of cells.
pub const BRICK_ROWS: usize = 9;
/// Brick board: the side of a cell; the container is `BRICK_COLUMNS` cells wide.
pub const BRICK_CELL: f64 = 1.0;
/// Brick board: the empty launch area between the floor and the lowest row, in cells.
pub const BRICK_LAUNCH_ROWS: usize = 3;
/// Brick board: the empty space between the highest row and the ceiling, in cells.
pub const BRICK_TOP_ROWS: usize = 1;
/// Brick board: the gap between a brick and the edge of its cell.
pub const BRICK_INSET: f64 = 0.05;
/// Brick board: the radius of a round obstacle (centred in its cell).
pub const BRICK_OBSTACLE_RADIUS: f64 = 0.3;
/// Brick board: the radius of every ball.
pub const BRICK_BALL_RADIUS: f64 = 0.1;
/// Brick board: the speed of every ball at time 0.
pub const BRICK_BALL_SPEED: f64 = 10.0;

/// Free balls: the box's width.
pub const FREE_BOX_WIDTH: f64 = 16.0;
/// Free balls: the box's height.
pub const FREE_BOX_HEIGHT: f64 = 9.0;

/// Pegs: the box's width.
pub const PEGS_WIDTH: f64 = 10.0;
/// Pegs: the gravity, in m/s^2, pointing down (-y).
pub const PEGS_GRAVITY: f64 = 9.81;
/// Pegs: the number of rows of pegs.
pub const PEGS_ROWS: usize = 8;
/// Pegs: the radius of a peg.
pub const PEGS_PEG_RADIUS: f64 = 0.15;
/// Pegs: the radius of every ball.
pub const PEGS_BALL_RADIUS: f64 = 0.1;

/// The four segments of the axis-aligned box `[x0, x1] x [y0, y1]`, counter-clockwise.
fn rectangle(x0: f64, y0: f64, x1: f64, y1: f64) -> Vec<SceneSegment> {
    polygon(&[[x0, y0], [x1, y0], [x1, y1], [x0, y1]])
}

/// The closed polygon through `corners`: one segment per side.
fn polygon(corners: &[[f64; 2]]) -> Vec<SceneSegment> {
    (0..corners.len())
        .map(|i| SceneSegment {
            a: corners[i],
            b: corners[(i + 1) % corners.len()],
            restitution: 1.0,
            friction: 0.0,
            tangential_restitution: 0.0,
            rolling_resistance: 0.0,
        })
        .collect()
}

fn ball(id: usize, pos: [f64; 2], vel: [f64; 2], radius: f64) -> SceneBall {
    SceneBall {
        id: id as u64,
        pos,
        vel,
        radius,
        mass: 1.0,
        restitution: 1.0,
        spin: 0.0,
        inertia: 0.5,
        friction: 0.0,
        tangential_restitution: 0.0,
        rolling_resistance: 0.0,
        roll: [0.0, 0.0],
    }
}

fn scaled(v: [f64; 2], speed: f64) -> [f64; 2] {
    [v[0] * speed, v[1] * speed]
}

/// A hard-disk gas: `balls` equal balls (unit mass, unit speed, random directions) at area
/// packing fraction `packing`, colliding with each other, without gravity, in the square box
/// `[0, L]^2` (4 segments) with `L = sqrt(balls)`.
///
/// The radius follows from the packing: `packing = balls * pi * r^2 / L^2`. Balls start on the
/// most open lattice that fits: rows of equal spacing, every other row shifted by half a
/// spacing when that opens it up (a square lattice for a square number of balls at moderate
/// packings, a near-hexagonal one otherwise), at least `r` from the walls.
///
/// # Panics
/// If `balls` is 0, or `packing` is not in `(0, 0.85)`, or no such lattice keeps the balls
/// apart (packing 0.4 always fits; 0.7 fits for every `balls` from 38 up, and for some
/// smaller counts).
#[must_use]
pub fn gas(balls: usize, packing: f64, seed: u64) -> Scene {
    let (side, radius) = gas_box(balls, packing, 0.85);
    let inner = side - 2.0 * radius;
    let lattice = best_lattice(balls, inner);
    assert!(
        lattice.clearance >= 2.0 * radius * (1.0 + 1e-9) && inner >= 0.0,
        "{balls} balls at packing {packing} do not fit on a lattice in their box"
    );
    let mut rng = SplitMix64::new(seed);
    let balls = (0..balls)
        .map(|k| {
            let [x, y] = lattice.site(k);
            let vel = scaled(rng.direction(), GAS_SPEED);
            ball(k, [radius + x, radius + y], vel, radius)
        })
        .collect();
    Scene {
        gravity: [0.0, 0.0],
        ball_ball: true,
        segments: rectangle(0.0, 0.0, side, side),
        circles: Vec::new(),
        balls,
        sleep: false,
        table: None,
        periodic: None,
    }
}

/// [`gas`] with one large ball among the small ones: the balls within `ratio + 1` radii of
/// the box's centre give way to one ball of `ratio` times their radius there, of mass
/// `ratio^2` (the same density), moving as the first of them did. What a drop-and-merge box
/// with one large ball costs the broad phase, whose cells follow the largest radius.
///
/// # Panics
/// As [`gas`]; and if `ratio` is below 1 or the large ball does not fit in the box.
#[must_use]
pub fn gas_with_large(balls: usize, packing: f64, ratio: f64, seed: u64) -> Scene {
    let mut scene = gas(balls, packing, seed);
    assert!(ratio >= 1.0, "a large ball's ratio {ratio} is below 1");
    let (side, radius) = gas_box(balls, packing, 0.85);
    let large = ratio * radius;
    assert!(
        2.0 * large < side,
        "a ball {ratio} times the radius does not fit"
    );
    let centre = [0.5 * side, 0.5 * side];
    let clear = |b: &SceneBall| {
        let (dx, dy) = (b.pos[0] - centre[0], b.pos[1] - centre[1]);
        (dx * dx + dy * dy).sqrt() > (large + radius) * (1.0 + 1e-9)
    };
    let vel = scene
        .balls
        .iter()
        .find(|b| !clear(b))
        .map_or([0.0, GAS_SPEED], |b| b.vel);
    scene.balls.retain(clear);
    for (k, b) in scene.balls.iter_mut().enumerate() {
        b.id = k as u64;
    }
    let mut big = ball(scene.balls.len(), centre, vel, large);
    big.mass = ratio * ratio;
    scene.balls.push(big);
    scene
}

/// A gas's box side and radius: `balls` balls at [`GAS_NUMBER_DENSITY`] and `packing`.
///
/// # Panics
/// If there is no ball, or the packing is not in `(0, most)`.
fn gas_box(balls: usize, packing: f64, most: f64) -> (f64, f64) {
    assert!(balls > 0, "a gas needs at least one ball");
    assert!(
        packing > 0.0 && packing < most,
        "packing fraction {packing} is not in (0, {most})"
    );
    let side = (balls as f64 / GAS_NUMBER_DENSITY).sqrt();
    let radius = (packing * side * side / (balls as f64 * std::f64::consts::PI)).sqrt();
    (side, radius)
}

/// [`gas`] in a periodic box instead of a closed one (`World::set_periodic`): the same number
/// density, radius and speeds, the balls on a square lattice of `ceil(sqrt(n))` sites a side
/// filled in order (no walls: a hard-disk fluid without surfaces).
///
/// # Panics
/// If the packing is not in `(0, 0.75)`: a square lattice of touching disks packs `pi / 4`.
#[must_use]
pub fn periodic_gas(balls: usize, packing: f64, seed: u64) -> Scene {
    let (side, radius) = gas_box(balls, packing, 0.75);
    let per_side = (balls as f64).sqrt().ceil() as usize;
    let spacing = side / per_side as f64;
    let mut rng = SplitMix64::new(seed);
    let balls = (0..balls)
        .map(|k| {
            let (i, j) = (k % per_side, k / per_side);
            let pos = [(i as f64 + 0.5) * spacing, (j as f64 + 0.5) * spacing];
            ball(k, pos, scaled(rng.direction(), GAS_SPEED), radius)
        })
        .collect();
    Scene {
        ball_ball: true,
        balls,
        periodic: Some([side, side]),
        ..Scene::default()
    }
}

/// [`gas`] of rough, inelastic disks: every pair has restitution 0.9 (each ball 0.9^(1/2)),
/// Coulomb friction 0.5 and tangential restitution 0.5, and each ball starts spinning at up
/// to its speed over its radius either way (the walls stay smooth). It cools (Haff's law), so
/// the suite stops it by collisions.
#[must_use]
pub fn rough_gas(balls: usize, packing: f64, seed: u64) -> Scene {
    let mut scene = gas(balls, packing, seed);
    let mut rng = SplitMix64::new(seed ^ 0x5eed_5b1a);
    for ball in &mut scene.balls {
        ball.restitution = 0.9_f64.sqrt();
        ball.friction = 0.5;
        ball.tangential_restitution = 0.5;
        ball.spin = GAS_SPEED / ball.radius * rng.range(-1.0, 1.0);
    }
    scene
}

/// Rows of sites filling the square `[0, inner]^2`, first to last row bottom to top.
struct Lattice {
    inner: f64,
    columns: usize,
    dx: f64,
    dy: f64,
    staggered: bool,
    /// The smallest distance between two sites.
    clearance: f64,
}

impl Lattice {
    fn site(&self, k: usize) -> [f64; 2] {
        let (row, column) = (k / self.columns, k % self.columns);
        let shift = if self.staggered && row % 2 == 1 {
            0.5
        } else {
            0.0
        };
        // A single column or a single row stands in the middle.
        let x = if self.columns == 1 && !self.staggered {
            0.5 * self.inner
        } else {
            (column as f64 + shift) * self.dx
        };
        let y = if self.dy.is_finite() {
            row as f64 * self.dy
        } else {
            0.5 * self.inner
        };
        [x, y]
    }
}

/// The lattice of `n` sites in `[0, inner]^2` whose closest two sites are furthest apart.
fn best_lattice(n: usize, inner: f64) -> Lattice {
    let mut best: Option<Lattice> = None;
    for columns in 1..=n {
        let rows = n.div_ceil(columns);
        for staggered in [false, true] {
            if staggered && rows == 1 {
                continue;
            }
            // The last site of a shifted row ends at `inner`, like the last of a plain one.
            let span = columns as f64 - 1.0 + if staggered { 0.5 } else { 0.0 };
            let dx = if span > 0.0 { inner / span } else { inner };
            let dy = if rows > 1 {
                inner / (rows - 1) as f64
            } else {
                f64::INFINITY
            };
            let mut clearance = f64::INFINITY;
            if columns > 1 {
                clearance = clearance.min(dx);
            }
            if rows > 1 {
                let neighbour = if staggered {
                    (0.25 * dx * dx + dy * dy).sqrt()
                } else {
                    dy
                };
                clearance = clearance.min(neighbour).min(2.0 * dy);
            }
            if best.as_ref().is_none_or(|b| clearance > b.clearance) {
                best = Some(Lattice {
                    inner,
                    columns,
                    dx,
                    dy,
                    staggered,
                    clearance,
                });
            }
        }
    }
    // n >= 1, so the loop ran at least once.
    best.unwrap_or(Lattice {
        inner,
        columns: 1,
        dx: inner,
        dy: f64::INFINITY,
        staggered: false,
        clearance: f64::INFINITY,
    })
}

/// What a cell of the brick board holds.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Cell {
    Empty,
    /// A square brick: 4 segments.
    Square,
    /// A right triangle (3 segments) with its right angle at corner 0..4 of the cell
    /// (counter-clockwise from the bottom left).
    Triangle(usize),
    /// A round obstacle: a circle.
    Round,
}

/// The cells of the board, row by row from the bottom; the top row is left empty.
fn board_cells(rng: &mut SplitMix64) -> Vec<Cell> {
    (0..BRICK_ROWS * BRICK_COLUMNS)
        .map(|i| {
            if i / BRICK_COLUMNS == BRICK_ROWS - 1 {
                return Cell::Empty;
            }
            match rng.below(20) {
                0..=8 => Cell::Square,
                9..=12 => Cell::Triangle(rng.below(4) as usize),
                13..=14 => Cell::Round,
                _ => Cell::Empty,
            }
        })
        .collect()
}

/// A board of the brick breaker "One More Brick" with a volley of `balls` balls.
///
/// The container is `[0, 7] x [0, 13]` (4 segments: floor, walls and ceiling, so balls bounce
/// forever). Above a launch area of 3 cells, a board of 7 x 9 cells of side 1 holds, per cell
/// (seeded): a square brick (45%, 4 segments inset by 0.05), a right triangle in one of four
/// orientations (20%, 3 segments), a round obstacle (10%, a circle of radius 0.3 at the cell's
/// centre) or nothing (25%). The top row of cells is left empty. All balls (radius 0.1) start
/// at height 0.5 within 0.5 of the bottom centre, moving upwards (at 15 to 165 degrees) at speed
/// 10, and pass through each other (`ball_ball: false`).
#[must_use]
pub fn brick_board(balls: usize, seed: u64) -> Scene {
    let mut rng = SplitMix64::new(seed);
    let width = BRICK_COLUMNS as f64 * BRICK_CELL;
    let height = (BRICK_LAUNCH_ROWS + BRICK_ROWS + BRICK_TOP_ROWS) as f64 * BRICK_CELL;
    let mut segments = rectangle(0.0, 0.0, width, height);
    let mut circles = Vec::new();
    let cells = board_cells(&mut rng);
    for row in 0..BRICK_ROWS {
        for column in 0..BRICK_COLUMNS {
            let x0 = column as f64 * BRICK_CELL;
            let y0 = (BRICK_LAUNCH_ROWS + row) as f64 * BRICK_CELL;
            let (lo, hi) = (BRICK_INSET, BRICK_CELL - BRICK_INSET);
            let corners = [
                [x0 + lo, y0 + lo],
                [x0 + hi, y0 + lo],
                [x0 + hi, y0 + hi],
                [x0 + lo, y0 + hi],
            ];
            match cells[row * BRICK_COLUMNS + column] {
                Cell::Empty => {}
                Cell::Square => segments.extend(polygon(&corners)),
                Cell::Triangle(right_angle) => {
                    // The three corners other than the one opposite the right angle.
                    let triangle: Vec<[f64; 2]> =
                        (0..3).map(|i| corners[(right_angle + 3 + i) % 4]).collect();
                    segments.extend(polygon(&triangle));
                }
                Cell::Round => circles.push(SceneCircle {
                    center: [x0 + 0.5 * BRICK_CELL, y0 + 0.5 * BRICK_CELL],
                    radius: BRICK_OBSTACLE_RADIUS,
                    restitution: 1.0,
                    friction: 0.0,
                    tangential_restitution: 0.0,
                    rolling_resistance: 0.0,
                }),
            }
        }
    }
    let balls = (0..balls)
        .map(|k| {
            let x = 0.5 * width + rng.range(-0.5, 0.5) * BRICK_CELL;
            // Upwards, at 15 to 165 degrees from the floor: the direction (cos a, sin a) with
            // tan a bounded, taken from a random point above the line y = |x| tan 15.
            let dir = loop {
                let [dx, dy] = rng.direction();
                if dy > 0.267_949_192_431_122_7 * dx.abs() {
                    break [dx, dy];
                }
            };
            ball(
                k,
                [x, 0.5 * BRICK_CELL],
                scaled(dir, BRICK_BALL_SPEED),
                BRICK_BALL_RADIUS,
            )
        })
        .collect();
    Scene {
        gravity: [0.0, 0.0],
        ball_ball: false,
        segments,
        circles,
        balls,
        sleep: false,
        table: None,
        periodic: None,
    }
}

/// `balls` balls passing through each other (`ball_ball: false`), without gravity, in the box
/// `[0, 16] x [0, 9]` (exactly 4 axis-aligned segments), so each ball's path is the mirror
/// folding of a straight line. Radii are uniform in `[0.05, 0.15)`, positions uniform in the
/// box (clear of the walls), directions uniform and speeds uniform in `[1, 5)`.
#[must_use]
pub fn free_balls_in_box(balls: usize, seed: u64) -> Scene {
    let mut rng = SplitMix64::new(seed);
    let balls = (0..balls)
        .map(|k| {
            let radius = rng.range(0.05, 0.15);
            let x = rng.range(radius, FREE_BOX_WIDTH - radius);
            let y = rng.range(radius, FREE_BOX_HEIGHT - radius);
            let speed = rng.range(1.0, 5.0);
            ball(k, [x, y], scaled(rng.direction(), speed), radius)
        })
        .collect();
    Scene {
        gravity: [0.0, 0.0],
        ball_ball: false,
        segments: rectangle(0.0, 0.0, FREE_BOX_WIDTH, FREE_BOX_HEIGHT),
        circles: Vec::new(),
        balls,
        sleep: false,
        table: None,
        periodic: None,
    }
}

/// `balls` colliding balls falling under gravity `(0, -9.81)` through a lattice of round pegs,
/// in a closed box 10 wide (4 segments); every restitution is 1.
///
/// Pegs (radius 0.15) stand in 8 rows from `y = 1.5` to `y = 8.5`, one apart: even rows at
/// `x = 1, 2, ..., 9`, odd rows at `x = 0.5, 1.5, ..., 9.5`. Balls (radius 0.1) start above
/// them from `y = 10` up, on a grid of spacing 0.4 (24 per row) with a seeded jitter of up
/// to 0.05 and random velocities of speed below 1. The ceiling is 2 above the highest ball.
#[must_use]
pub fn pegs_gravity(balls: usize, seed: u64) -> Scene {
    const SPACING: f64 = 0.4;
    const JITTER: f64 = 0.05;
    const FIRST_BALL_ROW: f64 = 10.0;
    let mut rng = SplitMix64::new(seed);
    const PER_ROW: usize = 24;
    let ball_rows = balls.div_ceil(PER_ROW).max(1);
    let height = FIRST_BALL_ROW + (ball_rows - 1) as f64 * SPACING + 2.0;
    let mut circles = Vec::new();
    for row in 0..PEGS_ROWS {
        let y = 1.5 + row as f64;
        let (first, count) = if row % 2 == 0 { (1.0, 9) } else { (0.5, 10) };
        for i in 0..count {
            circles.push(SceneCircle {
                center: [first + i as f64, y],
                radius: PEGS_PEG_RADIUS,
                restitution: 1.0,
                friction: 0.0,
                tangential_restitution: 0.0,
                rolling_resistance: 0.0,
            });
        }
    }
    let balls = (0..balls)
        .map(|k| {
            let (row, column) = (k / PER_ROW, k % PER_ROW);
            let x = SPACING * (column + 1) as f64 + rng.range(-JITTER, JITTER);
            let y = FIRST_BALL_ROW + SPACING * row as f64 + rng.range(-JITTER, JITTER);
            let speed = rng.unit();
            ball(k, [x, y], scaled(rng.direction(), speed), PEGS_BALL_RADIUS)
        })
        .collect();
    Scene {
        gravity: [0.0, -PEGS_GRAVITY],
        ball_ball: true,
        segments: rectangle(0.0, 0.0, PEGS_WIDTH, height),
        circles,
        balls,
        sleep: false,
        table: None,
        periodic: None,
    }
}

/// Pile: the box's width and height.
pub const PILE_WIDTH: f64 = 10.0;
/// Pile: the box's height.
pub const PILE_HEIGHT: f64 = 30.0;
/// Pile: the radius of every ball.
pub const PILE_BALL_RADIUS: f64 = 0.2;
/// Pile: the radius of a peg of the lattice.
pub const PILE_PEG_RADIUS: f64 = 0.1;

/// `count` inelastic balls of `radius` poured from a lattice `spacing` apart whose lowest
/// row is at `y0`, `x0 .. x1` wide, each with a random speed up to `speed`; every ball's
/// restitution is `sqrt(restitution)`, so a pair's (the product) is `restitution`.
#[allow(clippy::too_many_arguments)]
fn poured(
    rng: &mut SplitMix64,
    count: usize,
    radius: f64,
    spacing: f64,
    (x0, x1): (f64, f64),
    y0: f64,
    speed: f64,
    restitution: f64,
) -> Vec<SceneBall> {
    let per_row = (((x1 - x0) / spacing) as usize).max(1);
    let jitter = 0.5 * (spacing - 2.0 * radius) * 0.9;
    (0..count)
        .map(|k| {
            let (row, column) = (k / per_row, k % per_row);
            let x = x0 + spacing * (column as f64 + 0.5) + rng.range(-jitter, jitter);
            let y = y0 + spacing * row as f64 + rng.range(-jitter, jitter);
            let v = scaled(rng.direction(), speed * rng.unit());
            SceneBall {
                restitution: restitution.sqrt(),
                ..ball(k, [x, y], v, radius)
            }
        })
        .collect()
}

/// The walls of a closed box `[0, w] x [0, h]` of restitution `restitution`.
fn inelastic_box(w: f64, h: f64, restitution: f64) -> Vec<SceneSegment> {
    rectangle(0.0, 0.0, w, h)
        .into_iter()
        .map(|s| SceneSegment { restitution, ..s })
        .collect()
}

/// A pile: `balls` balls of radius 0.2 poured into a 10 x 30 box under gravity, with pair
/// restitution `restitution` (ball with ball and ball with wall), and, if `pegs`, a lattice
/// of pegs of radius 0.1 one metre apart (staggered rows from 1 m to 9 m up).
#[must_use]
pub fn pile(balls: usize, restitution: f64, pegs: bool, seed: u64) -> Scene {
    let mut rng = SplitMix64::new(seed);
    let mut circles = Vec::new();
    if pegs {
        for row in 0..9 {
            let y = 1.0 + row as f64;
            let first = if row % 2 == 0 { 1.0 } else { 0.5 };
            let mut x = first;
            while x < PILE_WIDTH - 0.25 {
                circles.push(SceneCircle {
                    center: [x, y],
                    radius: PILE_PEG_RADIUS,
                    restitution: restitution.sqrt(),
                    friction: 0.0,
                    tangential_restitution: 0.0,
                    rolling_resistance: 0.0,
                });
                x += 1.0;
            }
        }
    }
    let balls = poured(
        &mut rng,
        balls,
        PILE_BALL_RADIUS,
        0.5,
        (0.0, PILE_WIDTH),
        12.0,
        1.0,
        restitution,
    );
    Scene {
        gravity: [0.0, -PEGS_GRAVITY],
        ball_ball: true,
        segments: inelastic_box(PILE_WIDTH, PILE_HEIGHT, restitution.sqrt()),
        circles,
        balls,
        sleep: true,
        table: None,
        periodic: None,
    }
}

/// The radii of a drop-and-merge game's balls ([`mixed_pile`]): five sizes, as its fruits.
pub const MIXED_RADII: [f64; 5] = [0.15, 0.2, 0.25, 0.3, 0.4];

/// A drop-and-merge box, as such games pile their balls (without the merging): `balls` balls
/// of the five [`MIXED_RADII`], chosen at random, of equal density (mass `r^2 / 0.04`, one for
/// a ball of radius 0.2), dropped from rest on a jittered grid 0.9 m apart from 2 m up into a
/// box 6 m wide and 40 m tall under gravity, with pair restitution `restitution` and Coulomb
/// friction `friction` on every ball and wall.
#[must_use]
pub fn mixed_pile(balls: usize, restitution: f64, friction: f64, seed: u64) -> Scene {
    let mut rng = SplitMix64::new(seed);
    let (width, height, spacing) = (6.0, 40.0, 0.9);
    let per_row = (width / spacing) as usize;
    let jitter = 0.5 * (spacing - 2.0 * MIXED_RADII[4]) * 0.9;
    let margin = 0.5 * (width - spacing * per_row as f64);
    let e = restitution.sqrt();
    let balls = (0..balls)
        .map(|k| {
            let radius = MIXED_RADII[rng.below(MIXED_RADII.len() as u64) as usize];
            let (row, column) = (k / per_row, k % per_row);
            let x = margin + spacing * (column as f64 + 0.5) + rng.range(-jitter, jitter);
            let y = 2.0 + spacing * row as f64 + rng.range(-jitter, jitter);
            SceneBall {
                mass: radius * radius / 0.04,
                restitution: e,
                friction,
                ..ball(k, [x, y], [0.0, 0.0], radius)
            }
        })
        .collect();
    Scene {
        gravity: [0.0, -PEGS_GRAVITY],
        ball_ball: true,
        segments: inelastic_box(width, height, e)
            .into_iter()
            .map(|s| SceneSegment { friction, ..s })
            .collect(),
        circles: Vec::new(),
        balls,
        sleep: true,
        table: None,
        periodic: None,
    }
}

/// A hopper: `balls` balls of radius 0.1 (pair restitution `restitution`) poured into a
/// funnel 12 m wide at the top whose spout, 0.8 m wide, opens 6 m above a row of 12 bins, each
/// 1 m wide and 2 m deep, on the floor of a 12 m wide box.
#[must_use]
pub fn hopper(balls: usize, restitution: f64, seed: u64) -> Scene {
    let mut rng = SplitMix64::new(seed);
    let e = restitution.sqrt();
    let width = 12.0;
    let spout = (5.6, 6.4);
    let (spout_y, top_y) = (8.0, 14.0);
    let per_row = 40.0;
    let rows = (balls as f64 / per_row).ceil();
    let height = top_y + 1.0 + rows * 0.28 + 2.0;
    let mut segments = inelastic_box(width, height, e);
    let segment = |a: [f64; 2], b: [f64; 2]| SceneSegment {
        a,
        b,
        restitution: e,
        friction: 0.0,
        tangential_restitution: 0.0,
        rolling_resistance: 0.0,
    };
    segments.push(segment([0.0, top_y], [spout.0, spout_y]));
    segments.push(segment([width, top_y], [spout.1, spout_y]));
    for k in 1..12 {
        let x = k as f64;
        segments.push(segment([x, 0.0], [x, 2.0]));
    }
    let balls = poured(
        &mut rng,
        balls,
        0.1,
        0.28,
        (0.2, width - 0.2),
        top_y + 0.5,
        0.5,
        restitution,
    );
    Scene {
        gravity: [0.0, -PEGS_GRAVITY],
        ball_ball: true,
        segments,
        circles: Vec::new(),
        balls,
        sleep: true,
        table: None,
        periodic: None,
    }
}

/// Gives every ball, segment and circle of `scene` Coulomb friction `mu` (a rough pile, as a
/// game would set one up).
pub fn roughen(scene: &mut Scene, mu: f64) {
    for b in &mut scene.balls {
        b.friction = mu;
    }
    for s in &mut scene.segments {
        s.friction = mu;
    }
    for c in &mut scene.circles {
        c.friction = mu;
    }
}

/// A Galton board: `balls` balls of radius 0.1 (pair restitution `restitution`) poured
/// through a funnel onto a triangle of 12 rows of pegs (radius 0.08, 0.5 m apart), over 14
/// bins 0.5 m wide and 6 m deep.
#[must_use]
pub fn galton(balls: usize, restitution: f64, seed: u64) -> Scene {
    let mut rng = SplitMix64::new(seed);
    let e = restitution.sqrt();
    let width = 7.0;
    let centre = width / 2.0;
    let (bins_top, pegs_top) = (6.0, 12.5);
    let mut segments = Vec::new();
    let rows = (balls as f64 / 20.0).ceil();
    let height = pegs_top + 4.0 + rows * 0.25 + 2.0;
    segments.extend(inelastic_box(width, height, e));
    let segment = |a: [f64; 2], b: [f64; 2]| SceneSegment {
        a,
        b,
        restitution: e,
        friction: 0.0,
        tangential_restitution: 0.0,
        rolling_resistance: 0.0,
    };
    // The funnel over the apex.
    segments.push(segment(
        [0.0, pegs_top + 3.0],
        [centre - 0.35, pegs_top + 0.6],
    ));
    segments.push(segment(
        [width, pegs_top + 3.0],
        [centre + 0.35, pegs_top + 0.6],
    ));
    for k in 1..14 {
        let x = 0.5 * k as f64;
        segments.push(segment([x, 0.0], [x, bins_top]));
    }
    let mut circles = Vec::new();
    for row in 0..12 {
        let y = pegs_top - 0.5 * row as f64;
        for i in 0..=row {
            let x = centre + 0.5 * (i as f64 - row as f64 / 2.0);
            circles.push(SceneCircle {
                center: [x, y],
                radius: 0.08,
                restitution: e,
                friction: 0.0,
                tangential_restitution: 0.0,
                rolling_resistance: 0.0,
            });
        }
    }
    let balls = poured(
        &mut rng,
        balls,
        0.1,
        0.25,
        (0.2, width - 0.2),
        pegs_top + 4.0,
        0.2,
        restitution,
    );
    Scene {
        gravity: [0.0, -PEGS_GRAVITY],
        ball_ball: true,
        segments,
        circles,
        balls,
        sleep: true,
        table: None,
        periodic: None,
    }
}

/// Pool: the playing area's length and width (a 9-foot table), in metres.
pub const POOL_TABLE: [f64; 2] = [2.54, 1.27];
/// Pool: a ball's radius (57.15 mm balls) and mass, in metres and kilograms.
pub const POOL_BALL: (f64, f64) = (0.028_575, 0.17);
/// Pool: the gap left between neighbours in the rack (a tenth of a millimetre).
pub const POOL_RACK_GAP: f64 = 1e-4;

/// A break at pool: 15 balls racked in a triangle (apex on the foot spot, neighbours
/// [`POOL_RACK_GAP`] apart) and a cue ball from near the head spot, aimed at the apex within
/// a degree, at 5 to 9 m/s, with side spin of up to 40 rad/s either way and a roll of up to
/// its rolling value either way (draw to follow); a table seen from above
/// ([`exact2d::Table::POOL`]) inside four cushions (restitution 0.85 with a ball, friction
/// 0.2); balls of inertia 2/5 (spheres), ball-ball restitution 0.95, frictionless.
#[must_use]
pub fn pool_break(seed: u64) -> Scene {
    let mut rng = SplitMix64::new(seed);
    let [length, width] = POOL_TABLE;
    let (radius, mass) = POOL_BALL;
    let ball_e = 0.95_f64.sqrt();
    let cushion_e = 0.85 / ball_e;
    let corners = [[0.0, 0.0], [length, 0.0], [length, width], [0.0, width]];
    let segments = (0..4)
        .map(|k| SceneSegment {
            a: corners[k],
            b: corners[(k + 1) % 4],
            restitution: cushion_e,
            friction: 0.2,
            tangential_restitution: 0.0,
            rolling_resistance: 0.0,
        })
        .collect();
    let ball = |id: u64, pos: [f64; 2]| SceneBall {
        id,
        pos,
        vel: [0.0, 0.0],
        radius,
        mass,
        restitution: ball_e,
        spin: 0.0,
        roll: [0.0, 0.0],
        inertia: 0.4,
        friction: 0.0,
        tangential_restitution: 0.0,
        rolling_resistance: 0.0,
    };
    let apex = [0.75 * length, 0.5 * width];
    let pitch = 2.0 * radius + POOL_RACK_GAP;
    let mut balls = Vec::with_capacity(16);
    let head = [0.25 * length, 0.5 * width + rng.range(-0.05, 0.05)];
    let aim = (apex[1] - head[1]).atan2(apex[0] - head[0]) + rng.range(-1.0, 1.0).to_radians();
    let speed = rng.range(5.0, 9.0);
    let (sin, cos) = aim.sin_cos();
    let mut cue = ball(0, head);
    cue.vel = [speed * cos, speed * sin];
    cue.spin = rng.range(-40.0, 40.0);
    // Rolling along (cos, sin) at speed v turns about (-sin, cos) at v / r.
    let roll = rng.range(-1.0, 1.0) * speed / radius;
    cue.roll = [-sin * roll, cos * roll];
    balls.push(cue);
    let mut id = 1;
    for row in 0..5 {
        for j in 0..=row {
            let x = apex[0] + row as f64 * pitch * 0.75_f64.sqrt();
            let y = apex[1] + (j as f64 - row as f64 / 2.0) * pitch;
            balls.push(ball(id, [x, y]));
            id += 1;
        }
    }
    Scene {
        gravity: [0.0, 0.0],
        ball_ball: true,
        segments,
        circles: Vec::new(),
        balls,
        sleep: false,
        table: Some(exact2d::Table::POOL.into()),
        periodic: None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn assert_valid(scene: &Scene, balls: usize) {
        if let Err(error) = scene.validate() {
            panic!("invalid scene: {error}");
        }
        assert_eq!(scene.balls.len(), balls);
        let ids: Vec<u64> = scene.balls.iter().map(|b| b.id).collect();
        assert_eq!(ids, (0..balls as u64).collect::<Vec<_>>());
    }

    /// Area of the axis-aligned bounding box of the segments.
    fn box_area(scene: &Scene) -> f64 {
        let points = scene.segments.iter().flat_map(|s| [s.a, s.b]);
        let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
        for p in points {
            for i in 0..2 {
                lo[i] = lo[i].min(p[i]);
                hi[i] = hi[i].max(p[i]);
            }
        }
        (hi[0] - lo[0]) * (hi[1] - lo[1])
    }

    #[test]
    fn gas_validates_with_the_asked_packing() {
        let cases = [
            (1, 0.4),
            (2, 0.4),
            (10, 0.4),
            (37, 0.4),
            (1000, 0.4),
            (38, 0.7),
            (100, 0.7),
            (101, 0.7),
            (1000, 0.7),
            (4321, 0.7),
            (10_000, 0.7),
        ];
        for (n, packing) in cases {
            for seed in [0, 1, 99] {
                let scene = gas(n, packing, seed);
                assert_valid(&scene, n);
                assert!(scene.ball_ball);
                assert_eq!(scene.gravity, [0.0, 0.0]);
                assert_eq!(scene.segments.len(), 4);
                let discs: f64 = scene
                    .balls
                    .iter()
                    .map(|b| std::f64::consts::PI * b.radius * b.radius)
                    .sum();
                let measured = discs / box_area(&scene);
                assert!(
                    (measured - packing).abs() < 1e-12,
                    "{n} balls: packing {measured}, asked {packing}"
                );
                for b in &scene.balls {
                    let speed = (b.vel[0] * b.vel[0] + b.vel[1] * b.vel[1]).sqrt();
                    assert!((speed - 1.0).abs() < 1e-15);
                    assert_eq!(b.mass, 1.0);
                }
            }
        }
    }

    #[test]
    fn a_gas_with_a_large_ball_keeps_its_balls_apart_with_the_large_one_at_the_centre() {
        for ratio in [1.0, 5.0, 10.0, 20.0] {
            let scene = gas_with_large(1000, 0.4, ratio, 1);
            let n = scene.balls.len();
            assert_valid(&scene, n);
            let small = scene.balls[0].radius;
            let large = &scene.balls[n - 1];
            assert_eq!(large.radius, ratio * small);
            assert_eq!(large.mass, ratio * ratio);
            // Only the balls in its way gave way: a fraction of its area's worth.
            let gave = (1000 + 1 - n) as f64;
            assert!(
                gave <= 1.0 + 0.4 * (ratio + 2.0) * (ratio + 2.0),
                "{ratio}: {gave}"
            );
            assert!(scene.balls[..n - 1].iter().all(|b| b.radius == small));
        }
    }

    #[test]
    #[should_panic(expected = "do not fit")]
    fn gas_refuses_a_packing_that_does_not_fit() {
        let _ = gas(2, 0.7, 0);
    }

    #[test]
    fn other_generators_validate() {
        for n in [0, 1, 10, 200, 1000] {
            for seed in [0, 5, 12_345] {
                let board = brick_board(n, seed);
                assert_valid(&board, n);
                assert!(!board.ball_ball);
                let free = free_balls_in_box(n, seed);
                assert_valid(&free, n);
                assert_eq!(free.segments.len(), 4);
                assert!(!free.ball_ball);
                let pegs = pegs_gravity(n, seed);
                assert_valid(&pegs, n);
                assert!(pegs.ball_ball);
                assert_eq!(pegs.gravity, [0.0, -PEGS_GRAVITY]);
            }
        }
    }

    #[test]
    fn brick_board_has_every_kind_of_cell() {
        let cells = board_cells(&mut SplitMix64::new(3));
        assert_eq!(cells.len(), BRICK_COLUMNS * BRICK_ROWS);
        for kind in [Cell::Empty, Cell::Square, Cell::Round] {
            assert!(cells.contains(&kind), "no {kind:?} cell");
        }
        for corner in 0..4 {
            assert!(
                cells.contains(&Cell::Triangle(corner)),
                "no triangle {corner}"
            );
        }
        let board = brick_board(10, 3);
        let squares = cells.iter().filter(|&&c| c == Cell::Square).count();
        let triangles = cells
            .iter()
            .filter(|c| matches!(c, Cell::Triangle(_)))
            .count();
        let rounds = cells.iter().filter(|&&c| c == Cell::Round).count();
        assert_eq!(board.segments.len(), 4 + 4 * squares + 3 * triangles);
        assert_eq!(board.circles.len(), rounds);
        for b in &board.balls {
            let speed = (b.vel[0] * b.vel[0] + b.vel[1] * b.vel[1]).sqrt();
            assert!((speed - BRICK_BALL_SPEED).abs() < 1e-12);
            assert!(b.vel[1] > 0.0);
        }
    }

    #[test]
    fn same_seed_same_scene_other_seed_other_scene() {
        assert_eq!(gas(500, 0.7, 4), gas(500, 0.7, 4));
        assert_ne!(gas(500, 0.7, 4), gas(500, 0.7, 5));
        assert_eq!(brick_board(200, 4), brick_board(200, 4));
        assert_ne!(brick_board(200, 4), brick_board(200, 5));
        assert_eq!(free_balls_in_box(100, 4), free_balls_in_box(100, 4));
        assert_ne!(free_balls_in_box(100, 4), free_balls_in_box(100, 5));
        assert_eq!(pegs_gravity(100, 4), pegs_gravity(100, 4));
        assert_ne!(pegs_gravity(100, 4), pegs_gravity(100, 5));
    }

    #[test]
    fn a_pool_break_is_valid_deterministic_and_aimed_at_the_rack() {
        let a = pool_break(3);
        assert_eq!(a, pool_break(3));
        a.validate().unwrap();
        assert_eq!(a.balls.len(), 16);
        let cue = &a.balls[0];
        let speed = cue.vel[0].hypot(cue.vel[1]);
        assert!((5.0..9.0).contains(&speed) && cue.vel[0] > 0.0);
        assert!(a.table.is_some() && a.gravity == [0.0, 0.0]);
        assert_ne!(pool_break(4).balls[0].vel, cue.vel);
    }

    #[test]
    fn a_mixed_pile_has_its_sizes_apart_inside_its_box() {
        for seed in 1..4 {
            let scene = mixed_pile(120, 0.3, 0.5, seed);
            assert_valid(&scene, 120);
            for (i, a) in scene.balls.iter().enumerate() {
                assert!(MIXED_RADII.contains(&a.radius), "{}", a.radius);
                assert!((a.mass - a.radius * a.radius / 0.04).abs() < 1e-12);
                assert!(
                    a.pos[0] - a.radius > 0.0 && a.pos[0] + a.radius < 6.0,
                    "{:?}",
                    a.pos
                );
                assert!(
                    a.pos[1] - a.radius > 0.0 && a.pos[1] + a.radius < 40.0,
                    "{:?}",
                    a.pos
                );
                for b in &scene.balls[..i] {
                    let d = (a.pos[0] - b.pos[0]).hypot(a.pos[1] - b.pos[1]);
                    assert!(d > a.radius + b.radius, "{} and {} overlap", a.id, b.id);
                }
            }
            let sizes = MIXED_RADII.map(|r| scene.balls.iter().filter(|b| b.radius == r).count());
            assert!(sizes.iter().all(|&n| n > 0), "{sizes:?}");
            assert!(scene.build_world().is_ok());
        }
    }
}
