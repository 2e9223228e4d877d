//! Visual effects driven by what changed between two frames: a burst where a brick broke,
//! a beam where a laser fired. They animate on frame time only; the rules never see them.

use macroquad::color::Color;
use macroquad::shapes::{draw_line, draw_rectangle};
use onemorebrick::{BallView, Board, Brick, Cell, DVec2, PickupKind};

use crate::layout::Layout;
use crate::palette;

/// How long a brick's burst lasts, seconds of frame time.
pub const BURST_SECONDS: f32 = 0.5;
/// How long a laser beam stays visible after it fired.
pub const FLASH_SECONDS: f32 = 0.3;

/// The pieces of a broken brick flying apart.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Burst {
    /// The brick's centre (board coordinates).
    pub centre: DVec2,
    /// Its colour when it broke.
    pub colour: Color,
    /// Seconds since it broke.
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

impl Effects {
    /// Starts a burst.
    pub fn burst(&mut self, centre: DVec2, colour: Color) {
        self.bursts.push(Burst {
            centre,
            colour,
            age: 0.0,
        });
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
        self.bursts.retain(|b| b.age < BURST_SECONDS);
        self.flashes.retain(|f| f.age < FLASH_SECONDS);
    }

    /// Removes every effect (the board changed under them: a new round, a new game).
    pub fn clear(&mut self) {
        self.bursts.clear();
        self.flashes.clear();
    }

    /// Draws every effect.
    pub fn draw(&self, layout: &Layout, board: &Board) {
        for f in &self.flashes {
            draw_flash(layout, board, f);
        }
        for b in &self.bursts {
            draw_burst(layout, b);
        }
    }
}

/// Where the 8 pieces of a burst are (offsets in cells) and their size, at `age`.
pub fn burst_pieces(age: f32) -> ([DVec2; 8], f64) {
    let t = f64::from((age / BURST_SECONDS).clamp(0.0, 1.0));
    let reach = 0.15 + 0.55 * t;
    let mut pieces = [DVec2::ZERO; 8];
    for (k, p) in pieces.iter_mut().enumerate() {
        let angle = k as f64 * std::f64::consts::FRAC_PI_4 + 0.3;
        *p = DVec2::new(angle.cos(), angle.sin()) * reach - DVec2::new(0.0, 0.6 * t * t);
    }
    (pieces, 0.18 * (1.0 - t))
}

fn draw_burst(layout: &Layout, b: &Burst) {
    let (pieces, size) = burst_pieces(b.age);
    let alpha = 1.0 - b.age / BURST_SECONDS;
    let s = layout.px(size);
    for offset in pieces {
        let p = layout.to_screen(b.centre + offset);
        draw_rectangle(
            p.x - s / 2.0,
            p.y - s / 2.0,
            s,
            s,
            palette::with_alpha(b.colour, alpha),
        );
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
        fx.burst(DVec2::ONE, palette::TEXT);
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
        assert!(late[0].length() > early[0].length());
        assert!(small < big);
    }
}
