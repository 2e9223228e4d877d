//! `exact2d.World`: the engine's `World` with Python handles, NumPy arrays and exceptions.

use exact2d::{
    BallDesc, BallHandle, Body, CastHit, CastOptions, ColliderDesc, ColliderHandle,
    CollisionGroups, DVec2, Event, Shape, Table, World, WorldError,
};
use numpy::ndarray::{Array2, ArrayD};
use numpy::{IntoPyArray, PyArray1, PyArray2, PyArrayDyn, PyArrayMethods};
use pyo3::prelude::*;
use pyo3::types::PyDict;

use crate::args::{count, finite, groups, pair};
use crate::errors::{Class, error, invalid};
use crate::events::{PyEvent, columns};
use crate::ids::Ids;
use crate::state::{self, Carried};
use crate::table::{self, TableArg};

/// Events handled between two checks for Ctrl-C (and two re-acquisitions of the GIL) in a long
/// run: about a millisecond of work, so an interrupt is felt at once and the GIL costs
/// nothing measurable.
pub const EVENTS_PER_CHECK: u64 = 1 << 14;

// `add_ball`'s default `inertia = 0.5` (a literal, so that Python's signature shows it) is the
// engine's.
const _: () = assert!(exact2d::DEFAULT_INERTIA == 0.5);

/// An exact, event-driven 2D world of balls and static colliders (segments and circles).
///
/// Balls move in closed form between events; every collision is handled at its exact time of
/// impact, so nothing tunnels and runs are reproducible bit for bit. Bodies are named by
/// integer handles, never reused within a world. Arrays (`positions()`, ...) list the live
/// balls in one order, the order of `handles()`.
///
/// A world may be a periodic box (`periodic`, hard-disk physics without walls), and it keeps
/// observables for physicists (`collision_virial`, `collider_momentum`, `collider_impacts`,
/// `reset_observables`).
///
/// `copy()` (and `copy.copy`, `copy.deepcopy`) branches a world exactly: the copy goes on
/// with the original's events and bits. A pickle rebuilds the world from its state, exact
/// before the first step and to rounding after.
#[pyclass(module = "exact2d", name = "World")]
pub struct PyWorld {
    pub(crate) world: World,
    pub(crate) ids: Ids,
    /// What a pickle carried that the engine could not be given (images, observables).
    pub(crate) carried: Carried,
}

/// Maps an engine error to the Python exception, naming bodies by their Python handles.
pub fn world_error(e: WorldError, ids: &Ids) -> PyErr {
    match e {
        WorldError::OverlapsBall(h) => {
            error(Class::Overlap, format!("overlaps ball {}", ids.ball_id(h)))
        }
        WorldError::OverlapsCollider(h) => error(
            Class::Overlap,
            format!("overlaps collider {}", ids.collider_id(h)),
        ),
        WorldError::NoSuchBall(h) => error(
            Class::UnknownHandle,
            format!("no ball with handle {}", ids.ball_id(h)),
        ),
        WorldError::NoSuchCollider(h) => error(
            Class::UnknownHandle,
            format!("no collider with handle {}", ids.collider_id(h)),
        ),
        WorldError::TimeBeforeNow { .. } => error(Class::TimeBeforeNow, e.to_string()),
        // The engine's words name its Rust API; these name Python's.
        WorldError::TableAndGravity => {
            invalid("a table is seen from above: the world's gravity must be (0, 0) with a table")
        }
        WorldError::RollWithoutTable => invalid("a ball's roll needs a table (World.set_table)"),
        WorldError::Stalled { .. } => error(Class::Stalled, e.to_string()),
        WorldError::PeriodicWith("gravity") => {
            invalid(format!("{e}: the world's gravity must be (0, 0)"))
        }
        WorldError::PeriodicWith(_) => invalid(format!("{e}: the world must have no table")),
        WorldError::PeriodicNotEmpty => invalid(format!(
            "{e} (set World.periodic, or World(periodic=...), before adding balls)"
        )),
        _ => invalid(e.to_string()),
    }
}

/// Runs `world` to `until`, handing every event to `on_event`, with the GIL released, and
/// checks for Ctrl-C every [`EVENTS_PER_CHECK`] events (a `KeyboardInterrupt` leaves the world
/// at its last event, consistent). Returns the number of events.
pub fn run_to(
    py: Python<'_>,
    world: &mut World,
    until: f64,
    mut on_event: impl FnMut(&Event) + Send,
) -> Result<u64, RunError> {
    let mut total = 0;
    loop {
        let (handled, outcome) = py.allow_threads(|| {
            let mut handled = 0;
            while handled < EVENTS_PER_CHECK {
                match world.step_until(until) {
                    Ok(Some(event)) => {
                        on_event(&event);
                        handled += 1;
                    }
                    Ok(None) => return (handled, Some(Ok(()))),
                    Err(e) => return (handled, Some(Err(e))),
                }
            }
            (handled, None)
        });
        total += handled;
        match outcome {
            Some(Ok(())) => return Ok(total),
            Some(Err(e)) => return Err(RunError::World(e)),
            None => py.check_signals().map_err(RunError::Python)?,
        }
    }
}

/// Why a run stopped early.
pub enum RunError {
    /// The engine refused (a time before now, a stall).
    World(WorldError),
    /// A signal handler raised (Ctrl-C).
    Python(PyErr),
}

impl PyWorld {
    pub(crate) fn run_error(&self, e: RunError) -> PyErr {
        match e {
            RunError::World(e) => world_error(e, &self.ids),
            RunError::Python(e) => e,
        }
    }

    /// Adds a ball under the handle `id`.
    pub(crate) fn insert_ball(&mut self, desc: BallDesc, id: i64) -> PyResult<i64> {
        let handle = self.world.add_ball(desc).map_err(|e| match e {
            // The engine's words name the box by its sides' names; these give its numbers too.
            WorldError::OutsidePeriodicBox(_) => {
                let size = self.world.periodic_box().unwrap_or_default();
                invalid(format!(
                    "{e}; this box is [0, {}) x [0, {})",
                    size.x, size.y
                ))
            }
            _ => world_error(e, &self.ids),
        })?;
        self.ids.add_ball(handle, id);
        Ok(id)
    }

    /// Adds a collider under the handle `id`.
    pub(crate) fn insert_collider(&mut self, desc: ColliderDesc, id: i64) -> PyResult<i64> {
        let handle = self
            .world
            .add_collider(desc)
            .map_err(|e| world_error(e, &self.ids))?;
        self.ids.add_collider(handle, id);
        Ok(id)
    }

    fn ball_desc(
        pos: DVec2,
        vel: DVec2,
        radius: f64,
        mass: f64,
        restitution: f64,
        groups: CollisionGroups,
    ) -> BallDesc {
        BallDesc::new(pos, radius)
            .velocity(vel)
            .mass(mass)
            .restitution(restitution)
            .groups(groups)
    }

    /// `desc` with its spin and surface: angular velocity `spin`, `roll` (on a table),
    /// moment of inertia `inertia` (a factor of `m r^2`), Coulomb's `friction`, the
    /// `tangential_restitution` and the `rolling_resistance`.
    // One argument per property of the ball.
    #[allow(clippy::too_many_arguments)]
    fn rough_desc(
        desc: BallDesc,
        spin: f64,
        roll: DVec2,
        inertia: f64,
        friction: f64,
        tangential_restitution: f64,
        rolling_resistance: f64,
    ) -> BallDesc {
        desc.spin(spin)
            .roll(roll)
            .inertia(inertia)
            .friction(friction)
            .tangential_restitution(tangential_restitution)
            .rolling_resistance(rolling_resistance)
    }

    /// The box lengths ball `h` has crossed in a periodic box ([`World::ball_images`], counted
    /// so that its unwrapped position is its reported position plus these times the sides),
    /// the ones a pickle carried included: `[0, 0]` elsewhere.
    pub(crate) fn images_of(&self, h: BallHandle) -> [i64; 2] {
        let Some(own) = self.world.ball_images(h) else {
            return [0, 0];
        };
        let carried = self
            .carried
            .images
            .get(&self.ids.ball_id(h))
            .copied()
            .unwrap_or_default();
        [own[0] + carried[0], own[1] + carried[1]]
    }

    /// Ball `h`'s unwrapped position (reported at `position` now): in a periodic box the
    /// position plus the box lengths crossed ([`Self::images_of`]), as the engine adds them
    /// (one rounding); elsewhere the position.
    fn unwrapped_of(&self, h: BallHandle, position: DVec2) -> DVec2 {
        match self.world.periodic_box() {
            Some(size) => {
                let [kx, ky] = self.images_of(h);
                position + DVec2::new(kx as f64 * size.x, ky as f64 * size.y)
            }
            None => position,
        }
    }

    /// Every ball's unwrapped position ([`Self::unwrapped_of`]), `x, y` after `x, y` in the
    /// order of `World::balls` (the order of `handles()`): `unwrapped_positions()` and
    /// `run_many`'s `unwrapped`, one computation for both.
    pub(crate) fn unwrapped_pairs(&self) -> Vec<f64> {
        self.world
            .balls()
            .flat_map(|(h, b)| self.unwrapped_of(h, b.position).to_array())
            .collect()
    }

    /// The collision virial since `observables_since_of`, a pickle's carried one included.
    pub(crate) fn collision_virial_of(&self) -> f64 {
        let own = self.world.observables().collision_virial();
        self.carried
            .observables
            .as_ref()
            .map_or(own, |o| o.virial + own)
    }

    /// When the observables started (a pickle's carried time, if it carried them).
    pub(crate) fn observables_since_of(&self) -> f64 {
        self.carried
            .observables
            .as_ref()
            .map_or_else(|| self.world.observables().since(), |o| o.since)
    }

    /// The carried momentum and impacts of collider `h`, if a pickle carried any.
    fn carried_tally(&self, h: ColliderHandle) -> Option<(DVec2, u64)> {
        let o = self.carried.observables.as_ref()?;
        o.colliders.get(&self.ids.collider_id(h)).copied()
    }

    /// The momentum given to collider `h`, a pickle's carried momentum included.
    pub(crate) fn collider_momentum_of(&self, h: ColliderHandle) -> Option<DVec2> {
        let own = self.world.collider_momentum(h)?;
        Some(self.carried_tally(h).map_or(own, |(m, _)| m + own))
    }

    /// The impacts on collider `h`, a pickle's carried impacts included.
    pub(crate) fn collider_impacts_of(&self, h: ColliderHandle) -> Option<u64> {
        let own = self.world.collider_impacts(h)?;
        Some(self.carried_tally(h).map_or(own, |(_, n)| n + own))
    }

    fn event(&self, event: Option<Event>) -> Option<PyEvent> {
        event.map(|e| PyEvent::new(&e, &self.ids))
    }

    fn ball_column<'py, T: numpy::Element>(
        &self,
        py: Python<'py>,
        f: impl Fn(&exact2d::Ball) -> T,
    ) -> Bound<'py, PyArray1<T>> {
        let v: Vec<T> = self.world.balls().map(|(_, b)| f(&b)).collect();
        v.into_pyarray(py)
    }

    fn ball_pairs<'py>(
        &self,
        py: Python<'py>,
        f: impl Fn(&exact2d::Ball) -> DVec2,
    ) -> Bound<'py, PyArray2<f64>> {
        let v: Vec<f64> = self
            .world
            .balls()
            .flat_map(|(_, b)| f(&b).to_array())
            .collect();
        let n = v.len() / 2;
        Array2::from_shape_vec((n, 2), v)
            .expect("two per ball")
            .into_pyarray(py)
    }
}

fn cast_options(
    max_time: f64,
    groups_arg: Option<&Bound<'_, PyAny>>,
    include_sensors: bool,
    restitution: f64,
) -> PyResult<CastOptions> {
    if !(max_time >= 0.0) {
        return Err(invalid(format!("max_time must be >= 0 (got {max_time})")));
    }
    Ok(CastOptions {
        max_time,
        groups: groups(groups_arg)?,
        include_sensors,
        restitution,
    })
}

/// Where a cast ball touches a collider (see `World.cast_ball`).
#[pyclass(module = "exact2d", name = "CastHit", frozen, get_all)]
#[derive(Clone, Debug)]
pub struct PyCastHit {
    /// Time from the start of the cast.
    pub time: f64,
    /// The ball's centre at the hit.
    pub position: (f64, f64),
    /// The ball's velocity just before the hit.
    pub velocity: (f64, f64),
    /// The contact point on the collider.
    pub point: (f64, f64),
    /// Unit contact normal, from the collider towards the ball's centre.
    pub normal: (f64, f64),
    /// The collider hit (`-1` for a sleeping ball, which is a static circle to a cast).
    pub collider: i64,
}

#[pymethods]
impl PyCastHit {
    fn __repr__(&self) -> String {
        format!(
            "CastHit(time={:?}, position={:?}, collider={})",
            self.time, self.position, self.collider
        )
    }
}

impl PyCastHit {
    fn new(hit: &CastHit, ids: &Ids) -> Self {
        Self {
            time: hit.time,
            position: hit.position.into(),
            velocity: hit.velocity.into(),
            point: hit.point.into(),
            normal: hit.normal.into(),
            collider: ids.collider_id(hit.collider),
        }
    }
}

/// Any array-like as a float64 NumPy array (`numpy.asarray(value, dtype=float64)`).
fn float_array<'py>(
    py: Python<'py>,
    value: &Bound<'py, PyAny>,
    name: &str,
) -> PyResult<ArrayD<f64>> {
    let converted = py
        .import("numpy")?
        .call_method1("asarray", (value, "float64"))
        .map_err(|_| invalid(format!("{name} must be an array of numbers")))?;
    let array = converted
        .downcast::<PyArrayDyn<f64>>()
        .map_err(|_| invalid(format!("{name} must be an array of numbers")))?;
    Ok(array.readonly().as_array().to_owned())
}

/// A 1-D column of `n` values, or `default` everywhere.
fn column(values: Option<Vec<f64>>, n: usize, default: f64, name: &str) -> PyResult<Vec<f64>> {
    match values {
        None => Ok(vec![default; n]),
        Some(a) if a.len() == n => Ok(a),
        Some(a) => Err(invalid(format!(
            "{name} must have shape ({n},) like positions, got ({},)",
            a.len()
        ))),
    }
}

/// The rows of an (n, 2) array.
fn pairs_column(a: &ArrayD<f64>, name: &str) -> PyResult<Vec<DVec2>> {
    match a.shape() {
        [_, 2] => Ok(a
            .rows()
            .into_iter()
            .map(|r| DVec2::new(r[0], r[1]))
            .collect()),
        shape => Err(invalid(format!(
            "{name} must have shape (n, 2), got {shape:?}"
        ))),
    }
}

#[pymethods]
impl PyWorld {
    /// An empty world at time 0 with uniform `gravity` (an acceleration applied to every
    /// ball; pass `(0, 0)` for none), and a `table` if given (see `set_table`): a dict of
    /// some of `gravity`, `sliding_friction`, `rolling_friction` and `spinning_friction`, the
    /// others a pool table's (`{}` is a pool table), or a `periodic` box `(Lx, Ly)` if given
    /// (see `periodic`). `gravity` defaults to `(0, -9.81)`, or `(0, 0)` with a table or a
    /// periodic box, which need it.
    #[new]
    #[pyo3(signature = (gravity = None, table = None, periodic = None))]
    fn py_new(
        gravity: Option<&Bound<'_, PyAny>>,
        table: Option<&Bound<'_, PyAny>>,
        periodic: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<Self> {
        let table = match table {
            Some(t) => table::table_of(t, "table")?,
            None => None,
        };
        let periodic = periodic
            .filter(|p| !p.is_none())
            .map(|p| pair(p, "periodic"))
            .transpose()?;
        let gravity = match gravity {
            Some(g) => pair(g, "gravity")?,
            None if table.is_some() || periodic.is_some() => DVec2::ZERO,
            None => DVec2::new(0.0, -9.81),
        };
        let mut world = World::with_gravity(gravity).map_err(|e| invalid(e.to_string()))?;
        let ids = Ids::default();
        world.set_table(table).map_err(|e| world_error(e, &ids))?;
        if let Some(size) = periodic {
            world.set_periodic(size).map_err(|e| world_error(e, &ids))?;
        }
        Ok(Self {
            world,
            ids,
            carried: Carried::default(),
        })
    }

    /// The current time: every ball is reported at this time.
    #[getter]
    fn time(&self) -> f64 {
        self.world.time()
    }

    /// The uniform gravity `(x, y)`; setting it restates every ball now (sleeping balls wake).
    #[getter]
    fn get_gravity(&self) -> (f64, f64) {
        self.world.gravity().into()
    }

    #[setter]
    fn set_gravity(&mut self, gravity: &Bound<'_, PyAny>) -> PyResult<()> {
        let g = pair(gravity, "gravity")?;
        self.world
            .set_gravity(g)
            .map_err(|e| world_error(e, &self.ids))
    }

    /// The table's cloth, if the world is a table seen from above (see `set_table`): a dict
    /// of its `gravity`, `sliding_friction`, `rolling_friction` and `spinning_friction`;
    /// `None` otherwise.
    #[getter]
    fn table<'py>(&self, py: Python<'py>) -> PyResult<Option<Bound<'py, PyDict>>> {
        self.world.table().map(|t| table::dict(py, &t)).transpose()
    }

    /// The periodic box `(Lx, Ly)` if the world is one, `None` otherwise. Setting it makes
    /// the world the box `[0, Lx) x [0, Ly)` with its opposite edges glued: a ball leaving
    /// through one comes back through the other, two balls meet through their nearest
    /// images, and positions (`positions()`, `position`) come out in the box, while
    /// `unwrapped_positions()` adds the box lengths each ball has crossed (for diffusion).
    ///
    /// Set once, on a world without balls, without gravity and without a table (sleeping
    /// may be on, but no ball sleeps without gravity). Balls added then must be inside the
    /// box, of radius at most `min(Lx, Ly) / 6.6`, and static colliders (before or after)
    /// must keep clear of its edges by more than the largest ball's radius, so that no ball
    /// meets a collider's image across an edge.
    ///
    /// Raises `InvalidInputError` for sides not finite and > 0, a world with balls or
    /// periodic already, gravity or a table (the message names which), or `None` on a
    /// periodic world (a box cannot be taken away; `None` on another world changes nothing).
    #[getter]
    fn get_periodic(&self) -> Option<(f64, f64)> {
        self.world.periodic_box().map(Into::into)
    }

    #[setter]
    fn set_periodic(&mut self, size: &Bound<'_, PyAny>) -> PyResult<()> {
        if size.is_none() {
            return match self.world.periodic_box() {
                None => Ok(()),
                Some(_) => Err(invalid(
                    "a periodic box cannot be taken away (build a new world without one)",
                )),
            };
        }
        let size = pair(size, "periodic")?;
        self.world
            .set_periodic(size)
            .map_err(|e| world_error(e, &self.ids))
    }

    /// The collision virial `W` since `observables_since`: the sum, over every impulse two
    /// balls exchanged, of `(p_i - p_j) . J_i` (`p_i`, `p_j` their centres at the impact, in
    /// a periodic box through the nearest image; `J_i` the impulse ball `i` received), so
    /// each normal impulse adds its magnitude times the contact distance and friction
    /// nothing (kg m^2 / s). Without gravity, over a time `t` in which `N` balls have the
    /// mean kinetic energy `kT`, the pressure on an area `A` is
    /// `P A = N kT + W / (2 t)`, and the compressibility factor `Z = 1 + W / (2 t N kT)`.
    ///
    /// Counted: binary collisions, jams, a group's strikes, contacts with sleeping balls and,
    /// on a table, joins; not the forces of resting contact between balls a group holds
    /// together under gravity (continuous, not impulses). Reading it changes nothing.
    #[getter]
    fn collision_virial(&self) -> f64 {
        self.collision_virial_of()
    }

    /// The time the observables (`collision_virial`, `collider_momentum`,
    /// `collider_impacts`) count from: 0, or the time of the last `reset_observables()`.
    #[getter]
    fn observables_since(&self) -> f64 {
        self.observables_since_of()
    }

    /// Zeroes the observables (the collision virial, every collider's momentum and impacts)
    /// and has them count from now (`observables_since`), e.g. after equilibration. Nothing
    /// else changes: the events that follow are the same, bit for bit.
    fn reset_observables(&mut self) {
        self.world.reset_observables();
        self.carried.observables = None;
    }

    /// The momentum `(x, y)` the balls have given a collider since `observables_since`:
    /// minus the sum of the impulses it gave them (kg m / s), so a ball bouncing off a wall
    /// on its right gives it momentum along `+x`; an elastic bounce at normal speed `u` gives
    /// `2 m u`. Counted: every impulse the collider gives a ball (bounces with their
    /// friction, its share of jams and of groups' strikes, the velocity a settle on it drops,
    /// the cushion on a table); not the continuous forces of resting contact (a ball resting,
    /// sliding or rolling on it under gravity, a group held against it, a ball falling
    /// asleep on it). A collider added later starts at zero. Raises `UnknownHandleError` for
    /// a handle that is not a live collider.
    fn collider_momentum(&self, handle: i64) -> PyResult<(f64, f64)> {
        let h = self.ids.collider(handle)?;
        Ok(self.collider_momentum_of(h).unwrap_or_default().into())
    }

    /// The number of impacts on a collider since `observables_since`: its `contact` events
    /// (bounces, and jams and strikes returned as contact events; not settles or slides).
    /// Raises `UnknownHandleError` for a handle that is not a live collider.
    fn collider_impacts(&self, handle: i64) -> PyResult<u64> {
        let h = self.ids.collider(handle)?;
        Ok(self.collider_impacts_of(h).unwrap_or_default())
    }

    /// Makes the world a table seen from above (billiards, pool): its plane is the cloth,
    /// gravity `gravity` (> 0) pulls every ball into it, and every ball slides, rolls and
    /// spins to rest under the cloth's friction, each change at its analytic time. A ball
    /// carries a *roll* (its angular velocity about the horizontal axes, `set_roll`) besides
    /// its spin about the vertical (`set_spin`); the world's own gravity must be `(0, 0)`.
    ///
    /// Sliding (the contact point slips at `u = v + r (-roll_y, roll_x)`): kinetic friction
    /// `sliding_friction g` against `u` slows the ball and spins the roll up until the slip
    /// vanishes, after `|u| / (mu_s g (1 + 1/k))` (`k` the inertia factor: a sphere's 0.4
    /// gives `2 |u| / (7 mu_s g)`); rolling, it loses `rolling_friction g` of speed a second
    /// until it stops; its spin loses `spinning_friction g / (k r)` a second until it stops.
    /// Each such end is counted in `event_counts()["phase_ends"]`.
    ///
    /// `table`: a dict of some of the four values (the others a pool table's), as
    /// `World.table` gives; not given, a pool table (`gravity` 9.81, `sliding_friction` 0.2,
    /// `rolling_friction` 0.01, `spinning_friction` 0.0127); `None` takes the table away (the
    /// balls keep their velocities and lose their rolls). The keywords set single values on
    /// top. Every ball is restated now and goes on under the new law.
    ///
    /// Raises `InvalidInputError` for a value out of its range (gravity finite and > 0, each
    /// friction finite and >= 0: the message names it), if the world has gravity, or for
    /// values given with `None`.
    #[pyo3(signature = (table = TableArg::Pool, *, gravity = None, sliding_friction = None, rolling_friction = None, spinning_friction = None))]
    fn set_table(
        &mut self,
        table: TableArg,
        gravity: Option<f64>,
        sliding_friction: Option<f64>,
        rolling_friction: Option<f64>,
        spinning_friction: Option<f64>,
    ) -> PyResult<()> {
        let values = [
            gravity,
            sliding_friction,
            rolling_friction,
            spinning_friction,
        ];
        let table = match table {
            TableArg::Pool => Some(Table::POOL),
            TableArg::Given(t) => t,
        };
        let table = match table {
            Some(t) => Some(table::with_values(t, values)),
            None if values.iter().any(Option::is_some) => {
                return Err(invalid(
                    "set_table(None) takes the table away: it takes no values",
                ));
            }
            None => None,
        };
        self.world
            .set_table(table)
            .map_err(|e| world_error(e, &self.ids))
    }

    /// The collapse time `t_c` of the TC model (Luding and McNamara 1998): a collision of a
    /// ball less than `t_c` after its previous event is elastic. 0 (the default) is off.
    #[getter]
    fn get_collapse_time(&self) -> f64 {
        self.world.collapse_time()
    }

    #[setter]
    fn set_collapse_time(&mut self, t_c: f64) -> PyResult<()> {
        self.world
            .set_collapse_time(t_c)
            .map_err(|e| world_error(e, &self.ids))
    }

    /// Whether balls at rest fall asleep (stop costing events until something wakes them);
    /// off by default.
    #[getter]
    fn get_sleeping(&self) -> bool {
        self.world.sleeping()
    }

    #[setter]
    fn set_sleeping(&mut self, sleeping: bool) {
        self.world.set_sleeping(sleeping);
    }

    /// The number of live balls.
    #[getter]
    fn ball_count(&self) -> usize {
        self.world.ball_count()
    }

    /// The number of live colliders.
    #[getter]
    fn collider_count(&self) -> usize {
        self.world.collider_count()
    }

    /// The number of sleeping balls.
    #[getter]
    fn sleeping_count(&self) -> usize {
        self.world.sleeping_count()
    }

    /// Counts of the events handled so far, by kind (`contacts`, `ball_contacts`,
    /// `sensor_enters`, `sensor_exits`, and the internal `settles`, `leaves`, `jams`,
    /// `sleeps`, `wakes` and `phase_ends` (a phase under friction ended: a ball's slip
    /// vanished, it rolled to a stop or its spin stopped, on a surface or a table's cloth);
    /// `rigid_hits` counts the collisions a group of balls pressed together took as one
    /// body, also counted in `contacts` or `ball_contacts`).
    fn event_counts<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let c = self.world.event_counts();
        let dict = PyDict::new(py);
        for (key, value) in [
            ("contacts", c.contacts),
            ("ball_contacts", c.ball_contacts),
            ("sensor_enters", c.sensor_enters),
            ("sensor_exits", c.sensor_exits),
            ("settles", c.settles),
            ("leaves", c.leaves),
            ("jams", c.jams),
            ("rigid_hits", c.rigid_hits),
            ("sleeps", c.sleeps),
            ("wakes", c.wakes),
            ("phase_ends", c.phase_ends),
        ] {
            dict.set_item(key, value)?;
        }
        Ok(dict)
    }

    /// Adds a ball at the current time and returns its handle.
    ///
    /// `pos`, `vel`: pairs `(x, y)`; `radius`, `mass` > 0; `restitution` in [0, 1] (a pair
    /// uses the product of its two values); `groups`: `(memberships, filter)` bit masks, two
    /// bodies interact if each one's memberships meet the other's filter (default: all).
    ///
    /// Spin and friction: `spin` is the angular velocity (radians per second,
    /// counter-clockwise positive), `inertia` the moment of inertia as a factor of `m r^2`, in
    /// (0, 1] (0.5: a uniform disk; 1: a ring), `friction` Coulomb's `mu` >= 0 (0:
    /// frictionless) and `tangential_restitution` `beta` in [-1, 1] (-1 smooth, 0 a sticking
    /// contact ends without slip, 1 perfectly rough). An impact's tangential impulse is
    /// `(1 + beta) g / K`, capped at `mu` times the normal impulse (`g` the contact points'
    /// tangential slip, `K = (1 + 1/k_1)/m_1 + (1 + 1/k_2)/m_2`); a pair's `mu` is the
    /// geometric mean of its two values (no friction unless both have some) and its
    /// `1 + beta` the geometric mean of its two `1 + beta`. Friction acts at impacts in
    /// flight (bounces, ball-ball collisions) and on segments, where a ball rests, slides and
    /// rolls: it slides under kinetic friction `mu g_n` (`g_n` gravity's pull into the
    /// segment) until its contact point sticks, then rolls, accelerating at `g_t / (1 + k)`
    /// (`g_t` gravity's pull along the segment) as long as `|g_t| k / (1 + k) <= mu g_n`, and
    /// sliding otherwise. `rolling_resistance` `c` >= 0 slows a rolling ball by `c g_n` per
    /// second until it stops (a pair's `c` is the geometric mean of its two values). It rolls
    /// the same way over a segment's end point, a circle or a sleeping ball. Balls pressed
    /// together under gravity (a group) slide on each other against kinetic friction and
    /// stick while friction can hold them, the forces on their centres, their spin kept; a
    /// jam's impulses (a zero-time chain resolved as one impact) have friction the same way.
    /// A ball touching another ball alone stays frictionless there and keeps its spin.
    ///
    /// On a table (see `set_table`): `roll` is the ball's angular velocity about the
    /// horizontal axes, `(w_x, w_y)` in radians per second (a ball rolling along `+x` at
    /// speed `v` has `(0, v / radius)`); default `(0, 0)`, the only roll allowed without a
    /// table. The cloth's friction (the table's) slows the ball between impacts; its own
    /// `friction` and `tangential_restitution` act at impacts, on cushions and other balls.
    /// `inertia` 0.4 is a solid sphere's.
    ///
    /// Raises `InvalidInputError` for a bad number (its message names the range) or a roll
    /// without a table, `OverlapError` if the ball would overlap a body it interacts with
    /// (touching is allowed).
    #[pyo3(signature = (pos, vel, radius, mass = 1.0, restitution = 1.0, groups = None, spin = 0.0, inertia = 0.5, friction = 0.0, tangential_restitution = 0.0, rolling_resistance = 0.0, roll = None))]
    // Python's keyword arguments.
    #[allow(clippy::too_many_arguments)]
    fn add_ball(
        &mut self,
        pos: &Bound<'_, PyAny>,
        vel: &Bound<'_, PyAny>,
        radius: f64,
        mass: f64,
        restitution: f64,
        groups: Option<&Bound<'_, PyAny>>,
        spin: f64,
        inertia: f64,
        friction: f64,
        tangential_restitution: f64,
        rolling_resistance: f64,
        roll: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<i64> {
        let roll = roll.map_or(Ok(DVec2::ZERO), |r| pair(r, "roll"))?;
        let desc = Self::ball_desc(
            pair(pos, "pos")?,
            pair(vel, "vel")?,
            radius,
            mass,
            restitution,
            crate::args::groups(groups)?,
        );
        let desc = Self::rough_desc(
            desc,
            spin,
            roll,
            inertia,
            friction,
            tangential_restitution,
            rolling_resistance,
        );
        let id = self.ids.next_ball;
        self.insert_ball(desc, id)
    }

    /// Adds many balls from arrays: `positions` and `velocities` of shape (n, 2), `radii`,
    /// `masses` and `restitutions` of shape (n,) (masses and restitutions default to 1), and
    /// as `add_ball` takes them, `spins`, `inertias`, `frictions`, `tangential_restitutions`
    /// and `rolling_resistances` of shape (n,) (defaults 0, 0.5, 0, 0 and 0), and on a table
    /// `rolls` of shape (n, 2) (default 0). Returns their handles (int64, shape (n,)). All or
    /// nothing: if ball `i` is refused, none is added and the error says `balls[i]: ...`.
    #[pyo3(signature = (positions, velocities, radii, masses = None, restitutions = None, groups = None, spins = None, inertias = None, frictions = None, tangential_restitutions = None, rolling_resistances = None, rolls = None))]
    // Python's keyword arguments, one per column.
    #[allow(clippy::too_many_arguments)]
    fn add_balls<'py>(
        &mut self,
        py: Python<'py>,
        positions: &Bound<'py, PyAny>,
        velocities: &Bound<'py, PyAny>,
        radii: &Bound<'py, PyAny>,
        masses: Option<&Bound<'py, PyAny>>,
        restitutions: Option<&Bound<'py, PyAny>>,
        groups: Option<&Bound<'py, PyAny>>,
        spins: Option<&Bound<'py, PyAny>>,
        inertias: Option<&Bound<'py, PyAny>>,
        frictions: Option<&Bound<'py, PyAny>>,
        tangential_restitutions: Option<&Bound<'py, PyAny>>,
        rolling_resistances: Option<&Bound<'py, PyAny>>,
        rolls: Option<&Bound<'py, PyAny>>,
    ) -> PyResult<Bound<'py, PyArray1<i64>>> {
        let p = pairs_column(&float_array(py, positions, "positions")?, "positions")?;
        let v = pairs_column(&float_array(py, velocities, "velocities")?, "velocities")?;
        let n = p.len();
        if v.len() != n {
            return Err(invalid(format!(
                "velocities must have shape ({n}, 2) like positions, got ({}, 2)",
                v.len()
            )));
        }
        let vector = |a: Option<&Bound<'py, PyAny>>, name: &str| -> PyResult<Option<Vec<f64>>> {
            a.filter(|a| !a.is_none())
                .map(|a| float_array(py, a, name).map(|a| a.iter().copied().collect()))
                .transpose()
        };
        let r = column(vector(Some(radii), "radii")?, n, 1.0, "radii")?;
        let m = column(vector(masses, "masses")?, n, 1.0, "masses")?;
        let e = column(
            vector(restitutions, "restitutions")?,
            n,
            1.0,
            "restitutions",
        )?;
        let w = column(vector(spins, "spins")?, n, 0.0, "spins")?;
        let k = column(
            vector(inertias, "inertias")?,
            n,
            exact2d::DEFAULT_INERTIA,
            "inertias",
        )?;
        let mu = column(vector(frictions, "frictions")?, n, 0.0, "frictions")?;
        let beta = column(
            vector(tangential_restitutions, "tangential_restitutions")?,
            n,
            0.0,
            "tangential_restitutions",
        )?;
        let c = column(
            vector(rolling_resistances, "rolling_resistances")?,
            n,
            0.0,
            "rolling_resistances",
        )?;
        let roll = match rolls.filter(|a| !a.is_none()) {
            None => vec![DVec2::ZERO; n],
            Some(a) => {
                let roll = pairs_column(&float_array(py, a, "rolls")?, "rolls")?;
                if roll.len() != n {
                    return Err(invalid(format!(
                        "rolls must have shape ({n}, 2) like positions, got ({}, 2)",
                        roll.len()
                    )));
                }
                roll
            }
        };
        let g = crate::args::groups(groups)?;
        let mut added = Vec::with_capacity(n);
        self.world.reserve_balls(n);
        for i in 0..n {
            let desc = Self::ball_desc(p[i], v[i], r[i], m[i], e[i], g);
            let desc = Self::rough_desc(desc, w[i], roll[i], k[i], mu[i], beta[i], c[i]);
            let id = self.ids.next_ball;
            match self.insert_ball(desc, id) {
                Ok(id) => added.push(id),
                Err(err) => {
                    for &id in &added {
                        let handle = self.ids.ball(id)?;
                        let _ = self.world.remove_ball(handle);
                        self.ids.remove_ball(id);
                    }
                    return Err(error(
                        Class::from_err(py, &err),
                        format!("balls[{i}]: {}", err.value(py)),
                    ));
                }
            }
        }
        Ok(added.into_pyarray(py))
    }

    /// Adds a static segment from `a` to `b` (balls hit its interior from both sides and both
    /// end points) and returns its handle. A `sensor` is passed through and reports
    /// `sensor_enter` and `sensor_exit` events. `friction` (Coulomb's `mu` >= 0) and
    /// `tangential_restitution` (`beta` in [-1, 1]) make its surface rough, with the ball's
    /// own values as `add_ball` says; balls slide and roll on a rough segment, and its
    /// `rolling_resistance` (>= 0) with the ball's slows a rolling ball.
    #[pyo3(signature = (a, b, restitution = 1.0, sensor = false, groups = None, friction = 0.0, tangential_restitution = 0.0, rolling_resistance = 0.0))]
    // Python's keyword arguments.
    #[allow(clippy::too_many_arguments)]
    fn add_segment(
        &mut self,
        a: &Bound<'_, PyAny>,
        b: &Bound<'_, PyAny>,
        restitution: f64,
        sensor: bool,
        groups: Option<&Bound<'_, PyAny>>,
        friction: f64,
        tangential_restitution: f64,
        rolling_resistance: f64,
    ) -> PyResult<i64> {
        let desc = ColliderDesc::segment(pair(a, "a")?, pair(b, "b")?)
            .restitution(restitution)
            .friction(friction)
            .tangential_restitution(tangential_restitution)
            .rolling_resistance(rolling_resistance)
            .sensor(sensor)
            .groups(crate::args::groups(groups)?);
        let id = self.ids.next_collider;
        self.insert_collider(desc, id)
    }

    /// Adds a static circle (solid, or a `sensor` that balls pass through) and returns its
    /// handle. `friction`, `tangential_restitution` and `rolling_resistance` as for
    /// `add_segment` (a ball rolls over a circle as over a segment's end point).
    #[pyo3(signature = (center, radius, restitution = 1.0, sensor = false, groups = None, friction = 0.0, tangential_restitution = 0.0, rolling_resistance = 0.0))]
    // Python's keyword arguments.
    #[allow(clippy::too_many_arguments)]
    fn add_circle(
        &mut self,
        center: &Bound<'_, PyAny>,
        radius: f64,
        restitution: f64,
        sensor: bool,
        groups: Option<&Bound<'_, PyAny>>,
        friction: f64,
        tangential_restitution: f64,
        rolling_resistance: f64,
    ) -> PyResult<i64> {
        let desc = ColliderDesc::circle(pair(center, "center")?, radius)
            .restitution(restitution)
            .friction(friction)
            .tangential_restitution(tangential_restitution)
            .rolling_resistance(rolling_resistance)
            .sensor(sensor)
            .groups(crate::args::groups(groups)?);
        let id = self.ids.next_collider;
        self.insert_collider(desc, id)
    }

    /// Removes a ball; its handle is never given out again.
    fn remove_ball(&mut self, handle: i64) -> PyResult<()> {
        let h = self.ids.ball(handle)?;
        self.world
            .remove_ball(h)
            .map_err(|e| world_error(e, &self.ids))?;
        self.ids.remove_ball(handle);
        self.carried.images.remove(&handle);
        Ok(())
    }

    /// Removes a collider; balls resting on it fall, sleeping balls it held wake.
    fn remove_collider(&mut self, handle: i64) -> PyResult<()> {
        let h = self.ids.collider(handle)?;
        self.world
            .remove_collider(h)
            .map_err(|e| world_error(e, &self.ids))?;
        self.ids.remove_collider(handle);
        if let Some(o) = &mut self.carried.observables {
            o.colliders.remove(&handle);
        }
        Ok(())
    }

    /// Sets a ball's velocity from now on (a sleeping ball wakes).
    fn set_velocity(&mut self, handle: i64, vel: &Bound<'_, PyAny>) -> PyResult<()> {
        let h = self.ids.ball(handle)?;
        let v = pair(vel, "vel")?;
        self.world
            .set_ball_velocity(h, v)
            .map_err(|e| world_error(e, &self.ids))
    }

    /// Sets a ball's angular velocity (radians per second, counter-clockwise positive) from
    /// now on; its angle carries on from where it is. Spin changes no path by itself: only
    /// rough contacts (see `add_ball`) turn it into motion. A rough ball resting on a rough
    /// segment (a sleeping one too) wakes and starts sliding, then rolling. On a table the
    /// ball's phase on the cloth is taken again (spinning friction slows the new spin).
    fn set_spin(&mut self, handle: i64, spin: f64) -> PyResult<()> {
        let h = self.ids.ball(handle)?;
        self.world
            .set_ball_spin(h, spin)
            .map_err(|e| world_error(e, &self.ids))
    }

    /// Sets a ball's roll on a table (its angular velocity about the horizontal axes,
    /// `(w_x, w_y)` in radians per second; see `add_ball`) from now on: the ball's phase on
    /// the cloth (sliding, rolling) is taken again from its new state. Raises
    /// `InvalidInputError` without a table or for a roll that is not finite.
    fn set_roll(&mut self, handle: i64, roll: &Bound<'_, PyAny>) -> PyResult<()> {
        let h = self.ids.ball(handle)?;
        let r = pair(roll, "roll")?;
        self.world
            .set_ball_roll(h, r)
            .map_err(|e| world_error(e, &self.ids))
    }

    /// Sets a ball's angle (radians counter-clockwise, brought into [-pi, pi]) now; it turns
    /// on from there at its spin. Balls are round: nothing else changes.
    fn set_angle(&mut self, handle: i64, angle: f64) -> PyResult<()> {
        let h = self.ids.ball(handle)?;
        self.world
            .set_ball_angle(h, angle)
            .map_err(|e| world_error(e, &self.ids))
    }

    /// Whether `handle` is a live ball.
    fn has_ball(&self, handle: i64) -> bool {
        self.ids.ball(handle).is_ok()
    }

    /// Whether `handle` is a live collider.
    fn has_collider(&self, handle: i64) -> bool {
        self.ids.collider(handle).is_ok()
    }

    /// A live ball now, as a dict: `position`, `velocity`, `acceleration`, `radius`, `mass`,
    /// `restitution`, `groups`, `asleep`, `support` (the collider it rests or slides on, or
    /// `None`), `spin` (radians per second, counter-clockwise positive), `roll` (on a table:
    /// the angular velocity about the horizontal axes, `(0, 0)` elsewhere), `angle` (radians
    /// turned since it was added, wrapped to [-pi, pi]), `inertia` (a factor of `m r^2`),
    /// `friction`, `tangential_restitution`, `rolling_resistance`.
    fn ball<'py>(&self, py: Python<'py>, handle: i64) -> PyResult<Bound<'py, PyDict>> {
        let h = self.ids.ball(handle)?;
        let b = self
            .world
            .ball(h)
            .ok_or_else(|| world_error(WorldError::NoSuchBall(h), &self.ids))?;
        let dict = PyDict::new(py);
        dict.set_item("position", <(f64, f64)>::from(b.position))?;
        dict.set_item("velocity", <(f64, f64)>::from(b.velocity))?;
        let a = self.world.ball_acceleration(h).unwrap_or(DVec2::ZERO);
        dict.set_item("acceleration", <(f64, f64)>::from(a))?;
        dict.set_item("radius", b.radius)?;
        dict.set_item("mass", b.mass)?;
        dict.set_item("restitution", b.restitution)?;
        dict.set_item("groups", (b.groups.memberships, b.groups.filter))?;
        dict.set_item("asleep", self.world.ball_asleep(h))?;
        let support = self
            .world
            .ball_support(h)
            .map(|(c, _)| self.ids.collider_id(c));
        dict.set_item("support", support)?;
        dict.set_item("spin", b.spin)?;
        dict.set_item("roll", <(f64, f64)>::from(roll_of(&b)))?;
        dict.set_item("angle", b.angle)?;
        dict.set_item("inertia", b.inertia)?;
        dict.set_item("friction", b.friction)?;
        dict.set_item("tangential_restitution", b.tangential_restitution)?;
        dict.set_item("rolling_resistance", b.rolling_resistance)?;
        Ok(dict)
    }

    /// What holds a ball against gravity: a list of `("collider", handle)` and
    /// `("ball", handle)` (the sleeping balls it rests on); empty for a ball in flight.
    fn ball_holders(&self, handle: i64) -> PyResult<Vec<(&'static str, i64)>> {
        let h = self.ids.ball(handle)?;
        let holders = self.world.ball_holders(h).unwrap_or_default();
        Ok(holders
            .into_iter()
            .map(|b| match b {
                Body::Collider(c) => ("collider", self.ids.collider_id(c)),
                Body::Ball(b) => ("ball", self.ids.ball_id(b)),
            })
            .collect())
    }

    /// The sensors a ball overlaps now, in the order it entered them.
    fn ball_sensors(&self, handle: i64) -> PyResult<Vec<i64>> {
        let h = self.ids.ball(handle)?;
        let sensors = self.world.ball_sensors(h).unwrap_or_default();
        Ok(sensors.iter().map(|&c| self.ids.collider_id(c)).collect())
    }

    /// When a sleeping ball fell asleep; `None` if it is awake.
    fn ball_asleep_since(&self, handle: i64) -> PyResult<Option<f64>> {
        let h = self.ids.ball(handle)?;
        Ok(self.world.ball_asleep_since(h))
    }

    /// How many events the world has handled at the current instant, and how many balls had
    /// them (both 0 once the clock has moved on): what the stall check compares.
    fn instant_events(&self) -> (u64, usize) {
        self.world.instant_events()
    }

    /// Makes room for `additional` more balls (a hint for speed and memory).
    fn reserve_balls(&mut self, additional: i64) -> PyResult<()> {
        let n = count(additional, "additional", 1 << 40)?;
        self.world.reserve_balls(n);
        Ok(())
    }

    /// A ball's position now.
    fn position(&self, handle: i64) -> PyResult<(f64, f64)> {
        let h = self.ids.ball(handle)?;
        Ok(self.world.ball(h).map_or((0.0, 0.0), |b| b.position.into()))
    }

    /// A ball's unwrapped position now: in a periodic box, its position plus the box lengths
    /// it has crossed since it was added (the displacement since then is this minus where it
    /// was added); elsewhere its position.
    fn unwrapped_position(&self, handle: i64) -> PyResult<(f64, f64)> {
        let h = self.ids.ball(handle)?;
        Ok(self
            .world
            .ball(h)
            .map_or((0.0, 0.0), |b| self.unwrapped_of(h, b.position).into()))
    }

    /// A ball's velocity now.
    fn velocity(&self, handle: i64) -> PyResult<(f64, f64)> {
        let h = self.ids.ball(handle)?;
        Ok(self.world.ball(h).map_or((0.0, 0.0), |b| b.velocity.into()))
    }

    /// A ball's angular velocity now (radians per second, counter-clockwise positive).
    fn spin(&self, handle: i64) -> PyResult<f64> {
        let h = self.ids.ball(handle)?;
        Ok(self.world.ball(h).map_or(0.0, |b| b.spin))
    }

    /// A ball's roll now (on a table: its angular velocity about the horizontal axes,
    /// `(w_x, w_y)` in radians per second; `(0, 0)` without a table).
    fn roll(&self, handle: i64) -> PyResult<(f64, f64)> {
        let h = self.ids.ball(handle)?;
        Ok(self
            .world
            .ball(h)
            .map_or((0.0, 0.0), |b| roll_of(&b).into()))
    }

    /// A ball's angle now: the radians it has turned through since it was added (counter-
    /// clockwise positive), wrapped to [-pi, pi].
    fn angle(&self, handle: i64) -> PyResult<f64> {
        let h = self.ids.ball(handle)?;
        Ok(self.world.ball(h).map_or(0.0, |b| b.angle))
    }

    /// A live collider, as a dict: `kind` (`"segment"` with `a`, `b`, or `"circle"` with
    /// `center`, `radius`), `sensor`, `restitution`, `groups`, `friction`,
    /// `tangential_restitution`, `rolling_resistance`.
    fn collider<'py>(&self, py: Python<'py>, handle: i64) -> PyResult<Bound<'py, PyDict>> {
        let h = self.ids.collider(handle)?;
        let c = self
            .world
            .collider(h)
            .ok_or_else(|| world_error(WorldError::NoSuchCollider(h), &self.ids))?;
        let dict = PyDict::new(py);
        match c.shape {
            Shape::Segment(s) => {
                dict.set_item("kind", "segment")?;
                dict.set_item("a", <(f64, f64)>::from(s.a()))?;
                dict.set_item("b", <(f64, f64)>::from(s.b()))?;
            }
            Shape::Circle(circle) => {
                dict.set_item("kind", "circle")?;
                dict.set_item("center", <(f64, f64)>::from(circle.center))?;
                dict.set_item("radius", circle.radius)?;
            }
        }
        dict.set_item("sensor", c.sensor)?;
        dict.set_item("restitution", c.restitution)?;
        dict.set_item("groups", (c.groups.memberships, c.groups.filter))?;
        dict.set_item("friction", c.friction)?;
        dict.set_item("tangential_restitution", c.tangential_restitution)?;
        dict.set_item("rolling_resistance", c.rolling_resistance)?;
        Ok(dict)
    }

    /// The live balls' handles (int64, shape (n,)), in the order of every other array.
    fn handles<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<i64>> {
        let v: Vec<i64> = self
            .world
            .balls()
            .map(|(h, _)| self.ids.ball_id(h))
            .collect();
        v.into_pyarray(py)
    }

    /// The live colliders' handles (int64, shape (m,)).
    fn collider_handles<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<i64>> {
        let v: Vec<i64> = self
            .world
            .colliders()
            .map(|(h, _)| self.ids.collider_id(h))
            .collect();
        v.into_pyarray(py)
    }

    /// The balls' centres now (float64, shape (n, 2)).
    fn positions<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray2<f64>> {
        self.ball_pairs(py, |b| b.position)
    }

    /// The balls' unwrapped positions now (float64, shape (n, 2), in the order of
    /// `positions()`): in a periodic box, each position plus the box lengths the ball has
    /// crossed since it was added; elsewhere the positions.
    fn unwrapped_positions<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray2<f64>> {
        pairs_array(py, self.unwrapped_pairs())
    }

    /// The balls' velocities now (float64, shape (n, 2)).
    fn velocities<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray2<f64>> {
        self.ball_pairs(py, |b| b.velocity)
    }

    /// The balls' radii (float64, shape (n,)).
    fn radii<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        self.ball_column(py, |b| b.radius)
    }

    /// The balls' masses (float64, shape (n,)).
    fn masses<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        self.ball_column(py, |b| b.mass)
    }

    /// The balls' angular velocities now (float64, shape (n,); radians per second,
    /// counter-clockwise positive).
    fn spins<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        self.ball_column(py, |b| b.spin)
    }

    /// The balls' rolls now (float64, shape (n, 2)): on a table, each one's angular velocity
    /// about the horizontal axes `(w_x, w_y)` (radians per second; rolling along `+x` at
    /// speed `v`: `(0, v / r)`); zeros without a table.
    fn rolls<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray2<f64>> {
        self.ball_pairs(py, roll_of)
    }

    /// The balls' angles now (float64, shape (n,)): the radians each has turned through since
    /// it was added, wrapped to [-pi, pi].
    fn angles<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        self.ball_column(py, |b| b.angle)
    }

    /// The balls' moments of inertia as factors of `m r^2` (float64, shape (n,)): the moment
    /// of inertia of ball `i` is `inertias()[i] * masses()[i] * radii()[i]**2`.
    fn inertias<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        self.ball_column(py, |b| b.inertia)
    }

    /// The balls' kinetic energies now, translational and rotational (float64, shape (n,)):
    /// `m |v|^2 / 2 + k m r^2 (w^2 + |roll|^2) / 2` (the roll on a table).
    fn kinetic_energies<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        self.ball_column(py, exact2d::Ball::kinetic_energy)
    }

    /// Handles the next event, whenever it is, and returns it; `None` if no event will ever
    /// happen.
    fn step(&mut self) -> Option<PyEvent> {
        let e = self.world.step();
        self.event(e)
    }

    /// Handles the next event if it happens at or before `until` and returns it; otherwise
    /// moves the clock to `until` and returns `None`. Raises `TimeBeforeNowError` if `until`
    /// is before now (or NaN).
    fn step_until(&mut self, until: f64) -> PyResult<Option<PyEvent>> {
        let e = self
            .world
            .step_until(until)
            .map_err(|e| world_error(e, &self.ids))?;
        Ok(self.event(e))
    }

    /// Handles every event up to and including `t`, then leaves every ball exactly at `t`;
    /// returns the number of events. Releases the GIL and stops on Ctrl-C (the world is then
    /// left consistent, at its last event).
    fn advance_to(&mut self, py: Python<'_>, t: f64) -> PyResult<u64> {
        run_to(py, &mut self.world, t, |_| {}).map_err(|e| self.run_error(e))
    }

    /// `advance_to(t)`, collecting every event at Rust speed: a dict of NumPy arrays, one row
    /// per event, in order: `time` (float64), `kind` (int8: 0 contact, 1 ball_contact,
    /// 2 sensor_enter, 3 sensor_exit), `ball`, `other_ball`, `collider` (int64, -1 where not
    /// applicable), `point`, `normal` ((k, 2) float64, the normal NaN for sensor events),
    /// `impulse`, `normal_speed` (float64).
    fn advance_to_collect<'py>(&mut self, py: Python<'py>, t: f64) -> PyResult<Bound<'py, PyDict>> {
        let mut events = Vec::new();
        run_to(py, &mut self.world, t, |e| events.push(*e)).map_err(|e| self.run_error(e))?;
        columns(py, &events, &self.ids)
    }

    /// The time of the next event (or internal change), if any.
    fn next_event_time(&mut self) -> Option<f64> {
        self.world.next_event_time()
    }

    /// The first collider a ball of `radius` from `origin` with `velocity` (under the world's
    /// gravity) would touch, or `None`. Balls are ignored; sensors too unless
    /// `include_sensors`.
    #[pyo3(signature = (origin, velocity, radius, max_time = f64::INFINITY, groups = None, include_sensors = false))]
    fn cast_ball(
        &self,
        origin: &Bound<'_, PyAny>,
        velocity: &Bound<'_, PyAny>,
        radius: f64,
        max_time: f64,
        groups: Option<&Bound<'_, PyAny>>,
        include_sensors: bool,
    ) -> PyResult<Option<PyCastHit>> {
        let options = cast_options(max_time, groups, include_sensors, 1.0)?;
        let hit = self
            .world
            .cast_ball(
                pair(origin, "origin")?,
                pair(velocity, "velocity")?,
                radius,
                &options,
            )
            .map_err(|e| world_error(e, &self.ids))?;
        Ok(hit.map(|h| PyCastHit::new(&h, &self.ids)))
    }

    /// The first `bounces` contacts of a ball bouncing off the static colliders as the engine
    /// would bounce it (an aim preview): a list of `CastHit`, times from the launch.
    #[pyo3(signature = (origin, velocity, radius, bounces, max_time = f64::INFINITY, groups = None, restitution = 1.0))]
    // Python's keyword arguments.
    #[allow(clippy::too_many_arguments)]
    fn bounce_path(
        &self,
        origin: &Bound<'_, PyAny>,
        velocity: &Bound<'_, PyAny>,
        radius: f64,
        bounces: i64,
        max_time: f64,
        groups: Option<&Bound<'_, PyAny>>,
        restitution: f64,
    ) -> PyResult<Vec<PyCastHit>> {
        let bounces = count(bounces, "bounces", 1 << 20)?;
        let options = cast_options(max_time, groups, false, finite(restitution, "restitution")?)?;
        let hits = self
            .world
            .bounce_path(
                pair(origin, "origin")?,
                pair(velocity, "velocity")?,
                radius,
                bounces,
                &options,
            )
            .map_err(|e| world_error(e, &self.ids))?;
        Ok(hits.iter().map(|h| PyCastHit::new(h, &self.ids)).collect())
    }

    /// A world from a scene (format version 1, `docs/scene-format.md`): a path to a JSON file
    /// or a dict. Validated as `exact2d simulate` does, with its messages (`SceneError`, an
    /// `InvalidInputError`; a file's messages start with its path). Balls keep their scene
    /// ids as handles; colliders are numbered in the order segments, then circles. A scene's
    /// `"table"` (and its balls' `"roll"`) make the world a table seen from above (see
    /// `set_table`), and its `"periodic": [Lx, Ly]` a periodic box (see `periodic`).
    #[staticmethod]
    fn from_scene(py: Python<'_>, scene: &Bound<'_, PyAny>) -> PyResult<Self> {
        state::from_scene(py, scene)
    }

    /// The world now as a scene dict (format version 1) at time 0: what `from_scene` reads
    /// back. Raises `InvalidInputError` for what the format cannot say (sensors, collision
    /// groups other than all-meet-all or balls-pass-through-balls, a collapse time). Balls
    /// keep their spin, roll, inertia, friction, tangential restitution and rolling
    /// resistance, colliders their friction, tangential restitution and rolling resistance,
    /// and the world its table and its periodic box (`"periodic"`); a scene starts every
    /// angle at 0, so the balls' angles are not kept, nor the box lengths they have crossed
    /// (their unwrapped positions start again at their positions), nor the observables.
    fn to_scene<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        state::to_scene(py, self)
    }

    /// An independent world in the same state, bit for bit: the engine's clone, with the
    /// Python handles and what a pickle carried. Given the same calls, the two go on with the
    /// same events and bits, at any instant (mid-run, balls asleep, groups held), where a
    /// world pickled mid-run is rebuilt from its public state and its future matches to
    /// rounding only. Branching a run (a tree search, a perturbation) is a copy.
    pub(crate) fn copy(&self) -> Self {
        // Every field, by name: a field added to `PyWorld` must be copied here too.
        let Self {
            world,
            ids,
            carried,
        } = self;
        Self {
            world: world.clone(),
            ids: ids.clone(),
            carried: carried.clone(),
        }
    }

    /// `copy.copy(world)`: `copy()`, exact (not through the pickle).
    fn __copy__(&self) -> Self {
        self.copy()
    }

    /// `copy.deepcopy(world)`: `copy()`, exact (not through the pickle). A world holds no
    /// Python objects, so `memo` has nothing to share.
    fn __deepcopy__(&self, memo: &Bound<'_, PyAny>) -> Self {
        let _ = memo;
        self.copy()
    }

    /// Everything needed to rebuild the world (a JSON string); used by pickling. It keeps
    /// the table, the periodic box, every ball's spin, roll, angle, inertia, friction,
    /// tangential restitution, rolling resistance and unwrapped position, every collider's
    /// friction, tangential restitution and rolling resistance, and the observables (the
    /// collision virial, `observables_since`, each collider's momentum and impacts), bit for
    /// bit. The world is rebuilt from this state, so one pickled mid-run goes on to rounding
    /// only: `copy()` is the exact branch.
    fn __getstate__(&self) -> String {
        state::save(self)
    }

    fn __setstate__(&mut self, text: &str) -> PyResult<()> {
        *self = state::load(text)?;
        Ok(())
    }

    fn __reduce__<'py>(
        slf: &Bound<'py, Self>,
    ) -> PyResult<(Bound<'py, pyo3::types::PyType>, (), String)> {
        let text = slf.borrow().__getstate__();
        Ok((slf.get_type(), (), text))
    }

    fn __repr__(&self) -> String {
        let periodic = self
            .world
            .periodic_box()
            .map(|s| format!(", periodic={:?}", <(f64, f64)>::from(s)))
            .unwrap_or_default();
        format!(
            "World(time={:?}, balls={}, colliders={}, gravity={:?}{periodic})",
            self.world.time(),
            self.world.ball_count(),
            self.world.collider_count(),
            <(f64, f64)>::from(self.world.gravity())
        )
    }
}

/// A ball's roll, its zeros positive (the engine's `Ball::roll` of a ball without one may
/// hold a `-0.0`).
pub fn roll_of(b: &exact2d::Ball) -> DVec2 {
    b.roll + DVec2::ZERO
}

/// A (n, 2) array of pairs.
pub fn pairs_array(py: Python<'_>, v: Vec<f64>) -> Bound<'_, PyArray2<f64>> {
    let n = v.len() / 2;
    let a = Array2::from_shape_vec((n, 2), v).expect("pairs");
    a.into_pyarray(py)
}
