//! What the bounds need of a body: its vertex set and summary, and bounding
//! balls.

pub(crate) mod ball;
pub(crate) mod body;
