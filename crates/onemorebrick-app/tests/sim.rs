//! The `onemorebrick` binary, run as a user would: same seed, same output byte for byte;
//! `--json` ends with one parseable object; bad arguments fail with a message.

use std::process::{Command, Output};

fn run(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_onemorebrick"))
        .args(args)
        .output()
        .expect("the binary runs")
}

#[test]
fn the_same_seed_gives_byte_identical_standard_output() {
    for bot in ["random", "greedy"] {
        let args = [
            "sim",
            "--seed",
            "12",
            "--bot",
            bot,
            "--rounds",
            "15",
            "--candidates",
            "6",
        ];
        let (a, b) = (run(&args), run(&args));
        assert!(a.status.success(), "{}", String::from_utf8_lossy(&a.stderr));
        assert_eq!(a.stdout, b.stdout, "{bot}");
        let text = String::from_utf8(a.stdout).unwrap();
        assert!(
            text.lines().next().unwrap().starts_with("round 1: level 1"),
            "{text}"
        );
        assert!(text.lines().any(|l| l.starts_with("summary: ")), "{text}");
        // Wall-clock figures go to standard error only.
        assert!(!text.contains("wall"), "{text}");
        assert!(String::from_utf8_lossy(&a.stderr).contains("wall time"));
    }
    let other = run(&["sim", "--seed", "13", "--bot", "random", "--rounds", "15"]);
    let first = run(&["sim", "--seed", "12", "--bot", "random", "--rounds", "15"]);
    assert_ne!(
        other.stdout, first.stdout,
        "another seed plays another game"
    );
}

#[test]
fn json_output_ends_with_one_object_matching_the_summary() {
    let out = run(&[
        "sim", "--seed", "3", "--bot", "random", "--rounds", "10", "--json",
    ]);
    assert!(out.status.success());
    let text = String::from_utf8(out.stdout).unwrap();
    let last = text.lines().last().unwrap();
    let v: serde_json::Value = serde_json::from_str(last).expect("the last line is JSON");
    for key in [
        "level",
        "score",
        "balls",
        "bricks_destroyed",
        "collisions",
        "simulated_seconds",
    ] {
        assert!(v.get(key).is_some(), "{key} missing from {last}");
    }
    let rounds = text.lines().filter(|l| l.starts_with("round ")).count() as u64;
    assert_eq!(v["rounds"].as_u64(), Some(rounds));
    assert!(v["simulated_seconds"].as_f64().unwrap() > 0.0);
    // The per-round collisions add up to the summary's.
    let sum: u64 = text
        .lines()
        .filter(|l| l.starts_with("round "))
        .map(|l| {
            let at = l.find("collisions ").unwrap() + "collisions ".len();
            l[at..].split(',').next().unwrap().parse::<u64>().unwrap()
        })
        .sum();
    assert_eq!(v["collisions"].as_u64(), Some(sum));
}

#[test]
fn bad_arguments_fail_with_a_message_not_a_panic() {
    let cases: [&[&str]; 6] = [
        &["sim", "--seed", "x", "--bot", "random", "--rounds", "3"],
        &["sim", "--seed", "1", "--bot", "clever", "--rounds", "3"],
        &["sim", "--seed", "1", "--bot", "random", "--rounds", "0"],
        &["sim", "--seed", "1", "--bot", "random"],
        &["sim", "--seed", "-1", "--bot", "random", "--rounds", "3"],
        &["fly"],
    ];
    for args in cases {
        let out = run(args);
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(err.contains("error"), "{args:?}: {err}");
        assert!(!err.contains("panicked"), "{args:?}: {err}");
        assert!(out.stdout.is_empty(), "{args:?}");
    }
}

/// Negative numbers and out-of-range sizes get clap's message naming the argument and its
/// range (not "unexpected argument '-1' found"), and exit 2 as every bad argument does.
#[test]
fn negative_and_out_of_range_numbers_name_their_range() {
    let cases: [(&[&str], &str); 6] = [
        (
            &["sim", "--seed", "-1", "--bot", "random", "--rounds", "3"],
            "invalid value '-1' for '--seed <SEED>': a seed is a whole number in [0, 18446744073709551615]",
        ),
        (
            &["sim", "--seed", "1", "--bot", "random", "--rounds", "-4"],
            "-4 is not in 1..=100000",
        ),
        (
            &["screenshot", "--out", "x.png", "--width", "0"],
            "invalid value '0' for '--width <WIDTH>': 0 is not in 64..=8192",
        ),
        (
            &["screenshot", "--out", "x.png", "--volley", "-1"],
            "invalid value '-1' for '--volley <VOLLEY>': must be more than 0 and at most 600 seconds",
        ),
        (
            &["bench-frame", "--frames", "0", "--no-draw"],
            "invalid value '0' for '--frames <FRAMES>': 0 is not in 1..=10000",
        ),
        (&["bench", "--seed", "-3"], "a seed is a whole number"),
    ];
    for (args, message) in cases {
        let out = run(args);
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {err}");
        assert!(err.contains(message), "{args:?}: {err}");
        assert!(out.stdout.is_empty(), "{args:?}");
    }
}

/// The number after `key` in `line` (up to the next comma or colon).
fn number_after(line: &str, key: &str) -> u64 {
    let at = line.find(key).unwrap_or_else(|| panic!("{key} in {line}")) + key.len();
    line[at..]
        .split([',', ':'])
        .next()
        .unwrap()
        .trim()
        .parse()
        .unwrap()
}

/// A game played to its end: the level of the round that ended it is the level of the
/// summary and of the JSON, one number (it used to be one more).
#[test]
fn the_level_at_game_over_is_the_last_rounds() {
    for seed in ["1", "2", "3"] {
        let out = run(&[
            "sim", "--seed", seed, "--bot", "random", "--rounds", "500", "--json",
        ]);
        assert!(out.status.success());
        let text = String::from_utf8(out.stdout).unwrap();
        let lines: Vec<&str> = text.lines().collect();
        let [.., last_round, summary, json] = lines[..] else {
            panic!("{text}")
        };
        assert!(last_round.ends_with(", game over"), "seed {seed}: {text}");
        assert!(summary.ends_with(", game over"), "{summary}");
        let json: serde_json::Value = serde_json::from_str(json).unwrap();
        let level = number_after(last_round, "level ");
        assert_eq!(number_after(summary, "level "), level, "{summary}");
        assert_eq!(json["level"].as_u64(), Some(level));
        assert_eq!(json["game_over"].as_bool(), Some(true));
        // The last round's number is the count of rounds played.
        assert_eq!(
            number_after(last_round, "round "),
            json["rounds"].as_u64().unwrap()
        );
    }
}

/// `sim` and `screenshot` take the same bot options, with the same defaults: greedy, 32
/// candidates.
#[test]
fn the_bot_options_default_to_greedy_with_32_candidates() {
    let plain = run(&["sim", "--seed", "4", "--rounds", "3"]);
    let spelled = run(&[
        "sim",
        "--seed",
        "4",
        "--rounds",
        "3",
        "--bot",
        "greedy",
        "--candidates",
        "32",
    ]);
    assert!(plain.status.success());
    assert_eq!(plain.stdout, spelled.stdout);
    for command in ["sim", "screenshot", "watch"] {
        let help = run(&[command, "--help"]);
        let text = String::from_utf8_lossy(&help.stdout);
        assert!(text.contains("--bot <BOT>"), "{command}: {text}");
        assert!(text.contains("[default: greedy]"), "{command}: {text}");
        assert!(text.contains("[default: 32]"), "{command}: {text}");
    }
}
