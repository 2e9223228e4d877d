//! The generator itself: it covers every motif, a seed (or a byte string) names one scene,
//! and every scene is one the engine accepts.

use std::collections::BTreeSet;

use exact2d::scene::Scene;
use exact2d_hunt::generate::{Motif, Options, generate};
use exact2d_hunt::source::{Bytes, SplitMix64};

/// The seeds these tests look at.
const SEEDS: std::ops::Range<u64> = 0..400;

/// Every combination of the generator's options.
fn all_options() -> [Options; 4] {
    [(true, false), (true, true), (false, false), (false, true)]
        .map(|(gravity, elastic)| Options { gravity, elastic })
}

#[test]
fn a_few_hundred_seeds_cover_every_motif_with_every_option() {
    for options in all_options() {
        let mut seen = BTreeSet::new();
        let mut motifs_per_scene = BTreeSet::new();
        for seed in SEEDS {
            let generated = generate(&mut SplitMix64(seed), options);
            assert!(!generated.motifs.is_empty(), "seed {seed}");
            motifs_per_scene.insert(generated.motifs.len());
            seen.extend(generated.motifs.iter().copied());
        }
        let missing: Vec<&str> = Motif::ALL
            .iter()
            .filter(|m| !seen.contains(m))
            .map(|m| m.name())
            .collect();
        assert!(
            missing.is_empty(),
            "{options:?}: never generated {missing:?}"
        );
        assert_eq!(motifs_per_scene, BTreeSet::from([1, 2, 3]), "{options:?}");
    }
}

#[test]
fn the_motifs_have_distinct_names() {
    let names: BTreeSet<&str> = Motif::ALL.iter().map(|m| m.name()).collect();
    assert_eq!(names.len(), Motif::ALL.len());
}

#[test]
fn the_same_seed_gives_the_same_json_and_other_seeds_other_scenes() {
    let mut distinct = BTreeSet::new();
    for options in all_options() {
        for seed in SEEDS {
            let a = generate(&mut SplitMix64(seed), options);
            let b = generate(&mut SplitMix64(seed), options);
            let json = a.scene.to_json_string();
            assert_eq!(json, b.scene.to_json_string(), "seed {seed}, {options:?}");
            assert_eq!(
                (&a.motifs, a.scale, a.offset, a.bounds),
                (&b.motifs, b.scale, b.offset, b.bounds),
                "seed {seed}, {options:?}"
            );
            // The JSON is the scene: it reads back to the same scene.
            let back = Scene::from_json_str(&json).unwrap();
            assert_eq!(back, a.scene, "seed {seed}, {options:?}");
            distinct.insert(json);
        }
    }
    // Four option sets of 400 seeds: nearly every scene differs.
    assert!(distinct.len() > 1500, "{} distinct scenes", distinct.len());
}

#[test]
fn the_same_bytes_give_the_same_scene() {
    let mut bytes = Vec::new();
    let mut source = SplitMix64(99);
    for length in 0..200 {
        let a = generate(&mut Bytes::new(&bytes), Options::default());
        let b = generate(&mut Bytes::new(&bytes), Options::default());
        assert_eq!(
            a.scene.to_json_string(),
            b.scene.to_json_string(),
            "{length} bytes"
        );
        assert!(a.scene.build_world().is_ok(), "{bytes:?}");
        bytes.push(exact2d_hunt::source::Source::next_u64(&mut source) as u8);
    }
}

#[test]
fn every_scene_is_valid_and_the_engine_builds_it() {
    for options in all_options() {
        for seed in SEEDS {
            let generated = generate(&mut SplitMix64(seed), options);
            let scene = &generated.scene;
            assert_eq!(scene.validate(), Ok(()), "seed {seed}, {options:?}");
            let built = match scene.build_world() {
                Ok(built) => built,
                Err(e) => panic!("seed {seed}, {options:?}: refused: {e}"),
            };
            let world = built.world();
            assert_eq!(world.ball_count(), scene.balls.len(), "seed {seed}");
            assert!(scene.balls.len() <= 12, "seed {seed}");
            // Every ball starts inside the closed box (motifs' walls may reach out of it).
            let (lo, hi) = generated.bounds;
            let slack = 1e-9 * (hi - lo).max_element();
            for ball in &scene.balls {
                let p = exact2d::DVec2::from(ball.pos);
                let inside = p.cmpge(lo - slack).all() && p.cmple(hi + slack).all();
                assert!(inside, "seed {seed}: ball {} at {p:?}", ball.id);
            }
            if !options.gravity {
                assert_eq!(scene.gravity, [0.0, 0.0], "seed {seed}");
            }
            if options.elastic {
                let restitutions = scene.balls.iter().map(|b| b.restitution);
                let walls = scene.segments.iter().map(|s| s.restitution);
                let pegs = scene.circles.iter().map(|c| c.restitution);
                assert!(
                    restitutions.chain(walls).chain(pegs).all(|e| e == 1.0),
                    "seed {seed}"
                );
            }
        }
    }
}
