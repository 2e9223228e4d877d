//! Events as Python objects (one at a time) and as NumPy columns (a whole run at once).

use exact2d::{Event, Feature};
use numpy::IntoPyArray;
use numpy::ndarray::Array2;
use pyo3::prelude::*;
use pyo3::types::PyDict;

use crate::ids::Ids;

/// Kind codes of the `kind` column of `World.advance_to_collect`.
pub const KINDS: [&str; 4] = ["contact", "ball_contact", "sensor_enter", "sensor_exit"];

fn feature_name(feature: Feature) -> &'static str {
    match feature {
        Feature::SegmentInterior => "segment",
        Feature::SegmentEndA => "end_a",
        Feature::SegmentEndB => "end_b",
        Feature::Circle => "circle",
    }
}

/// Something that happened at an exact time: a ball bounced off a collider (`"contact"`),
/// two balls collided (`"ball_contact"`), or a ball entered or left a sensor
/// (`"sensor_enter"`, `"sensor_exit"`).
#[pyclass(module = "exact2d", name = "Event", frozen, get_all)]
#[derive(Clone, Debug)]
pub struct PyEvent {
    /// When (simulated seconds).
    pub time: f64,
    /// `"contact"`, `"ball_contact"`, `"sensor_enter"` or `"sensor_exit"`.
    pub kind: &'static str,
    /// The ball (for a ball contact, the one with the smaller slot: `normal` points from it
    /// to `other_ball`).
    pub ball: i64,
    /// The other ball of a ball contact, else `None`.
    pub other_ball: Option<i64>,
    /// The collider of a contact or a sensor event, else `None`.
    pub collider: Option<i64>,
    /// The part of the collider touched or crossed: `"segment"` (its interior), `"end_a"`,
    /// `"end_b"` or `"circle"`; `None` for a ball contact.
    pub feature: Option<&'static str>,
    /// The contact point (for a sensor event: the ball's centre).
    pub point: (f64, f64),
    /// The unit contact normal (from the collider to the ball, or from `ball` to
    /// `other_ball`); `None` for a sensor event.
    pub normal: Option<(f64, f64)>,
    /// The normal impulse applied (mass times change of normal velocity; for a ball contact,
    /// the impulse `other_ball` received along `normal`); 0 for a sensor event.
    pub impulse: f64,
    /// The approach speed along the normal before the contact; 0 for a sensor event.
    pub normal_speed: f64,
    /// The friction impulse along the normal turned a quarter counter-clockwise (on the ball
    /// of a contact, on `other_ball` of a ball contact); 0 without friction and for a sensor
    /// event.
    pub tangential_impulse: f64,
}

#[pymethods]
impl PyEvent {
    /// The bodies involved: `(ball, other_ball)` or `(ball, collider)`.
    #[getter]
    fn bodies(&self) -> (i64, i64) {
        (self.ball, self.other_ball.or(self.collider).unwrap_or(-1))
    }

    fn __repr__(&self) -> String {
        let other = match (self.other_ball, self.collider) {
            (Some(b), _) => format!("other_ball={b}"),
            (None, Some(c)) => format!("collider={c}"),
            _ => String::new(),
        };
        format!(
            "Event(kind={:?}, time={:?}, ball={}, {other}, impulse={:?})",
            self.kind, self.time, self.ball, self.impulse
        )
    }
}

impl PyEvent {
    /// The Python view of an engine event.
    pub fn new(event: &Event, ids: &Ids) -> Self {
        match event {
            Event::Contact(c) => Self {
                time: c.time,
                kind: KINDS[0],
                ball: ids.ball_id(c.ball),
                other_ball: None,
                collider: Some(ids.collider_id(c.collider)),
                feature: Some(feature_name(c.feature)),
                point: c.point.into(),
                normal: Some(c.normal.into()),
                impulse: c.impulse,
                normal_speed: c.normal_speed,
                tangential_impulse: c.tangential_impulse,
            },
            Event::BallContact(c) => Self {
                time: c.time,
                kind: KINDS[1],
                ball: ids.ball_id(c.a),
                other_ball: Some(ids.ball_id(c.b)),
                collider: None,
                feature: None,
                point: c.point.into(),
                normal: Some(c.normal.into()),
                impulse: c.impulse,
                normal_speed: c.normal_speed,
                tangential_impulse: c.tangential_impulse,
            },
            Event::SensorEnter(s) | Event::SensorExit(s) => Self {
                time: s.time,
                kind: KINDS[2 + usize::from(matches!(event, Event::SensorExit(_)))],
                ball: ids.ball_id(s.ball),
                other_ball: None,
                collider: Some(ids.collider_id(s.collider)),
                feature: Some(feature_name(s.feature)),
                point: s.position.into(),
                normal: None,
                impulse: 0.0,
                normal_speed: 0.0,
                tangential_impulse: 0.0,
            },
        }
    }
}

/// Every event of a run as NumPy columns, one row per event (see
/// `World.advance_to_collect`).
pub fn columns<'py>(py: Python<'py>, events: &[Event], ids: &Ids) -> PyResult<Bound<'py, PyDict>> {
    let n = events.len();
    let (mut time, mut kind, mut ball, mut other_ball, mut collider) = (
        Vec::with_capacity(n),
        Vec::with_capacity(n),
        Vec::with_capacity(n),
        Vec::with_capacity(n),
        Vec::with_capacity(n),
    );
    let (mut point, mut normal, mut impulse, mut normal_speed, mut tangential) = (
        Vec::with_capacity(2 * n),
        Vec::with_capacity(2 * n),
        Vec::with_capacity(n),
        Vec::with_capacity(n),
        Vec::with_capacity(n),
    );
    for event in events {
        let e = PyEvent::new(event, ids);
        time.push(e.time);
        kind.push(KINDS.iter().position(|k| *k == e.kind).unwrap_or(0) as i8);
        ball.push(e.ball);
        other_ball.push(e.other_ball.unwrap_or(-1));
        collider.push(e.collider.unwrap_or(-1));
        point.extend([e.point.0, e.point.1]);
        let (nx, ny) = e.normal.unwrap_or((f64::NAN, f64::NAN));
        normal.extend([nx, ny]);
        impulse.push(e.impulse);
        normal_speed.push(e.normal_speed);
        tangential.push(e.tangential_impulse);
    }
    let dict = PyDict::new(py);
    let pairs = |v: Vec<f64>| Array2::from_shape_vec((n, 2), v).expect("two per event");
    dict.set_item("time", time.into_pyarray(py))?;
    dict.set_item("kind", kind.into_pyarray(py))?;
    dict.set_item("ball", ball.into_pyarray(py))?;
    dict.set_item("other_ball", other_ball.into_pyarray(py))?;
    dict.set_item("collider", collider.into_pyarray(py))?;
    dict.set_item("point", pairs(point).into_pyarray(py))?;
    dict.set_item("normal", pairs(normal).into_pyarray(py))?;
    dict.set_item("impulse", impulse.into_pyarray(py))?;
    dict.set_item("normal_speed", normal_speed.into_pyarray(py))?;
    dict.set_item("tangential_impulse", tangential.into_pyarray(py))?;
    Ok(dict)
}
