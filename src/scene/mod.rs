//! Scenes of many moving bodies: every pair's first contact over a frame,
//! skipping what cannot touch.
//!
//! A [`Scene`] holds bodies (meshes through shared [`BallTree`](crate::BallTree)s,
//! convex vertex sets, balls), each with its motion over the frame or a
//! static pose. [`Scene::query`] answers, for every pair that can touch, its
//! first contact (or `Separated`), and the earliest contact per body and over
//! the scene ([`SceneReport`]); a [`SceneWorkspace`] kept across frames makes
//! the serial query allocation-free in steady state. With the `parallel`
//! feature, `Scene::par_query` runs the narrow phase on every core, with the
//! same report.
//!
//! What is skipped, and why it is sound (`proofs/11-scene.md`):
//!
//! * **Pairs whose swept boxes are apart.** Each body's [`SweptBox`] holds it
//!   throughout the frame (Lemma 11.1): its bounding ball at the start, grown
//!   along each axis direction by its one-sided rate times the frame's
//!   length, rounded outwards. Boxes more than the contact distance apart
//!   along an axis keep their bodies that far apart (Lemma 11.2).
//! * **Pairs of two static bodies**: neither moves, so a pair apart at the
//!   start stays apart, and the caller's engine owns resting contact.
//! * **Rates of bodies that do not need them**: a static body's box is its
//!   start box; a body that does not turn grows by its exact velocity (no
//!   bound, no arc); the automatic bound policy of convex pairs takes NEVQ
//!   alone where EVQ cannot shorten the step (Lemma 11.3).
//! * **Pairs the engine excludes**: [`Groups`] and a filter callback.
//!
//! Every skip is counted in [`SceneStats`].
//!
//! This module is the crate's scene *query*; the built-in test *bodies*
//! (torus knots, tori, boards) are in `bodies` (feature `bodies`).

mod body;
mod broad;
mod narrow;
mod params;
mod query;
mod report;
mod swept_box;

pub use body::{Groups, SceneBody};
pub use params::{SceneParams, SceneQueryError};
pub use query::Scene;
pub use report::{PairReport, SceneReport, SceneStats, SceneWorkspace};
pub use swept_box::SweptBox;
