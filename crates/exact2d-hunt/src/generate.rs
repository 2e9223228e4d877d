//! Adversarial scenes: round-number geometry of the kind level designers write, where
//! contacts tie exactly.
//!
//! Every scene is a closed box with one to three *motifs* in it and a few free balls, in local
//! units, then scaled (1e-6 to 1e6) and moved away from the origin (up to 1e9):
//!
//! | motif | what ties |
//! | --- | --- |
//! | channel | walls exactly one diameter apart, upright or at an angle; balls inside, touching both |
//! | peg_wall | a peg whose gap to a wall is exactly one diameter (or a rounding error more or less) |
//! | peg_peg | two pegs whose gap is exactly one diameter |
//! | wedge | a V of 1 to 90 degrees, balls dropped into it |
//! | touching | balls placed touching the floor, each other and a peg at time 0 |
//! | stack | columns and triangles of touching balls |
//! | corner_shot | a ball aimed exactly at an end point or a box corner |
//! | funnel | two slanted walls with a spout exactly one diameter wide, sometimes with an exact-fit stem |
//! | collinear | a floor segment inside another collinear one |
//! | polyline | segments sharing end points: valleys, hills, a post at a joint |
//! | box_fit | a box exactly one, two or three balls wide, the balls touching |
//!
//! Restitutions come from {1, 0.9, 0.8, 0.5, 0}, gravity is mostly down (sometimes tilted, or
//! off), and balls meet each other or not. Rotations use a fixed table of cosines and sines,
//! so a seed gives the same scene on every machine.

use exact2d::scene::{Scene, SceneBall, SceneCircle, SceneSegment, SceneTable};
use exact2d::{BallDesc, ColliderDesc, CollisionGroups, DVec2, World};

use crate::source::Source;

/// What a generated scene may use.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Options {
    /// Gravity (mostly down); without it, no gravity at all.
    pub gravity: bool,
    /// Every restitution 1: energy is then kept, except where jams absorb it.
    pub elastic: bool,
}

impl Default for Options {
    fn default() -> Self {
        Self {
            gravity: true,
            elastic: false,
        }
    }
}

/// The motifs (see the module documentation).
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Motif {
    /// Walls exactly one diameter apart.
    Channel,
    /// A peg one diameter from a wall.
    PegWall,
    /// Two pegs one diameter apart.
    PegPeg,
    /// A V-wedge.
    Wedge,
    /// Balls touching the floor, each other, a peg.
    Touching,
    /// Columns and triangles of balls.
    Stack,
    /// A ball aimed at an end point or a corner.
    CornerShot,
    /// A funnel with an exact-fit spout.
    Funnel,
    /// A floor inside a collinear floor.
    Collinear,
    /// Segments sharing end points.
    Polyline,
    /// A box exactly k balls wide.
    BoxFit,
}

impl Motif {
    /// Every motif.
    pub const ALL: [Motif; 11] = [
        Motif::Channel,
        Motif::PegWall,
        Motif::PegPeg,
        Motif::Wedge,
        Motif::Touching,
        Motif::Stack,
        Motif::CornerShot,
        Motif::Funnel,
        Motif::Collinear,
        Motif::Polyline,
        Motif::BoxFit,
    ];

    /// Its name, as in the module documentation.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Motif::Channel => "channel",
            Motif::PegWall => "peg_wall",
            Motif::PegPeg => "peg_peg",
            Motif::Wedge => "wedge",
            Motif::Touching => "touching",
            Motif::Stack => "stack",
            Motif::CornerShot => "corner_shot",
            Motif::Funnel => "funnel",
            Motif::Collinear => "collinear",
            Motif::Polyline => "polyline",
            Motif::BoxFit => "box_fit",
        }
    }
}

/// A generated scene and how it was made.
#[derive(Clone, Debug)]
pub struct Generated {
    /// The scene (balls that would overlap what was placed before them are left out).
    pub scene: Scene,
    /// Its motifs.
    pub motifs: Vec<Motif>,
    /// The scale applied to the local units.
    pub scale: f64,
    /// The offset added to every coordinate.
    pub offset: f64,
    /// The closed box: its lower-left and upper-right corners.
    pub bounds: (DVec2, DVec2),
}

/// Angles in degrees with their cosines and sines, to 1 ulp (a table, not `cos`/`sin`, so a
/// scene is the same on every platform).
const ROTATIONS: [(f64, f64, f64); 17] = [
    (0.0, 1.0, 0.0),
    (0.5, 0.999_961_923_064_171_3, 0.008_726_535_498_373_935),
    (1.0, 0.999_847_695_156_391_3, 0.017_452_406_437_283_51),
    (2.0, 0.999_390_827_019_095_8, 0.034_899_496_702_500_97),
    (2.5, 0.999_048_221_581_857_8, 0.043_619_387_365_336),
    (5.0, 0.996_194_698_091_745_5, 0.087_155_742_747_658_17),
    (7.5, 0.991_444_861_373_810_4, 0.130_526_192_220_051_57),
    (10.0, 0.984_807_753_012_208, 0.173_648_177_666_930_33),
    (15.0, 0.965_925_826_289_068_3, 0.258_819_045_102_520_74),
    (17.0, 0.956_304_755_963_035_4, 0.292_371_704_722_736_77),
    (20.0, 0.939_692_620_785_908_4, 0.342_020_143_325_668_7),
    (22.5, 0.923_879_532_511_286_7, 0.382_683_432_365_089_8),
    (30.0, 0.866_025_403_784_438_7, 0.499_999_999_999_999_94),
    (40.0, 0.766_044_443_118_978, 0.642_787_609_686_539_3),
    (
        45.0,
        std::f64::consts::FRAC_1_SQRT_2,
        0.707_106_781_186_547_5,
    ),
    (60.0, 0.500_000_000_000_000_1, 0.866_025_403_784_438_6),
    (90.0, 0.0, 1.0),
];

/// `p` rotated by `degrees` (one of [`ROTATIONS`], or its negative).
fn rotate(degrees: f64, p: DVec2) -> DVec2 {
    let (c, s) = ROTATIONS
        .iter()
        .find(|(d, _, _)| *d == degrees.abs())
        .map_or((1.0, 0.0), |&(_, c, s)| (c, s.copysign(degrees)));
    DVec2::new(c * p.x - s * p.y, s * p.x + c * p.y)
}

fn v(x: f64, y: f64) -> DVec2 {
    DVec2::new(x, y)
}

/// A scene in local units, before it is scaled and moved.
#[derive(Default)]
struct Local {
    segments: Vec<(DVec2, DVec2, f64)>,
    circles: Vec<(DVec2, f64, f64)>,
    balls: Vec<(DVec2, DVec2, f64, f64)>,
}

/// The shared choices of one motif: where, how bouncy, the balls' radius and a small speed.
struct Place {
    x: f64,
    y: f64,
    width: f64,
    height: f64,
    radius: f64,
    wall_e: f64,
    ball_e: f64,
    small: f64,
}

const RESTITUTIONS: [f64; 5] = [1.0, 0.9, 0.8, 0.5, 0.0];

/// A scene from `source` (see the module documentation).
pub fn generate<S: Source>(source: &mut S, options: Options) -> Generated {
    let restitution = |source: &mut S| {
        if options.elastic {
            1.0
        } else {
            source.pick(&RESTITUTIONS)
        }
    };
    let mut local = Local::default();
    let width = source.pick(&[4.0, 5.0, 8.0, 10.0]);
    let height = source.pick(&[4.0, 6.0, 10.0]);
    let box_e = restitution(source);
    let corners = [v(0.0, 0.0), v(width, 0.0), v(width, height), v(0.0, height)];
    for i in 0..4 {
        local
            .segments
            .push((corners[i], corners[(i + 1) % 4], box_e));
    }
    let radius = source.pick(&[0.1, 0.2, 0.25, 0.5]);
    let mut motifs = Vec::new();
    for _ in 0..1 + source.below(3) {
        let motif = Motif::ALL[source.below(Motif::ALL.len() as u64) as usize];
        motifs.push(motif);
        let place = Place {
            x: source.pick(&[1.0, 2.0, width / 2.0, width - 1.0, 1.5]),
            y: source.pick(&[1.0, 2.0, height / 2.0, 1.5]),
            width,
            height,
            radius,
            wall_e: restitution(source),
            ball_e: restitution(source),
            small: source.pick(&[0.0, 0.0, 0.1, -0.1, 0.01, 1.0, -1.0]),
        };
        add_motif(&mut local, motif, &place, source);
    }
    for _ in 0..source.below(3) {
        let p = v(
            0.5 + source.unit() * (width - 1.0),
            0.5 + source.unit() * (height - 1.0),
        );
        let vel = v(source.unit() * 4.0 - 2.0, source.unit() * 4.0 - 2.0);
        let e = restitution(source);
        local.balls.push((p, vel, radius, e));
    }
    local.balls.truncate(12);
    let gravity = if options.gravity {
        match source.below(10) {
            0 => v(0.0, 0.0),
            1 => v(3.0, -8.0),
            2 => v(0.0, -1.0),
            _ => v(0.0, -9.81),
        }
    } else {
        DVec2::ZERO
    };
    let ball_ball = source.chance(0.6);
    let scale = source.pick(&[1e-6, 1e-3, 0.1, 1.0, 1.0, 1.0, 1.0, 10.0, 1e3, 1e6]);
    let offset = source.pick(&[0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 1e3, 1e6, 1e9]);
    let scene = place_scene(
        &local,
        gravity * scale,
        ball_ball,
        scale,
        offset,
        (width, height),
    );
    let bounds = (
        v(offset, offset),
        v(offset + scale * width, offset + scale * height),
    );
    Generated {
        scene,
        motifs,
        scale,
        offset,
        bounds,
    }
}

/// The scene of `local`, scaled by `scale` and moved by `offset`, with only the balls that
/// fit: inside the box, and clear (to the engine's placement tolerance) of what was placed
/// before them.
fn place_scene(
    local: &Local,
    gravity: DVec2,
    ball_ball: bool,
    scale: f64,
    offset: f64,
    (width, height): (f64, f64),
) -> Scene {
    let place = |p: DVec2| [offset + scale * p.x, offset + scale * p.y];
    let mut scene = Scene {
        gravity: [gravity.x, gravity.y],
        ball_ball,
        // The engine as it ships: balls at rest fall asleep.
        sleep: true,
        ..Scene::default()
    };
    for &(a, b, e) in &local.segments {
        let (a, b) = (place(a), place(b));
        if a != b {
            scene.segments.push(SceneSegment {
                a,
                b,
                restitution: e,
                friction: 0.0,
                tangential_restitution: 0.0,
                rolling_resistance: 0.0,
            });
        }
    }
    for &(c, r, e) in &local.circles {
        scene.circles.push(SceneCircle {
            center: place(c),
            radius: r * scale,
            restitution: e,
            friction: 0.0,
            tangential_restitution: 0.0,
            rolling_resistance: 0.0,
        });
    }
    let mut world = World::with_gravity(gravity).unwrap_or_default();
    for s in &scene.segments {
        let _ = world.add_collider(ColliderDesc::segment(DVec2::from(s.a), DVec2::from(s.b)));
    }
    for c in &scene.circles {
        let _ = world.add_collider(ColliderDesc::circle(DVec2::from(c.center), c.radius));
    }
    let groups = if ball_ball {
        CollisionGroups::ALL
    } else {
        CollisionGroups::new(1, !1)
    };
    for &(p, vel, r, e) in &local.balls {
        let inside = p.x - r >= -1e-12
            && p.x + r <= width + 1e-12
            && p.y - r >= -1e-12
            && p.y + r <= height + 1e-12;
        let pos = place(p);
        let desc = BallDesc::new(DVec2::from(pos), r * scale).groups(groups);
        if inside && world.add_ball(desc).is_ok() {
            scene.balls.push(SceneBall {
                id: scene.balls.len() as u64,
                pos,
                vel: [vel.x * scale, vel.y * scale],
                radius: r * scale,
                mass: 1.0,
                restitution: e,
                spin: 0.0,
                inertia: 0.5,
                friction: 0.0,
                tangential_restitution: 0.0,
                rolling_resistance: 0.0,
                roll: [0.0, 0.0],
            });
        }
    }
    scene
}

fn add_motif(local: &mut Local, motif: Motif, place: &Place, source: &mut impl Source) {
    match motif {
        Motif::Channel => channel(local, place, source),
        Motif::PegWall => peg_wall(local, place, source),
        Motif::PegPeg => peg_peg(local, place, source),
        Motif::Wedge => wedge(local, place, source),
        Motif::Touching => touching(local, place, source),
        Motif::Stack => stack(local, place, source),
        Motif::CornerShot => corner_shot(local, place, source),
        Motif::Funnel => funnel(local, place, source),
        Motif::Collinear => collinear(local, place, source),
        Motif::Polyline => polyline(local, place, source),
        Motif::BoxFit => box_fit(local, place, source),
    }
}

fn channel(local: &mut Local, p: &Place, source: &mut impl Source) {
    let angle = source.pick(&[0.0, 0.0, 90.0, 30.0, 45.0, 17.0, 60.0, 1.0]);
    let length = source.pick(&[1.0, 2.0, 3.0]);
    let c = v(p.x, p.y);
    for side in [-1.0, 1.0] {
        let (a, b) = (v(side * p.radius, -length), v(side * p.radius, length));
        local
            .segments
            .push((c + rotate(angle, a), c + rotate(angle, b), p.wall_e));
    }
    for i in 0..1 + source.below(3) {
        let along = length * 0.5 - i as f64 * 2.0 * p.radius;
        let velocity = rotate(angle, v(p.small, 0.0));
        local.balls.push((
            c + rotate(angle, v(0.0, along)),
            velocity,
            p.radius,
            p.ball_e,
        ));
    }
}

fn peg_wall(local: &mut Local, p: &Place, source: &mut impl Source) {
    let peg = source.pick(&[0.1, 0.2, 0.5, p.radius]);
    let wall = source.pick(&[0.0, 1.0]);
    if wall != 0.0 {
        local
            .segments
            .push((v(wall, 0.0), v(wall, p.height * 0.7), p.wall_e));
    }
    let y = source.pick(&[1.0, 1.5, 2.0]);
    let gap = 2.0 * p.radius * source.pick(&[1.0, 1.0, 1.0 - 1e-9, 1.0 + 1e-12]);
    local.circles.push((v(wall + gap + peg, y), peg, p.wall_e));
    let x = wall + p.radius + source.pick(&[0.0, 0.0, 0.05, p.radius]);
    let above = source.pick(&[1.0, 0.5, 2.0 * p.radius]);
    local
        .balls
        .push((v(x, y + above), v(p.small, 0.0), p.radius, p.ball_e));
}

fn peg_peg(local: &mut Local, p: &Place, source: &mut impl Source) {
    let peg = source.pick(&[0.1, 0.2, 0.5, p.radius]);
    let y = source.pick(&[1.0, 1.5, 2.0]);
    let gap = 2.0 * p.radius * source.pick(&[1.0, 1.0, 0.9, 1.0 + 1e-12]);
    let dy = source.pick(&[0.0, 0.0, 0.1, p.radius]);
    local.circles.push((v(p.x, y), peg, p.wall_e));
    local
        .circles
        .push((v(p.x + 2.0 * peg + gap, y + dy), peg, p.wall_e));
    let middle = p.x + peg + 0.5 * gap + source.pick(&[0.0, 0.0, 0.01, 0.1]);
    let above = source.pick(&[1.0, 0.7, 2.0]);
    local
        .balls
        .push((v(middle, y + above), v(p.small, 0.0), p.radius, p.ball_e));
}

fn wedge(local: &mut Local, p: &Place, source: &mut impl Source) {
    // Half-angles of V-wedges of 1 to 90 degrees.
    let half = source.pick(&[0.5, 1.0, 2.5, 5.0, 7.5, 15.0, 22.5, 30.0, 45.0]);
    let tilt = source.pick(&[0.0, 0.0, 10.0, -20.0, 45.0]);
    let apex = v(p.x, source.pick(&[0.0, 0.5, 1.0]));
    let length = source.pick(&[2.0, 3.0]);
    for side in [-1.0, 1.0] {
        let arm = rotate(side * half, v(0.0, length));
        local
            .segments
            .push((apex, apex + rotate(tilt, arm), p.wall_e));
    }
    for i in 0..1 + source.below(2) {
        let y = 0.8 * length - i as f64 * 2.5 * p.radius;
        let x = source.pick(&[0.0, 0.0, 0.01, 0.05]);
        local.balls.push((
            apex + rotate(tilt, v(x, y)),
            v(p.small, 0.0),
            p.radius,
            p.ball_e,
        ));
    }
}

fn touching(local: &mut Local, p: &Place, source: &mut impl Source) {
    let r = p.radius;
    for i in 0..1 + source.below(4) {
        let x = source.pick(&[r, 3.0 * r, p.x]) + 2.0 * r * i as f64;
        let speed = source.pick(&[0.0, 0.0, 1.0, -1.0, 0.1]);
        local.balls.push((v(x, r), v(speed, 0.0), r, p.ball_e));
    }
    if source.chance(0.5) {
        let peg = source.pick(&[0.2, 0.5]);
        let c = v(p.x, p.y);
        local.circles.push((c, peg, p.wall_e));
        let angle = source.pick(&[90.0, 45.0, 0.0, 30.0]);
        local
            .balls
            .push((c + rotate(angle, v(peg + r, 0.0)), DVec2::ZERO, r, p.ball_e));
    }
}

fn stack(local: &mut Local, p: &Place, source: &mut impl Source) {
    let r = p.radius;
    let x = source.pick(&[p.x, r, p.width - r]);
    let lean = source.pick(&[0.0, 0.0, r * 0.5, 1e-9]);
    for i in 0..2 + source.below(4) {
        let shift = if i % 2 == 1 { lean } else { 0.0 };
        local.balls.push((
            v(x + shift, r + 2.0 * r * i as f64),
            DVec2::ZERO,
            r,
            p.ball_e,
        ));
    }
    if source.chance(0.4) {
        // A triangle: two on the floor touching, one on top of both.
        let x0 = p.x;
        local.balls.push((v(x0, r), DVec2::ZERO, r, p.ball_e));
        local
            .balls
            .push((v(x0 + 2.0 * r, r), DVec2::ZERO, r, p.ball_e));
        let top = v(x0 + r, r + 3f64.sqrt() * r);
        local.balls.push((top, DVec2::ZERO, r, p.ball_e));
    }
}

fn corner_shot(local: &mut Local, p: &Place, source: &mut impl Source) {
    let a = v(p.x, p.y);
    let b = a + rotate(source.pick(&[0.0, 90.0, 45.0, 30.0]), v(1.0, 0.0));
    local.segments.push((a, b, p.wall_e));
    let target = match source.below(3) {
        0 => a,
        1 => b,
        _ => DVec2::ZERO,
    };
    let from = v(
        source.pick(&[0.5, p.width - 0.5, p.x + 1.0]),
        source.pick(&[p.height - 0.5, 0.5 + p.radius, p.y + 1.0]),
    );
    let speed = source.pick(&[1.0, 10.0, 100.0]);
    let direction = (target - from).normalize_or_zero();
    local
        .balls
        .push((from, direction * speed, p.radius, p.ball_e));
}

fn funnel(local: &mut Local, p: &Place, source: &mut impl Source) {
    let spout = 2.0 * p.radius * source.pick(&[1.0, 1.0, 0.5, 1.0 + 1e-12]);
    let y0 = source.pick(&[1.0, 1.5]);
    let top = y0 + source.pick(&[1.0, 1.5]);
    let spread = source.pick(&[1.0, 0.5, 1.5]);
    let (left, right) = (p.x - 0.5 * spout, p.x + 0.5 * spout);
    local
        .segments
        .push((v(left, y0), v(left - spread, top), p.wall_e));
    local
        .segments
        .push((v(right, y0), v(right + spread, top), p.wall_e));
    if source.chance(0.5) {
        // An exact-fit stem under the spout.
        local
            .segments
            .push((v(left, y0), v(left, y0 - 0.5), p.wall_e));
        local
            .segments
            .push((v(right, y0), v(right, y0 - 0.5), p.wall_e));
    }
    for i in 0..1 + source.below(4) {
        let x = p.x + source.pick(&[0.0, 0.1, -0.2, 0.3]);
        let y = top - 0.2 - 2.1 * p.radius * i as f64;
        local
            .balls
            .push((v(x, y), v(p.small, 0.0), p.radius, p.ball_e));
    }
}

fn collinear(local: &mut Local, p: &Place, source: &mut impl Source) {
    let y = source.pick(&[0.0, 1.0]);
    let a = source.pick(&[1.0, 1.5]);
    local.segments.push((v(a, y), v(a + 1.0, y), p.wall_e));
    if y != 0.0 {
        local
            .segments
            .push((v(0.5, y), v(p.width - 0.5, y), p.wall_e));
    }
    let x = source.pick(&[0.6, a, a + 1.0, a - p.radius]);
    let speed = source.pick(&[0.5, 1.0, 0.0, -0.5]);
    local
        .balls
        .push((v(x, y + p.radius), v(speed, 0.0), p.radius, p.ball_e));
}

fn polyline(local: &mut Local, p: &Place, source: &mut impl Source) {
    let y0 = source.pick(&[1.0, 0.5]);
    let dy = source.pick(&[0.5, -0.5, 0.2, 0.0, 1.0]);
    let corners = [v(p.x - 1.0, y0 + dy), v(p.x, y0), v(p.x + 1.0, y0 + dy)];
    local.segments.push((corners[0], corners[1], p.wall_e));
    local.segments.push((corners[1], corners[2], p.wall_e));
    if source.chance(0.3) {
        // A post down from the joint.
        let post = (corners[1], corners[1] + v(0.0, -0.5), p.wall_e);
        local.segments.push(post);
    }
    let x = source.pick(&[0.0, 0.1, 0.5]);
    local
        .balls
        .push((corners[0] + v(x, 1.0), v(p.small, 0.0), p.radius, p.ball_e));
}

fn box_fit(local: &mut Local, p: &Place, source: &mut impl Source) {
    let k = source.pick(&[1.0, 2.0, 3.0]);
    let inner = 2.0 * p.radius * k;
    let x0 = p.x.min(p.width - inner - 0.1).max(0.1);
    let y0 = source.pick(&[0.0, 0.5]);
    local
        .segments
        .push((v(x0, y0), v(x0 + inner, y0), p.wall_e));
    local.segments.push((v(x0, y0), v(x0, y0 + 2.0), p.wall_e));
    local
        .segments
        .push((v(x0 + inner, y0), v(x0 + inner, y0 + 2.0), p.wall_e));
    let vy = source.pick(&[0.0, -1.0, 1.0]);
    for i in 0..k as usize {
        let x = x0 + p.radius + 2.0 * p.radius * i as f64;
        let vx = p.small * (i as f64 - 0.5);
        local
            .balls
            .push((v(x, y0 + 1.0), v(vx, vy), p.radius, p.ball_e));
    }
}

/// Mixed into a seed for its roughness (`exact2d-hunt --rough`), so that the rough scene keeps
/// the seed's geometry.
pub const ROUGH_SEED: u64 = 0x5eed_f00d_0000_0019;

/// Mixed into a seed for its table (`exact2d-hunt --table`), so that the table keeps the
/// seed's geometry.
pub const TABLE_SEED: u64 = 0x5eed_7ab1_e000_0019;

/// Makes `scene` rough, its geometry unchanged: from `source`, each ball gets Coulomb friction
/// (none a quarter of the time, else 0.2, 0.5 or 1.5), a tangential restitution (-1, 0, 0.5 or
/// 1), a rolling resistance (none half the time, else 0.01 or 0.1) and a spin of up to twenty
/// times its speed scale over its radius either way; each segment and circle a friction and a
/// tangential restitution from the same sets. `exact2d-hunt --rough` runs every seed's scene
/// so: the same exact fits, wedges and touching placements, now with friction at their
/// impacts and balls sliding and rolling on their surfaces.
pub fn roughen(scene: &mut Scene, source: &mut impl Source) {
    let material = |source: &mut dyn FnMut() -> u64| {
        let pick = |x: u64, items: &[f64]| items[(x % items.len() as u64) as usize];
        (
            pick(source(), &[0.0, 0.2, 0.5, 1.5]),
            pick(source(), &[-1.0, 0.0, 0.5, 1.0]),
            pick(source(), &[0.0, 0.0, 0.01, 0.1]),
        )
    };
    let mut next = || source.next_u64();
    for s in &mut scene.segments {
        (s.friction, s.tangential_restitution, s.rolling_resistance) = material(&mut next);
    }
    for c in &mut scene.circles {
        (c.friction, c.tangential_restitution, c.rolling_resistance) = material(&mut next);
    }
    for b in &mut scene.balls {
        (b.friction, b.tangential_restitution, b.rolling_resistance) = material(&mut next);
        let speed = b.vel[0].abs().max(b.vel[1].abs()).max(b.radius);
        let turn = (next() >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0;
        b.spin = 20.0 * turn * speed / b.radius;
    }
}

/// Makes `scene` a table seen from above, its geometry unchanged: gravity goes into the
/// table (its magnitude, or `9.81 * scale` without one), the cloth gets a sliding friction
/// (none, 0.2 or 1), a rolling friction (none, 0.01 or 0.2) and a spinning friction (none,
/// 0.01 or 0.5) from `source`, and each ball a roll of up to twenty times its speed scale over
/// its radius about each horizontal axis, and a moment of inertia of a sphere (2/5) half the
/// time. `exact2d-hunt --table` runs every seed's scene so (with `--rough` too, friction at
/// the impacts as well): the same exact fits, wedges and touching placements, with balls
/// sliding, rolling and spinning to rest on the cloth and driven into cushions by it.
pub fn lay_on_table(scene: &mut Scene, scale: f64, source: &mut impl Source) {
    let mut next = || source.next_u64();
    let pick = |x: u64, items: &[f64]| items[(x % items.len() as u64) as usize];
    let g = DVec2::from(scene.gravity).length();
    let gravity = if g > 0.0 { g } else { 9.81 * scale };
    scene.gravity = [0.0, 0.0];
    scene.table = Some(SceneTable {
        gravity,
        sliding_friction: pick(next(), &[0.0, 0.2, 1.0]),
        rolling_friction: pick(next(), &[0.0, 0.01, 0.2]),
        spinning_friction: pick(next(), &[0.0, 0.01, 0.5]),
    });
    for b in &mut scene.balls {
        let speed = b.vel[0].abs().max(b.vel[1].abs()).max(b.radius);
        let mut turn = || (next() >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0;
        let roll = [turn(), turn()];
        b.roll = roll.map(|t| 20.0 * t * speed / b.radius);
        if next() % 2 == 0 {
            b.inertia = 0.4;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::source::SplitMix64;

    #[test]
    fn a_table_scene_keeps_its_geometry_and_is_valid() {
        for seed in 0..200 {
            let plain = generate(&mut SplitMix64(seed), Options::default());
            let mut table = plain.clone();
            lay_on_table(&mut table.scene, table.scale, &mut SplitMix64(seed ^ 91));
            assert_eq!(table.scene.segments, plain.scene.segments);
            assert_eq!(table.scene.gravity, [0.0, 0.0]);
            assert!(table.scene.table.is_some_and(|t| t.gravity > 0.0));
            table.scene.validate().unwrap();
        }
    }

    #[test]
    fn the_rotation_table_is_right_to_an_ulp() {
        for &(d, c, s) in &ROTATIONS {
            let a = d.to_radians();
            assert!((c - a.cos()).abs() <= 2.0 * f64::EPSILON, "{d}");
            assert!((s - a.sin()).abs() <= 2.0 * f64::EPSILON, "{d}");
        }
        assert_eq!(
            rotate(-30.0, v(1.0, 0.0)),
            v(ROTATIONS[12].1, -0.499_999_999_999_999_94)
        );
    }

    #[test]
    fn a_seed_names_one_scene_and_every_motif_comes_up() {
        let a = generate(&mut SplitMix64(7), Options::default());
        let b = generate(&mut SplitMix64(7), Options::default());
        assert_eq!(a.scene, b.scene);
        let mut seen = std::collections::BTreeSet::new();
        let (mut scales, mut offsets) = (Vec::new(), Vec::new());
        for seed in 0..300 {
            let g = generate(&mut SplitMix64(seed), Options::default());
            seen.extend(g.motifs.iter().copied());
            scales.push(g.scale);
            offsets.push(g.offset);
            assert!(g.scene.validate().is_ok(), "seed {seed}");
        }
        assert_eq!(seen.len(), Motif::ALL.len());
        assert!(scales.contains(&1e-6) && scales.contains(&1e6));
        assert!(offsets.contains(&1e9));
    }

    #[test]
    fn elastic_scenes_without_gravity_keep_every_restitution_at_one() {
        let options = Options {
            gravity: false,
            elastic: true,
        };
        for seed in 0..50 {
            let g = generate(&mut SplitMix64(seed), options);
            assert_eq!(g.scene.gravity, [0.0, 0.0]);
            assert!(g.scene.balls.iter().all(|b| b.restitution == 1.0));
            assert!(g.scene.segments.iter().all(|s| s.restitution == 1.0));
        }
    }

    #[test]
    fn a_rough_scene_keeps_its_geometry_and_is_valid() {
        for seed in 0..200 {
            let plain = generate(&mut SplitMix64(seed), Options::default());
            let mut rough = generate(&mut SplitMix64(seed), Options::default());
            roughen(&mut rough.scene, &mut SplitMix64(seed ^ 77));
            assert_eq!(rough.scene.segments.len(), plain.scene.segments.len());
            for (r, p) in rough.scene.balls.iter().zip(&plain.scene.balls) {
                assert_eq!((r.pos, r.vel, r.radius), (p.pos, p.vel, p.radius));
            }
            rough.scene.validate().unwrap();
            assert!(rough.scene.balls.is_empty() || rough.scene.is_rough());
        }
    }
}
