//! The adapter, compiled once per precision: `src/f64.rs` and `src/f32.rs`
//! each bring their parry (`parry3d-f64` or `parry3d`) into scope as `parry`
//! and include this file as their module `adapter`. Its parts are the files
//! of `src/adapter/`, one concept each; each uses only the parts above it in
//! this list (named in brackets):
//!
//! - `error.rs`: `CastError`.
//! - `swept.rs`: the collider shape wrapper `Swept` and its forwarding impls.
//! - `convert.rs`: parry's poses, motions and shapes in `motion-bound`'s
//!   terms, `Body` (error, swept).
//! - `cast.rs`: the certified cast, `cast_shapes_nonlinear` (error, convert).
//! - `cache.rs`: `ShapeCache`, converted bodies kept across queries (error,
//!   swept, convert, cast).
//! - `past_contact.rs`: whether a pair touching at the start goes deeper,
//!   the core's rule on parry's shapes (swept, convert, cache).
//! - `dispatcher.rs`: `CertifiedDispatcher`, rapier's query dispatcher
//!   (error, swept, cache, past_contact).

use super::parry;

#[path = "adapter/cache.rs"]
mod cache;
#[path = "adapter/cast.rs"]
mod cast;
#[path = "adapter/convert.rs"]
mod convert;
#[path = "adapter/dispatcher.rs"]
mod dispatcher;
#[path = "adapter/error.rs"]
mod error;
#[path = "adapter/past_contact.rs"]
mod past_contact;
#[path = "adapter/swept.rs"]
mod swept;

pub use cache::{CacheStats, ShapeCache};
pub use cast::cast_shapes_nonlinear;
pub use convert::{isometry, rigid_motion, Body};
pub use dispatcher::{CertifiedDispatcher, DispatchStats};
pub use error::CastError;
#[allow(unused_imports)] // the f32 adapter has no rapier pass
pub(crate) use past_contact::{PastContact, Touching};
pub use swept::Swept;
