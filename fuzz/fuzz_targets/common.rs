//! What the world fuzz targets share: the choice between the two modes, coordinates on a
//! dyadic grid, the two collision groups, the overlap and stall checks of the random mode, and
//! the adversarial mode (scenes from `exact2d_hunt`, run with its checker).

use exact2d::{CollisionGroups, DVec2, Shape, World, WorldError, overlap_bound};
use exact2d_hunt::check::EVENTS_PER_BALL;
use exact2d_hunt::generate::{Options, generate};
use exact2d_hunt::run::{Limits, run_world};
use exact2d_hunt::source::Bytes;

/// How far the adversarial mode runs a scene: two simulated seconds or 20,000 events,
/// whichever comes first, so one input takes well under a second even instrumented.
pub const LIMITS: Limits = Limits {
    until: 2.0,
    events: 20_000,
    collapse: 0.0,
};

/// The mode an input asks for (the low bit of its first byte), with the bytes after that one.
pub enum Mode<'a> {
    /// A random world in general position: the bytes are an `arbitrary` spec.
    Random(&'a [u8]),
    /// An adversarial scene: the bytes steer `exact2d_hunt::generate`.
    Adversarial(&'a [u8]),
}

/// Splits `data` into its mode and that mode's bytes; `None` for an empty input.
pub fn mode(data: &[u8]) -> Option<Mode<'_>> {
    let (&first, rest) = data.split_first()?;
    Some(if first & 1 == 0 {
        Mode::Random(rest)
    } else {
        Mode::Adversarial(rest)
    })
}

/// Generates a scene from `bytes` with `options`, builds it and runs it to [`LIMITS`] with
/// every invariant of `exact2d_hunt::check` checked after every event; panics on a finding,
/// naming the scene (motifs, scale, offset, and its JSON to replay it).
///
/// The generator promises valid scenes (it leaves out degenerate segments and balls that
/// would overlap what was placed before them, and its tests assert that the scenes validate),
/// so a scene that `build_world` refuses is a finding too.
///
/// With `table`, the scene is laid on a table seen from above first
/// (`generate::lay_on_table`, from the same bytes).
pub fn adversarial(bytes: &[u8], options: Options, table: bool) {
    let mut generated = generate(&mut Bytes::new(bytes), options);
    if table {
        let scale = generated.scale;
        exact2d_hunt::generate::lay_on_table(&mut generated.scene, scale, &mut Bytes::new(bytes));
    }
    let motifs: Vec<_> = generated.motifs.iter().map(|m| m.name()).collect();
    let what = format!(
        "motifs {motifs:?}, scale {:e}, offset {:e}, {options:?}",
        generated.scale, generated.offset
    );
    run_generated(&generated, &what);
}

/// Builds `generated` and runs it to [`LIMITS`] with every check of `exact2d_hunt::check`;
/// panics on a refusal or a finding, naming the scene (`what`, and its JSON to replay it).
fn run_generated(generated: &exact2d_hunt::generate::Generated, what: &str) {
    let describe = || format!("{what}\nscene: {}", generated.scene.to_json_string());
    let world = match generated.scene.build_world() {
        Ok(built) => built.into_world(),
        Err(e) => panic!("the generated scene was refused: {e}; {}", describe()),
    };
    let outcome = run_world(world, generated.bounds, LIMITS);
    if let Some(finding) = outcome.finding {
        panic!(
            "{finding} after {} events (t = {:?}); {}",
            outcome.events,
            outcome.time,
            describe()
        );
    }
}

/// [`adversarial`] for a periodic box (`exact2d_hunt::periodic::generate_periodic`, from the
/// same bytes): balls on and through its edges, rows wrapping round it, boxes as small as the
/// engine takes; every check of `exact2d_hunt::check` (pairs through their nearest images,
/// every ball in the box) after every event. (Only `world_events` runs periodic boxes: they
/// take no gravity.)
#[allow(dead_code)]
pub fn periodic(bytes: &[u8]) {
    let generated = exact2d_hunt::periodic::generate_periodic(&mut Bytes::new(bytes));
    run_generated(
        &generated,
        &format!("periodic, scale {:e}", generated.scale),
    );
}

/// Coordinates on a 1/64 grid in [-8, 8): exact doubles, so touching placements, shared end
/// points, collinear and crossing segments come up often.
pub fn coord(c: i16) -> f64 {
    f64::from(c % 512) / 64.0
}

/// Everything interacts but balls of the second group pass through each other.
pub fn groups(second: bool) -> CollisionGroups {
    if second {
        CollisionGroups::new(2, !2)
    } else {
        CollisionGroups::ALL
    }
}

/// The gap between a ball (centre `p`, radius `r`) and a shape, and the contact distance.
pub fn gap(shape: &Shape, p: DVec2, r: f64) -> (f64, f64) {
    match shape {
        Shape::Segment(s) => (s.distance(p) - r, r),
        Shape::Circle(k) => (p.distance(k.center) - k.radius - r, k.radius + r),
    }
}

/// The first pair of interacting bodies that overlap deeper than the engine's stated bound,
/// [`overlap_bound`]`(coordinates, reach)`: `coordinates` is the larger largest magnitude of a
/// coordinate of the two (for a collider, of its point nearest the ball: a segment's closest
/// point, a circle's centre), `reach` their contact distance. Names the pair, the depth and
/// the bound.
pub fn overlap(world: &World) -> Option<String> {
    let balls: Vec<_> = world.balls().collect();
    for (i, &(ha, a)) in balls.iter().enumerate() {
        let ca = a.position.abs().max_element();
        for &(hb, b) in &balls[..i] {
            if !a.groups.interact(b.groups) {
                continue;
            }
            let reach = a.radius + b.radius;
            let depth = reach - a.position.distance(b.position);
            let bound = overlap_bound(ca.max(b.position.abs().max_element()), reach);
            if depth > bound {
                return Some(format!(
                    "balls {} and {} overlap {depth:e} (bound {bound:e}): {a:?}, {b:?}",
                    hb.index(),
                    ha.index()
                ));
            }
        }
        for (hc, c) in world.colliders() {
            if c.sensor || !c.groups.interact(a.groups) {
                continue;
            }
            let near = match &c.shape {
                Shape::Segment(s) => s.closest_point(a.position),
                Shape::Circle(k) => k.center,
            };
            let (g, reach) = gap(&c.shape, a.position, a.radius);
            let bound = overlap_bound(ca.max(near.abs().max_element()), reach);
            if -g > bound {
                return Some(format!(
                    "ball {} and collider {} overlap {:e} (bound {bound:e}): {a:?}, {:?}",
                    ha.index(),
                    hc.index(),
                    -g,
                    c.shape
                ));
            }
        }
    }
    None
}

/// Panics unless the clock moves on: the events at the current instant (internal ones
/// included) stay within `exact2d_hunt::check::EVENTS_PER_BALL` per ball that had one, plus
/// that many again.
pub fn check_instant(world: &World, t: f64) {
    let (events, balls) = world.instant_events();
    assert!(
        events <= EVENTS_PER_BALL * (balls as u64 + 1),
        "stall: {events} events at t = {t} among {balls} balls"
    );
}

/// The next event before `until`, or `None` at the end; panics if the engine reports an error
/// (its own stall safety net, [`WorldError::Stalled`], included).
pub fn next_event(world: &mut World, until: f64) -> Option<exact2d::Event> {
    match world.step_until(until) {
        Ok(event) => event,
        Err(e @ WorldError::Stalled { .. }) => panic!("the engine reported a stall: {e}"),
        Err(e) => panic!("step_until({until}) failed at t = {}: {e}", world.time()),
    }
}
