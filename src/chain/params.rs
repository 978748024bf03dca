//! A chain query's parameters: the contact distance, the iteration limit
//! and the broad phase's sub-intervals.

use crate::chain::model::ChainError;
use crate::Float;

/// A query's parameters.
#[derive(Clone, Copy, Debug, PartialEq)]
#[non_exhaustive]
pub struct ChainParams<T> {
    /// Surfaces this close count as touching (world units; default `1e-3`).
    pub contact_distance: T,
    /// Iterations per pair and segment (default 10,000).
    pub max_iterations: usize,
    /// Sub-intervals of the broad phase's swept balls (1 to 64, default 32).
    pub broad_pieces: usize,
}

impl<T: Float> Default for ChainParams<T> {
    fn default() -> Self {
        Self {
            contact_distance: T::from_f64(1e-3),
            max_iterations: 10_000,
            broad_pieces: 32,
        }
    }
}

impl<T: Float> ChainParams<T> {
    /// With a contact distance.
    #[must_use]
    pub fn with_contact_distance(mut self, d: T) -> Self {
        self.contact_distance = d;
        self
    }

    /// `Ok` when every parameter is in its range.
    pub(super) fn validate(&self) -> Result<(), ChainError> {
        if !(self.contact_distance > T::ZERO && self.contact_distance.is_finite()) {
            return Err(ChainError::InvalidParameter(
                "contact_distance must be positive and finite",
            ));
        }
        if self.max_iterations == 0 || self.broad_pieces == 0 || self.broad_pieces > 64 {
            return Err(ChainError::InvalidParameter(
                "max_iterations and broad_pieces (1 to 64) must be positive",
            ));
        }
        Ok(())
    }
}
