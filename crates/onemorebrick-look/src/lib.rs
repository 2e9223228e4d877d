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

/// A count in at most four characters plus a suffix, for a brick or a ball count: below
/// 10,000 every digit ("9999"); above, three significant digits, cut (never rounded up, so a
/// brick never shows more hit points than it has) with `k`, `M` or `G`: "12.3k", "123k",
/// "1.23M", "4.29G".
pub fn compact(n: u32) -> String {
    if n < 10_000 {
        return n.to_string();
    }
    let (unit, suffix) = match n {
        0..1_000_000 => (1_000, 'k'),
        1_000_000..1_000_000_000 => (1_000_000, 'M'),
        _ => (1_000_000_000, 'G'),
    };
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
}
