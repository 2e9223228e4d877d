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
    // Whether a ball outside the extent could come into it touching the line (see
    // `extent_entry`): only if it touches the near side's offset line now, or crosses it
    // beyond the end it is beyond now. Otherwise the near gap stays positive until it enters
    // the extent, and the centre cannot reach the far side without crossing the near side.
    let mut entry_matters = false;
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
        if side == near && c <= 0.0 {
            entry_matters = true;
        }
        if let Some(t) = t {
            let u = segment.projection(motion.position_at(t));
            if (-overlap..=1.0 + overlap).contains(&u) {
                consider(&mut best, t, SegmentFeature::Interior);
            } else if side == near && (u > 1.0) == (u0 > 1.0) {
                // Crossed beyond the end the centre is beyond now (the other end is reached
                // through the extent, clear of the line).
                entry_matters = true;
            }
        }
    }
    let ends = [
        (segment.a(), SegmentFeature::EndA),
        (segment.b(), SegmentFeature::EndB),
    ];
    for (point, feature) in ends {
        let limit = best.map_or(horizon, |b| b.time);
        // Strictly beyond the interior's range: within it the interior decides a touching
        // contact alone (the normals agree there to 1e-12). A ball touching the junction and
        // moving along the segment into its extent is tangential to the interior but, by a
        // few ulps, approaching the end point: the end point's policy said "contact now" for a
        // graze, and the jam that followed rested the ball on it as on a wedge.
        let in_region = touching_policy
            && match feature {
                SegmentFeature::EndA => u0 < -overlap,
                _ => u0 > 1.0 + overlap,
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
    if entry_matters && crossing == Crossing::Enter && !(-overlap..=1.0 + overlap).contains(&u0) {
        if let Some(t) = extent_entry(motion, radius, segment, overlap, u0, &best, horizon) {
            consider(&mut best, t, SegmentFeature::Interior);
        }
    }
    best
}

/// The contact of a ball that comes into the segment's extent (its centre starts to project
/// onto the segment) already touching the segment's line and moving into it: the interior is
/// touched at that moment, with the policy of [`first_contact`] applied there.
///
/// In exact arithmetic a centre cannot reach the line's offset inside the extent without
/// first crossing the circle around the end point it came past (the capsule's boundary is
/// continuous at the junction), so the end-point candidate would have come first. But a
/// centre that slides past the end point at exactly the contact distance (a ball of diameter
/// `w` in a channel of width `w`, pressed against the far side: round-number geometry) grazes
/// that circle, a double root within rounding and no contact by the policy, and enters the
/// extent with a gap of zero (or a rounding below) that the interior's roots, which look only
/// for a crossing from outside, never report: the ball drifted into the segment unseen. This
/// candidate closes that gap between the two features' tests. It is asked only while the
/// centre projects outside the extent now, and only for a time before every other candidate,
/// so it changes nothing where the end point or the interior already gave the contact.
fn extent_entry(
    motion: &Motion,
    radius: f64,
    segment: &Segment,
    overlap: f64,
    u0: f64,
    best: &Option<SegmentContact>,
    horizon: f64,
) -> Option<f64> {
    let d = segment.direction();
    let inv = 1.0 / d.length_squared();
    // The distance in segment lengths still to go to the junction, as a gap quadratic in
    // half-b form, positive now: beyond `b` it is `u - 1`, before `a` it is `-u`. The
    // junction itself, not the edge of the interior's range: there the ball is inside that
    // range, where the end point leaves a touching contact to the interior.
    let side_u = if u0 > 1.0 { 1.0 } else { -1.0 };
    let edge = if u0 > 1.0 { 1.0 } else { 0.0 };
    let a_u = side_u * 0.5 * d.dot(motion.acceleration) * inv;
    let b_u = side_u * 0.5 * d.dot(motion.velocity) * inv;
    let c_u = side_u * (u0 - edge);
    let entry = first_descent(a_u, b_u, c_u)?;
    if entry > best.map_or(horizon, |b| b.time) {
        return None;
    }
    let position = motion.position_at(entry);
    let velocity = motion.velocity_at(entry);
    let n = segment.normal();
    let s = segment.signed_distance(position);
    let side = if s >= 0.0 { 1.0 } else { -1.0 };
    // A gap within the rounding of the position at the entry (8 ulps of its coordinates, the
    // world's `SNAP_ULPS`) is touching: the position there is rounded, and its sign must not
    // decide. (A ball that overlapped the line by 8e-15 outside the extent and could not get
    // clear before its turning point came in at the junction with a true gap of -8e-17,
    // computed as +0: taken as clear, it was left to the interior's root, which had none,
    // and went into the wall: rough hunt seed 37696.)
    let c = side * s - radius;
    let snap = 8.0 * f64::EPSILON * (position.abs().max_element() + radius);
    if c > snap {
        // Clear of the line: a later contact is the interior's own root.
        return None;
    }
    let c = c.min(0.0);
    let a = side * 0.5 * n.dot(motion.acceleration);
    let b = side * 0.5 * n.dot(velocity);
    let later = first_contact(a, b, c)?;
    let t = entry + later;
    let u = segment.projection(motion.position_at(t));
    (later == 0.0 || (-overlap..=1.0 + overlap).contains(&u)).then_some(t)
}
