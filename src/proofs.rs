//! The proofs, one module per lemma file of `proofs/` (rendered here so
//! that the documentation reaches them; the files are the source). Each
//! names the tests that check it; `tests/proofs_name_real_tests.rs` checks
//! that every test it names exists.
#![doc = include_str!("../proofs/README.md")]

/// Directed speed and displacement; frame invariance; scaling laws.
#[doc = include_str!("../proofs/01-definitions.md")]
pub mod definitions {}

/// A CA step is conservative iff `mu` bounds the speed.
#[doc = include_str!("../proofs/02-ca-step.md")]
pub mod ca_step {}

/// NEVQ bounds the directed speed at every time.
#[doc = include_str!("../proofs/03-nevq.md")]
pub mod nevq {}

/// The corrected EVQ case split, and where the printed Eq. 2 fails.
#[doc = include_str!("../proofs/04-evq-case-split.md")]
pub mod evq_case_split {}

/// EVQ is never above NEVQ.
#[doc = include_str!("../proofs/05-evq-le-nevq.md")]
pub mod evq_le_nevq {}

/// Restriction to a sub-interval keeps summaries valid.
#[doc = include_str!("../proofs/06-sub-intervals.md")]
pub mod sub_intervals {}

/// The closed-form oracle.
#[doc = include_str!("../proofs/07-reference.md")]
pub mod reference {}

/// EVQ of a ball in `O(1)`.
#[doc = include_str!("../proofs/08-ball-bound.md")]
pub mod ball_bound {}

/// Conservative advancement never steps past the first contact.
#[doc = include_str!("../proofs/09-ca-toi.md")]
pub mod ca_toi {}

/// One-sided bounds and closing rates.
#[doc = include_str!("../proofs/10-one-sided.md")]
pub mod one_sided {}

/// Scenes: swept boxes, culling, and the skipped work.
#[doc = include_str!("../proofs/11-scene.md")]
pub mod scene {}

/// Convex shapes as a core and a radius: supports, gaps and bounds.
#[doc = include_str!("../proofs/12-shapes.md")]
pub mod shapes {}

/// Kinematic chains: the chain bound, sub-intervals, rounding, and
/// conservative advancement of link pairs.
#[doc = include_str!("../proofs/13-chains.md")]
pub mod chains {}

/// Floating point: every bound is an upper bound for its float inputs.
#[doc = include_str!("../proofs/floating-point.md")]
pub mod floating_point {}
