//! `exact2d soak`, run as a user runs it: the built binary on the example scenes and on small
//! scenes in a temporary directory. Event counts are checked against the counts asked for and
//! against hand-counted bounces; failures against the exit codes of `docs/scene-format.md`.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

use serde_json::Value;

mod common;
use common::keys_in_order;

/// A fresh directory for one test, removed when the test ends.
struct TempDir(PathBuf);

impl TempDir {
    fn new(test: &str) -> Self {
        let name = format!("exact2d-soak-{}-{test}", std::process::id());
        let dir = std::env::temp_dir().join(name);
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap();
        Self(dir)
    }

    /// Writes `contents` to `name` in the directory and returns the path.
    fn write(&self, name: &str, contents: &str) -> PathBuf {
        let path = self.0.join(name);
        std::fs::write(&path, contents).unwrap();
        path
    }
}

impl Drop for TempDir {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

fn example(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../examples")
        .join(name)
}

fn soak(scene: &Path, args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_exact2d"))
        .arg("soak")
        .arg(scene)
        .args(args)
        .output()
        .unwrap()
}

/// The report of a run that exited with `code`: one JSON line on standard output.
fn report(output: &Output, code: i32) -> Value {
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert_eq!(output.status.code(), Some(code), "stderr: {stderr}");
    let stdout = std::str::from_utf8(&output.stdout).unwrap();
    assert!(
        stdout.ends_with('\n') && stdout.lines().count() == 1,
        "one line: {stdout}"
    );
    serde_json::from_str(stdout).unwrap()
}

/// Asserts a run refused before it started: the exit code, nothing on standard output, and
/// returns standard error.
fn refused(output: &Output, code: i32) -> String {
    assert_eq!(output.status.code(), Some(code), "{output:?}");
    assert!(output.stdout.is_empty(), "partial output: {output:?}");
    String::from_utf8(output.stderr.clone()).unwrap()
}

#[test]
fn sinai_runs_exactly_the_events_asked_with_every_invariant_kept() {
    let out = report(
        &soak(&example("sinai.json"), &["--events", "100000", "--closed"]),
        0,
    );
    assert_eq!(out["events"], 100_000);
    assert_eq!(out["collisions"], 100_000);
    assert_eq!(out["sensor_events"], 0);
    assert_eq!(out["stopped"], "events");
    assert_eq!(out["invariants_ok"], true);
    assert_eq!(out["balls_escaped"], 0);
    // Checks at the start and after every `check_every` events (the end is one of them here).
    let every = out["check_every"].as_u64().unwrap();
    assert_eq!(
        out["checks"].as_u64().unwrap(),
        1 + 100_000_u64.div_ceil(every)
    );
    let overlap = out["worst_overlap"].as_f64().unwrap();
    assert!((0.0..=1e-9).contains(&overlap), "{overlap}");
    // Every body of Sinai's billiard is elastic: the drift is measured.
    let drift = out["worst_energy_drift"].as_f64().unwrap();
    assert!((0.0..=1e-9).contains(&drift), "{drift}");
    assert!(out["time"].as_f64().unwrap() > 0.0);
    assert!(out["events_per_s"].as_f64().unwrap() > 0.0);
}

/// The hard-disk example in its periodic box: pairs across the edges are measured through
/// their nearest images, and `--closed` means the box itself.
#[test]
fn hard_disks_in_a_periodic_box_keep_every_invariant() {
    let out = report(
        &soak(
            &example("hard_disks.json"),
            &["--events", "200000", "--check-every", "2000", "--closed"],
        ),
        0,
    );
    assert_eq!(out["invariants_ok"], true);
    assert_eq!(out["balls_escaped"], 0);
    let overlap = out["worst_overlap"].as_f64().unwrap();
    assert!((0.0..=1e-9).contains(&overlap), "{overlap}");
    let drift = out["worst_energy_drift"].as_f64().unwrap();
    assert!((0.0..=1e-9).contains(&drift), "{drift}");
}

#[test]
fn the_checks_come_every_k_events_and_at_the_end() {
    let out = report(
        &soak(
            &example("sinai.json"),
            &["--events", "1001", "--check-every", "100"],
        ),
        0,
    );
    assert_eq!(out["events"], 1001);
    assert_eq!(out["check_every"], 100);
    // At 0, 100, ..., 1000, and at the end, 1001.
    assert_eq!(out["checks"], 12);
    assert_eq!(out["balls_escaped"], Value::Null);
}

#[test]
fn the_same_run_twice_gives_the_same_report_apart_from_wall_clock_figures() {
    let run = || {
        let mut out = report(
            &soak(&example("brick_board.json"), &["--events", "20000"]),
            0,
        );
        for key in ["wall_s", "events_per_s", "check_wall_s"] {
            out.as_object_mut().unwrap().remove(key).unwrap();
        }
        out
    };
    assert_eq!(run(), run());
}

#[test]
fn a_scene_with_no_event_left_ends_early_with_a_clear_report() {
    let dir = TempDir::new("no-events");
    // One bounce off the wall at x = 2 (centre at x = 1.5, time 1.5), then the ball flies off.
    let scene = dir.write(
        "scene.json",
        r#"{ "segments": [ { "a": [2, -1], "b": [2, 1] } ],
             "balls": [ { "id": 7, "pos": [0, 0], "vel": [1, 0], "radius": 0.5 } ] }"#,
    );
    let output = soak(&scene, &["--events", "1000"]);
    let out = report(&output, 0);
    assert_eq!(out["events"], 1);
    assert_eq!(out["collisions"], 1);
    assert_eq!(out["stopped"], "no_events_left");
    assert_eq!(out["time"], 1.5);
    assert_eq!(out["invariants_ok"], true);
    assert_eq!(out["worst_energy_drift"], 0.0);
    let stderr = String::from_utf8(output.stderr).unwrap();
    assert!(
        stderr.contains("no event left after 1 events, at time 1.5"),
        "{stderr}"
    );
}

#[test]
fn a_ball_outside_a_closed_scene_fails_containment_with_exit_1() {
    let dir = TempDir::new("escaped");
    let scene = dir.write(
        "scene.json",
        r#"{ "segments": [ { "a": [0, 0], "b": [4, 0] }, { "a": [0, 3], "b": [4, 3] } ],
             "balls": [ { "id": 1, "pos": [2, 1], "vel": [0, 1], "radius": 0.5 },
                        { "id": 42, "pos": [9, 1], "vel": [0, 1], "radius": 0.5 } ] }"#,
    );
    let output = soak(&scene, &["--events", "10", "--closed"]);
    let out = report(&output, 1);
    assert_eq!(out["invariants_ok"], false);
    assert_eq!(out["stopped"], "invariant");
    assert_eq!(out["events"], 0);
    assert_eq!(out["balls_escaped"], 1);
    let stderr = String::from_utf8(output.stderr).unwrap();
    let message = stderr.lines().last().unwrap();
    assert!(
        message.starts_with(&scene.display().to_string()),
        "{message}"
    );
    for part in ["event 0", "time 0.0", "containment", "first ball 42"] {
        assert!(message.contains(part), "{part}: {message}");
    }
    // Without --closed the same scene is fine.
    let out = report(&soak(&scene, &["--events", "10"]), 0);
    assert_eq!(out["invariants_ok"], true);
    assert_eq!(out["events"], 10);
}

#[test]
fn inelastic_scenes_report_no_energy_drift() {
    let dir = TempDir::new("inelastic");
    let scene = dir.write(
        "scene.json",
        r#"{ "segments": [ { "a": [0, 0], "b": [1, 0], "restitution": 0.5 }, { "a": [1, 0], "b": [1, 1] },
                          { "a": [1, 1], "b": [0, 1] }, { "a": [0, 1], "b": [0, 0] } ],
             "balls": [ { "id": 0, "pos": [0.5, 0.5], "vel": [0.3, 0.7], "radius": 0.1 } ] }"#,
    );
    let out = report(&soak(&scene, &["--events", "50"]), 0);
    assert_eq!(out["worst_energy_drift"], Value::Null);
    assert_eq!(out["events"], 50);
}

#[test]
fn bad_counts_exit_2_naming_the_option() {
    let sinai = example("sinai.json");
    for (args, option) in [
        (vec!["--events", "0"], "--events"),
        (vec!["--events", "ten"], "--events"),
        (vec!["--events", "-5"], "--events"),
        (vec!["--events", "1.5"], "--events"),
        (
            vec!["--events", "10", "--check-every", "0"],
            "--check-every",
        ),
        (
            vec!["--events", "10", "--check-every", "x"],
            "--check-every",
        ),
        (vec![], "--events"),
    ] {
        let stderr = refused(&soak(&sinai, &args), 2);
        assert!(stderr.contains(option), "{args:?}: {stderr}");
    }
    // A negative count is a value out of range, not an unknown option.
    let stderr = refused(&soak(&sinai, &["--events", "-5"]), 2);
    assert!(
        stderr.contains("invalid value '-5' for '--events <N>': not a whole number >= 1"),
        "{stderr}"
    );
}

#[test]
fn an_invalid_scene_exits_2_with_one_line_naming_the_file() {
    let dir = TempDir::new("invalid");
    let scene = dir.write(
        "scene.json",
        r#"{ "balls": [ { "id": 0, "pos": [0, 0], "vel": [1, 0], "radius": -1 } ] }"#,
    );
    let stderr = refused(&soak(&scene, &["--events", "10"]), 2);
    assert_eq!(stderr.lines().count(), 1, "{stderr}");
    assert!(
        stderr.starts_with(&format!("{}: balls[0].radius", scene.display())),
        "{stderr}"
    );
}

#[test]
fn closed_without_a_solid_collider_exits_2() {
    let dir = TempDir::new("open");
    let scene = dir.write(
        "scene.json",
        r#"{ "balls": [ { "id": 0, "pos": [0, 0], "vel": [1, 0], "radius": 1 } ] }"#,
    );
    let stderr = refused(&soak(&scene, &["--events", "10", "--closed"]), 2);
    assert!(
        stderr.contains("--closed needs at least one solid collider"),
        "{stderr}"
    );
}

/// As `exact2d simulate` does (`docs/scene-format.md`): a file that cannot be read is not
/// bad input but an error of the environment, exit code 1.
#[test]
fn a_missing_scene_file_exits_1_naming_it() {
    let dir = TempDir::new("missing");
    let path = dir.0.join("nowhere.json");
    let stderr = refused(&soak(&path, &["--events", "10"]), 1);
    assert!(
        stderr.starts_with(&format!("{}: cannot read the scene: ", path.display())),
        "{stderr}"
    );
    assert_eq!(stderr.lines().count(), 1);
}

/// Two balls of radius 0.5 side by side in a box exactly 2 wide, touching each other and a
/// wall each, dropped under gravity: every contact ties. Such scenes once stalled the clock
/// (events at one instant without end); now the soak runs them with the clock moving on.
fn exact_fit_drop(dir: &TempDir, restitution: f64) -> PathBuf {
    let scene = format!(
        r#"{{ "gravity": [0, -9.81],
             "segments": [ {{ "a": [0, 0], "b": [2, 0] }}, {{ "a": [2, 0], "b": [2, 4] }},
                           {{ "a": [2, 4], "b": [0, 4] }}, {{ "a": [0, 4], "b": [0, 0] }} ],
             "balls": [ {{ "id": 1, "pos": [0.5, 2], "vel": [0, 0], "radius": 0.5, "restitution": {restitution} }},
                        {{ "id": 2, "pos": [1.5, 2], "vel": [0, 0], "radius": 0.5, "restitution": {restitution} }} ] }}"#
    );
    dir.write(&format!("exact-fit-{restitution}.json"), &scene)
}

#[test]
fn two_balls_dropped_into_a_box_exactly_two_wide_soak_without_a_stall() {
    let dir = TempDir::new("exact-fit");
    let output = soak(
        &exact_fit_drop(&dir, 1.0),
        &["--events", "20000", "--closed"],
    );
    let out = report(&output, 0);
    assert_eq!(out["stopped"], "events");
    assert_eq!(out["invariants_ok"], true);
    assert_eq!(out["events"], 20_000);
    assert_eq!(out["balls_escaped"], 0);
    // Both balls bounce on the floor in step, 2 bounces every 2 sqrt(2 * 1.5 / 9.81) s.
    let period = 2.0 * (3.0_f64 / 9.81).sqrt();
    let time = out["time"].as_f64().unwrap();
    assert!(
        (time - (period / 2.0 + 9999.0 * period)).abs() < 1e-6,
        "{time}"
    );
    let drift = out["worst_energy_drift"].as_f64().unwrap();
    assert!((0.0..=1e-9).contains(&drift), "{drift}");
    // Perfectly inelastic, they come to rest on the floor at once: 2 events, then none.
    let out = report(&soak(&exact_fit_drop(&dir, 0.0), &["--events", "1000"]), 0);
    assert_eq!(out["stopped"], "no_events_left");
    assert_eq!(out["events"], 2);
    assert!((out["time"].as_f64().unwrap() - period / 2.0).abs() < 1e-12);
}

#[test]
fn the_report_has_the_documented_keys_in_order_and_types() {
    for (scene, args) in [
        (example("sinai.json"), vec!["--events", "5000", "--closed"]),
        (example("pegs_gravity.json"), vec!["--events", "5000"]),
    ] {
        let output = soak(&scene, &args);
        let out = report(&output, 0);
        let line = std::str::from_utf8(&output.stdout).unwrap();
        assert_eq!(
            keys_in_order(line),
            [
                "events",
                "collisions",
                "sensor_events",
                "time",
                "stopped",
                "wall_s",
                "events_per_s",
                "check_every",
                "checks",
                "check_wall_s",
                "worst_overlap",
                "worst_energy_drift",
                "balls_escaped",
                "invariants_ok"
            ],
            "{line}"
        );
        for key in [
            "events",
            "collisions",
            "sensor_events",
            "check_every",
            "checks",
        ] {
            assert!(out[key].is_u64(), "{key}: {line}");
        }
        for key in [
            "time",
            "wall_s",
            "events_per_s",
            "check_wall_s",
            "worst_overlap",
        ] {
            assert!(out[key].is_f64(), "{key}: {line}");
        }
        assert!(out["worst_energy_drift"].is_f64() || out["worst_energy_drift"].is_null());
        assert!(out["balls_escaped"].is_u64() || out["balls_escaped"].is_null());
        assert_eq!(out["invariants_ok"], true, "{line}");
    }
}

/// `--help` with its lines joined, so a phrase can be found across a line break.
fn help(command: &str) -> String {
    let output = Command::new(env!("CARGO_BIN_EXE_exact2d"))
        .args([command, "--help"])
        .output()
        .unwrap();
    assert_eq!(output.status.code(), Some(0), "{output:?}");
    let text = String::from_utf8(output.stdout).unwrap();
    text.split_whitespace().collect::<Vec<_>>().join(" ")
}

#[test]
fn the_help_states_the_bounds_the_soak_checks() {
    let soak = help("soak");
    for phrase in [
        "overlap deeper than 1e-9 of their contact distance plus 256 units in the last place of the contact's coordinate scale",
        "time never goes back and moves on: at most 64 events at one instant per ball that had one, plus 64",
        "the energy of an elastic world drifts less than 1e-9 relative",
        "only a gain counts",
        "1 a broken invariant, a stalled clock among them",
    ] {
        assert!(soak.contains(phrase), "{phrase}: {soak}");
    }
    assert!(
        !soak.contains("1e-9 of their contact distance, that time"),
        "the old, fixed bound: {soak}"
    );
    let simulate = help("simulate");
    assert!(
        simulate.contains("1 anything else (such as an unreadable file, or a clock that stalls"),
        "{simulate}"
    );
}
