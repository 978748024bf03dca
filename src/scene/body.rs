//! The bodies of a scene: a shape, its motion over the frame, its groups.

use crate::ca::Compound;
use crate::shape::ball::enclosing_ball;
use crate::{
    BallTree, BoundingBall, Convex, ConvexKind, Float, HalfSpace, InputError, RigidMotion,
    VertexSet,
};

/// The shape of a scene body, in its own frame (the frame its tree or
/// vertices are given in). A shape is borrowed: every body of the same shape
/// shares one [`BallTree`] (or one vertex array) for the scene's lifetime.
#[derive(Clone, Copy, Debug)]
#[non_exhaustive]
pub enum BodyShape<'a, T> {
    /// A triangle mesh through its ball tree (convex or not).
    Mesh(&'a BallTree<T>),
    /// A convex polytope given by its vertices (distances by GJK).
    Convex(VertexSet<'a, T>),
    /// A ball (in the body frame).
    Ball(BoundingBall<T>),
    /// A convex shape: a ball, capsule, cuboid, cylinder, cone or polytope,
    /// rounded or not ([`Convex`]).
    Shape(Convex<'a, T>),
    /// A half-space (the ground, a wall): it may translate but not turn,
    /// and it is never paired with another half-space.
    HalfSpace(HalfSpace<T>),
    /// Several parts moving as one body ([`Compound`]).
    Compound(&'a Compound<'a, T>),
}

/// The kind of a [`BodyShape`], for errors and counters.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum ShapeKind {
    /// [`BodyShape::Mesh`].
    Mesh,
    /// [`BodyShape::Convex`].
    Convex,
    /// [`BodyShape::Ball`].
    Ball,
    /// [`BodyShape::Shape`], of this kind.
    Shape(ConvexKind),
    /// [`BodyShape::HalfSpace`].
    HalfSpace,
    /// [`BodyShape::Compound`].
    Compound,
}

impl core::fmt::Display for ShapeKind {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self {
            Self::Mesh => f.write_str("mesh"),
            Self::Convex => f.write_str("convex vertex set"),
            Self::Ball => f.write_str("ball"),
            Self::Shape(kind) => write!(f, "{kind}"),
            Self::HalfSpace => f.write_str("half-space"),
            Self::Compound => f.write_str("compound"),
        }
    }
}

impl<T: Float> BodyShape<'_, T> {
    /// The kind of shape.
    #[must_use]
    pub const fn kind(&self) -> ShapeKind {
        match self {
            Self::Mesh(_) => ShapeKind::Mesh,
            Self::Convex(_) => ShapeKind::Convex,
            Self::Ball(_) => ShapeKind::Ball,
            Self::Shape(s) => ShapeKind::Shape(s.kind()),
            Self::HalfSpace(_) => ShapeKind::HalfSpace,
            Self::Compound(_) => ShapeKind::Compound,
        }
    }

    /// A ball in the body frame holding the whole shape: the tree's root
    /// ball, the ball itself, or for a vertex set the ball about the centre of
    /// its bounding box with the radius rounded up
    /// (`proofs/floating-point.md`, "Summary"). `O(N)` for a vertex set, so a
    /// scene computes it once per body.
    ///
    /// # Errors
    /// [`InputError::TooLarge`] with [`Quantity::Radius`](crate::Quantity::Radius) for a vertex set
    /// whose bounding ball's radius exceeds [`Float::MAX_INPUT`].
    pub fn bounding_ball(&self) -> Result<BoundingBall<T>, InputError> {
        match self {
            Self::Mesh(tree) => Ok(*tree.root_ball()),
            Self::Ball(ball) => Ok(*ball),
            Self::Convex(set) => enclosing_ball(set.vertices()),
            Self::Shape(s) => BoundingBall::try_new([T::ZERO; 3], s.reach()),
            // Unbounded: the broad phase tests half-spaces by their plane.
            Self::HalfSpace(_) => BoundingBall::try_new([T::ZERO; 3], T::ZERO),
            Self::Compound(c) => c.bounding_ball(),
        }
    }
}

/// Interaction groups, as in most engines: a pair is tested only when each
/// body is a member of a group that the other's filter accepts,
/// `(a.memberships & b.filter) != 0 && (b.memberships & a.filter) != 0`.
///
/// ```
/// use motion_bound::scene::Groups;
/// let debris = Groups::new(0b10, 0b01); // debris meets only the world
/// let world = Groups::new(0b01, 0b11);
/// assert!(debris.interacts_with(world));
/// assert!(!debris.interacts_with(debris));
/// assert!(Groups::ALL.interacts_with(Groups::ALL));
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Groups {
    memberships: u32,
    filter: u32,
}

impl Groups {
    /// Member of every group, meets every group (the default).
    pub const ALL: Self = Self::new(u32::MAX, u32::MAX);
    /// Meets nothing.
    pub const NONE: Self = Self::new(0, 0);

    /// The groups a body belongs to and the groups it meets.
    #[must_use]
    pub const fn new(memberships: u32, filter: u32) -> Self {
        Self {
            memberships,
            filter,
        }
    }

    /// Whether a body of these groups and one of `other` are tested.
    #[must_use]
    pub const fn interacts_with(self, other: Self) -> bool {
        (self.memberships & other.filter) != 0 && (other.memberships & self.filter) != 0
    }
}

impl Default for Groups {
    fn default() -> Self {
        Self::ALL
    }
}

/// One body of a scene: its shape, its motion over the scene's frame, its
/// groups, and the per-body summary the scene computes once (the bounding
/// ball; whether it moves, turns).
#[derive(Clone, Copy, Debug)]
pub struct SceneBody<'a, T> {
    pub(super) shape: BodyShape<'a, T>,
    pub(super) ball: BoundingBall<T>,
    pub(super) motion: RigidMotion<T>,
    pub(super) groups: Groups,
}

impl<'a, T: Float> SceneBody<'a, T> {
    pub(super) fn try_new(
        shape: BodyShape<'a, T>,
        motion: RigidMotion<T>,
        groups: Groups,
    ) -> Result<Self, InputError> {
        Ok(Self {
            shape,
            ball: shape.bounding_ball()?,
            motion,
            groups,
        })
    }

    /// The shape.
    #[must_use]
    pub const fn shape(&self) -> &BodyShape<'a, T> {
        &self.shape
    }

    /// The motion over the scene's frame.
    #[must_use]
    pub const fn motion(&self) -> &RigidMotion<T> {
        &self.motion
    }

    /// The interaction groups.
    #[must_use]
    pub const fn groups(&self) -> Groups {
        self.groups
    }

    /// The ball (in the body frame) that holds the whole shape.
    #[must_use]
    pub const fn bounding_ball(&self) -> &BoundingBall<T> {
        &self.ball
    }

    /// Whether the body does not move during the frame (`v = 0` and
    /// `w = 0`: a static body, or a dynamic one at rest).
    #[must_use]
    pub fn is_static(&self) -> bool {
        self.motion.linear() == crate::Vec3::ZERO && !self.is_turning()
    }

    /// Whether the body turns during the frame (`w != 0`); a body that does
    /// not takes the translation-only path.
    #[must_use]
    pub fn is_turning(&self) -> bool {
        self.motion.angular() != crate::Vec3::ZERO
    }
}
