//! Certified continuous collision detection for [parry] and [rapier] users.
//!
//! [parry]: https://parry.rs
//! [rapier]: https://rapier.rs
//!
//! Parry's shapes and `NonlinearRigidMotion`s in, parry's `ShapeCastHit`
//! out, answered by `motion-bound`'s conservative advancement: a reported
//! time of impact is never later than the first contact, and "no impact" is
//! certified, floating-point rounding included.
//!
//! - [`cast_shapes_nonlinear`]: parry's function of that name, certified.
//! - [`ShapeCache`]: shapes converted once (a mesh's tree built once per
//!   shared shape), and the same cast through them.
//! - [`CertifiedDispatcher`]: a query dispatcher for rapier's narrow phase
//!   whose `cast_shapes_nonlinear` is the certified one. Rapier asks it
//!   only for cylinders, cones, half-spaces and custom shapes (it sweeps
//!   balls, boxes, capsules and hulls itself, and never a moving mesh).
//! - [`rapier::CertifiedPass`] (feature `rapier`): with rapier, run it around
//!   each step (`pass.step(&mut world)`), made with the dispatcher: it casts
//!   every CCD body's actual motion over the step against everything it may
//!   meet, plain shapes, nothing wrapped, and covers what rapier's CCD never
//!   asks (two bullets, a moving mesh) or does with a time (its own clamping
//!   path).
//! - [`Swept`]: a collider shape wrapper with which rapier's own CCD hands
//!   every pair of that collider to the dispatcher, for when the pass is
//!   not run; the shape then says `Custom` ([`Swept::see_through`]).
//!
//! `f64` (the default feature, `parry3d-f64`) is re-exported at the root;
//! `f32` (`parry3d`) is the module `f32` (re-exported at the root when
//! `f64` is off).
//!
// The pass's link: to the item when the feature is on (docs.rs builds every feature), to its
// page on docs.rs otherwise, so that no build of these docs has a broken link.
#![cfg_attr(
    feature = "rapier",
    doc = "[`rapier::CertifiedPass`]: crate::rapier::CertifiedPass"
)]
#![cfg_attr(
    not(feature = "rapier"),
    doc = "[`rapier::CertifiedPass`]: https://docs.rs/motion-bound-parry/latest/motion_bound_parry/rapier/struct.CertifiedPass.html"
)]
#![forbid(unsafe_code)]
#![cfg_attr(docsrs, feature(doc_cfg))]

#[cfg(feature = "f32")]
pub mod f32;
#[cfg(feature = "f64")]
pub mod f64;

#[cfg(feature = "f64")]
pub use crate::f64::*;

#[cfg(feature = "rapier")]
pub mod rapier;

#[cfg(all(feature = "f32", not(feature = "f64")))]
pub use crate::f32::*;

/// The README's examples, run as doctests (its rapier setup needs the
/// feature `rapier`).
#[cfg(all(doctest, feature = "rapier"))]
#[doc = include_str!("../README.md")]
pub struct ReadmeDoctests;
