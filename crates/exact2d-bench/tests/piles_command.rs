//! `exact2d-bench piles`: a row per pile, every small pile at rest, totals that add up, and
//! bad arguments refused with the range they must lie in.

use std::process::Command;

fn bench(args: &[&str]) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_exact2d-bench"))
        .args(args)
        .output()
        .expect("the bench runs")
}

/// Twelve-ball piles of restitution 0.8, seeds 1 and 2, without and with pegs: four rows,
/// each at rest well within its budget, and a last row whose events are the rows' sum.
#[test]
fn small_piles_all_rest_and_their_totals_add_up() {
    let out = bench(&[
        "piles", "--balls", "12", "--seeds", "2", "--only", "e = 0.8", "--budget", "60",
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(
        out.stderr.is_empty(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = String::from_utf8(out.stdout).expect("text");
    let rows: Vec<Vec<&str>> = text
        .lines()
        .skip(2)
        .map(|line| line.trim_matches('|').split('|').map(str::trim).collect())
        .collect();
    assert_eq!(rows.len(), 5, "{text}");
    let (piles, total) = rows.split_at(4);
    let mut events = 0u64;
    for row in piles {
        assert!(row[0].starts_with("12 balls, e = 0.8"), "{text}");
        assert_eq!(row[1], "yes", "{text}");
        events += row[3].parse::<u64>().expect("events");
    }
    assert_eq!(total[0][0], "all 4", "{text}");
    assert_eq!(total[0][1], "4", "{text}");
    assert_eq!(
        total[0][3].parse::<u64>().expect("events"),
        events,
        "{text}"
    );
}

#[test]
fn bad_arguments_name_their_range() {
    for (args, range) in [
        (["piles", "--seeds", "0"], "1..=1000"),
        (["piles", "--budget", "0"], "above 0"),
        (["piles", "--balls", "9999"], "1..=5000"),
    ] {
        let out = bench(&args);
        assert!(!out.status.success());
        let error = String::from_utf8_lossy(&out.stderr);
        assert!(error.contains(range), "{error}");
    }
}
