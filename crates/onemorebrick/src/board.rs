//! The grid of cells: row 0 is the launcher's row at the bottom, new rows enter at the top.

use exact2d::DVec2;
use serde::{Deserialize, Serialize};

use crate::GameError;
use crate::cell::{Brick, Cell};
use crate::pickup::PickupKind;

/// A `columns x rows` grid of cells, stored row by row from the bottom.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct Board {
    columns: u32,
    rows: u32,
    cells: Vec<Cell>,
}

/// What moving the rows down did.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct ShiftOutcome {
    /// A brick arrived in the bottom row: the game is over.
    pub brick_reached_bottom: bool,
    /// +1 pick-ups that arrived in the bottom row (they are granted).
    pub extra_balls: u32,
}

impl Board {
    /// An empty board.
    #[must_use]
    pub fn new(columns: u32, rows: u32) -> Self {
        Self {
            columns,
            rows,
            cells: vec![Cell::Empty; (columns * rows) as usize],
        }
    }

    /// Number of columns.
    #[must_use]
    pub fn columns(&self) -> u32 {
        self.columns
    }

    /// Number of rows.
    #[must_use]
    pub fn rows(&self) -> u32 {
        self.rows
    }

    /// The index of cell `(column, row)` in [`cells`](Self::cells); `None` outside the board.
    #[must_use]
    pub fn index(&self, column: u32, row: u32) -> Option<usize> {
        (column < self.columns && row < self.rows).then_some((row * self.columns + column) as usize)
    }

    /// The `(column, row)` of a cell index.
    #[must_use]
    pub fn position(&self, index: usize) -> (u32, u32) {
        let index = index as u32;
        (index % self.columns, index / self.columns)
    }

    /// The lower-left corner of a cell in board coordinates.
    #[must_use]
    pub fn origin(&self, index: usize) -> DVec2 {
        let (c, r) = self.position(index);
        DVec2::new(f64::from(c), f64::from(r))
    }

    /// Every cell, row by row from the bottom.
    #[must_use]
    pub fn cells(&self) -> &[Cell] {
        &self.cells
    }

    /// The cell at `(column, row)`; `None` outside the board.
    #[must_use]
    pub fn get(&self, column: u32, row: u32) -> Option<Cell> {
        self.index(column, row).map(|i| self.cells[i])
    }

    /// Puts `cell` at `(column, row)`.
    ///
    /// # Errors
    /// [`GameError::InvalidState`] if the cell is outside the board.
    pub fn set(&mut self, column: u32, row: u32, cell: Cell) -> Result<(), GameError> {
        let i = self.index(column, row).ok_or_else(|| {
            GameError::InvalidState(format!(
                "cell ({column}, {row}) is outside the {} x {} board",
                self.columns, self.rows
            ))
        })?;
        self.cells[i] = cell;
        Ok(())
    }

    /// Puts `cell` at an in-range `(column, row)` (the spawn's cells always are).
    pub(crate) fn put(&mut self, column: u32, row: u32, cell: Cell) {
        self.cells[(row * self.columns + column) as usize] = cell;
    }

    pub(crate) fn cell_mut(&mut self, index: usize) -> &mut Cell {
        &mut self.cells[index]
    }

    /// The bricks, with their cell indices, in cell order.
    pub fn bricks(&self) -> impl Iterator<Item = (usize, &Brick)> {
        self.cells
            .iter()
            .enumerate()
            .filter_map(|(i, c)| c.brick().map(|b| (i, b)))
    }

    /// The sum of every brick's hit points.
    #[must_use]
    pub fn total_hp(&self) -> u64 {
        self.bricks().map(|(_, b)| u64::from(b.hp)).sum()
    }

    /// Whether no brick is left.
    #[must_use]
    pub fn is_clear(&self) -> bool {
        self.bricks().next().is_none()
    }

    /// Removes every used pick-up (the end of a round).
    pub fn remove_used_pickups(&mut self) {
        for cell in &mut self.cells {
            if matches!(cell, Cell::Pickup(p) if p.used) {
                *cell = Cell::Empty;
            }
        }
    }

    /// Moves every row down one step; the top row becomes empty. What arrives in the bottom
    /// row is settled there: a brick ends the game, a +1 pick-up is granted, any other
    /// pick-up and an obstacle leave (the launcher's row stays free for balls).
    pub fn shift_down(&mut self) -> ShiftOutcome {
        let width = self.columns as usize;
        self.cells.drain(..width);
        self.cells.extend(std::iter::repeat_n(Cell::Empty, width));
        let mut outcome = ShiftOutcome::default();
        for cell in &mut self.cells[..width] {
            match cell {
                Cell::Brick(_) => outcome.brick_reached_bottom = true,
                Cell::Pickup(p) => {
                    if p.kind == PickupKind::ExtraBall {
                        outcome.extra_balls += 1;
                    }
                    *cell = Cell::Empty;
                }
                Cell::Obstacle => *cell = Cell::Empty,
                Cell::Empty => {}
            }
        }
        outcome
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::cell::Shape;
    use crate::pickup::Pickup;

    #[test]
    fn shift_moves_rows_down_and_settles_the_bottom_row() {
        let mut board = Board::new(3, 3);
        let brick = Cell::Brick(Brick {
            shape: Shape::Square,
            hp: 2,
        });
        board.set(0, 2, brick).unwrap();
        board
            .set(1, 1, Cell::Pickup(Pickup::new(PickupKind::ExtraBall)))
            .unwrap();
        board.set(2, 1, Cell::Obstacle).unwrap();
        assert!(board.set(3, 0, brick).is_err(), "outside the board");
        assert_eq!(board.get(0, 3), None);
        let outcome = board.shift_down();
        assert_eq!(board.get(0, 1), Some(brick));
        assert_eq!(board.get(1, 0), Some(Cell::Empty));
        assert_eq!(board.get(2, 0), Some(Cell::Empty));
        assert_eq!(outcome.extra_balls, 1);
        assert!(!outcome.brick_reached_bottom);
        assert!(board.shift_down().brick_reached_bottom);
    }
}
