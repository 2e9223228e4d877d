//! What `exact2d simulate` writes: the result object and the event lines.
//!
//! Field order is part of the format, and `serde` writes struct fields in declaration order.
//! `serde_json` prints every `f64` as the shortest text that reads back to the same bits.

use std::fs::File;
use std::io::{BufWriter, Write};
use std::path::{Path, PathBuf};

use exact2d::scene::{BuiltScene, SceneItem};
use exact2d::{BallContactEvent, BallHandle, ContactEvent, Event, Feature};
use serde::Serialize;

use crate::failure::Failure;

/// The result: `{"time":T,"events":N,"wall_s":S,"balls":[...]}`, then `"asleep":K` for a
/// scene that lets balls sleep (a key added after the format's first version), then with
/// `--observables` `"virial":W,"since":T0,"colliders":[...]`.
#[derive(Serialize)]
pub struct Report {
    /// The time simulated to.
    pub time: f64,
    /// Collisions handled.
    pub events: u64,
    /// Seconds spent simulating.
    pub wall_s: f64,
    /// Every ball, in scene order.
    pub balls: Vec<BallState>,
    /// How many balls sleep at the end, if the scene lets them (`"sleep": true`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub asleep: Option<usize>,
    /// With `--observables`: the collision virial (`World::observables`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub virial: Option<f64>,
    /// With `--observables`: the time the observables count from.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub since: Option<f64>,
    /// With `--observables`: each collider's momentum and impacts, in scene order.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub colliders: Option<Vec<ColliderState>>,
}

/// `{"segment":I,"momentum":[x,y],"impacts":N}` (or `"circle":I`): what a scene collider took
/// (`World::collider_momentum`, `World::collider_impacts`).
#[derive(Serialize)]
pub struct ColliderState {
    /// Which collider, as the events file names it.
    #[serde(flatten)]
    pub item: ColliderItem,
    /// The momentum the balls gave it.
    pub momentum: [f64; 2],
    /// The collisions with it.
    pub impacts: u64,
}

/// A scene collider: `"segment":I` or `"circle":I`, its index in its list.
#[derive(Serialize)]
#[serde(rename_all = "lowercase")]
pub enum ColliderItem {
    /// `segments[I]`.
    Segment(usize),
    /// `circles[I]`.
    Circle(usize),
}

/// `{"id":ID,"pos":[x,y],"vel":[x,y]}`, and `"spin":W` last in a scene with spin or
/// friction (a key added after the format's first version), then `"roll":[x,y]` in a scene
/// with a table, then `"unwrapped":[x,y]` in a periodic box (the position plus the box
/// lengths crossed: for diffusion).
#[derive(Serialize)]
pub struct BallState {
    /// The ball's scene id.
    pub id: u64,
    /// Position of the centre.
    pub pos: [f64; 2],
    /// Velocity.
    pub vel: [f64; 2],
    /// Angular velocity, counter-clockwise positive, if the scene has spin or friction.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub spin: Option<f64>,
    /// On a table: the angular velocity about the horizontal axes (after `spin`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub roll: Option<[f64; 2]>,
    /// In a periodic box: the unwrapped position (after `roll`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub unwrapped: Option<[f64; 2]>,
}

/// One line of the events file: `{"time":t,"kind":...}`, then the fields of its kind, then
/// `"impulse"`: the normal impulse applied (the engine's `impulse`; added after the format's
/// first version, so readers of the older keys are unaffected).
#[derive(Serialize)]
struct EventLine {
    time: f64,
    #[serde(flatten)]
    collision: Collision,
    impulse: f64,
    /// The friction impulse (along `normal` turned a quarter counter-clockwise, on the ball
    /// of a ball-collider contact, on `b` of a ball-ball one), last, in a scene with spin or
    /// friction only (so that other scenes write what they always wrote).
    #[serde(skip_serializing_if = "Option::is_none")]
    tangential_impulse: Option<f64>,
}

/// What collided; serialised with `"kind"` first, then the variant's fields in order.
#[derive(Serialize)]
#[serde(tag = "kind")]
enum Collision {
    /// `"ball_segment","ball":ID,"segment":I,"point":[x,y],"normal":[x,y]`
    #[serde(rename = "ball_segment")]
    Segment {
        ball: u64,
        segment: usize,
        point: [f64; 2],
        normal: [f64; 2],
    },
    /// `"ball_end_point","ball":ID,"segment":I,"end":"a"|"b","point":[x,y],"normal":[x,y]`
    #[serde(rename = "ball_end_point")]
    EndPoint {
        ball: u64,
        segment: usize,
        end: End,
        point: [f64; 2],
        normal: [f64; 2],
    },
    /// `"ball_circle","ball":ID,"circle":I,"point":[x,y],"normal":[x,y]`
    #[serde(rename = "ball_circle")]
    Circle {
        ball: u64,
        circle: usize,
        point: [f64; 2],
        normal: [f64; 2],
    },
    /// `"ball_ball","balls":[ID_A,ID_B],"point":[x,y],"normal":[x,y]`
    #[serde(rename = "ball_ball")]
    Ball {
        balls: [u64; 2],
        point: [f64; 2],
        normal: [f64; 2],
    },
}

/// A segment's end point, `"a"` or `"b"`.
#[derive(Serialize)]
#[serde(rename_all = "lowercase")]
enum End {
    A,
    B,
}

/// The events file, written line by line as the simulation goes.
pub struct EventLog {
    path: PathBuf,
    out: BufWriter<File>,
    /// Whether lines carry the friction impulse (a scene with spin or friction).
    rough: bool,
}

impl EventLog {
    /// Creates (or truncates) the file; `rough`: the lines carry the friction impulse.
    pub fn create(path: &Path, rough: bool) -> Result<Self, Failure> {
        let file = File::create(path).map_err(|e| write_failure(path, &e))?;
        Ok(Self {
            path: path.to_owned(),
            out: BufWriter::new(file),
            rough,
        })
    }

    /// Writes the line of a collision; sensor events (which scenes cannot create) are skipped.
    pub fn write(&mut self, event: &Event, built: &BuiltScene) -> Result<(), Failure> {
        let line = match event {
            Event::Contact(contact) => EventLine {
                time: contact.time,
                collision: contact_collision(contact, built)?,
                impulse: contact.impulse,
                tangential_impulse: self.rough.then_some(contact.tangential_impulse),
            },
            Event::BallContact(contact) => EventLine {
                time: contact.time,
                collision: ball_collision(contact, built)?,
                impulse: contact.impulse,
                tangential_impulse: self.rough.then_some(contact.tangential_impulse),
            },
            Event::SensorEnter(_) | Event::SensorExit(_) => return Ok(()),
        };
        serde_json::to_writer(&mut self.out, &line)
            .map_err(std::io::Error::from)
            .and_then(|()| self.out.write_all(b"\n"))
            .map_err(|e| write_failure(&self.path, &e))
    }

    /// Flushes the file: a write error surfaces here rather than being lost on drop.
    pub fn finish(mut self) -> Result<(), Failure> {
        self.out.flush().map_err(|e| write_failure(&self.path, &e))
    }
}

fn contact_collision(contact: &ContactEvent, built: &BuiltScene) -> Result<Collision, Failure> {
    let ball = ball_id(built, contact.ball)?;
    let (point, normal) = (contact.point.to_array(), contact.normal.to_array());
    let collision = match (built.collider_item(contact.collider), contact.feature) {
        (Some(SceneItem::Segment(segment)), Feature::SegmentInterior) => Collision::Segment {
            ball,
            segment,
            point,
            normal,
        },
        (Some(SceneItem::Segment(segment)), Feature::SegmentEndA) => Collision::EndPoint {
            ball,
            segment,
            end: End::A,
            point,
            normal,
        },
        (Some(SceneItem::Segment(segment)), Feature::SegmentEndB) => Collision::EndPoint {
            ball,
            segment,
            end: End::B,
            point,
            normal,
        },
        (Some(SceneItem::Circle(circle)), Feature::Circle) => Collision::Circle {
            ball,
            circle,
            point,
            normal,
        },
        (item, feature) => {
            let message = format!("internal error: a contact with {item:?} at {feature:?}");
            return Err(Failure::Other(message));
        }
    };
    Ok(collision)
}

fn ball_collision(contact: &BallContactEvent, built: &BuiltScene) -> Result<Collision, Failure> {
    let balls = [ball_id(built, contact.a)?, ball_id(built, contact.b)?];
    let (point, normal) = (contact.point.to_array(), contact.normal.to_array());
    Ok(Collision::Ball {
        balls,
        point,
        normal,
    })
}

fn ball_id(built: &BuiltScene, handle: BallHandle) -> Result<u64, Failure> {
    built
        .ball_id(handle)
        .ok_or_else(|| Failure::Other(format!("internal error: unknown ball {handle:?}")))
}

/// Writes `value` as one JSON line on standard output. The whole line is serialised first, so
/// a failure leaves standard output empty.
pub fn print_json_line(value: &impl Serialize) -> Result<(), Failure> {
    let mut text =
        serde_json::to_vec(value).map_err(|e| Failure::Other(format!("internal error: {e}")))?;
    text.push(b'\n');
    let mut stdout = std::io::stdout().lock();
    stdout
        .write_all(&text)
        .and_then(|()| stdout.flush())
        .map_err(|e| Failure::Other(format!("cannot write the result to standard output: {e}")))
}

fn write_failure(path: &Path, error: &std::io::Error) -> Failure {
    Failure::Other(format!(
        "{}: cannot write the events: {error}",
        path.display()
    ))
}
