//! What moves: balls, their closed-form trajectories, and the collision response.

mod ball;
mod ball_set;
mod contact_friction;
mod dense;
mod gram;
mod hold;
mod impact;
mod impact_friction;
mod lemke;
mod mixing;
mod principal;
mod response;
mod rolling;
mod rough;
mod shelf;
mod sleep;
mod support;
mod table;
mod time;
mod trajectory;

pub use ball::{Ball, BallDesc, BallHandle};
pub(crate) use ball_set::{BallSet, Extra, Kinematics, Material, Properties};
pub(crate) use contact_friction::{Rub, frictional_hold};
pub(crate) use hold::{Hold, PARALLEL};
pub(crate) use impact::{
    ContactRow, Factored, Hit, Rigid, resolve_impact_from, resolve_impact_guessed,
    resolve_impact_with_impulses, resolve_with_equalities_factored,
};
pub(crate) use impact_friction::resolve_frictional_impact;
pub use response::{collide_balls, collide_balls_backed, reflect, restated_bounce};
pub(crate) use response::{rebound, rebound_backed};
pub(crate) use rolling::OnLine;
pub(crate) use rough::Spin;
pub use rough::{DEFAULT_INERTIA, Roughness, SpinningBody, apply_friction, friction_impulse};
pub use sleep::SLEEP_SPEED;
pub(crate) use sleep::{Sleep, gentle, rests, sleep_speed, takes};
pub(crate) use support::{NO_COLLIDER, Next, Rubbing, Support, Touch, touching_gap};
pub use support::{PIVOT_STEP, SETTLE_HEIGHT};
pub use table::Table;
pub(crate) use table::{ClothPhase, OnCloth, contact_velocity, roll_of};
pub(crate) use time::sooner;
pub use time::{RESOLUTION, Time};
pub use trajectory::Trajectory;
