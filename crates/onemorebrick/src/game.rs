//! A game: the state between volleys, the volley in flight, and the commands that change
//! them. This is the API a front end, a bot or a test drives.

use exact2d::{CastOptions, DVec2};

use crate::GameError;
use crate::aim::Aim;
use crate::arena::{Arena, BALL_GROUPS};
use crate::ball::BallView;
use crate::board::Board;
use crate::config::Config;
use crate::replay::Command;
use crate::round::{self, Phase, RoundReport};
use crate::state::GameState;
use crate::volley::{Step, Tally, Volley};

/// A game of One More Brick.
///
/// ```
/// use onemorebrick::{Aim, Config, Game, Phase};
///
/// let mut game = Game::new(Config::default(), 7)?;
/// game.shoot(Aim::new(0.3, 1.0))?;
/// // A front end calls `advance_to` once per frame; this finishes the round at once.
/// let report = game.finish_round()?;
/// assert_eq!(game.phase(), Phase::Aiming);
/// assert_eq!(game.state().level(), 2);
/// assert!(report.tally.end_time > 0.0);
/// # Ok::<(), onemorebrick::GameError>(())
/// ```
pub struct Game {
    seed: u64,
    state: GameState,
    live: Option<Live>,
    history: Vec<Command>,
    last_report: Option<RoundReport>,
}

/// The volley in flight and the shot that started it.
struct Live {
    volley: Volley,
    aim: Aim,
}

impl Game {
    /// A new game from a seed.
    ///
    /// # Errors
    /// [`GameError::InvalidConfig`].
    pub fn new(config: Config, seed: u64) -> Result<Self, GameError> {
        Ok(Self::from_state(seed, GameState::new(config, seed)?))
    }

    /// A game from a state between volleys (a custom board, a loaded file). `seed` is only
    /// recorded, for replays; the state's generator is used as it is.
    #[must_use]
    pub fn from_state(seed: u64, state: GameState) -> Self {
        Self {
            seed,
            state,
            live: None,
            history: Vec::new(),
            last_report: None,
        }
    }

    /// The seed the game was created with.
    #[must_use]
    pub fn seed(&self) -> u64 {
        self.seed
    }

    /// The phase of the round.
    #[must_use]
    pub fn phase(&self) -> Phase {
        if self.live.is_some() {
            Phase::Volley
        } else if self.state.game_over {
            Phase::GameOver
        } else {
            Phase::Aiming
        }
    }

    /// The state at the start of the current volley (or now, between volleys).
    #[must_use]
    pub fn state(&self) -> &GameState {
        &self.state
    }

    /// The board as it is now: during a volley, with the damage done so far.
    #[must_use]
    pub fn board(&self) -> &Board {
        self.live
            .as_ref()
            .map_or(&self.state.board, |l| l.volley.board())
    }

    /// Every command so far (shots, recalls, finishes, restarts): with the seed and the
    /// configuration, a [`Replay`](crate::Replay).
    #[must_use]
    pub fn history(&self) -> &[Command] {
        &self.history
    }

    /// The report of the last round resolved.
    #[must_use]
    pub fn last_report(&self) -> Option<&RoundReport> {
        self.last_report.as_ref()
    }

    /// The volley's clock (simulated seconds since its first launch), if a volley is live.
    #[must_use]
    pub fn volley_time(&self) -> Option<f64> {
        self.live.as_ref().map(|l| l.volley.time())
    }

    /// The aim of the live volley.
    #[must_use]
    pub fn volley_aim(&self) -> Option<Aim> {
        self.live.as_ref().map(|l| l.aim)
    }

    /// The live volley's counts so far.
    #[must_use]
    pub fn volley_tally(&self) -> Option<&Tally> {
        self.live.as_ref().map(|l| l.volley.tally())
    }

    /// Balls of the live volley not launched yet.
    #[must_use]
    pub fn balls_waiting(&self) -> u32 {
        self.live.as_ref().map_or(0, |l| l.volley.waiting())
    }

    /// The balls in play (empty between volleys).
    #[must_use]
    pub fn balls(&self) -> Vec<BallView> {
        self.live
            .as_ref()
            .map_or_else(Vec::new, |l| l.volley.balls())
    }

    fn expect_phase(&self, needed: Phase) -> Result<(), GameError> {
        let actual = self.phase();
        if actual == needed {
            Ok(())
        } else {
            Err(GameError::WrongPhase { needed, actual })
        }
    }

    /// Fires a volley of every ball along `aim`, from the launch position.
    ///
    /// # Errors
    /// [`GameError::WrongPhase`] outside [`Phase::Aiming`]; [`GameError::InvalidAim`].
    pub fn shoot(&mut self, aim: Aim) -> Result<(), GameError> {
        self.expect_phase(Phase::Aiming)?;
        let state = &self.state;
        let volley = Volley::start(
            &state.config,
            state.board.clone(),
            state.rng.clone(),
            state.launch_x,
            aim,
            state.balls,
        )?;
        self.live = Some(Live { volley, aim });
        self.history.push(Command::Shoot(aim));
        Ok(())
    }

    /// Does the next thing in the volley at or before `limit` (an engine event, a launch, a
    /// deadline) or moves the clock to `limit`; resolves the round when its last ball leaves.
    /// Tests use it to look at the balls after every event.
    ///
    /// # Errors
    /// [`GameError::WrongPhase`] without a volley; [`GameError::TimeBeforeNow`].
    pub fn step(&mut self, limit: f64) -> Result<Step, GameError> {
        self.expect_phase(Phase::Volley)?;
        let live = self.live.as_mut().expect("phase checked");
        let step = live.volley.step(limit)?;
        if live.volley.is_over() {
            self.resolve();
            return Ok(Step::Over);
        }
        Ok(step)
    }

    /// Plays the volley until its clock reaches `time` (a frame) or the round ends; returns
    /// the report if it ended.
    ///
    /// # Errors
    /// As [`step`](Self::step).
    pub fn advance_to(&mut self, time: f64) -> Result<Option<RoundReport>, GameError> {
        loop {
            match self.step(time)? {
                Step::Event | Step::Action => {}
                Step::Reached => return Ok(None),
                Step::Over => return Ok(self.last_report),
            }
        }
    }

    /// Finish-round-now: plays the rest of the volley at once (the same bits as playing it
    /// frame by frame).
    ///
    /// # Errors
    /// [`GameError::WrongPhase`] without a volley.
    pub fn finish_round(&mut self) -> Result<RoundReport, GameError> {
        self.expect_phase(Phase::Volley)?;
        let at = self.volley_time().unwrap_or(0.0);
        self.history.push(Command::Finish { at });
        let report = self.advance_to(f64::INFINITY)?;
        Ok(report.expect("an unbounded advance ends the round"))
    }

    /// Recall: every ball returns at once (those not launched yet too), and the round ends.
    ///
    /// # Errors
    /// [`GameError::WrongPhase`] without a volley.
    pub fn recall(&mut self) -> Result<RoundReport, GameError> {
        self.expect_phase(Phase::Volley)?;
        let live = self.live.as_mut().expect("phase checked");
        let at = live.volley.time();
        live.volley.recall()?;
        self.history.push(Command::Recall { at });
        self.resolve();
        Ok(self.last_report.expect("just resolved"))
    }

    /// After a game over: starts again from the checkpoint (the rules are in
    /// [`round`]).
    ///
    /// # Errors
    /// [`GameError::WrongPhase`] unless the game is over.
    pub fn restart(&mut self) -> Result<(), GameError> {
        self.expect_phase(Phase::GameOver)?;
        round::restart(&mut self.state);
        self.history.push(Command::Restart);
        Ok(())
    }

    /// What shooting along `aim` now would do, played to the end on a copy (the game is not
    /// changed). Bots use it; it is exactly what [`shoot`](Self::shoot) then
    /// [`finish_round`](Self::finish_round) would report.
    ///
    /// # Errors
    /// As [`shoot`](Self::shoot).
    pub fn preview(&self, aim: Aim) -> Result<(RoundReport, GameState), GameError> {
        self.expect_phase(Phase::Aiming)?;
        let mut copy = Game::from_state(self.seed, self.state.clone());
        copy.shoot(aim)?;
        let report = copy.finish_round()?;
        Ok((report, copy.state))
    }

    /// The aim preview: the launch point, then where the first ball's centre would be at each
    /// of its first `bounces` bounces (the engine's own cast, [`World::bounce_path`]), on the
    /// board as it is now. Pick-ups are passed through and the minimum-elevation rule is not
    /// applied: the preview shows geometry, as the genre's previews do.
    ///
    /// [`World::bounce_path`]: exact2d::World::bounce_path
    ///
    /// # Errors
    /// [`GameError::WrongPhase`] outside [`Phase::Aiming`]; [`GameError::InvalidAim`].
    pub fn aim_preview(&self, aim: Aim, bounces: usize) -> Result<Vec<DVec2>, GameError> {
        self.expect_phase(Phase::Aiming)?;
        let config = &self.state.config;
        aim.validate(config.min_elevation_tan)?;
        let arena = Arena::build(config, &self.state.board)?;
        let origin = DVec2::new(self.state.launch_x, config.ball_radius);
        let options = CastOptions {
            groups: BALL_GROUPS,
            ..CastOptions::default()
        };
        let velocity = aim.velocity(config.ball_speed);
        let hits =
            arena
                .world
                .bounce_path(origin, velocity, config.ball_radius, bounces, &options)?;
        Ok(std::iter::once(origin)
            .chain(hits.iter().map(|h| h.position))
            .collect())
    }

    fn resolve(&mut self) {
        let live = self.live.take().expect("a volley to resolve");
        let collisions = live.volley.collisions();
        let (board, rng, tally) = live.volley.finish();
        let report = round::resolve(&mut self.state, board, rng, tally, collisions);
        self.last_report = Some(report);
    }

    /// Rebuilds a game from its parts (a save file): `state` between volleys, and if a volley
    /// was live, its aim and clock. The volley is re-simulated from the state, which gives
    /// the same bits as the game that was saved.
    pub(crate) fn rebuild(
        seed: u64,
        state: GameState,
        history: Vec<Command>,
        volley: Option<(Aim, f64)>,
    ) -> Result<Self, GameError> {
        let mut game = Game::from_state(seed, state);
        if let Some((aim, elapsed)) = volley {
            game.shoot(aim)?;
            game.advance_to(elapsed)?;
            if game.phase() != Phase::Volley {
                return Err(GameError::InvalidState(
                    "the saved volley ends before its saved clock".to_owned(),
                ));
            }
        }
        game.history = history;
        Ok(game)
    }
}
