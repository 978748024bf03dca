//! Half-spaces: the ground, a wall.

use crate::error::InputError;
use crate::{Direction, Float, Vec3};

/// The half-space `{x : x . m <= 0}` of a body frame: the solid below the
/// plane through the body origin with outward normal `m` (parry's
/// `HalfSpace`). Its body's motion places it; it may translate but not
/// rotate (a rotating plane sweeps unboundedly far from its rotation centre:
/// [`CaError::TurnedHalfSpace`](crate::ca::CaError::TurnedHalfSpace)).
///
/// The stored normal is the given one normalised in floating point; the
/// half-space is exactly `{x : x . m^ <= 0}` for that stored `m^` (any
/// positive multiple of a normal gives the same half-space).
///
/// ```
/// use motion_bound::{HalfSpace, InputError, Vec3};
/// let ground = HalfSpace::try_new(Vec3::new(0.0, 2.0, 0.0))?;
/// assert_eq!(ground.normal().get(), Vec3::new(0.0, 1.0, 0.0));
/// assert_eq!(HalfSpace::try_new(Vec3::<f64>::ZERO).err(), Some(InputError::ZeroDirection));
/// # Ok::<(), InputError>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HalfSpace<T> {
    normal: Direction<T>,
}

impl<T: Float> HalfSpace<T> {
    /// The half-space below the plane through the body origin with outward
    /// normal `normal` (any length).
    ///
    /// # Errors
    /// As [`Direction::try_new`]: [`InputError::ZeroDirection`] for a zero
    /// normal, [`InputError::NonFinite`] / [`InputError::TooLarge`] with
    /// [`Quantity::Direction`](crate::Quantity::Direction).
    pub fn try_new(normal: Vec3<T>) -> Result<Self, InputError> {
        Ok(Self {
            normal: Direction::try_new(normal)?,
        })
    }

    /// The outward unit normal (as stored).
    #[inline]
    #[must_use]
    pub const fn normal(&self) -> Direction<T> {
        self.normal
    }
}
