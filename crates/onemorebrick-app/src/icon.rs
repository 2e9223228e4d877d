//! `onemorebrick icon`: the game's icon, drawn from the palette without a window: on the
//! board's colour, three rows of bricks in the ramp's colours (hot at the top), a ball and
//! its aim's dots. The web build's favicon, home-screen icon and manifest icons
//! (`web/build.sh`); square, opaque, with the picture inside the middle 80 % (the part a
//! "maskable" icon keeps).

use std::path::PathBuf;

use clap::Args;
use onemorebrick_look::palette::{self as look, Rgba};

/// Samples per pixel along each axis (the edges are antialiased by averaging them).
const SUPERSAMPLE: u32 = 4;

/// Arguments of `onemorebrick icon`.
#[derive(Args, Debug)]
pub struct IconArgs {
    /// Width and height in pixels (16 to 2048).
    #[arg(long, default_value_t = 512, value_parser = clap::value_parser!(u32).range(16..=2048), allow_negative_numbers = true)]
    pub size: u32,
    /// The PNG file to write.
    #[arg(long)]
    pub out: PathBuf,
}

/// A brick of the icon: its column and row (0 at the top) on a 4 x 4 grid and its ramp
/// colour.
const BRICKS: [(u32, u32, usize); 7] = [
    (0, 0, 6),
    (1, 0, 5),
    (3, 0, 6),
    (0, 1, 4),
    (2, 1, 3),
    (3, 1, 5),
    (1, 2, 1),
];

/// The colour at `(x, y)` of the unit square (y down).
fn shade(x: f64, y: f64) -> Rgba {
    // The picture: a 4 x 4 grid in the middle 80 % of the square.
    let (gx, gy) = ((x - 0.1) / 0.8 * 4.0, (y - 0.1) / 0.8 * 4.0);
    for (column, row, ramp) in BRICKS {
        let (u, v) = (gx - f64::from(column), gy - f64::from(row));
        if (0.06..0.94).contains(&u) && (0.06..0.94).contains(&v) {
            return look::RAMP[ramp];
        }
    }
    let ball = (2.6, 3.55);
    let near = |p: (f64, f64), r: f64| (gx - p.0).powi(2) + (gy - p.1).powi(2) < r * r;
    if near(ball, 0.3) {
        return look::BALL;
    }
    // The aim: dots from the ball up toward the gap in the bricks.
    for k in 1..=4 {
        let t = f64::from(k) * 0.45;
        if near((ball.0 - 0.35 * t, ball.1 - t), 0.07) {
            return look::mix(look::BOARD, look::TEXT, look::PREVIEW[3]);
        }
    }
    look::BOARD
}

/// The icon's RGBA pixels, top row first.
pub fn render(size: u32) -> Vec<u8> {
    let mut out = Vec::with_capacity(size as usize * size as usize * 4);
    let n = f64::from(SUPERSAMPLE);
    for py in 0..size {
        for px in 0..size {
            let mut sum = [0.0f32; 3];
            for sy in 0..SUPERSAMPLE {
                for sx in 0..SUPERSAMPLE {
                    let x = (f64::from(px) + (f64::from(sx) + 0.5) / n) / f64::from(size);
                    let y = (f64::from(py) + (f64::from(sy) + 0.5) / n) / f64::from(size);
                    let c = shade(x, y);
                    for (s, v) in sum.iter_mut().zip(c) {
                        *s += v;
                    }
                }
            }
            let samples = (SUPERSAMPLE * SUPERSAMPLE) as f32;
            out.extend(sum.map(|s| (s / samples * 255.0).round().clamp(0.0, 255.0) as u8));
            out.push(255);
        }
    }
    out
}

/// Writes the icon.
pub fn run(args: &IconArgs) -> Result<(), String> {
    let row = args.size as usize * 4;
    let top_first = render(args.size);
    let bottom_first: Vec<u8> = top_first
        .chunks_exact(row)
        .rev()
        .flatten()
        .copied()
        .collect();
    crate::screenshot::write_png(&args.out, args.size, args.size, &bottom_first, &[])?;
    println!("wrote {} ({}x{})", args.out.display(), args.size, args.size);
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn pixel(image: &[u8], size: u32, x: u32, y: u32) -> [u8; 3] {
        let i = (y * size + x) as usize * 4;
        [image[i], image[i + 1], image[i + 2]]
    }

    fn rgb(c: Rgba) -> [u8; 3] {
        [c[0], c[1], c[2]].map(|v| (v * 255.0).round() as u8)
    }

    #[test]
    fn the_icon_shows_the_hottest_brick_top_left_on_the_board() {
        let size = 64;
        let image = render(size);
        assert_eq!(image.len(), 64 * 64 * 4);
        // The middle of the top-left brick: grid cell (0, 0), at 0.1 + 0.8 * 0.5 / 4.
        let at = (0.2 * 64.0) as u32;
        assert_eq!(pixel(&image, size, at, at), rgb(look::RAMP[6]));
        assert_eq!(pixel(&image, size, 1, 1), rgb(look::BOARD), "the margin");
        assert!(image.chunks_exact(4).all(|p| p[3] == 255), "opaque");
    }
}
