//! Vectors, points, unit directions, rotations and placements: the
//! geometric vocabulary every layer above speaks (`no_std`, no allocation).

pub(crate) mod direction;
pub(crate) mod isometry;
pub(crate) mod point;
pub(crate) mod pose;
pub(crate) mod rotation;
pub(crate) mod rotation_plane;
pub(crate) mod vec3;
