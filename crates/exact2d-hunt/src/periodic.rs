//! Adversarial periodic boxes (`exact2d-hunt --periodic`): what users of a periodic box write
//! and what its edges make hard.
//!
//! A box as small as the engine takes (6.6 radii across) or a few times that, at a scale from
//! 1e-6 to 1e6; balls on the edges themselves (`x = 0`), touching each other through an edge or
//! a corner, in rows that wrap round the box with every ball touching the next, sliding along
//! an edge line, crossing an edge along an axis (so that every crossing is exact), grazing
//! through an edge, tiny and large speeds (1e-9 to 100 box lengths a second), restitution from 1 down to 0, and sometimes a static
//! circle clear of the edges. Balls that would overlap what was placed before them are left
//! out, so every scene is valid. [`check`](crate::check) measures pairs through their nearest
//! images and holds every ball in the box.

use exact2d::DVec2;
use exact2d::scene::{Scene, SceneBall, SceneCircle};

use crate::generate::Generated;
use crate::source::Source;

fn v(x: f64, y: f64) -> DVec2 {
    DVec2::new(x, y)
}

/// A periodic scene from `source`.
pub fn generate_periodic<S: Source>(source: &mut S) -> Generated {
    let scale = source.pick(&[1e-6, 1e-3, 1.0, 1.0, 1.0, 1e3, 1e6]);
    let r = source.pick(&[0.1, 0.25, 0.5]);
    // The smallest box the engine takes is 6.6 radii across (three cells of 2.2).
    let side = |source: &mut S| {
        let k: f64 = source.pick(&[6.6, 6.6, 8.0, 10.0, 13.2, 20.0]);
        k * r
    };
    let (w, h) = (side(source), side(source));
    let e = |source: &mut S| source.pick(&[1.0, 1.0, 0.9, 0.5, 0.0]);
    let speed = |source: &mut S| source.pick(&[1.0, 1.0, 2.5, 1e-9, 100.0]);
    let direction = |source: &mut S| -> DVec2 {
        match source.below(6) {
            0 => v(1.0, 0.0),
            1 => v(-1.0, 0.0),
            2 => v(0.0, 1.0),
            3 => v(0.0, -1.0),
            4 => v(1.0, 1.0),
            _ => v(source.unit() * 2.0 - 1.0, source.unit() * 2.0 - 1.0),
        }
    };
    let mut balls: Vec<(DVec2, DVec2, f64)> = Vec::new();
    for _ in 0..1 + source.below(3) {
        let y = source.pick(&[0.0, r, 0.5 * h, h - r]);
        let x = source.pick(&[0.0, r, 0.5 * w, w - r]);
        match source.below(6) {
            // Two balls touching through the left and right edges.
            0 => {
                let u = direction(source) * speed(source);
                balls.push((v(0.0, y), u, e(source)));
                balls.push((v(w - 2.0 * r, y), -u, e(source)));
            }
            // A row wrapping round the box, each ball touching the next.
            1 => {
                let start = w - r;
                let u = direction(source) * speed(source);
                for k in 0..(w / (2.0 * r)).floor() as usize {
                    let px = (start + 2.0 * r * k as f64) % w;
                    let push = if k == 0 { u } else { DVec2::ZERO };
                    balls.push((v(px, y), push, e(source)));
                }
            }
            // Touching through a corner.
            2 => {
                let d = 2.0 * r / 2f64.sqrt();
                balls.push((v(0.0, 0.0), direction(source) * speed(source), e(source)));
                balls.push((
                    v(w - d, h - d),
                    direction(source) * speed(source),
                    e(source),
                ));
            }
            // Sliding along an edge line, and one crossing it along an axis.
            3 => {
                balls.push((v(x, 0.0), v(speed(source), 0.0), e(source)));
                balls.push((v(0.0, y), v(0.0, -speed(source)), e(source)));
            }
            // Two balls grazing through an edge: paths exactly a diameter apart.
            4 => {
                let s = speed(source);
                balls.push((v(w - r, y), v(s, 0.0), e(source)));
                balls.push((v(r, (y + 2.0 * r) % h), v(-s, 0.0), e(source)));
            }
            // Anywhere.
            _ => {
                for _ in 0..1 + source.below(4) {
                    let p = v(source.unit() * w, source.unit() * h);
                    balls.push((p, direction(source) * speed(source), e(source)));
                }
            }
        }
    }
    let mut circles = Vec::new();
    if source.chance(0.25) {
        let c = v(0.5 * w, 0.5 * h);
        let radius = source.pick(&[0.5, 1.0]) * r;
        // Clear of the edges by more than a radius: the box is at least 6.6 radii across.
        circles.push(SceneCircle {
            center: [c.x * scale, c.y * scale],
            radius: radius * scale,
            restitution: e(source),
            friction: 0.0,
            tangential_restitution: 0.0,
            rolling_resistance: 0.0,
        });
    }
    let size = v(w, h) * scale;
    // The box takes radii up to its shorter side / 6.6 as the engine computes it.
    let mut radius = r * scale;
    while radius > size.min_element() / (3.0 * 2.2) {
        radius = f64::from_bits(radius.to_bits() - 1);
    }
    let mut scene = Scene {
        ball_ball: true,
        circles,
        periodic: Some([size.x, size.y]),
        ..Scene::default()
    };
    for (p, u, restitution) in balls {
        let p = p * scale;
        let pos = [wrap(p.x, size.x), wrap(p.y, size.y)];
        let ball = SceneBall {
            id: scene.balls.len() as u64,
            pos,
            vel: [u.x * scale, u.y * scale],
            radius,
            mass: 1.0,
            restitution,
            spin: 0.0,
            inertia: 0.5,
            friction: 0.0,
            tangential_restitution: 0.0,
            rolling_resistance: 0.0,
            roll: [0.0, 0.0],
        };
        scene.balls.push(ball);
        if scene.validate().is_err() {
            scene.balls.pop();
        }
    }
    Generated {
        scene,
        motifs: Vec::new(),
        scale,
        offset: 0.0,
        bounds: (DVec2::ZERO, size),
    }
}

/// `x` brought into `[0, l)`.
fn wrap(x: f64, l: f64) -> f64 {
    let y = x.rem_euclid(l);
    if y < l { y } else { 0.0 }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::run::{Limits, run};
    use crate::source::SplitMix64;

    #[test]
    fn periodic_scenes_are_valid_and_keep_every_invariant() {
        let mut wrapped = 0;
        for seed in 0..300 {
            let generated = generate_periodic(&mut SplitMix64(seed));
            generated.scene.validate().unwrap();
            assert!(!generated.scene.balls.is_empty(), "seed {seed}");
            let outcome = run(
                &generated,
                Limits {
                    until: 2.0,
                    events: 3000,
                    collapse: 0.0,
                },
            );
            assert_eq!(outcome.finding, None, "seed {seed}");
            wrapped += u64::from(outcome.events > 0);
        }
        assert!(wrapped > 100, "{wrapped} scenes had events");
    }
}
