//! Text in the frames: glyph outlines of the game's typeface (Ubuntu, from
//! `epaint_default_fonts`, read with ttf-parser) filled and stroked by tiny-skia, so numbers are
//! anti-aliased at every cell size. The stroke thickens the light face to a bold weight that
//! stays readable on the bright bricks; text is fitted to a box (as large as it allows) and
//! placed at an anchor.

use tiny_skia::{FillRule, LineCap, LineJoin, Paint, PathBuilder, Pixmap, Stroke, Transform};
use ttf_parser::{Face, OutlineBuilder};

/// The stroke's width as a fraction of the cap height: Ubuntu Light's stems are about 0.09 of
/// it; adding 0.08 (0.04 each side) gives the weight of a bold face.
const EMBOLDEN: f32 = 0.08;

/// The typeface's bytes.
fn face() -> Option<Face<'static>> {
    Face::parse(epaint_default_fonts::UBUNTU_LIGHT, 0).ok()
}

/// Collects a glyph's outline into a path, in font units moved right by `dx` (y up).
struct Outline<'a> {
    path: &'a mut PathBuilder,
    dx: f32,
}

impl OutlineBuilder for Outline<'_> {
    fn move_to(&mut self, x: f32, y: f32) {
        self.path.move_to(x + self.dx, y);
    }
    fn line_to(&mut self, x: f32, y: f32) {
        self.path.line_to(x + self.dx, y);
    }
    fn quad_to(&mut self, x1: f32, y1: f32, x: f32, y: f32) {
        self.path.quad_to(x1 + self.dx, y1, x + self.dx, y);
    }
    fn curve_to(&mut self, x1: f32, y1: f32, x2: f32, y2: f32, x: f32, y: f32) {
        self.path
            .cubic_to(x1 + self.dx, y1, x2 + self.dx, y2, x + self.dx, y);
    }
    fn close(&mut self) {
        self.path.close();
    }
}

/// Which point of a text its anchor is, across: the left of its ink, its centre or its right.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Align {
    /// The anchor is the ink's left edge.
    Left,
    /// The anchor is the ink's centre.
    Centre,
    /// The anchor is the ink's right edge.
    Right,
}

/// Draws `text` at `anchor` (pixels, y down: the middle of its cap band, and across as
/// `align` says), as large as fits in `max_width` by `max_height` pixels (the height of a
/// capital or a digit, stroke included) in `paint`'s colour. Characters the typeface lacks
/// are skipped. `None` if there was nothing to draw.
pub fn draw(
    pixmap: &mut Pixmap,
    text: &str,
    anchor: (f32, f32),
    align: Align,
    max_width: f32,
    max_height: f32,
    paint: &Paint,
) -> Option<()> {
    let face = face()?;
    let mut builder = PathBuilder::new();
    let mut pen = 0.0f32;
    for ch in text.chars() {
        let Some(id) = face.glyph_index(ch) else {
            continue;
        };
        face.outline_glyph(
            id,
            &mut Outline {
                path: &mut builder,
                dx: pen,
            },
        );
        pen += f32::from(face.glyph_hor_advance(id).unwrap_or(0));
    }
    let path = builder.finish()?;
    let ink = path.bounds();
    let cap = f32::from(face.capital_height().filter(|&c| c > 0)?);
    // Pixels per font unit: the cap height (plus the stroke) fills `max_height` unless the
    // ink (plus the stroke) is wider than `max_width`.
    let grown = 1.0 + EMBOLDEN;
    let by_height = max_height / (cap * grown);
    let by_width = max_width / (ink.width() + cap * EMBOLDEN);
    let scale = by_height.min(by_width);
    if !(scale > 0.0 && scale.is_finite()) {
        return None;
    }
    // The ink's left, centre or right at the anchor, stroke included; the cap band (baseline
    // to cap height) centred on it vertically.
    let half = scale * cap * EMBOLDEN / 2.0;
    let tx = match align {
        Align::Left => anchor.0 + half - scale * ink.left(),
        Align::Centre => anchor.0 - scale * (ink.left() + ink.width() / 2.0),
        Align::Right => anchor.0 - half - scale * ink.right(),
    };
    let ty = anchor.1 + scale * cap / 2.0;
    let transform = Transform::from_row(scale, 0.0, 0.0, -scale, tx, ty);
    pixmap.fill_path(&path, paint, FillRule::Winding, transform, None);
    let stroke = Stroke {
        width: cap * EMBOLDEN,
        line_cap: LineCap::Round,
        line_join: LineJoin::Round,
        ..Stroke::default()
    };
    pixmap.stroke_path(&path, paint, &stroke, transform, None);
    Some(())
}
