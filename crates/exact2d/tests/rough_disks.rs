//! Rough disks: friction at impacts (`dynamics/rough.rs`), checked against independent answers:
//! the model evaluated in exact rational arithmetic, conservation laws, the kinetic theory of
//! rough disks' homogeneous cooling state, and closed-form bounces.

mod common;

use common::SplitMix;
use exact2d::{
    BallDesc, BallHandle, ColliderDesc, DVec2, Event, Roughness, SpinningBody, World,
    apply_friction, friction_impulse,
};
use num_rational::BigRational;
use num_traits::{Signed, ToPrimitive, Zero};

// ----------------------------------------------------------------------------------------
// The impulse against exact rational arithmetic.

fn q(x: f64) -> BigRational {
    BigRational::from_float(x).expect("finite")
}

/// A body in rationals: velocity, spin, mass, inertia factor, radius.
#[derive(Clone)]
struct Exact {
    v: [BigRational; 2],
    w: BigRational,
    m: BigRational,
    k: BigRational,
    r: BigRational,
}

impl Exact {
    fn of(b: &SpinningBody) -> Self {
        Exact {
            v: [q(b.velocity.x), q(b.velocity.y)],
            w: q(b.spin),
            m: q(b.mass),
            k: q(b.inertia),
            r: q(b.radius),
        }
    }

    /// Takes the impulse `j` (a vector) at the point `arm` from its centre.
    fn kick(&self, j: &[BigRational; 2], arm: &[BigRational; 2]) -> Exact {
        let inertia = &self.k * &self.m * &self.r * &self.r;
        let torque = &arm[0] * &j[1] - &arm[1] * &j[0];
        Exact {
            v: [&self.v[0] + &j[0] / &self.m, &self.v[1] + &j[1] / &self.m],
            w: &self.w + torque / inertia,
            ..self.clone()
        }
    }

    /// The velocity of its material point at `arm` from its centre.
    fn point_velocity(&self, arm: &[BigRational; 2]) -> [BigRational; 2] {
        [
            &self.v[0] - &self.w * &arm[1],
            &self.v[1] + &self.w * &arm[0],
        ]
    }
}

/// The model, from its definition: the contact points' relative velocity along `t`, the
/// change one unit of tangential impulse makes to it (found by applying it), the sticking
/// impulse `(1 + beta) g_t / K`, capped by `mu P`. Returns both bodies after the impulse.
fn exact_friction(
    a: &Exact,
    b: Option<&Exact>,
    n: [f64; 2],
    normal_impulse: f64,
    mu: f64,
    beta: f64,
) -> (Exact, Option<Exact>) {
    let n = [q(n[0]), q(n[1])];
    let t = [-n[1].clone(), n[0].clone()];
    let arm_a = [&a.r * &n[0], &a.r * &n[1]];
    let arm_b = b.map(|b| [-(&b.r * &n[0]), -(&b.r * &n[1])]);
    let slip = |a: &Exact, b: Option<&Exact>| {
        let pa = a.point_velocity(&arm_a);
        let pb = match (b, &arm_b) {
            (Some(b), Some(arm)) => b.point_velocity(arm),
            _ => [BigRational::zero(), BigRational::zero()],
        };
        (&pa[0] - &pb[0]) * &t[0] + (&pa[1] - &pb[1]) * &t[1]
    };
    let g = slip(a, b);
    // One unit of impulse along t on b, minus on a.
    let unit_on = |s: &BigRational| [&t[0] * s, &t[1] * s];
    let one = BigRational::from_integer(1.into());
    let minus = -one.clone();
    let a1 = a.kick(&unit_on(&minus), &arm_a);
    let b1 = b.map(|b| b.kick(&unit_on(&one), arm_b.as_ref().unwrap()));
    let stiffness = &g - slip(&a1, b1.as_ref());
    let stick = (q(1.0) + q(beta)) * g.abs() / &stiffness;
    let cap = q(mu) * q(normal_impulse);
    let magnitude = if stick <= cap { stick } else { cap };
    let j = if g.is_negative() {
        -magnitude
    } else {
        magnitude
    };
    let a2 = a.kick(&unit_on(&(-j.clone())), &arm_a);
    let b2 = b.map(|b| b.kick(&unit_on(&j), arm_b.as_ref().unwrap()));
    (a2, b2)
}

fn close(x: f64, exact: &BigRational, scale: f64) -> bool {
    (x - exact.to_f64().unwrap()).abs() <= 1e-14 * scale
}

#[test]
fn the_friction_impulse_agrees_with_an_exact_rational_evaluation() {
    let mut rng = SplitMix(19);
    let (mut sticking, mut sliding) = (0, 0);
    for case in 0..2000 {
        let body = |rng: &mut SplitMix| SpinningBody {
            velocity: DVec2::new(rng.range(-3.0, 3.0), rng.range(-3.0, 3.0)),
            spin: rng.range(-20.0, 20.0),
            mass: rng.range(0.1, 10.0),
            inertia: rng.range(0.2, 1.0),
            radius: rng.range(0.05, 2.0),
        };
        let a = body(&mut rng);
        let b = body(&mut rng);
        let angle = rng.range(-3.2, 3.2);
        let n = DVec2::new(angle.cos(), angle.sin());
        let normal_impulse = rng.range(0.0, 5.0);
        let mu = if case % 5 == 0 {
            0.0
        } else {
            rng.range(0.0, 2.0)
        };
        let beta = rng.range(-1.0, 1.0);
        let roughness = Roughness {
            friction: mu,
            tangential_restitution: beta,
            ..Roughness::SMOOTH
        };
        let against_wall = case % 3 == 0;
        let other = (!against_wall).then_some(&b);
        let j = friction_impulse(&a, other, n, normal_impulse, roughness);
        let (a2, b2) = apply_friction(&a, other, n, j);
        let (ea, eb) = (Exact::of(&a), Exact::of(&b));
        let (xa, xb) = exact_friction(
            &ea,
            (!against_wall).then_some(&eb),
            n.to_array(),
            normal_impulse,
            mu,
            beta,
        );
        let scale = [&a, &b]
            .iter()
            .map(|b| b.velocity.length() + (b.spin * b.radius).abs())
            .fold(0.0, f64::max);
        let check = |body: &SpinningBody, exact: &Exact| {
            close(body.velocity.x, &exact.v[0], scale)
                && close(body.velocity.y, &exact.v[1], scale)
                && close(body.spin * body.radius, &(&exact.w * &exact.r), scale)
        };
        assert!(check(&a2, &xa), "case {case}: {a2:?}");
        if let (Some(b2), Some(xb)) = (b2, xb) {
            assert!(check(&b2, &xb), "case {case}: {b2:?}");
        }
        if mu > 0.0 {
            if (j.abs() - mu * normal_impulse).abs() <= 1e-12 * mu * normal_impulse {
                sliding += 1;
            } else {
                sticking += 1;
            }
        }
    }
    // Both regimes were exercised.
    assert!(sticking > 300 && sliding > 300, "{sticking} {sliding}");
}

// ----------------------------------------------------------------------------------------
// Conservation: elastic, perfectly rough disks.

/// `n` disks of radius `r` on a jittered lattice in the box `[0, size]^2` (smooth, elastic
/// walls), velocities of temperature `temperature` per degree of freedom, every ball with
/// restitution `e`, friction `mu`, tangential restitution `beta`, spin `spin(rng)`.
fn rough_gas(
    n: usize,
    r: f64,
    size: f64,
    (e, mu, beta): (f64, f64, f64),
    seed: u64,
    spin: impl Fn(&mut SplitMix) -> f64,
) -> (World, Vec<BallHandle>) {
    let mut world = common::boxed(size, DVec2::ZERO);
    let mut rng = SplitMix(seed);
    let side = (n as f64).sqrt().ceil() as usize;
    let spacing = size / side as f64;
    assert!(spacing > 2.0 * r);
    let room = 0.5 * (spacing - 2.0 * r) * 0.9;
    let mut handles = Vec::with_capacity(n);
    for k in 0..n {
        let (i, j) = ((k % side) as f64, (k / side) as f64);
        let p = DVec2::new(
            (i + 0.5) * spacing + rng.range(-room, room),
            (j + 0.5) * spacing + rng.range(-room, room),
        );
        let velocity = DVec2::new(gaussian(&mut rng), gaussian(&mut rng));
        let desc = BallDesc::new(p, r)
            .velocity(velocity)
            .restitution(e)
            .friction(mu)
            .tangential_restitution(beta)
            .spin(spin(&mut rng));
        handles.push(world.add_ball(desc).unwrap());
    }
    (world, handles)
}

/// A standard normal deviate (Box and Muller).
fn gaussian(rng: &mut SplitMix) -> f64 {
    let u = 1.0 - rng.next_f64();
    let v = rng.next_f64();
    (-2.0 * u.ln()).sqrt() * (std::f64::consts::TAU * v).cos()
}

/// Translational and rotational kinetic energy, summed exactly enough (pairwise is plenty
/// for a thousand terms at 1e-12).
fn energies(world: &World) -> (f64, f64) {
    world.balls().fold((0.0, 0.0), |(t, r), (_, b)| {
        let inertia = b.inertia * b.mass * b.radius * b.radius;
        (
            t + 0.5 * b.mass * b.velocity.length_squared(),
            r + 0.5 * inertia * b.spin * b.spin,
        )
    })
}

/// A pair's angular momentum about the origin, and its scale: the sum of the magnitudes of
/// its terms, `m |p| |v|` and `|I w|` (the rounding of `p x v` is relative to `|p| |v|`).
fn angular_momentum(balls: &[(DVec2, DVec2, f64, f64)]) -> (f64, f64) {
    balls
        .iter()
        .fold((0.0, 0.0), |(l, s), &(p, v, spin_momentum, mass)| {
            let orbital = mass * p.perp_dot(v);
            let size = mass * p.length() * v.length();
            (l + orbital + spin_momentum, s + size + spin_momentum.abs())
        })
}

#[test]
fn elastic_perfectly_rough_disks_keep_their_energy_and_angular_momentum() {
    // 400 disks, packing 0.2; every collision between two balls sticks (mu huge) and
    // reverses the contact's tangential motion (beta = 1); the walls are smooth.
    let (n, r) = (400, 0.5);
    let size = (n as f64 * std::f64::consts::PI * r * r / 0.2).sqrt();
    let (mut world, handles) =
        rough_gas(n, r, size, (1.0, 1e12, 1.0), 3, |rng| rng.range(-2.0, 2.0));
    let (t0, r0) = energies(&world);
    let start = t0 + r0;
    // Each ball's velocity and spin as of its last event (nothing changes them in between).
    let mut last: Vec<(DVec2, f64)> = handles
        .iter()
        .map(|&h| {
            let b = world.ball(h).unwrap();
            (b.velocity, b.spin)
        })
        .collect();
    let slot = |h: BallHandle| h.index() as usize;
    let (mut pairs, mut worst) = (0_u64, 0.0_f64);
    let events = 1_000_000;
    for _ in 0..events {
        match world.step().expect("a gas never runs out of events") {
            Event::BallContact(c) => {
                pairs += 1;
                let mut before = Vec::new();
                let mut after = Vec::new();
                for h in [c.a, c.b] {
                    let b = world.ball(h).unwrap();
                    let inertia = b.inertia * b.mass * b.radius * b.radius;
                    let (v, w) = last[slot(h)];
                    before.push((b.position, v, inertia * w, b.mass));
                    after.push((b.position, b.velocity, inertia * b.spin, b.mass));
                    last[slot(h)] = (b.velocity, b.spin);
                }
                let (l0, scale) = angular_momentum(&before);
                let (l1, _) = angular_momentum(&after);
                worst = worst.max((l1 - l0).abs() / scale);
            }
            Event::Contact(c) => {
                let b = world.ball(c.ball).unwrap();
                // Smooth walls: the spin is untouched.
                assert_eq!(b.spin, last[slot(c.ball)].1);
                last[slot(c.ball)] = (b.velocity, b.spin);
            }
            _ => {}
        }
    }
    let (t1, r1) = energies(&world);
    let drift = ((t1 + r1) - start).abs() / start;
    eprintln!(
        "{events} events ({pairs} between balls): energy drift {drift:.2e}, rotational share \
         {:.3} from {:.3}, worst angular momentum change of a pair {worst:.2e}",
        r1 / (t1 + r1),
        r0 / start
    );
    assert!(pairs > 600_000);
    assert!(drift < 1e-12, "energy drift {drift:e}");
    assert!(
        worst < 1e-14,
        "angular momentum changed by {worst:e} of its scale"
    );
    // Energy moved between translation and rotation (the collisions are rough)...
    assert!((r1 / (t1 + r1) - r0 / start).abs() > 0.01);
}

// ----------------------------------------------------------------------------------------
// The homogeneous cooling state of rough inelastic disks.

/// The kinetic theory of the homogeneous cooling state of rough disks (2D) in the
/// molecular-chaos approximation with Maxwellian velocities and spins (Huthmann and
/// Zippelius 1997; Luding, Huthmann, McNamara and Zippelius 1998, whose two-dimensional
/// equations these are; derived afresh in ARCHITECTURE.md, "Spin and friction").
///
/// With `q` the inertia factor and `eta = q (1 + beta) / (2 (1 + q))`, per collision of two
/// balls the translational energy changes on average by `-A T_tr + B T_rot` and the
/// rotational by `B T_tr - C T_rot`, where
/// `A = 1 - e^2 + 2 eta (1 - eta)`, `B = 2 eta^2 / q`, `C = (2 eta / q) (1 - eta / q)`
/// (`T_tr = <m v^2> / 2`, `T_rot = <I w^2>`, per degree of freedom). A smooth, elastic wall
/// takes `(1 - e_wall^2) T_tr` per hit; `walls` is the ratio of wall hits to collisions.
struct Theory {
    a: f64,
    b: f64,
    c: f64,
}

impl Theory {
    fn new(e: f64, beta: f64, q: f64, walls: f64, e_wall: f64) -> Self {
        let eta = q * (1.0 + beta) / (2.0 * (1.0 + q));
        Theory {
            a: 1.0 - e * e + 2.0 * eta * (1.0 - eta) + walls * (1.0 - e_wall * e_wall),
            b: 2.0 * eta * eta / q,
            c: (2.0 * eta / q) * (1.0 - eta / q),
        }
    }

    /// `T_rot / T_tr` in the cooling state: with `E_tr = N T_tr`, `E_rot = N T_rot / 2` and
    /// both decaying at one rate, `B R^2 + (2 C - A) R - 2 B = 0`.
    fn ratio(&self) -> f64 {
        let (a, b, c) = (self.a, self.b, self.c);
        let p = a - 2.0 * c;
        (p + (p * p + 8.0 * b * b).sqrt()) / (2.0 * b)
    }

    /// `-d ln T_tr / d tau`, `tau` the collisions per ball: `(A - B R) / 2`.
    fn decay(&self) -> f64 {
        (self.a - self.b * self.ratio()) / 2.0
    }
}

struct Cooling {
    /// Mean of `T_rot / T_tr` over the window.
    ratio: f64,
    /// `-d ln T_tr / d tau` fitted over the window.
    decay: f64,
    /// Wall hits per collision of two balls, over the window.
    walls: f64,
    /// `(time, T_tr)` over the window.
    samples: Vec<(f64, f64)>,
    /// Enskog's collision rate per ball at the window's start: `2 sigma n chi sqrt(pi T / m)`,
    /// with Henderson's contact value of the pair correlation of hard disks,
    /// `chi = (1 - 7 phi / 16) / (1 - phi)^2`.
    enskog: f64,
}

impl Cooling {
    /// Haff's law at `decay` per collision: the largest relative gap between
    /// `sqrt(T_tr(t0) / T_tr(t))` and `1 + decay nu0 (t - t0) / 2`.
    fn haff(&self, decay: f64) -> f64 {
        let (start, t_start) = self.samples[0];
        self.samples
            .iter()
            .map(|&(time, t)| {
                let law = 1.0 + 0.5 * decay * self.enskog * (time - start);
                ((t_start / t).sqrt() / law - 1.0).abs()
            })
            .fold(0.0, f64::max)
    }
}

/// Cools a gas of `n` rough disks (radius 0.5, unit mass, inertia 1/2, packing `phi`, pair
/// restitution `e`, in a box of smooth walls that a ball meets with restitution `sqrt(e)`)
/// from no spin at all, and measures over `tau` (collisions per ball) in `window`.
fn cool(n: usize, phi: f64, e: f64, beta: f64, seed: u64, window: (f64, f64)) -> Cooling {
    let r = 0.5;
    let size = (n as f64 * std::f64::consts::PI * r * r / phi).sqrt();
    // A pair's restitution is the product of its balls': each ball has sqrt(e).
    let (mut world, _) = rough_gas(n, r, size, (e.sqrt(), 1e12, beta), seed, |_| 0.0);
    let temperatures = |world: &World| {
        let (t, rot) = energies(world);
        (t / n as f64, 2.0 * rot / n as f64)
    };
    let (mut pairs, mut window_pairs, mut window_hits) = (0_u64, 0_u64, 0_u64);
    let mut samples: Vec<(f64, f64, f64, f64)> = Vec::new(); // (tau, time, T_tr, R)
    let mut next_sample = window.0;
    loop {
        let tau = 2.0 * pairs as f64 / n as f64;
        if tau >= next_sample {
            let (t, rot) = temperatures(&world);
            samples.push((tau, world.time(), t, rot / t));
            next_sample += 0.25;
            if tau >= window.1 {
                break;
            }
        }
        let inside = tau >= window.0;
        match world.step().expect("the gas goes on") {
            Event::BallContact(_) => {
                pairs += 1;
                window_pairs += u64::from(inside);
            }
            Event::Contact(_) => window_hits += u64::from(inside),
            _ => {}
        }
    }
    let m = samples.len() as f64;
    let ratio = samples.iter().map(|s| s.3).sum::<f64>() / m;
    // Least squares of ln T_tr against tau.
    let (sx, sy) = samples
        .iter()
        .fold((0.0, 0.0), |(x, y), s| (x + s.0, y + s.2.ln()));
    let (mx, my) = (sx / m, sy / m);
    let (sxy, sxx) = samples.iter().fold((0.0, 0.0), |(a, b), s| {
        (
            a + (s.0 - mx) * (s.2.ln() - my),
            b + (s.0 - mx) * (s.0 - mx),
        )
    });
    let chi = (1.0 - 7.0 * phi / 16.0) / ((1.0 - phi) * (1.0 - phi));
    let density = n as f64 / (size * size);
    let t_start = samples[0].2;
    Cooling {
        ratio,
        decay: -sxy / sxx,
        walls: window_hits as f64 / window_pairs as f64,
        samples: samples.iter().map(|s| (s.1, s.2)).collect(),
        enskog: 2.0 * (2.0 * r) * density * chi * (std::f64::consts::PI * t_start).sqrt(),
    }
}

#[test]
fn rough_disks_cool_homogeneously_as_kinetic_theory_predicts() {
    // 4000 disks at packing 0.05, from no spin: the ratio of rotational to translational
    // temperature tends to the theory's, and the gas cools at its rate (per collision, and in
    // time by Haff's law with Enskog's collision rate). Measured over 15 to 45 collisions a
    // ball (15 to 35 when inelastic, before clusters form): the first 15 let the spins come
    // up (the ratio relaxes at about 0.2 to 0.5 a collision).
    for (e, beta) in [(1.0, -0.5), (1.0, 0.0), (1.0, 0.5), (0.9, 1.0)] {
        let window = if e == 1.0 { (15.0, 45.0) } else { (15.0, 35.0) };
        let measured = cool(4000, 0.05, e, beta, 11, window);
        let theory = Theory::new(e, beta, 0.5, measured.walls, e.sqrt());
        let haff = measured.haff(theory.decay());
        let ratio = measured.ratio / theory.ratio() - 1.0;
        let decay = measured.decay / theory.decay() - 1.0;
        eprintln!(
            "e {e} beta {beta}: T_rot/T_tr {:.4} (theory {:.4}), decay per collision {:.4} \
             (theory {:.4}), wall hits per collision {:.4}, Haff's law within {haff:.3}",
            measured.ratio,
            theory.ratio(),
            measured.decay,
            theory.decay(),
            measured.walls,
        );
        assert!(
            ratio.abs() < 0.06,
            "e {e} beta {beta}: ratio off by {ratio}"
        );
        assert!(
            decay.abs() < 0.04,
            "e {e} beta {beta}: decay off by {decay}"
        );
        assert!(haff < 0.04, "e {e} beta {beta}: Haff's law off by {haff}");
    }
}

#[test]
fn a_spinning_disk_bouncing_off_a_wall_leaves_at_the_angle_the_model_predicts() {
    // A uniform disk (k = 1/2, radius 0.5, unit mass) meets the floor y = 0 at velocity
    // (1, -2) spinning at w: the contact point slips at g = 1 + 0.5 w along +x. Normal:
    // restitution 1, impulse 4. Tangential: K = 1 + 1/k = 3; sticking takes (1 + beta) |g| / 3,
    // capped by mu 4; the velocity along x drops by it, the spin by 2 J (J / (k m r)).
    for (w, mu, beta) in [
        (0.0, 1.0, 0.0),
        (6.0, 1.0, 0.0),
        (-10.0, 0.1, 0.5),
        (4.0, 1.0, 1.0),
    ] {
        let mut world = World::new();
        world
            .add_collider(
                ColliderDesc::segment(DVec2::new(-10.0, 0.0), DVec2::new(10.0, 0.0))
                    .friction(mu)
                    .tangential_restitution(beta),
            )
            .unwrap();
        let ball = world
            .add_ball(
                BallDesc::new(DVec2::new(0.0, 2.5), 0.5)
                    .velocity(DVec2::new(1.0, -2.0))
                    .spin(w)
                    .friction(mu)
                    .tangential_restitution(beta),
            )
            .unwrap();
        let Some(Event::Contact(hit)) = world.step() else {
            panic!("the ball meets the floor");
        };
        assert_eq!(hit.time, 1.0);
        let after = world.ball(ball).unwrap();
        let g = 1.0 + 0.5 * w;
        let j = ((1.0 + beta) * g.abs() / 3.0).min(mu * 4.0) * g.signum();
        let expected = (DVec2::new(1.0 - j, 2.0), w - 4.0 * j);
        // The event carries it: along the normal turned a quarter counter-clockwise, -x.
        assert!((hit.tangential_impulse - j).abs() < 1e-15, "{hit:?}");
        assert!(
            (after.velocity - expected.0).length() < 1e-15
                && (after.spin - expected.1).abs() < 1e-14,
            "w {w}: {:?} {} where {expected:?}",
            after.velocity,
            after.spin
        );
        // The angle it leaves at, against the normal.
        let angle = after.velocity.x.atan2(after.velocity.y);
        let predicted = expected.0.x.atan2(expected.0.y);
        assert!((angle - predicted).abs() < 1e-15);
        // Never more energy.
        let before = 0.5 * 5.0 + 0.5 * 0.5 * 0.25 * w * w;
        assert!(after.kinetic_energy() <= before);
    }
}

#[test]
fn frictionless_balls_keep_their_spin_and_turn_at_it() {
    // Friction on the wall only: the pair's is the geometric mean, 0, so the spin stays.
    let mut world = World::new();
    world
        .add_collider(
            ColliderDesc::segment(DVec2::new(-10.0, 0.0), DVec2::new(10.0, 0.0)).friction(1.0),
        )
        .unwrap();
    let ball = world
        .add_ball(
            BallDesc::new(DVec2::new(0.0, 2.5), 0.5)
                .velocity(DVec2::new(1.0, -2.0))
                .spin(3.0),
        )
        .unwrap();
    world.advance_to(1.5).unwrap();
    let b = world.ball(ball).unwrap();
    assert_eq!((b.velocity, b.spin), (DVec2::new(1.0, 2.0), 3.0));
    assert!((b.angle - (4.5 - std::f64::consts::TAU)).abs() < 1e-15);
    world.set_ball_spin(ball, -1.0).unwrap();
    world.advance_to(2.0).unwrap();
    let b = world.ball(ball).unwrap();
    assert!((b.angle - (4.0 - std::f64::consts::TAU)).abs() < 1e-15);
    assert!(world.set_ball_spin(ball, f64::NAN).is_err());
    // An angle set now turns on at the spin from there.
    world.set_ball_angle(ball, 7.0).unwrap();
    assert_eq!(world.ball(ball).unwrap().angle, 7.0 - std::f64::consts::TAU);
    world.advance_to(2.5).unwrap();
    let b = world.ball(ball).unwrap();
    assert!((b.angle - (6.5 - std::f64::consts::TAU)).abs() < 1e-15);
    assert!(world.set_ball_angle(ball, f64::INFINITY).is_err());
}

#[test]
fn bad_roughness_is_refused_with_its_range() {
    let mut world = World::new();
    let ball = |d: BallDesc| World::new().add_ball(d).unwrap_err().to_string();
    let at = BallDesc::new(DVec2::ZERO, 1.0);
    assert_eq!(
        ball(at.friction(-1.0)),
        "friction must be finite and >= 0 (got -1)"
    );
    assert!(ball(at.friction(f64::INFINITY)).contains(">= 0"));
    assert_eq!(
        ball(at.tangential_restitution(1.5)),
        "tangential restitution must be in [-1, 1] (got 1.5)"
    );
    assert!(ball(at.inertia(0.0)).contains("(0, 1]"));
    assert!(ball(at.inertia(1.5)).contains("(0, 1]"));
    assert!(ball(at.spin(f64::NAN)).contains("spin"));
    let wall = ColliderDesc::segment(DVec2::ZERO, DVec2::X);
    assert!(world.add_collider(wall.friction(f64::NAN)).is_err());
    assert!(
        world
            .add_collider(wall.tangential_restitution(-2.0))
            .is_err()
    );
    assert_eq!(world.collider_count(), 0);
}
