//! Visual effects driven by what changed between two frames: a burst where a brick broke,
//! a beam where a laser fired, recalled balls flying home, new rows sliding in. They
//! animate on frame time only, after the rules have moved on; the rules never see them.

use macroquad::color::{Color, WHITE};
use macroquad::math::Vec2;
use macroquad::shapes::{draw_circle, draw_circle_lines, draw_line, draw_rectangle, draw_triangle};
use onemorebrick::{BallView, Board, Brick, Cell, DVec2, PickupKind, Shape};
use onemorebrick_look as look;

use crate::layout::Layout;
use crate::palette;

/// How long a brick's burst lasts, seconds of frame time.
pub const BURST_SECONDS: f32 = 0.6;
/// How long a laser beam stays visible after it fired.
pub const FLASH_SECONDS: f32 = 0.3;
/// How long recalled balls take to fly back to the launcher.
pub const HOMING_SECONDS: f32 = 0.45;
/// How long the board takes to slide down one row at a round's end.
pub const SLIDE_SECONDS: f32 = 0.3;
/// How long the mark of a ball a hazard took out lasts, seconds.
pub const TAKEN_SECONDS: f32 = 0.7;
/// Ghosts in a recalled ball's trail, and the seconds between them.
const TRAIL: usize = 3;
const TRAIL_STEP: f32 = 0.025;
/// The pieces a broken brick bursts into.
pub const PIECES: usize = 12;
/// The score counter's time constant: the shown score closes about two thirds of its gap
/// to the real one in this many seconds.
pub const COUNT_SECONDS: f64 = 0.15;
/// The score counter's slowest pace, points per second (the last points count up too).
pub const COUNT_MIN_RATE: f64 = 8.0;

/// A broken brick bursting: a bright flash of its shape, and pieces in its colour flying
/// apart.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Burst {
    /// The brick's shape.
    pub shape: Shape,
    /// Its cell's lower-left corner (board coordinates).
    pub origin: DVec2,
    /// Its colour as last drawn.
    pub colour: Color,
    /// Seconds since it broke.
    pub age: f32,
}

/// A recalled ball flying from where it was back to the launcher.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Homing {
    /// Where it was when recalled (board coordinates).
    pub start: DVec2,
    /// The launcher's ball centre.
    pub target: DVec2,
    /// Its radius, cells.
    pub radius: f64,
    /// Its colour.
    pub colour: Color,
    /// Seconds since the recall.
    pub age: f32,
}

/// A laser beam across a row, a column or both.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Flash {
    /// The laser pick-up's cell.
    pub cell: usize,
    /// Its kind (which beams).
    pub kind: PickupKind,
    /// Seconds since it last fired.
    pub age: f32,
}

/// Every running effect.
#[derive(Clone, Debug, Default)]
pub struct Effects {
    /// Brick bursts.
    pub bursts: Vec<Burst>,
    /// Laser beams.
    pub flashes: Vec<Flash>,
    /// Recalled balls on their way home.
    pub homing: Vec<Homing>,
    /// Seconds since the board moved down a row, while it slides.
    pub slide: Option<f32>,
    /// Where hazards took balls out, and how long ago (seconds).
    pub taken: Vec<(DVec2, f32)>,
}

/// The bricks of `before` that are gone in `after` (the same board a frame later), with
/// their cell index.
pub fn broken_bricks(before: &Board, after: &Board) -> Vec<(usize, Brick)> {
    before
        .bricks()
        .filter(|(i, _)| after.cells()[*i].brick().is_none())
        .map(|(i, b)| (i, *b))
        .collect()
}

/// The bricks of `before` (the volley's board at the start of the frame that ended the
/// round) that did not survive into `after` (the next round's board, every row one step
/// lower).
pub fn broken_at_round_end(before: &Board, after: &Board) -> Vec<(usize, Brick)> {
    before
        .bricks()
        .filter(|(i, _)| {
            let (column, row) = before.position(*i);
            row == 0
                || after
                    .get(column, row - 1)
                    .and_then(|c| c.brick().copied())
                    .is_none()
        })
        .map(|(i, b)| (i, *b))
        .collect()
}

/// The laser pick-ups some ball overlaps now (a ball entering one fires it).
pub fn lasers_touched(
    board: &Board,
    balls: &[BallView],
    pickup_radius: f64,
) -> Vec<(usize, PickupKind)> {
    let mut out = Vec::new();
    for (i, cell) in board.cells().iter().enumerate() {
        let Cell::Pickup(p) = cell else { continue };
        if !(p.kind.hits_row() || p.kind.hits_column()) {
            continue;
        }
        let centre = board.origin(i) + DVec2::splat(0.5);
        if balls
            .iter()
            .any(|b| b.position.distance(centre) < pickup_radius + b.radius)
        {
            out.push((i, p.kind));
        }
    }
    out
}

/// Where the balls were that a hazard took out between two frames: `hazards` new take-outs
/// (the volley's tally) among the balls of `before` gone from `after`, those that touched a
/// hazard of `board` (within the pick-up's radius and their own, the rules' touch), nearest
/// first. A ball gone elsewhere (home at the floor) is not one.
pub fn taken_out(
    before: &[BallView],
    after: &[BallView],
    board: &Board,
    pickup_radius: f64,
    hazards: u32,
) -> Vec<DVec2> {
    let centres: Vec<DVec2> = board
        .cells()
        .iter()
        .enumerate()
        .filter(|(_, c)| matches!(c, Cell::Pickup(p) if p.kind == PickupKind::Hazard))
        .map(|(i, _)| board.origin(i) + DVec2::splat(0.5))
        .collect();
    let mut gone: Vec<(f64, DVec2)> = before
        .iter()
        .filter(|b| after.iter().all(|a| a.id != b.id))
        .filter_map(|b| {
            let nearest = centres
                .iter()
                .map(|c| c.distance(b.position) - pickup_radius - b.radius)
                .fold(f64::INFINITY, f64::min);
            // A frame's motion: the ball touched the hazard during the frame, not at its start.
            (nearest <= 4.0 * b.radius).then_some((nearest, b.position))
        })
        .collect();
    gone.sort_by(|a, b| a.0.total_cmp(&b.0));
    gone.into_iter()
        .take(hazards as usize)
        .map(|(_, p)| p)
        .collect()
}

impl Effects {
    /// Marks where a hazard took a ball out: a ring in the hazard's colour that grows and
    /// fades, struck through as its icon is.
    pub fn take_out(&mut self, at: DVec2) {
        self.taken.push((at, 0.0));
    }

    /// Starts the burst of `brick`, whose cell's lower-left corner is `origin`, drawn in
    /// `colour` until it broke.
    pub fn burst(&mut self, brick: &Brick, origin: DVec2, colour: Color) {
        self.bursts.push(Burst {
            shape: brick.shape,
            origin,
            colour,
            age: 0.0,
        });
    }

    /// Sends `balls` (where they were when recalled) home to the launcher ball at
    /// `target`.
    pub fn recall(
        &mut self,
        balls: &[BallView],
        target: DVec2,
        colours: impl Fn(&BallView) -> Color,
    ) {
        self.homing.extend(balls.iter().map(|b| Homing {
            start: b.position,
            target,
            radius: b.radius,
            colour: colours(b),
            age: 0.0,
        }));
    }

    /// Starts the board's slide: it has just moved down a row.
    pub fn start_slide(&mut self) {
        self.slide = Some(0.0);
    }

    /// How far above the rules' positions the board is drawn now, in cells.
    pub fn board_offset(&self) -> f64 {
        self.slide.map_or(0.0, slide_offset)
    }

    /// Fires (or keeps firing) the laser in `cell`.
    pub fn flash(&mut self, cell: usize, kind: PickupKind) {
        match self.flashes.iter_mut().find(|f| f.cell == cell) {
            Some(f) => f.age = 0.0,
            None => self.flashes.push(Flash {
                cell,
                kind,
                age: 0.0,
            }),
        }
    }

    /// Ages every effect by `dt` seconds and drops the finished ones.
    pub fn update(&mut self, dt: f32) {
        for b in &mut self.bursts {
            b.age += dt;
        }
        for f in &mut self.flashes {
            f.age += dt;
        }
        for h in &mut self.homing {
            h.age += dt;
        }
        for t in &mut self.taken {
            t.1 += dt;
        }
        self.taken.retain(|t| t.1 < TAKEN_SECONDS);
        self.bursts.retain(|b| b.age < BURST_SECONDS);
        self.flashes.retain(|f| f.age < FLASH_SECONDS);
        self.homing.retain(|h| h.age < HOMING_SECONDS);
        self.slide = self.slide.map(|a| a + dt).filter(|&a| a < SLIDE_SECONDS);
    }

    /// Removes every effect (the board changed under them: a new round, a new game).
    pub fn clear(&mut self) {
        *self = Self::default();
    }

    /// Draws the bursts and the beams.
    pub fn draw(&self, layout: &Layout, board: &Board) {
        for f in &self.flashes {
            draw_flash(layout, board, f);
        }
        for b in &self.bursts {
            draw_burst(layout, b);
        }
        for &(at, age) in &self.taken {
            draw_taken(layout, at, age);
        }
    }

    /// Draws the recalled balls on their way home.
    pub fn draw_homing(&self, layout: &Layout) {
        let r = |h: &Homing| layout.px(h.radius).max(1.0);
        for h in &self.homing {
            // A short fading trail behind the ball.
            for k in 1..=TRAIL {
                let age = h.age - k as f32 * TRAIL_STEP;
                if age <= 0.0 {
                    break;
                }
                let p = layout.to_screen(homing_position(h.start, h.target, age));
                let alpha = 0.45 * (1.0 - k as f32 / (TRAIL + 1) as f32);
                draw_circle(p.x, p.y, r(h) * 0.8, palette::with_alpha(h.colour, alpha));
            }
            let p = layout.to_screen(homing_position(h.start, h.target, h.age));
            draw_circle(p.x, p.y, r(h), h.colour);
        }
    }
}

/// Where a recalled ball is `age` seconds after the recall: on the straight line from
/// `start` to the launcher at `target`, easing in and out (smoothstep), at `target` from
/// [`HOMING_SECONDS`] on.
pub fn homing_position(start: DVec2, target: DVec2, age: f32) -> DVec2 {
    let t = f64::from((age / HOMING_SECONDS).clamp(0.0, 1.0));
    let e = t * t * (3.0 - 2.0 * t);
    start * (1.0 - e) + target * e
}

/// How far above the rules' positions the board is drawn `age` seconds after it moved
/// down a row, in cells: one row (where it was) at first, easing out to none at
/// [`SLIDE_SECONDS`].
pub fn slide_offset(age: f32) -> f64 {
    let left = 1.0 - f64::from((age / SLIDE_SECONDS).clamp(0.0, 1.0));
    left * left * left
}

/// `layout` with the board drawn `cells` higher (a slide): the same rectangle moved up.
pub fn raised(layout: &Layout, cells: f64) -> Layout {
    let mut raised = *layout;
    raised.board.y -= layout.px(cells);
    raised
}

/// The score shown `dt` seconds later, counting up from `shown` toward `score`: it
/// closes its gap exponentially (time constant [`COUNT_SECONDS`]) but at least
/// [`COUNT_MIN_RATE`] points a second, and never passes `score`. A lower score (a new
/// game, a restart) is shown at once.
pub fn count_up(shown: f64, score: u64, dt: f32) -> f64 {
    let target = score as f64;
    if shown >= target {
        return target;
    }
    let dt = f64::from(dt.max(0.0));
    let step = (target - shown) * (1.0 - (-dt / COUNT_SECONDS).exp()) + COUNT_MIN_RATE * dt;
    (shown + step).min(target)
}

/// Where the [`PIECES`] pieces of a burst are (offsets from the brick's centre, cells) and
/// their size (cells), at `age`: they fly out fast and slow down, each at its own angle and
/// speed, fall a little, and shrink.
pub fn burst_pieces(age: f32) -> ([DVec2; PIECES], f64) {
    let t = f64::from((age / BURST_SECONDS).clamp(0.0, 1.0));
    let out = 1.0 - (1.0 - t) * (1.0 - t);
    let mut pieces = [DVec2::ZERO; PIECES];
    for (k, p) in pieces.iter_mut().enumerate() {
        // A fixed scatter: each piece a little off the even spread, at its own speed.
        let jitter = ((k * 7) % 11) as f64 / 11.0;
        let angle = (k as f64 + 0.6 * jitter) * std::f64::consts::TAU / PIECES as f64;
        let reach = 0.2 + 1.0 * out * (0.55 + 0.45 * ((k * 5) % 7) as f64 / 6.0);
        *p = DVec2::new(angle.cos(), angle.sin()) * reach - DVec2::new(0.0, 0.5 * t * t);
    }
    (pieces, 0.26 * (1.0 - t) + 0.04)
}

/// The burst's brightness and how far its flash has grown, at `age`: the flash is the
/// brick's shape, whitened, growing by up to a third and fading in the burst's first
/// third.
pub fn burst_flash(age: f32) -> (f32, f64) {
    let t = (age / (BURST_SECONDS / 3.0)).clamp(0.0, 1.0);
    (1.0 - t, 1.0 + f64::from(t) / 3.0)
}

/// `c` moved toward white by `t`.
fn lighten(c: Color, t: f32) -> Color {
    Color::new(
        c.r + (WHITE.r - c.r) * t,
        c.g + (WHITE.g - c.g) * t,
        c.b + (WHITE.b - c.b) * t,
        c.a,
    )
}

/// The mark of a ball taken out at `at`, `age` seconds ago: a ring in the hazard's colour,
/// growing from a ball's size to a cell's, struck through, fading out.
fn draw_taken(layout: &Layout, at: DVec2, age: f32) {
    let (rgba, _) = look::palette::pickup(PickupKind::Hazard);
    let t = (age / TAKEN_SECONDS).clamp(0.0, 1.0);
    let colour = palette::with_alpha(palette::color(rgba), 1.0 - t);
    let c = layout.to_screen(at);
    let r = layout.px(0.15 + 0.35 * f64::from(t));
    let w = (r * 0.18).max(2.0);
    draw_circle_lines(c.x, c.y, r, w, colour);
    let d = r * std::f32::consts::FRAC_1_SQRT_2;
    draw_line(c.x - d, c.y - d, c.x + d, c.y + d, w, colour);
}

fn draw_burst(layout: &Layout, b: &Burst) {
    let centre = look::centroid(b.shape, b.origin);
    let (flash, grown) = burst_flash(b.age);
    if flash > 0.0 {
        let points: Vec<Vec2> = look::drawn_outline(b.shape, b.origin)
            .into_iter()
            .map(|p| layout.to_screen(centre + (p - centre) * grown))
            .collect();
        let colour = palette::with_alpha(lighten(b.colour, 0.55), flash.sqrt() * 0.9);
        for k in 1..points.len() - 1 {
            draw_triangle(points[0], points[k], points[k + 1], colour);
        }
    }
    let (pieces, size) = burst_pieces(b.age);
    let fade = 1.0 - b.age / BURST_SECONDS;
    let colour = palette::with_alpha(lighten(b.colour, 0.25 * fade), fade.sqrt());
    let s = layout.px(size);
    for offset in pieces {
        let p = layout.to_screen(centre + offset);
        draw_rectangle(p.x - s / 2.0, p.y - s / 2.0, s, s, colour);
    }
}

fn draw_flash(layout: &Layout, board: &Board, f: &Flash) {
    let alpha = 1.0 - f.age / FLASH_SECONDS;
    let colour = palette::with_alpha(palette::LASER, alpha);
    let centre = board.origin(f.cell) + DVec2::splat(0.5);
    let width = layout.px(0.12) * alpha.max(0.3);
    if f.kind.hits_row() {
        let a = layout.to_screen(DVec2::new(0.0, centre.y));
        let b = layout.to_screen(DVec2::new(f64::from(board.columns()), centre.y));
        draw_line(a.x, a.y, b.x, b.y, width, colour);
    }
    if f.kind.hits_column() {
        let a = layout.to_screen(DVec2::new(centre.x, 0.0));
        let b = layout.to_screen(DVec2::new(centre.x, f64::from(board.rows())));
        draw_line(a.x, a.y, b.x, b.y, width, colour);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use onemorebrick::{Pickup, Shape};

    fn brick(hp: u32) -> Cell {
        Cell::Brick(Brick {
            shape: Shape::Square,
            hp,
        })
    }

    fn ball_at(x: f64, y: f64) -> BallView {
        BallView {
            id: 0,
            position: DVec2::new(x, y),
            velocity: DVec2::new(0.0, 1.0),
            radius: 0.15,
            clone: false,
            floor_bounce: false,
            shield: false,
        }
    }

    #[test]
    fn a_ball_gone_at_a_hazard_is_marked_and_one_gone_home_is_not() {
        use onemorebrick::{Pickup, PickupKind};
        let mut board = Board::new(7, 9);
        let hazard = Cell::Pickup(Pickup {
            kind: PickupKind::Hazard,
            used: false,
        });
        board.set(2, 4, hazard).unwrap();
        let centre = board.origin(board.index(2, 4).unwrap()) + DVec2::splat(0.5);
        let mut at_hazard = ball_at(centre.x + 0.2, centre.y);
        at_hazard.id = 3;
        let mut home = ball_at(5.5, 0.15);
        home.id = 4;
        let stays = ball_at(1.0, 1.0);
        let before = [at_hazard, home, stays];
        let after = [stays];
        let marked = taken_out(&before, &after, &board, 0.3, 1);
        assert_eq!(marked, vec![at_hazard.position]);
        assert!(
            taken_out(&before, &after, &board, 0.3, 0).is_empty(),
            "no take-out in the tally"
        );
        assert!(
            taken_out(&before, &before, &board, 0.3, 1).is_empty(),
            "nothing gone"
        );
        let mut effects = Effects::default();
        effects.take_out(at_hazard.position);
        effects.update(TAKEN_SECONDS * 0.5);
        assert_eq!(effects.taken.len(), 1);
        effects.update(TAKEN_SECONDS * 0.5);
        assert!(effects.taken.is_empty(), "faded out");
    }

    #[test]
    fn only_bricks_that_left_are_broken() {
        let mut before = Board::new(7, 9);
        before.set(1, 5, brick(3)).unwrap();
        before.set(2, 5, brick(1)).unwrap();
        let mut after = before.clone();
        after.set(1, 5, brick(2)).unwrap();
        after.set(2, 5, Cell::Empty).unwrap();
        let broken = broken_bricks(&before, &after);
        assert_eq!(broken.len(), 1);
        assert_eq!(broken[0].0, before.index(2, 5).unwrap());
        assert!(broken_bricks(&after, &after).is_empty());
    }

    #[test]
    fn bricks_broken_as_the_round_ends_are_found_after_the_shift() {
        let mut before = Board::new(7, 9);
        before.set(1, 5, brick(3)).unwrap();
        before.set(2, 5, brick(1)).unwrap();
        let mut after = Board::new(7, 9);
        after.set(1, 4, brick(3)).unwrap();
        after.set(4, 8, brick(9)).unwrap();
        let broken = broken_at_round_end(&before, &after);
        assert_eq!(
            broken,
            vec![(
                before.index(2, 5).unwrap(),
                Brick {
                    shape: Shape::Square,
                    hp: 1
                }
            )]
        );
    }

    #[test]
    fn a_laser_fires_while_a_ball_is_in_it() {
        let mut board = Board::new(7, 9);
        board
            .set(3, 4, Cell::Pickup(Pickup::new(PickupKind::LaserCross)))
            .unwrap();
        board
            .set(5, 4, Cell::Pickup(Pickup::new(PickupKind::Split)))
            .unwrap();
        let inside = [ball_at(3.6, 4.5)];
        let touched = lasers_touched(&board, &inside, 0.3);
        assert_eq!(
            touched,
            vec![(board.index(3, 4).unwrap(), PickupKind::LaserCross)]
        );
        assert!(lasers_touched(&board, &[ball_at(3.5, 5.5)], 0.3).is_empty());
        assert!(
            lasers_touched(&board, &[ball_at(5.5, 4.5)], 0.3).is_empty(),
            "not a laser"
        );
    }

    #[test]
    fn effects_fade_out_and_refire() {
        let mut fx = Effects::default();
        let square = Brick {
            shape: Shape::Square,
            hp: 3,
        };
        fx.burst(&square, DVec2::ONE, palette::TEXT);
        fx.flash(4, PickupKind::LaserVertical);
        fx.update(FLASH_SECONDS * 0.9);
        fx.flash(4, PickupKind::LaserVertical);
        assert_eq!(fx.flashes.len(), 1);
        fx.update(FLASH_SECONDS * 0.5);
        assert_eq!(fx.flashes.len(), 1, "firing again restarts the beam");
        fx.update(BURST_SECONDS);
        assert!(fx.bursts.is_empty() && fx.flashes.is_empty());
    }

    #[test]
    fn burst_pieces_spread_and_shrink() {
        let (early, big) = burst_pieces(0.0);
        let (late, small) = burst_pieces(BURST_SECONDS * 0.9);
        for (a, b) in early.iter().zip(&late) {
            assert!(b.length() > a.length());
        }
        assert!(small < big);
        assert!(
            big >= 0.25,
            "big enough to see: {big} of a cell (the old dots: 0.18)"
        );
        let (bright, size) = burst_flash(0.0);
        assert_eq!((bright, size), (1.0, 1.0), "the flash starts as the brick");
        assert_eq!(burst_flash(BURST_SECONDS / 3.0).0, 0.0);
    }

    #[test]
    fn a_burst_is_drawn_where_the_brick_was() {
        let mut fx = Effects::default();
        let brick = Brick {
            shape: Shape::Triangle(onemorebrick::Corner::BottomLeft),
            hp: 7,
        };
        fx.burst(&brick, DVec2::new(2.0, 5.0), palette::TEXT);
        let b = fx.bursts[0];
        assert_eq!((b.shape, b.origin), (brick.shape, DVec2::new(2.0, 5.0)));
    }

    #[test]
    fn a_recalled_ball_flies_from_where_it_was_to_the_launcher() {
        let (start, home) = (DVec2::new(5.2, 7.9), DVec2::new(3.5, 0.15));
        assert_eq!(homing_position(start, home, 0.0), start);
        assert_eq!(homing_position(start, home, HOMING_SECONDS), home);
        assert_eq!(homing_position(start, home, HOMING_SECONDS * 3.0), home);
        // On the straight line between, ever closer to home.
        let mut last = start.distance(home);
        for k in 1..20 {
            let p = homing_position(start, home, HOMING_SECONDS * k as f32 / 20.0);
            let cross = (p - start).perp_dot(home - start);
            assert!(cross.abs() < 1e-9, "off the line at {k}");
            let d = p.distance(home);
            assert!(d < last, "not closer at {k}");
            last = d;
        }
        let half = homing_position(start, home, HOMING_SECONDS / 2.0);
        assert!(
            (half - (start + home) / 2.0).length() < 1e-6,
            "half way at half time"
        );
    }

    #[test]
    fn homing_balls_are_dropped_once_home() {
        let mut fx = Effects::default();
        let home = DVec2::new(3.5, 0.15);
        fx.recall(&[ball_at(1.0, 6.0), ball_at(6.0, 2.0)], home, |_| {
            palette::BALL
        });
        assert_eq!(fx.homing.len(), 2);
        assert_eq!(fx.homing[1].start, DVec2::new(6.0, 2.0));
        fx.update(HOMING_SECONDS * 0.5);
        assert_eq!(fx.homing.len(), 2);
        fx.update(HOMING_SECONDS * 0.5);
        assert!(fx.homing.is_empty());
    }

    #[test]
    fn the_slide_starts_a_row_up_and_ends_at_the_rules_positions() {
        assert_eq!(slide_offset(0.0), 1.0);
        assert_eq!(slide_offset(SLIDE_SECONDS), 0.0);
        let mut last = 1.0;
        for k in 1..=10 {
            let o = slide_offset(SLIDE_SECONDS * k as f32 / 10.0);
            assert!(o < last && o >= 0.0);
            last = o;
        }
        let layout = Layout::new(540.0, 860.0, 7, 9);
        let brick = DVec2::new(2.0, 4.0);
        let start = raised(&layout, slide_offset(0.0)).to_screen(brick);
        let above = layout.to_screen(brick + DVec2::new(0.0, 1.0));
        assert!((start - above).length() < 1e-3, "drawn where it was");
        let end = raised(&layout, slide_offset(SLIDE_SECONDS)).to_screen(brick);
        assert_eq!(
            end,
            layout.to_screen(brick),
            "drawn where the rules have it"
        );
        let mut fx = Effects::default();
        fx.start_slide();
        assert_eq!(fx.board_offset(), 1.0);
        fx.update(SLIDE_SECONDS);
        assert_eq!((fx.slide, fx.board_offset()), (None, 0.0));
    }

    #[test]
    fn the_score_counts_up_to_the_score_and_never_past_it() {
        for score in [1_u64, 37, 12_345, 9_876_543] {
            let mut shown = 0.0;
            let mut frames = 0;
            while shown < score as f64 {
                let next = count_up(shown, score, 1.0 / 60.0);
                assert!(next > shown && next <= score as f64, "{score}: {next}");
                shown = next;
                frames += 1;
            }
            assert_eq!(shown, score as f64);
            assert!(frames <= 180, "{score}: counted for {frames} frames");
            assert!(frames >= 2 || score == 1, "{score}: no count at all");
        }
        assert_eq!(count_up(10.0, 500, 10.0), 500.0, "a long frame lands on it");
        assert_eq!(
            count_up(800.0, 0, 1.0 / 60.0),
            0.0,
            "a new game shows 0 at once"
        );
        assert_eq!(count_up(5.0, 5, 0.0), 5.0);
    }
}
