//! The benchmark suite: the cases, running one, and the table of results.

use std::time::Instant;

use exact2d::World;
use exact2d::scene::Scene;
use exact2d_bench::minimal::MinimalGas;
use exact2d_bench::scenes;

use crate::counting_alloc::live_bytes;
use crate::resident;

/// The seed of every scene of the suite.
const SEED: u64 = 1;

/// One benchmark: a scene, and when to stop.
pub struct Case {
    /// What the table calls the scene.
    pub label: String,
    /// The number of balls.
    pub balls: usize,
    make: Box<dyn Fn() -> Scene>,
    /// Stop once this many collisions are handled...
    collisions: Option<u64>,
    /// ...or at this simulated time, whichever comes first.
    until: f64,
    /// The clock advances by this much per `advance_to` call.
    dt: f64,
}

impl Case {
    /// What `--only` is matched against: the label and the ball count.
    pub fn name(&self) -> String {
        format!("{} {}", self.label, self.balls)
    }
}

/// The collisions a gas of `n` balls runs for: 20 per ball, at least 2 * 10^5, at most 10^7.
fn gas_collisions(n: usize) -> u64 {
    (20 * n as u64).clamp(200_000, 10_000_000)
}

/// Every case of the suite, in order; `quick` stops the gases at 10^4 balls.
pub fn cases(quick: bool) -> Vec<Case> {
    let sizes: &[usize] = if quick {
        &[1_000, 10_000]
    } else {
        &[1_000, 10_000, 100_000, 1_000_000]
    };
    let mut cases = Vec::new();
    for packing in [0.4, 0.7] {
        for &n in sizes {
            cases.push(Case {
                label: format!("gas {packing}"),
                balls: n,
                make: Box::new(move || scenes::gas(n, packing, SEED)),
                collisions: Some(gas_collisions(n)),
                // A cap that a gas never reaches: about one collision per ball per second.
                until: 1e6,
                dt: 0.05,
            });
        }
    }
    for packing in [0.4, 0.7] {
        for &n in sizes {
            cases.push(Case {
                label: format!("periodic {packing}"),
                balls: n,
                make: Box::new(move || scenes::periodic_gas(n, packing, SEED)),
                collisions: Some(gas_collisions(n)),
                until: 1e6,
                dt: 0.05,
            });
        }
    }
    // One ball ten times the others' radius: the cells follow the largest radius, so every
    // small ball's 3 x 3 block holds some hundred small balls (BENCHMARKS.md).
    cases.push(Case {
        label: "one large among small, 10x".to_owned(),
        balls: 1_000,
        make: Box::new(|| scenes::gas_with_large(1_000, 0.4, 10.0, SEED)),
        collisions: Some(gas_collisions(1_000)),
        until: 1e6,
        dt: 0.05,
    });
    for &n in sizes.iter().take(2) {
        cases.push(Case {
            label: "rough_disks 0.4".to_owned(),
            balls: n,
            make: Box::new(move || scenes::rough_gas(n, 0.4, SEED)),
            collisions: Some(gas_collisions(n)),
            until: 1e6,
            dt: 0.05,
        });
    }
    for n in [200, 1_000] {
        cases.push(Case {
            label: "brick_board".to_owned(),
            balls: n,
            make: Box::new(move || scenes::brick_board(n, SEED)),
            collisions: None,
            until: 60.0,
            dt: 1.0 / 60.0,
        });
    }
    cases.push(Case {
        label: "free_balls_in_box".to_owned(),
        balls: 10_000,
        make: Box::new(|| scenes::free_balls_in_box(10_000, SEED)),
        collisions: None,
        until: 20.0,
        dt: 1.0 / 60.0,
    });
    cases.push(Case {
        label: "pegs_gravity".to_owned(),
        balls: 1_000,
        make: Box::new(|| scenes::pegs_gravity(1_000, SEED)),
        collisions: None,
        until: 20.0,
        dt: 1.0 / 60.0,
    });
    cases
}

/// The measurements of one case.
pub struct Row {
    label: String,
    balls: usize,
    collisions: u64,
    simulated: f64,
    build_s: f64,
    wall_s: f64,
    bytes_per_ball: f64,
    energy_drift: f64,
}

impl Row {
    fn ns_per_collision(&self) -> f64 {
        self.wall_s * 1e9 / self.collisions.max(1) as f64
    }

    /// The row as a line of the markdown table.
    fn line(&self) -> String {
        format!(
            "| {} | {} | {} | {:.2} | {:.3} | {:.3} | {:.0} | {:.0} | {:.0} | {:.1e} |",
            self.label,
            self.balls,
            self.collisions,
            self.simulated,
            self.build_s,
            self.wall_s,
            self.collisions as f64 / self.wall_s,
            self.ns_per_collision(),
            self.bytes_per_ball,
            self.energy_drift,
        )
    }
}

const HEADER: &str = "| scene | N | collisions | simulated s | build s | wall s | collisions/s | ns/collision | bytes/ball | rel. energy drift |\n\
                      | --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |";

/// Kinetic (translational and rotational) plus potential energy, the potential measured
/// from the origin.
fn energy(world: &World) -> f64 {
    let g = world.gravity();
    world
        .balls()
        .map(|(_, b)| b.kinetic_energy() - b.mass * g.dot(b.position))
        .sum()
}

/// Builds and runs one case, printing progress on stderr when it takes a while.
///
/// # Errors
/// A message if the scene does not build or the world refuses a time (both would be bugs).
pub fn run(case: &Case) -> Result<Row, String> {
    run_with(case, || {})
}

/// [`run`], calling `on_built` once the world is built and the scene dropped, before the run.
fn run_with(case: &Case, on_built: impl FnOnce()) -> Result<Row, String> {
    let before = live_bytes();
    let start = Instant::now();
    let scene = (case.make)();
    let built = scene
        .build_world()
        .map_err(|e| format!("{}: the scene does not build: {e}", case.name()))?;
    drop(scene);
    let mut world = built.into_world();
    let build_s = start.elapsed().as_secs_f64();
    let bytes = live_bytes() as f64 - before as f64;
    on_built();

    let e0 = energy(&world);
    let start = Instant::now();
    let mut next_report = 1;
    let mut t = 0.0;
    loop {
        let done = world.event_counts().collisions();
        let fraction = match case.collisions {
            Some(target) => (done as f64 / target as f64).max(t / case.until),
            None => t / case.until,
        };
        if fraction >= 1.0 {
            break;
        }
        // Every 10%, once the run has taken more than two seconds.
        if fraction * 10.0 >= f64::from(next_report) {
            let elapsed = start.elapsed().as_secs_f64();
            if elapsed > 2.0 {
                eprintln!(
                    "  {}: {:.0}% ({done} collisions, t = {t:.2}, {elapsed:.1} s)",
                    case.name(),
                    fraction * 100.0
                );
            }
            next_report = (fraction * 10.0) as u32 + 1;
        }
        t = (t + case.dt).min(case.until);
        world
            .advance_to(t)
            .map_err(|e| format!("{}: {e}", case.name()))?;
    }
    let wall_s = start.elapsed().as_secs_f64();
    let e1 = energy(&world);
    Ok(Row {
        label: case.label.clone(),
        balls: case.balls,
        collisions: world.event_counts().collisions(),
        simulated: world.time(),
        build_s,
        wall_s,
        bytes_per_ball: bytes / case.balls as f64,
        energy_drift: ((e1 - e0) / e0).abs(),
    })
}

/// Runs `breaks` pool breaks ([`scenes::pool_break`], seeds 1 to `breaks`) each until every
/// ball is at rest (no event left), and prints their events (collisions and the internal
/// transitions: a slide ending in rolling, a roll or a spin stopping; pooltool counts the
/// same) per wall second.
///
/// # Errors
/// A message if a scene does not build or a world refuses a step (both would be bugs).
pub fn run_pool(breaks: u64) -> Result<(), String> {
    let (mut events, mut collisions, mut phases, mut wall) = (0u64, 0u64, 0u64, 0.0);
    let mut per_break = Vec::new();
    for seed in 1..=breaks {
        let scene = scenes::pool_break(seed);
        let mut world = scene
            .build_world()
            .map_err(|e| format!("pool break {seed}: the scene does not build: {e}"))?
            .into_world();
        let start = Instant::now();
        while world.step().is_some() {}
        wall += start.elapsed().as_secs_f64();
        let counts = world.event_counts();
        if world
            .balls()
            .any(|(_, b)| b.velocity != exact2d::DVec2::ZERO)
        {
            return Err(format!(
                "pool break {seed}: a ball still moves with no event left"
            ));
        }
        events += counts.handled();
        collisions += counts.collisions();
        phases += counts.phase_ends;
        per_break.push(counts.handled() as f64);
    }
    println!(
        "| scene | breaks | events | collisions | phase ends | median events a break | wall s | events/s |\n\
         | --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: |"
    );
    println!(
        "| pool break, 16 balls | {breaks} | {events} | {collisions} | {phases} | {:.0} | {wall:.3} | {:.0} |",
        median(per_break),
        events as f64 / wall
    );
    Ok(())
}

/// Runs `cases`, printing each row on stderr as it finishes, then the table and the growth
/// of the cost per collision with N on stdout.
///
/// # Errors
/// The first failing case's message.
pub fn run_all(cases: &[Case]) -> Result<(), String> {
    let mut rows = Vec::new();
    eprintln!("{HEADER}");
    for case in cases {
        let row = run(case)?;
        eprintln!("{}", row.line());
        rows.push(row);
    }
    println!("{HEADER}");
    for row in &rows {
        println!("{}", row.line());
    }
    println!();
    for label in GROWTH_LABELS {
        if let Some((small, large)) = smallest_and_largest(&rows, label, |r| (&r.label, r.balls)) {
            println!(
                "cost per collision, {label}: N={} / N={} = {:.2}",
                large.balls,
                small.balls,
                large.ns_per_collision() / small.ns_per_collision()
            );
        }
    }
    Ok(())
}

/// The gases whose cost per collision is compared from N = 1000 to the largest N run.
const GROWTH_LABELS: [&str; 4] = ["gas 0.4", "gas 0.7", "periodic 0.4", "periodic 0.7"];

/// Of the rows labelled `label` (`key` gives a row's label and N), the one at N = 1000 and
/// the one at the largest N, if that is larger: how the cost per collision grows.
fn smallest_and_largest<'a, R>(
    rows: &'a [R],
    label: &str,
    key: impl Fn(&R) -> (&str, usize),
) -> Option<(&'a R, &'a R)> {
    let gases: Vec<&R> = rows.iter().filter(|r| key(r).0 == label).collect();
    let small = gases.iter().find(|r| key(r).1 == 1_000)?;
    let large = gases.iter().max_by_key(|r| key(r).1)?;
    (key(large).1 > key(small).1).then_some((small, large))
}

/// The median of `values` (not empty).
fn median(mut values: Vec<f64>) -> f64 {
    values.sort_by(f64::total_cmp);
    let n = values.len();
    if n % 2 == 1 {
        values[n / 2]
    } else {
        0.5 * (values[n / 2 - 1] + values[n / 2])
    }
}

/// Runs the gas of `case` in [`MinimalGas`] for `collisions` collisions: its wall seconds.
fn run_minimal_case(case: &Case, collisions: u64) -> Result<f64, String> {
    run_minimal_with(case, collisions, || {})
}

/// [`run_minimal_case`], calling `built` once the gas is built and the scene dropped.
fn run_minimal_with(case: &Case, collisions: u64, built: impl FnOnce()) -> Result<f64, String> {
    let scene = (case.make)();
    let mut gas = MinimalGas::new(&scene).map_err(|e| format!("{}: {e}", case.name()))?;
    drop(scene);
    built();
    let start = Instant::now();
    gas.run(collisions, |_, _| {});
    Ok(start.elapsed().as_secs_f64())
}

/// Runs every gas case in the engine and in [`MinimalGas`] for the same collisions, one after
/// the other, `rounds` times, and prints the median rates and how the cost per collision
/// grows with N in each.
///
/// # Errors
/// The first failing case's message.
pub fn run_minimal(quick: bool, rounds: u32) -> Result<(), String> {
    const HEADER: &str = "| scene | N | collisions | exact2d collisions/s | minimal collisions/s | exact2d time / minimal time | exact2d peak bytes/disk | minimal peak bytes/disk |\n\
                          | --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: |";
    /// One gas, in both codes.
    struct Pair {
        label: String,
        balls: usize,
        line: String,
        /// Wall seconds per collision, in exact2d and in the minimal code.
        engine: f64,
        minimal: f64,
    }
    let mut rows = Vec::new();
    eprintln!("{HEADER}");
    for case in cases(quick)
        .iter()
        .filter(|c| c.label.starts_with("gas") || c.label.starts_with("periodic"))
    {
        let (mut engine, mut minimal, mut collisions) = (Vec::new(), Vec::new(), 0);
        for _ in 0..rounds {
            let row = run(case)?;
            collisions = row.collisions;
            engine.push(row.wall_s);
            minimal.push(run_minimal_case(case, collisions)?);
        }
        let (engine, minimal) = (median(engine), median(minimal));
        let per_disk = |minimal| {
            peak_in_child(case, collisions, minimal).map_or("n/a".to_string(), |b| {
                format!("{:.0}", b / case.balls as f64)
            })
        };
        let line = format!(
            "| {} | {} | {collisions} | {:.0} | {:.0} | {:.2} | {} | {} |",
            case.label,
            case.balls,
            collisions as f64 / engine,
            collisions as f64 / minimal,
            engine / minimal,
            per_disk(false),
            per_disk(true),
        );
        eprintln!("{line}");
        rows.push(Pair {
            label: case.label.clone(),
            balls: case.balls,
            line,
            engine: engine / collisions as f64,
            minimal: minimal / collisions as f64,
        });
    }
    println!("{HEADER}");
    for row in &rows {
        println!("{}", row.line);
    }
    println!();
    for label in GROWTH_LABELS {
        if let Some((small, large)) = smallest_and_largest(&rows, label, |r| (&r.label, r.balls)) {
            println!(
                "cost per collision, {label}, N={} / N={}: exact2d {:.2}, minimal {:.2}",
                large.balls,
                small.balls,
                large.engine / small.engine,
                large.minimal / small.minimal,
            );
        }
    }
    Ok(())
}

/// The peak resident bytes of the whole process while it runs `case` for `collisions`
/// collisions, its world (or the minimal code's gas) built: run in a child process of its own
/// (`exact2d-bench peak`), so that nothing an earlier case left resident is counted. `None`
/// (with a note on standard error) where the system does not say.
fn peak_in_child(case: &Case, collisions: u64, minimal: bool) -> Option<f64> {
    let exe = std::env::current_exe().ok()?;
    let mut command = std::process::Command::new(exe);
    command.args([
        "peak",
        "--label",
        &case.label,
        "--balls",
        &case.balls.to_string(),
        "--collisions",
        &collisions.to_string(),
    ]);
    if minimal {
        command.arg("--minimal");
    }
    let output = command.output().ok()?;
    let parsed = String::from_utf8_lossy(&output.stdout).trim().parse().ok();
    if parsed.is_none() {
        eprintln!(
            "  {}: no peak resident set ({})",
            case.name(),
            String::from_utf8_lossy(&output.stderr).trim()
        );
    }
    parsed
}

/// `exact2d-bench peak`: runs the gas labelled `label` with `balls` balls (a case of
/// [`run_minimal`]) in the engine or the minimal code for `collisions` collisions, and prints
/// the process's peak resident bytes from the moment the world is built (the scene dropped)
/// to the end of the run.
///
/// # Errors
/// No such case, a failing run, or a system that does not report the resident set.
pub fn print_peak(label: &str, balls: usize, collisions: u64, minimal: bool) -> Result<(), String> {
    let case = cases(false)
        .into_iter()
        .find(|c| c.label == label && c.balls == balls)
        .ok_or_else(|| format!("no gas \"{label}\" of {balls} balls in the suite"))?;
    let mut reset = false;
    if minimal {
        run_minimal_with(&case, collisions, || reset = resident::reset_peak())?;
    } else {
        let collisions_case = Case {
            collisions: Some(collisions),
            ..case
        };
        run_with(&collisions_case, || reset = resident::reset_peak())?;
    }
    let peak = resident::peak_bytes().filter(|_| reset).ok_or(
        "this system does not report the peak resident set (/proc/self/clear_refs, VmHWM)",
    )?;
    println!("{peak}");
    Ok(())
}
