//! The browser's front end: `main` reads the page's address and opens the game (or the
//! frame benchmark), and each frame the game's state is published for the scripts that
//! drive the page (`window.onemorebrick.status`: the browser test waits on it).
//!
//! The address's query: `?seed=N` fixes new games' seeds as `--seed` does on the desktop
//! (the browser test knows its board so); `?bench=frame` times frames with 1000 balls in
//! flight (`bench_frame`).

use onemorebrick::Phase;

use crate::app::App;
use crate::storage::Seeds;

/// Opens what the page's address asks for; a bad query value is shown as a notice.
pub fn main() {
    if onemorebrick_web::query("bench").as_deref() == Some("frame") {
        crate::bench_frame::run_in_browser();
        return;
    }
    let mut notices = Vec::new();
    let seeds = match onemorebrick_web::query("seed") {
        None => Seeds::Os,
        Some(text) => match crate::parse_seed(&text) {
            Ok(seed) => Seeds::Fixed(seed),
            Err(e) => {
                notices.push(format!("The address's seed={text:?} is ignored: {e}."));
                Seeds::Os
            }
        },
    };
    crate::play::run_in_browser(seeds, notices);
}

/// Publishes the game's state after frame number `frames` (1 for the first): the level,
/// score, phase, balls in flight and notices (and their panel's rectangle, in CSS pixels),
/// with the page's clock.
pub fn publish_status(app: &App, frames: u64) {
    let game = app.game();
    let state = game.state();
    let phase = match game.phase() {
        Phase::Aiming => "aiming",
        Phase::Volley => "volley",
        Phase::GameOver => "game-over",
    };
    let (notices, area) = app.notices();
    let area = area.map(|r| [r.x, r.y, r.w, r.h]);
    let status = serde_json::json!({
        "frames": frames,
        "ms": onemorebrick_web::now_ms(),
        // As text: JavaScript's numbers hold 53 bits.
        "seed": game.seed().to_string(),
        "level": state.level(),
        "score": state.score(),
        "phase": phase,
        "view": format!("{:?}", app.view()),
        "balls": app.balls_in_flight(),
        "commands": game.history().len(),
        "notices": notices,
        "notice_area": area,
    });
    onemorebrick_web::publish("status", &status.to_string());
    if frames == 1 {
        let first = serde_json::json!({ "ms": onemorebrick_web::now_ms() });
        onemorebrick_web::publish("first_frame", &first.to_string());
    }
}
