//! Python handles: plain integers that are never reused within a world.
//!
//! The engine's handles are a slot and a generation; Python users get one integer per body
//! instead, counted up from 0 (or the scene's ids), so that a handle kept after its ball was
//! removed can never name another ball.

use std::collections::BTreeMap;

use exact2d::{BallHandle, ColliderHandle};

use crate::errors::{Class, error};
use pyo3::PyErr;

/// The map between Python handles and engine handles, both ways.
#[derive(Clone, Debug, Default)]
pub struct Ids {
    /// Ball slot index -> Python handle (`None`: empty slot).
    ball_of_slot: Vec<Option<(BallHandle, i64)>>,
    balls: BTreeMap<i64, BallHandle>,
    /// The next ball handle to give out.
    pub next_ball: i64,
    collider_of_slot: Vec<Option<(ColliderHandle, i64)>>,
    colliders: BTreeMap<i64, ColliderHandle>,
    /// The next collider handle to give out.
    pub next_collider: i64,
}

fn put<H: Copy>(table: &mut Vec<Option<(H, i64)>>, slot: u32, value: Option<(H, i64)>) {
    let slot = slot as usize;
    if table.len() <= slot {
        table.resize(slot + 1, None);
    }
    table[slot] = value;
}

impl Ids {
    /// Records a new ball under the Python handle `id`.
    pub fn add_ball(&mut self, handle: BallHandle, id: i64) {
        put(&mut self.ball_of_slot, handle.index(), Some((handle, id)));
        self.balls.insert(id, handle);
        self.next_ball = self.next_ball.max(id.saturating_add(1));
    }

    /// Records a new collider under the Python handle `id`.
    pub fn add_collider(&mut self, handle: ColliderHandle, id: i64) {
        put(
            &mut self.collider_of_slot,
            handle.index(),
            Some((handle, id)),
        );
        self.colliders.insert(id, handle);
        self.next_collider = self.next_collider.max(id.saturating_add(1));
    }

    /// Forgets a ball.
    pub fn remove_ball(&mut self, id: i64) {
        if let Some(handle) = self.balls.remove(&id) {
            put(&mut self.ball_of_slot, handle.index(), None);
        }
    }

    /// Forgets a collider.
    pub fn remove_collider(&mut self, id: i64) {
        if let Some(handle) = self.colliders.remove(&id) {
            put(&mut self.collider_of_slot, handle.index(), None);
        }
    }

    /// The engine handle of the ball `id`, or an `UnknownHandleError`.
    pub fn ball(&self, id: i64) -> Result<BallHandle, PyErr> {
        self.balls
            .get(&id)
            .copied()
            .ok_or_else(|| error(Class::UnknownHandle, format!("no ball with handle {id}")))
    }

    /// The engine handle of the collider `id`, or an `UnknownHandleError`.
    pub fn collider(&self, id: i64) -> Result<ColliderHandle, PyErr> {
        self.colliders.get(&id).copied().ok_or_else(|| {
            error(
                Class::UnknownHandle,
                format!("no collider with handle {id}"),
            )
        })
    }

    /// The Python handle of a live engine ball (`-1` if unknown: never for a live ball).
    pub fn ball_id(&self, handle: BallHandle) -> i64 {
        match self.ball_of_slot.get(handle.index() as usize) {
            Some(Some((h, id))) if *h == handle => *id,
            _ => -1,
        }
    }

    /// The Python handle of an engine collider (`-1` if unknown: a sleeping ball's circle).
    pub fn collider_id(&self, handle: ColliderHandle) -> i64 {
        match self.collider_of_slot.get(handle.index() as usize) {
            Some(Some((h, id))) if *h == handle => *id,
            _ => -1,
        }
    }
}
