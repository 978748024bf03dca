//! Per-body summaries, computed once and reused by every query.

use crate::error::{check_components, InputError, Quantity};
use crate::rounding::radius_up;
use crate::Float;

/// What the NEVQ bound needs of a body: an upper bound `R^` of the largest
/// distance `max_i |r_i|` of a body point from the rotation centre.
///
/// Computed once per body ([`VertexSet::try_new`]) or given directly for a
/// bounding sphere ([`BodySummary::from_radius`]); `O(1)` to use.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BodySummary<T> {
    max_radius: T,
}

impl<T: Float> BodySummary<T> {
    /// A summary for a body known to lie within `radius` of its rotation
    /// centre (a bounding sphere centred there).
    ///
    /// # Errors
    /// [`InputError::NonFinite`] / [`InputError::TooLarge`] with
    /// [`Quantity::Radius`], or [`InputError::NegativeRadius`].
    pub fn from_radius(radius: T) -> Result<Self, InputError> {
        check_components([radius, T::ZERO, T::ZERO], Quantity::Radius)?;
        if radius < T::ZERO {
            return Err(InputError::NegativeRadius);
        }
        Ok(Self { max_radius: radius })
    }

    /// The rounded-up largest radius `R^ >= max_i |r_i|`.
    #[inline]
    #[must_use]
    pub const fn max_radius(&self) -> T {
        self.max_radius
    }
}

/// The vertices of a body, relative to its rotation centre at the epoch,
/// with their [`BodySummary`]. Borrowed: building one allocates nothing.
///
/// For a convex body the vertices are its hull's; for any body they may be
/// all of its vertices (the bounds then hold for every point of the convex
/// hull, hence of the body).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct VertexSet<'a, T> {
    vertices: &'a [[T; 3]],
    summary: BodySummary<T>,
}

impl<'a, T: Float> VertexSet<'a, T> {
    /// Validates the vertices and computes the summary (`O(N)`, once per body).
    ///
    /// # Errors
    /// [`InputError::EmptyVertexSet`], or [`InputError::NonFinite`] /
    /// [`InputError::TooLarge`] with [`Quantity::Vertex`] naming the first bad
    /// vertex.
    ///
    /// ```
    /// use motion_bound::VertexSet;
    /// let cube = [[1.0, 1.0, 1.0], [-1.0, -1.0, -1.0], [1.0, -1.0, 1.0]];
    /// let body = VertexSet::try_new(&cube).unwrap();
    /// assert!(body.summary().max_radius() >= 3f64.sqrt());
    /// assert!(body.summary().max_radius() <= 3f64.sqrt() * (1.0 + 1e-15));
    /// ```
    pub fn try_new(vertices: &'a [[T; 3]]) -> Result<Self, InputError> {
        if vertices.is_empty() {
            return Err(InputError::EmptyVertexSet);
        }
        for (i, r) in vertices.iter().enumerate() {
            check_components(*r, Quantity::Vertex(i))?;
        }
        Ok(Self::from_validated(vertices))
    }

    /// The set of vertices that the caller has already validated as
    /// [`try_new`](Self::try_new) does (non-empty, finite, within
    /// [`Float::MAX_INPUT`]); a validated `TriMesh` builds its set with this.
    #[must_use]
    pub(crate) fn from_validated(vertices: &'a [[T; 3]]) -> Self {
        let mut max_sq = T::ZERO;
        for r in vertices {
            let sq = r[0] * r[0] + r[1] * r[1] + r[2] * r[2];
            if sq > max_sq {
                max_sq = sq;
            }
        }
        Self {
            vertices,
            summary: BodySummary {
                max_radius: radius_up(max_sq),
            },
        }
    }

    /// The summary (the rounded-up largest radius).
    #[inline]
    #[must_use]
    pub const fn summary(&self) -> BodySummary<T> {
        self.summary
    }

    /// The vertices, relative to the rotation centre at the epoch.
    #[inline]
    #[must_use]
    pub const fn vertices(&self) -> &'a [[T; 3]] {
        self.vertices
    }

    /// The number of vertices (at least one).
    #[inline]
    #[must_use]
    pub const fn len(&self) -> usize {
        self.vertices.len()
    }

    /// Always `false`: an empty set is rejected at construction.
    #[inline]
    #[must_use]
    pub const fn is_empty(&self) -> bool {
        false
    }
}

#[cfg(test)]
mod tests {
    use super::VertexSet;
    use crate::{InputError, Quantity};

    #[test]
    fn bad_vertex_sets_are_typed_errors() {
        let empty: [[f64; 3]; 0] = [];
        assert_eq!(
            VertexSet::try_new(&empty),
            Err(InputError::EmptyVertexSet),
            "empty"
        );
        let nan = [[0.0, 0.0, 0.0], [0.0, f32::NAN, 0.0]];
        assert_eq!(
            VertexSet::try_new(&nan),
            Err(InputError::NonFinite(Quantity::Vertex(1))),
            "NaN"
        );
        let huge = [[1e300, 0.0, 0.0]];
        assert_eq!(
            VertexSet::try_new(&huge),
            Err(InputError::TooLarge(Quantity::Vertex(0))),
            "huge"
        );
    }

    #[test]
    fn radius_is_rounded_up_even_when_squares_underflow() {
        let tiny = [[1e-200, 0.0, 0.0]];
        let body = VertexSet::try_new(&tiny).unwrap();
        assert!(body.summary().max_radius() >= 1e-200, "underflowed square");
        let origin = [[0.0f32; 3]];
        assert!(
            VertexSet::try_new(&origin).unwrap().summary().max_radius() >= 0.0,
            "origin"
        );
    }
}
