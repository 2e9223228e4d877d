//! Resting and sliding contact under gravity.
//!
//! A ball with restitution below 1 bouncing on a floor makes infinitely many bounces in a finite
//! time: after a bounce with outgoing normal speed `w` under a normal pull `g_n`, the next
//! comes `2 w / g_n` later with speed `e w`, so the bounces accumulate at
//! `t* = t + 2 w / (g_n (1 - e))`. An event-driven engine cannot follow them all, and a ball
//! at rest on a floor, whose gap has a double root, would sink if nothing held it.
//!
//! So once a ball *touches* a surface (within [`SETTLE_HEIGHT`]), is pulled into it, and moves
//! off it too slowly to rise more than [`SETTLE_HEIGHT`] before gravity brings it back, it
//! becomes *supported*: its normal velocity is dropped (a kinetic energy of at most
//! `m g_n SETTLE_HEIGHT`) and it slides along the surface under the tangential part of
//! gravity, in closed form, with no events until it reaches the end of the surface or is hit.
//!
//! - **Segment interior**: the centre slides on the line at the ball's radius from the segment,
//!   until its projection leaves the segment.
//! - **A point** (a segment's end point, or a static circle, whose centre the ball's centre
//!   keeps at the contact distance `rho`): a frictionless ball pivots around it until the
//!   surface turns away from gravity fast enough to let it fly. The arc is not a polynomial in
//!   time, so the engine follows the polygon circumscribed about it, with one edge every
//!   [`PIVOT_STEP`]: the centre slides along an edge tangent to the arc, and at the edge's end
//!   its velocity turns by the step, speed kept. The polygon lies outside the arc (no overlap)
//!   and within `rho (1 / cos(PIVOT_STEP / 2) - 1) = 9.5e-6 rho` of it; energy is conserved.
//!   At each corner the ball flies off if its free flight would never touch the point again.
//! - **A wedge**: a ball that settles on a second surface while the first pulls it into the
//!   second, and the second into the first, is held by both: at rest.
//!
//! The support's lowest-level facts live here; the world applies them (`pipeline/step.rs`).

use glam::DVec2;

use super::Time;
use super::hold::PARALLEL;
use super::table::ClothPhase;
use crate::geometry::{ColliderHandle, Feature, Segment, Shape};
use crate::roots::first_descent;
use crate::toi::{Motion, feature_overlap};

/// How close to a surface, as a fraction of the contact's coordinate scale (the ball's largest
/// coordinate plus the contact distance), a ball touches it for resting contact, and how high
/// its next hop may be for it to settle: `2^-44`, 256 units in the last place of that scale.
/// Below this, rounding of positions is no longer small against the hop: the Zeno tail is
/// cut there, within `2 e w / (g_n (1 - e))` (with `w = sqrt(2 g_n h)`) of its accumulation
/// time.
pub const SETTLE_HEIGHT: f64 = 5.684_341_886_080_802e-14;

/// How far past a segment's end, in segment lengths, a slide goes on: four times the
/// segment kernel's overlap of interior and end points (`FEATURE_OVERLAP`, 1e-12).
const END_MARGIN: f64 = 4e-12;

/// The angle between two edges of a pivot's polygon: half a degree.
pub const PIVOT_STEP: f64 = std::f64::consts::PI / 360.0;
/// `cos(PIVOT_STEP)`, `sin(PIVOT_STEP)` and `tan(PIVOT_STEP / 2)` as constants (no libm on the
/// simulation path).
const PIVOT_COS: f64 = 0.999_961_923_064_171_3;
const PIVOT_SIN: f64 = 0.008_726_535_498_373_935;
const PIVOT_HALF_TAN: f64 = 0.004_363_350_820_701_567;

/// How far below zero a pivot edge's sine to the next segment's normal, and below
/// [`PIVOT_COS`] its cosine, may round and the segment still count as reached within the step
/// (`Support::pivot`): 8 ulps of 1, the rounding of a dot product of two unit vectors, each
/// the rounded rotation of the last. The steps land on a segment whose angle is a multiple of
/// half a degree (45 degrees: ninety steps) to the rounding of those products: rough hunt
/// seed 2513226 reached the edge one step before such a segment with the cosine one ulp
/// below `PIVOT_COS`, and the edge on it with the sine at -1.1e-16, and pivoted on past it,
/// 2.1e-3 of its radius into the segment.
const PIVOT_ROUNDING: f64 = 8.0 * f64::EPSILON;

/// Where a ball touches a collider: the feature whose region holds its centre, the unit normal
/// from the surface to the centre, the gap (negative: overlap), and for point features the
/// point (or circle centre) and the contact distance.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Touch {
    pub feature: Feature,
    pub normal: DVec2,
    pub gap: f64,
    /// The point pivoted around and the contact distance, for end points and circles.
    pub point: Option<(DVec2, f64)>,
}

impl Touch {
    /// The nearest feature of `shape` to a ball of `radius` centred at `p`.
    pub(crate) fn of(shape: &Shape, p: DVec2, radius: f64) -> Option<Self> {
        let point = |c: DVec2, reach: f64, feature| {
            let d = p - c;
            let length = d.length();
            (length > 0.0).then(|| Self {
                feature,
                normal: d / length,
                gap: length - reach,
                point: Some((c, reach)),
            })
        };
        match shape {
            Shape::Segment(s) => {
                let u = s.projection(p);
                if u < 0.0 {
                    point(s.a(), radius, Feature::SegmentEndA)
                } else if u > 1.0 {
                    point(s.b(), radius, Feature::SegmentEndB)
                } else {
                    Some(Self::on_interior(s, p, radius))
                }
            }
            Shape::Circle(c) => point(c.center, radius + c.radius, Feature::Circle),
        }
    }

    /// Segment `s`'s interior (its line), taken as the feature a ball of `radius` centred at
    /// `p` touches, whichever feature is nearest.
    pub(crate) fn on_interior(s: &Segment, p: DVec2, radius: f64) -> Self {
        let distance = s.signed_distance(p);
        let normal = if distance >= 0.0 {
            s.normal()
        } else {
            DVec2::ZERO - s.normal()
        };
        Self {
            feature: Feature::SegmentInterior,
            normal,
            gap: distance.abs() - radius,
            point: None,
        }
    }

    /// The contact distance: the ball's radius for a segment's interior, the point's reach
    /// for an end point or a circle.
    pub(crate) fn reach(&self, radius: f64) -> f64 {
        self.point.map_or(radius, |(_, reach)| reach)
    }

    /// How far the ball at `p` may be from the surface and still touch it: [`SETTLE_HEIGHT`]
    /// of the contact's coordinate scale.
    pub(crate) fn height(&self, p: DVec2, radius: f64) -> f64 {
        SETTLE_HEIGHT * (p.abs().max_element() + self.reach(radius))
    }

    /// Whether a ball at `p` touches the surface: no more than [`Self::height`] off it (see
    /// [`touching_gap`]).
    pub(crate) fn touches(&self, p: DVec2, radius: f64) -> bool {
        touching_gap(self.gap, p.abs().max_element(), self.reach(radius))
    }

    /// Whether a ball at `p` with velocity `v` and acceleration `a` rests on this touch: it
    /// touches (see [`Self::touches`]), is pulled in, and cannot move in or out by more than
    /// [`SETTLE_HEIGHT`] before the pull stops it.
    ///
    /// A pull is at least [`PARALLEL`] of the acceleration, as for [`Hold`](super::Hold) (so that the two
    /// agree on what holds a ball). Around a point the gap also curves away as the ball moves
    /// past it: the pull is the
    /// gap's second derivative, `a.n + |v_t|^2 / reach`, and a ball fast enough to make it
    /// non-negative flies off rather than pivots.
    pub(crate) fn holds(&self, p: DVec2, v: DVec2, a: DVec2, radius: f64) -> bool {
        self.holds_within(p, v, a, radius, PARALLEL * a.length())
    }

    /// [`Self::holds`], with a pull no stronger than `slack` taken for none: the rounding of
    /// the acceleration's direction where it is known better than to [`PARALLEL`] (a table's
    /// cloth, whose pull follows the slip: `ClothPhase::slack`). A pull the trajectory carries
    /// but the hold takes for none drives the ball back into the surface for ever, in bounces
    /// that shorten towards an accumulation time.
    pub(crate) fn holds_within(
        &self,
        p: DVec2,
        v: DVec2,
        a: DVec2,
        radius: f64,
        slack: f64,
    ) -> bool {
        self.touches(p, radius) && self.pulled_in(p, v, a, radius, slack)
    }

    /// [`Self::holds_within`] for a ball known to touch (by the rule of what it touches: a
    /// sleeping ball's circle is touched as far as two balls touch, `balls_touch`): it is
    /// pulled in by more than `slack`, and too slow along the normal to hop higher than
    /// [`SETTLE_HEIGHT`] before the pull stops it.
    pub(crate) fn pulled_in(&self, p: DVec2, v: DVec2, a: DVec2, radius: f64, slack: f64) -> bool {
        let pull = self.pull(v, a);
        // A pull below the rounding of the acceleration is none, as for [`Hold`].
        if !(pull < -slack) {
            return false;
        }
        let speed = v.dot(self.normal);
        let height = self.height(p, radius);
        speed * speed <= 2.0 * -pull * height
    }

    /// The gap's second derivative for a ball at velocity `v` and acceleration `a`: `a . n`,
    /// and about a point or a circle `a . n + |v_t|^2 / reach` (the surface curves away as the
    /// ball moves past it). Negative: the ball is pulled in.
    pub(crate) fn pull(&self, v: DVec2, a: DVec2) -> f64 {
        match self.point {
            None => a.dot(self.normal),
            Some((_, reach)) => {
                let slide = v - self.normal * v.dot(self.normal);
                a.dot(self.normal) + slide.length_squared() / reach
            }
        }
    }
}

/// Whether bodies whose coordinates reach `coordinates` in magnitude, with contact distance
/// `reach`, touch at `gap`: no more than [`SETTLE_HEIGHT`] of the contact's coordinate scale
/// (`coordinates + reach`) apart, and no more than half the contact distance into each other,
/// or that band, whichever is deeper.
///
/// Touching bodies overlap by no more than [`overlap_bound`](crate::overlap_bound) (a
/// placement's tolerance and rounding). The lower end is far below that on purpose: a ball
/// that the rounding of many events has taken a hair deeper than the bound still touches what
/// it is in, so it is held there (pulled in) or bounces (approaching), and never sinks on
/// for want of a contact. Only a ball more than half inside a surface does not touch it,
/// unless it is within the band: for a ball of a few units in the last place of its
/// coordinates (radius 2e-7 at 1e9, where one unit is 1.2e-7) a single rounding of its
/// position can put its centre on the surface's line, and it still touches (found by
/// `exact2d-hunt --table`: the ball, not touching, was met at once and again at one
/// instant, its jam finding nothing to push against).
pub(crate) fn touching_gap(gap: f64, coordinates: f64, reach: f64) -> bool {
    let height = SETTLE_HEIGHT * (coordinates + reach);
    gap <= height && gap >= -(0.5 * reach).max(height)
}

/// What holds a supported ball: the line its centre slides on (a segment's, or one edge of a
/// pivot's polygon), its extent, and the acceleration along it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Support {
    /// The supporting collider; its feature.
    pub collider: ColliderHandle,
    pub feature: Feature,
    /// Unit normal of the line, from the surface to the centre.
    pub normal: DVec2,
    /// A point of the line the centre slides on.
    pub origin: DVec2,
    /// The line's extent, along `normal.perp()` from `origin`.
    pub lo: f64,
    pub hi: f64,
    /// The ball's acceleration: gravity without its normal part (zero in a wedge).
    pub acceleration: DVec2,
    /// For a pivot: the point and the contact distance.
    pub pivot: Option<(DVec2, f64)>,
    /// For an end-point pivot: the segment's other end, whose side the pivot must not reach.
    pub other_end: Option<DVec2>,
    /// The second collider of a wedge.
    pub wedge: Option<ColliderHandle>,
    /// For an end-point pivot: the segment that goes on from the end point, which the ball
    /// slides onto when the pivot has turned to it.
    pub next: Option<Next>,
    /// The segment the ball slid off onto this one through their shared end point: the ball
    /// passes that point at exactly the contact distance (a graze), so neither is predicted
    /// against while it slides here.
    pub from: Option<ColliderHandle>,
    /// For a segment: the segments going on straight or turning away (down) from its end
    /// points. Their shared end points are grazed as the ball reaches an end, so they are not
    /// predicted against while it slides here; the end of the slide hands the ball on.
    pub ends: [Option<ColliderHandle>; 2],
    /// For a ball held by a group (see `pipeline/group.rs`): no line, only the acceleration
    /// the group's contacts leave it, until the group lets go.
    pub held: Option<Held>,
    /// For a rough ball on a segment: how friction turns it in this phase of its motion
    /// (see `dynamics/rolling.rs`).
    pub rub: Option<Rubbing>,
}

/// How friction moves a rough ball along its line in one phase (sliding, rolling, or at rest
/// under rolling resistance): the acceleration is the support's; these are its spin's.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Rubbing {
    /// The spin from the phase's start, if friction fixes it (rolling: `v . t / r`).
    pub omega: Option<f64>,
    /// The spin's rate of change.
    pub alpha: f64,
    /// When the phase ends (the slip vanishes, or a rolling ball stops), if it does.
    pub end: Option<Time>,
    /// Whether the ball rolls.
    pub rolling: bool,
    /// On a table: the roll's rate of change (as the contact point's velocity); zero on a
    /// line.
    pub roll_rate: DVec2,
    /// On a table: when the translation's and the spin's phases end (see
    /// `dynamics/table.rs`); `None` on a line.
    pub table: Option<TableEnds>,
    /// On a table: the rounding of the acceleration's direction (`ClothPhase::slack`); zero
    /// on a line.
    pub slack: f64,
}

/// When the parts of a table phase end (see `dynamics/table.rs`): the slip vanishing or the
/// ball stopping, and the spin stopping.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct TableEnds {
    pub translation: Option<Time>,
    pub spin: Option<Time>,
}

/// A ball held with other balls by their contacts (see `pipeline/group.rs`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Held {
    /// The group.
    pub group: u32,
    /// How long after the start of the ball's trajectory the group lets go (infinite: while
    /// nothing changes).
    pub until: f64,
}

/// The collider handle of a support that has none (a held ball's).
pub(crate) const NO_COLLIDER: ColliderHandle = ColliderHandle {
    index: u32::MAX,
    generation: u32::MAX,
};

/// The segment a pivot turns onto, and the way the pivot turns to reach it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Next {
    pub collider: ColliderHandle,
    pub segment: Segment,
    /// Its unit normal on the ball's side.
    pub normal: DVec2,
    /// Whether the pivot turns forwards (the way `normal.perp()` points) to reach it.
    pub forwards: bool,
    /// Whether the current edge ends on the segment's line (the next corner joins it).
    pub joins: bool,
}

impl Support {
    /// A sleeping ball's: at rest at `p` against `collider` (feature `feature`, unit normal
    /// `normal` from it to the centre), with no extent and no acceleration.
    pub(crate) fn asleep(
        collider: ColliderHandle,
        feature: Feature,
        normal: DVec2,
        p: DVec2,
    ) -> Self {
        Self {
            collider,
            feature,
            normal,
            origin: p,
            lo: 0.0,
            hi: 0.0,
            acceleration: DVec2::ZERO,
            pivot: None,
            other_end: None,
            wedge: None,
            next: None,
            from: None,
            ends: [None, None],
            held: None,
            rub: None,
        }
    }

    /// Sliding on a segment's interior, from the ball's centre `p` at `radius` from it.
    pub(crate) fn on_segment(
        collider: ColliderHandle,
        a: DVec2,
        b: DVec2,
        normal: DVec2,
        radius: f64,
        gravity: DVec2,
    ) -> Self {
        let origin = a + normal * radius;
        let along = (b - a).dot(normal.perp());
        // The slide goes on a hair past each end (`END_MARGIN` lengths, more than the segment
        // kernel's overlap of interior and end point), so that a ball flying off is clear of
        // the interior and moving away from the end point when it leaves, rather than found
        // touching and approaching it by a rounding error.
        // Far from the origin, four times the kernel's wider overlap there.
        let overlap = Segment::new(a, b).map_or(0.0, |s| feature_overlap(&s));
        let margin = END_MARGIN.max(4.0 * overlap) * along.abs();
        Self {
            collider,
            feature: Feature::SegmentInterior,
            normal,
            origin,
            lo: along.min(0.0) - margin,
            hi: along.max(0.0) + margin,
            acceleration: tangential(gravity, normal),
            pivot: None,
            other_end: None,
            wedge: None,
            next: None,
            from: None,
            ends: [None; 2],
            held: None,
            rub: None,
        }
    }

    /// Held by group `group` with `acceleration` (see [`Held`]), at centre `p`.
    pub(crate) fn held(acceleration: DVec2, p: DVec2, group: u32, until: f64) -> Self {
        Self {
            held: Some(Held { group, until }),
            ..Self::lineless(acceleration, p)
        }
    }

    /// A support without a collider or a line, moving the ball at centre `p` with
    /// `acceleration` only: a group's hold, the cloth of a table.
    fn lineless(acceleration: DVec2, p: DVec2) -> Self {
        Self {
            collider: NO_COLLIDER,
            feature: Feature::SegmentInterior,
            // No line: a zero normal matches no surface (see `same_normal`).
            normal: DVec2::ZERO,
            origin: p,
            lo: f64::NEG_INFINITY,
            hi: f64::INFINITY,
            acceleration,
            pivot: None,
            other_end: None,
            wedge: None,
            next: None,
            from: None,
            ends: [None; 2],
            held: None,
            rub: None,
        }
    }

    /// On a table's cloth (see `dynamics/table.rs`), at centre `p` now (`now`), in `phase`:
    /// no collider and no line (a zero normal matches no surface), only the phase's
    /// accelerations, until the first of its ends, or `until` (seconds from now) if sooner:
    /// then it is laid on the cloth afresh, in the same phase, nothing of it ended.
    pub(crate) fn on_table(p: DVec2, phase: &ClothPhase, until: Option<f64>, now: Time) -> Self {
        let at = |d: Option<f64>| d.map(|d| now.after(d));
        let end = super::sooner(phase.end(), until);
        Self {
            rub: Some(Rubbing {
                omega: None,
                alpha: phase.alpha,
                end: at(end),
                rolling: phase.rolling,
                roll_rate: phase.roll_rate,
                slack: phase.slack,
                table: Some(TableEnds {
                    translation: at(phase.translation_end),
                    spin: at(phase.spin_end),
                }),
            }),
            ..Self::lineless(phase.accel, p)
        }
    }

    /// This support of a line or a pivot's edge without friction's share: gravity's part along
    /// it, no phase (`World::rubbed` gives friction's share afresh). A wedge or a group holds
    /// its ball with no friction phase: it is returned as it is, but for the phase.
    pub(crate) fn smooth(&self, gravity: DVec2) -> Self {
        let acceleration = if self.wedge.is_some() || self.held.is_some() {
            self.acceleration
        } else {
            tangential(gravity, self.normal)
        };
        Self {
            acceleration,
            rub: None,
            ..*self
        }
    }

    /// When the parts of the ball's table phase end, if it is on a table's cloth.
    pub(crate) fn table(&self) -> Option<TableEnds> {
        self.rub.and_then(|r| r.table)
    }

    /// Pivoting around `point` at distance `reach`, on the polygon edge tangent at `normal`.
    /// If the segment `next` goes on from the point less than a step further round, the edge
    /// ends on its line (where the ball slides onto it).
    pub(crate) fn pivot(
        collider: ColliderHandle,
        feature: Feature,
        (point, reach): (DVec2, f64),
        normal: DVec2,
        other_end: Option<DVec2>,
        next: Option<Next>,
        gravity: DVec2,
    ) -> Self {
        let half = reach * PIVOT_HALF_TAN;
        let mut support = Self {
            collider,
            feature,
            normal,
            origin: point + normal * reach,
            lo: -half,
            hi: half,
            acceleration: tangential(gravity, normal),
            pivot: Some((point, reach)),
            other_end,
            wedge: None,
            next,
            from: None,
            ends: [None; 2],
            held: None,
            rub: None,
        };
        if let Some(next) = next {
            let ahead = if next.forwards {
                normal.perp()
            } else {
                DVec2::ZERO - normal.perp()
            };
            let (sin, cos) = (next.normal.dot(ahead), next.normal.dot(normal));
            if sin >= -PIVOT_ROUNDING && cos >= PIVOT_COS - PIVOT_ROUNDING {
                // The tangents at `normal` and at the segment's normal meet `tan(angle / 2)`
                // along (a sine below zero is a rounding of none).
                let to = reach * sin.max(0.0) / (1.0 + cos);
                if next.forwards {
                    support.hi = to;
                } else {
                    support.lo = -to;
                }
                support.next = Some(Next {
                    joins: true,
                    ..next
                });
            }
        }
        support
    }

    /// The next edge of a pivot's polygon, turning forwards (the way `normal.perp()` points)
    /// or backwards; `None` if it would leave the end point's region (the ball then drops onto
    /// the segment) or face away from gravity.
    pub(crate) fn turned(&self, forwards: bool, gravity: DVec2) -> Option<Self> {
        let (point, _) = self.pivot?;
        let t = self.normal.perp();
        let sin = if forwards { PIVOT_SIN } else { -PIVOT_SIN };
        let normal = (self.normal * PIVOT_COS + t * sin).normalize();
        if !(gravity.dot(normal) < 0.0) {
            return None;
        }
        if let Some(other) = self.other_end {
            if normal.dot(point - other) <= 0.0 {
                return None;
            }
        }
        Some(Self::pivot(
            self.collider,
            self.feature,
            self.pivot?,
            normal,
            self.other_end,
            self.next.map(|n| Next { joins: false, ..n }),
            gravity,
        ))
    }

    /// The ball's state moved onto the line: position projected onto it, velocity along it.
    pub(crate) fn restrict(&self, p: DVec2, v: DVec2) -> (DVec2, DVec2) {
        let n = self.normal;
        if self.wedge.is_some() {
            return (p - n * (p - self.origin).dot(n), DVec2::ZERO);
        }
        (p - n * (p - self.origin).dot(n), v - n * v.dot(n))
    }

    /// Where along the line a centre `p` is.
    pub(crate) fn coordinate(&self, p: DVec2) -> f64 {
        (p - self.origin).dot(self.normal.perp())
    }

    /// How long after the start of `motion` the centre leaves the line's extent, if ever.
    pub(crate) fn leave_time(&self, motion: &Motion) -> Option<f64> {
        // A table has no edge (its phase's end is the support's `rub`).
        if self.table().is_some() {
            return None;
        }
        if let Some(held) = self.held {
            return held.until.is_finite().then_some(held.until);
        }
        if self.wedge.is_some() {
            return None;
        }
        let t = self.normal.perp();
        let s = self.coordinate(motion.position);
        let (v, a) = (motion.velocity.dot(t), motion.acceleration.dot(t));
        let low = exit(s - self.lo, 0.5 * v, 0.5 * a);
        let high = exit(self.hi - s, -0.5 * v, -0.5 * a);
        match (low, high) {
            (Some(l), Some(h)) => Some(l.min(h)),
            (l, h) => l.or(h),
        }
    }
}

/// The first `t >= 0` at which `f(t) = c + 2 b t + a t^2`, non-negative or rounded just below
/// zero now, goes below zero: now if it is at zero and moving (or accelerating) down.
fn exit(c: f64, b: f64, a: f64) -> Option<f64> {
    if c <= 0.0 && (b < 0.0 || (b == 0.0 && a < 0.0)) {
        return Some(0.0);
    }
    first_descent(a, b, c)
}

/// `g` without its component along the unit `normal`.
fn tangential(g: DVec2, normal: DVec2) -> DVec2 {
    g - normal * g.dot(normal)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_pivot_constants_are_the_step_s_cosine_sine_and_half_tangent() {
        assert!((PIVOT_COS - PIVOT_STEP.cos()).abs() <= f64::EPSILON);
        assert!((PIVOT_SIN - PIVOT_STEP.sin()).abs() <= f64::EPSILON * PIVOT_SIN);
        assert!((PIVOT_HALF_TAN - (PIVOT_STEP / 2.0).tan()).abs() <= f64::EPSILON * PIVOT_HALF_TAN);
        assert_eq!(SETTLE_HEIGHT, 2f64.powi(-44));
    }

    #[test]
    fn a_slide_leaves_a_segment_at_the_analytic_time() {
        let handle = ColliderHandle {
            index: 0,
            generation: 0,
        };
        // A ramp of slope 3/4 (normal (-3, 4) / 5): the tangential pull is g sin(a) = 6.
        let (a, b) = (DVec2::ZERO, DVec2::new(4.0, 3.0));
        let normal = DVec2::new(-3.0, 4.0) / 5.0;
        let g = DVec2::new(0.0, -10.0);
        let s = Support::on_segment(handle, a, b, normal, 0.5, g);
        assert!((s.acceleration.length() - 6.0).abs() < 1e-14);
        // At rest half-way: it slides 2.5 down to a, and on past it by `END_MARGIN` ramp
        // lengths, in sqrt(2 * (2.5 + 5 END_MARGIN) / 6) s.
        let p = (a + b) * 0.5 + normal * 0.5;
        let motion = Motion {
            position: p,
            velocity: DVec2::ZERO,
            acceleration: s.acceleration,
        };
        let t = s.leave_time(&motion).unwrap();
        let expected = (2.0 * (2.5 + 5.0 * END_MARGIN) / 6.0f64).sqrt();
        assert!((t - expected).abs() < 1e-15, "{t} vs {expected}");
    }
}
