//! The adapter for `parry3d` (and `rapier3d`), in `f32`.

use parry3d as parry;

// The same source for both precisions, each with its own `parry`.
#[allow(clippy::duplicate_mod)]
#[path = "adapter.rs"]
mod adapter;

pub use adapter::*;
