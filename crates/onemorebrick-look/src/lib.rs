//! How One More Brick looks, in plain numbers every front end can use: the desktop game
//! (macroquad) and the frames of the Python environment (tiny-skia) draw the same board from
//! the same palette, write a brick's hit points at the same place and shorten big numbers the
//! same way. Colours are linear RGBA in `0..=1`; nothing here draws.

pub mod palette;

use onemorebrick::DVec2;
use onemorebrick::Shape;
use onemorebrick::cell::outline;

/// The centroid of a brick's outline: the cell centre for a square, the triangle's
/// centroid for a triangle (where its hit points are written, inside the triangle).
pub fn centroid(shape: Shape, origin: DVec2) -> DVec2 {
    let points = outline(shape, origin);
    if points.len() == 4 {
        return origin + DVec2::splat(0.5);
    }
    points.iter().copied().sum::<DVec2>() / points.len() as f64
}

/// The gap between neighbouring bricks, in cells: each brick is drawn moved this far inward.
pub const GAP: f64 = 0.05;

/// A brick's outline as drawn: its corners moved [`GAP`] toward its [`centroid`], so that
/// neighbours show a seam.
pub fn drawn_outline(shape: Shape, origin: DVec2) -> Vec<DVec2> {
    inset(&outline(shape, origin), centroid(shape, origin), GAP)
}

/// The outline moved `gap` inward toward `centre` (a corner nearer than that goes to it).
pub fn inset(points: &[DVec2], centre: DVec2, gap: f64) -> Vec<DVec2> {
    points
        .iter()
        .map(|p| {
            let d = *p - centre;
            let len = d.length();
            if len <= gap {
                centre
            } else {
                centre + d * ((len - gap) / len)
            }
        })
        .collect()
}

/// The clear space kept between a brick's number and its drawn edge, in cells.
pub const NUMBER_MARGIN: f64 = 0.045;

/// Whether `p` is at least `margin` inside the convex, counter-clockwise polygon `points`.
fn inside_by(points: &[DVec2], p: DVec2, margin: f64) -> bool {
    let n = points.len();
    (0..n).all(|i| {
        let (a, b) = (points[i], points[(i + 1) % n]);
        let edge = b - a;
        edge.perp_dot(p - a) / edge.length() >= margin
    })
}

/// The largest box of width-to-height `ratio`, centred on the brick's [`centroid`], that
/// fits inside its [`drawn_outline`] with [`NUMBER_MARGIN`] to spare: the room for its
/// number, as (width, height) in cells.
pub fn number_box(shape: Shape, ratio: f64) -> DVec2 {
    let ratio = if ratio.is_finite() && ratio > 0.0 {
        ratio
    } else {
        1.0
    };
    let c = centroid(shape, DVec2::ZERO);
    let drawn = drawn_outline(shape, DVec2::ZERO);
    let fits = |h: f64| {
        let half = DVec2::new(h * ratio, h) / 2.0;
        [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)]
            .iter()
            .all(|(sx, sy)| {
                inside_by(
                    &drawn,
                    c + DVec2::new(sx * half.x, sy * half.y),
                    NUMBER_MARGIN,
                )
            })
    };
    // Bisection on the height: a box that fits still fits when smaller (convexity).
    let (mut lo, mut hi) = (0.0, 1.0 / ratio.min(1.0));
    for _ in 0..50 {
        let mid = (lo + hi) / 2.0;
        if fits(mid) { lo = mid } else { hi = mid }
    }
    DVec2::new(lo * ratio, lo)
}

/// A count in at most four characters plus a suffix, for a brick or a ball count: below
/// 10,000 every digit ("9999"); above, three significant digits, cut (never rounded up, so a
/// brick never shows more hit points than it has) with `k`, `M` or `G`: "12.3k", "123k",
/// "1.23M", "4.29G".
pub fn compact(n: u32) -> String {
    compact_wide(u64::from(n))
}

/// [`compact`] for any `u64` (a score): past `G` come `T`, `P` and `E` ("18.4E" at most).
pub fn compact_wide(n: u64) -> String {
    if n < 10_000 {
        return n.to_string();
    }
    const UNITS: [(u64, char); 6] = [
        (1_000, 'k'),
        (1_000_000, 'M'),
        (1_000_000_000, 'G'),
        (1_000_000_000_000, 'T'),
        (1_000_000_000_000_000, 'P'),
        (1_000_000_000_000_000_000, 'E'),
    ];
    let (unit, suffix) = UNITS
        .iter()
        .rev()
        .copied()
        .find(|(unit, _)| n >= *unit)
        .unwrap_or(UNITS[0]);
    let whole = n / unit;
    let rest = n % unit;
    // Digits after the point so that three digits show in all.
    let decimals = match whole {
        0..10 => 2,
        10..100 => 1,
        _ => 0,
    };
    if decimals == 0 {
        return format!("{whole}{suffix}");
    }
    let scale = if decimals == 2 { unit / 100 } else { unit / 10 };
    let fraction = rest / scale;
    format!("{whole}.{fraction:0width$}{suffix}", width = decimals)
}

#[cfg(test)]
mod tests {
    use super::*;
    use onemorebrick::Corner;
    use onemorebrick::cell::distance_to_outline;

    #[test]
    fn small_counts_keep_every_digit() {
        for (n, s) in [
            (0, "0"),
            (7, "7"),
            (999, "999"),
            (1234, "1234"),
            (9999, "9999"),
        ] {
            assert_eq!(compact(n), s);
        }
    }

    #[test]
    fn big_counts_show_three_digits_cut_down() {
        let cases = [
            (10_000, "10.0k"),
            (12_345, "12.3k"),
            (99_999, "99.9k"),
            (100_000, "100k"),
            (999_999, "999k"),
            (1_000_000, "1.00M"),
            (1_239_999, "1.23M"),
            (12_345_678, "12.3M"),
            (999_999_999, "999M"),
            (1_005_000_000, "1.00G"),
            (u32::MAX, "4.29G"),
        ];
        for (n, s) in cases {
            assert_eq!(compact(n), s, "{n}");
        }
    }

    #[test]
    fn a_compact_count_never_exceeds_the_count() {
        // Read back: the shown value is at most the true one and within 1 % of it.
        for n in (10_000u32..u32::MAX - 7_777_777).step_by(7_777_777) {
            let s = compact(n);
            let (digits, suffix) = s.split_at(s.len() - 1);
            let unit = match suffix {
                "k" => 1e3,
                "M" => 1e6,
                "G" => 1e9,
                _ => panic!("{s}"),
            };
            let shown: f64 = digits.parse::<f64>().expect("a number") * unit;
            assert!(
                shown <= f64::from(n) + 1e-6 && shown > f64::from(n) * 0.99,
                "{n} {s}"
            );
            assert!(s.len() <= 5, "{s}");
        }
    }

    #[test]
    fn inset_moves_every_corner_inward() {
        let square = outline(Shape::Square, DVec2::ZERO);
        let centre = DVec2::splat(0.5);
        let inner = inset(&square, centre, 0.1);
        for (a, b) in square.iter().zip(&inner) {
            assert!((a.distance(centre) - b.distance(centre) - 0.1).abs() < 1e-12);
        }
    }

    #[test]
    fn a_triangles_number_sits_inside_the_triangle() {
        let origin = DVec2::new(2.0, 3.0);
        for corner in Corner::ALL {
            let shape = Shape::Triangle(corner);
            let c = centroid(shape, origin);
            let d = distance_to_outline(&outline(shape, origin), c);
            assert_eq!(d, 0.0, "{corner:?}");
            assert!(
                (c - (origin + DVec2::splat(0.5))).length() > 0.2,
                "{corner:?}"
            );
        }
        assert_eq!(centroid(Shape::Square, origin), DVec2::new(2.5, 3.5));
    }

    #[test]
    fn a_numbers_box_is_the_largest_inside_the_drawn_brick() {
        let corners = |b: DVec2, c: DVec2| {
            [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)]
                .map(|(x, y)| c + DVec2::new(x * b.x, y * b.y) / 2.0)
        };
        let mut shapes = vec![Shape::Square];
        shapes.extend(Corner::ALL.map(Shape::Triangle));
        for shape in shapes {
            let drawn = drawn_outline(shape, DVec2::ZERO);
            let c = centroid(shape, DVec2::ZERO);
            for ratio in [0.5, 1.0, 1.6, 3.0] {
                let b = number_box(shape, ratio);
                assert!((b.x / b.y - ratio).abs() < 1e-9);
                assert!(
                    corners(b, c)
                        .iter()
                        .all(|p| inside_by(&drawn, *p, NUMBER_MARGIN - 1e-9))
                );
                let bigger = b * 1.01;
                assert!(
                    !corners(bigger, c)
                        .iter()
                        .all(|p| inside_by(&drawn, *p, NUMBER_MARGIN))
                );
            }
        }
        // A square's room: the drawn side (0.93) less the margins.
        let side = 1.0 - 2.0 * GAP / 2f64.sqrt() - 2.0 * NUMBER_MARGIN;
        assert!((number_box(Shape::Square, 1.0).x - side).abs() < 1e-6);
        // A triangle's is smaller: a box of ratio r at its centroid has w + h <= 2/3.
        let t = number_box(Shape::Triangle(Corner::TopLeft), 1.0);
        assert!(t.x + t.y < 2.0 / 3.0 && t.x > 0.2, "{t:?}");
    }

    #[test]
    fn wide_counts_go_on_past_giga() {
        let cases = [
            (9_999, "9999"),
            (123_456, "123k"),
            (4_294_967_295, "4.29G"),
            (12_345_678_901_234, "12.3T"),
            (999_999_999_999_999, "999T"),
            (1_234_567_890_123_456, "1.23P"),
            (u64::MAX, "18.4E"),
        ];
        for (n, s) in cases {
            assert_eq!(compact_wide(n), s, "{n}");
        }
    }
}
