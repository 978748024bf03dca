//! Closed time intervals.

use crate::error::{check_components, InputError, Quantity};
use crate::Float;

/// A closed time interval `[start, end]` with `start <= end`.
///
/// Times are in the same unit as the velocities (a frame is usually
/// `[0, 1]`); the epoch `t = 0` is when body points are given.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TimeInterval<T> {
    start: T,
    end: T,
}

impl<T: Float> TimeInterval<T> {
    /// `[0, 1]`: one normalised frame, the seed's interval.
    pub const UNIT: Self = Self {
        start: T::ZERO,
        end: T::ONE,
    };

    /// `[start, end]`.
    ///
    /// # Errors
    /// [`InputError::NonFinite`] or [`InputError::TooLarge`] (for `|t|` above
    /// [`Float::MAX_INPUT`]) with [`Quantity::Time`], and
    /// [`InputError::ReversedInterval`] when `end < start`.
    ///
    /// ```
    /// use motion_bound::{InputError, TimeInterval};
    /// assert_eq!(TimeInterval::try_new(0.25, 0.75).unwrap().length(), 0.5);
    /// assert_eq!(TimeInterval::try_new(1.0, 0.0), Err(InputError::ReversedInterval));
    /// ```
    pub fn try_new(start: T, end: T) -> Result<Self, InputError> {
        check_components([start, end, T::ZERO], Quantity::Time)?;
        if end < start {
            return Err(InputError::ReversedInterval);
        }
        Ok(Self { start, end })
    }

    /// The start time.
    #[inline]
    #[must_use]
    pub const fn start(self) -> T {
        self.start
    }

    /// The end time.
    #[inline]
    #[must_use]
    pub const fn end(self) -> T {
        self.end
    }

    /// `end - start`, rounded to nearest.
    #[inline]
    #[must_use]
    pub fn length(self) -> T {
        self.end - self.start
    }

    /// `true` if `[start, end]` lies within `self`.
    #[inline]
    #[must_use]
    pub fn contains_interval(self, other: Self) -> bool {
        self.start <= other.start && other.end <= self.end
    }

    /// `true` if `t` lies within `self`.
    #[inline]
    #[must_use]
    pub fn contains(self, t: T) -> bool {
        self.start <= t && t <= self.end
    }
}
