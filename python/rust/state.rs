//! Scenes and pickling: a world to and from the scene format, and to and from its full state.
//!
//! The scene format (version 1) describes a world at time 0 with the keys the CLI reads. A
//! pickled world needs more (the clock, sensors, groups, handles), so its state is a JSON
//! object of its own: `{"format": "exact2d-py-world", "version": 1, ...}`, with every body
//! as it is now. Loading it builds a world at that time with the same bodies, handles and
//! settings, adding colliders and then balls in slot order. Restated at the pickled instant,
//! its future matches the original's to rounding; a world pickled before its first step
//! continues bit for bit. `World.copy()` (the engine's clone, `copy.copy` and `copy.deepcopy`
//! too) is the exact branch mid-run; pickling is for other processes.
//!
//! Spin (version 2): every ball keeps its spin, moment of inertia, friction, tangential
//! restitution and angle (set back with `World::set_ball_angle`), every collider its friction
//! and tangential restitution. Rolling resistance (still version 2, an optional key): every
//! ball and collider keeps its own; a pickle without it (older, or version 1) loads with 0.
//!
//! Table (version 3): the world's table (`"table"`: its four values, or `null`) and every
//! ball's roll; versions 1 and 2 load without a table. The table is set before the balls are
//! added, so each ball on the cloth takes its phase (sliding, rolling, spinning) afresh from
//! its state at the pickled instant: a world pickled before its first step continues bit for
//! bit, one pickled mid-run to rounding (its trajectories and phase ends restated then). The
//! engine keeps a roll as its contact point's velocity `c = r (-w_y, w_x)` and reports
//! `w = c / r`, so the `c` loaded is `(c / r) r`: a rolling ball's is snapped back to `-v`
//! (a slip within rounding is none), and a roll as given (`c` = `w r` rounded) came back
//! exactly in every test; a sliding ball's may come back an ulp off.
//!
//! Periodic boxes and observables (version 4): the world's periodic box (`"periodic"`:
//! `[Lx, Ly]`, or `null`), set before any body is added; every ball's images (`"images"`:
//! the box lengths it has crossed, `[kx, ky]`, in a periodic box only); the observables
//! (`"observables"`: `since` and the collision `virial`) and every collider's `momentum` and
//! `impacts`. The engine cannot be handed images or accumulated observables, so the loaded
//! world carries them beside it ([`Carried`]) and adds them to the engine's own when they
//! are read: at the pickled instant the values are the original's, bit for bit (the images
//! are integers, and the engine's sums start again from zero). After that they agree to the
//! rounding of the restated world (a world pickled before its first step: bit for bit), and
//! `reset_observables` drops the carried observables.

use std::collections::BTreeMap;
use std::path::PathBuf;

use exact2d::scene::{Scene, SceneBall, SceneCircle, SceneItem, SceneSegment};
use exact2d::{BallDesc, ColliderDesc, CollisionGroups, DVec2, Shape, Table, World};
use pyo3::prelude::*;
use serde_json::{Value, json};

use crate::errors::{Class, error, invalid};
use crate::ids::Ids;
use crate::world::{PyWorld, roll_of, world_error};

const STATE_FORMAT: &str = "exact2d-py-world";
/// The version written; versions 1 (before spin and friction), 2 (before tables) and 3
/// (before periodic boxes and observables) are still read.
const STATE_VERSION: u64 = 4;

/// What a world loaded from a pickle carries beside its engine, which cannot be handed it
/// back: added to the engine's values when they are read (see the module's doc).
#[derive(Clone, Debug, Default)]
pub struct Carried {
    /// Per ball handle, the images it had crossed when pickled (`[kx, ky]`, never `[0, 0]`).
    pub images: BTreeMap<i64, [i64; 2]>,
    /// The observables when pickled, until `reset_observables`.
    pub observables: Option<CarriedObservables>,
}

/// The observables of a pickled world (see [`Carried`]).
#[derive(Clone, Debug, Default)]
pub struct CarriedObservables {
    /// When they started.
    pub since: f64,
    /// The collision virial.
    pub virial: f64,
    /// Per collider handle, the momentum given to it and its impacts.
    pub colliders: BTreeMap<i64, (DVec2, u64)>,
}

/// The groups the scene format gives balls with `ball_ball: false`.
const BALLS_IGNORE_EACH_OTHER: CollisionGroups = CollisionGroups::new(1, !1);

/// Reads a scene from a path or a dict: the text, and the prefix of its messages.
pub fn scene_text(py: Python<'_>, scene: &Bound<'_, PyAny>) -> PyResult<(String, String)> {
    if scene.is_instance_of::<pyo3::types::PyDict>() {
        let module = py.import("exact2d._scene")?;
        let text: String = module.call_method1("dumps", (scene,))?.extract()?;
        return Ok((text, String::new()));
    }
    let path: PathBuf = scene.extract().map_err(|_| {
        invalid("a scene must be a dict or a path to a JSON file (str or os.PathLike)")
    })?;
    let text = std::fs::read_to_string(&path).map_err(|e| {
        pyo3::exceptions::PyOSError::new_err(format!(
            "{}: cannot read the scene: {e}",
            path.display()
        ))
    })?;
    Ok((text, format!("{}: ", path.display())))
}

/// Parses and validates a scene, with the CLI's messages.
pub fn parse_scene(text: &str, prefix: &str) -> PyResult<Scene> {
    let scene =
        Scene::from_json_str(text).map_err(|e| error(Class::Scene, format!("{prefix}{e}")))?;
    scene
        .validate()
        .map_err(|e| error(Class::Scene, format!("{prefix}{e}")))?;
    if let Some((i, b)) = scene
        .balls
        .iter()
        .enumerate()
        .find(|(_, b)| b.id >= i64::MAX as u64)
    {
        return Err(error(
            Class::Scene,
            format!(
                "{prefix}balls[{i}].id must be below 2**63 in Python (got {})",
                b.id
            ),
        ));
    }
    Ok(scene)
}

/// Builds a validated scene's world, with the scene's ids as handles.
pub fn build_scene(scene: &Scene, prefix: &str) -> PyResult<PyWorld> {
    let built = scene
        .build_world()
        .map_err(|e| error(Class::Scene, format!("{prefix}{e}")))?;
    let mut ids = Ids::default();
    for (&handle, &id) in built.ball_handles().iter().zip(built.ball_ids()) {
        ids.add_ball(handle, id as i64);
    }
    let segments = scene.segments.len() as i64;
    let colliders: Vec<_> = built.world().colliders().map(|(h, _)| h).collect();
    for handle in colliders {
        let id = match built.collider_item(handle) {
            Some(SceneItem::Segment(i)) => i as i64,
            Some(SceneItem::Circle(i)) => segments + i as i64,
            _ => continue,
        };
        ids.add_collider(handle, id);
    }
    Ok(PyWorld {
        world: built.into_world(),
        ids,
        carried: Carried::default(),
    })
}

/// `World.from_scene`.
pub fn from_scene(py: Python<'_>, scene: &Bound<'_, PyAny>) -> PyResult<PyWorld> {
    let (text, prefix) = scene_text(py, scene)?;
    let scene = parse_scene(&text, &prefix)?;
    build_scene(&scene, &prefix)
}

/// The world as a scene (time 0 = now).
pub fn scene_of(w: &PyWorld) -> PyResult<Scene> {
    let world = &w.world;
    if world.collapse_time() != 0.0 {
        return Err(invalid(
            "to_scene: the scene format has no collapse time (set it to 0 first)",
        ));
    }
    let mut scene = Scene {
        gravity: world.gravity().to_array(),
        sleep: world.sleeping(),
        table: world.table().map(Into::into),
        periodic: world.periodic_box().map(|s| s.to_array()),
        ..Scene::default()
    };
    for (h, c) in world.colliders() {
        let id = w.ids.collider_id(h);
        if c.sensor || c.groups != CollisionGroups::default() {
            return Err(invalid(format!(
                "to_scene: collider {id} is a sensor or has collision groups, which the scene format cannot say"
            )));
        }
        match c.shape {
            Shape::Segment(s) => scene.segments.push(SceneSegment {
                a: s.a().to_array(),
                b: s.b().to_array(),
                restitution: c.restitution,
                friction: c.friction,
                tangential_restitution: c.tangential_restitution,
                rolling_resistance: c.rolling_resistance,
            }),
            Shape::Circle(circle) => scene.circles.push(SceneCircle {
                center: circle.center.to_array(),
                radius: circle.radius,
                restitution: c.restitution,
                friction: c.friction,
                tangential_restitution: c.tangential_restitution,
                rolling_resistance: c.rolling_resistance,
            }),
        }
    }
    let mut groups = None;
    for (h, b) in world.balls() {
        let id = w.ids.ball_id(h);
        let meet = match b.groups {
            g if g == CollisionGroups::default() => true,
            g if g == BALLS_IGNORE_EACH_OTHER => false,
            _ => {
                return Err(invalid(format!(
                    "to_scene: ball {id} has collision groups the scene format cannot say"
                )));
            }
        };
        if *groups.get_or_insert(meet) != meet {
            return Err(invalid(
                "to_scene: some balls meet balls and some do not; the scene format has one ball_ball for all",
            ));
        }
        scene.balls.push(SceneBall {
            id: id as u64,
            pos: b.position.to_array(),
            vel: b.velocity.to_array(),
            radius: b.radius,
            mass: b.mass,
            restitution: b.restitution,
            spin: b.spin,
            inertia: b.inertia,
            friction: b.friction,
            tangential_restitution: b.tangential_restitution,
            rolling_resistance: b.rolling_resistance,
            roll: roll_of(&b).to_array(),
        });
    }
    scene.ball_ball = groups.unwrap_or(true);
    Ok(scene)
}

/// `World.to_scene`.
pub fn to_scene<'py>(py: Python<'py>, w: &PyWorld) -> PyResult<Bound<'py, PyAny>> {
    let text = scene_of(w)?.to_json_string();
    py.import("json")?.call_method1("loads", (text,))
}

fn groups_json(g: CollisionGroups) -> Value {
    json!([g.memberships, g.filter])
}

/// The full state as JSON text.
pub fn save(w: &PyWorld) -> String {
    let world = &w.world;
    let colliders: Vec<Value> = world
        .colliders()
        .map(|(h, c)| {
            let mut v = match c.shape {
                Shape::Segment(s) => {
                    json!({"kind": "segment", "a": s.a().to_array(), "b": s.b().to_array()})
                }
                Shape::Circle(k) => {
                    json!({"kind": "circle", "center": k.center.to_array(), "radius": k.radius})
                }
            };
            v["id"] = json!(w.ids.collider_id(h));
            v["sensor"] = json!(c.sensor);
            v["restitution"] = json!(c.restitution);
            v["friction"] = json!(c.friction);
            v["tangential_restitution"] = json!(c.tangential_restitution);
            v["rolling_resistance"] = json!(c.rolling_resistance);
            v["groups"] = groups_json(c.groups);
            v["momentum"] = json!(w.collider_momentum_of(h).unwrap_or_default().to_array());
            v["impacts"] = json!(w.collider_impacts_of(h).unwrap_or_default());
            v
        })
        .collect();
    let periodic = world.periodic_box();
    let balls: Vec<Value> = world
        .balls()
        .map(|(h, b)| {
            let mut v = json!({
                "id": w.ids.ball_id(h),
                "pos": b.position.to_array(),
                "vel": b.velocity.to_array(),
                "radius": b.radius,
                "mass": b.mass,
                "restitution": b.restitution,
                "groups": groups_json(b.groups),
                "spin": b.spin,
                "roll": b.roll.to_array(),
                "angle": b.angle,
                "inertia": b.inertia,
                "friction": b.friction,
                "tangential_restitution": b.tangential_restitution,
                "rolling_resistance": b.rolling_resistance,
            });
            if periodic.is_some() {
                v["images"] = json!(w.images_of(h));
            }
            v
        })
        .collect();
    json!({
        "format": STATE_FORMAT,
        "version": STATE_VERSION,
        "time": world.time(),
        "gravity": world.gravity().to_array(),
        "collapse_time": world.collapse_time(),
        "sleeping": world.sleeping(),
        "table": world.table().map(|t| json!({
            "gravity": t.gravity,
            "sliding_friction": t.sliding_friction,
            "rolling_friction": t.rolling_friction,
            "spinning_friction": t.spinning_friction,
        })),
        "periodic": periodic.map(|s| s.to_array()),
        "observables": {
            "since": w.observables_since_of(),
            "virial": w.collision_virial_of(),
        },
        "next_ball": w.ids.next_ball,
        "next_collider": w.ids.next_collider,
        "colliders": colliders,
        "balls": balls,
    })
    .to_string()
}

fn bad_state(what: &str) -> PyErr {
    invalid(format!("not a pickled exact2d world: {what}"))
}

fn num(v: &Value, key: &str) -> PyResult<f64> {
    v.get(key)
        .and_then(Value::as_f64)
        .ok_or_else(|| bad_state(key))
}

/// An optional number (absent in version 1, or for rolling resistance in the first version-2
/// pickles): `default` if missing.
fn num_or(v: &Value, key: &str, default: f64) -> PyResult<f64> {
    match v.get(key) {
        None => Ok(default),
        Some(x) => x.as_f64().ok_or_else(|| bad_state(key)),
    }
}

fn int(v: &Value, key: &str) -> PyResult<i64> {
    v.get(key)
        .and_then(Value::as_i64)
        .ok_or_else(|| bad_state(key))
}

fn vec2(v: &Value, key: &str) -> PyResult<DVec2> {
    match v.get(key).and_then(Value::as_array).map(|a| &a[..]) {
        Some([x, y]) => match (x.as_f64(), y.as_f64()) {
            (Some(x), Some(y)) => Ok(DVec2::new(x, y)),
            _ => Err(bad_state(key)),
        },
        _ => Err(bad_state(key)),
    }
}

/// The table of a version-3 pickle (`null` or absent: none).
fn table_of(v: &Value) -> PyResult<Option<Table>> {
    let Some(t) = v.get("table").filter(|t| !t.is_null()) else {
        return Ok(None);
    };
    let value = |key: &str| {
        t.get(key)
            .and_then(Value::as_f64)
            .ok_or_else(|| bad_state(&format!("table.{key}")))
    };
    Ok(Some(Table {
        gravity: value("gravity")?,
        sliding_friction: value("sliding_friction")?,
        rolling_friction: value("rolling_friction")?,
        spinning_friction: value("spinning_friction")?,
    }))
}

/// An optional pair (a ball's roll, absent before version 3): zero if missing.
fn vec2_or_zero(v: &Value, key: &str) -> PyResult<DVec2> {
    match v.get(key) {
        None => Ok(DVec2::ZERO),
        Some(_) => vec2(v, key),
    }
}

fn groups_of(v: &Value) -> PyResult<CollisionGroups> {
    match v.get("groups").and_then(Value::as_array).map(|a| &a[..]) {
        Some([m, f]) => {
            let mask = |x: &Value| {
                x.as_u64()
                    .and_then(|x| u32::try_from(x).ok())
                    .ok_or_else(|| bad_state("groups"))
            };
            Ok(CollisionGroups::new(mask(m)?, mask(f)?))
        }
        _ => Err(bad_state("groups")),
    }
}

/// The periodic box of a version-4 pickle (`null` or absent: none).
fn periodic_of(v: &Value) -> PyResult<Option<DVec2>> {
    match v.get("periodic") {
        None | Some(Value::Null) => Ok(None),
        Some(_) => vec2(v, "periodic").map(Some),
    }
}

/// A ball's images in a version-4 pickle of a periodic world (absent: none).
fn images_of(v: &Value) -> PyResult<[i64; 2]> {
    match v.get("images").map(|k| k.as_array().map(|a| &a[..])) {
        None => Ok([0, 0]),
        Some(Some([x, y])) => match (x.as_i64(), y.as_i64()) {
            (Some(x), Some(y)) => Ok([x, y]),
            _ => Err(bad_state("images")),
        },
        Some(_) => Err(bad_state("images")),
    }
}

/// A collider's momentum and impacts in a version-4 pickle (absent: none).
fn tally_of(v: &Value) -> PyResult<(DVec2, u64)> {
    let momentum = match v.get("momentum") {
        None => DVec2::ZERO,
        Some(_) => vec2(v, "momentum")?,
    };
    let impacts = match v.get("impacts") {
        None => 0,
        Some(n) => n.as_u64().ok_or_else(|| bad_state("impacts"))?,
    };
    Ok((momentum, impacts))
}

/// A pickled ball: how to add it (its velocity and spin included), its handle, angle and
/// images.
struct SavedBall {
    desc: BallDesc,
    id: i64,
    angle: f64,
    images: [i64; 2],
}

/// A world from its full state.
pub fn load(text: &str) -> PyResult<PyWorld> {
    let v: Value = serde_json::from_str(text).map_err(|e| bad_state(&e.to_string()))?;
    if v.get("format").and_then(Value::as_str) != Some(STATE_FORMAT) {
        return Err(bad_state("format"));
    }
    if !matches!(
        v.get("version").and_then(Value::as_u64),
        Some(1..=STATE_VERSION)
    ) {
        return Err(bad_state("version"));
    }
    let gravity = vec2(&v, "gravity")?;
    let time = num(&v, "time")?;
    let empty = Vec::new();
    let mut colliders = Vec::new();
    let mut tallies = BTreeMap::new();
    for c in v
        .get("colliders")
        .and_then(Value::as_array)
        .unwrap_or(&empty)
    {
        let desc = match c.get("kind").and_then(Value::as_str) {
            Some("segment") => ColliderDesc::segment(vec2(c, "a")?, vec2(c, "b")?),
            Some("circle") => ColliderDesc::circle(vec2(c, "center")?, num(c, "radius")?),
            _ => return Err(bad_state("collider kind")),
        };
        let sensor = c.get("sensor").and_then(Value::as_bool).unwrap_or(false);
        let desc = desc
            .sensor(sensor)
            .restitution(num(c, "restitution")?)
            .friction(num_or(c, "friction", 0.0)?)
            .tangential_restitution(num_or(c, "tangential_restitution", 0.0)?)
            .rolling_resistance(num_or(c, "rolling_resistance", 0.0)?)
            .groups(groups_of(c)?);
        let id = int(c, "id")?;
        tallies.insert(id, tally_of(c)?);
        colliders.push((desc, id));
    }
    let mut balls = Vec::new();
    for b in v.get("balls").and_then(Value::as_array).unwrap_or(&empty) {
        let desc = BallDesc::new(vec2(b, "pos")?, num(b, "radius")?)
            .velocity(vec2(b, "vel")?)
            .mass(num(b, "mass")?)
            .restitution(num(b, "restitution")?)
            .groups(groups_of(b)?)
            .spin(num_or(b, "spin", 0.0)?)
            .roll(vec2_or_zero(b, "roll")?)
            .inertia(num_or(b, "inertia", exact2d::DEFAULT_INERTIA)?)
            .friction(num_or(b, "friction", 0.0)?)
            .tangential_restitution(num_or(b, "tangential_restitution", 0.0)?)
            .rolling_resistance(num_or(b, "rolling_resistance", 0.0)?);
        balls.push(SavedBall {
            desc,
            id: int(b, "id")?,
            angle: num_or(b, "angle", 0.0)?,
            images: images_of(b)?,
        });
    }
    let mut world = World::with_gravity(gravity).map_err(|e| invalid(e.to_string()))?;
    world.advance_to(time).map_err(|e| invalid(e.to_string()))?;
    // A pickle without observables (before version 4) has them start at the pickled instant.
    world.reset_observables();
    world
        .set_collapse_time(num(&v, "collapse_time")?)
        .map_err(|e| invalid(e.to_string()))?;
    world.set_sleeping(v.get("sleeping").and_then(Value::as_bool).unwrap_or(false));
    let mut w = PyWorld {
        world,
        ids: Ids::default(),
        carried: Carried::default(),
    };
    w.world
        .set_table(table_of(&v)?)
        .map_err(|e| world_error(e, &w.ids))?;
    if let Some(size) = periodic_of(&v)? {
        w.world
            .set_periodic(size)
            .map_err(|e| world_error(e, &w.ids))?;
    }
    for (desc, id) in colliders {
        w.insert_collider(desc, id)?;
    }
    let refused = |e: PyErr| Python::with_gil(|py| invalid(format!("{}", e.value(py))));
    for b in &balls {
        w.insert_ball(b.desc, b.id).map_err(refused)?;
        if b.angle != 0.0 {
            let h = w.ids.ball(b.id)?;
            w.world
                .set_ball_angle(h, b.angle)
                .map_err(|e| invalid(e.to_string()))?;
        }
        if b.images != [0, 0] {
            if w.world.periodic_box().is_none() {
                return Err(bad_state("images without a periodic box"));
            }
            w.carried.images.insert(b.id, b.images);
        }
    }
    if let Some(o) = v.get("observables") {
        w.carried.observables = Some(CarriedObservables {
            since: num(o, "since")?,
            virial: num(o, "virial")?,
            colliders: tallies,
        });
    }
    w.ids.next_ball = w.ids.next_ball.max(int(&v, "next_ball")?);
    w.ids.next_collider = w.ids.next_collider.max(int(&v, "next_collider")?);
    Ok(w)
}
