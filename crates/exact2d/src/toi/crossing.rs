//! Which way a ball crosses the boundary of a shape.

/// Which way a ball crosses a shape's boundary.
///
/// Solid shapes only ever produce [`Crossing::Enter`]: a contact. Sensors, which balls pass
/// through, produce both: entering when the ball starts to overlap the shape, exiting when it
/// stops.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Crossing {
    /// The gap between ball and shape closes: contact begins.
    Enter,
    /// The ball, now overlapping the shape, leaves it.
    Exit,
}
