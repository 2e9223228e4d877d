//! Scene files (format version 1): one test per rule of `docs/scene-format.md` and per kind of
//! malformed input, each asserting the exact message, which must name the offending item by
//! its path in the file; then the exact round trip of `f64` values through JSON.

use exact2d::scene::{Scene, SceneBall, SceneError, SceneItem, SceneSegment};

/// The message of the error `text` is rejected with.
fn error(text: &str) -> String {
    match Scene::from_json_str(text) {
        Ok(scene) => panic!("accepted: {scene:?}"),
        Err(error) => error.to_string(),
    }
}

/// A scene of the given balls (JSON objects), with `extra` top-level keys before them.
fn with_balls(extra: &str, balls: &[&str]) -> String {
    format!(r#"{{ {extra} "balls": [ {} ] }}"#, balls.join(", "))
}

/// A valid ball: id, at (x, y), radius 0.5, moving right.
fn ball(id: u64, x: f64, y: f64) -> String {
    format!(r#"{{ "id": {id}, "pos": [{x:?}, {y:?}], "vel": [1.0, 0.0], "radius": 0.5 }}"#)
}

const WALL: &str = r#""segments": [ { "a": [-10, 0], "b": [10, 0] } ],"#;

// ---- defaults and a valid scene -------------------------------------------------------------

#[test]
fn a_minimal_scene_takes_the_defaults_of_the_format() {
    let scene = Scene::from_json_str(
        r#"{ "balls": [ { "id": 0, "pos": [1, 2], "vel": [3, 4], "radius": 0.5 } ] }"#,
    )
    .unwrap();
    assert_eq!(scene.gravity, [0.0, 0.0]);
    assert!(!scene.ball_ball);
    assert!(scene.segments.is_empty() && scene.circles.is_empty());
    let ball = &scene.balls[0];
    assert_eq!(
        (ball.id, ball.pos, ball.vel, ball.radius),
        (0, [1.0, 2.0], [3.0, 4.0], 0.5)
    );
    assert_eq!((ball.mass, ball.restitution), (1.0, 1.0));
}

#[test]
fn every_key_of_the_format_is_read() {
    let scene = Scene::from_json_str(
        r#"{ "gravity": [0.0, -9.81], "ball_ball": true,
             "segments": [ { "a": [0, 0], "b": [10, 0], "restitution": 0.5 } ],
             "circles": [ { "center": [5, 5], "radius": 0.5, "restitution": 0.25 } ],
             "balls": [ { "id": 9, "pos": [1, 1], "vel": [3, 2], "radius": 0.25, "mass": 2, "restitution": 0 } ] }"#,
    )
    .unwrap();
    assert_eq!(scene.gravity, [0.0, -9.81]);
    assert!(scene.ball_ball);
    assert_eq!(scene.segments[0].restitution, 0.5);
    assert_eq!(
        (scene.circles[0].center, scene.circles[0].radius),
        ([5.0, 5.0], 0.5)
    );
    assert_eq!(scene.circles[0].restitution, 0.25);
    assert_eq!(
        (
            scene.balls[0].id,
            scene.balls[0].mass,
            scene.balls[0].restitution
        ),
        (9, 2.0, 0.0)
    );
}

// ---- malformed JSON --------------------------------------------------------------------------

#[test]
fn an_empty_file_is_rejected() {
    let expected = "empty scene: expected a JSON object with a `balls` list";
    assert_eq!(error(""), expected);
    assert_eq!(error(" \n\t "), expected);
    assert_eq!(Scene::from_json_str(""), Err(SceneError::Empty));
}

#[test]
fn malformed_json_is_rejected_with_its_line_and_column() {
    assert_eq!(
        error("{ \"balls\": [\n  { \"id\": 0, }\n] }"),
        "balls[0]: trailing comma at line 2 column 14"
    );
    assert_eq!(
        error(r#"{ "balls": [ "#),
        "balls: EOF while parsing a list at line 1 column 13"
    );
    assert_eq!(
        error(r#"{ "balls": [] "#),
        "EOF while parsing an object at line 1 column 14"
    );
    assert_eq!(
        error(r#"{ balls: [] }"#),
        "key must be a string at line 1 column 3"
    );
}

#[test]
fn text_after_the_scene_is_rejected() {
    assert_eq!(
        error(r#"{ "balls": [] } x"#),
        "trailing characters at line 1 column 17"
    );
}

#[test]
fn a_document_that_is_not_an_object_is_rejected() {
    assert_eq!(
        error("[]"),
        "invalid type: sequence, expected a scene object at line 1 column 0"
    );
    assert_eq!(
        error("7"),
        "invalid type: integer `7`, expected a scene object at line 1 column 1"
    );
}

#[test]
fn an_error_message_stays_on_one_line() {
    let message = error(r#"{ "balls": [], "a\nb": 1 }"#);
    assert!(!message.contains('\n'), "{message}");
    assert!(
        message.starts_with(r"a\nb: unknown field `a\nb`"),
        "{message}"
    );
}

// ---- keys: unknown, missing, repeated --------------------------------------------------------

#[test]
fn an_unknown_top_level_key_is_rejected() {
    assert_eq!(
        error(r#"{ "balls": [], "foo": 1 }"#),
        "foo: unknown field `foo`, expected one of `gravity`, `ball_ball`, `segments`, `circles`, `balls`, `sleep`, `table`, `periodic` at line 1 column 20"
    );
}

#[test]
fn an_unknown_ball_key_is_rejected() {
    let text = with_balls(
        "",
        &[
            &ball(0, 0.0, 0.0),
            r#"{ "id": 1, "pos": [5, 5], "vel": [0, 0], "radius": 1, "colour": 1 }"#,
        ],
    );
    assert_eq!(
        error(&text),
        "balls[1].colour: unknown field `colour`, expected one of `id`, `pos`, `vel`, `radius`, `mass`, `restitution`, `spin`, `roll`, `inertia`, `friction`, `tangential_restitution`, `rolling_resistance` at line 1 column 142"
    );
}

#[test]
fn an_unknown_segment_key_is_rejected() {
    assert_eq!(
        error(r#"{ "segments": [ { "a": [0, 0], "b": [1, 0], "sensor": true } ], "balls": [] }"#),
        "segments[0].sensor: unknown field `sensor`, expected one of `a`, `b`, `restitution`, `friction`, `tangential_restitution`, `rolling_resistance` at line 1 column 52"
    );
}

#[test]
fn an_unknown_circle_key_is_rejected() {
    assert_eq!(
        error(r#"{ "circles": [ { "center": [0, 0], "radius": 1, "r": 1 } ], "balls": [] }"#),
        "circles[0].r: unknown field `r`, expected one of `center`, `radius`, `restitution`, `friction`, `tangential_restitution`, `rolling_resistance` at line 1 column 51"
    );
}

#[test]
fn a_missing_balls_list_is_rejected() {
    assert_eq!(
        error(r#"{ "gravity": [0, -1] }"#),
        "missing field `balls` at line 1 column 22"
    );
    assert_eq!(error("{}"), "missing field `balls` at line 1 column 2");
}

#[test]
fn a_missing_required_key_is_rejected() {
    assert_eq!(
        error(r#"{ "balls": [ { "id": 0, "pos": [0, 0], "vel": [0, 0] } ] }"#),
        "balls[0]: missing field `radius` at line 1 column 54"
    );
    assert_eq!(
        error(r#"{ "segments": [ { "a": [0, 0] } ], "balls": [] }"#),
        "segments[0]: missing field `b` at line 1 column 31"
    );
}

#[test]
fn a_repeated_key_is_rejected() {
    assert_eq!(
        error(
            r#"{ "balls": [ { "id": 0, "id": 1, "pos": [0, 0], "vel": [0, 0], "radius": 1 } ] }"#
        ),
        "balls[0]: duplicate field `id` at line 1 column 28"
    );
}

// ---- types -----------------------------------------------------------------------------------

#[test]
fn a_vector_must_be_two_numbers() {
    let base = r#"{ "balls": [ { "id": 0, "pos": POS, "vel": [0, 0], "radius": 1 } ] }"#;
    let expected = |what: &str, column: usize| {
        format!(
            "balls[0].pos: {what}, expected an array of two numbers [x, y] at line 1 column {column}"
        )
    };
    assert_eq!(
        error(&base.replace("POS", "[1, 2, 3]")),
        expected("invalid length 3", 40)
    );
    assert_eq!(
        error(&base.replace("POS", "[1]")),
        expected("invalid length 1", 34)
    );
    assert_eq!(
        error(&base.replace("POS", "[]")),
        expected("invalid length 0", 33)
    );
    assert_eq!(
        error(&base.replace("POS", r#""here""#)),
        expected(r#"invalid type: string "here""#, 37)
    );
    assert_eq!(
        error(&base.replace("POS", r#"{"x": 1}"#)),
        expected("invalid type: map", 31)
    );
    assert_eq!(
        error(&base.replace("POS", r#"[1, "2"]"#)),
        "balls[0].pos[1]: invalid type: string \"2\", expected f64 at line 1 column 38"
    );
}

#[test]
fn a_number_of_the_wrong_type_is_rejected() {
    assert_eq!(
        error(r#"{ "balls": [ { "id": 0, "pos": [0, 0], "vel": [0, 0], "radius": "1" } ] }"#),
        "balls[0].radius: invalid type: string \"1\", expected f64 at line 1 column 67"
    );
    assert_eq!(
        error(r#"{ "balls": [ { "id": 0, "pos": [0, 0], "vel": [0, 0], "radius": null } ] }"#),
        "balls[0].radius: invalid type: null, expected f64 at line 1 column 68"
    );
}

#[test]
fn ball_ball_must_be_a_boolean() {
    assert_eq!(
        error(r#"{ "ball_ball": 1, "balls": [] }"#),
        "ball_ball: invalid type: integer `1`, expected a boolean at line 1 column 16"
    );
}

#[test]
fn lists_must_be_lists() {
    assert_eq!(
        error(r#"{ "balls": { "id": 0 } }"#),
        "balls: invalid type: map, expected a sequence at line 1 column 11"
    );
    assert_eq!(
        error(r#"{ "segments": [ [0, 0, 1, 0] ], "balls": [] }"#),
        "segments[0]: invalid type: sequence, expected a segment object at line 1 column 16"
    );
}

#[test]
fn an_item_written_as_an_array_of_its_values_is_rejected() {
    // Serde's derive alone would read these as a ball and as a whole scene.
    assert_eq!(
        error(r#"{ "balls": [ [0, [1, 2], [3, 4], 0.5] ] }"#),
        "balls[0]: invalid type: sequence, expected a ball object at line 1 column 13"
    );
    assert_eq!(
        error(r#"[ [0, 0], false, [], [], [] ]"#),
        "invalid type: sequence, expected a scene object at line 1 column 0"
    );
}

// ---- ids -------------------------------------------------------------------------------------

#[test]
fn an_id_must_be_a_non_negative_integer() {
    let base = r#"{ "balls": [ { "id": ID, "pos": [0, 0], "vel": [0, 0], "radius": 1 } ] }"#;
    let with_id = |id: &str| error(&base.replace("ID", id));
    assert_eq!(
        with_id("1.5"),
        "balls[0].id: invalid type: floating point `1.5`, expected a non-negative integer at line 1 column 24"
    );
    assert_eq!(
        with_id("1.0"),
        "balls[0].id: invalid type: floating point `1.0`, expected a non-negative integer at line 1 column 24"
    );
    assert_eq!(
        with_id("-1"),
        "balls[0].id: invalid value: integer `-1`, expected a non-negative integer at line 1 column 23"
    );
    assert_eq!(
        with_id(r#""7""#),
        "balls[0].id: invalid type: string \"7\", expected a non-negative integer at line 1 column 24"
    );
    assert_eq!(
        with_id("18446744073709551616"),
        "balls[0].id: invalid type: floating point `1.8446744073709552e+19`, expected a non-negative integer at line 1 column 41"
    );
}

#[test]
fn the_largest_id_is_accepted() {
    let text = with_balls("", &[&ball(u64::MAX, 0.0, 0.0)]);
    assert_eq!(Scene::from_json_str(&text).unwrap().balls[0].id, u64::MAX);
}

#[test]
fn a_duplicate_id_is_rejected_naming_the_later_ball() {
    let text = with_balls(
        "",
        &[
            &ball(7, 0.0, 0.0),
            &ball(3, 5.0, 0.0),
            &ball(7, 10.0, 0.0),
            &ball(3, 15.0, 0.0),
        ],
    );
    assert_eq!(error(&text), "balls[2]: duplicate id 7");
    assert_eq!(
        Scene::from_json_str(&text),
        Err(SceneError::DuplicateId {
            index: 2,
            first: 0,
            id: 7
        })
    );
}

// ---- numbers ---------------------------------------------------------------------------------

#[test]
fn a_number_too_large_for_an_f64_is_rejected_not_made_infinite() {
    let text = r#"{ "balls": [ { "id": 0, "pos": [0, 1e400], "vel": [0, 0], "radius": 1 } ] }"#;
    assert_eq!(
        error(text),
        "balls[0].pos[1]: number out of range at line 1 column 40"
    );
    let text = r#"{ "gravity": [-1e400, 0], "balls": [] }"#;
    assert_eq!(
        error(text),
        "gravity[0]: number out of range at line 1 column 20"
    );
}

#[test]
fn nan_and_infinity_are_not_json() {
    let text = r#"{ "balls": [ { "id": 0, "pos": [NaN, 0], "vel": [0, 0], "radius": 1 } ] }"#;
    assert_eq!(
        error(text),
        "balls[0].pos[0]: expected value at line 1 column 33"
    );
    let text = r#"{ "balls": [ { "id": 0, "pos": [0, 0], "vel": [0, 0], "radius": Infinity } ] }"#;
    assert_eq!(
        error(text),
        "balls[0].radius: expected value at line 1 column 65"
    );
}

#[test]
fn a_non_finite_number_in_a_scene_built_in_code_is_rejected() {
    let scene = |change: fn(&mut Scene)| {
        let mut scene = Scene::from_json_str(&with_balls(WALL, &[&ball(0, 0.0, 1.0)])).unwrap();
        change(&mut scene);
        scene.validate().unwrap_err().to_string()
    };
    assert_eq!(
        scene(|s| s.gravity[1] = f64::NAN),
        "gravity[1] must be finite"
    );
    assert_eq!(
        scene(|s| s.segments[0].b[0] = f64::INFINITY),
        "segments[0].b[0] must be finite"
    );
    assert_eq!(
        scene(|s| s.balls[0].vel[1] = f64::NEG_INFINITY),
        "balls[0].vel[1] must be finite"
    );
    assert_eq!(
        scene(|s| s.balls[0].radius = f64::INFINITY),
        "balls[0].radius must be finite"
    );
    assert_eq!(
        scene(|s| s.balls[0].mass = f64::NAN),
        "balls[0].mass must be finite"
    );
    assert_eq!(
        scene(|s| s.balls[0].restitution = f64::NAN),
        "balls[0].restitution must be finite"
    );
}

#[test]
fn a_radius_must_be_positive() {
    let text = with_balls(
        "",
        &[
            &ball(0, 0.0, 0.0),
            r#"{ "id": 1, "pos": [5, 0], "vel": [0, 0], "radius": 0 }"#,
        ],
    );
    assert_eq!(error(&text), "balls[1].radius must be > 0");
    let text = with_balls(
        "",
        &[r#"{ "id": 1, "pos": [5, 0], "vel": [0, 0], "radius": -0.5 }"#],
    );
    assert_eq!(error(&text), "balls[0].radius must be > 0");
    let text = with_balls(
        "",
        &[r#"{ "id": 1, "pos": [5, 0], "vel": [0, 0], "radius": -0.0 }"#],
    );
    assert_eq!(error(&text), "balls[0].radius must be > 0");
    let text = with_balls(
        r#""circles": [ { "center": [0, 0], "radius": 1 }, { "center": [5, 0], "radius": 0 } ],"#,
        &[],
    );
    assert_eq!(error(&text), "circles[1].radius must be > 0");
}

#[test]
fn a_mass_must_be_positive() {
    let text = with_balls(
        "",
        &[r#"{ "id": 1, "pos": [5, 0], "vel": [0, 0], "radius": 1, "mass": 0 }"#],
    );
    assert_eq!(error(&text), "balls[0].mass must be > 0");
    let text = with_balls(
        "",
        &[r#"{ "id": 1, "pos": [5, 0], "vel": [0, 0], "radius": 1, "mass": -2 }"#],
    );
    assert_eq!(error(&text), "balls[0].mass must be > 0");
}

#[test]
fn the_smallest_positive_radius_and_mass_are_accepted() {
    let text = with_balls(
        "",
        &[r#"{ "id": 1, "pos": [5, 0], "vel": [0, 0], "radius": 5e-324, "mass": 5e-324 }"#],
    );
    assert!(Scene::from_json_str(&text).is_ok());
}

#[test]
fn a_restitution_must_be_in_zero_one() {
    let ball_with = |e: &str| {
        with_balls(
            "",
            &[&format!(
                r#"{{ "id": 1, "pos": [5, 5], "vel": [0, 0], "radius": 1, "restitution": {e} }}"#
            )],
        )
    };
    assert_eq!(
        error(&ball_with("1.5")),
        "balls[0].restitution must be in [0, 1]"
    );
    assert_eq!(
        error(&ball_with("-0.1")),
        "balls[0].restitution must be in [0, 1]"
    );
    assert_eq!(
        error(&ball_with("1.0000000000000002")),
        "balls[0].restitution must be in [0, 1]"
    );
    assert!(Scene::from_json_str(&ball_with("0")).is_ok());
    assert!(Scene::from_json_str(&ball_with("1")).is_ok());
    let text = with_balls(
        r#""segments": [ { "a": [0, 0], "b": [1, 0], "restitution": -0.5 } ],"#,
        &[],
    );
    assert_eq!(error(&text), "segments[0].restitution must be in [0, 1]");
    let text = with_balls(
        r#""circles": [ { "center": [0, 0], "radius": 1, "restitution": 2 } ],"#,
        &[],
    );
    assert_eq!(error(&text), "circles[0].restitution must be in [0, 1]");
}

// ---- segments --------------------------------------------------------------------------------

#[test]
fn a_segment_needs_two_distinct_end_points() {
    let text = with_balls(
        r#""segments": [ { "a": [0, 0], "b": [1, 0] }, { "a": [0, 1], "b": [1, 1] }, { "a": [2, 2], "b": [2.0, 2e0] } ],"#,
        &[],
    );
    assert_eq!(error(&text), "segments[2]: end points must be distinct");
}

#[test]
fn a_segment_whose_squared_length_overflows_or_underflows_is_rejected() {
    let message = "segments[0]: length out of range (its square must be a positive finite f64)";
    let text = with_balls(r#""segments": [ { "a": [0, 0], "b": [1e155, 0] } ],"#, &[]);
    assert_eq!(error(&text), message);
    let text = with_balls(r#""segments": [ { "a": [0, 0], "b": [0, 1e-170] } ],"#, &[]);
    assert_eq!(error(&text), message);
    let text = with_balls(
        r#""segments": [ { "a": [0, 0], "b": [1e150, 1e-150] } ],"#,
        &[],
    );
    assert!(Scene::from_json_str(&text).is_ok());
}

// ---- overlaps at time 0 ----------------------------------------------------------------------

#[test]
fn a_ball_overlapping_a_segment_is_rejected() {
    // The wall is y = 0; balls[1] reaches 0.1 below it.
    let text = with_balls(WALL, &[&ball(0, 0.0, 3.0), &ball(1, 2.0, 0.4)]);
    assert_eq!(error(&text), "balls[1] overlaps segments[0]");
}

#[test]
fn a_ball_overlapping_a_segment_end_point_is_rejected() {
    // Beyond the end point (10, 0): the distance to the segment is the distance to the corner.
    let text = with_balls(WALL, &[&ball(0, 10.3, 0.3)]);
    assert_eq!(error(&text), "balls[0] overlaps segments[0]");
    assert!(Scene::from_json_str(&with_balls(WALL, &[&ball(0, 10.3, 0.41)])).is_ok());
}

#[test]
fn a_ball_overlapping_a_circle_is_rejected() {
    let circles =
        r#""circles": [ { "center": [20, 20], "radius": 1 }, { "center": [0, 0], "radius": 1 } ],"#;
    let text = with_balls(circles, &[&ball(0, 1.2, 0.0)]);
    assert_eq!(error(&text), "balls[0] overlaps circles[1]");
}

#[test]
fn a_ball_inside_a_circle_is_rejected() {
    let text = with_balls(
        r#""circles": [ { "center": [0, 0], "radius": 5 } ],"#,
        &[&ball(0, 1.0, 1.0)],
    );
    assert_eq!(error(&text), "balls[0] overlaps circles[0]");
}

#[test]
fn balls_overlapping_each_other_are_rejected_when_they_collide() {
    let balls = [ball(0, 0.0, 0.0), ball(1, 5.0, 0.0), ball(2, 0.9, 0.0)];
    let balls: Vec<&str> = balls.iter().map(String::as_str).collect();
    assert_eq!(
        error(&with_balls(r#""ball_ball": true,"#, &balls)),
        "balls[2] overlaps balls[0]"
    );
}

#[test]
fn balls_may_overlap_each_other_when_they_do_not_collide() {
    let balls = [ball(0, 0.0, 0.0), ball(1, 0.0, 0.0), ball(2, 0.1, 0.0)];
    let balls: Vec<&str> = balls.iter().map(String::as_str).collect();
    assert!(Scene::from_json_str(&with_balls("", &balls)).is_ok());
    assert!(Scene::from_json_str(&with_balls(r#""ball_ball": false,"#, &balls)).is_ok());
}

#[test]
fn touching_is_allowed() {
    // Exactly touching a segment, a circle and another ball (radius 0.5 each).
    let text = with_balls(
        &format!(
            r#"{WALL} "circles": [ {{ "center": [5, 0.5], "radius": 1 }} ], "ball_ball": true,"#
        ),
        &[&ball(0, 0.0, 0.5), &ball(1, 1.0, 0.5), &ball(2, 3.5, 0.5)],
    );
    assert!(Scene::from_json_str(&text).is_ok());
}

#[test]
fn an_overlap_within_the_tolerance_counts_as_touching() {
    // OVERLAP_TOLERANCE is 1e-9 of the contact distance (here the radius, 0.5).
    let inside = |depth: f64| with_balls(WALL, &[&ball(0, 0.0, 0.5 - depth)]);
    assert!(Scene::from_json_str(&inside(0.25e-9)).is_ok());
    assert_eq!(error(&inside(1e-9)), "balls[0] overlaps segments[0]");
}

/// Text of a scene from its top-level keys and its balls.
fn scene_of(keys: &str, balls: &[String]) -> String {
    let balls: Vec<&str> = balls.iter().map(String::as_str).collect();
    with_balls(keys, &balls)
}

#[test]
fn the_first_overlapping_ball_is_reported() {
    // Only balls[1] and balls[2] overlap anything; balls[1] comes first.
    let balls = [ball(0, 0.0, 3.0), ball(1, 0.0, 0.2), ball(2, 0.0, 0.1)];
    assert_eq!(
        error(&scene_of(WALL, &balls)),
        "balls[1] overlaps segments[0]"
    );
}

#[test]
fn a_segment_is_named_before_a_circle_and_a_circle_before_a_ball() {
    let statics = r#""ball_ball": true,
        "segments": [ { "a": [-10, 0], "b": [10, 0] }, { "a": [-10, 0.5], "b": [10, 0.5] } ],
        "circles": [ { "center": [3, -1], "radius": 1 } ],"#;
    // balls[1] overlaps balls[0], both segments and the circle; balls[0] nothing.
    let balls = [ball(0, 2.5, 1.3), ball(1, 2.5, 0.4)];
    assert_eq!(
        Scene::from_json_str(&scene_of(statics, &balls)),
        Err(SceneError::Overlap {
            ball: 1,
            other: SceneItem::Segment(0)
        })
    );
    let circle = r#""ball_ball": true, "circles": [ { "center": [3, -1], "radius": 1 } ],"#;
    assert_eq!(
        error(&scene_of(circle, &balls)),
        "balls[1] overlaps circles[0]"
    );
}

#[test]
fn the_earliest_of_several_overlapped_balls_is_named() {
    let balls = [ball(0, 0.0, 0.0), ball(1, 1.5, 0.0), ball(2, 0.75, 0.0)];
    assert_eq!(
        error(&scene_of(r#""ball_ball": true,"#, &balls)),
        "balls[2] overlaps balls[0]"
    );
}

#[test]
fn rules_are_checked_in_file_order_numbers_then_ids_then_overlaps() {
    // balls[0] overlaps the wall, balls[2] repeats an id, balls[3] has a bad radius.
    let text = with_balls(
        WALL,
        &[
            &ball(0, 0.0, 0.1),
            &ball(1, 3.0, 3.0),
            &ball(1, 6.0, 3.0),
            r#"{ "id": 5, "pos": [9, 9], "vel": [0, 0], "radius": 0 }"#,
        ],
    );
    assert_eq!(error(&text), "balls[3].radius must be > 0");
    let text = with_balls(
        WALL,
        &[&ball(0, 0.0, 0.1), &ball(1, 3.0, 3.0), &ball(1, 6.0, 3.0)],
    );
    assert_eq!(error(&text), "balls[2]: duplicate id 1");
}

// ---- round trip ------------------------------------------------------------------------------

/// Values whose shortest decimal form is long, subnormal, or at the ends of the range.
const AWKWARD: [f64; 10] = [
    0.1 + 0.2,
    1e-310,
    5e-324,
    1.7976931348623157e308,
    -0.0,
    1.0 / 3.0,
    -2.0 / 3.0,
    9007199254740993.0,
    2.2250738585072014e-308,
    123456.789e-5,
];

#[test]
fn every_f64_survives_a_round_trip_through_json() {
    let mut scene = Scene::default();
    for (k, pair) in AWKWARD.chunks(2).enumerate() {
        let [x, y] = [pair[0], pair[1]];
        let radius = AWKWARD[k].abs().clamp(5e-324, 1e-3);
        let mass = AWKWARD[(k + 3) % AWKWARD.len()].abs().max(5e-324);
        let pos = [1e6 * k as f64 + 0.1 + 0.2, 1e-310];
        scene.balls.push(SceneBall {
            id: k as u64,
            pos,
            vel: [x, y],
            radius,
            mass,
            restitution: 1.0 / 3.0,
            spin: 0.0,
            inertia: 0.5,
            friction: 0.0,
            tangential_restitution: 0.0,
            rolling_resistance: 0.0,
            roll: [0.0, 0.0],
        });
    }
    scene.gravity = [AWKWARD[0], AWKWARD[1]];
    scene.segments.push(SceneSegment {
        a: [1e100, 1e-310],
        b: [1e100 + 1e85, 1.7976931348623157e100],
        restitution: 0.1 + 0.2,
        friction: 0.0,
        tangential_restitution: 0.0,
        rolling_resistance: 0.0,
    });
    if let Err(e) = scene.validate() {
        panic!("{e}");
    }

    let text = scene.to_json_string();
    let back = Scene::from_json_str(&text).unwrap();
    assert_eq!(bits(&back), bits(&scene), "{text}");
    // Writing again gives the same text.
    assert_eq!(back.to_json_string(), text);
}

#[test]
fn numbers_in_the_file_read_to_the_nearest_f64() {
    let text = r#"{ "gravity": [0.30000000000000004, 1e-310], "balls": [],
                   "circles": [ { "center": [5e-324, -0.0], "radius": 1.7976931348623157e308 } ] }"#;
    let scene = Scene::from_json_str(text).unwrap();
    assert_eq!(scene.gravity[0].to_bits(), (0.1f64 + 0.2).to_bits());
    assert_eq!(scene.gravity[1].to_bits(), 1e-310f64.to_bits());
    assert_eq!(scene.circles[0].center[0].to_bits(), 1);
    assert_eq!(scene.circles[0].center[1].to_bits(), (-0.0f64).to_bits());
    assert_eq!(scene.circles[0].radius, f64::MAX);
}

/// Every number of a scene, as bits (so -0.0 and 0.0 differ).
fn bits(scene: &Scene) -> Vec<u64> {
    let mut out: Vec<u64> = scene.gravity.iter().map(|x| x.to_bits()).collect();
    for s in &scene.segments {
        out.extend(
            s.a.iter()
                .chain(&s.b)
                .chain([&s.restitution])
                .map(|x| x.to_bits()),
        );
    }
    for b in &scene.balls {
        out.push(b.id);
        out.extend(
            b.pos
                .iter()
                .chain(&b.vel)
                .chain([&b.radius, &b.mass, &b.restitution])
                .map(|x| x.to_bits()),
        );
    }
    out
}

// ---- periodic boxes ---------------------------------------------------------------------------

#[test]
fn a_periodic_box_is_read_and_checked() {
    const BOX: &str = r#""periodic": [10, 8], "ball_ball": true,"#;
    let scene = Scene::from_json_str(&with_balls(BOX, &[&ball(0, 5.0, 4.0)])).unwrap();
    assert_eq!(scene.periodic, Some([10.0, 8.0]));
    assert!(
        Scene::from_json_str(&with_balls("", &[&ball(0, 5.0, 4.0)]))
            .unwrap()
            .periodic
            .is_none()
    );
    assert_eq!(
        error(&with_balls(
            r#""periodic": [10, 0],"#,
            &[&ball(0, 5.0, 4.0)]
        )),
        "periodic must be > 0 on both sides"
    );
    assert_eq!(
        error(&with_balls(
            r#""periodic": [10, 8], "gravity": [0, -1],"#,
            &[&ball(0, 5.0, 4.0)]
        )),
        "gravity must be [0, 0] in a periodic box"
    );
    assert_eq!(
        error(&with_balls(BOX, &[&ball(0, 5.0, 4.0), &ball(1, 10.0, 4.0)])),
        "balls[1].pos must be inside the periodic box [0, Lx) x [0, Ly)"
    );
    assert_eq!(
        error(&with_balls(
            r#""periodic": [3, 8], "ball_ball": true,"#,
            &[&ball(0, 1.0, 4.0)]
        )),
        "balls[0].radius must be at most min(Lx, Ly) / 6.6 in a periodic box"
    );
    let near = r#""periodic": [10, 8], "circles": [ { "center": [1, 4], "radius": 0.6 } ],"#;
    assert_eq!(
        error(&with_balls(near, &[&ball(0, 5.0, 4.0)])),
        "circles[0] must be clear of the periodic box's edges by more than the largest ball's radius"
    );
}

#[test]
fn balls_overlapping_through_a_periodic_edge_are_rejected() {
    // 0.2 from one edge and 9.3 from it across the other: 0.9 apart through the edge.
    const BOX: &str = r#""periodic": [10, 8], "ball_ball": true,"#;
    assert_eq!(
        error(&with_balls(BOX, &[&ball(0, 0.2, 4.0), &ball(1, 9.3, 4.2)])),
        "balls[1] overlaps balls[0]"
    );
    // Touching through the corner is allowed, and the world builds.
    let corner = with_balls(BOX, &[&ball(0, 0.0, 0.0), &ball(1, 9.0, 0.0)]);
    let scene = Scene::from_json_str(&corner).unwrap();
    assert!(scene.build_world().is_ok());
}
