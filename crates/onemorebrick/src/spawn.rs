//! The new row that enters at the top after every round, and the difficulty curve.
//!
//! Drawn from the game's generator, in this order:
//! 1. the number of bricks, uniform in `[min(1 + (level - 1) / 8, c - 2), c - 2]` for `c`
//!    columns: two cells are kept for pick-ups, and every eighth level raises the minimum;
//! 2. a random order of the columns (Fisher-Yates); the first cells in that order take the
//!    bricks, the next one the +1 ball, the next one the second pick-up (uniform among the
//!    eleven other kinds);
//! 3. from level 5, each remaining column holds an obstacle with probability 1/8;
//! 4. per brick, its shape (a square with probability 3/4, else a triangle with a uniform
//!    open corner) and its hit points `level x m`, where the multiplier `m` is 3 with
//!    probability `min(level, 40) / 160`, 2 with probability `min(level, 40) / 80`, else 1:
//!    at level 1 almost every brick has `level` points; from level 40 on, half have double
//!    and a quarter triple.

use crate::board::Board;
use crate::cell::{Brick, Cell, Corner, Shape};
use crate::pickup::{Pickup, PickupKind};
use crate::rng::GameRng;

/// Fills the top row of `board` (which must be empty) for `level`.
pub fn spawn_row(board: &mut Board, level: u32, rng: &mut GameRng) {
    let columns = board.columns();
    let top = board.rows() - 1;
    let most = columns - 2;
    let least = (1 + (level.max(1) - 1) / 8).min(most);
    let bricks = rng.between(least, most);
    let mut order: Vec<u32> = (0..columns).collect();
    for i in (1..order.len()).rev() {
        let j = rng.below(i as u32 + 1) as usize;
        order.swap(i, j);
    }
    let (brick_columns, rest) = order.split_at(bricks as usize);
    board.put(
        rest[0],
        top,
        Cell::Pickup(Pickup::new(PickupKind::ExtraBall)),
    );
    let other = PickupKind::ALL[1 + rng.below(11) as usize];
    board.put(rest[1], top, Cell::Pickup(Pickup::new(other)));
    if level >= 5 {
        for &column in &rest[2..] {
            if rng.chance(1, 8) {
                board.put(column, top, Cell::Obstacle);
            }
        }
    }
    for &column in brick_columns {
        let brick = draw_brick(level, rng);
        board.put(column, top, Cell::Brick(brick));
    }
}

/// One brick's shape and hit points.
fn draw_brick(level: u32, rng: &mut GameRng) -> Brick {
    let shape = if rng.chance(3, 4) {
        Shape::Square
    } else {
        Shape::Triangle(Corner::ALL[rng.below(4) as usize])
    };
    let hardness = level.clamp(1, 40);
    let roll = rng.below(160);
    let multiplier = if roll < hardness {
        3
    } else if roll < 3 * hardness {
        2
    } else {
        1
    };
    Brick {
        shape,
        hp: level.max(1).saturating_mul(multiplier),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_row_has_bricks_and_two_pickups_one_of_them_an_extra_ball() {
        let mut rng = GameRng::from_seed(5);
        for level in 1..200 {
            let mut board = Board::new(7, 9);
            spawn_row(&mut board, level, &mut rng);
            let row: Vec<Cell> = (0..7).filter_map(|c| board.get(c, 8)).collect();
            let pickups: Vec<PickupKind> = row
                .iter()
                .filter_map(|c| match c {
                    Cell::Pickup(p) => Some(p.kind),
                    _ => None,
                })
                .collect();
            assert_eq!(pickups.len(), 2);
            assert_eq!(
                pickups
                    .iter()
                    .filter(|&&k| k == PickupKind::ExtraBall)
                    .count(),
                1
            );
            let bricks: Vec<&Brick> = row.iter().filter_map(Cell::brick).collect();
            assert!(!bricks.is_empty() && bricks.len() <= 5);
            assert!(bricks.len() as u32 >= (1 + (level - 1) / 8).min(5));
            for b in bricks {
                assert!(
                    [level, 2 * level, 3 * level].contains(&b.hp),
                    "{level} {b:?}"
                );
            }
            assert!((0..8).all(|r| (0..7).all(|c| board.get(c, r) == Some(Cell::Empty))));
        }
    }

    #[test]
    fn hit_point_multipliers_follow_the_curve_at_level_40() {
        let mut rng = GameRng::from_seed(9);
        let mut counts = [0u32; 4];
        for _ in 0..16_000 {
            counts[(draw_brick(40, &mut rng).hp / 40) as usize] += 1;
        }
        // The curve at level 40: triple 40/160, double 80/160, single 40/160. With 16000
        // draws a share's standard deviation is under 0.004; 0.02 is five of them.
        let expect = [0.0, 0.25, 0.5, 0.25];
        for m in 1..4 {
            let share = f64::from(counts[m]) / 16_000.0;
            assert!((share - expect[m]).abs() < 0.02, "{m}: {share}");
        }
    }
}
