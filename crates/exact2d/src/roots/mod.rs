//! Root finding that keeps every digit near contact.
//!
//! A time of impact is the first time a *gap function* (positive while two shapes are apart)
//! reaches zero while decreasing. Two kinds of gap functions occur:
//!
//! - quadratics, solved in closed form by [`first_descent`] and [`first_contact`], with a
//!   cancellation-free root formula and a compensated [`discriminant`];
//! - the quartic gap between a parabola and a point (a ball under gravity against a corner or
//!   a static circle), [`ParabolicGap`], whose roots are isolated by the critical points of the
//!   quartic and then refined to the first representable time of contact.
//!
//! Everything here is `+ - * /` and `sqrt`, which IEEE 754 rounds correctly, so results are
//! identical on every platform and at every optimisation level.

mod compensated;
mod parabolic_gap;
mod quadratic;
mod refine;

pub use compensated::{discriminant, two_product};
pub use parabolic_gap::ParabolicGap;
pub use quadratic::{first_contact, first_descent};
pub(crate) use refine::refine_descent;
