//! What moves: balls, their closed-form trajectories, and the collision response.

mod ball;
mod ball_set;
mod response;
mod time;
mod trajectory;

pub use ball::{Ball, BallDesc, BallHandle};
pub(crate) use ball_set::{BallSet, Kinematics, Properties, SensorList};
pub use response::{collide_balls, reflect};
pub use time::{RESOLUTION, Time};
pub use trajectory::Trajectory;
