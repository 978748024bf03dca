//! The bodies of a scene: a shape, its motion over the frame, its groups.

use crate::ca::Shape;
use crate::{BoundingBall, Float, InputError, RigidMotion};

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
    pub(super) shape: Shape<'a, T>,
    pub(super) ball: BoundingBall<T>,
    pub(super) motion: RigidMotion<T>,
    pub(super) groups: Groups,
}

impl<'a, T: Float> SceneBody<'a, T> {
    pub(super) fn try_new(
        shape: Shape<'a, T>,
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
    pub const fn shape(&self) -> &Shape<'a, T> {
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
