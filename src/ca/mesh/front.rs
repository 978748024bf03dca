//! The front of node pairs one step of a [`MeshPair`](super::MeshPair) hands
//! to the next (`proofs/09-ca-toi.md`, Lemma 9.9): the cut of both
//! hierarchies the step ended with, each pair with how long what the step
//! measured of it stays true.

use crate::rounding::{advance_down, step_down};
use crate::{Float, RigidMotion};

/// A node pair (node `i` of A, node `j` of B) of the cut a step ended with,
/// and its certificates: its distance stays above the clearance until
/// `deadline`, and above the contact distance before `near_from`
/// (`near_from <= deadline`; times of the query, as `f64`, exact for `f32`
/// and `f64`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct FrontEntry {
    pub(super) i: u32,
    pub(super) j: u32,
    pub(super) deadline: f64,
    pub(super) near_from: f64,
}

impl FrontEntry {
    /// The entry of a pair measured at time `t` with the bounds of the
    /// motions over `[t, horizon]`: its safe step `step` (certified gap
    /// `gap` closing at most at `rate`, the sum of both bodies' bounds) and
    /// the contact distance `cd`. Both times are rounded down, and neither
    /// passes `horizon`, where the bounds stop holding.
    #[inline]
    pub(super) fn new<T: Float>(
        (i, j): (u32, u32),
        t: T,
        horizon: T,
        (step, gap, rate, cd): (T, T, T, T),
    ) -> Self {
        let near = step_down(gap, cd, rate, T::ZERO);
        Self {
            i,
            j,
            deadline: until(t, step, horizon).to_f64(),
            near_from: until(t, near.min_nan(step), horizon).to_f64(),
        }
    }
}

impl FrontEntry {
    /// Whether a step at `t` whose best step is at most `best` would
    /// measure the pair anew: it may be near, or what is left of its step
    /// is below `best` (roughly: only a choice of speed rests on it).
    #[inline]
    pub(super) fn stale<T: Float>(&self, t: T, best: T) -> bool {
        let t = t.to_f64();
        t >= self.near_from || self.near_from.is_nan() || self.deadline - t < best.to_f64()
    }
}

/// A time at most `t + step` in exact arithmetic and at most `horizon`: `t`
/// itself for a NaN or negative step.
#[inline]
fn until<T: Float>(t: T, step: T, horizon: T) -> T {
    if step.is_nan() || step < T::ZERO {
        return t;
    }
    if step == T::INFINITY {
        return horizon;
    }
    let d = advance_down(t, step);
    if d <= horizon {
        d
    } else if d > horizon {
        horizon
    } else {
        t
    }
}

/// What a front is valid for: the step that made it (its time), the two
/// motions and every parameter its certificates depend on. A step carries
/// the front only when its own are the same and its time is not earlier
/// (Lemma 9.9); else it descends from the roots.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct Carry<T> {
    pub(super) t: T,
    pub(super) motions: (RigidMotion<T>, RigidMotion<T>),
    /// The contact distance and clearance, the bound kind and sidedness.
    pub(super) params: (T, T, crate::BoundKind, bool),
    /// The node pairs the last descent from the roots evaluated: a front
    /// grown past a multiple of it is dropped (`MAX_GROWTH`).
    pub(super) root_pairs: u64,
    /// The step the step that made the front certified (what a stepper
    /// without seeds takes as this step's likely length).
    pub(super) last_step: T,
}

/// A front of more entries than this many times the node pairs of the last
/// descent from the roots (plus `MIN_FRONT`) is dropped for a new descent:
/// entries left fine after the bodies moved apart cost a queue entry each,
/// where the roots would prune them together (a choice of speed only).
pub(super) const MAX_GROWTH: u64 = 32;
pub(super) const MIN_FRONT: u64 = 64;

impl<T: Float> Carry<T> {
    /// What the front made by a step at `t` that certified `step` is valid
    /// for, the step having evaluated `pairs` node pairs starting from the
    /// front `previous` describes (or from the roots, `None`).
    #[inline]
    pub(super) fn after(
        previous: Option<Self>,
        (t, step): (T, T),
        motions: (RigidMotion<T>, RigidMotion<T>),
        params: (T, T, crate::BoundKind, bool),
        pairs: u64,
    ) -> Self {
        Self {
            t,
            motions,
            params,
            root_pairs: previous.map_or(pairs, |c| c.root_pairs),
            last_step: step,
        }
    }

    /// Whether a step at `t` of motions `a`, `b` (over any interval) with
    /// `params` may start from the front this carry describes, of `len`
    /// entries.
    #[inline]
    pub(super) fn takes(
        &self,
        t: T,
        (a, b): (&RigidMotion<T>, &RigidMotion<T>),
        params: (T, T, crate::BoundKind, bool),
        len: usize,
    ) -> bool {
        t >= self.t
            && self.params == params
            && self.motions.0.with_interval(a.interval()) == *a
            && self.motions.1.with_interval(b.interval()) == *b
            && (len as u64) <= MAX_GROWTH * self.root_pairs + MIN_FRONT
    }
}

#[cfg(test)]
mod tests {
    use super::{until, FrontEntry};

    /// The certified times never pass `t + step` (checked in exact
    /// arithmetic through `f64` sums of `f32` values, exact here) nor the
    /// horizon, and a NaN or negative step certifies nothing past `t`.
    #[test]
    fn certified_times_stay_within_the_step_and_the_horizon() {
        let mut g = crate::rng::SplitMix64::new(9);
        for _ in 0..10_000 {
            let t = g.range(0.0, 1.0) as f32;
            let s = (g.range(0.0, 1.0) as f32) * if g.range(0.0, 1.0) < 0.5 { 1e-6 } else { 1.0 };
            let h = t + g.range(0.0, 1.0) as f32;
            let d = until(t, s, h);
            assert!(
                f64::from(d) <= f64::from(t) + f64::from(s) && d <= h && d >= t.min(h),
                "{t} {s} {h} {d}"
            );
        }
        assert_eq!(until(0.5f64, f64::NAN, 1.0), 0.5);
        assert_eq!(until(0.5f64, -1.0, 1.0), 0.5);
        assert_eq!(until(0.5f64, f64::INFINITY, 1.0), 1.0);
        assert_eq!(until(0.5f64, f64::MAX, 1.0), 1.0);
        // The near time comes before the deadline, and a gap within the
        // contact distance is near at once.
        let e = FrontEntry::new((1, 2), 0.25f64, 1.0, (0.5, 1.0, 1.0, 0.2));
        assert!(e.near_from <= e.deadline && e.deadline <= 0.75 && e.near_from > 0.25);
        let e = FrontEntry::new((1, 2), 0.25f64, 1.0, (0.5, 0.1, 1.0, 0.2));
        assert_eq!(e.near_from, 0.25);
    }
}
