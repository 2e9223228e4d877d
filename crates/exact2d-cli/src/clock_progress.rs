//! `simulate`'s sign of life on standard error: how far the clock has come. A bar on a
//! terminal; otherwise a plain line at most every [`LINE_INTERVAL`], so a run of a few seconds
//! writes nothing. Standard output is untouched.

use std::io::{IsTerminal, Write};
use std::time::{Duration, Instant};

use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};

/// The least wall time between two plain progress lines.
const LINE_INTERVAL: Duration = Duration::from_secs(10);

/// Events between two looks at the wall clock (a look costs more than an event's share).
pub const EVENTS_PER_LOOK: u64 = 4096;

/// The bar's steps over the run: thousandths of the end time.
const STEPS: u64 = 1000;

/// Progress of a run to simulated time `until`.
pub struct ClockProgress {
    bar: Option<ProgressBar>,
    start: Instant,
    last_line: Instant,
    until: f64,
}

impl ClockProgress {
    /// A bar if standard error is a terminal, else plain lines, for a run to `until`.
    #[must_use]
    pub fn new(until: f64) -> Self {
        let bar = std::io::stderr().is_terminal().then(|| {
            let bar = ProgressBar::with_draw_target(Some(STEPS), ProgressDrawTarget::stderr());
            let template = "{elapsed_precise} [{bar:30}] {msg}";
            if let Ok(style) = ProgressStyle::with_template(template) {
                bar.set_style(style.progress_chars("=> "));
            }
            bar
        });
        let now = Instant::now();
        Self {
            bar,
            start: now,
            last_line: now,
            until,
        }
    }

    /// The clock is at `time` after `events` events.
    pub fn at(&mut self, time: f64, events: u64) {
        let share = if self.until > 0.0 {
            (time / self.until).clamp(0.0, 1.0)
        } else {
            1.0
        };
        let message = format!("t = {time:.6e} of {:.6e}, {events} events", self.until);
        if let Some(bar) = &self.bar {
            bar.set_position((share * STEPS as f64) as u64);
            bar.set_message(message);
            return;
        }
        let now = Instant::now();
        if now - self.last_line < LINE_INTERVAL {
            return;
        }
        self.last_line = now;
        let rate = events as f64 / (now - self.start).as_secs_f64().max(f64::MIN_POSITIVE);
        // Best effort: a closed standard error must not stop the run.
        let _ = writeln!(
            std::io::stderr(),
            "simulate: {message} ({:.3} %), {rate:.4e} events/s",
            100.0 * share
        );
    }

    /// Removes the bar (the report follows on standard output).
    pub fn finish(&self) {
        if let Some(bar) = &self.bar {
            bar.finish_and_clear();
        }
    }
}

impl Drop for ClockProgress {
    /// A run that stops on an error leaves no bar behind its message.
    fn drop(&mut self) {
        self.finish();
    }
}
