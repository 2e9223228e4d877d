//! How the command names bodies in its messages: a ball by its scene id (`ball 7`), a
//! collider by its item in the scene (`segments[2]`, `circles[0]`), as the events file and
//! the soak's violations do.
//!
//! A scene's world keeps those names in the bodies' `user_data` (a ball's id, a collider's
//! index in its list), so they are read from the [`World`] alone.

use exact2d::{BallHandle, Collider, ColliderHandle, Event, Shape, World, WorldError};

/// A collider's scene name, `segments[i]` or `circles[i]` (a scene stores the index in
/// `user_data`).
#[must_use]
pub fn collider_name(collider: &Collider) -> String {
    match collider.shape {
        Shape::Segment(_) => format!("segments[{}]", collider.user_data),
        Shape::Circle(_) => format!("circles[{}]", collider.user_data),
    }
}

/// `ball ID`, the ball's scene id; `ball #HANDLE` (its slot) if the world has no such ball.
#[must_use]
pub fn ball(world: &World, handle: BallHandle) -> String {
    match world.ball(handle) {
        Some(ball) => format!("ball {}", ball.user_data),
        None => format!("ball #{}", handle.index()),
    }
}

/// The collider's scene name ([`collider_name`]); `collider #HANDLE` if the world has no
/// such collider.
#[must_use]
pub fn collider(world: &World, handle: ColliderHandle) -> String {
    match world.collider(handle) {
        Some(c) => collider_name(c),
        None => format!("collider #{}", handle.index()),
    }
}

/// The bodies of an event: `ball 1 and ball 2`, `ball 1 and segments[0]`, or for a sensor
/// event `ball 1 and sensor circles[3]`.
#[must_use]
pub fn of_event(world: &World, event: &Event) -> String {
    match event {
        Event::Contact(c) => format!(
            "{} and {}",
            ball(world, c.ball),
            collider(world, c.collider)
        ),
        Event::BallContact(c) => format!("{} and {}", ball(world, c.a), ball(world, c.b)),
        Event::SensorEnter(s) | Event::SensorExit(s) => {
            let sensor = collider(world, s.collider);
            format!("{} and sensor {sensor}", ball(world, s.ball))
        }
    }
}

/// The message of the engine's stall error ([`WorldError::Stalled`]), with the bodies named
/// as the scene names them: `the clock stalled at t = 1.5: 3000 events at that instant;
/// the last between ball 1 and segments[0]`. `None` for any other error.
#[must_use]
pub fn stall(world: &World, error: &WorldError) -> Option<String> {
    let WorldError::Stalled {
        time,
        events,
        ball: first,
        other_ball,
        collider: partner,
    } = *error
    else {
        return None;
    };
    let mut bodies = ball(world, first);
    if let Some(other) = other_ball {
        bodies = format!("{bodies} and {}", ball(world, other));
    }
    if let Some(c) = partner {
        bodies = format!("{bodies} and {}", collider(world, c));
    }
    Some(format!(
        "the clock stalled at t = {time:?}: {events} events at that instant; the last between {bodies}"
    ))
}

#[cfg(test)]
mod tests {
    use super::*;
    use exact2d::{BallDesc, ColliderDesc, DVec2};

    /// A world as a scene builds it: ids and item indices in `user_data`.
    fn world() -> (World, [BallHandle; 2], [ColliderHandle; 2]) {
        let mut world = World::new();
        let floor = ColliderDesc::segment(DVec2::new(-5.0, 0.0), DVec2::new(5.0, 0.0));
        let floor = world.add_collider(floor.user_data(3)).unwrap();
        let peg = ColliderDesc::circle(DVec2::new(0.0, 5.0), 1.0);
        let peg = world.add_collider(peg.user_data(0)).unwrap();
        let a = BallDesc::new(DVec2::new(0.0, 1.0), 0.5).user_data(41);
        let b = BallDesc::new(DVec2::new(2.0, 1.0), 0.5).user_data(42);
        let (a, b) = (world.add_ball(a).unwrap(), world.add_ball(b).unwrap());
        (world, [a, b], [floor, peg])
    }

    #[test]
    fn a_stall_names_the_time_the_count_and_the_bodies_by_their_scene_names() {
        let (world, [a, b], [floor, peg]) = world();
        let with_ball = WorldError::Stalled {
            time: 1.5,
            events: 3000,
            ball: a,
            other_ball: Some(b),
            collider: None,
        };
        assert_eq!(
            stall(&world, &with_ball).unwrap(),
            "the clock stalled at t = 1.5: 3000 events at that instant; the last between ball 41 and ball 42"
        );
        let with_collider = WorldError::Stalled {
            time: 0.25,
            events: 2001,
            ball: b,
            other_ball: None,
            collider: Some(floor),
        };
        assert_eq!(
            stall(&world, &with_collider).unwrap(),
            "the clock stalled at t = 0.25: 2001 events at that instant; the last between ball 42 and segments[3]"
        );
        let at_peg = WorldError::Stalled {
            time: 0.25,
            events: 2001,
            ball: b,
            other_ball: None,
            collider: Some(peg),
        };
        assert!(
            stall(&world, &at_peg)
                .unwrap()
                .ends_with("ball 42 and circles[0]")
        );
        assert_eq!(stall(&world, &WorldError::DegenerateSegment), None);
    }

    #[test]
    fn a_body_the_world_no_longer_has_is_named_by_its_slot() {
        let (mut world, [a, _], [floor, _]) = world();
        world.remove_ball(a).unwrap();
        world.remove_collider(floor).unwrap();
        assert_eq!(ball(&world, a), format!("ball #{}", a.index()));
        assert_eq!(
            collider(&world, floor),
            format!("collider #{}", floor.index())
        );
    }
}
