//! Ball against a static segment: its interior (either side) and its two end points.

use super::{Crossing, Motion, point_crossing};
use crate::geometry::Segment;
use crate::roots::{first_contact, first_descent};

/// Which part of a segment a ball touches.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum SegmentFeature {
    /// The interior: the contact normal is the segment's normal.
    Interior,
    /// The end point `a`: the contact normal points from `a` to the ball's centre.
    EndA,
    /// The end point `b`: the contact normal points from `b` to the ball's centre.
    EndB,
}

/// The first contact of a ball with a segment.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SegmentContact {
    /// The time of impact, relative to the motion's `t = 0`.
    pub time: f64,
    /// The part of the segment touched.
    pub feature: SegmentFeature,
}

/// How far outside `[0, 1]` (in units of the segment's length) a contact with the interior
/// may be and still count, and how far inside it a contact with an end point may be.
///
/// The interior and end-point candidates are computed separately, at slightly different times,
/// so a shot at the exact junction could round to "outside the interior" *and* "not beyond the
/// end point": both would be rejected and the ball would pass through. An overlap of the two
/// acceptance ranges closes that gap; the contacts it admits are within 1e-12 segment lengths of
/// the junction, where the interior and end-point normals agree to 1e-12.
const FEATURE_OVERLAP: f64 = 1e-12;

/// The overlap of a segment's interior and end-point acceptance ranges, in segment lengths:
/// [`FEATURE_OVERLAP`], or, far from the origin, 8 ulps of the end points' coordinates (the
/// rounding of a projection `(p - a) . d / |d|^2` computed there), whichever is larger.
#[inline]
pub(crate) fn feature_overlap(segment: &Segment) -> f64 {
    let scale = segment.a().abs().max(segment.b().abs()).max_element();
    let rounding = 8.0 * f64::EPSILON * scale;
    // The root and the division only where the rounding wins (far out, or a tiny segment).
    let squared = segment.direction().length_squared();
    if rounding * rounding <= FEATURE_OVERLAP * FEATURE_OVERLAP * squared {
        return FEATURE_OVERLAP;
    }
    FEATURE_OVERLAP.max(rounding / squared.sqrt())
}

/// The first time in `[0, horizon]` at which a ball of `radius` moving with `motion` touches
/// the segment (`Crossing::Enter`), or stops overlapping it (`Crossing::Exit`, for sensors),
/// and which part of the segment that is.
///
/// The candidates are the interior from either side (the signed distance to the line,
/// `s(t) = s0 + (n.v) t + (n.g) t^2 / 2`, reaching `±r`: a quadratic, closed form) and each end
/// point ([`time_of_impact_ball_point`](super::time_of_impact_ball_point)). An interior
/// candidate counts only if the ball's centre
/// then projects onto the segment, an end-point candidate only if it projects beyond that end;
/// the earliest valid candidate is the contact.
///
/// The touching-contact policy ("touching and approaching is contact now") is applied only to
/// the feature whose region holds the ball's centre now: the near side of the interior if the
/// centre projects onto the segment, an end point if it projects beyond that end. The other
/// features can only be reached later (the far side by going around an end, under gravity), so
/// for them only a genuine crossing counts. This matters for sensors: a ball inside a capsule,
/// outside the circle around one end point and moving away from it, must not "exit now" there.
///
/// Ties (the junction of interior and end point) go to the interior, then `EndA`, then `EndB`.
#[must_use]
pub fn time_of_impact_ball_segment(
    motion: &Motion,
    radius: f64,
    segment: &Segment,
    crossing: Crossing,
    horizon: f64,
) -> Option<SegmentContact> {
    segment_crossing(motion, radius, segment, crossing, horizon, true)
}

/// [`time_of_impact_ball_segment`], with the touching-contact policy switched on or off:
/// without it only a crossing from the far side counts, on every feature (a contact the world
/// has closed for the instant, see `pipeline/instant.rs`).
pub(crate) fn segment_crossing(
    motion: &Motion,
    radius: f64,
    segment: &Segment,
    crossing: Crossing,
    horizon: f64,
    touching_policy: bool,
) -> Option<SegmentContact> {
    let mut best: Option<SegmentContact> = None;
    let consider = |best: &mut Option<SegmentContact>, time: f64, feature: SegmentFeature| {
        if time <= horizon && best.is_none_or(|b| time < b.time) {
            *best = Some(SegmentContact { time, feature });
        }
    };
    let overlap = feature_overlap(segment);
    let n = segment.normal();
    let s0 = segment.signed_distance(motion.position);
    let u0 = segment.projection(motion.position);
    let near = if s0 >= 0.0 { 1.0 } else { -1.0 };
    // Exits are descents of the negated gaps.
    let sign = match crossing {
        Crossing::Enter => 1.0,
        Crossing::Exit => -1.0,
    };
    for side in [near, -near] {
        // Gap to the line on this side, g(t) = side * s(t) - r, in half-b form.
        let a = sign * side * 0.5 * n.dot(motion.acceleration);
        let b = sign * side * 0.5 * n.dot(motion.velocity);
        let c = sign * (side * s0 - radius);
        let in_region = touching_policy && side == near && (-overlap..=1.0 + overlap).contains(&u0);
        let t = if in_region {
            first_contact(a, b, c)
        } else {
            first_descent(a, b, c)
        };
        if let Some(t) = t {
            let u = segment.projection(motion.position_at(t));
            if (-overlap..=1.0 + overlap).contains(&u) {
                consider(&mut best, t, SegmentFeature::Interior);
            }
        }
    }
    let ends = [
        (segment.a(), SegmentFeature::EndA),
        (segment.b(), SegmentFeature::EndB),
    ];
    for (point, feature) in ends {
        let limit = best.map_or(horizon, |b| b.time);
        let in_region = touching_policy
            && match feature {
                SegmentFeature::EndA => u0 <= overlap,
                _ => u0 >= 1.0 - overlap,
            };
        let beyond = |t: f64| {
            let u = segment.projection(motion.position_at(t));
            match feature {
                SegmentFeature::EndA => u <= overlap,
                _ => u >= 1.0 - overlap,
            }
        };
        if let Some(t) = point_crossing(motion, point, radius, crossing, limit, in_region, beyond) {
            consider(&mut best, t, feature);
        }
    }
    best
}
