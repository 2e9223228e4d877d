//! The pick-ups' icons: small drawn shapes in each kind's colour (`onemorebrick_look`), no
//! letters, so none reads like a HUD label ("x2" was both the split and the speed). One
//! function draws an icon in a circle; the board and the help screen both call it.
//!
//! | kind | icon |
//! | --- | --- |
//! | +1 ball | a bold plus |
//! | split | a ball's path forking in two, a ball at each end |
//! | hazard | a ball struck through (the ball leaves play) |
//! | floor bounce | a path bouncing off a floor bar, arrow up |
//! | lasers | double arrows along the row, the column, or both |
//! | random direction | a die |
//! | bigger / smaller | a ball with arrows pointing out / in |
//! | boost | a lightning bolt |
//! | shield | a shield |

use macroquad::color::Color;
use macroquad::math::Vec2;
use macroquad::shapes::{
    draw_circle, draw_circle_lines, draw_line, draw_rectangle_lines, draw_triangle,
};
use onemorebrick::{DVec2, Pickup, PickupKind};
use onemorebrick_look as look;

use crate::layout::Layout;
use crate::palette;

/// How strongly a used pick-up (gone at the end of the round) is drawn.
const USED_ALPHA: f32 = 0.35;

/// A kind's colour (`onemorebrick_look::palette::pickup`).
pub fn colour(kind: PickupKind) -> Color {
    palette::color(look::palette::pickup(kind).0)
}

/// Draws a pick-up of the board in its cell, its icon the size of its sensor circle.
pub fn draw_on_board(layout: &Layout, pickup: &Pickup, origin: DVec2, radius: f64) {
    let centre = layout.to_screen(origin + DVec2::splat(0.5));
    let alpha = if pickup.used { USED_ALPHA } else { 1.0 };
    draw_icon(pickup.kind, centre, layout.px(radius), alpha);
}

/// Draws `kind`'s icon in the circle of radius `r` around `centre`, at opacity `alpha`: a
/// faint disc and a ring (the sensor's extent) and the kind's shape inside.
pub fn draw_icon(kind: PickupKind, centre: Vec2, r: f32, alpha: f32) {
    let c = palette::with_alpha(colour(kind), alpha);
    draw_circle(centre.x, centre.y, r, palette::with_alpha(c, 0.18 * alpha));
    draw_circle_lines(centre.x, centre.y, r, (r * 0.1).max(1.2), c);
    let pen = Pen {
        centre,
        r,
        width: (r * 0.16).max(1.5),
        colour: c,
    };
    match kind {
        PickupKind::ExtraBall => plus(&pen),
        PickupKind::Split => split(&pen),
        PickupKind::Hazard => struck_ball(&pen),
        PickupKind::FloorBounce => floor_bounce(&pen),
        PickupKind::LaserHorizontal => double_arrow(&pen, Vec2::X),
        PickupKind::LaserVertical => double_arrow(&pen, Vec2::Y),
        PickupKind::LaserCross => {
            double_arrow(&pen, Vec2::X);
            double_arrow(&pen, Vec2::Y);
        }
        PickupKind::RandomDirection => die(&pen),
        PickupKind::Bigger => arrows_around(&pen, 0.26, true),
        PickupKind::Smaller => arrows_around(&pen, 0.15, false),
        PickupKind::Boost => bolt(&pen),
        PickupKind::Shield => shield(&pen),
    }
}

/// Where and how an icon is drawn: points are given in units of the icon's radius, y down.
struct Pen {
    centre: Vec2,
    r: f32,
    width: f32,
    colour: Color,
}

impl Pen {
    fn at(&self, x: f32, y: f32) -> Vec2 {
        self.centre + Vec2::new(x, y) * self.r
    }

    fn line(&self, a: (f32, f32), b: (f32, f32)) {
        let (a, b) = (self.at(a.0, a.1), self.at(b.0, b.1));
        draw_line(a.x, a.y, b.x, b.y, self.width, self.colour);
    }

    fn dot(&self, x: f32, y: f32, radius: f32) {
        let p = self.at(x, y);
        draw_circle(p.x, p.y, radius * self.r, self.colour);
    }

    fn triangle(&self, a: Vec2, b: Vec2, c: Vec2) {
        draw_triangle(
            self.at(a.x, a.y),
            self.at(b.x, b.y),
            self.at(c.x, c.y),
            self.colour,
        );
    }

    /// A filled arrowhead with its tip at `tip`, pointing along `dir` (a unit vector).
    fn head(&self, tip: Vec2, dir: Vec2, length: f32, half_width: f32) {
        let base = tip - dir * length;
        let side = dir.perp() * half_width;
        self.triangle(tip, base + side, base - side);
    }
}

fn plus(pen: &Pen) {
    let w = pen.width * 1.5;
    let (a, b) = (pen.at(-0.55, 0.0), pen.at(0.55, 0.0));
    draw_line(a.x, a.y, b.x, b.y, w, pen.colour);
    let (a, b) = (pen.at(0.0, -0.55), pen.at(0.0, 0.55));
    draw_line(a.x, a.y, b.x, b.y, w, pen.colour);
}

fn split(pen: &Pen) {
    pen.line((0.0, 0.55), (0.0, 0.05));
    pen.line((0.0, 0.05), (-0.42, -0.4));
    pen.line((0.0, 0.05), (0.42, -0.4));
    for (x, y) in [(-0.42, -0.4), (0.42, -0.4), (0.0, 0.55)] {
        pen.dot(x, y, 0.15);
    }
}

fn struck_ball(pen: &Pen) {
    pen.dot(0.0, 0.0, 0.34);
    let (a, b) = (pen.at(-0.62, -0.62), pen.at(0.62, 0.62));
    let board = palette::with_alpha(palette::BOARD, pen.colour.a);
    draw_line(a.x, a.y, b.x, b.y, pen.width * 2.4, board);
    draw_line(a.x, a.y, b.x, b.y, pen.width, pen.colour);
}

fn floor_bounce(pen: &Pen) {
    pen.line((-0.6, 0.5), (0.6, 0.5));
    pen.line((-0.5, -0.35), (0.0, 0.32));
    pen.line((0.0, 0.32), (0.38, -0.18));
    let dir = Vec2::new(0.5, -0.67).normalize();
    pen.head(Vec2::new(0.52, -0.38), dir, 0.3, 0.2);
}

fn double_arrow(pen: &Pen, dir: Vec2) {
    let (a, b) = (dir * -0.4, dir * 0.4);
    pen.line((a.x, a.y), (b.x, b.y));
    pen.head(dir * 0.72, dir, 0.34, 0.24);
    pen.head(dir * -0.72, -dir, 0.34, 0.24);
}

fn die(pen: &Pen) {
    let corner = pen.at(-0.5, -0.5);
    let side = pen.r;
    draw_rectangle_lines(corner.x, corner.y, side, side, pen.width, pen.colour);
    for (x, y) in [(-0.24, -0.24), (0.0, 0.0), (0.24, 0.24)] {
        pen.dot(x, y, 0.1);
    }
}

/// A ball of `radius` with four arrows pointing away from it (`out`) or at it.
fn arrows_around(pen: &Pen, radius: f32, out: bool) {
    pen.dot(0.0, 0.0, radius);
    for dir in [Vec2::X, Vec2::Y, -Vec2::X, -Vec2::Y] {
        if out {
            pen.head(dir * 0.74, dir, 0.3, 0.2);
        } else {
            pen.head(dir * (radius + 0.1), -dir, 0.3, 0.2);
        }
    }
}

fn bolt(pen: &Pen) {
    let v = Vec2::new;
    pen.triangle(v(0.22, -0.72), v(-0.36, 0.12), v(0.12, 0.04));
    pen.triangle(v(-0.22, 0.72), v(0.36, -0.12), v(-0.12, -0.04));
}

fn shield(pen: &Pen) {
    let v = Vec2::new;
    let outline = [
        v(-0.5, -0.55),
        v(0.5, -0.55),
        v(0.5, 0.05),
        v(0.0, 0.66),
        v(-0.5, 0.05),
    ];
    let middle = v(0.0, -0.05);
    for k in 0..outline.len() {
        pen.triangle(middle, outline[k], outline[(k + 1) % outline.len()]);
    }
}
