//! Tolerances, limits and the bound choice of a conservative-advancement query.

use core::fmt;

use crate::ca::Work;
use crate::{BoundKind, Float, RigidMotion};

/// Which directed bound a conservative-advancement query uses: a policy over
/// its many bounds, where [`BoundKind`] is the choice for one evaluation.
/// `Nevq` and `Evq` use that kind everywhere; `Auto` (the default) takes EVQ
/// wherever it costs `O(1)` and decides per step on vertex sets.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum BoundChoice {
    /// NEVQ (the seed's Eq. 3) everywhere: cheapest, loosest.
    Nevq,
    /// EVQ (the seed's Eq. 1, corrected Eq. 2) everywhere: tightest; `O(N)` per
    /// query on vertex sets, `O(1)` on bounding balls.
    Evq,
    /// EVQ wherever it costs `O(1)` (bounding balls, triangles); on a vertex
    /// set, NEVQ first and EVQ only when NEVQ's step would not end the query.
    #[default]
    Auto,
}

impl BoundChoice {
    /// The bound used where the cost is `O(1)` either way.
    #[inline]
    #[must_use]
    pub const fn cheap_kind(self) -> BoundKind {
        match self {
            Self::Nevq => BoundKind::Nevq,
            Self::Evq | Self::Auto => BoundKind::Evq,
        }
    }
}

/// Which pair within the contact distance a contact reports as its witness
/// ([`Contact::witness`](crate::ca::Contact::witness)), for steppers that
/// search for it ([`MeshPair`](crate::ca::MeshPair); the others measure one
/// closest pair anyway).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum WitnessSearch {
    /// The closest triangle pair at the contact time: once a pair within the
    /// contact distance is found, a branch and bound over the pairs whose
    /// certified gaps are below its distance (within the work budget; a
    /// budget that runs out keeps the closest found so far). What an engine
    /// builds contact points and normals from. The search starts from the
    /// last step's front of node pairs: about 2 % more instructions than
    /// [`First`](Self::First) on the seed's Table 1 knots (`docs/performance.md`).
    /// [`CaParams::witness_tolerance`] lets it stop earlier.
    #[default]
    Closest,
    /// The first pair found within the contact distance: no search beyond
    /// it. Its distance is at most the contact distance, and may be larger
    /// than the least (up to 1.6 times on the shipped meshes). For queries
    /// that need only the time.
    First,
}

/// The parameters of a conservative-advancement query.
///
/// ```
/// use motion_bound::ca::{BoundChoice, CaParams};
/// let p = CaParams::<f64>::default().with_contact_distance(1e-3).with_bound(BoundChoice::Evq);
/// assert_eq!(p.max_iterations, 100);
/// assert!(p.validate().is_ok());
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
#[non_exhaustive]
pub struct CaParams<T> {
    /// Contact is declared when the distance is at most this (in the scene's
    /// length unit; for meshes, the distance between their surfaces), at the
    /// start ([`CaOutcome::InitialContact`](crate::ca::CaOutcome::InitialContact))
    /// or as soon as a step finds the bodies within it. Any positive finite
    /// size is legal, larger than the bodies too; `0` is refused (no
    /// placement in floating point certifies surfaces that meet exactly),
    /// and one below what the placement resolves at the bodies' scale and
    /// distance from the origin ends the query with
    /// [`CaOutcome::PrecisionLimit`](crate::ca::CaOutcome::PrecisionLimit),
    /// which names that resolution. The steps keep the distance above
    /// half of it ([`clearance`](Self::clearance)), so the reported time is
    /// never later than the first time the distance falls to that.
    /// Default `1e-4`: set it for your scale.
    pub contact_distance: T,
    /// A step at most this long, taken at least this long before the end of
    /// the interval, ends the query with
    /// [`ContactCriterion::TimeTolerance`](crate::ca::ContactCriterion::TimeTolerance)
    /// (the bodies approach too fast to resolve further). Default `1e-9`.
    pub time_tolerance: T,
    /// The most iterations before [`CaOutcome::IterationLimit`](crate::ca::CaOutcome::IterationLimit)
    /// for bodies that do not turn; a query's limit adds
    /// [`iterations_per_turn`](Self::iterations_per_turn) for each turn its
    /// bodies make ([`iteration_limit`](Self::iteration_limit)). Default `100`.
    pub max_iterations: u32,
    /// The iterations a query is given for each full turn (`2 pi` rad) its
    /// two bodies make over the interval, on top of
    /// [`max_iterations`](Self::max_iterations): a body that turns many
    /// times comes near the other many times, and each near pass takes its
    /// own steps. Default `16` (the fast-spin fly-bys of
    /// `examples/fast_spins.rs` need at most about 9 a turn:
    /// `docs/performance.md`); `0` for a limit that does not follow the motion.
    pub iterations_per_turn: u32,
    /// Which bound to use. Default [`BoundChoice::Auto`].
    pub bound: BoundChoice,
    /// The time-resolved step: each iteration takes its bounds over the
    /// motions restricted to `[t, t + h]`, with `h` this factor times the
    /// previous step (the rest of the interval on the first iteration, or
    /// when `t + h` reaches past it). A step is never longer than `h`, so a
    /// step cut by the horizon makes the next horizon `factor` times longer.
    /// Over a shorter arc the EVQ term is tighter (the rotating direction
    /// sweeps less), so steps near contact get longer and fewer.
    /// Default `2`; `0` takes every bound over the rest of the interval.
    /// Must be `0` or greater than `1` (`+inf` acts like `0`).
    pub horizon_factor: T,
    /// Bound the *closing rate* of a pair with one-sided bounds (the rate of
    /// A along `n` plus that of B along `-n`, each signed:
    /// [`DirectedProbe::ball_rate`](crate::DirectedProbe::ball_rate)) instead
    /// of the sum of the absolute speeds `|v.n| + ...` the seed's bounds give.
    /// Never looser; much tighter when a body recedes or turns away.
    /// Default `true`; `false` steps exactly as the seed's Eq. 1 to 3 do.
    pub one_sided: bool,
    /// The most work one query may do, over all its iterations: node pairs
    /// and triangle pairs of a [`MeshPair`](crate::ca::MeshPair)'s
    /// traversal (steppers that do not count work ignore it); a query never
    /// does more than either count. When either runs out the query ends with
    /// [`CaOutcome::WorkLimit`](crate::ca::CaOutcome::WorkLimit) at the
    /// time reached (or, when the step has already found the bodies within
    /// the contact distance, with that contact and the closest pair found
    /// so far). [`CaReport::work`](crate::ca::CaReport::work) says what a
    /// query used. Every other part of a mesh query's work is bounded by
    /// these counts, and making the pair does none, whatever the meshes
    /// (duplicated and degenerate triangles included): about 0.4 to 0.8 us a
    /// unit (node pair or triangle pair) on meshes of 100,000 triangles
    /// ([`DEFAULT_WORK_BUDGET`](Self::DEFAULT_WORK_BUDGET)). Default
    /// [`DEFAULT_WORK_BUDGET`](Self::DEFAULT_WORK_BUDGET);
    /// [`Work::UNLIMITED`] for none.
    pub work_budget: Work,
    /// Which pair a contact reports as its witness. Default
    /// [`WitnessSearch::Closest`].
    pub witness: WitnessSearch,
    /// How far the witness of [`WitnessSearch::Closest`] may be from the
    /// least distance: the search for the closest pair stops once every
    /// pair left is certified no closer than the witness's distance minus
    /// this, so the witness's distance is at most the least distance plus
    /// this (each distance the exact distance of the triangles as placed, to
    /// its rounding). It saves only the pairs whose certified gaps fall
    /// within it of the witness: at 5 % of the contact distance, 3.5 % of
    /// the node pairs of board-against-sphere fly-bys, and almost none on
    /// the seed's knots, whose searched pairs are genuinely nearer
    /// (`docs/performance.md`). Default `0`: the closest pair. Must be
    /// finite and at least `0`; the contact's time is the same whatever it
    /// is.
    pub witness_tolerance: T,
}

impl<T: Float> Default for CaParams<T> {
    fn default() -> Self {
        Self {
            contact_distance: T::from_f64(1e-4),
            time_tolerance: T::from_f64(1e-9),
            max_iterations: 100,
            iterations_per_turn: 16,
            bound: BoundChoice::Auto,
            horizon_factor: T::TWO,
            one_sided: true,
            work_budget: Self::DEFAULT_WORK_BUDGET,
            witness: WitnessSearch::Closest,
            witness_tolerance: T::ZERO,
        }
    }
}

impl<T: Float> CaParams<T> {
    /// The default [`work_budget`](Self::work_budget): 50,000 node pairs and
    /// 10,000 triangle pairs, more than ten times what a query of the seed's
    /// Table 1 uses, and at most about 50 ms on meshes of 100,000 triangles,
    /// duplicated and degenerate ones included. Measured against the bunny
    /// (`examples/degenerate_meshes.rs`; `docs/performance.md`, "degenerate
    /// meshes bounded"), a unit of work (node pair or triangle pair) took
    /// 0.4 us on the 75K bunny with every vertex doubled and 24,592
    /// zero-area triangles added (19 ms for a query that used the 50,000
    /// node pairs), and 0.8 us on 100,000 near copies of one triangle, whose
    /// nodes all overlap so that no pair is pruned and the tree misses the
    /// cache (40 ms; up to 1.2 us and 58 ms with other jobs on the two
    /// cores). Exact copies share one leaf and cost nothing. A triangle pair
    /// against a curved convex shape (a cylinder, a cone: GJK) costs up to
    /// about 3.5 us, so 10,000 of them about 35 ms. Fast spins against a
    /// mesh fit: a convex shape and the bunny each turning 200 rad over the
    /// interval take at most about 1,100 triangle pairs and 11,000 node
    /// pairs (`examples/fast_spins.rs`; `docs/performance.md`, "fast
    /// spins against a mesh").
    pub const DEFAULT_WORK_BUDGET: Work = Work::new(50_000, 10_000);

    /// With another work budget ([`Work::UNLIMITED`] for none).
    #[must_use]
    pub const fn with_work_budget(mut self, budget: Work) -> Self {
        self.work_budget = budget;
        self
    }

    /// With another witness search.
    #[must_use]
    pub const fn with_witness(mut self, search: WitnessSearch) -> Self {
        self.witness = search;
        self
    }

    /// With another witness tolerance
    /// ([`witness_tolerance`](Self::witness_tolerance)).
    ///
    /// ```
    /// use motion_bound::ca::{CaError, CaParams, Parameter};
    /// let p = CaParams::<f64>::default().with_contact_distance(1e-3);
    /// // An engine that builds contacts to a micrometre needs no closer pair.
    /// assert!(p.with_witness_tolerance(1e-6).validate().is_ok());
    /// assert_eq!(
    ///     p.with_witness_tolerance(-1.0).validate(),
    ///     Err(CaError::InvalidParameter(Parameter::WitnessTolerance))
    /// );
    /// ```
    #[must_use]
    pub const fn with_witness_tolerance(mut self, tolerance: T) -> Self {
        self.witness_tolerance = tolerance;
        self
    }

    /// With another contact distance.
    #[must_use]
    pub const fn with_contact_distance(mut self, d: T) -> Self {
        self.contact_distance = d;
        self
    }

    /// With another time tolerance.
    #[must_use]
    pub const fn with_time_tolerance(mut self, t: T) -> Self {
        self.time_tolerance = t;
        self
    }

    /// With another iteration limit.
    #[must_use]
    pub const fn with_max_iterations(mut self, n: u32) -> Self {
        self.max_iterations = n;
        self
    }

    /// With another number of iterations per turn (`0`: the limit is
    /// [`max_iterations`](Self::max_iterations) whatever the bodies turn).
    #[must_use]
    pub const fn with_iterations_per_turn(mut self, n: u32) -> Self {
        self.iterations_per_turn = n;
        self
    }

    /// The iteration limit of a query of these motions:
    /// [`max_iterations`](Self::max_iterations) plus
    /// [`iterations_per_turn`](Self::iterations_per_turn) times the turns
    /// both bodies make over the interval (`(|w_a| + |w_b|) (t1 - t0) / 2 pi`,
    /// rounded up), saturating at `u32::MAX`.
    ///
    /// ```
    /// use motion_bound::ca::CaParams;
    /// use motion_bound::RigidMotion;
    /// let still = RigidMotion::try_from_arrays([0.0; 3], [1.0, 0.0, 0.0], [0.0; 3])?;
    /// // 200 rad over [0, 1]: 31.8 turns, 32 with the rounding up.
    /// let spinning = RigidMotion::try_from_arrays([0.0; 3], [0.0; 3], [0.0, 200.0, 0.0])?;
    /// let p = CaParams::<f64>::default();
    /// assert_eq!(p.iteration_limit(&still, &still), 100);
    /// assert_eq!(p.iteration_limit(&spinning, &still), 100 + 16 * 32);
    /// # Ok::<(), motion_bound::InputError>(())
    /// ```
    #[must_use]
    pub fn iteration_limit(&self, a: &RigidMotion<T>, b: &RigidMotion<T>) -> u32 {
        if self.iterations_per_turn == 0 {
            return self.max_iterations;
        }
        let length = a.interval().end().to_f64() - a.interval().start().to_f64();
        let angle = (a.angular_speed().to_f64() + b.angular_speed().to_f64()) * length;
        let turns = angle / core::f64::consts::TAU;
        if turns.is_nan() || turns <= 0.0 {
            return self.max_iterations;
        }
        // Rounded up (`as` truncates and saturates; `ceil` needs `std`).
        let whole = turns as u32;
        let whole = if f64::from(whole) < turns {
            whole.saturating_add(1)
        } else {
            whole
        };
        self.max_iterations
            .saturating_add(whole.saturating_mul(self.iterations_per_turn))
    }

    /// With another bound choice.
    #[must_use]
    pub const fn with_bound(mut self, b: BoundChoice) -> Self {
        self.bound = b;
        self
    }

    /// With one-sided (closing-rate) bounds on or off.
    #[must_use]
    pub const fn with_one_sided(mut self, on: bool) -> Self {
        self.one_sided = on;
        self
    }

    /// With another horizon factor (`0` turns the time-resolved step off).
    #[must_use]
    pub const fn with_horizon_factor(mut self, factor: T) -> Self {
        self.horizon_factor = factor;
        self
    }

    /// The clearance the certified steps keep: half the contact distance.
    ///
    /// Every step is certified to keep the bodies more than this apart, so a
    /// query never steps over a stretch where the distance falls to half the
    /// contact distance, and a contact is then declared as soon as a step
    /// finds the distance at most the contact distance (which it must, before
    /// the distance reaches the clearance: the steps shrink towards that
    /// time). The half is a trade: a clearance nearer the contact distance
    /// would catch shallower dips but converge more slowly.
    #[inline]
    #[must_use]
    pub fn clearance(&self) -> T {
        self.contact_distance * T::HALF
    }

    /// Checks the parameters.
    ///
    /// # Errors
    /// [`CaError::InvalidParameter`] naming a zero contact distance, a
    /// tolerance (of time or of the witness) that is negative, NaN
    /// or infinite, a zero iteration limit, or a horizon factor that is
    /// neither `0` nor above `1`.
    pub fn validate(&self) -> Result<(), CaError> {
        let ok = |x: T| x.is_finite() && x >= T::ZERO;
        // A zero contact distance asks for surfaces that meet exactly, which
        // no placement in floating point can certify (every query would end
        // in `PrecisionLimit`): refused here, where it is made.
        if !(ok(self.contact_distance) && self.contact_distance > T::ZERO) {
            return Err(CaError::InvalidParameter(Parameter::ContactDistance));
        }
        if !ok(self.time_tolerance) {
            return Err(CaError::InvalidParameter(Parameter::TimeTolerance));
        }
        if !ok(self.witness_tolerance) {
            return Err(CaError::InvalidParameter(Parameter::WitnessTolerance));
        }
        let f = self.horizon_factor;
        if !(f == T::ZERO || f > T::ONE) {
            return Err(CaError::InvalidParameter(Parameter::HorizonFactor));
        }
        if self.max_iterations == 0 {
            return Err(CaError::InvalidParameter(Parameter::MaxIterations));
        }
        Ok(())
    }
}

/// The tuning knobs of the mesh traversal ([`MeshPair`](crate::ca::MeshPair)):
/// every value in range is sound; they trade work per step against steps.
///
/// ```
/// use motion_bound::ca::MeshParams;
/// let p = MeshParams::<f64>::default().with_far_ratio(8.0);
/// assert_eq!((p.accept_fraction, p.far_ratio), (1.0, 8.0));
/// assert!(p.validate().is_ok());
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
#[non_exhaustive]
pub struct MeshParams<T> {
    /// A step is accepted once every pair left in the queue has a step at
    /// least this fraction of the best found. Default `1`: the least step
    /// over the finest cut the traversal reaches. A smaller fraction refines
    /// less per step and takes shorter steps. In `(0, 1]`.
    pub accept_fraction: T,
    /// A node pair whose volumes' gap is at least this many times the sum
    /// of its balls' radii is settled with its own step, not split: below
    /// it the gap grows by at most `2 / ratio` of itself, so splitting buys
    /// little step and costs a descent. Default `6`; `+inf` always splits.
    /// At least `0`.
    pub far_ratio: T,
    /// Whether a step starts from the node pairs the last step of the same
    /// query ended with (its front), each keeping the step it certified
    /// until that runs out, rather than descending from the roots
    /// (`proofs/09-ca-toi.md`, Lemma 9.9); a step takes the front only when
    /// at least half of it would keep its step. (A mesh against a convex
    /// shape takes its own switch,
    /// [`MeshConvexPair::with_carry_front`](crate::ca::MeshConvexPair::with_carry_front).) The outcomes are the same
    /// either way. Default `true`: on Intel Xeon (2026-12-03,
    /// `docs/performance.md`) 6 to 13 % less time on the seed's knot queries
    /// (2.8K to 34K triangles), and up to 5 % more on meshes of a few hundred
    /// triangles.
    pub carry_front: bool,
}

impl<T: Float> Default for MeshParams<T> {
    fn default() -> Self {
        Self {
            accept_fraction: T::ONE,
            far_ratio: T::from_f64(6.0),
            carry_front: true,
        }
    }
}

impl<T: Float> MeshParams<T> {
    /// With another accept fraction.
    #[must_use]
    pub const fn with_accept_fraction(mut self, fraction: T) -> Self {
        self.accept_fraction = fraction;
        self
    }

    /// With another far ratio.
    #[must_use]
    pub const fn with_far_ratio(mut self, ratio: T) -> Self {
        self.far_ratio = ratio;
        self
    }

    /// With the front carried from step to step, or not.
    #[must_use]
    pub const fn with_carry_front(mut self, carry: bool) -> Self {
        self.carry_front = carry;
        self
    }

    /// Checks the knobs.
    ///
    /// # Errors
    /// [`CaError::InvalidParameter`] with [`Parameter::AcceptFraction`] for a
    /// fraction outside `(0, 1]` (or NaN), [`Parameter::FarRatio`] for a
    /// negative or NaN ratio.
    pub fn validate(&self) -> Result<(), CaError> {
        let f = self.accept_fraction;
        if !(f > T::ZERO && f <= T::ONE) {
            return Err(CaError::InvalidParameter(Parameter::AcceptFraction));
        }
        if self.far_ratio.is_nan() || self.far_ratio < T::ZERO {
            return Err(CaError::InvalidParameter(Parameter::FarRatio));
        }
        Ok(())
    }
}

/// A parameter of a query ([`CaParams`] or [`MeshParams`]), as named by
/// [`CaError::InvalidParameter`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum Parameter {
    /// [`CaParams::contact_distance`]: positive and finite.
    ContactDistance,
    /// [`CaParams::time_tolerance`]: finite and at least `0`.
    TimeTolerance,
    /// [`CaParams::max_iterations`]: at least `1`.
    MaxIterations,
    /// [`CaParams::horizon_factor`]: `0` or above `1`.
    HorizonFactor,
    /// [`MeshParams::accept_fraction`]: in `(0, 1]`.
    AcceptFraction,
    /// [`MeshParams::far_ratio`]: at least `0`.
    FarRatio,
    /// [`CaParams::witness_tolerance`]: finite and at least `0`.
    WitnessTolerance,
}

impl fmt::Display for Parameter {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Self::ContactDistance => "contact_distance (positive and finite)",
            Self::TimeTolerance => "time_tolerance (finite, at least 0)",
            Self::MaxIterations => "max_iterations (at least 1)",
            Self::HorizonFactor => "horizon_factor (0 or above 1)",
            Self::AcceptFraction => "accept_fraction (in (0, 1])",
            Self::FarRatio => "far_ratio (at least 0)",
            Self::WitnessTolerance => "witness_tolerance (finite, at least 0)",
        })
    }
}

/// Why a conservative-advancement query could not run.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub enum CaError {
    /// A parameter is out of range.
    InvalidParameter(Parameter),
    /// The two motions are over different time intervals.
    IntervalMismatch,
    /// An input was rejected by the core (a motion restricted to a
    /// sub-interval, a bounding ball, a vertex set).
    Input(crate::InputError),
    /// A half-space's motion has a start orientation or an angular
    /// velocity: half-spaces may only translate (a turning plane sweeps
    /// unboundedly far from its rotation centre). Give its normal in the
    /// world frame.
    TurnedHalfSpace,
    /// No stepper takes this pair of shape kinds (two half-spaces).
    Unsupported,
}

impl fmt::Display for CaError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::InvalidParameter(p) => write!(f, "parameter out of range: {p}"),
            Self::IntervalMismatch => f.write_str("the two motions have different intervals"),
            Self::Input(e) => write!(f, "invalid input: {e}"),
            Self::Unsupported => f.write_str("no stepper takes this pair of shape kinds"),
            Self::TurnedHalfSpace => {
                f.write_str("a half-space may only translate (no start orientation, no spin)")
            }
        }
    }
}

impl core::error::Error for CaError {}

impl From<crate::InputError> for CaError {
    fn from(e: crate::InputError) -> Self {
        Self::Input(e)
    }
}
