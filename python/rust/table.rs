//! A table seen from above (billiards, pool) in Python: its cloth as a dict of the four values
//! of [`exact2d::Table`], read from a mapping (missing keys take the pool cloth's,
//! [`Table::POOL`]), as the scene format's `"table"` reads them.

use exact2d::Table;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyMapping};

use crate::errors::invalid;

/// The keys of a table's dict, in the order of [`Table`]'s fields.
pub const KEYS: [&str; 4] = [
    "gravity",
    "sliding_friction",
    "rolling_friction",
    "spinning_friction",
];

/// `table`'s value under `key` (one of [`KEYS`]).
fn field<'a>(table: &'a mut Table, key: &str) -> Option<&'a mut f64> {
    match key {
        "gravity" => Some(&mut table.gravity),
        "sliding_friction" => Some(&mut table.sliding_friction),
        "rolling_friction" => Some(&mut table.rolling_friction),
        "spinning_friction" => Some(&mut table.spinning_friction),
        _ => None,
    }
}

/// A table from `None` (no table) or a mapping of some of [`KEYS`] to numbers (the others
/// the pool cloth's). The values are checked by the engine ([`exact2d::World::set_table`]).
pub fn table_of(value: &Bound<'_, PyAny>, name: &str) -> PyResult<Option<Table>> {
    if value.is_none() {
        return Ok(None);
    }
    let keys = KEYS.join(", ");
    let mapping = value.downcast::<PyMapping>().map_err(|_| {
        invalid(format!(
            "{name} must be None or a dict of numbers with some of the keys {keys}"
        ))
    })?;
    let mut table = Table::POOL;
    for item in mapping.items()?.try_iter()? {
        let (key, number): (Bound<'_, PyAny>, Bound<'_, PyAny>) = item?.extract()?;
        let key: String = key
            .extract()
            .map_err(|_| invalid(format!("{name}'s keys must be strings among {keys}")))?;
        let slot = field(&mut table, &key)
            .ok_or_else(|| invalid(format!("{name} has no key {key:?} (its keys: {keys})")))?;
        *slot = number
            .extract()
            .map_err(|_| invalid(format!("{name}[{key:?}] must be a number")))?;
    }
    Ok(Some(table))
}

/// `table` with the keyword values that are given (`set_table(..., sliding_friction=0.3)`).
pub fn with_values(mut table: Table, values: [Option<f64>; 4]) -> Table {
    for (key, value) in KEYS.into_iter().zip(values) {
        if let (Some(value), Some(slot)) = (value, field(&mut table, key)) {
            *slot = value;
        }
    }
    table
}

/// The dict of a table: its four values under [`KEYS`].
pub fn dict<'py>(py: Python<'py>, table: &Table) -> PyResult<Bound<'py, PyDict>> {
    let dict = PyDict::new(py);
    let values = [
        table.gravity,
        table.sliding_friction,
        table.rolling_friction,
        table.spinning_friction,
    ];
    for (key, value) in KEYS.into_iter().zip(values) {
        dict.set_item(key, value)?;
    }
    Ok(dict)
}

/// `World.set_table`'s first argument: missing (a pool table), or given (`None`: no table).
pub enum TableArg {
    /// Not given: the pool cloth, [`Table::POOL`].
    Pool,
    /// Given: a table, or `None` to take it away.
    Given(Option<Table>),
}

impl<'py> FromPyObject<'py> for TableArg {
    fn extract_bound(value: &Bound<'py, PyAny>) -> PyResult<Self> {
        table_of(value, "table").map(TableArg::Given)
    }
}
