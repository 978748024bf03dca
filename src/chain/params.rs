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
    /// Refuse a segment whose ends are outside the joints' limits
    /// ([`ChainError::BeyondLimits`]), in
    /// [`check_segment`](crate::chain::ChainScene::check_segment) and
    /// [`check_path`](crate::chain::ChainScene::check_path): a planner's
    /// sample beyond a limit is a bug to hear about, not a motion to certify.
    /// Default `true`; `false` checks any segment (a chain whose limits are
    /// soft, or a query of motions that are not the robot's).
    pub within_limits: bool,
    /// What an edge query ([`check_edge`](crate::chain::ChainScene::check_edge),
    /// [`edge_is_free`](crate::chain::ChainScene::edge_is_free)) keeps
    /// between the links and everything else (world units, default `0`:
    /// exact against the meshes and shapes): a planner's safety margin.
    pub padding: T,
    /// The most items (a ball or triangle against what it is checked
    /// against) an edge query tests before it answers
    /// [`EdgeOutcome::Undecided`](crate::chain::EdgeOutcome::Undecided)
    /// (default 250,000: about 40 ms on the Panda's meshes, `docs/performance.md`).
    pub edge_budget: usize,
    /// Whether the edge queries rake the edge over time first
    /// (`proofs/13-chains.md`, Lemmas 13.9 to 13.13): the chain placed at up
    /// to 32 times at once in `f32` lanes, every checked pair's link covers
    /// tested there, and only what that does not clear handed to the finer
    /// engine. On by default; the answers are certified either way. It runs
    /// when [`edge_budget`](Self::edge_budget) is at least 4,096 (its lane
    /// tests count against the budget); a smaller budget gets the engine
    /// alone, item by item.
    pub rake: bool,
}

impl<T: Float> Default for ChainParams<T> {
    fn default() -> Self {
        Self {
            contact_distance: T::from_f64(1e-3),
            max_iterations: 10_000,
            broad_pieces: 32,
            within_limits: true,
            padding: T::ZERO,
            edge_budget: 250_000,
            rake: true,
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

    /// With the limit check on or off
    /// ([`within_limits`](Self::within_limits)).
    #[must_use]
    pub fn with_within_limits(mut self, on: bool) -> Self {
        self.within_limits = on;
        self
    }

    /// With a padding ([`padding`](Self::padding)).
    #[must_use]
    pub fn with_padding(mut self, padding: T) -> Self {
        self.padding = padding;
        self
    }

    /// With an edge query's work budget ([`edge_budget`](Self::edge_budget)).
    #[must_use]
    pub fn with_edge_budget(mut self, items: usize) -> Self {
        self.edge_budget = items;
        self
    }

    /// `Ok` when every parameter is in its range.
    /// [`rake`](Self::rake) on or off.
    #[must_use]
    pub fn with_rake(mut self, on: bool) -> Self {
        self.rake = on;
        self
    }

    pub(super) fn validate(&self) -> Result<(), ChainError> {
        if !(self.contact_distance > T::ZERO && self.contact_distance.is_finite()) {
            return Err(ChainError::InvalidParameter(
                "contact_distance must be positive and finite",
            ));
        }
        if !(self.padding >= T::ZERO && self.padding.is_finite()) {
            return Err(ChainError::InvalidParameter(
                "padding must be non-negative and finite",
            ));
        }
        if self.edge_budget == 0 {
            return Err(ChainError::InvalidParameter("edge_budget must be positive"));
        }
        if self.max_iterations == 0 || self.broad_pieces == 0 || self.broad_pieces > 64 {
            return Err(ChainError::InvalidParameter(
                "max_iterations and broad_pieces (1 to 64) must be positive",
            ));
        }
        Ok(())
    }
}
