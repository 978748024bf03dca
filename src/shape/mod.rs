//! What the bounds need of a body: its vertex set and summary, bounding
//! balls, and convex shapes as a core and a radius.

pub(crate) mod ball;
pub(crate) mod body;
pub(crate) mod convex;
pub(crate) mod half_space;
