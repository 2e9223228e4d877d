//! `exact2d.run_many`: independent worlds run in parallel on a rayon pool.

use std::sync::atomic::{AtomicBool, Ordering};
use std::time::Duration;

use exact2d::World;
use numpy::IntoPyArray;
use pyo3::prelude::*;
use pyo3::types::PyDict;
use rayon::prelude::*;

use crate::errors::invalid;
use crate::state;
use crate::world::{EVENTS_PER_CHECK, PyWorld, pairs_array, world_error};

/// How often the calling thread looks for Ctrl-C while the pool works.
const SIGNAL_POLL: Duration = Duration::from_millis(20);

/// One world's outcome: events handled, or the engine's refusal.
type Outcome = Result<u64, exact2d::WorldError>;

fn run_one(world: &mut World, until: f64, cancel: &AtomicBool) -> Outcome {
    let mut handled = 0;
    while world.step_until(until)?.is_some() {
        handled += 1;
        if handled % EVENTS_PER_CHECK == 0 && cancel.load(Ordering::Relaxed) {
            break;
        }
    }
    Ok(handled)
}

/// A world to run from a scene (path or dict) or a `World` (copied exactly, `World.copy()`:
/// the original is not changed, and the copy goes on as the original would, bit for bit).
fn world_of(py: Python<'_>, item: &Bound<'_, PyAny>, index: usize) -> PyResult<PyWorld> {
    let prefixed = |e: PyErr| {
        let class = crate::errors::Class::from_err(py, &e);
        crate::errors::error(class, format!("scenes[{index}]: {}", e.value(py)))
    };
    if let Ok(w) = item.downcast::<PyWorld>() {
        return Ok(w.borrow().copy());
    }
    state::from_scene(py, item).map_err(prefixed)
}

/// Runs every scene to time `until` in parallel and returns one dict per scene, in order:
/// `handles` (int64, (n,)), `positions`, `velocities` (float64, (n, 2)), `spins`, `angles`
/// (float64, (n,), as `World.spins()` and `World.angles()`), `rolls` (float64, (n, 2), as
/// `World.rolls()`), `unwrapped` (float64, (n, 2), as `World.unwrapped_positions()`,
/// `positions` outside a periodic box), `collision_virial` and `observables_since` (floats,
/// as the `World` properties), `events` (the number handled) and `time`. Every array lists
/// the balls in the order of `handles`. `scenes` holds scene dicts, scene file paths or
/// `World`s (copied exactly, as `World.copy()`: the originals are not changed). `threads`:
/// the pool's size (default: one per core).
///
/// Each world is independent and deterministic, so the results do not depend on `threads`.
/// The GIL is released while the pool works; Ctrl-C stops every world within a few thousand
/// events and raises `KeyboardInterrupt`.
#[pyfunction]
#[pyo3(signature = (scenes, until, threads = None))]
pub fn run_many<'py>(
    py: Python<'py>,
    scenes: &Bound<'py, PyAny>,
    until: f64,
    threads: Option<i64>,
) -> PyResult<Vec<Bound<'py, PyDict>>> {
    if !(until >= 0.0) {
        return Err(invalid(format!("until must be >= 0 (got {until})")));
    }
    let threads = match threads {
        None => 0,
        Some(n) if (1..=1024).contains(&n) => n as usize,
        Some(n) => return Err(invalid(format!("threads must be in [1, 1024] (got {n})"))),
    };
    // Whole `PyWorld`s, not their engines alone: a copied `World` carries what its pickle
    // held beside the engine (images, observables), which `unwrapped` and the observables
    // include, as `World.unwrapped_positions()` and its properties do.
    let mut worlds = Vec::new();
    for (i, item) in scenes.try_iter()?.enumerate() {
        worlds.push(world_of(py, &item?, i)?);
    }
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .map_err(|e| invalid(format!("cannot start {threads} threads: {e}")))?;
    let cancel = AtomicBool::new(false);
    let mut interrupted = None;
    let outcomes: Option<Vec<Outcome>> = std::thread::scope(|scope| {
        let job = scope.spawn(|| {
            pool.install(|| {
                worlds
                    .par_iter_mut()
                    .map(|w| run_one(&mut w.world, until, &cancel))
                    .collect::<Vec<_>>()
            })
        });
        while !job.is_finished() {
            py.allow_threads(|| std::thread::sleep(SIGNAL_POLL));
            if interrupted.is_none() {
                if let Err(e) = py.check_signals() {
                    cancel.store(true, Ordering::Relaxed);
                    interrupted = Some(e);
                }
            }
        }
        job.join().ok()
    });
    if let Some(e) = interrupted {
        return Err(e);
    }
    let outcomes = outcomes.ok_or_else(|| {
        crate::errors::error(
            crate::errors::Class::Stalled,
            "internal error: a worker thread panicked",
        )
    })?;
    let mut results = Vec::with_capacity(worlds.len());
    for (i, (w, outcome)) in worlds.iter().zip(outcomes).enumerate() {
        let (world, ids) = (&w.world, &w.ids);
        let events = outcome.map_err(|e| {
            let err = world_error(e, ids);
            crate::errors::error(
                crate::errors::Class::from_err(py, &err),
                format!("scenes[{i}]: {}", err.value(py)),
            )
        })?;
        let dict = PyDict::new(py);
        let handles: Vec<i64> = world.balls().map(|(h, _)| ids.ball_id(h)).collect();
        let p: Vec<f64> = world
            .balls()
            .flat_map(|(_, b)| b.position.to_array())
            .collect();
        let v: Vec<f64> = world
            .balls()
            .flat_map(|(_, b)| b.velocity.to_array())
            .collect();
        dict.set_item("handles", handles.into_pyarray(py))?;
        dict.set_item("positions", pairs_array(py, p))?;
        dict.set_item("velocities", pairs_array(py, v))?;
        let spins: Vec<f64> = world.balls().map(|(_, b)| b.spin).collect();
        let angles: Vec<f64> = world.balls().map(|(_, b)| b.angle).collect();
        dict.set_item("spins", spins.into_pyarray(py))?;
        let rolls: Vec<f64> = world
            .balls()
            .flat_map(|(_, b)| crate::world::roll_of(&b).to_array())
            .collect();
        dict.set_item("rolls", pairs_array(py, rolls))?;
        dict.set_item("angles", angles.into_pyarray(py))?;
        dict.set_item("unwrapped", pairs_array(py, w.unwrapped_pairs()))?;
        dict.set_item("collision_virial", w.collision_virial_of())?;
        dict.set_item("observables_since", w.observables_since_of())?;
        dict.set_item("events", events)?;
        dict.set_item("time", world.time())?;
        results.push(dict);
    }
    Ok(results)
}
