//! Conservative advancement of a compound against any shape: the pairs of
//! its parts, each by its own stepper.

use core::marker::PhantomData;

use crate::ca::{CaError, CaParams, CaStep, MeshWorkspace, Shape, StepResult, Witness, Work};
use crate::{Direction, Float, PreparedMotion, RigidMotion};

/// The stepper of one pair of parts: what a compound pair needs of the
/// dispatch ([`AnyPair`](crate::ca::AnyPair) is it). A compound pair is
/// generic over it so that this file needs nothing of the dispatch, which
/// in turn takes compounds here (no import cycle).
pub(crate) trait PartPair<'a, T: Float>: CaStep<T> + Sized {
    /// The stepper of parts `a` and `b`.
    fn try_new(a: Shape<'a, T>, b: Shape<'a, T>) -> Result<Self, CaError>;
    /// With the scratch space `ws`.
    fn with_workspace(self, ws: MeshWorkspace<T>) -> Self;
    /// The scratch space.
    fn into_workspace(self) -> MeshWorkspace<T>;
}

/// A step with its witness and normal.
type Advance<T> = (T, Option<Witness<T>>, Option<Direction<T>>);

/// A pair with a compound on either side: the pairs of its parts, each by
/// its family's stepper, made afresh at every step (allocation-free: they
/// share one mesh workspace), the least step over them (Lemma 9.2: the
/// part pairs cover every point pair), the closest contact among them.
#[derive(Debug)]
pub(crate) struct CompoundPair<'a, T, P> {
    a: Shape<'a, T>,
    b: Shape<'a, T>,
    ws: MeshWorkspace<T>,
    work: Work,
    /// The stepper of its part pairs, made at each step.
    parts: PhantomData<fn() -> P>,
}

impl<'a, T: Float, P> CompoundPair<'a, T, P> {
    /// The pair of `a` and `b`, either or both compounds.
    pub(crate) fn new(a: Shape<'a, T>, b: Shape<'a, T>) -> Self {
        Self {
            a,
            b,
            ws: MeshWorkspace::new(),
            work: Work::ZERO,
            parts: PhantomData,
        }
    }

    /// With the scratch space `ws` for its parts' mesh pairs.
    pub(crate) fn with_workspace(self, ws: MeshWorkspace<T>) -> Self {
        Self { ws, ..self }
    }

    /// The scratch space.
    pub(crate) fn into_workspace(self) -> MeshWorkspace<T> {
        self.ws
    }
}

impl<'a, T: Float, P: PartPair<'a, T>> CaStep<T> for CompoundPair<'a, T, P> {
    fn step(
        &mut self,
        t: T,
        a: &PreparedMotion<T>,
        b: &PreparedMotion<T>,
        params: &CaParams<T>,
    ) -> StepResult<T> {
        let mut used = Work::ZERO;
        let mut advance: Option<Advance<T>> = None;
        let mut touching: Option<(Witness<T>, Option<Direction<T>>)> = None;
        let mut limit: Option<T> = None;
        for i in 0..self.a.part_count() {
            for j in 0..self.b.part_count() {
                let Ok(pair) = P::try_new(self.a.part(i), self.b.part(j)) else {
                    continue;
                };
                let mut pair = pair.with_workspace(core::mem::take(&mut self.ws));
                let budget = params.work_budget.saturating_sub(used);
                let r = pair.step(t, a, b, &params.with_work_budget(budget));
                let w = pair.work();
                used = Work::new(
                    used.node_pairs + w.node_pairs,
                    used.triangle_pairs + w.triangle_pairs,
                );
                self.work = Work::new(
                    self.work.node_pairs + w.node_pairs,
                    self.work.triangle_pairs + w.triangle_pairs,
                );
                self.ws = pair.into_workspace();
                match r {
                    StepResult::Touching { witness, normal } => {
                        if touching.is_none_or(|(w0, _)| witness.distance < w0.distance) {
                            touching = Some((witness, normal));
                        }
                    }
                    StepResult::WorkLimit if touching.is_none() => return StepResult::WorkLimit,
                    StepResult::WorkLimit => {}
                    StepResult::PrecisionLimit { resolution } => {
                        limit = Some(limit.map_or(resolution, |r| r.max_nan(resolution)));
                    }
                    StepResult::Advance {
                        step,
                        witness,
                        normal,
                    } => {
                        if advance.is_none_or(|(s, _, _)| step < s) {
                            advance = Some((step, witness, normal));
                        }
                    }
                }
            }
        }
        if let Some((witness, normal)) = touching {
            return StepResult::Touching { witness, normal };
        }
        if let Some(resolution) = limit {
            return StepResult::PrecisionLimit { resolution };
        }
        let (step, witness, normal) = advance.unwrap_or((T::ZERO, None, None));
        StepResult::Advance {
            step,
            witness,
            normal,
        }
    }

    fn work(&self) -> Work {
        self.work
    }

    /// A point of a part inside another body's solid mesh part (Lemma 9.7):
    /// each pair of parts' own check, the first contact found.
    fn initial_overlap(
        &mut self,
        t: T,
        a: &PreparedMotion<T>,
        b: &PreparedMotion<T>,
        params: &CaParams<T>,
    ) -> Option<StepResult<T>> {
        let mut used = Work::ZERO;
        for i in 0..self.a.part_count() {
            for j in 0..self.b.part_count() {
                let Ok(pair) = P::try_new(self.a.part(i), self.b.part(j)) else {
                    continue;
                };
                let mut pair = pair.with_workspace(core::mem::take(&mut self.ws));
                let budget = params.work_budget.saturating_sub(used);
                let r = pair.initial_overlap(t, a, b, &params.with_work_budget(budget));
                let w = pair.work();
                used = used.saturating_add(w);
                self.work = self.work.saturating_add(w);
                self.ws = pair.into_workspace();
                if r.is_some() {
                    return r;
                }
            }
        }
        None
    }

    fn check_motions(&self, a: &RigidMotion<T>, b: &RigidMotion<T>) -> Result<(), CaError> {
        for i in 0..self.a.part_count() {
            for j in 0..self.b.part_count() {
                P::try_new(self.a.part(i), self.b.part(j))?.check_motions(a, b)?;
            }
        }
        Ok(())
    }
}
