//! Runs the same scene files in exact2d and in Rapier (at 60 Hz and at 240 Hz) and prints one
//! markdown table: speed, energy drift, penetration, error against the analytic path (balls in
//! a box), escapes.
//!
//! ```text
//! cargo run --release -p exact2d-vs-rapier -- [--seconds T] [--scenes-dir DIR] [SCENE.json ...]
//! cargo run --release -p exact2d-vs-rapier -- --pile N [--seconds T]
//! ```
//!
//! `--pile N` instead pours N balls into a box, with and without pegs, until they rest, in
//! exact2d and in Rapier at 60 Hz, both with sleeping on and no friction, and in both with
//! Rapier's default friction (Rapier's balls rolling; `pile.rs`).
//!
//! Without scene files it generates the standard set with `exact2d_bench::scenes`, writes it
//! to `DIR` (default `target/vs-rapier-scenes/` in the workspace) and reads the files back, so
//! that both engines run the same files. See this crate's README for what is measured and how
//! Rapier is set up.

mod engines;
mod measure;
mod pile;

use std::path::{Path, PathBuf};
use std::process::ExitCode;

use exact2d::scene::Scene;
use exact2d_bench::scenes;

use engines::{Engine, FRAME_HZ, rapier_parameters};
use measure::SceneGeometry;

const USAGE: &str = "usage: exact2d-vs-rapier [--seconds T] [--scenes-dir DIR] [SCENE.json ...]\n       exact2d-vs-rapier --pile N [--seconds T]";

/// Wall seconds exact2d may spend on one pile before the run is cut short (and said so).
const PILE_BUDGET: f64 = 300.0;

/// Simulated seconds per scene without `--seconds`.
const DEFAULT_SECONDS: f64 = 60.0;

/// The command line.
struct Args {
    seconds: Option<f64>,
    scenes_dir: Option<PathBuf>,
    files: Vec<PathBuf>,
    pile: Option<usize>,
}

/// A scene to compare: its name, its file and how long to run it.
struct Job {
    name: String,
    path: PathBuf,
    seconds: f64,
}

/// One row of the table: an engine on a scene.
struct Row {
    scene: String,
    seconds: f64,
    engine: Engine,
    wall_per_second: f64,
    drift_end: f64,
    drift_worst: f64,
    penetration: (f64, f64),
    position_error: Option<f64>,
    escaped: usize,
}

fn main() -> ExitCode {
    match run() {
        Ok(()) => ExitCode::SUCCESS,
        Err(message) => {
            eprintln!("exact2d-vs-rapier: {message}");
            ExitCode::from(2)
        }
    }
}

fn run() -> Result<(), String> {
    let Some(args) = parse_args(std::env::args().skip(1))? else {
        println!("{USAGE}");
        return Ok(());
    };
    let seconds = args.seconds.unwrap_or(DEFAULT_SECONDS);
    if let Some(balls) = args.pile {
        return pile::run(balls, seconds, PILE_BUDGET);
    }
    let jobs = if args.files.is_empty() {
        let dir = args.scenes_dir.clone().unwrap_or_else(|| {
            Path::new(env!("CARGO_MANIFEST_DIR")).join("../../target/vs-rapier-scenes")
        });
        write_standard_set(&dir, seconds)?
    } else {
        let job = |path: &PathBuf| Job {
            name: path.file_stem().map_or_else(
                || path.display().to_string(),
                |s| s.to_string_lossy().into_owned(),
            ),
            path: path.clone(),
            seconds,
        };
        args.files.iter().map(job).collect()
    };
    // Read every file first, so that a bad one stops the run before any measurement.
    let scenes = jobs
        .iter()
        .map(|job| read_scene(&job.path))
        .collect::<Result<Vec<_>, _>>()?;
    let mut rows = Vec::new();
    for (job, scene) in jobs.iter().zip(&scenes) {
        for engine in Engine::ALL {
            eprintln!(
                "running {} with {} for {} s",
                job.name,
                engine.label(),
                job.seconds
            );
            rows.push(measure(job, scene, engine)?);
        }
    }
    print_table(&rows);
    Ok(())
}

/// The command line; `None` for `--help`.
fn parse_args(mut args: impl Iterator<Item = String>) -> Result<Option<Args>, String> {
    let mut parsed = Args {
        seconds: None,
        scenes_dir: None,
        files: Vec::new(),
        pile: None,
    };
    while let Some(arg) = args.next() {
        match arg.as_str() {
            "-h" | "--help" => return Ok(None),
            "--seconds" => {
                let value = args.next().ok_or("--seconds needs a value")?;
                let seconds: f64 = value
                    .parse()
                    .map_err(|_| format!("--seconds: `{value}` is not a number"))?;
                if !(seconds > 0.0 && seconds <= 1e6) {
                    return Err(format!("--seconds must be in (0, 1e6], not {value}"));
                }
                parsed.seconds = Some(seconds);
            }
            "--pile" => {
                let value = args.next().ok_or("--pile needs a number of balls")?;
                let balls: usize = value
                    .parse()
                    .map_err(|_| format!("--pile: `{value}` is not a whole number"))?;
                if !(1..=100_000).contains(&balls) {
                    return Err(format!("--pile must be in [1, 100000], not {value}"));
                }
                parsed.pile = Some(balls);
            }
            "--scenes-dir" => {
                let value = args.next().ok_or("--scenes-dir needs a value")?;
                parsed.scenes_dir = Some(PathBuf::from(value));
            }
            flag if flag.starts_with('-') => return Err(format!("unknown option {flag}\n{USAGE}")),
            file => parsed.files.push(PathBuf::from(file)),
        }
    }
    if parsed.pile.is_some() && (parsed.scenes_dir.is_some() || !parsed.files.is_empty()) {
        return Err(format!("--pile runs its own scenes\n{USAGE}"));
    }
    if parsed.scenes_dir.is_some() && !parsed.files.is_empty() {
        return Err(format!(
            "--scenes-dir is for the generated set, not with scene files\n{USAGE}"
        ));
    }
    Ok(Some(parsed))
}

/// Generates the standard set with fixed seeds, writes it to `dir` and returns the jobs.
fn write_standard_set(dir: &Path, seconds: f64) -> Result<Vec<Job>, String> {
    let mut fast = scenes::free_balls_in_box(10, 3);
    for ball in &mut fast.balls {
        // Speeds 100 to 500 m/s: 1.7 to 8.3 m per 60 Hz frame in a 16 x 9 box.
        ball.vel = ball.vel.map(|v| v * 100.0);
    }
    let set = [
        ("brick_board_200", scenes::brick_board(200, 1)),
        ("free_box_1000", scenes::free_balls_in_box(1000, 2)),
        ("free_box_10_fast", fast),
        ("pegs_gravity_100", scenes::pegs_gravity(100, 4)),
        ("gas_1000", scenes::gas(1000, 0.4, 5)),
    ];
    std::fs::create_dir_all(dir).map_err(|e| format!("{}: {e}", dir.display()))?;
    let mut jobs = Vec::new();
    for (name, scene) in set {
        let path = dir.join(format!("{name}.json"));
        std::fs::write(&path, scene.to_json_string())
            .map_err(|e| format!("{}: {e}", path.display()))?;
        jobs.push(Job {
            name: name.to_owned(),
            path,
            seconds,
        });
    }
    Ok(jobs)
}

fn read_scene(path: &Path) -> Result<Scene, String> {
    let text = std::fs::read_to_string(path).map_err(|e| format!("{}: {e}", path.display()))?;
    let scene = Scene::from_json_str(&text).map_err(|e| format!("{}: {e}", path.display()))?;
    scene
        .validate()
        .map_err(|e| format!("{}: {e}", path.display()))?;
    Ok(scene)
}

/// Runs one engine on one scene and measures it at every frame.
fn measure(job: &Job, scene: &Scene, engine: Engine) -> Result<Row, String> {
    let geometry = SceneGeometry::new(scene);
    let initial: Vec<_> = scene
        .balls
        .iter()
        .map(|b| measure::BallState {
            position: b.pos.into(),
            velocity: b.vel.into(),
        })
        .collect();
    let e0 = geometry.energy(&initial);
    let drift = |e: f64| (e - e0).abs() / e0.abs().max(f64::MIN_POSITIVE);
    let frames = engines::frames(job.seconds);
    let mut row = Row {
        scene: job.name.clone(),
        seconds: frames as f64 / f64::from(FRAME_HZ),
        engine,
        wall_per_second: 0.0,
        drift_end: 0.0,
        drift_worst: 0.0,
        penetration: geometry.max_penetration(&initial),
        position_error: geometry.is_analytic().then_some(0.0),
        escaped: 0,
    };
    let wall = engine
        .run(scene, frames, |t, balls| {
            row.drift_end = drift(geometry.energy(balls));
            row.drift_worst = row.drift_worst.max(row.drift_end);
            let penetration = geometry.max_penetration(balls);
            if penetration.0 > row.penetration.0 {
                row.penetration = penetration;
            }
            if let Some(error) = geometry.position_error(t, balls) {
                row.position_error = row.position_error.map(|e| e.max(error));
            }
            row.escaped = geometry.escaped(balls);
        })
        .map_err(|e| format!("{}: {}: {e}", job.path.display(), engine.label()))?;
    row.wall_per_second = wall.as_secs_f64() / row.seconds;
    Ok(row)
}

fn print_table(rows: &[Row]) {
    println!(
        "| scene | engine | wall s per simulated s | x slower than exact2d | energy drift end (worst) \
         | max penetration (/ radius) | position error | escaped |"
    );
    println!("| --- | --- | ---: | ---: | --- | --- | ---: | ---: |");
    for row in rows {
        let exact = rows
            .iter()
            .find(|r| r.scene == row.scene && r.engine == Engine::Exact2d);
        let slower = match (row.engine, exact) {
            (Engine::Exact2d, _) | (_, None) => "1".to_owned(),
            (_, Some(exact)) => format!("{:.1}", row.wall_per_second / exact.wall_per_second),
        };
        println!(
            "| {} ({} s) | {} | {:.2e} | {} | {} ({}) | {} ({:.1}%) | {} | {} |",
            row.scene,
            row.seconds,
            row.engine.label(),
            row.wall_per_second,
            slower,
            sci(row.drift_end),
            sci(row.drift_worst),
            sci(row.penetration.0),
            100.0 * row.penetration.1,
            row.position_error.map_or_else(|| "-".to_owned(), sci),
            row.escaped,
        );
    }
    let p = rapier_parameters(1.0 / 60.0);
    println!(
        "\nRapier: rapier2d-f64 0.36, one core (no `parallel`), CCD on every ball, \
         max_ccd_substeps {}, {} solver iterations, contact softness {} Hz / damping {} \
         (static {} Hz), slop {}, prediction distance {}, no speed cap, no contact recycling.",
        p.max_ccd_substeps,
        p.num_solver_iterations,
        p.contact_softness.natural_frequency,
        p.contact_softness.damping_ratio,
        p.static_contact_softness.natural_frequency,
        p.normalized_allowed_linear_error,
        p.normalized_prediction_distance,
    );
    println!("{}", machine());
}

/// A number in short scientific notation, and plain 0 for zero.
fn sci(x: f64) -> String {
    if x == 0.0 {
        "0".to_owned()
    } else {
        format!("{x:.1e}")
    }
}

/// The machine: cores available and the CPU model.
fn machine() -> String {
    let cores = std::thread::available_parallelism().map_or(0, usize::from);
    let cpu = std::fs::read_to_string("/proc/cpuinfo")
        .ok()
        .and_then(|info| {
            info.lines()
                .find(|l| l.starts_with("model name"))
                .and_then(|l| l.split(':').nth(1))
                .map(|m| m.trim().to_owned())
        })
        .unwrap_or_else(|| "unknown CPU".to_owned());
    format!("Machine: nproc {cores}, {cpu}; one thread per engine, timing with std::time::Instant.")
}

#[cfg(test)]
mod tests {
    use super::*;

    fn parse(args: &[&str]) -> Result<Option<Args>, String> {
        parse_args(args.iter().map(|s| (*s).to_owned()))
    }

    #[test]
    fn a_pile_takes_a_count_of_balls_and_nothing_else() {
        let args = parse(&["--pile", "400", "--seconds", "60"])
            .unwrap()
            .unwrap();
        assert_eq!((args.pile, args.seconds), (Some(400), Some(60.0)));
        for (bad, message) in [
            (&["--pile", "0"][..], "--pile must be in [1, 100000], not 0"),
            (&["--pile", "-3"][..], "--pile: `-3` is not a whole number"),
            (&["--pile"][..], "--pile needs a number of balls"),
            (&["--pile", "5", "a.json"][..], "--pile runs its own scenes"),
        ] {
            let error = parse(bad).err().unwrap_or_default();
            assert!(error.starts_with(message), "{bad:?}: {error}");
        }
    }
}
