//! A stable hash of a game, for golden-hash tests: FNV-1a (64-bit) over a byte stream the
//! game writes field by field (doubles as their IEEE bits, little-endian), so it does not
//! change with the Rust version, the platform or `std`'s hasher. The generator enters as
//! its JSON text (`rand_pcg`'s serde form: state and increment).

use crate::board::Board;
use crate::cell::{Cell, Corner, Shape};
use crate::game::Game;
use crate::state::GameState;

/// FNV-1a, 64-bit: offset basis `0xcbf29ce484222325`, prime `0x100000001b3`.
#[derive(Clone, Copy, Debug)]
pub struct Fnv1a(u64);

impl Default for Fnv1a {
    fn default() -> Self {
        Self(0xcbf2_9ce4_8422_2325)
    }
}

impl Fnv1a {
    /// Hashes bytes.
    pub fn write(&mut self, bytes: &[u8]) {
        for &b in bytes {
            self.0 = (self.0 ^ u64::from(b)).wrapping_mul(0x0100_0000_01b3);
        }
    }

    /// Hashes a `u64`, little-endian.
    pub fn write_u64(&mut self, x: u64) {
        self.write(&x.to_le_bytes());
    }

    /// Hashes a double's bits.
    pub fn write_f64(&mut self, x: f64) {
        self.write_u64(x.to_bits());
    }

    /// The hash so far.
    #[must_use]
    pub fn finish(&self) -> u64 {
        self.0
    }
}

/// The stable hash of a game: its state between volleys, the live board, and every ball in
/// play (id, position, velocity, radius) with the volley clock.
#[must_use]
pub fn hash_game(game: &Game) -> u64 {
    let mut h = Fnv1a::default();
    hash_state(&mut h, game.state());
    hash_board(&mut h, game.board());
    if let Some(t) = game.volley_time() {
        h.write_f64(t);
    }
    for ball in game.balls() {
        h.write_u64(u64::from(ball.id));
        for x in [
            ball.position.x,
            ball.position.y,
            ball.velocity.x,
            ball.velocity.y,
        ] {
            h.write_f64(x);
        }
        h.write_f64(ball.radius);
    }
    h.finish()
}

fn hash_state(h: &mut Fnv1a, s: &GameState) {
    for x in [s.level, s.balls] {
        h.write_u64(u64::from(x));
    }
    h.write_f64(s.launch_x);
    h.write_u64(s.score);
    h.write_u64(s.best_score);
    let cp = s.checkpoint.map_or((0, 0), |c| (c.level, c.balls));
    h.write_u64(u64::from(cp.0));
    h.write_u64(u64::from(cp.1));
    h.write_u64(u64::from(s.game_over));
    h.write(s.rng.fingerprint().as_bytes());
    let t = &s.totals;
    for x in [
        u64::from(t.rounds),
        t.bricks_destroyed,
        t.damage,
        t.collisions,
    ] {
        h.write_u64(x);
    }
    h.write_f64(t.simulated_seconds);
    hash_board(h, &s.board);
}

fn hash_board(h: &mut Fnv1a, board: &Board) {
    for cell in board.cells() {
        let (tag, extra) = match cell {
            Cell::Empty => (0, 0),
            Cell::Obstacle => (1, 0),
            Cell::Brick(b) => {
                let shape = match b.shape {
                    Shape::Square => 0,
                    Shape::Triangle(c) => 1 + Corner::ALL.iter().position(|&k| k == c).unwrap_or(0),
                };
                (2 + shape as u64, u64::from(b.hp))
            }
            Cell::Pickup(p) => (8 + p.kind as u64, u64::from(p.used)),
        };
        h.write_u64(tag);
        h.write_u64(extra);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fnv1a_matches_the_published_test_vectors() {
        // From the FNV reference test suite: "" and "a" and "foobar".
        let hash = |s: &str| {
            let mut h = Fnv1a::default();
            h.write(s.as_bytes());
            h.finish()
        };
        assert_eq!(hash(""), 0xcbf2_9ce4_8422_2325);
        assert_eq!(hash("a"), 0xaf63_dc4c_8601_ec8c);
        assert_eq!(hash("foobar"), 0x8594_4171_f739_67e8);
    }
}
