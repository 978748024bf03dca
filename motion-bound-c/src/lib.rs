//! The C ABI of [`motion_bound`]: certified continuous collision detection
//! (the first time two rigid bodies, each translating and rotating, come
//! within a contact distance) for C and C++ programs.
//!
//! The header `include/motion_bound.h` is generated from this crate by
//! cbindgen (`cbindgen.toml`); every item below is documented there too.
//!
//! # Conventions
//!
//! - **Status codes.** Every function returns an [`MbStatus`]
//!   (`MB_STATUS_OK` is `0`), except [`mb_params_default`],
//!   [`mb_last_error_message`] and [`mb_version`], which cannot fail. Results
//!   are written through `out` pointers, and only on success.
//! - **Error messages.** A failing call stores a message, read by
//!   [`mb_last_error_message`]; it is per thread.
//! - **Handles.** Shapes, motions, scenes and scene results are opaque
//!   handles made by `mb_*_new`-style constructors and released by their
//!   `mb_*_free` (which accept `NULL`). The library keeps a registry of the
//!   handles it gave out: a `NULL`, freed (dangling) or foreign pointer, or a
//!   handle of another type, is refused with `MB_STATUS_NULL_POINTER` or
//!   `MB_STATUS_INVALID_HANDLE` before it is read. A handle is immutable
//!   after construction except a scene, which [`mb_scene_add`] grows.
//! - **Threads.** Immutable handles (shapes, motions, scene results) may be
//!   read from any number of threads at once; a scene may be queried from
//!   several threads at once but not while another thread adds to it; no
//!   handle may be freed while another thread uses it.
//! - **No panic crosses the boundary**: each function runs inside
//!   [`std::panic::catch_unwind`], and a panic becomes
//!   `MB_STATUS_INTERNAL_ERROR` with its message.
//!
//! `unsafe` lives in this crate only (the core forbids it), in the small
//! helpers of the private `ptr` module, each block with a `SAFETY:` comment.
#![deny(clippy::undocumented_unsafe_blocks)]
#![warn(missing_docs)]

mod chain;
mod error;
mod motion;
mod ptr;
mod query;
mod scene;
mod shape;
mod value;

pub use chain::{
    mb_chain_dof, mb_chain_free, mb_chain_from_urdf_file, mb_chain_from_urdf_string,
    mb_chain_limits, mb_chain_link_count, mb_chain_link_index, mb_chain_link_name,
    mb_chain_params_default, mb_chain_scene_add_obstacle, mb_chain_scene_add_points,
    mb_chain_scene_allow_collision, mb_chain_scene_allow_collisions_at, mb_chain_scene_check_edge,
    mb_chain_scene_check_segment, mb_chain_scene_checks_pair, mb_chain_scene_clearance,
    mb_chain_scene_collides_at, mb_chain_scene_edge_is_free, mb_chain_scene_edges_are_free,
    mb_chain_scene_free, mb_chain_scene_link_name, mb_chain_scene_new, mb_chain_scene_set_params,
    MbChain, MbChainPair, MbChainPairKind, MbChainParams, MbChainScene, MbEdgeOutcome,
    MbEdgeReport, MbSegmentOutcome, MbSegmentReport,
};
pub use error::{mb_last_error_message, mb_version, MbStatus};
pub use motion::{
    mb_motion_about_centre, mb_motion_between, mb_motion_between_about, mb_motion_free,
    mb_motion_from_velocities, mb_motion_point_at, MbMotion, MbPose, MbQuat, MbVec3,
};
pub use query::{
    mb_params_default, mb_past_contact, mb_past_contact_below, mb_time_of_impact,
    mb_time_of_impact_batch, MbBelowReport, MbBound, MbCeiling, MbCriterion, MbOutcome,
    MbPairQuery, MbParams, MbPastOutcome, MbPastReport, MbReport, MbWitnessSearch,
};
pub use scene::{
    mb_scene_add, mb_scene_free, mb_scene_len, mb_scene_new, mb_scene_query, mb_scene_result_free,
    mb_scene_result_get, mb_scene_result_len, MbScene, MbScenePair, MbSceneResult,
};
pub use shape::{
    mb_shape_ball, mb_shape_capsule, mb_shape_compound, mb_shape_cone, mb_shape_convex_hull,
    mb_shape_cuboid, mb_shape_cylinder, mb_shape_free, mb_shape_get_kind, mb_shape_half_space,
    mb_shape_mesh, mb_shape_rounded, MbMeshSolidity, MbShape, MbShapeKind,
};
pub use value::{
    mb_motion_value_between, mb_motion_value_between_about, mb_past_contact_below_values,
    mb_time_of_impact_values, MbMotionValue,
};
