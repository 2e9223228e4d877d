//! The native module of the `exact2d` and `onemorebrick` Python packages
//! (`exact2d._native`), built by maturin from `python/pyproject.toml`.
//!
//! The engine ([`exact2d`]) and the rules ([`onemorebrick`]) are wrapped as they are: Python
//! handles are integers never reused, numbers are validated before they reach Rust (bad
//! input raises a `ValueError` subclass carrying the Rust message, never a panic), arrays are
//! NumPy float64, and long runs release the GIL and stop on Ctrl-C. The Python side
//! (`python/src/exact2d`, `python/src/onemorebrick`) adds the exception classes and the
//! Gymnasium environment.

mod args;
mod errors;
mod events;
mod game;
mod ids;
mod render;
mod run_many;
mod state;
mod table;
mod text;
mod world;

use pyo3::prelude::*;

/// The native part of `exact2d` and `onemorebrick`; import those packages instead.
#[pymodule]
fn _native(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<world::PyWorld>()?;
    m.add_class::<events::PyEvent>()?;
    m.add_class::<world::PyCastHit>()?;
    m.add_function(wrap_pyfunction!(run_many::run_many, m)?)?;
    m.add_class::<game::PyGame>()?;
    m.add_class::<game::PyRandomBot>()?;
    m.add_class::<game::PyGreedyBot>()?;
    m.add("PICKUP_KINDS", game::PICKUP_NAMES.to_vec())?;
    m.add("CELL_KINDS", game::CELL_KINDS)?;
    m.add("EVENT_KINDS", events::KINDS.to_vec())?;
    Ok(())
}
