//! Why a scene was rejected, and the names of the items in a scene.

use std::fmt;

use crate::WorldError;

/// A static shape or a ball of a scene, by its position in the scene's lists.
///
/// Displays as the item's path in the scene file: `segments[2]`, `circles[0]`, `balls[3]`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum SceneItem {
    /// `segments[i]`.
    Segment(usize),
    /// `circles[i]`.
    Circle(usize),
    /// `balls[i]` (the index in the list, not the ball's `id`).
    Ball(usize),
}

impl fmt::Display for SceneItem {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            SceneItem::Segment(i) => write!(f, "segments[{i}]"),
            SceneItem::Circle(i) => write!(f, "circles[{i}]"),
            SceneItem::Ball(i) => write!(f, "balls[{i}]"),
        }
    }
}

/// Why a scene was rejected. Each error names one offending item by its path in the file
/// (`balls[3].radius`); its [`Display`](fmt::Display) is a single line, such as
/// `balls[3].radius must be > 0`, ready to be prefixed with the file name.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum SceneError {
    /// The text is empty or only white space.
    Empty,
    /// The text is not a scene: malformed JSON, a value of the wrong type, an unknown, missing
    /// or repeated key, a number too large for an `f64`, an `id` that is not a non-negative
    /// integer.
    Parse {
        /// Where in the document, like `balls[0].pos[1]`; empty for the document itself.
        path: String,
        /// What is wrong, as worded by the JSON reader.
        message: String,
        /// 1-based line of the error (0 if unknown).
        line: usize,
        /// 1-based column of the error (0 if unknown).
        column: usize,
    },
    /// A number is NaN or infinite. JSON cannot spell these, so only a scene built in code
    /// can have one.
    NotFinite {
        /// Like `balls[0].vel[1]`.
        path: String,
    },
    /// A radius or a mass is not > 0.
    NotPositive {
        /// Like `balls[3].radius`.
        path: String,
    },
    /// A restitution is outside `[0, 1]`.
    RestitutionOutOfRange {
        /// Like `segments[1].restitution`.
        path: String,
    },
    /// A number is outside its range (friction, tangential restitution, inertia).
    OutOfRange {
        /// Like `balls[2].inertia`.
        path: String,
        /// The range, as the message writes it: `>= 0`, `in [-1, 1]`, `in (0, 1]`.
        range: &'static str,
    },
    /// `segments[index]` has two equal end points.
    DegenerateSegment {
        /// The index in `segments`.
        index: usize,
    },
    /// `segments[index]` has end points so far apart, or so close, that the square of its
    /// length overflows or underflows an `f64`, which the engine cannot use (it needs the
    /// length and the unit normal).
    SegmentLengthOutOfRange {
        /// The index in `segments`.
        index: usize,
    },
    /// `balls[index]` has the same `id` as the earlier `balls[first]`.
    DuplicateId {
        /// The index in `balls` of the later ball.
        index: usize,
        /// The earlier ball with this id.
        first: usize,
        /// The id.
        id: u64,
    },
    /// `balls[ball]` overlaps `other` at time 0 (deeper than
    /// [`OVERLAP_TOLERANCE`](crate::OVERLAP_TOLERANCE) of the contact distance). When
    /// `other` is a ball it is an earlier one.
    Overlap {
        /// The index in `balls`.
        ball: usize,
        /// A static shape, or an earlier ball.
        other: SceneItem,
    },
    /// The engine refused an item that passed validation. Validation applies the engine's
    /// own rules, so this signals a bug; it is reported rather than panicking.
    Engine {
        /// The item being added.
        item: SceneItem,
        /// The engine's reason.
        error: WorldError,
    },
}

impl fmt::Display for SceneError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            SceneError::Empty => {
                write!(f, "empty scene: expected a JSON object with a `balls` list")
            }
            SceneError::Parse {
                path,
                message,
                line,
                column,
            } => {
                if !path.is_empty() {
                    write!(f, "{path}: ")?;
                }
                write!(f, "{message}")?;
                if *line > 0 {
                    write!(f, " at line {line} column {column}")?;
                }
                Ok(())
            }
            SceneError::NotFinite { path } => write!(f, "{path} must be finite"),
            SceneError::NotPositive { path } => write!(f, "{path} must be > 0"),
            SceneError::RestitutionOutOfRange { path } => write!(f, "{path} must be in [0, 1]"),
            SceneError::OutOfRange { path, range } => write!(f, "{path} must be {range}"),
            SceneError::DegenerateSegment { index } => {
                write!(f, "segments[{index}]: end points must be distinct")
            }
            SceneError::SegmentLengthOutOfRange { index } => write!(
                f,
                "segments[{index}]: length out of range (its square must be a positive finite f64)"
            ),
            SceneError::DuplicateId { index, id, .. } => {
                write!(f, "balls[{index}]: duplicate id {id}")
            }
            SceneError::Overlap { ball, other } => write!(f, "balls[{ball}] overlaps {other}"),
            SceneError::Engine { item, error } => {
                write!(f, "{item}: refused by the engine: {error}")
            }
        }
    }
}

impl std::error::Error for SceneError {}
