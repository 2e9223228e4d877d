//! Reading arguments from Python: every refusal is an `InvalidInputError` naming the
//! argument and what it must be, never a panic or a bare `TypeError` from deep inside.

use exact2d::{CollisionGroups, DVec2};
use pyo3::prelude::*;

use crate::errors::invalid;

/// A pair of numbers `(x, y)`: a tuple, a list or a NumPy array of two numbers.
pub fn pair(value: &Bound<'_, PyAny>, name: &str) -> PyResult<DVec2> {
    let numbers: Vec<f64> = value
        .extract()
        .map_err(|_| invalid(format!("{name} must be a pair of numbers (x, y)")))?;
    match numbers[..] {
        [x, y] => Ok(DVec2::new(x, y)),
        _ => Err(invalid(format!(
            "{name} must be a pair of numbers (x, y), got {} numbers",
            numbers.len()
        ))),
    }
}

/// A finite number.
pub fn finite(value: f64, name: &str) -> PyResult<f64> {
    if value.is_finite() {
        Ok(value)
    } else {
        Err(invalid(format!("{name} must be finite (got {value})")))
    }
}

/// Collision groups `(memberships, filter)`, two 32-bit masks; `None` is every group.
pub fn groups(value: Option<&Bound<'_, PyAny>>) -> PyResult<CollisionGroups> {
    let Some(value) = value.filter(|v| !v.is_none()) else {
        return Ok(CollisionGroups::default());
    };
    let message = || {
        invalid("groups must be a pair of integers (memberships, filter), each in [0, 2**32 - 1]")
    };
    let masks: Vec<i64> = value.extract().map_err(|_| message())?;
    let mask = |m: i64| u32::try_from(m).map_err(|_| message());
    match masks[..] {
        [memberships, filter] => Ok(CollisionGroups::new(mask(memberships)?, mask(filter)?)),
        _ => Err(message()),
    }
}

/// A count in `[0, max]`.
pub fn count(value: i64, name: &str, max: i64) -> PyResult<usize> {
    count_in(value, name, 0, max)
}

/// A count in `[min, max]` (`0 <= min`).
pub fn count_in(value: i64, name: &str, min: i64, max: i64) -> PyResult<usize> {
    if (min..=max).contains(&value) {
        Ok(value as usize)
    } else {
        Err(invalid(format!(
            "{name} must be in [{min}, {max}] (got {value})"
        )))
    }
}

/// A seed: an integer in `[0, 2**64 - 1]`.
pub fn seed(value: &Bound<'_, PyAny>, name: &str) -> PyResult<u64> {
    value
        .extract::<u64>()
        .map_err(|_| invalid(format!("{name} must be an integer in [0, 2**64 - 1]")))
}
