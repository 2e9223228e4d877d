//! The hunt as a property test: generated scenes (from seeds, and from fuzzer-like bytes),
//! with gravity and without, keep every invariant of [`exact2d_hunt::check`] after every
//! event.
//!
//! Each scene runs to 1 simulated second or 20,000 events, so a case stays short in debug;
//! the `exact2d-hunt` command runs the same scenes longer.

use exact2d_hunt::generate::{Generated, Options, generate};
use exact2d_hunt::run::{Limits, run};
use exact2d_hunt::source::{Bytes, SplitMix64};
use proptest::prelude::*;
use proptest::test_runner::{Config, RngSeed, TestCaseError};

/// How far each scene runs.
const LIMITS: Limits = Limits {
    until: 1.0,
    events: 20_000,
    collapse: 0.0,
};

/// `cases` cases (or `PROPTEST_CASES`) from the fixed `seed` (or `PROPTEST_RNG_SEED`), so
/// every run checks the same scenes; no regression files are written into the source tree.
/// Shrinking is capped at `shrink` steps: each one runs a scene again.
fn config(seed: u64, cases: u32, shrink: u32) -> Config {
    let default = Config::default();
    let rng_seed = match default.rng_seed {
        RngSeed::Random => RngSeed::Fixed(seed),
        chosen => chosen,
    };
    let cases = std::env::var("PROPTEST_CASES")
        .ok()
        .and_then(|n| n.parse().ok())
        .unwrap_or(cases);
    Config {
        cases,
        failure_persistence: None,
        max_shrink_iters: shrink,
        rng_seed,
        ..default
    }
}

/// The scene of `make` with gravity and without, each run with [`LIMITS`]: no finding.
fn keeps_every_invariant(
    what: &str,
    elastic: bool,
    make: impl Fn(Options) -> Generated,
) -> Result<(), TestCaseError> {
    for gravity in [true, false] {
        let generated = make(Options { gravity, elastic });
        let outcome = run(&generated, LIMITS);
        let motifs: Vec<&str> = generated.motifs.iter().map(|m| m.name()).collect();
        prop_assert!(
            outcome.finding.is_none(),
            "{what}, gravity {gravity}, elastic {elastic} [{}] scale {:e} offset {:e}: {}",
            motifs.join(","),
            generated.scale,
            generated.offset,
            outcome.finding.unwrap()
        );
    }
    Ok(())
}

proptest! {
    // A seed's scene has nothing to do with its neighbours': shrinking a seed finds nothing
    // simpler, so the failing seed is reported as drawn.
    #![proptest_config(config(0x5eed, 128, 0))]

    /// Seeded scenes (the `exact2d-hunt` command's).
    #[test]
    fn seeded_scenes_keep_every_invariant(seed in any::<u64>(), elastic in any::<bool>()) {
        keeps_every_invariant(&format!("seed {seed}"), elastic, |options| {
            generate(&mut SplitMix64(seed), options)
        })?;
    }
}

proptest! {
    // Bytes shrink towards zeros, the first choice of every list: simpler scenes.
    #![proptest_config(config(0xb17e5, 128, 64))]

    /// Scenes steered by a fuzzer's bytes (the fuzz targets' `Bytes` source), zeros once they
    /// run out.
    #[test]
    fn fuzzer_byte_scenes_keep_every_invariant(
        bytes in prop::collection::vec(any::<u8>(), 0..400),
        elastic in any::<bool>(),
    ) {
        keeps_every_invariant(&format!("bytes {bytes:?}"), elastic, |options| {
            generate(&mut Bytes::new(&bytes), options)
        })?;
    }
}

#[test]
fn a_collapse_time_reaches_the_world_and_a_bad_one_is_reported() {
    // With a collapse time longer than the run every collision is elastic (the TC model), so
    // the periodic scenes with inelastic balls go another way than without one; each keeps
    // every invariant either way.
    let (mut differ, mut inelastic) = (0, 0);
    for seed in 0..60 {
        let generated = exact2d_hunt::periodic::generate_periodic(&mut SplitMix64(seed));
        if generated.scene.balls.iter().all(|b| b.restitution == 1.0) {
            continue;
        }
        inelastic += 1;
        let plain = run(&generated, LIMITS);
        let tc = run(
            &generated,
            Limits {
                collapse: 1e9,
                ..LIMITS
            },
        );
        assert_eq!(plain.finding, None, "seed {seed}");
        assert_eq!(tc.finding, None, "seed {seed} with a collapse time");
        differ += usize::from((plain.events, plain.time) != (tc.events, tc.time));
    }
    assert!(
        inelastic > 10 && differ > 5,
        "{differ} of {inelastic} differ"
    );
    let generated = generate(&mut SplitMix64(1), Options::default());
    let refused = run(
        &generated,
        Limits {
            collapse: -1.0,
            ..LIMITS
        },
    );
    let finding = refused
        .finding
        .expect("a negative collapse time is refused");
    assert!(finding.detail.contains("collapse time"), "{finding}");
}
