//! Typed errors for invalid input.

use core::fmt;

/// Which input an [`InputError`] is about.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub enum Quantity {
    /// The closest direction `n`.
    Direction,
    /// The linear velocity `v` of the rotation centre.
    LinearVelocity,
    /// The angular velocity `w`.
    AngularVelocity,
    /// The rotation centre at the epoch.
    Centre,
    /// A time (an interval end).
    Time,
    /// The body point with this index in the vertex slice.
    Vertex(usize),
    /// A radius given directly (a bounding sphere).
    Radius,
    /// A rigid placement (rotation matrix or translation).
    Pose,
    /// A body's orientation (a quaternion).
    Orientation,
    /// The rotation centre in the body frame (parry's `local_center`).
    LocalCentre,
    /// A motion's duration.
    Duration,
    /// A shape's extent: a half height or a half extent.
    Extent,
}

/// Why an input was rejected.
///
/// Every constructor that validates returns this; no function of the crate
/// panics on bad floating-point input.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub enum InputError {
    /// A component is NaN or infinite.
    NonFinite(Quantity),
    /// A component exceeds [`Float::MAX_INPUT`](crate::Float::MAX_INPUT)
    /// (`2^507` for `f64`, `2^59` for `f32`), beyond which intermediates could
    /// overflow.
    TooLarge(Quantity),
    /// A direction of length zero.
    ZeroDirection,
    /// A vertex set with no vertex.
    EmptyVertexSet,
    /// A negative radius.
    NegativeRadius,
    /// An interval whose end precedes its start.
    ReversedInterval,
    /// A sub-interval that is not inside the motion's interval.
    NotASubInterval,
    /// A quaternion of length zero (no rotation).
    ZeroQuaternion,
    /// A 3x3 matrix that is not a rotation: not orthonormal to within
    /// [`Rotation::MATRIX_TOLERANCE`](crate::Rotation::MATRIX_TOLERANCE), or a
    /// reflection (negative determinant).
    NotARotation,
    /// A duration that is zero or negative.
    NonPositiveDuration,
    /// A triangle list with no triangle (a ball tree needs one).
    NoTriangles,
    /// A ball tree's piece length
    /// ([`BallTree::try_with_piece_length`](crate::BallTree::try_with_piece_length))
    /// that is NaN, zero or negative.
    PieceLength,
    /// A cylinder or cone of zero height (a disc).
    ZeroHeight,
    /// A shape placed a second time (place it once, at its whole pose).
    AlreadyPlaced,
    /// A compound with no part.
    EmptyCompound,
    /// A triangle names a vertex that does not exist.
    TriangleIndexOutOfRange {
        /// The triangle's position in the list.
        triangle: usize,
        /// The vertex index it names.
        index: u32,
    },
}

impl fmt::Display for Quantity {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Direction => f.write_str("direction"),
            Self::LinearVelocity => f.write_str("linear velocity"),
            Self::AngularVelocity => f.write_str("angular velocity"),
            Self::Centre => f.write_str("rotation centre"),
            Self::Time => f.write_str("time"),
            Self::Vertex(i) => write!(f, "vertex {i}"),
            Self::Radius => f.write_str("radius"),
            Self::Pose => f.write_str("pose"),
            Self::Orientation => f.write_str("orientation"),
            Self::LocalCentre => f.write_str("local rotation centre"),
            Self::Duration => f.write_str("duration"),
            Self::Extent => f.write_str("extent"),
        }
    }
}

impl fmt::Display for InputError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::NonFinite(q) => write!(f, "{q} is not finite"),
            Self::TooLarge(q) => write!(f, "{q} exceeds the largest supported magnitude"),
            Self::ZeroDirection => f.write_str("direction has zero length"),
            Self::EmptyVertexSet => f.write_str("vertex set is empty"),
            Self::NegativeRadius => f.write_str("radius is negative"),
            Self::ReversedInterval => f.write_str("interval end precedes its start"),
            Self::NotASubInterval => {
                f.write_str("sub-interval is not inside the motion's interval")
            }
            Self::ZeroQuaternion => f.write_str("quaternion has zero length"),
            Self::NotARotation => f.write_str(
                "matrix is not a rotation (not orthonormal to within 1e-6, or a reflection)",
            ),
            Self::NonPositiveDuration => f.write_str("duration is not positive"),
            Self::NoTriangles => f.write_str("no triangle"),
            Self::PieceLength => f.write_str("a piece length that is not positive"),
            Self::ZeroHeight => f.write_str("a cylinder or cone of zero height"),
            Self::AlreadyPlaced => f.write_str("a shape placed twice"),
            Self::EmptyCompound => f.write_str("a compound with no part"),
            Self::TriangleIndexOutOfRange { triangle, index } => {
                write!(
                    f,
                    "triangle {triangle} names vertex {index}, which does not exist"
                )
            }
        }
    }
}

impl core::error::Error for InputError {}

/// Checks that every component is finite and at most `MAX_INPUT` in magnitude.
pub(crate) fn check_components<T: crate::Float>(c: [T; 3], q: Quantity) -> Result<(), InputError> {
    for x in c {
        if !x.is_finite() {
            return Err(InputError::NonFinite(q));
        }
        if x.abs() > T::MAX_INPUT {
            return Err(InputError::TooLarge(q));
        }
    }
    Ok(())
}
