//! `exact2d simulate`, run as a user runs it: the built binary on scene files in a temporary
//! directory. Results are checked against analytic answers and hand-computed events, failures
//! against the exit codes and messages of `docs/scene-format.md`.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

use serde_json::Value;

mod common;
use common::keys_in_order;

/// A fresh directory for one test, removed when the test ends.
struct TempDir(PathBuf);

impl TempDir {
    fn new(test: &str) -> Self {
        let dir = std::env::temp_dir().join(format!("exact2d-cli-{}-{test}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap();
        Self(dir)
    }
}

impl std::ops::Deref for TempDir {
    type Target = Path;

    fn deref(&self) -> &Path {
        &self.0
    }
}

impl Drop for TempDir {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

/// Writes `contents` to `dir/name` and returns the path.
fn write(dir: &Path, name: &str, contents: impl AsRef<[u8]>) -> PathBuf {
    let path = dir.join(name);
    std::fs::write(&path, contents).unwrap();
    path
}

fn exact2d(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_exact2d"))
        .args(args)
        .output()
        .unwrap()
}

fn simulate(scene: &Path, until: &str, events: Option<&Path>) -> Output {
    let mut args = vec!["simulate", scene.to_str().unwrap(), "--until", until];
    if let Some(events) = events {
        args.extend(["--events", events.to_str().unwrap()]);
    }
    exact2d(&args)
}

/// The result object of a successful run.
fn result(output: &Output) -> Value {
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert_eq!(output.status.code(), Some(0), "stderr: {stderr}");
    assert!(output.stderr.is_empty(), "stderr: {stderr}");
    let stdout = std::str::from_utf8(&output.stdout).unwrap();
    assert!(
        stdout.ends_with('\n') && stdout.lines().count() == 1,
        "one line: {stdout}"
    );
    serde_json::from_str(stdout).unwrap()
}

/// Asserts a failed run: the exit code, nothing on stdout, and one line on stderr.
fn failure(output: &Output, code: i32) -> String {
    assert_eq!(output.status.code(), Some(code), "{output:?}");
    assert!(output.stdout.is_empty(), "partial output: {output:?}");
    let stderr = String::from_utf8(output.stderr.clone()).unwrap();
    stderr.strip_suffix('\n').unwrap_or(&stderr).to_owned()
}

fn xy(value: &Value) -> [f64; 2] {
    [value[0].as_f64().unwrap(), value[1].as_f64().unwrap()]
}

// ---- results ---------------------------------------------------------------------------------

/// The analytic position on one axis of a ball bouncing between walls at 0 and `size`: the
/// free coordinate `u = x0 - r + v t` folded into `[0, L]`, `L = size - 2r`, by mirroring.
/// Also returns the number of bounces: the multiples of `L` that `u` crossed.
fn fold(x0: f64, v: f64, t: f64, r: f64, size: f64) -> (f64, u64) {
    let length = size - 2.0 * r;
    let u = (x0 - r) + v * t;
    let bounces = ((u / length).floor() - ((x0 - r) / length).floor()).abs() as u64;
    let m = u.rem_euclid(2.0 * length);
    (
        if m <= length {
            r + m
        } else {
            r + 2.0 * length - m
        },
        bounces,
    )
}

#[test]
fn a_ball_in_a_box_ends_where_mirror_folding_puts_it() {
    let dir = TempDir::new("fold");
    // Speeds with few bits, so v * t is exact and so is the reference.
    let (x0, y0, vx, vy, r, t) = (3.0, 2.0, 7.25, -2.875, 0.5, 10.0);
    let scene = format!(
        r#"{{ "segments": [ {{ "a": [0, 0], "b": [10, 0] }}, {{ "a": [10, 0], "b": [10, 8] }},
                           {{ "a": [10, 8], "b": [0, 8] }}, {{ "a": [0, 8], "b": [0, 0] }} ],
             "balls": [ {{ "id": 12, "pos": [{x0:?}, {y0:?}], "vel": [{vx:?}, {vy:?}], "radius": {r:?} }} ] }}"#
    );
    let output = simulate(&write(&dir, "box.json", scene), "10", None);
    let out = result(&output);
    let keys = keys_in_order(std::str::from_utf8(&output.stdout).unwrap());
    assert_eq!(keys, ["time", "events", "wall_s", "balls"]);
    let (x, x_bounces) = fold(x0, vx, t, r, 10.0);
    let (y, y_bounces) = fold(y0, vy, t, r, 8.0);
    let ball = &out["balls"][0];
    assert_eq!(ball["id"], 12);
    let pos = xy(&ball["pos"]);
    assert!(
        (pos[0] - x).abs() < 1e-12 && (pos[1] - y).abs() < 1e-12,
        "{pos:?} vs {:?}",
        [x, y]
    );
    // Reflection off an axis-aligned wall is exact: each bounce flips one sign.
    let sign = |bounces: u64| if bounces % 2 == 0 { 1.0 } else { -1.0 };
    assert_eq!(
        xy(&ball["vel"]),
        [vx * sign(x_bounces), vy * sign(y_bounces)]
    );
    assert_eq!(out["time"], 10.0);
    assert_eq!(out["events"], x_bounces + y_bounces);
    assert!(out["wall_s"].as_f64().unwrap() >= 0.0);
}

#[test]
fn balls_are_reported_in_scene_order_with_their_ids() {
    let dir = TempDir::new("order");
    let scene = r#"{ "balls": [
        { "id": 30, "pos": [0, 0], "vel": [1, 0.5], "radius": 0.1 },
        { "id": 1, "pos": [5, 0], "vel": [0, 0], "radius": 0.1 },
        { "id": 20, "pos": [-5, 0], "vel": [-0.25, 0], "radius": 0.1 } ] }"#;
    let out = result(&simulate(&write(&dir, "s.json", scene), "2", None));
    let balls = out["balls"].as_array().unwrap();
    assert_eq!(
        balls
            .iter()
            .map(|b| b["id"].as_u64().unwrap())
            .collect::<Vec<_>>(),
        [30, 1, 20]
    );
    assert_eq!(xy(&balls[0]["pos"]), [2.0, 1.0]);
    assert_eq!(xy(&balls[2]["pos"]), [-5.5, 0.0]);
    assert_eq!(out["events"], 0);
}

#[test]
fn until_zero_gives_the_initial_state_exactly() {
    let dir = TempDir::new("zero");
    let scene = r#"{ "gravity": [0, -9.81], "balls": [ { "id": 0, "pos": [0.1, 0.30000000000000004], "vel": [1e-310, -3], "radius": 1 } ] }"#;
    let output = simulate(&write(&dir, "s.json", scene), "0", None);
    let stdout = std::str::from_utf8(&output.stdout).unwrap();
    assert!(
        stdout.starts_with(r#"{"time":0.0,"events":0,"wall_s":"#),
        "{stdout}"
    );
    let balls = r#""balls":[{"id":0,"pos":[0.1,0.30000000000000004],"vel":[1e-310,-3.0]}]}"#;
    assert!(stdout.ends_with(&format!("{balls}\n")), "{stdout}");
}

// ---- events ----------------------------------------------------------------------------------

/// Five lanes far apart, one collision each (radius 0.5, speed 1 along x unless said):
/// - y = 0: `segments[1]` (x = 5, y in [-1, 1]), its interior at t = 4.5;
/// - y = 9.7: `segments[0]` (x = 5, y in [10, 12]), end point a = (5, 10) when the centre is at
///   distance 0.5 from it, x = 5 - 0.4, at t = 4.6, normal (-0.8, -0.6);
/// - y = 39.7, from x = -1: `segments[2]` from (5, 42) to (5, 40), end point b, at t = 5.6;
/// - y = 20: `circles[0]` (centre (5, 20), radius 1), at t = 3.5, point (4, 20);
/// - y = 30: ball 10 hits ball 20 (at rest at x = 3) at t = 2, point (2.5, 30).
const LANES: &str = r#"{ "ball_ball": true,
    "segments": [ { "a": [5, 10], "b": [5, 12] }, { "a": [5, -1], "b": [5, 1] }, { "a": [5, 42], "b": [5, 40] } ],
    "circles": [ { "center": [5, 20], "radius": 1 } ],
    "balls": [
        { "id": 7, "pos": [0, 0], "vel": [1, 0], "radius": 0.5 },
        { "id": 3, "pos": [0, 9.7], "vel": [1, 0], "radius": 0.5 },
        { "id": 5, "pos": [-1, 39.7], "vel": [1, 0], "radius": 0.5 },
        { "id": 42, "pos": [0, 20], "vel": [1, 0], "radius": 0.5 },
        { "id": 10, "pos": [0, 30], "vel": [1, 0], "radius": 0.5 },
        { "id": 20, "pos": [3, 30], "vel": [0, 0], "radius": 0.5 } ] }"#;

fn assert_close(actual: f64, expected: f64, what: &str) {
    assert!(
        (actual - expected).abs() < 1e-12,
        "{what}: {actual} vs {expected}"
    );
}

fn assert_close_xy(actual: &Value, expected: [f64; 2], what: &str) {
    let actual = xy(actual);
    assert_close(actual[0], expected[0], what);
    assert_close(actual[1], expected[1], what);
}

#[test]
fn the_events_file_has_one_line_per_collision_of_each_kind() {
    let dir = TempDir::new("events");
    let events_path = dir.join("events.jsonl");
    let out = result(&simulate(
        &write(&dir, "lanes.json", LANES),
        "10",
        Some(&events_path),
    ));
    let text = std::fs::read_to_string(&events_path).unwrap();
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(out["events"], 5);
    assert_eq!(lines.len(), 5, "{text}");
    let keys: Vec<Vec<String>> = lines.iter().map(|l| keys_in_order(l)).collect();
    let events: Vec<Value> = lines
        .iter()
        .map(|l| serde_json::from_str(l).unwrap())
        .collect();

    assert_eq!(
        keys[0],
        ["time", "kind", "balls", "point", "normal", "impulse"]
    );
    assert_eq!(
        (&events[0]["kind"], &events[0]["balls"]),
        (&"ball_ball".into(), &serde_json::json!([10, 20]))
    );
    assert_close(events[0]["time"].as_f64().unwrap(), 2.0, "ball-ball time");
    assert_close_xy(&events[0]["point"], [2.5, 30.0], "ball-ball point");
    assert_close_xy(&events[0]["normal"], [1.0, 0.0], "ball-ball normal");
    // Equal masses, elastic, head on: ball 20 leaves with ball 10's velocity, 1.
    assert_close(
        events[0]["impulse"].as_f64().unwrap(),
        1.0,
        "ball-ball impulse",
    );

    assert_eq!(
        keys[1],
        [
            "time", "kind", "ball", "circle", "point", "normal", "impulse"
        ]
    );
    assert_eq!(
        (&events[1]["kind"], &events[1]["ball"], &events[1]["circle"]),
        (&"ball_circle".into(), &42.into(), &0.into())
    );
    assert_close(events[1]["time"].as_f64().unwrap(), 3.5, "circle time");
    assert_close_xy(&events[1]["point"], [4.0, 20.0], "circle point");
    assert_close_xy(&events[1]["normal"], [-1.0, 0.0], "circle normal");
    // A head-on elastic bounce of mass 1 at speed 1: 2 m v.
    assert_close(
        events[1]["impulse"].as_f64().unwrap(),
        2.0,
        "circle impulse",
    );

    assert_eq!(
        keys[2],
        [
            "time", "kind", "ball", "segment", "point", "normal", "impulse"
        ]
    );
    assert_eq!(
        (
            &events[2]["kind"],
            &events[2]["ball"],
            &events[2]["segment"]
        ),
        (&"ball_segment".into(), &7.into(), &1.into())
    );
    assert_close(events[2]["time"].as_f64().unwrap(), 4.5, "segment time");
    assert_close_xy(&events[2]["point"], [5.0, 0.0], "segment point");
    assert_close_xy(&events[2]["normal"], [-1.0, 0.0], "segment normal");
    assert_close(
        events[2]["impulse"].as_f64().unwrap(),
        2.0,
        "segment impulse",
    );

    assert_eq!(
        keys[3],
        [
            "time", "kind", "ball", "segment", "end", "point", "normal", "impulse"
        ]
    );
    let expected = (&"ball_end_point".into(), &3.into(), &0.into(), &"a".into());
    assert_eq!(
        (
            &events[3]["kind"],
            &events[3]["ball"],
            &events[3]["segment"],
            &events[3]["end"]
        ),
        expected
    );
    assert_close(events[3]["time"].as_f64().unwrap(), 4.6, "end point a time");
    assert_close_xy(&events[3]["point"], [5.0, 10.0], "end point a point");
    assert_close_xy(&events[3]["normal"], [-0.8, -0.6], "end point a normal");
    // The normal part of the velocity (1, 0) is 0.8: the impulse is 2 x 0.8.
    assert_close(
        events[3]["impulse"].as_f64().unwrap(),
        1.6,
        "end point a impulse",
    );

    let expected = (&"ball_end_point".into(), &5.into(), &2.into(), &"b".into());
    assert_eq!(
        (
            &events[4]["kind"],
            &events[4]["ball"],
            &events[4]["segment"],
            &events[4]["end"]
        ),
        expected
    );
    assert_close(events[4]["time"].as_f64().unwrap(), 5.6, "end point b time");
    assert_close_xy(&events[4]["point"], [5.0, 40.0], "end point b point");
    assert_close_xy(&events[4]["normal"], [-0.8, -0.6], "end point b normal");
    assert_close(
        events[4]["impulse"].as_f64().unwrap(),
        1.6,
        "end point b impulse",
    );
}

// ---- failures --------------------------------------------------------------------------------

/// A scene with spin or friction prints each ball's `spin` last; the bounce is the model's
/// (`crates/exact2d/tests/rough_disks.rs` has the algebra): a disk at (1, -2) turning at 6
/// rad/s meets a rough floor (mu 1, beta 0) and leaves rolling, at (1 - 4/3, 2), turning at
/// 6 - 16/3. A scene without such keys prints no `spin`.
#[test]
fn a_rough_scene_prints_each_balls_spin() {
    let dir = TempDir::new("spin");
    let scene = r#"{ "segments": [ { "a": [-10, 0], "b": [10, 0], "friction": 1 } ],
        "balls": [ { "id": 4, "pos": [0, 2.5], "vel": [1, -2], "radius": 0.5, "spin": 6, "friction": 1 },
                   { "id": 5, "pos": [5, 2.5], "vel": [0, 0], "radius": 0.5 } ] }"#;
    let events = dir.join("rough-events.jsonl");
    let output = simulate(&write(&dir, "rough.json", scene), "1.5", Some(&events));
    // The bounce's line ends with the friction impulse, along the normal turned a quarter
    // counter-clockwise (-x): (1 + beta) g / K = 4 / 3 where Coulomb allows mu P = 4.
    let log = std::fs::read_to_string(&events).unwrap();
    let line = log.lines().next().unwrap();
    assert_eq!(
        keys_in_order(line),
        [
            "time",
            "kind",
            "ball",
            "segment",
            "point",
            "normal",
            "impulse",
            "tangential_impulse"
        ]
    );
    let value: Value = serde_json::from_str(line).unwrap();
    assert_close(
        value["tangential_impulse"].as_f64().unwrap(),
        4.0 / 3.0,
        "friction impulse",
    );
    let text = String::from_utf8(output.stdout.clone()).unwrap();
    let first = &text[text.find(r#"{"id":4"#).unwrap()..];
    let first = &first[..=first.find('}').unwrap()];
    assert_eq!(keys_in_order(first), ["id", "pos", "vel", "spin"]);
    let value = result(&output);
    let balls = value["balls"].as_array().unwrap();
    assert_close_xy(&balls[0]["vel"], [1.0 - 4.0 / 3.0, 2.0], "velocity");
    assert_close(balls[0]["spin"].as_f64().unwrap(), 6.0 - 16.0 / 3.0, "spin");
    // Ball 5 has no friction: its spin is printed, and is 0.
    assert_eq!(balls[1]["spin"].as_f64(), Some(0.0));
    let plain = r#"{ "balls": [ { "id": 0, "pos": [0, 0], "vel": [1, 0], "radius": 1 } ] }"#;
    let output = simulate(&write(&dir, "plain.json", plain), "1", None);
    assert!(!String::from_utf8(output.stdout).unwrap().contains("spin"));
}

#[test]
fn an_invalid_scene_exits_2_with_one_line_naming_the_file_and_the_item() {
    let dir = TempDir::new("invalid");
    let cases = [
        (
            r#"{ "balls": [ { "id": 0, "pos": [0, 0], "vel": [0, 0], "radius": 1 },
                          { "id": 1, "pos": [5, 0], "vel": [0, 0], "radius": 0 } ] }"#,
            "balls[1].radius must be > 0",
        ),
        (
            r#"{ "segments": [ { "a": [-5, 0], "b": [5, 0] } ], "balls": [ { "id": 0, "pos": [0, 0.25], "vel": [0, 0], "radius": 0.5 } ] }"#,
            "balls[0] overlaps segments[0]",
        ),
        (
            r#"{ "balls": [], "extra": true }"#,
            "extra: unknown field `extra`, expected one of `gravity`, `ball_ball`, `segments`, `circles`, `balls`, `sleep`, `table`, `periodic` at line 1 column 22",
        ),
        (
            "{ \"balls\": [\n",
            "balls: EOF while parsing a list at line 2 column 0",
        ),
        (
            "",
            "empty scene: expected a JSON object with a `balls` list",
        ),
        (
            r#"{ "balls": [ { "id": 0, "pos": [0, 0], "vel": [0, 0], "radius": 1, "inertia": 1.5 } ] }"#,
            "balls[0].inertia must be in (0, 1]",
        ),
        (
            r#"{ "segments": [ { "a": [-5, -2], "b": [5, -2], "friction": -0.5 } ], "balls": [] }"#,
            "segments[0].friction must be >= 0",
        ),
        (
            r#"{ "circles": [ { "center": [0, 5], "radius": 1, "tangential_restitution": 2 } ], "balls": [] }"#,
            "circles[0].tangential_restitution must be in [-1, 1]",
        ),
    ];
    for (k, (scene, message)) in cases.iter().enumerate() {
        let path = write(&dir, &format!("scene{k}.json"), scene);
        let stderr = failure(&simulate(&path, "1", None), 2);
        assert_eq!(stderr, format!("{}: {message}", path.display()));
    }
}

#[test]
fn a_scene_that_is_not_utf8_exits_2() {
    let dir = TempDir::new("utf8");
    let path = write(&dir, "scene.json", b"{ \"balls\": [] \xff }");
    let stderr = failure(&simulate(&path, "1", None), 2);
    assert_eq!(
        stderr,
        format!(
            "{}: not UTF-8 text (invalid byte at offset 14)",
            path.display()
        )
    );
}

#[test]
fn a_bad_until_exits_2_naming_until() {
    let dir = TempDir::new("until");
    let path = write(&dir, "scene.json", r#"{ "balls": [] }"#);
    for until in ["-1", "nan", "inf", "-inf", "1e400", "ten", ""] {
        let output = simulate(&path, until, None);
        assert_eq!(
            output.status.code(),
            Some(2),
            "--until {until:?}: {output:?}"
        );
        assert!(output.stdout.is_empty());
        let stderr = String::from_utf8(output.stderr).unwrap();
        assert!(stderr.contains("--until"), "--until {until:?}: {stderr}");
    }
    let output = exact2d(&["simulate", path.to_str().unwrap()]);
    assert_eq!(output.status.code(), Some(2));
    assert!(
        String::from_utf8(output.stderr)
            .unwrap()
            .contains("--until")
    );
}

#[test]
fn a_missing_scene_file_exits_1() {
    let dir = TempDir::new("missing");
    let path = dir.join("nowhere.json");
    let stderr = failure(&simulate(&path, "1", None), 1);
    assert!(
        stderr.starts_with(&format!("{}: cannot read the scene: ", path.display())),
        "{stderr}"
    );
    assert_eq!(stderr.lines().count(), 1);
}

#[test]
fn an_events_file_that_cannot_be_created_exits_1() {
    let dir = TempDir::new("unwritable");
    let path = write(&dir, "scene.json", r#"{ "balls": [] }"#);
    let events = dir.join("no-such-dir").join("events.jsonl");
    let stderr = failure(&simulate(&path, "1", Some(&events)), 1);
    assert!(
        stderr.starts_with(&format!("{}: cannot write the events: ", events.display())),
        "{stderr}"
    );
}

// ---- examples and determinism ----------------------------------------------------------------

fn example_scenes() -> Vec<PathBuf> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples");
    let mut scenes: Vec<PathBuf> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|entry| entry.unwrap().path())
        .filter(|path| path.extension().is_some_and(|e| e == "json"))
        .collect();
    scenes.sort();
    scenes
}

#[test]
fn every_example_scene_runs_to_t_10() {
    let scenes = example_scenes();
    assert!(scenes.len() >= 4, "{scenes:?}");
    for path in scenes {
        let out = result(&simulate(&path, "10", None));
        let scene: Value = serde_json::from_str(&std::fs::read_to_string(&path).unwrap()).unwrap();
        assert_eq!(out["time"], 10.0, "{}", path.display());
        assert_eq!(
            out["balls"].as_array().unwrap().len(),
            scene["balls"].as_array().unwrap().len()
        );
        assert!(
            out["events"].as_u64().unwrap() > 0,
            "{}: nothing happened",
            path.display()
        );
    }
}

/// `examples/hopper.json` (60 balls poured through a funnel into bins, sleeping on) runs to
/// rest, as the README says: by t = 300 every ball sleeps, the output ends with `"asleep"`,
/// and 1000 s more handle no collision at all. Every ball is inside the box.
#[test]
fn the_hopper_example_comes_to_rest() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/hopper.json");
    let scene: Value = serde_json::from_str(&std::fs::read_to_string(&path).unwrap()).unwrap();
    let balls = scene["balls"].as_array().unwrap().len();
    let output = simulate(&path, "300", None);
    let keys = keys_in_order(std::str::from_utf8(&output.stdout).unwrap());
    assert_eq!(keys, ["time", "events", "wall_s", "balls", "asleep"]);
    let at_rest = result(&output);
    assert_eq!(at_rest["asleep"].as_u64().unwrap() as usize, balls);
    for ball in at_rest["balls"].as_array().unwrap() {
        let [x, y] = xy(&ball["pos"]);
        assert!((0.0..=12.0).contains(&x) && y > 0.0, "{ball}");
        assert_eq!(ball["vel"], serde_json::json!([0.0, 0.0]), "{ball}");
    }
    let later = result(&simulate(&path, "1300", None));
    assert_eq!(later["events"], at_rest["events"]);
    assert_eq!(later["balls"], at_rest["balls"]);
}

/// `examples/pool_break.json` (a break at pool on a table seen from above) comes to rest, as
/// the README says: by t = 60 every ball is still, without spin or roll (the output gives
/// both for a table), on the table; 100 s more handle no collision.
#[test]
fn the_pool_break_example_comes_to_rest_on_the_table() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/pool_break.json");
    let output = simulate(&path, "60", None);
    let at_rest = result(&output);
    let balls = at_rest["balls"].as_array().unwrap();
    assert_eq!(balls.len(), 16);
    for ball in balls {
        let [x, y] = xy(&ball["pos"]);
        assert!(
            (0.0..=2.54).contains(&x) && (0.0..=1.27).contains(&y),
            "{ball}"
        );
        assert_eq!(ball["vel"], serde_json::json!([0.0, 0.0]), "{ball}");
        assert_eq!(ball["spin"], serde_json::json!(0.0), "{ball}");
        assert_eq!(ball["roll"], serde_json::json!([0.0, 0.0]), "{ball}");
    }
    assert!(at_rest["events"].as_u64().unwrap() >= 15, "the rack broke");
    let later = result(&simulate(&path, "160", None));
    assert_eq!(later["events"], at_rest["events"]);
    assert_eq!(later["balls"], at_rest["balls"]);
}

/// Standard output with the value of `wall_s` cut out.
fn without_wall_s(stdout: &[u8]) -> String {
    let text = std::str::from_utf8(stdout).unwrap();
    let start = text.find(r#""wall_s":"#).unwrap();
    let end = start + text[start..].find(',').unwrap();
    format!("{}{}", &text[..start], &text[end..])
}

#[test]
fn the_same_scene_run_twice_gives_the_same_bytes_apart_from_wall_s() {
    let dir = TempDir::new("twice");
    for path in example_scenes() {
        let (first_events, second_events) = (dir.join("first.jsonl"), dir.join("second.jsonl"));
        let first = simulate(&path, "10", Some(&first_events));
        let second = simulate(&path, "10", Some(&second_events));
        assert_eq!(first.status.code(), Some(0));
        assert_eq!(
            without_wall_s(&first.stdout),
            without_wall_s(&second.stdout),
            "{}",
            path.display()
        );
        let read = |p: &Path| std::fs::read(p).unwrap();
        assert!(
            read(&first_events) == read(&second_events),
            "{}: events differ",
            path.display()
        );
    }
}

/// Two balls of radius 0.5 side by side in a box exactly 2 wide, touching each other and a
/// wall each, dropped under gravity from 1.5 above the floor: every contact ties. Such scenes
/// once stalled the clock; now both balls bounce, elastically and in step, 9 times each by
/// t = 10, and end where the bounce's parabola puts them.
#[test]
fn two_balls_dropped_into_a_box_exactly_two_wide_bounce_in_step_without_a_stall() {
    let dir = TempDir::new("exact-fit");
    let scene = write(
        &dir,
        "scene.json",
        r#"{ "gravity": [0, -9.81],
             "segments": [ { "a": [0, 0], "b": [2, 0] }, { "a": [2, 0], "b": [2, 4] },
                           { "a": [2, 4], "b": [0, 4] }, { "a": [0, 4], "b": [0, 0] } ],
             "balls": [ { "id": 1, "pos": [0.5, 2], "vel": [0, 0], "radius": 0.5 },
                        { "id": 2, "pos": [1.5, 2], "vel": [0, 0], "radius": 0.5 } ] }"#,
    );
    let (g, fall) = (9.81_f64, (3.0_f64 / 9.81).sqrt());
    let since_bounce = (10.0 - fall).rem_euclid(2.0 * fall);
    let y = 0.5 + g * fall * since_bounce - 0.5 * g * since_bounce * since_bounce;
    let vy = g * fall - g * since_bounce;
    let events_path = dir.join("events.jsonl");
    // Without an events file the run is one `advance_to`; with one, `step_until` event by event.
    for events in [None, Some(events_path.as_path())] {
        let out = result(&simulate(&scene, "10", events));
        assert_eq!(out["time"], 10.0);
        assert_eq!(out["events"], 18);
        for (ball, x) in out["balls"].as_array().unwrap().iter().zip([0.5, 1.5]) {
            assert_eq!(ball["pos"][0], x);
            assert_eq!(ball["vel"][0], 0.0);
            assert_close(ball["pos"][1].as_f64().unwrap(), y, "y");
            assert_close(ball["vel"][1].as_f64().unwrap(), vy, "vy");
        }
    }
    let lines = std::fs::read_to_string(&events_path).unwrap();
    assert_eq!(lines.lines().count(), 18);
    assert!(
        lines
            .lines()
            .all(|l| l.contains(r#""kind":"ball_segment","#)),
        "{lines}"
    );
}

/// `--observables` adds the collision virial, the time it counts from and each collider's
/// momentum and impacts, last, named as the events file names colliders; without it the output
/// is what it always was. A ball of mass 2.5 bouncing between walls at x = 0 and x = 10 (its
/// centre between 0.5 and 9.5, starting at 5 at 4 units a second) meets the right wall at
/// 1.125 s and every 4.5 s after, the left 2.25 s after each: by t = 100, 22 each, every one
/// giving `2 m v = 20`. A second ball, above the walls' ends, bounces off a circle once, head
/// on, and flies off.
#[test]
fn the_observables_flag_adds_the_virial_and_each_collider_s_momentum_and_impacts() {
    let dir = TempDir::new("observables");
    let scene = r#"{ "segments": [ { "a": [0, -100], "b": [0, 100] }, { "a": [10, -100], "b": [10, 100] } ],
        "circles": [ { "center": [100, 200], "radius": 1 } ],
        "balls": [ { "id": 7, "pos": [5, 0], "vel": [4, 0.25], "radius": 0.5, "mass": 2.5 },
                   { "id": 8, "pos": [95, 200], "vel": [2, 0], "radius": 0.5 } ] }"#;
    let path = write(&dir, "walls.json", scene);
    let args = |flag: bool| {
        let mut args = vec!["simulate", path.to_str().unwrap(), "--until", "100"];
        if flag {
            args.push("--observables");
        }
        exact2d(&args)
    };
    let (plain, observed) = (args(false), args(true));
    let text = std::str::from_utf8(&observed.stdout).unwrap();
    assert_eq!(
        keys_in_order(text),
        [
            "time",
            "events",
            "wall_s",
            "balls",
            "virial",
            "since",
            "colliders"
        ]
    );
    let out = result(&observed);
    assert_eq!(out["virial"], 0.0);
    assert_eq!(out["since"], 0.0);
    let colliders = out["colliders"].as_array().unwrap();
    assert_eq!(colliders.len(), 3);
    // Each in the order written (serde_json's `Value` sorts keys, so on the text).
    assert!(
        text.contains(r#"{"segment":0,"momentum":[-440.0,0.0],"impacts":22}"#),
        "{text}"
    );
    assert!(
        text.contains(r#"{"segment":1,"momentum":[440.0,0.0],"impacts":22}"#),
        "{text}"
    );
    // Ball 8 (mass 1) meets the circle head on at 2 and leaves at -2: the circle takes 4.
    assert!(
        text.contains(r#"{"circle":0,"momentum":[4.0,0.0],"impacts":1}"#),
        "{text}"
    );
    // Without the flag: the same object without the three keys.
    assert_eq!(
        keys_in_order(std::str::from_utf8(&plain.stdout).unwrap()),
        ["time", "events", "wall_s", "balls"]
    );
    let cut = without_wall_s(&observed.stdout);
    let start = cut.find(r#","virial":"#).unwrap();
    assert_eq!(
        format!("{}}}\n", &cut[..start]),
        without_wall_s(&plain.stdout)
    );
}

/// A periodic box: positions come out wrapped into it, each ball's unwrapped position last;
/// a lone ball's are its free flight, folded and not.
#[test]
fn a_periodic_box_prints_wrapped_and_unwrapped_positions() {
    let dir = TempDir::new("periodic");
    // Speeds and times with few bits: v t is exact, and so are the references.
    let scene = r#"{ "periodic": [10, 8],
        "balls": [ { "id": 3, "pos": [2.5, 1.0], "vel": [7.25, -2.875], "radius": 0.5 } ] }"#;
    let output = simulate(&write(&dir, "torus.json", scene), "10", None);
    let keys = keys_in_order(std::str::from_utf8(&output.stdout).unwrap());
    assert_eq!(keys, ["time", "events", "wall_s", "balls"]);
    let out = result(&output);
    let ball = &out["balls"][0];
    let (ux, uy) = (2.5 + 7.25 * 10.0, 1.0 - 2.875 * 10.0);
    let unwrapped = xy(&ball["unwrapped"]);
    assert!(
        (unwrapped[0] - ux).abs() < 1e-12 && (unwrapped[1] - uy).abs() < 1e-12,
        "{unwrapped:?}"
    );
    let pos = xy(&ball["pos"]);
    let want = [ux.rem_euclid(10.0), uy.rem_euclid(8.0)];
    assert!(
        (pos[0] - want[0]).abs() < 1e-12 && (pos[1] - want[1]).abs() < 1e-12,
        "{pos:?} against {want:?}"
    );
    assert_eq!(xy(&ball["vel"]), [7.25, -2.875]);
    assert_eq!(out["events"], 0);
    // The hard-disk example: every disk inside the box.
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/hard_disks.json");
    let out = result(&simulate(&path, "50", None));
    for ball in out["balls"].as_array().unwrap() {
        let [x, y] = xy(&ball["pos"]);
        assert!(
            (0.0..25.0).contains(&x) && (0.0..25.0).contains(&y),
            "{ball}"
        );
        assert!(ball["unwrapped"].is_array(), "{ball}");
    }
}
