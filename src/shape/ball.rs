//! Bounding balls of body parts, relative to the rotation centre.

use crate::error::{check_components, InputError, Quantity};
use crate::rounding::radius_up;
use crate::Float;

/// A ball of centre `s` (an offset from the rotation centre at the epoch)
/// and radius `rho` that contains a part of a body: a node of a
/// bounding-volume hierarchy, or a whole body.
///
/// Its directed bounds cost `O(1)`
/// ([`DirectedProbe::ball_speed`](crate::DirectedProbe::ball_speed)); the
/// rounded-up `|s|` and `|s| + rho` they need are computed once here.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BoundingBall<T> {
    centre: [T; 3],
    radius: T,
    centre_norm_up: T,
    outer_up: T,
}

impl<T: Float> BoundingBall<T> {
    /// The ball of centre `centre` (a body point: a [`Point3`](crate::Point3)
    /// in the body frame, or a plain `[T; 3]`) and radius `radius`.
    ///
    /// # Errors
    /// [`InputError::NonFinite`] / [`InputError::TooLarge`] with
    /// [`Quantity::Centre`] or [`Quantity::Radius`], or
    /// [`InputError::NegativeRadius`].
    ///
    /// ```
    /// use motion_bound::{BoundingBall, Point3};
    /// let b = BoundingBall::try_new(Point3::new(3.0, 4.0, 0.0), 1.0).unwrap();
    /// assert!(b.outer_radius_up() >= 6.0 && b.outer_radius_up() < 6.0 + 1e-12);
    /// assert!(BoundingBall::try_new([0.0; 3], -1.0).is_err());
    /// ```
    pub fn try_new(centre: impl Into<crate::Point3<T>>, radius: T) -> Result<Self, InputError> {
        let centre = centre.into().to_array();
        check_components(centre, Quantity::Centre)?;
        check_components([radius, T::ZERO, T::ZERO], Quantity::Radius)?;
        if radius < T::ZERO {
            return Err(InputError::NegativeRadius);
        }
        let [x, y, z] = centre;
        let centre_norm_up = radius_up(x * x + y * y + z * z);
        // fl(fl(a + b)(1 + gamma_2)) >= (a + b)(1 - u)^2 (1 + 3u) >= a + b.
        let outer_up = crate::rounding::sum_up(centre_norm_up, radius);
        Ok(Self {
            centre,
            radius,
            centre_norm_up,
            outer_up,
        })
    }

    /// The centre, relative to the rotation centre at the epoch.
    #[inline]
    #[must_use]
    pub const fn centre(&self) -> &[T; 3] {
        &self.centre
    }

    /// The radius.
    #[inline]
    #[must_use]
    pub const fn radius(&self) -> T {
        self.radius
    }

    /// An upper bound of `|s|`.
    #[inline]
    #[must_use]
    pub const fn centre_norm_up(&self) -> T {
        self.centre_norm_up
    }

    /// An upper bound of `|s| + rho`, the distance from the rotation centre of
    /// the ball's farthest point.
    #[inline]
    #[must_use]
    pub const fn outer_radius_up(&self) -> T {
        self.outer_up
    }
}

/// The ball about the centre of the points' bounding box, its radius rounded
/// up to hold every point (`proofs/floating-point.md`, "Summary"): what a
/// vertex set's or a tree node's ball is.
///
/// # Errors
/// [`InputError::TooLarge`] with [`Quantity::Radius`] when the radius exceeds
/// [`Float::MAX_INPUT`] (or the points are not finite).
#[cfg(feature = "alloc")]
pub(crate) fn enclosing_ball<T: Float>(points: &[[T; 3]]) -> Result<BoundingBall<T>, InputError> {
    let (mut lo, mut hi) = ([T::INFINITY; 3], [-T::INFINITY; 3]);
    for v in points {
        for k in 0..3 {
            lo[k] = lo[k].min_nan(v[k]);
            hi[k] = hi[k].max_nan(v[k]);
        }
    }
    // Any centre will do for soundness: the radius is measured from it.
    let centre: [T; 3] = core::array::from_fn(|k| lo[k] * T::HALF + hi[k] * T::HALF);
    let mut max_sq = T::ZERO;
    for v in points {
        let d = [v[0] - centre[0], v[1] - centre[1], v[2] - centre[2]];
        max_sq = max_sq.max_nan(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    }
    BoundingBall::try_new(centre, crate::rounding::offset_radius_up(max_sq))
        .map_err(|_| InputError::TooLarge(Quantity::Radius))
}
