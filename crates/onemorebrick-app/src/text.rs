//! Every text of the window, in one typeface: Ubuntu (Light, from `epaint_default_fonts`, the
//! Ubuntu Font Licence 1.0), loaded once. Text is laid out here (glyph positions and the box
//! its ink covers, from the font's own metrics), fitted to boxes, and drawn through macroquad
//! glyph by glyph.
//!
//! Crisp at any size and DPI: glyphs are rasterised at the physical pixel size (the size in
//! logical pixels times the screen's DPI scale; macroquad does the multiplication) and every
//! glyph's pen position is snapped to a physical pixel, so a glyph's bitmap lands texel for
//! pixel on the screen, anti-aliased by the rasteriser's coverage and never resampled (except
//! horizontally when a style is condensed). A bold weight is drawn as copies of the light one
//! moved by whole physical pixels, so its edges keep their coverage.

use std::cell::OnceCell;
use std::sync::OnceLock;

use macroquad::color::Color;
use macroquad::math::{Rect, Vec2};
use macroquad::text::{Font, TextParams, draw_text_ex, load_ttf_font_from_bytes, set_default_font};
use macroquad::window::screen_dpi_scale;

/// The typeface's file.
const TYPEFACE: &[u8] = epaint_default_fonts::UBUNTU_LIGHT;
/// The smallest size drawn, in logical pixels.
pub const MIN_SIZE: f32 = 6.0;
/// The largest size drawn, in logical pixels.
pub const MAX_SIZE: f32 = 400.0;
/// How far a bold copy is moved, as a share of the size (horizontally; half of it
/// vertically): Ubuntu Light's stems are about 0.07 of the size wide, a bold one about 0.13.
const BOLD: f32 = 0.06;

/// How text looks: its size, weight and shape.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Style {
    /// The size (the em) in logical pixels; drawn at a whole number of them.
    pub size: f32,
    /// Drawn bold (copies of the light weight, moved by whole pixels).
    pub bold: bool,
    /// Horizontal scale of the glyphs (1 is the typeface's own shape, less is condensed).
    pub aspect: f32,
    /// Extra space after each glyph, as a share of the size (negative pulls them together).
    pub tracking: f32,
}

impl Style {
    /// The typeface as it is, at `size` pixels.
    pub const fn regular(size: f32) -> Self {
        Self {
            size,
            bold: false,
            aspect: 1.0,
            tracking: 0.0,
        }
    }

    /// Bold, at `size` pixels.
    pub const fn bold(size: f32) -> Self {
        Self {
            bold: true,
            ..Self::regular(size)
        }
    }

    /// The same style at another size.
    pub const fn at(self, size: f32) -> Self {
        Self { size, ..self }
    }

    /// The whole number of logical pixels the size is drawn at.
    pub fn pixels(&self) -> u16 {
        self.size.round().clamp(MIN_SIZE, MAX_SIZE) as u16
    }
}

/// The box a text's ink covers, relative to the pen's start on the baseline, in logical
/// pixels, y down (so `top` is negative for glyphs above the baseline).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Ink {
    /// Left edge.
    pub left: f32,
    /// Right edge.
    pub right: f32,
    /// Top edge.
    pub top: f32,
    /// Bottom edge.
    pub bottom: f32,
}

impl Ink {
    /// Its width.
    pub fn width(&self) -> f32 {
        self.right - self.left
    }

    /// Its height.
    pub fn height(&self) -> f32 {
        self.bottom - self.top
    }

    /// Its centre.
    pub fn centre(&self) -> Vec2 {
        Vec2::new(
            (self.left + self.right) / 2.0,
            (self.top + self.bottom) / 2.0,
        )
    }

    fn cover(self, other: Ink) -> Ink {
        Ink {
            left: self.left.min(other.left),
            right: self.right.max(other.right),
            top: self.top.min(other.top),
            bottom: self.bottom.max(other.bottom),
        }
    }
}

/// A laid-out text: each glyph with its pen offset from the start (logical pixels, on
/// physical pixels), and the ink's box.
#[derive(Clone, Debug, PartialEq)]
pub struct Laid {
    /// Each character and its pen's x offset.
    pub glyphs: Vec<(char, f32)>,
    /// The box the ink covers.
    pub ink: Ink,
    /// How far bold copies reach (logical pixels), right and down; 0 when not bold.
    pub bold_reach: f32,
}

/// The typeface's outlines and metrics, parsed once (for layout, with no window needed).
fn metrics_font() -> &'static fontdue::Font {
    static FONT: OnceLock<fontdue::Font> = OnceLock::new();
    FONT.get_or_init(|| {
        fontdue::Font::from_bytes(TYPEFACE, fontdue::FontSettings::default())
            .expect("the bundled Ubuntu typeface parses")
    })
}

/// Snaps a logical length to whole physical pixels.
fn snap(x: f32, dpi: f32) -> f32 {
    (x * dpi).round() / dpi
}

/// Lays `text` out in `style` for a screen of DPI scale `dpi` (pure: the same numbers
/// macroquad draws with, since both rasterise the same font at the same pixel size).
pub fn lay_out(text: &str, style: &Style, dpi: f32) -> Laid {
    let dpi = if dpi.is_finite() && dpi > 0.0 {
        dpi
    } else {
        1.0
    };
    let font = metrics_font();
    let size = f32::from(style.pixels());
    // What macroquad rasterises at: the logical size in physical pixels, rounded up.
    let raster = (size * dpi).ceil();
    let aspect = style.aspect.clamp(0.25, 4.0);
    let mut glyphs = Vec::with_capacity(text.len());
    let mut ink: Option<Ink> = None;
    let mut pen = 0.0f32;
    let mut last = None;
    for c in text.chars() {
        let kern = last
            .and_then(|l| font.horizontal_kern(l, c, raster))
            .unwrap_or(0.0);
        pen = snap(pen + kern * aspect / dpi, dpi);
        let m = font.metrics(c, raster);
        glyphs.push((c, pen));
        if m.width > 0 && m.height > 0 {
            let left = pen + m.xmin as f32 * aspect / dpi;
            let glyph = Ink {
                left,
                right: left + m.width as f32 * aspect / dpi,
                top: -((m.ymin + m.height as i32) as f32) / dpi,
                bottom: -(m.ymin as f32) / dpi,
            };
            ink = Some(ink.map_or(glyph, |i| i.cover(glyph)));
        }
        pen += m.advance_width * aspect / dpi + style.tracking * size;
        last = Some(c);
    }
    let mut ink = ink.unwrap_or_default();
    let bold_reach = if style.bold {
        bold_step(size, dpi)
    } else {
        0.0
    };
    ink.right += bold_reach;
    ink.bottom += bold_reach / 2.0;
    Laid {
        glyphs,
        ink,
        bold_reach,
    }
}

/// How far the bold copies reach, in whole physical pixels (at least one).
fn bold_step(size: f32, dpi: f32) -> f32 {
    (size * BOLD * dpi).round().max(1.0) / dpi
}

/// The box `text`'s ink covers in `style` on this screen.
pub fn measure(text: &str, style: &Style) -> Ink {
    lay_out(text, style, screen_dpi_scale()).ink
}

/// The largest whole pixel size from `min` to `max` at which `fits` holds, assuming it
/// holds for every size below one where it holds; `min` if none does. `fits` is asked
/// about a few sizes only: it starts from `guess` (clamped to the range) and steps.
pub fn largest_size(min: f32, max: f32, guess: f32, fits: impl Fn(f32) -> bool) -> f32 {
    let (min, max) = (min.round(), max.round().max(min.round()));
    let mut size = guess.round().clamp(min, max);
    while size > min && !fits(size) {
        size -= 1.0;
    }
    while size < max && fits(size + 1.0) {
        size += 1.0;
    }
    size
}

/// `style` at the largest size up to its own whose ink fits `width x height` on a screen of
/// DPI scale `dpi` (at least [`MIN_SIZE`]). When `min_aspect` is below the style's aspect,
/// the glyphs are first condensed, down to it, before the size shrinks.
pub fn fit_style(
    text: &str,
    style: Style,
    width: f32,
    height: f32,
    min_aspect: f32,
    dpi: f32,
) -> Style {
    let ink = |s: &Style| lay_out(text, s, dpi).ink;
    let fits = |s: &Style| {
        let i = ink(s);
        i.width() <= width && i.height() <= height
    };
    // Condense to the width, if allowed, at the size the height allows.
    let tall = {
        let at_max = ink(&style);
        let guess = style.size * (height / at_max.height().max(1e-3)).min(1.0);
        style.at(largest_size(MIN_SIZE, style.size, guess, |s| {
            ink(&style.at(s)).height() <= height
        }))
    };
    let mut shaped = tall;
    let w = ink(&tall).width();
    if w > width && min_aspect < style.aspect {
        shaped.aspect = (style.aspect * width / w).max(min_aspect);
        // Ink does not scale exactly with the aspect (pixel rounding): step down until it fits.
        while !fits(&shaped) && shaped.aspect > min_aspect {
            shaped.aspect = (shaped.aspect - 0.01).max(min_aspect);
        }
    }
    let guess = {
        let i = ink(&shaped);
        let k = (width / i.width().max(1e-3)).min(height / i.height().max(1e-3));
        shaped.size * k.min(1.0)
    };
    shaped.at(largest_size(MIN_SIZE, shaped.size, guess, |s| {
        fits(&shaped.at(s))
    }))
}

/// `style` fitted to `width x height` on this screen (see [`fit_style`]).
pub fn fit(text: &str, style: Style, width: f32, height: f32, min_aspect: f32) -> Style {
    fit_style(text, style, width, height, min_aspect, screen_dpi_scale())
}

thread_local! {
    /// The typeface in macroquad (its glyph atlas lives in the window's GL context).
    static FONT: OnceCell<Font> = const { OnceCell::new() };
}

/// Runs `f` with the loaded typeface (loaded on first use, and made macroquad's default so
/// that nothing falls back to its built-in pixel font).
fn with_font<R>(f: impl FnOnce(&Font) -> R) -> R {
    FONT.with(|cell| {
        let font = cell.get_or_init(|| {
            let font =
                load_ttf_font_from_bytes(TYPEFACE).expect("the bundled Ubuntu typeface loads");
            set_default_font(font.clone());
            font
        });
        f(font)
    })
}

/// Draws `text` in `style` with its pen starting at `origin` on the baseline; returns the
/// screen box its ink covers.
pub fn draw(text: &str, origin: Vec2, style: &Style, colour: Color) -> Rect {
    let dpi = screen_dpi_scale();
    let laid = lay_out(text, style, dpi);
    let origin = Vec2::new(snap(origin.x, dpi), snap(origin.y, dpi));
    let step = 1.0 / dpi;
    let copies = |reach: f32| (reach * dpi).round() as u32;
    with_font(|font| {
        let params = TextParams {
            font: Some(font),
            font_size: style.pixels(),
            font_scale: 1.0,
            font_scale_aspect: style.aspect.clamp(0.25, 4.0),
            rotation: 0.0,
            color: colour,
        };
        let mut buf = [0u8; 4];
        for (c, x) in &laid.glyphs {
            let s: &str = c.encode_utf8(&mut buf);
            for i in 0..=copies(laid.bold_reach) {
                for j in 0..=copies(laid.bold_reach / 2.0) {
                    let (dx, dy) = (i as f32 * step, j as f32 * step);
                    draw_text_ex(s, origin.x + x + dx, origin.y + dy, params.clone());
                }
            }
        }
    });
    let i = laid.ink;
    Rect::new(origin.x + i.left, origin.y + i.top, i.width(), i.height())
}

/// Draws `text` in `style` with its ink's box centred on `centre`; returns that box.
pub fn draw_centred(text: &str, centre: Vec2, style: &Style, colour: Color) -> Rect {
    let ink = measure(text, style);
    draw(text, centre - ink.centre(), style, colour)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn no_other_module_draws_text_with_macroquad() {
        // The built-in pixel font must not come back through a direct call.
        let src = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
        for entry in std::fs::read_dir(&src).unwrap() {
            let path = entry.unwrap().path();
            if path.file_name().is_some_and(|n| n == "text.rs") {
                continue;
            }
            let code = std::fs::read_to_string(&path).unwrap();
            for banned in [
                "macroquad::text::",
                "macroquad::text;",
                "draw_text_ex(",
                "draw_text(",
                "measure_text(",
            ] {
                assert!(
                    !code.contains(banned),
                    "{} uses {banned}: draw text through text.rs",
                    path.display()
                );
            }
        }
    }

    #[test]
    fn digits_sit_on_the_baseline_at_about_seven_tenths_of_the_size() {
        let ink = lay_out("1", &Style::regular(100.0), 1.0).ink;
        assert!(ink.bottom.abs() <= 1.0, "{ink:?}");
        assert!((ink.height() - 70.0).abs() <= 2.0, "{ink:?}");
    }

    #[test]
    fn the_layout_scales_with_the_size_and_keeps_logical_pixels_at_any_dpi() {
        let small = lay_out("12345", &Style::regular(20.0), 1.0).ink;
        let big = lay_out("12345", &Style::regular(80.0), 1.0).ink;
        assert!((big.width() / small.width() - 4.0).abs() < 0.15);
        let retina = lay_out("12345", &Style::regular(80.0), 2.0).ink;
        assert!((retina.width() - big.width()).abs() <= 1.0);
        assert!((retina.height() - big.height()).abs() <= 1.0);
    }

    #[test]
    fn pen_positions_land_on_physical_pixels() {
        for dpi in [1.0, 1.5, 2.0] {
            let laid = lay_out("LEVEL 123", &Style::regular(23.0), dpi);
            for (_, x) in laid.glyphs {
                assert!(((x * dpi) - (x * dpi).round()).abs() < 1e-3, "{x} at {dpi}");
            }
        }
    }

    #[test]
    fn bold_reaches_further_and_condensed_is_narrower() {
        let light = lay_out("888", &Style::regular(50.0), 1.0).ink;
        let bold = lay_out("888", &Style::bold(50.0), 1.0).ink;
        assert!(bold.width() > light.width() && bold.height() > light.height());
        let narrow = Style {
            aspect: 0.7,
            ..Style::regular(50.0)
        };
        let narrow = lay_out("888", &narrow, 1.0).ink;
        assert!(narrow.width() < light.width() * 0.75);
        assert_eq!(narrow.height(), light.height());
    }

    #[test]
    fn the_largest_size_is_the_last_that_fits_from_any_guess() {
        let fits = |s: f32| s * 3.7 <= 100.0; // up to 27.02
        for guess in [0.0, 6.0, 20.0, 27.0, 28.0, 90.0, 1000.0] {
            assert_eq!(largest_size(6.0, 80.0, guess, fits), 27.0, "{guess}");
        }
        assert_eq!(largest_size(6.0, 80.0, 30.0, |_| false), 6.0);
        assert_eq!(largest_size(6.0, 80.0, 30.0, |_| true), 80.0);
    }

    #[test]
    fn a_fitted_text_never_exceeds_its_box_and_one_size_more_would() {
        let texts = [
            "7",
            "42",
            "888",
            "1234",
            "12.3k",
            "LEVEL 999",
            "BEST 9999999",
        ];
        let boxes = [(60.0, 30.0), (30.0, 60.0), (200.0, 40.0), (17.0, 9.0)];
        for dpi in [1.0, 1.25, 2.0] {
            for text in texts {
                for (w, h) in boxes {
                    for base in [Style::regular(120.0), Style::bold(120.0)] {
                        let s = fit_style(text, base, w, h, 1.0, dpi);
                        let ink = lay_out(text, &s, dpi).ink;
                        if s.size > MIN_SIZE {
                            assert!(ink.width() <= w && ink.height() <= h, "{text} {w}x{h}");
                        }
                        let more = lay_out(text, &s.at(s.size + 1.0), dpi).ink;
                        assert!(
                            more.width() > w || more.height() > h,
                            "{text} in {w}x{h} at {dpi}: {} is not the largest",
                            s.size
                        );
                    }
                }
            }
        }
    }

    #[test]
    fn condensing_comes_before_shrinking_and_stops_at_its_limit() {
        let (w, h) = (50.0, 40.0);
        let base = Style::bold(200.0);
        let plain = fit_style("888", base, w, h, 1.0, 1.0);
        let condensed = fit_style("888", base, w, h, 0.7, 1.0);
        assert!(condensed.size > plain.size, "{condensed:?} {plain:?}");
        assert!(condensed.aspect >= 0.7 && condensed.aspect < 1.0);
        let ink = lay_out("888", &condensed, 1.0).ink;
        assert!(ink.width() <= w && ink.height() <= h);
        // One digit needs no condensing: the height decides.
        let one = fit_style("8", base, w, h, 0.7, 1.0);
        assert_eq!(one.aspect, 1.0);
        assert!(lay_out("8", &one, 1.0).ink.height() > h - 3.0);
    }
}
