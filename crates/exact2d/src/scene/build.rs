//! Turning a scene into a [`World`], and mapping the engine's handles back to scene items.

use std::num::NonZeroU32;

use super::{Scene, SceneBall, SceneError, SceneItem};
use crate::{
    BallDesc, BallHandle, ColliderDesc, ColliderHandle, CollisionGroups, DVec2, World, WorldError,
};

/// The groups of balls that pass through each other (`ball_ball: false`): members of group 1
/// that interact with every group but 1, so they still hit colliders, which are in all groups.
const BALLS_IGNORE_EACH_OTHER: CollisionGroups = CollisionGroups::new(1, !1);

/// A scene turned into a world at time 0, with the map between the world's handles and the
/// scene's items.
///
/// Handles map back only while they are live: a ball removed from the world (or added later
/// through [`world_mut`](Self::world_mut)) has no scene index.
pub struct BuiltScene {
    world: World,
    /// Scene index -> handle.
    ball_handles: Vec<BallHandle>,
    /// Scene index -> id.
    ball_ids: Vec<u64>,
    /// Ball slot index -> scene index plus one.
    ball_slots: Vec<Option<NonZeroU32>>,
    /// Collider slot index -> (handle, item).
    collider_slots: Vec<Option<(ColliderHandle, SceneItem)>>,
}

impl Scene {
    /// Validates the scene and builds its world at time 0.
    ///
    /// Bodies are added in scene order (segments, then circles, then balls), so the same scene
    /// always gives the same world, bit for bit. Each collider's `user_data` is its index in
    /// its list, each ball's is its `id`. Balls collide with each other only if `ball_ball`
    /// is set; a pair's restitution is the product of its two values (the engine's rule).
    ///
    /// The engine predicts each ball's first event as it is added, against every body, so
    /// building takes O(n^2) for n balls.
    ///
    /// # Errors
    /// Any error of [`Scene::validate`]; [`SceneError::Engine`] should the engine still refuse
    /// an item (a bug).
    pub fn build_world(&self) -> Result<BuiltScene, SceneError> {
        // The tables that live as long as the world (its balls' arrays, this map) are made
        // before validation's, which come and go: so they do not land among the holes those
        // leave. With glibc, freeing a table of 128 KiB to 32 MiB raises the size from which
        // it maps memory of its own to that table's, and a table below that size comes from
        // the heap, whose holes stay resident: built after validation, a 10^6-disk periodic
        // box kept 25 MB more resident than it held. Reserving maps no pages, so a scene that
        // fails validation costs nothing for it; a world this makes where validation would
        // fail is dropped, and the error is validation's.
        let reserved = self.configured_world().map(|mut world| {
            world.reserve_balls(self.balls.len());
            BuiltScene {
                world,
                ball_handles: Vec::with_capacity(self.balls.len()),
                ball_ids: Vec::with_capacity(self.balls.len()),
                ball_slots: Vec::with_capacity(self.balls.len()),
                collider_slots: Vec::new(),
            }
        });
        self.validate()?;
        let mut built = reserved?;
        for (i, s) in self.segments.iter().enumerate() {
            let desc = ColliderDesc::segment(DVec2::from(s.a), DVec2::from(s.b));
            let desc = desc
                .restitution(s.restitution)
                .friction(s.friction)
                .tangential_restitution(s.tangential_restitution)
                .rolling_resistance(s.rolling_resistance);
            built.add_collider(SceneItem::Segment(i), desc)?;
        }
        for (i, c) in self.circles.iter().enumerate() {
            let desc = ColliderDesc::circle(DVec2::from(c.center), c.radius);
            let desc = desc
                .restitution(c.restitution)
                .friction(c.friction)
                .tangential_restitution(c.tangential_restitution)
                .rolling_resistance(c.rolling_resistance);
            built.add_collider(SceneItem::Circle(i), desc)?;
        }
        let groups = if self.ball_ball {
            CollisionGroups::default()
        } else {
            BALLS_IGNORE_EACH_OTHER
        };
        for (i, ball) in self.balls.iter().enumerate() {
            built.add_ball(i, ball, groups)?;
        }
        Ok(built)
    }

    /// An empty world with the scene's gravity, sleeping, periodic box and table.
    fn configured_world(&self) -> Result<World, SceneError> {
        let gravity = DVec2::from(self.gravity);
        let mut world = World::with_gravity(gravity).map_err(|_| SceneError::NotFinite {
            path: "gravity".to_owned(),
        })?;
        world.set_sleeping(self.sleep);
        if let Some(size) = self.periodic {
            world
                .set_periodic(DVec2::from(size))
                .map_err(|_| SceneError::OutOfRange {
                    path: "periodic".to_owned(),
                    range: "finite and > 0, with gravity [0, 0] and no table",
                })?;
        }
        if let Some(table) = self.table {
            world
                .set_table(Some(table.into()))
                .map_err(|error| SceneError::OutOfRange {
                    path: "table".to_owned(),
                    range: match error {
                        WorldError::TableAndGravity => "with gravity [0, 0]",
                        _ => "finite, gravity > 0 and frictions >= 0",
                    },
                })?;
        }
        Ok(world)
    }
}

impl BuiltScene {
    fn add_collider(&mut self, item: SceneItem, desc: ColliderDesc) -> Result<(), SceneError> {
        let (SceneItem::Segment(index) | SceneItem::Circle(index) | SceneItem::Ball(index)) = item;
        let handle = self
            .world
            .add_collider(desc.user_data(index as u64))
            .map_err(|error| SceneError::Engine { item, error })?;
        put(&mut self.collider_slots, handle.index(), (handle, item));
        Ok(())
    }

    fn add_ball(
        &mut self,
        index: usize,
        ball: &SceneBall,
        groups: CollisionGroups,
    ) -> Result<(), SceneError> {
        let desc = BallDesc::new(DVec2::from(ball.pos), ball.radius)
            .velocity(DVec2::from(ball.vel))
            .mass(ball.mass)
            .restitution(ball.restitution)
            .spin(ball.spin)
            .roll(DVec2::from(ball.roll))
            .inertia(ball.inertia)
            .friction(ball.friction)
            .tangential_restitution(ball.tangential_restitution)
            .rolling_resistance(ball.rolling_resistance)
            .groups(groups)
            .user_data(ball.id);
        let handle = self
            .world
            .add_ball(desc)
            .map_err(|error| self.engine_error(index, error))?;
        // Stored plus one, in four bytes (a world has fewer than 2^32 ball slots, so a scene
        // that builds has fewer balls).
        if let Some(stored) = u32::try_from(index + 1).ok().and_then(NonZeroU32::new) {
            put(&mut self.ball_slots, handle.index(), stored);
        }
        self.ball_handles.push(handle);
        self.ball_ids.push(ball.id);
        Ok(())
    }

    /// Names the other party of an overlap the engine found, if it is one of ours.
    fn engine_error(&self, ball: usize, error: WorldError) -> SceneError {
        let other = match error {
            WorldError::OverlapsCollider(handle) => self.collider_item(handle),
            WorldError::OverlapsBall(handle) => self.ball_index(handle).map(SceneItem::Ball),
            _ => None,
        };
        match other {
            Some(other) => SceneError::Overlap { ball, other },
            None => SceneError::Engine {
                item: SceneItem::Ball(ball),
                error,
            },
        }
    }

    /// The world, at time 0 until it is stepped.
    #[must_use]
    pub fn world(&self) -> &World {
        &self.world
    }

    /// The world, to step it (or change it).
    pub fn world_mut(&mut self) -> &mut World {
        &mut self.world
    }

    /// The world alone, dropping the map.
    #[must_use]
    pub fn into_world(self) -> World {
        self.world
    }

    /// The balls' handles, in scene order: `ball_handles()[i]` is `balls[i]`.
    #[must_use]
    pub fn ball_handles(&self) -> &[BallHandle] {
        &self.ball_handles
    }

    /// The balls' ids, in scene order.
    #[must_use]
    pub fn ball_ids(&self) -> &[u64] {
        &self.ball_ids
    }

    /// The index in `balls` of the ball with this handle; `None` if it is not a scene ball.
    #[must_use]
    pub fn ball_index(&self, handle: BallHandle) -> Option<usize> {
        let index = (*self.ball_slots.get(handle.index() as usize)?)?.get() as usize - 1;
        let live = self.ball_handles[index] == handle && self.world.ball(handle).is_some();
        live.then_some(index)
    }

    /// The scene `id` of the ball with this handle; `None` if it is not a scene ball.
    #[must_use]
    pub fn ball_id(&self, handle: BallHandle) -> Option<u64> {
        self.ball_index(handle).map(|index| self.ball_ids[index])
    }

    /// The scene item (`segments[i]` or `circles[i]`) of the collider with this handle; `None`
    /// if it is not a scene collider.
    #[must_use]
    pub fn collider_item(&self, handle: ColliderHandle) -> Option<SceneItem> {
        let (stored, item) = (*self.collider_slots.get(handle.index() as usize)?)?;
        (stored == handle && self.world.collider(handle).is_some()).then_some(item)
    }
}

/// Stores `value` at `slot`, growing the table as needed.
fn put<T: Copy>(table: &mut Vec<Option<T>>, slot: u32, value: T) {
    let slot = slot as usize;
    if table.len() <= slot {
        table.resize(slot + 1, None);
    }
    table[slot] = Some(value);
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Event;

    const SCENE: &str = r#"{
        "segments": [ { "a": [10, -5], "b": [10, 5] }, { "a": [-10, -5], "b": [-10, 5], "restitution": 0.5 } ],
        "circles": [ { "center": [0, 3], "radius": 1 } ],
        "balls": [
            { "id": 42, "pos": [-2, 0], "vel": [1, 0], "radius": 0.5 },
            { "id": 7, "pos": [2, 0], "vel": [-1, 0], "radius": 0.5, "restitution": 0.5 }
        ]
    }"#;

    #[test]
    fn handles_map_back_to_scene_items_and_ids() {
        let built = Scene::from_json_str(SCENE).unwrap().build_world().unwrap();
        let handles = built.ball_handles().to_vec();
        assert_eq!(built.ball_ids(), &[42, 7]);
        assert_eq!(
            handles
                .iter()
                .map(|&h| built.ball_index(h))
                .collect::<Vec<_>>(),
            [Some(0), Some(1)]
        );
        assert_eq!(built.ball_id(handles[1]), Some(7));
        let items: Vec<_> = built
            .world()
            .colliders()
            .map(|(h, _)| built.collider_item(h))
            .collect();
        let expected = [
            SceneItem::Segment(0),
            SceneItem::Segment(1),
            SceneItem::Circle(0),
        ];
        assert_eq!(items, expected.map(Some));
        let restitutions: Vec<f64> = built
            .world()
            .colliders()
            .map(|(_, c)| c.restitution)
            .collect();
        assert_eq!(restitutions, [1.0, 0.5, 1.0]);
        assert_eq!(built.world().ball(handles[1]).unwrap().user_data, 7);
    }

    #[test]
    fn a_removed_ball_no_longer_maps_back() {
        let mut built = Scene::from_json_str(SCENE).unwrap().build_world().unwrap();
        let handle = built.ball_handles()[0];
        built.world_mut().remove_ball(handle).unwrap();
        let new = built
            .world_mut()
            .add_ball(BallDesc::new(DVec2::new(0.0, -3.0), 0.5))
            .unwrap();
        assert_eq!(new.index(), handle.index(), "the slot is reused");
        assert_eq!(
            (built.ball_index(handle), built.ball_index(new)),
            (None, None)
        );
    }

    #[test]
    fn balls_pass_through_each_other_unless_ball_ball_is_set() {
        // The two balls meet head on at t = 1.5; without ball_ball they reach the walls.
        let first_event = |scene: &str| {
            let mut built = Scene::from_json_str(scene).unwrap().build_world().unwrap();
            built.world_mut().step().unwrap()
        };
        assert!(matches!(first_event(SCENE), Event::Contact(_)));
        let colliding = SCENE.replacen('{', r#"{ "ball_ball": true,"#, 1);
        let Event::BallContact(contact) = first_event(&colliding) else {
            panic!("no ball contact")
        };
        assert_eq!(contact.time, 1.5);
    }
}
