//! What one step finds: a node pair's safe step or nearness
//! ([`NodeStep`]), and the witnesses of the pairs it measured ([`Found`]);
//! and the rules both mesh steppers decide by from them: what to do with
//! the pair at the head of the queue, which child pairs to queue, and the
//! step's result.

use crate::ca::{StepResult, Witness};
use crate::{Direction, Float};

/// What the safe step of a node pair found (`Descent::node_step`,
/// `MeshConvexPair::node_step`).
#[derive(Clone, Copy, Debug)]
pub(super) enum NodeStep<T> {
    /// Certified apart by more than the contact distance, with its safe step;
    /// `far`: far apart for its size (its step is taken as it is); `gap`
    /// and `rate`: the certified gap the step was made from and the sum of
    /// both bodies' bounds on its closing speed (what the front needs,
    /// Lemma 9.9; `rate = +inf` certifies nothing beyond the step's time).
    Apart { step: T, far: bool, gap: T, rate: T },
    /// Its certified gap (`-inf` when no direction separates the volumes) is
    /// at most the contact distance: it must be split.
    Near(T),
}

/// What one step's measured triangle pairs found.
#[derive(Clone, Copy, Debug)]
pub(super) struct Found<T> {
    /// The closest pair measured, and its triangles.
    pub(super) closest: Option<Witness<T>>,
    pub(super) closest_triangles: Option<(u32, u32)>,
    /// The direction of the pair with the least step.
    pub(super) normal: Option<Direction<T>>,
    /// The closest pair within the contact distance, if any: its witness,
    /// triangles and direction.
    pub(super) touching: Option<Witness<T>>,
    pub(super) touching_triangles: Option<(u32, u32)>,
    pub(super) touching_normal: Option<Direction<T>>,
    /// How far the witness may be from the closest pair
    /// ([`CaParams::witness_tolerance`](crate::ca::CaParams::witness_tolerance)).
    pub(super) tolerance: T,
}

impl<T: Float> Found<T> {
    /// Nothing found yet, in a search for the closest pair to within
    /// `tolerance`.
    pub(super) fn new(tolerance: T) -> Self {
        Self {
            tolerance,
            ..Self::default()
        }
    }

    /// Once a contact is found, the certified gap a pair must be below to be
    /// searched further for a closer one: the contact's distance less the
    /// tolerance, rounded down (exactly the distance for a zero tolerance).
    /// A pair whose gap is at least this is no closer than the witness by
    /// more than the tolerance.
    #[inline]
    pub(super) fn bar(&self) -> Option<T> {
        self.touching
            .map(|w| crate::rounding::diff_down(w.distance, self.tolerance))
    }
}

impl<T: Float> Default for Found<T> {
    fn default() -> Self {
        Self {
            tolerance: T::ZERO,
            closest: None,
            closest_triangles: None,
            normal: None,
            touching: None,
            touching_triangles: None,
            touching_normal: None,
        }
    }
}

impl<T: Float> NodeStep<T> {
    /// The step as the descent takes it: below the resolution (`limited`)
    /// no pair is near, and one within the clearance (or unseparated) is a
    /// zero step (`proofs/09-ca-toi.md`, Lemma 9.6).
    #[inline]
    pub(super) fn resolved(self, limited: bool) -> Self {
        match self {
            Self::Near(_) if limited => Self::Apart {
                step: T::ZERO,
                far: false,
                gap: T::ZERO,
                rate: T::INFINITY,
            },
            other => other,
        }
    }
}

/// What a descent does with the node pair at the head of its queue
/// ([`Found::head`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Head {
    /// Work on it.
    Go,
    /// Stop: the contact found stands.
    Stop,
    /// Stop best-first: the pair's step, and every step left in the queue,
    /// is at least the best step found (times the accept fraction).
    Cut,
    /// Stop undecided: the work budget is spent before any contact.
    OutOfWork,
}

impl<T: Float> Found<T> {
    /// What the descent does with the pair at the head of its queue
    /// (`near`, and its `key`: its certified gap when near, else its step),
    /// given the best step `best`, the accept fraction `accept` and whether
    /// the work budget is spent (`out_of_work`).
    ///
    /// Once a contact is found the rest is a branch and bound for the
    /// closest pair: near pairs come first, least certified gap (a lower
    /// bound of their distance) first, and every other pair is farther than
    /// the contact distance; so the descent stops at the first pair that is
    /// not near or whose gap is not below the contact's [`bar`](Self::bar)
    /// (at once when only the first contact is wanted). Before that it is best-first: every pair left
    /// has a step at least `key`, so once `key` reaches `best * accept`,
    /// `min(best, key)` is safe for the whole meshes. Out of work, a contact
    /// already found stands (its witness the closest pair so far); anything
    /// else is undecided.
    #[inline]
    pub(super) fn head(
        &self,
        (near, key): (bool, T),
        (best, accept): (T, T),
        first_only: bool,
        out_of_work: bool,
    ) -> Head {
        if let Some(bar) = self.bar() {
            if first_only || !near || key >= bar {
                return Head::Stop;
            }
        } else if !near && key >= best * accept {
            return Head::Cut;
        }
        match (out_of_work, self.touching) {
            (false, _) => Head::Go,
            (true, Some(_)) => Head::Stop,
            (true, None) => Head::OutOfWork,
        }
    }

    /// Whether a child node pair whose own step is `step` goes into the
    /// queue (the others are pruned): once a contact is found, a near pair
    /// whose gap is below the [`bar`](Self::bar); before that, a near pair
    /// or one whose step is short of the best step `best`.
    #[inline]
    pub(super) fn queues(&self, step: NodeStep<T>, best: T) -> bool {
        match (step, self.bar()) {
            (NodeStep::Near(g), Some(bar)) if g < bar => true,
            (_, Some(_)) => false,
            (NodeStep::Apart { step, .. }, None) if step >= best => false,
            (_, None) => true,
        }
    }

    /// Keeps the witness `w` of a measured pair (with its `triangles`, when
    /// it has them): as the closest pair when it is the closest so far; and
    /// when the pair is within the contact distance (`apart` false) or
    /// touching (no direction `dir`), as the contact when it is the closest
    /// one so far, with its direction. The direction along which the pair's
    /// own step is then wanted: none for a contact, and none once a contact
    /// is found (the search for the closest pair needs no steps).
    #[inline]
    pub(super) fn keep(
        &mut self,
        w: Witness<T>,
        triangles: Option<(u32, u32)>,
        dir: Option<Direction<T>>,
        apart: bool,
    ) -> Option<Direction<T>> {
        if self.closest.is_none_or(|b| w.distance < b.distance) {
            self.closest = Some(w);
            self.closest_triangles = triangles;
        }
        let (Some(n), true) = (dir, apart) else {
            if self.touching.is_none_or(|b| w.distance < b.distance) {
                self.touching = Some(w);
                self.touching_triangles = triangles;
                self.touching_normal = dir;
            }
            return None;
        };
        self.touching.is_none().then_some(n)
    }

    /// Folds a measured pair's own step `step` along `n` into the best step
    /// `best`: the least step, with its direction.
    #[inline]
    pub(super) fn fold(&mut self, step: T, n: Direction<T>, best: &mut T) {
        if step < *best {
            *best = step;
            self.normal = Some(n);
        }
    }

    /// The triangles of the step's witness: the contact's if one was
    /// found, else the closest pair's.
    #[inline]
    pub(super) fn witness_triangles(&self) -> Option<(u32, u32)> {
        if self.touching.is_some() {
            self.touching_triangles
        } else {
            self.closest_triangles
        }
    }

    /// The step's result from what it found and its best step `best`: the
    /// contact found, with its direction; else, below the resolution
    /// (`limited`) with no positive step, the precision limit `resolution`
    /// (`proofs/09-ca-toi.md`, Lemma 9.6); else the safe step `best`, with
    /// the closest pair measured and the direction of the least step.
    #[inline]
    pub(super) fn verdict(&self, best: T, limited: bool, resolution: T) -> StepResult<T> {
        if let Some(witness) = self.touching {
            return StepResult::Touching {
                witness,
                normal: self.touching_normal,
            };
        }
        if limited && best <= T::ZERO {
            return StepResult::PrecisionLimit { resolution };
        }
        StepResult::Advance {
            step: best,
            witness: self.closest,
            normal: self.normal,
        }
    }
}
