//! The adapter for `parry3d-f64` (and `rapier3d-f64`).

use parry3d_f64 as parry;

// The same source for both precisions, each with its own `parry`.
#[allow(clippy::duplicate_mod)]
#[path = "adapter.rs"]
mod adapter;

pub use adapter::*;
