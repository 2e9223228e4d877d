//! The scene file format, version 1, as Rust types.
//!
//! The types mirror the JSON document key for key (`#[serde(deny_unknown_fields)]` at every
//! level), with the defaults of the format's table. Three readers tighten what serde's derive
//! would accept: `pair` reads `[x, y]` so that a wrong length gets a clear message, `id` refuses
//! `1.5` and `-1` with the words "non-negative integer", and `Object` accepts a struct only as
//! a JSON object.

use std::fmt;
use std::marker::PhantomData;

use serde::de::value::MapAccessDeserializer;
use serde::de::{self, IgnoredAny, MapAccess, SeqAccess, Unexpected, Visitor};
use serde::{Deserialize, Deserializer, Serialize};

/// A whole scene: the world at time 0.
///
/// Build one in code, or read one with [`Scene::from_json_str`]; check it with
/// [`Scene::validate`]; run it with [`Scene::build_world`]. Serialising it (with `serde_json`,
/// or [`Scene::to_json_string`]) writes every `f64` so that it reads back to the same bits.
///
/// Read files with [`Scene::from_json_str`]: deserialising a `Scene` directly with serde
/// neither validates it nor refuses an item written as an array of its values.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Scene {
    /// Uniform acceleration applied to every ball; default `[0, 0]`.
    #[serde(default, deserialize_with = "pair")]
    pub gravity: [f64; 2],
    /// Whether balls collide with each other; default `false`.
    #[serde(default)]
    pub ball_ball: bool,
    /// Static segments; default none.
    #[serde(default, deserialize_with = "objects")]
    pub segments: Vec<SceneSegment>,
    /// Static circles; default none.
    #[serde(default, deserialize_with = "objects")]
    pub circles: Vec<SceneCircle>,
    /// The moving balls; required.
    #[serde(deserialize_with = "objects")]
    pub balls: Vec<SceneBall>,
    /// Whether balls at rest fall asleep (see `World::set_sleeping`); default `false` (as in
    /// the API), so that files written before sleeping existed run exactly as they did.
    #[serde(default, skip_serializing_if = "is_false")]
    pub sleep: bool,
    /// A table seen from above (see [`Table`](crate::Table)): the cloth's friction, under
    /// which every ball slides, rolls and spins to rest; default none. Needs `gravity`
    /// `[0, 0]`.
    #[serde(
        default,
        deserialize_with = "optional_object",
        skip_serializing_if = "Option::is_none"
    )]
    pub table: Option<SceneTable>,
    /// A periodic box `[Lx, Ly]` (see `World::set_periodic`): the box `[0, Lx) x [0, Ly)`
    /// with opposite edges glued, every ball inside it; default none. Needs `gravity`
    /// `[0, 0]` and no table; static colliders keep clear of its edges by more than the
    /// largest ball's radius, and a ball's radius is at most `min(Lx, Ly) / 6.6`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub periodic: Option<[f64; 2]>,
}

/// A table's cloth; each key defaults to pooltool's pool cloth ([`Table::POOL`](crate::Table::POOL)).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SceneTable {
    /// Gravity into the table, `> 0`; default 9.81.
    #[serde(default = "table_gravity")]
    pub gravity: f64,
    /// Sliding friction `mu_s`, `>= 0`; default 0.2.
    #[serde(default = "table_sliding")]
    pub sliding_friction: f64,
    /// Rolling friction `mu_r`, `>= 0`; default 0.01.
    #[serde(default = "table_rolling")]
    pub rolling_friction: f64,
    /// Spinning friction `mu_sp`, `>= 0`; default 0.0127.
    #[serde(default = "table_spinning")]
    pub spinning_friction: f64,
}

impl Default for SceneTable {
    fn default() -> Self {
        Self::from(crate::Table::POOL)
    }
}

impl From<crate::Table> for SceneTable {
    fn from(t: crate::Table) -> Self {
        Self {
            gravity: t.gravity,
            sliding_friction: t.sliding_friction,
            rolling_friction: t.rolling_friction,
            spinning_friction: t.spinning_friction,
        }
    }
}

impl From<SceneTable> for crate::Table {
    fn from(t: SceneTable) -> Self {
        Self {
            gravity: t.gravity,
            sliding_friction: t.sliding_friction,
            rolling_friction: t.rolling_friction,
            spinning_friction: t.spinning_friction,
        }
    }
}

fn table_gravity() -> f64 {
    crate::Table::POOL.gravity
}

fn table_sliding() -> f64 {
    crate::Table::POOL.sliding_friction
}

fn table_rolling() -> f64 {
    crate::Table::POOL.rolling_friction
}

fn table_spinning() -> f64 {
    crate::Table::POOL.spinning_friction
}

impl Scene {
    /// Whether the scene has a table, or any ball has spin, friction, a tangential
    /// restitution, a rolling resistance or a moment of inertia of its own, or any segment or circle friction, a tangential
    /// restitution or a rolling resistance: then
    /// `exact2d simulate` prints each ball's `spin`.
    #[must_use]
    pub fn is_rough(&self) -> bool {
        let surface = |friction: f64, beta: f64, c: f64| friction != 0.0 || beta != 0.0 || c != 0.0;
        self.table.is_some()
            || self.balls.iter().any(SceneBall::is_rough)
            || self
                .segments
                .iter()
                .any(|s| surface(s.friction, s.tangential_restitution, s.rolling_resistance))
            || self
                .circles
                .iter()
                .any(|c| surface(c.friction, c.tangential_restitution, c.rolling_resistance))
    }
}

#[allow(clippy::trivially_copy_pass_by_ref)]
fn is_false(b: &bool) -> bool {
    !*b
}

/// A static line segment from `a` to `b`: balls hit its interior (from both sides) and both
/// end points.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SceneSegment {
    /// First end point.
    #[serde(deserialize_with = "pair")]
    pub a: [f64; 2],
    /// Second end point, distinct from `a`.
    #[serde(deserialize_with = "pair")]
    pub b: [f64; 2],
    /// Coefficient of restitution in `[0, 1]`; default 1.
    #[serde(default = "one")]
    pub restitution: f64,
    /// Coulomb's friction coefficient, `>= 0`; default 0 (frictionless). A pair uses the
    /// geometric mean of its two values.
    #[serde(default, skip_serializing_if = "is_zero")]
    pub friction: f64,
    /// Tangential restitution in `[-1, 1]`; default 0. A pair's `1 + beta` is the geometric
    /// mean of its two `1 + beta`.
    #[serde(default, skip_serializing_if = "is_zero")]
    pub tangential_restitution: f64,
    /// Rolling resistance, `>= 0`; default 0. A pair uses the geometric mean of its two.
    #[serde(default, skip_serializing_if = "is_zero")]
    pub rolling_resistance: f64,
}

/// A static disc.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SceneCircle {
    /// The centre.
    #[serde(deserialize_with = "pair")]
    pub center: [f64; 2],
    /// The radius, `> 0`.
    pub radius: f64,
    /// Coefficient of restitution in `[0, 1]`; default 1.
    #[serde(default = "one")]
    pub restitution: f64,
    /// Coulomb's friction coefficient, `>= 0`; default 0 (frictionless). A pair uses the
    /// geometric mean of its two values.
    #[serde(default, skip_serializing_if = "is_zero")]
    pub friction: f64,
    /// Tangential restitution in `[-1, 1]`; default 0. A pair's `1 + beta` is the geometric
    /// mean of its two `1 + beta`.
    #[serde(default, skip_serializing_if = "is_zero")]
    pub tangential_restitution: f64,
    /// Rolling resistance, `>= 0`; default 0. A pair uses the geometric mean of its two.
    #[serde(default, skip_serializing_if = "is_zero")]
    pub rolling_resistance: f64,
}

/// A moving ball.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SceneBall {
    /// The user's name for the ball, unique in the scene; results and events use it.
    #[serde(deserialize_with = "id")]
    pub id: u64,
    /// Position of the centre at time 0.
    #[serde(deserialize_with = "pair")]
    pub pos: [f64; 2],
    /// Velocity at time 0.
    #[serde(deserialize_with = "pair")]
    pub vel: [f64; 2],
    /// The radius, `> 0`.
    pub radius: f64,
    /// The mass, `> 0`; default 1.
    #[serde(default = "one")]
    pub mass: f64,
    /// Coefficient of restitution in `[0, 1]`; default 1.
    #[serde(default = "one")]
    pub restitution: f64,
    /// Angular velocity at time 0, radians per second, counter-clockwise positive; default 0.
    #[serde(default, skip_serializing_if = "is_zero")]
    pub spin: f64,
    /// On a table: angular velocity about the horizontal axes at time 0, `[w_x, w_y]` in
    /// radians per second (rolling along `+x` at speed `v`: `[0, v / radius]`); default
    /// `[0, 0]`, the only value allowed without a table.
    #[serde(
        default,
        deserialize_with = "pair",
        skip_serializing_if = "is_zero_pair"
    )]
    pub roll: [f64; 2],
    /// Moment of inertia as a factor of `m r^2`, in `(0, 1]`; default 0.5 (a uniform disk).
    #[serde(default = "half", skip_serializing_if = "is_half")]
    pub inertia: f64,
    /// Coulomb's friction coefficient, `>= 0`; default 0 (frictionless). A pair uses the
    /// geometric mean of its two values.
    #[serde(default, skip_serializing_if = "is_zero")]
    pub friction: f64,
    /// Tangential restitution in `[-1, 1]`; default 0. A pair's `1 + beta` is the geometric
    /// mean of its two `1 + beta`.
    #[serde(default, skip_serializing_if = "is_zero")]
    pub tangential_restitution: f64,
    /// Rolling resistance, `>= 0`; default 0. A pair uses the geometric mean of its two.
    #[serde(default, skip_serializing_if = "is_zero")]
    pub rolling_resistance: f64,
}

impl SceneBall {
    /// Whether the ball has spin, friction, a tangential restitution or a moment of inertia
    /// of its own (a scene with such a ball prints each ball's `spin`).
    #[must_use]
    pub fn is_rough(&self) -> bool {
        self.spin != 0.0
            || self.roll != [0.0, 0.0]
            || self.friction != 0.0
            || self.tangential_restitution != 0.0
            || self.rolling_resistance != 0.0
            || self.inertia.to_bits() != half().to_bits()
    }
}

fn one() -> f64 {
    1.0
}

fn half() -> f64 {
    crate::DEFAULT_INERTIA
}

#[allow(clippy::trivially_copy_pass_by_ref)]
fn is_zero(x: &f64) -> bool {
    x.to_bits() == 0
}

fn is_zero_pair(x: &[f64; 2]) -> bool {
    x.iter().all(is_zero)
}

#[allow(clippy::trivially_copy_pass_by_ref)]
fn is_half(x: &f64) -> bool {
    x.to_bits() == half().to_bits()
}

/// What a JSON object of the format is called in messages.
pub(super) trait Named {
    /// Like "a ball object".
    const EXPECTING: &'static str;
}

impl Named for Scene {
    const EXPECTING: &'static str = "a scene object";
}

impl Named for SceneSegment {
    const EXPECTING: &'static str = "a segment object";
}

impl Named for SceneCircle {
    const EXPECTING: &'static str = "a circle object";
}

impl Named for SceneBall {
    const EXPECTING: &'static str = "a ball object";
}

impl Named for SceneTable {
    const EXPECTING: &'static str = "a table object";
}

/// A `T` read only from a JSON object. Serde's derive would also read a struct from an array
/// of its values in field order (`[0, [1, 2], [3, 4], 0.5]` as a ball), which the format
/// does not allow.
pub(super) struct Object<T>(pub T);

impl<'de, T: Deserialize<'de> + Named> Deserialize<'de> for Object<T> {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        deserializer
            .deserialize_map(ObjectVisitor(PhantomData))
            .map(Object)
    }
}

struct ObjectVisitor<T>(PhantomData<T>);

impl<'de, T: Deserialize<'de> + Named> Visitor<'de> for ObjectVisitor<T> {
    type Value = T;

    fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(T::EXPECTING)
    }

    fn visit_map<A: MapAccess<'de>>(self, map: A) -> Result<T, A::Error> {
        T::deserialize(MapAccessDeserializer::new(map))
    }
}

/// Reads a list of objects.
fn objects<'de, D, T>(deserializer: D) -> Result<Vec<T>, D::Error>
where
    D: Deserializer<'de>,
    T: Deserialize<'de> + Named,
{
    let list = Vec::<Object<T>>::deserialize(deserializer)?;
    Ok(list.into_iter().map(|Object(item)| item).collect())
}

/// Reads an object (a key that is present; an absent one is its default, `None`).
fn optional_object<'de, D, T>(deserializer: D) -> Result<Option<T>, D::Error>
where
    D: Deserializer<'de>,
    T: Deserialize<'de> + Named,
{
    Object::<T>::deserialize(deserializer).map(|Object(item)| Some(item))
}

/// Reads `[x, y]`: exactly two numbers.
fn pair<'de, D: Deserializer<'de>>(deserializer: D) -> Result<[f64; 2], D::Error> {
    deserializer.deserialize_seq(PairVisitor)
}

struct PairVisitor;

impl<'de> Visitor<'de> for PairVisitor {
    type Value = [f64; 2];

    fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("an array of two numbers [x, y]")
    }

    fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<Self::Value, A::Error> {
        let x = seq
            .next_element()?
            .ok_or_else(|| de::Error::invalid_length(0, &self))?;
        let y = seq
            .next_element()?
            .ok_or_else(|| de::Error::invalid_length(1, &self))?;
        // Count the surplus so the message can say how long the array really is.
        let mut length = 2;
        while seq.next_element::<IgnoredAny>()?.is_some() {
            length += 1;
        }
        if length > 2 {
            return Err(de::Error::invalid_length(length, &self));
        }
        Ok([x, y])
    }
}

/// Reads a ball id: a JSON integer >= 0 (not `1.0`, not `-1`).
fn id<'de, D: Deserializer<'de>>(deserializer: D) -> Result<u64, D::Error> {
    deserializer.deserialize_u64(IdVisitor)
}

struct IdVisitor;

impl Visitor<'_> for IdVisitor {
    type Value = u64;

    fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("a non-negative integer")
    }

    fn visit_u64<E: de::Error>(self, value: u64) -> Result<u64, E> {
        Ok(value)
    }

    fn visit_i64<E: de::Error>(self, value: i64) -> Result<u64, E> {
        u64::try_from(value).map_err(|_| E::invalid_value(Unexpected::Signed(value), &self))
    }
}
