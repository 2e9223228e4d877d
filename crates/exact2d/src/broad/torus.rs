//! A periodic box: the rectangle `[0, Lx) x [0, Ly)` whose opposite edges are glued, and the
//! cells of the ball grid that tile it.
//!
//! **Where positions live.** A ball's path is kept in the box: it is restated, and moved by
//! one box length, at the moment its centre crosses an edge (a *wrap*, handled as the ball
//! grid's crossing out of a cell on the edge). Stored positions are therefore always within
//! the box, up to the rounding of a crossing, and never lose digits however far a ball
//! travels: an unwrapped position grows without bound, and its ulp with it.
//!
//! **Why the move is exact one way and half an ulp the other.** Leaving through `x = L` the
//! centre is at `x = L` to within rounding, so `x - L` is exact (Sterbenz: `L / 2 <= x <= 2 L`);
//! it comes out as a tiny number, negative if the crossing's time was rounded early, and is
//! then clamped to `0`. Leaving through `x = 0` the centre is at `x ~ 0`, and `x + L` is rounded
//! once at the magnitude of `L` (at most half an ulp of `L`): the precision a coordinate has
//! there anyway, and the precision with which the pair of a ball near `0` and one near `L`
//! is seen across the edge in any case. A ball moving down an axis may sit at `L` itself (the
//! box's closure); it is reported at 0.
//!
//! **Images.** Two balls meet through their nearest images. Cells tile the box exactly
//! (`n >= 3` per axis, each side at least `CELL_PER_RADIUS` radius capacities), so the 3 x 3
//! block around a cell holds nine distinct cells, and each is reached through one image: a
//! block cell left of cell 0 is cell `n - 1` seen one box length to the left. A prediction
//! sees a partner in such a cell at its path moved by that image's shift (`k L`, `k` in
//! `{-1, 0, 1}`: exact). At an event, where the two touch (their distance at most their
//! contact distance, below `L / 2` since `L >= 6.6` radii), the nearest image of the centres'
//! difference is that same image.

use glam::DVec2;

use super::path::floor;

/// How close to an edge, in ulps of the box's side, a centre moving out of a cell on that
/// edge counts as leaving through it (see [`Torus::wrap`]).
const EDGE_ULPS: f64 = 16.0;

/// The number of cells of side at least `min_side` across a length; at least 3.
fn cells_across(length: f64, min_side: f64) -> i32 {
    let n = (length / min_side).floor();
    if n >= 3.0 {
        n.min(f64::from(1 << 20)) as i32
    } else {
        3
    }
}

/// A periodic box and its tiling into cells.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Torus {
    /// `(Lx, Ly)`.
    pub size: DVec2,
    /// Cells across each axis (at least 3).
    pub n: [i32; 2],
    /// The cells' sides, `L / n`.
    pub side: DVec2,
}

impl Torus {
    /// The box `[0, size.x) x [0, size.y)` tiled with cells of side at least `min_side` (one
    /// cell per axis if `min_side` is zero, before any ball is added).
    pub(crate) fn new(size: DVec2, min_side: f64) -> Self {
        let n = [
            cells_across(size.x, min_side),
            cells_across(size.y, min_side),
        ];
        Self {
            size,
            n,
            side: DVec2::new(size.x / f64::from(n[0]), size.y / f64::from(n[1])),
        }
    }

    /// The cell of a centre at `p` (clamped into the box: `p` is in it up to rounding).
    pub(crate) fn cell_of(&self, p: DVec2) -> (i32, i32) {
        let c = |x: f64, side: f64, n: i32| {
            let k = floor(x / side);
            if k >= 0.0 { (k as i32).min(n - 1) } else { 0 }
        };
        (
            c(p.x, self.side.x, self.n[0]),
            c(p.y, self.side.y, self.n[1]),
        )
    }

    /// The corners of cell `(cx, cy)`, the box's own edges for cells on them.
    pub(crate) fn cell_bounds(&self, cx: i32, cy: i32) -> (DVec2, DVec2) {
        let edge = |k: i32, side: f64, n: i32, length: f64| {
            let lo = if k == 0 { 0.0 } else { f64::from(k) * side };
            let hi = if k == n - 1 {
                length
            } else {
                f64::from(k + 1) * side
            };
            (lo, hi)
        };
        let (x0, x1) = edge(cx, self.side.x, self.n[0], self.size.x);
        let (y0, y1) = edge(cy, self.side.y, self.n[1], self.size.y);
        (DVec2::new(x0, y0), DVec2::new(x1, y1))
    }

    /// Whether cell `(cx, cy)` lies on an edge of the box (its 3 x 3 block reaches across).
    #[inline]
    pub(crate) fn on_edge(&self, cx: i32, cy: i32) -> bool {
        cx == 0 || cy == 0 || cx == self.n[0] - 1 || cy == self.n[1] - 1
    }

    /// A block coordinate `k` (a cell index one beyond the box, or inside it) as the cell it
    /// is and the image it is seen through: `(cell, -1 | 0 | 1)`.
    pub(crate) fn wrap_index(k: i32, n: i32) -> (i32, i32) {
        if k < 0 {
            (k + n, -1)
        } else if k >= n {
            (k - n, 1)
        } else {
            (k, 0)
        }
    }

    /// The shift of image `(kx, ky)` (each in `{-1, 0, 1}`): exact.
    pub(crate) fn shift(&self, kx: i32, ky: i32) -> DVec2 {
        DVec2::new(f64::from(kx) * self.size.x, f64::from(ky) * self.size.y)
    }

    /// The shift, a multiple of the box's sides, that brings `d` (a difference of two
    /// positions in the box) to its nearest image: `d + shift` in `[-L/2, L/2]`.
    pub(crate) fn nearest_shift(&self, d: DVec2) -> DVec2 {
        let s = |d: f64, l: f64| {
            if d > 0.5 * l {
                -l
            } else if d < -0.5 * l {
                l
            } else {
                0.0
            }
        };
        DVec2::new(s(d.x, self.size.x), s(d.y, self.size.y))
    }

    /// The wrap of a ball at `p` moving at `v` (at a crossing, or before it is predicted):
    /// its position brought into the box where it is on an edge moving out or past one (see
    /// the module's documentation), with the images it moved through: `+1` for a move by
    /// `-L` (it left through `L`), `-1` for a move by `+L`.
    ///
    /// Per axis: moving up the axis, a centre within `EDGE_ULPS` of `L` or past it leaves
    /// through `L` (`x - L`, exact, never below 0); moving down it, one within `EDGE_ULPS`
    /// of 0 or below it leaves through 0 (`x + L`, rounded once, never above `L`); at rest,
    /// one past an edge is brought back. A crossing's time is rounded, and one rounded early
    /// leaves the centre a hair inside: were it not wrapped then, its next crossing would be
    /// now again, for ever. A centre a hair past an edge but moving back in (an event at the
    /// edge turned it, or a wrap's `x - L` came out below 0) is put on the edge: outside its
    /// cell's box by a rounding, its next crossing would be its entry, at a time the clock
    /// cannot tell from now. (Moved across the edge instead, it would be on the far edge
    /// moving out.) Both moves are within `EDGE_ULPS` of the box's side.
    pub(crate) fn wrap(&self, p: DVec2, v: DVec2) -> (DVec2, [i32; 2]) {
        let w = |x: f64, v: f64, l: f64| -> (f64, i32) {
            let near = EDGE_ULPS * f64::EPSILON * l;
            if (v > 0.0 && x >= l - near) || (v == 0.0 && x >= l) {
                ((x - l).max(0.0), 1)
            } else if (v < 0.0 && x <= near) || (v == 0.0 && x < 0.0) {
                ((x + l).min(l), -1)
            } else if v > 0.0 && x < 0.0 {
                (0.0, 0)
            } else if v < 0.0 && x > l {
                (l, 0)
            } else {
                (x, 0)
            }
        };
        let (x, kx) = w(p.x, v.x, self.size.x);
        let (y, ky) = w(p.y, v.y, self.size.y);
        (DVec2::new(x, y), [kx, ky])
    }

    /// A position reported in `[0, L)`: the same wrap, for output only.
    pub(crate) fn reported(&self, p: DVec2) -> DVec2 {
        let w = |x: f64, l: f64| -> f64 {
            if x >= l {
                (x - l).max(0.0)
            } else if x < 0.0 {
                // The nearest double in the box to `x + L`: `0` itself when `x` is smaller
                // than rounding there can tell.
                let y = x + l;
                if y < l { y } else { 0.0 }
            } else {
                x
            }
        };
        DVec2::new(w(p.x, self.size.x), w(p.y, self.size.y))
    }

    /// Whether `p` is in `[0, Lx) x [0, Ly)`.
    pub(crate) fn contains(&self, p: DVec2) -> bool {
        p.x >= 0.0 && p.y >= 0.0 && p.x < self.size.x && p.y < self.size.y
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cells_tile_the_box_and_are_at_least_the_side_asked() {
        let t = Torus::new(DVec2::new(10.0, 7.3), 2.2 * 0.5);
        assert_eq!(t.n, [9, 6]);
        assert!(t.side.x >= 1.1 && t.side.y >= 1.1);
        assert_eq!(t.cell_bounds(0, 0).0, DVec2::ZERO);
        assert_eq!(t.cell_bounds(8, 5).1, DVec2::new(10.0, 7.3));
        // A box too small for three cells of the side asked still has three.
        assert_eq!(Torus::new(DVec2::splat(1.0), 0.5).n, [3, 3]);
        assert_eq!(t.cell_of(DVec2::new(9.999_999_999_999_998, 0.0)), (8, 0));
        assert_eq!(t.cell_of(DVec2::new(-1e-300, 7.3)), (0, 5));
    }

    #[test]
    fn wrapping_right_is_exact_and_left_is_rounded_once() {
        let t = Torus::new(DVec2::new(10.0, 0.1), 0.0);
        let (right, left, up) = (DVec2::X, -DVec2::X, DVec2::Y);
        let x = 10.000_000_000_000_002;
        assert_eq!(
            t.wrap(DVec2::new(x, 0.05), right),
            (DVec2::new(x - 10.0, 0.05), [1, 0])
        );
        // A crossing rounded early leaves it a hair inside: it still wraps, to the edge.
        let early = DVec2::new(9.999_999_999_999_998, 0.05);
        assert_eq!(t.wrap(early, right), (DVec2::new(0.0, 0.05), [1, 0]));
        // Not if it moves back in: at or a hair past the edge, it is put on the edge.
        assert_eq!(t.wrap(early, left).1, [0, 0]);
        assert_eq!(
            t.wrap(DVec2::new(x, 0.05), left),
            (DVec2::new(10.0, 0.05), [0, 0])
        );
        assert_eq!(
            t.wrap(DVec2::new(-1e-17, 0.05), right),
            (DVec2::new(0.0, 0.05), [0, 0])
        );
        // At rest past an edge, it is brought back.
        assert_eq!(t.wrap(DVec2::new(10.0, 0.05), DVec2::ZERO).0.x, 0.0);
        // Leaving through 0: rounded at the magnitude of L, never beyond L.
        let (p, k) = t.wrap(DVec2::new(-1e-20, 0.05), left);
        assert_eq!((p.x, k), (10.0, [-1, 0]));
        let (p, _) = t.wrap(DVec2::new(-0.25, 0.05), left);
        assert_eq!(p.x, 9.75);
        // On the edge itself, moving out.
        assert_eq!(
            t.wrap(DVec2::new(0.0, 0.05), left),
            (DVec2::new(10.0, 0.05), [-1, 0])
        );
        // In y too, with its own side.
        assert_eq!(t.wrap(DVec2::new(1.0, 0.1), up).0.y, 0.0);
        assert_eq!(t.reported(DVec2::new(-1e-20, 0.05)).x, 0.0);
        assert_eq!(t.reported(DVec2::new(10.0, 0.05)).x, 0.0);
    }

    #[test]
    fn the_nearest_image_of_a_difference_is_within_half_a_side() {
        let t = Torus::new(DVec2::new(10.0, 4.0), 0.0);
        for (d, want) in [
            (DVec2::new(9.5, 0.0), DVec2::new(-0.5, 0.0)),
            (DVec2::new(-9.5, 1.9), DVec2::new(0.5, 1.9)),
            (DVec2::new(4.9, -2.5), DVec2::new(4.9, 1.5)),
        ] {
            assert_eq!(d + t.nearest_shift(d), want);
        }
        assert_eq!(Torus::wrap_index(-1, 5), (4, -1));
        assert_eq!(Torus::wrap_index(5, 5), (0, 1));
        assert_eq!(Torus::wrap_index(2, 5), (2, 0));
        assert_eq!(t.shift(-1, 1), DVec2::new(-10.0, 4.0));
    }
}
