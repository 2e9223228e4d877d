//! Seeded benchmark scenes and the benchmark suite of exact2d.
//!
//! [`scenes`] generates the benchmark scenes: deterministic for a seed, valid by
//! construction, built from the numbers of [`rng::SplitMix64`]. The `exact2d-bench` binary
//! runs the suite over them and writes the scenes that are compared with other engines:
//!
//! ```text
//! cargo run --release -p exact2d-bench -- suite [--quick] [--only SUBSTRING]
//! cargo run --release -p exact2d-bench -- scenes --out DIR
//! cargo run --release -p exact2d-bench -- minimal [--quick] [--rounds K]
//! cargo run --release -p exact2d-bench -- latency
//! cargo run --release -p exact2d-bench -- rest [--quick] [--only SUBSTRING] [--friction MU]
//! cargo run --release -p exact2d-bench -- piles [--seeds N] [--balls N] [--friction MU]
//! cargo bench -p exact2d-bench --bench kernels -- --quick
//! ```
//!
//! The suite prints a markdown table: collisions handled, simulated and wall seconds (the
//! scene's generation and the world's build are timed apart), collisions per second,
//! nanoseconds per collision, live heap bytes per ball of the built world (measured by a
//! counting global allocator) and the relative drift of the total energy.

//!
//! [`minimal`] is a minimal, inexact hard-disk gas code, the floor that `minimal` compares the
//! engine with on the suite's gases; [`latency`] measures the machine's memory latency by
//! working-set size.

pub mod balance;
pub mod latency;
pub mod minimal;
pub mod rng;
pub mod scenes;
