//! `onemorebrick bricks`: where a new game's bricks are drawn on a screen of a given size,
//! and in which colour, worked out from the rules and the layout alone (no window): one
//! JSON line per brick, `{"column", "row", "hp", "x", "y", "rgb"}`, with `(x, y)` a point
//! well inside the drawn brick and clear of its number, in the screen's pixels (CSS pixels
//! in a browser). The browser test (`web/test/browser.mjs`) looks for these colours there
//! on the page's canvas.

use std::io::Write;

use clap::Args;
use onemorebrick::{Config, DVec2, Game};
use onemorebrick_look::{self as look, palette};

use crate::failure::Failure;
use crate::layout::Layout;

/// How far from a brick's centroid toward its outline the point is, as a share of the way:
/// past the number (a square's is at most 0.275 cells tall, half the outline's 0.465 at
/// the corners) and clear of the antialiased edge.
const TOWARD_OUTLINE: f64 = 0.8;

/// Arguments of `onemorebrick bricks`.
#[derive(Args, Debug)]
pub struct BricksArgs {
    /// The new game's seed.
    #[arg(long, value_parser = crate::parse_seed, allow_negative_numbers = true)]
    pub seed: u64,
    /// The screen's width in pixels (1 to 100000).
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=100_000))]
    pub width: u32,
    /// The screen's height in pixels (1 to 100000).
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=100_000))]
    pub height: u32,
}

/// Distance from `p` to the segment `a`-`b`.
fn to_segment(p: DVec2, a: DVec2, b: DVec2) -> f64 {
    let ab = b - a;
    let t = ((p - a).dot(ab) / ab.length_squared()).clamp(0.0, 1.0);
    (a + ab * t - p).length()
}

/// The point of a brick (its drawn outline, convex, and its centroid) looked at: of the
/// points [`TOWARD_OUTLINE`] of the way from the centroid to each corner, the farthest from
/// every edge.
pub fn sample_point(outline: &[DVec2], centroid: DVec2) -> DVec2 {
    let clearance = |p: DVec2| {
        (0..outline.len())
            .map(|i| to_segment(p, outline[i], outline[(i + 1) % outline.len()]))
            .fold(f64::INFINITY, f64::min)
    };
    outline
        .iter()
        .map(|&corner| centroid + (corner - centroid) * TOWARD_OUTLINE)
        .max_by(|a, b| clearance(*a).total_cmp(&clearance(*b)))
        .unwrap_or(centroid)
}

/// Prints the bricks of a new game with `args.seed`.
pub fn run(args: &BricksArgs) -> Result<(), Failure> {
    let game = Game::new(Config::default(), args.seed)?;
    let board = game.board();
    let layout = Layout::new(
        args.width as f32,
        args.height as f32,
        board.columns(),
        board.rows(),
    );
    let top = palette::ramp_top(board, game.state().level());
    let mut out = std::io::stdout().lock();
    for (i, cell) in board.cells().iter().enumerate() {
        let onemorebrick::Cell::Brick(brick) = cell else {
            continue;
        };
        let origin = board.origin(i);
        let outline = look::drawn_outline(brick.shape, origin);
        let point = layout.to_screen(sample_point(&outline, look::centroid(brick.shape, origin)));
        let colour = palette::brick(brick.hp, top);
        let rgb = [colour[0], colour[1], colour[2]].map(|c| (c * 255.0).round() as u8);
        let line = serde_json::json!({
            "column": origin.x as u32,
            "row": origin.y as u32,
            "hp": brick.hp,
            "x": point.x,
            "y": point.y,
            "rgb": rgb,
        });
        writeln!(out, "{line}")?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use onemorebrick::{Corner, Shape};

    #[test]
    fn a_square_is_looked_at_near_a_corner_clear_of_its_number() {
        let origin = DVec2::new(2.0, 3.0);
        let outline = look::drawn_outline(Shape::Square, origin);
        let c = look::centroid(Shape::Square, origin);
        let p = sample_point(&outline, c) - c;
        // Past the number's half height (0.275 cells), inside the drawn half side (0.45).
        assert!(p.y.abs() > 0.3 && p.y.abs() < 0.42, "{p}");
        assert!(p.x.abs() > 0.3 && p.x.abs() < 0.42, "{p}");
    }

    #[test]
    fn a_triangle_is_looked_at_inside_it() {
        for corner in Corner::ALL {
            let shape = Shape::Triangle(corner);
            let origin = DVec2::ZERO;
            let outline = look::drawn_outline(shape, origin);
            let p = sample_point(&outline, look::centroid(shape, origin));
            // Inside the convex outline: on the same side of every edge as the centroid.
            let c = look::centroid(shape, origin);
            for i in 0..outline.len() {
                let (a, b) = (outline[i], outline[(i + 1) % outline.len()]);
                let side = |q: DVec2| (b - a).perp_dot(q - a);
                assert!(side(p) * side(c) > 0.0, "{corner:?}: {p}");
                assert!(to_segment(p, a, b) > 0.04, "{corner:?}: clear of the edge");
            }
        }
    }
}
