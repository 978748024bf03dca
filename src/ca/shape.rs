//! The shape of a body, whatever its kind: the one vocabulary that
//! [`AnyPair`](crate::ca::AnyPair), scenes, the parry adapter and the Python
//! binding speak.
//!
//! | kind | what it is | built by |
//! |---|---|---|
//! | [`Shape::Convex`] | a convex shape: a core and a radius (ball, capsule, cuboid, cylinder, cone, polytope, rounded or not) | [`Convex`]'s constructors |
//! | [`Shape::VertexSet`] | the convex hull of a point set, the seed's setting: distances by GJK on the points, EVQ on them | [`VertexSet::try_new`] |
//! | [`Shape::Ball`] | a ball anywhere in the body frame (a sphere-bounded body) | [`BoundingBall::try_new`] |
//! | [`Shape::Mesh`] | a triangle mesh, convex or not, through its hierarchy | [`BallTree::try_from_mesh`](crate::BallTree::try_from_mesh) |
//! | [`Shape::HalfSpace`] | a half-space (the ground, a wall): it may translate, not turn | [`HalfSpace::try_new`] |
//! | [`Shape::Compound`] | several parts ([`Part`]) moving as one body | [`Compound::try_new`] |
//!
//! Which stepper a pair of kinds takes is decided in one place,
//! [`AnyPair::try_new`](crate::ca::AnyPair::try_new).

use alloc::vec::Vec;

use crate::bvh::BallTree;
use crate::error::{InputError, Quantity};
use crate::rounding::sum_up;
use crate::shape::ball::enclosing_ball;
use crate::{BoundingBall, Convex, ConvexKind, Float, HalfSpace, VertexSet};

/// A body's shape, in its own frame (the frame its tree, vertices or core
/// are given in), whatever its kind. A shape borrows what is costly to build
/// (a mesh's [`BallTree`], a vertex array, a [`Compound`]), so that every
/// body of the same shape shares one copy.
///
/// ```
/// use motion_bound::ca::{Shape, ShapeKind};
/// use motion_bound::{BoundingBall, Convex, ConvexKind, VertexSet};
/// let tet = [[1.0, 1.0, 1.0], [1.0, -1.0, -1.0], [-1.0, 1.0, -1.0], [-1.0, -1.0, 1.0]];
/// let shapes = [
///     Shape::Convex(Convex::try_capsule(1.0, 0.25)?),
///     Shape::VertexSet(VertexSet::try_new(&tet)?),
///     Shape::Ball(BoundingBall::try_new([0.0, 1.0, 0.0], 0.5)?),
/// ];
/// assert_eq!(shapes[0].kind(), ShapeKind::Convex(ConvexKind::Capsule));
/// // The ball that holds each shape, in the body frame.
/// assert!(shapes[1].bounding_ball()?.radius() >= 3f64.sqrt());
/// assert_eq!(shapes[2].bounding_ball()?.centre(), &[0.0, 1.0, 0.0]);
/// # Ok::<(), motion_bound::InputError>(())
/// ```
#[derive(Clone, Copy, Debug)]
#[non_exhaustive]
pub enum Shape<'a, T> {
    /// A convex shape: a core and a radius ([`Convex`]).
    Convex(Convex<'a, T>),
    /// The convex hull of a point set ([`VertexSet`]): against another
    /// vertex set, GJK on the points and the automatic NEVQ/EVQ policy on
    /// them ([`VertexSetPair`](crate::ca::VertexSetPair)); against other
    /// kinds, the polytope [`Convex::polytope`] of the same points.
    VertexSet(VertexSet<'a, T>),
    /// A ball anywhere in the body frame ([`BoundingBall`]): against another
    /// ball, the closed-form [`BallPair`](crate::ca::BallPair); against other
    /// kinds, the convex ball it is.
    Ball(BoundingBall<T>),
    /// A triangle mesh (convex or not) through its hierarchy.
    Mesh(&'a BallTree<T>),
    /// A half-space (the ground, a wall): it may translate but not turn,
    /// and it is never paired with another half-space.
    HalfSpace(HalfSpace<T>),
    /// Several parts moving as one body.
    Compound(&'a Compound<'a, T>),
}

/// The kind of a [`Shape`], for errors, counters and reports.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum ShapeKind {
    /// [`Shape::Convex`], of this kind.
    Convex(ConvexKind),
    /// [`Shape::VertexSet`].
    VertexSet,
    /// [`Shape::Ball`].
    Ball,
    /// [`Shape::Mesh`].
    Mesh,
    /// [`Shape::HalfSpace`].
    HalfSpace,
    /// [`Shape::Compound`].
    Compound,
}

impl core::fmt::Display for ShapeKind {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self {
            Self::Convex(kind) => write!(f, "{kind}"),
            Self::VertexSet => f.write_str("convex vertex set"),
            Self::Ball => f.write_str("ball"),
            Self::Mesh => f.write_str("mesh"),
            Self::HalfSpace => f.write_str("half-space"),
            Self::Compound => f.write_str("compound"),
        }
    }
}

impl<'a, T: Float> Shape<'a, T> {
    /// The kind of shape.
    #[must_use]
    pub const fn kind(&self) -> ShapeKind {
        match self {
            Self::Convex(s) => ShapeKind::Convex(s.kind()),
            Self::VertexSet(_) => ShapeKind::VertexSet,
            Self::Ball(_) => ShapeKind::Ball,
            Self::Mesh(_) => ShapeKind::Mesh,
            Self::HalfSpace(_) => ShapeKind::HalfSpace,
            Self::Compound(_) => ShapeKind::Compound,
        }
    }

    /// A ball in the body frame holding the whole shape: the tree's root
    /// ball, the ball itself, the ball of radius [`Convex::reach`] or
    /// [`Compound::reach`] about the body origin, or for a vertex set the
    /// ball about the centre of its bounding box with the radius rounded up
    /// (`proofs/floating-point.md`, "Summary"); a half-space's is empty (it
    /// is unbounded: a scene tests it by its plane). `O(N)` for a vertex
    /// set, so a scene computes it once per body.
    ///
    /// # Errors
    /// [`InputError::TooLarge`] with [`Quantity::Radius`] for a vertex set
    /// whose bounding ball's radius exceeds [`Float::MAX_INPUT`].
    pub fn bounding_ball(&self) -> Result<BoundingBall<T>, InputError> {
        match self {
            Self::Mesh(tree) => Ok(*tree.root_ball()),
            Self::Ball(ball) => Ok(*ball),
            Self::VertexSet(set) => enclosing_ball(set.vertices()),
            Self::Convex(s) => BoundingBall::try_new([T::ZERO; 3], s.reach()),
            Self::HalfSpace(_) => BoundingBall::try_new([T::ZERO; 3], T::ZERO),
            Self::Compound(c) => c.bounding_ball(),
        }
    }

    /// The `k`-th of this shape's parts (a compound's, or the shape itself
    /// as its only part).
    pub(crate) fn part(&self, k: usize) -> Self {
        match *self {
            Self::Compound(c) => match c.parts()[k] {
                Part::Convex(s) => Self::Convex(s),
                Part::Mesh(t) => Self::Mesh(t),
            },
            other => other,
        }
    }

    /// How many parts [`part`](Self::part) has.
    pub(crate) fn part_count(&self) -> usize {
        match self {
            Self::Compound(c) => c.parts().len(),
            _ => 1,
        }
    }
}

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
