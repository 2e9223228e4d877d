//! Reading a scene from JSON text and writing it back.
//!
//! `serde_json` (with `float_roundtrip`) reads every number to the nearest `f64` and writes the
//! shortest text that reads back to the same bits, so a scene survives a round trip exactly.
//! A number too large for an `f64` (`1e400`) is refused as "number out of range"; one too small
//! (`1e-400`) becomes 0, as IEEE rounding does. `serde_path_to_error` records where in the
//! document a reading error happened, so the message names the item (`balls[0].pos[1]`).

use serde_path_to_error::Segment;

use super::format::Object;
use super::{Scene, SceneError};

impl Scene {
    /// Reads a scene from JSON text and [validates](Scene::validate) it.
    ///
    /// # Errors
    /// [`SceneError::Empty`] for empty text, [`SceneError::Parse`] for malformed JSON or a
    /// document that does not follow the format (a wrong type, an unknown or missing key, a
    /// number out of range, trailing characters), and any error of [`Scene::validate`].
    pub fn from_json_str(text: &str) -> Result<Scene, SceneError> {
        if text.trim().is_empty() {
            return Err(SceneError::Empty);
        }
        let mut deserializer = serde_json::Deserializer::from_str(text);
        let Object(scene): Object<Scene> =
            serde_path_to_error::deserialize(&mut deserializer).map_err(parse_error)?;
        // Without this, text after the document (`{"balls": []} x`) would be ignored.
        deserializer
            .end()
            .map_err(|error| json_error(String::new(), &error))?;
        scene.validate()?;
        Ok(scene)
    }

    /// The scene as pretty-printed JSON that [`Scene::from_json_str`] reads back to an equal
    /// scene, every `f64` bit for bit (NaN and infinities, which JSON cannot spell, are written
    /// as `null` and do not read back).
    #[must_use]
    pub fn to_json_string(&self) -> String {
        serde_json::to_string_pretty(self).expect("a scene serialises to JSON: no maps, no I/O")
    }
}

fn parse_error(error: serde_path_to_error::Error<serde_json::Error>) -> SceneError {
    let path = path_string(error.path());
    json_error(path, error.inner())
}

/// Splits `serde_json`'s message from the position it appends, so the position can be
/// printed after the path.
fn json_error(path: String, error: &serde_json::Error) -> SceneError {
    let (line, column) = (error.line(), error.column());
    let text = error.to_string();
    let suffix = format!(" at line {line} column {column}");
    let message = text.strip_suffix(&suffix).unwrap_or(&text);
    SceneError::Parse {
        path: one_line(&path),
        message: one_line(message),
        line,
        column,
    }
}

/// `balls[0].pos[1]`: map keys joined by dots, list indices in brackets. Segments the
/// tracker could not name (`?`, inside a key being read) are left out.
fn path_string(path: &serde_path_to_error::Path) -> String {
    let mut out = String::new();
    for segment in path {
        match segment {
            Segment::Seq { index } => out.push_str(&format!("[{index}]")),
            Segment::Map { key } | Segment::Enum { variant: key } => {
                if !out.is_empty() {
                    out.push('.');
                }
                out.push_str(key);
            }
            Segment::Unknown => {}
        }
    }
    out
}

/// Escapes control characters: a key in the file may contain a newline, and an error must
/// stay on one line.
fn one_line(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        if c.is_control() {
            out.extend(c.escape_default());
        } else {
            out.push(c);
        }
    }
    out
}
