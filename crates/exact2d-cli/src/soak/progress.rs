//! Progress on standard error: a bar on a terminal, plain lines otherwise.

use std::io::{IsTerminal, Write};
use std::time::{Duration, Instant};

use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};

/// The least time between two plain progress lines, so a log stays readable when checks are
/// frequent.
const LINE_INTERVAL: Duration = Duration::from_secs(2);

/// Where the progress goes.
pub enum Progress {
    /// A progress bar (standard error is a terminal).
    Bar(ProgressBar),
    /// Plain lines, at most one per [`LINE_INTERVAL`].
    Lines {
        /// When the run started.
        start: Instant,
        /// When the last line was written (`None` before the first).
        last: Option<Instant>,
        /// The events asked for.
        total: u64,
    },
}

impl Progress {
    /// A bar if standard error is a terminal, else plain lines, for a run of `total` events.
    #[must_use]
    pub fn new(total: u64) -> Self {
        if !std::io::stderr().is_terminal() {
            return Progress::Lines {
                start: Instant::now(),
                last: None,
                total,
            };
        }
        let bar = ProgressBar::with_draw_target(Some(total), ProgressDrawTarget::stderr());
        let template =
            "{elapsed_precise} [{bar:30}] {human_pos}/{human_len} events, {per_sec}, {msg}";
        if let Ok(style) = ProgressStyle::with_template(template) {
            bar.set_style(style.progress_chars("=> "));
        }
        Progress::Bar(bar)
    }

    /// Events handled so far (called often: cheap for the bar, nothing for plain lines).
    pub fn advance(&self, events: u64) {
        if let Progress::Bar(bar) = self {
            bar.set_position(events);
        }
    }

    /// A check passed after `events` events at simulated time `time`.
    pub fn checked(&mut self, events: u64, time: f64, worst_overlap: f64) {
        match self {
            Progress::Bar(bar) => {
                bar.set_position(events);
                bar.set_message(format!("t = {time:.6e}, worst overlap {worst_overlap:.2e}"));
            }
            Progress::Lines { start, last, total } => {
                let now = Instant::now();
                if last.is_some_and(|l| now - l < LINE_INTERVAL) {
                    return;
                }
                *last = Some(now);
                let seconds = (now - *start).as_secs_f64();
                let rate = events as f64 / seconds.max(f64::MIN_POSITIVE);
                let line = format!(
                    "soak: {events}/{total} events, t = {time:e}, {rate:.4e} events/s, worst overlap {worst_overlap:e}"
                );
                // Progress is best effort: a closed standard error must not stop the run.
                let _ = writeln!(std::io::stderr(), "{line}");
            }
        }
    }

    /// Removes the bar (the final report follows on standard output).
    pub fn finish(&self) {
        if let Progress::Bar(bar) = self {
            bar.finish_and_clear();
        }
    }
}
