//! The two engines, each run on a scene frame by frame at 60 Hz, as a game would.

use std::time::{Duration, Instant};

use exact2d::DVec2;
use exact2d::scene::Scene;
use rapier2d_f64::prelude::{
    CoefficientCombineRule, ColliderBuilder, Group, IntegrationParameters, InteractionGroups,
    InteractionTestMode, PhysicsWorld, RigidBodyBuilder, RigidBodyHandle, SpringCoefficients,
    Vector,
};

use crate::measure::BallState;

/// Frames per simulated second: every engine is observed (and exact2d advanced) at 60 Hz.
pub const FRAME_HZ: u32 = 60;

/// An engine to run a scene with.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Engine {
    /// exact2d, `advance_to(k / 60)` for every frame `k`.
    Exact2d,
    /// Rapier with this many fixed steps per simulated second (a multiple of 60).
    Rapier {
        /// Steps per second.
        hz: u32,
    },
}

impl Engine {
    /// The engines compared on every scene.
    pub const ALL: [Engine; 3] = [
        Engine::Exact2d,
        Engine::Rapier { hz: 60 },
        Engine::Rapier { hz: 240 },
    ];

    /// The engine's name in the table.
    #[must_use]
    pub fn label(self) -> String {
        match self {
            Engine::Exact2d => "exact2d".to_owned(),
            Engine::Rapier { hz } => format!("Rapier {hz} Hz"),
        }
    }

    /// Runs `scene` for `frames` frames, calling `observe(t, balls)` after each frame with
    /// the frame's time and the balls in scene order. Returns the wall time spent stepping
    /// the engine (building the world and observing it are not counted).
    ///
    /// # Errors
    /// A scene exact2d refuses, or an engine error while stepping, as a message.
    pub fn run(
        self,
        scene: &Scene,
        frames: u64,
        observe: impl FnMut(f64, &[BallState]),
    ) -> Result<Duration, String> {
        match self {
            Engine::Exact2d => run_exact2d(scene, frames, observe),
            Engine::Rapier { hz } => Ok(run_rapier(scene, frames, hz / FRAME_HZ, observe)),
        }
    }
}

/// The frames of a run of `seconds` simulated seconds (at least one).
#[must_use]
pub fn frames(seconds: f64) -> u64 {
    (seconds * f64::from(FRAME_HZ)).round().max(1.0) as u64
}

/// The balls of an exact2d world, `handles` in order, into `states`.
///
/// # Errors
/// A handle that is not live, as a message.
pub fn exact2d_states(
    world: &exact2d::World,
    handles: &[exact2d::BallHandle],
    states: &mut Vec<BallState>,
) -> Result<(), String> {
    states.clear();
    for &handle in handles {
        let ball = world.ball(handle).ok_or("a scene ball vanished")?;
        states.push(BallState {
            position: ball.position,
            velocity: ball.velocity,
        });
    }
    Ok(())
}

/// The balls of a Rapier world, `handles` in order, into `states`.
pub fn rapier_states(
    world: &PhysicsWorld,
    handles: &[RigidBodyHandle],
    states: &mut Vec<BallState>,
) {
    states.clear();
    states.extend(handles.iter().map(|&h| {
        let body = &world.bodies[h];
        let (p, v) = (body.translation(), body.linvel());
        BallState {
            position: DVec2::new(p.x, p.y),
            velocity: DVec2::new(v.x, v.y),
        }
    }));
}

/// The frame time of frame `k`, as every engine and the analytic reference see it.
#[must_use]
pub fn frame_time(k: u64) -> f64 {
    k as f64 / f64::from(FRAME_HZ)
}

fn run_exact2d(
    scene: &Scene,
    frames: u64,
    mut observe: impl FnMut(f64, &[BallState]),
) -> Result<Duration, String> {
    let mut built = scene.build_world().map_err(|e| e.to_string())?;
    let handles = built.ball_handles().to_vec();
    let mut states = Vec::with_capacity(handles.len());
    let mut wall = Duration::ZERO;
    for k in 1..=frames {
        let t = frame_time(k);
        let start = Instant::now();
        built.world_mut().advance_to(t).map_err(|e| e.to_string())?;
        wall += start.elapsed();
        exact2d_states(built.world(), &handles, &mut states)?;
        observe(t, &states);
    }
    Ok(wall)
}

/// Rapier's integration parameters for a step of `dt`, set to make it as exact as it can be
/// on bouncing balls (see the README of this crate for each choice).
#[must_use]
pub fn rapier_parameters(dt: f64) -> IntegrationParameters {
    IntegrationParameters {
        dt,
        // The default caps speeds at 400 units/s, which would slow the fast balls down.
        normalized_max_linear_velocity: f64::MAX,
        // Recycled contacts keep stale points for up to 0.05 units of motion.
        contact_recycling: false,
        // Let CCD split a step at up to 16 successive impacts instead of clamping the motion
        // at the first one (the default is 1).
        max_ccd_substeps: 16,
        // Contacts 4 times stiffer than the defaults (30 Hz, and 60 Hz against fixed bodies):
        // less overlap before a contact pushes back. Stiffer still (1000 Hz, or critical
        // damping) measured no better.
        contact_softness: SpringCoefficients::new(120.0, 10.0),
        static_contact_softness: SpringCoefficients::new(240.0, 10.0),
        // Speculative contacts from 0.1 units away (the radius of the standard set's balls)
        // instead of 0.02: less overlap in every standard scene, at little cost.
        normalized_prediction_distance: 0.1,
        ..IntegrationParameters::default()
    }
}

/// Builds the Rapier world of a scene: one fixed body holding the segments and circles, and
/// one dynamic ball per scene ball, in scene order; frictionless, the balls' rotations
/// locked, as in exact2d.
pub(crate) fn rapier_world(scene: &Scene, dt: f64) -> (PhysicsWorld, Vec<RigidBodyHandle>) {
    rapier_world_with_friction(scene, dt, None)
}

/// [`rapier_world`], or with `friction` (Coulomb's coefficient on every collider, combined
/// as a product) and the balls free to turn, so that they roll: a scene as a game would set
/// it up in Rapier, for comparison with what exact2d models (no friction).
pub(crate) fn rapier_world_with_friction(
    scene: &Scene,
    dt: f64,
    friction: Option<f64>,
) -> (PhysicsWorld, Vec<RigidBodyHandle>) {
    let mut world = PhysicsWorld::new();
    world.gravity = vector(scene.gravity);
    world.integration_parameters = rapier_parameters(dt);
    let elastic = |builder: ColliderBuilder, restitution: f64| {
        builder
            .friction(friction.unwrap_or(0.0))
            .friction_combine_rule(CoefficientCombineRule::Multiply)
            .restitution(restitution)
            .restitution_combine_rule(CoefficientCombineRule::Multiply)
    };
    let ground = world.insert_body(RigidBodyBuilder::fixed());
    for s in &scene.segments {
        let segment = ColliderBuilder::segment(vector(s.a), vector(s.b));
        world.insert_collider(elastic(segment, s.restitution), Some(ground));
    }
    for c in &scene.circles {
        let circle = ColliderBuilder::ball(c.radius).translation(vector(c.center));
        world.insert_collider(elastic(circle, c.restitution), Some(ground));
    }
    // Balls are in group 1; without ball_ball they interact with every group but their own.
    let groups = if scene.ball_ball {
        InteractionGroups::all()
    } else {
        InteractionGroups::new(Group::GROUP_1, !Group::GROUP_1, InteractionTestMode::And)
    };
    let balls = scene
        .balls
        .iter()
        .map(|b| {
            let body = RigidBodyBuilder::dynamic()
                .translation(vector(b.pos))
                .linvel(vector(b.vel));
            let body = if friction.is_some() {
                body
            } else {
                body.lock_rotations()
            };
            let body = body
                .ccd_enabled(true)
                // Sleeping as the scene says (its `sleep` key), with Rapier's own thresholds.
                .can_sleep(scene.sleep);
            let collider = elastic(ColliderBuilder::ball(b.radius), b.restitution)
                .mass(b.mass)
                .collision_groups(groups);
            world.insert(body, collider).0
        })
        .collect();
    (world, balls)
}

fn run_rapier(
    scene: &Scene,
    frames: u64,
    steps_per_frame: u32,
    mut observe: impl FnMut(f64, &[BallState]),
) -> Duration {
    let (mut world, handles) = rapier_world(scene, 1.0 / f64::from(FRAME_HZ * steps_per_frame));
    let mut states = Vec::with_capacity(handles.len());
    let mut wall = Duration::ZERO;
    for k in 1..=frames {
        let start = Instant::now();
        for _ in 0..steps_per_frame {
            world.step();
        }
        wall += start.elapsed();
        rapier_states(&world, &handles, &mut states);
        observe(frame_time(k), &states);
    }
    wall
}

pub(crate) fn vector([x, y]: [f64; 2]) -> Vector {
    Vector::new(x, y)
}
