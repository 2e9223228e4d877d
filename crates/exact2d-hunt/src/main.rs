//! `exact2d-hunt`: runs adversarial scenes (see the library) and tallies what breaks.
//!
//! ```text
//! exact2d-hunt [--from SEED] [--count N] [--seconds S] [--until T] [--events N] [--out DIR]
//!              [--rough] [--table | --periodic] [--collapse T_C]
//! ```
//!
//! Seeds `SEED, SEED + 1, ...` are generated and run until `N` seeds are done or `S` wall
//! seconds have passed, each to simulated time `T` or `N` events. Standard output gets one
//! line per finding (seed, motifs, scale, offset, the invariant and its detail) and a summary
//! line (JSON); `--out` also writes each finding's scene as `DIR/seed-SEED.json`, to replay
//! with `exact2d soak` or `exact2d simulate`. Progress goes to standard error. Exit codes: 0
//! nothing found, 1 something found (or a file could not be written), 2 bad arguments.

use std::collections::BTreeMap;
use std::io::Write;
use std::path::PathBuf;
use std::process::ExitCode;
use std::time::{Duration, Instant};

use clap::Parser;
use exact2d_hunt::generate::{Options, ROUGH_SEED, TABLE_SEED, generate, lay_on_table, roughen};
use exact2d_hunt::periodic::generate_periodic;
use exact2d_hunt::run::{Limits, run};
use exact2d_hunt::source::SplitMix64;
use serde::Serialize;

/// Run adversarial scenes (exact fits, touching placements, wedges, funnels, far offsets)
/// through exact2d, checking every invariant after every event.
#[derive(Parser)]
#[command(name = "exact2d-hunt", version)]
struct Args {
    /// The first seed
    #[arg(long, default_value_t = 0)]
    from: u64,
    /// How many seeds, at most
    #[arg(long, value_parser = parse_count)]
    count: Option<u64>,
    /// Stop after this many wall-clock seconds (a number > 0)
    #[arg(long, value_parser = parse_seconds)]
    seconds: Option<f64>,
    /// Simulated seconds per scene (a number > 0)
    #[arg(long, default_value_t = 3.0, value_parser = parse_seconds)]
    until: f64,
    /// Events per scene, at most: a scene that needs more is counted as slow
    #[arg(long, default_value_t = 300_000, value_parser = parse_count)]
    events: u64,
    /// Write each finding's scene here as seed-SEED.json
    #[arg(long, value_name = "DIR")]
    out: Option<PathBuf>,
    /// Give every seed's scene friction, tangential restitution, rolling resistance and spin
    /// (the same geometry; see `generate::roughen`)
    #[arg(long)]
    rough: bool,
    /// Make every seed's scene a table seen from above: no gravity in the plane, a cloth
    /// with sliding, rolling and spinning friction, balls with rolls (the same geometry; see
    /// `generate::lay_on_table`)
    #[arg(long)]
    table: bool,
    /// Make every seed's scene a periodic box instead (see `periodic::generate_periodic`):
    /// balls on and through its edges, rows wrapping round it, boxes as small as the engine
    /// takes; `--rough` adds friction at the impacts.
    #[arg(long, conflicts_with = "table")]
    periodic: bool,
    /// Give every seed's world this collapse time (the TC model, `World::set_collapse_time`;
    /// a number >= 0, 0 for none). The scene files `--out` writes do not carry it: replay a
    /// finding with the same flag.
    #[arg(long, default_value_t = 0.0, value_parser = parse_collapse)]
    collapse: f64,
}

fn parse_count(text: &str) -> Result<u64, String> {
    match text.trim().parse::<u64>() {
        Ok(0) => Err("must be at least 1".to_owned()),
        Ok(n) => Ok(n),
        Err(_) => Err("not a whole number >= 1".to_owned()),
    }
}

fn parse_seconds(text: &str) -> Result<f64, String> {
    match text.trim().parse::<f64>() {
        Ok(s) if s > 0.0 && s.is_finite() => Ok(s),
        _ => Err("must be a finite number > 0".to_owned()),
    }
}

fn parse_collapse(text: &str) -> Result<f64, String> {
    match text.trim().parse::<f64>() {
        Ok(t) if t >= 0.0 && t.is_finite() => Ok(t),
        _ => Err("must be a finite number >= 0".to_owned()),
    }
}

fn main() -> ExitCode {
    let args = Args::parse();
    let count = args.count.unwrap_or(if args.seconds.is_some() {
        u64::MAX
    } else {
        1000
    });
    let limit = args.seconds.map(Duration::from_secs_f64);
    let limits = Limits {
        until: args.until,
        events: args.events,
        collapse: args.collapse,
    };
    let start = Instant::now();
    let (mut seeds, mut slow, mut found) = (0u64, 0u64, 0u64);
    let mut classes: BTreeMap<&'static str, u64> = BTreeMap::new();
    let mut busiest = (0u64, 0usize, 0u64);
    let mut stdout = std::io::stdout().lock();
    for seed in args.from..args.from.saturating_add(count) {
        if limit.is_some_and(|l| start.elapsed() >= l) {
            break;
        }
        let mut generated = if args.periodic {
            generate_periodic(&mut SplitMix64(seed))
        } else {
            generate(&mut SplitMix64(seed), Options::default())
        };
        if args.rough {
            roughen(&mut generated.scene, &mut SplitMix64(seed ^ ROUGH_SEED));
        }
        if args.table {
            let scale = generated.scale;
            lay_on_table(
                &mut generated.scene,
                scale,
                &mut SplitMix64(seed ^ TABLE_SEED),
            );
        }
        let outcome = run(&generated, limits);
        seeds += 1;
        slow += u64::from(outcome.slow);
        let (events, balls) = outcome.busiest;
        if events * (busiest.1 as u64 + 1) > busiest.0 * (balls as u64 + 1) {
            busiest = (events, balls, seed);
        }
        if let Some(finding) = outcome.finding {
            found += 1;
            *classes.entry(finding.class.name()).or_insert(0) += 1;
            let motifs: Vec<&str> = generated.motifs.iter().map(|m| m.name()).collect();
            let collapse = if args.collapse > 0.0 {
                format!(" collapse {:e}", args.collapse)
            } else {
                String::new()
            };
            let line = format!(
                "seed {seed} [{}] scale {:e} offset {:e}{collapse}: {finding}",
                motifs.join(","),
                generated.scale,
                generated.offset
            );
            if writeln!(stdout, "{line}").is_err() {
                return ExitCode::from(1);
            }
            if let Some(dir) = &args.out {
                let path = dir.join(format!("seed-{seed}.json"));
                if let Err(e) = std::fs::write(&path, generated.scene.to_json_string()) {
                    let _ = writeln!(std::io::stderr(), "{}: {e}", path.display());
                    return ExitCode::from(1);
                }
            }
        }
        if seeds % 100 == 0 {
            let _ = writeln!(
                std::io::stderr(),
                "exact2d-hunt: {seeds} seeds, {found} findings, {:.0} s",
                start.elapsed().as_secs_f64()
            );
        }
    }
    let summary = Summary {
        seeds,
        from: args.from,
        // Tenths of a second: the figure is for people, and varies more than that.
        wall_s: (start.elapsed().as_secs_f64() * 10.0).round() / 10.0,
        findings: found,
        classes,
        slow,
        busiest_instant: Busiest {
            events: busiest.0,
            balls: busiest.1,
            seed: busiest.2,
        },
    };
    let summary = serde_json::to_string(&summary).expect("a summary serializes");
    if writeln!(stdout, "{summary}").is_err() {
        return ExitCode::from(1);
    }
    if found == 0 {
        ExitCode::SUCCESS
    } else {
        ExitCode::from(1)
    }
}

/// The JSON line the hunt ends with (keys in this order).
#[derive(Serialize)]
struct Summary {
    seeds: u64,
    from: u64,
    wall_s: f64,
    findings: u64,
    classes: BTreeMap<&'static str, u64>,
    slow: u64,
    busiest_instant: Busiest,
}

/// The instant with the most events per ball involved: how many, over how many balls, and
/// in which seed's scene.
#[derive(Serialize)]
struct Busiest {
    events: u64,
    balls: usize,
    seed: u64,
}
