//! What a conservative-advancement query found, and what ended it.

use crate::{Direction, Float, Point3};

/// Closest features at one time: the distance and a witness point on each
/// body (in the world frame).
#[derive(Clone, Copy, Debug, PartialEq)]
#[non_exhaustive]
pub struct Witness<T> {
    /// The distance found between the bodies (for a contact, at most the
    /// contact distance).
    pub distance: T,
    /// The witness point on body A.
    pub on_a: Point3<T>,
    /// The witness point on body B.
    pub on_b: Point3<T>,
}

impl<T: Float> Witness<T> {
    /// The closest features `on_a`, `on_b` at `distance` apart (what a
    /// [`Proximity`](crate::ca::Proximity) oracle returns).
    #[inline]
    #[must_use]
    pub const fn new(distance: T, on_a: Point3<T>, on_b: Point3<T>) -> Self {
        Self {
            distance,
            on_a,
            on_b,
        }
    }

    /// The unit direction from `on_a` to `on_b`, or `None` when the witness
    /// points coincide (a touching contact has no defined direction from the
    /// points alone).
    #[must_use]
    pub fn normal(&self) -> Option<Direction<T>> {
        Direction::try_new(self.on_b - self.on_a).ok()
    }
}

/// A contact: the time and the closest features at that time.
///
/// What "contact" means: the bodies' computed distance is at most
/// [`CaParams::contact_distance`](crate::ca::CaParams::contact_distance). For
/// meshes the distance is between their surfaces (the triangles): a body
/// wholly inside a hollow mesh is not in contact with it, while one starting
/// inside a mesh declared solid ([`TriMesh::try_solid`](crate::TriMesh::try_solid))
/// is an initial contact (`proofs/09-ca-toi.md`, Lemma 9.7). The reported time
/// is never later than the first time the surfaces touch (distance 0) under
/// the exact motions (`proofs/09-ca-toi.md`); conservative advancement steps
/// towards touching, so it is not necessarily the first time the distance
/// fell to the contact distance.
#[derive(Clone, Copy, Debug, PartialEq)]
#[non_exhaustive]
pub struct Contact<T> {
    /// The reported time of contact; never later than the first time the
    /// surfaces touch.
    pub time: T,
    /// The closest features at `time`, when the stepper measured them
    /// (always for [`ContactCriterion::Distance`] and initial contacts; a
    /// contact by time tolerance may have none).
    pub witness: Option<Witness<T>>,
    /// The unit contact normal from A to B at `time`, when the stepper knew
    /// one (the last separating direction it used), else the witnesses'.
    pub normal: Option<Direction<T>>,
}

/// Which tolerance declared a contact.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum ContactCriterion {
    /// The distance fell to the contact distance or below.
    Distance,
    /// The certified steps stalled: at `time`, at least the time tolerance
    /// before the interval's end, a step was at most the time tolerance (or
    /// too short to advance time at all) while the distance was still above
    /// the contact distance (a very fast or grazing approach).
    ///
    /// Guaranteed: no contact before `time`, and `time + time_tolerance` is
    /// before the interval's end. Not guaranteed: that a contact follows
    /// (a grazing pass may stay apart). Near the end no stall is declared:
    /// a query there goes on to a contact, [`CaOutcome::Separated`] or
    /// [`CaOutcome::IterationLimit`].
    TimeTolerance,
}

/// What ended a conservative-advancement query.
#[derive(Clone, Copy, Debug, PartialEq)]
#[non_exhaustive]
pub enum CaOutcome<T> {
    /// Contact at `contact.time`, declared by `criterion`.
    Contact {
        /// The contact.
        contact: Contact<T>,
        /// Which tolerance declared it.
        criterion: ContactCriterion,
    },
    /// The bodies are already within the contact distance at the start, or
    /// one starts inside the other's solid mesh
    /// ([`TriMesh::try_solid`](crate::TriMesh::try_solid)): then the
    /// witness has distance `0`, both its points at the point found inside,
    /// and no normal.
    InitialContact(Contact<T>),
    /// No contact in the interval: a certified step from the last time
    /// reached the interval's end (in exact arithmetic), so the bodies do not
    /// touch anywhere in it.
    Separated,
    /// Undecided from `time` on: the iteration limit was reached, or, within
    /// the time tolerance of the interval's end, a step was too short to
    /// advance time. No contact before `time` (certified), nothing known
    /// after.
    IterationLimit {
        /// The safe time reached.
        time: T,
    },
    /// Undecided from `time` on: the query's work budget
    /// ([`CaParams::work_budget`](crate::ca::CaParams::work_budget)) ran out
    /// during the step from `time`. No contact before `time` (certified),
    /// nothing known after: treat it as a possible contact at `time`, as
    /// [`IterationLimit`](Self::IterationLimit).
    WorkLimit {
        /// The safe time reached.
        time: T,
    },
    /// Undecided from `time` on: at `time` the bodies came within the
    /// contact distance plus what the placement's rounding can resolve, and
    /// the contact distance is below that resolution, so no step can be
    /// certified and no distance within the contact distance trusted. No
    /// contact before `time` (certified); treat it as a possible contact at
    /// `time`. A contact distance above `resolution` (or bodies nearer the
    /// origin of their own frames, or of smaller extent) resolves it.
    PrecisionLimit {
        /// The safe time reached.
        time: T,
        /// The length the placement at `time` cannot resolve: the certified
        /// gaps lose this much to rounding (at least half the contact
        /// distance, else this outcome is not given).
        resolution: T,
    },
}

impl<T: Float> CaOutcome<T> {
    /// The contact, if the query declared one (initial or later).
    #[must_use]
    pub fn contact(&self) -> Option<&Contact<T>> {
        match self {
            Self::Contact { contact, .. } | Self::InitialContact(contact) => Some(contact),
            Self::Separated
            | Self::IterationLimit { .. }
            | Self::WorkLimit { .. }
            | Self::PrecisionLimit { .. } => None,
        }
    }

    /// The earliest time a contact may happen: the contact time, the time
    /// an undecided query reached (iteration, work or precision limit), or
    /// `None` when separated over the interval.
    #[must_use]
    pub fn earliest_possible_contact(&self) -> Option<T> {
        match self {
            Self::Contact { contact, .. } | Self::InitialContact(contact) => Some(contact.time),
            Self::IterationLimit { time }
            | Self::WorkLimit { time }
            | Self::PrecisionLimit { time, .. } => Some(*time),
            Self::Separated => None,
        }
    }
}

/// The outcome with the number of iterations (calls of the stepper) it took
/// and the work it did.
#[derive(Clone, Copy, Debug, PartialEq)]
#[non_exhaustive]
pub struct CaReport<T> {
    /// What ended the query.
    pub outcome: CaOutcome<T>,
    /// Iterations used (at least one).
    pub iterations: u32,
    /// The work the stepper did for this query ([`CaStep::work`](crate::ca::CaStep::work);
    /// zero for steppers that do not count it).
    pub work: Work,
}

/// Work of a query, counted by the steppers that descend hierarchies
/// ([`MeshPair`](crate::ca::MeshPair)), or a budget of it
/// ([`CaParams::work_budget`](crate::ca::CaParams::work_budget)).
///
/// ```
/// use motion_bound::ca::Work;
/// let budget = Work::new(1_000, 100);
/// let used = Work::new(400, 100);
/// assert_eq!(budget.saturating_sub(used), Work::new(600, 0));
/// assert!(!used.exceeds(budget) && Work::new(0, 101).exceeds(budget));
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub struct Work {
    /// Node pairs taken from the traversal's queue and worked on (split,
    /// settled or measured): each costs up to two child evaluations.
    pub node_pairs: u64,
    /// Triangle pairs whose exact distance was computed.
    pub triangle_pairs: u64,
}

impl Work {
    /// No work.
    pub const ZERO: Self = Self::new(0, 0);
    /// No limit.
    pub const UNLIMITED: Self = Self::new(u64::MAX, u64::MAX);

    /// `node_pairs` node pairs and `triangle_pairs` triangle pairs.
    #[inline]
    #[must_use]
    pub const fn new(node_pairs: u64, triangle_pairs: u64) -> Self {
        Self {
            node_pairs,
            triangle_pairs,
        }
    }

    /// Each count less `other`'s, at least zero.
    #[inline]
    #[must_use]
    pub const fn saturating_sub(self, other: Self) -> Self {
        Self::new(
            self.node_pairs.saturating_sub(other.node_pairs),
            self.triangle_pairs.saturating_sub(other.triangle_pairs),
        )
    }

    /// Each count plus `other`'s, at most `u64::MAX`.
    #[cfg(feature = "alloc")]
    #[inline]
    #[must_use]
    pub(crate) const fn saturating_add(self, other: Self) -> Self {
        Self::new(
            self.node_pairs.saturating_add(other.node_pairs),
            self.triangle_pairs.saturating_add(other.triangle_pairs),
        )
    }

    /// Whether either count is above `budget`'s.
    #[inline]
    #[must_use]
    pub const fn exceeds(self, budget: Self) -> bool {
        self.node_pairs > budget.node_pairs || self.triangle_pairs > budget.triangle_pairs
    }
}
