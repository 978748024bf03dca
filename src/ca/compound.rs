//! Compound bodies: several parts moving as one rigid body.

use alloc::vec::Vec;

use crate::bvh::BallTree;
use crate::error::{InputError, Quantity};
use crate::rounding::sum_up;
use crate::{BoundingBall, Convex, Float};

/// A part of a [`Compound`], in the compound's body frame: a convex shape
/// (placed at its local pose by [`Convex::try_placed`]) or a mesh (its
/// vertices given in the body frame).
#[derive(Clone, Copy, Debug)]
#[non_exhaustive]
pub enum Part<'a, T> {
    /// A convex shape.
    Convex(Convex<'a, T>),
    /// A triangle mesh through its tree.
    Mesh(&'a BallTree<T>),
}

/// Several parts moving as one rigid body (one motion): a table of boxes, a
/// dumbbell, a mesh with a box. A pair of a compound and another body is the
/// pairs of its parts (`proofs/12-shapes.md`, "Compounds").
///
/// ```
/// use motion_bound::ca::{Compound, Part};
/// use motion_bound::{Convex, InputError, Isometry, Vec3};
/// // A dumbbell: two balls on a bar.
/// let at = |x: f64| Isometry::try_from_translation(Vec3::new(x, 0.0, 0.0));
/// let dumbbell = Compound::try_new(vec![
///     Part::Convex(Convex::try_ball(0.3)?.try_placed(at(-1.0)?)?),
///     Part::Convex(Convex::try_ball(0.3)?.try_placed(at(1.0)?)?),
///     Part::Convex(Convex::try_capsule(0.0, 0.05)?),
/// ])?;
/// assert_eq!(dumbbell.parts().len(), 3);
/// assert!(dumbbell.reach() >= 1.3);
/// assert_eq!(Compound::<f64>::try_new(vec![]).err(), Some(InputError::EmptyCompound));
/// # Ok::<(), InputError>(())
/// ```
#[derive(Clone, Debug)]
pub struct Compound<'a, T> {
    parts: Vec<Part<'a, T>>,
    reach: T,
}

impl<'a, T: Float> Compound<'a, T> {
    /// The compound of `parts`.
    ///
    /// # Errors
    /// [`InputError::EmptyCompound`] for no part; [`InputError::TooLarge`]
    /// with [`Quantity::Radius`] when its reach overflows the range.
    pub fn try_new(parts: Vec<Part<'a, T>>) -> Result<Self, InputError> {
        if parts.is_empty() {
            return Err(InputError::EmptyCompound);
        }
        let mut reach = T::ZERO;
        for p in &parts {
            let r = match p {
                Part::Convex(c) => c.reach(),
                Part::Mesh(tree) => {
                    sum_up(tree.root_ball().centre_norm_up(), tree.root_ball().radius())
                }
            };
            reach = reach.max_nan(r);
        }
        if reach > T::MAX_INPUT || reach.is_nan() {
            return Err(InputError::TooLarge(Quantity::Radius));
        }
        Ok(Self { parts, reach })
    }

    /// The parts.
    #[must_use]
    pub fn parts(&self) -> &[Part<'a, T>] {
        &self.parts
    }

    /// An upper bound of the distance from the body origin of every point of
    /// every part.
    #[must_use]
    pub const fn reach(&self) -> T {
        self.reach
    }

    /// The ball about the body origin of radius [`reach`](Self::reach).
    ///
    /// # Errors
    /// None for a compound made by [`try_new`](Self::try_new).
    pub fn bounding_ball(&self) -> Result<BoundingBall<T>, InputError> {
        BoundingBall::try_new([T::ZERO; 3], self.reach)
    }
}
