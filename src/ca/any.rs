//! Any two shapes: the one place where a pair of kinds picks its stepper.

use crate::bvh::BallTree;
use crate::ca::compound::{Compound, Part};
use crate::ca::{
    CaError, CaParams, CaStep, HalfSpacePair, MeshPair, MeshParams, MeshShapePair, MeshWorkspace,
    ShapePair, StepResult, Witness, Work,
};
use crate::{Convex, Direction, Float, HalfSpace, PreparedMotion, RigidMotion};

/// A body's shape, whatever its kind.
#[derive(Clone, Copy, Debug)]
#[non_exhaustive]
pub enum Shape<'a, T> {
    /// A convex shape: a core and a radius ([`Convex`]).
    Convex(Convex<'a, T>),
    /// A triangle mesh through its hierarchy.
    Mesh(&'a BallTree<T>),
    /// A half-space (translating only).
    HalfSpace(HalfSpace<T>),
    /// Several parts moving as one body.
    Compound(&'a Compound<'a, T>),
}

impl<'a, T: Float> Shape<'a, T> {
    /// The `k`-th of this shape's parts (a compound's, or the shape itself
    /// as its only part), and how many there are.
    fn part(&self, k: usize) -> Shape<'a, T> {
        match *self {
            Shape::Compound(c) => match c.parts()[k] {
                Part::Convex(s) => Shape::Convex(s),
                Part::Mesh(t) => Shape::Mesh(t),
            },
            other => other,
        }
    }

    fn part_count(&self) -> usize {
        match self {
            Shape::Compound(c) => c.parts().len(),
            _ => 1,
        }
    }
}

/// The stepper of a pair of [`Shape`]s of any kinds, a [`CaStep`]: each
/// family of pairs has one stepper (mesh-mesh [`MeshPair`], mesh against
/// a convex shape or a half-space [`MeshShapePair`], convex-convex
/// [`ShapePair`], convex against a half-space [`HalfSpacePair`]), taken
/// in either order; this is where the choice is made.
///
/// ```
/// use motion_bound::ca::{time_of_impact, AnyPair, CaParams, Shape};
/// use motion_bound::{Convex, HalfSpace, RigidMotion, Vec3};
/// // The ground first, a ball second: the pair is taken the other way
/// // round and its answer turned back.
/// let ground = Shape::HalfSpace(HalfSpace::try_new(Vec3::new(0.0, 1.0, 0.0))?);
/// let ball = Shape::Convex(Convex::try_ball(0.5)?);
/// let still = RigidMotion::try_from_arrays([0.0; 3], [0.0; 3], [0.0; 3])?;
/// let falling = RigidMotion::try_from_arrays([0.0, 2.5, 0.0], [0.0, -4.0, 0.0], [0.0; 3])?;
/// let mut pair = AnyPair::try_new(ground, ball)?;
/// let report = time_of_impact(&mut pair, &still, &falling, &CaParams::default())?;
/// let contact = report.outcome.contact().expect("it lands");
/// assert!(contact.time <= 0.5 && contact.time > 0.5 - 1e-4);
/// // The normal points from the first body (the ground) to the second.
/// assert!(contact.normal.expect("a normal").get().y > 0.99);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug)]
pub struct AnyPair<'a, T> {
    pair: Kinds<'a, T>,
    /// The stepper takes B before A.
    swapped: bool,
    /// A workspace given to a pair that does not descend a mesh.
    spare: Option<MeshWorkspace<T>>,
}

#[derive(Debug)]
enum Kinds<'a, T> {
    Meshes(MeshPair<'a, T>),
    MeshShape(MeshShapePair<'a, T>),
    Shapes(ShapePair<'a, T>),
    HalfSpace(HalfSpacePair<'a, T>),
    Compound(CompoundPair<'a, T>),
}

impl<'a, T: Float> AnyPair<'a, T> {
    /// The stepper for bodies of shapes `a` and `b`.
    ///
    /// # Errors
    /// [`CaError::Unsupported`] for two half-spaces.
    pub fn try_new(a: Shape<'a, T>, b: Shape<'a, T>) -> Result<Self, CaError> {
        use Shape::{Convex as C, HalfSpace as H, Mesh as M};
        let (pair, swapped) = match (a, b) {
            (Shape::Compound(_), _) | (_, Shape::Compound(_)) => (
                Kinds::Compound(CompoundPair {
                    a,
                    b,
                    ws: MeshWorkspace::new(),
                    work: Work::ZERO,
                }),
                false,
            ),
            (M(ta), M(tb)) => (Kinds::Meshes(MeshPair::new(ta, tb)), false),
            (M(t), C(s)) => (Kinds::MeshShape(MeshShapePair::new(t, s)), false),
            (C(s), M(t)) => (Kinds::MeshShape(MeshShapePair::new(t, s)), true),
            (M(t), H(h)) => (
                Kinds::MeshShape(MeshShapePair::with_half_space(t, h)),
                false,
            ),
            (H(h), M(t)) => (Kinds::MeshShape(MeshShapePair::with_half_space(t, h)), true),
            (C(sa), C(sb)) => (Kinds::Shapes(ShapePair::new(sa, sb)), false),
            (C(s), H(h)) => (Kinds::HalfSpace(HalfSpacePair::new(s, h)), false),
            (H(h), C(s)) => (Kinds::HalfSpace(HalfSpacePair::new(s, h)), true),
            (H(_), H(_)) => return Err(CaError::Unsupported),
        };
        Ok(Self {
            pair,
            swapped,
            spare: None,
        })
    }

    /// With the scratch space `workspace` for a pair that descends a mesh
    /// (taken back by [`into_workspace`](Self::into_workspace)); other pairs
    /// keep it untouched.
    #[must_use]
    pub fn with_workspace(mut self, workspace: MeshWorkspace<T>) -> Self {
        self.pair = match self.pair {
            Kinds::Meshes(p) => Kinds::Meshes(p.with_workspace_from(workspace)),
            Kinds::MeshShape(p) => Kinds::MeshShape(p.with_workspace(workspace)),
            Kinds::Compound(p) => Kinds::Compound(CompoundPair { ws: workspace, ..p }),
            other => {
                self.spare = Some(workspace);
                other
            }
        };
        self
    }

    /// The scratch space (the one given, or a new empty one).
    #[must_use]
    pub fn into_workspace(self) -> MeshWorkspace<T> {
        match self.pair {
            Kinds::Meshes(p) => p.into_workspace(),
            Kinds::MeshShape(p) => p.into_workspace(),
            Kinds::Compound(p) => p.ws,
            _ => self.spare.unwrap_or_default(),
        }
    }

    /// With the mesh traversal's knobs (for a mesh-mesh pair; others have
    /// none).
    ///
    /// # Errors
    /// As [`MeshPair::try_with_params`].
    pub fn try_with_mesh_params(mut self, params: MeshParams<T>) -> Result<Self, CaError> {
        if let Kinds::Meshes(p) = self.pair {
            self.pair = Kinds::Meshes(p.try_with_params(params)?);
        } else {
            params.validate()?;
        }
        Ok(self)
    }

    fn inner(&mut self) -> &mut dyn CaStep<T> {
        match &mut self.pair {
            Kinds::Meshes(p) => p,
            Kinds::MeshShape(p) => p,
            Kinds::Shapes(p) => p,
            Kinds::HalfSpace(p) => p,
            Kinds::Compound(p) => p,
        }
    }

    fn inner_ref(&self) -> &dyn CaStep<T> {
        match &self.pair {
            Kinds::Meshes(p) => p,
            Kinds::MeshShape(p) => p,
            Kinds::Shapes(p) => p,
            Kinds::HalfSpace(p) => p,
            Kinds::Compound(p) => p,
        }
    }
}

/// A result for `(B, A)` turned into one for `(A, B)`: the witnesses
/// exchanged, the normal reversed.
fn turned<T: Float>(r: StepResult<T>) -> StepResult<T> {
    let flip = |w: Witness<T>| Witness::new(w.distance, w.on_b, w.on_a);
    match r {
        StepResult::Touching { witness, normal } => StepResult::Touching {
            witness: flip(witness),
            normal: normal.map(|n| -n),
        },
        StepResult::Advance {
            step,
            witness,
            normal,
        } => StepResult::Advance {
            step,
            witness: witness.map(flip),
            normal: normal.map(|n| -n),
        },
        other => other,
    }
}

impl<T: Float> CaStep<T> for AnyPair<'_, T> {
    fn step(
        &mut self,
        t: T,
        a: &PreparedMotion<T>,
        b: &PreparedMotion<T>,
        params: &CaParams<T>,
    ) -> StepResult<T> {
        if self.swapped {
            turned(self.inner().step(t, b, a, params))
        } else {
            self.inner().step(t, a, b, params)
        }
    }

    fn work(&self) -> Work {
        self.inner_ref().work()
    }

    fn check_motions(&self, a: &RigidMotion<T>, b: &RigidMotion<T>) -> Result<(), CaError> {
        if self.swapped {
            self.inner_ref().check_motions(b, a)
        } else {
            self.inner_ref().check_motions(a, b)
        }
    }
}

/// A step with its witness and normal.
type Advance<T> = (T, Option<Witness<T>>, Option<Direction<T>>);

/// A pair with a compound on either side: the pairs of its parts, each by
/// its family's stepper, made afresh at every step (allocation-free: they
/// share one mesh workspace), the least step over them (Lemma 9.2: the
/// part pairs cover every point pair), the closest contact among them.
#[derive(Debug)]
struct CompoundPair<'a, T> {
    a: Shape<'a, T>,
    b: Shape<'a, T>,
    ws: MeshWorkspace<T>,
    work: Work,
}

impl<T: Float> CaStep<T> for CompoundPair<'_, T> {
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
                let Ok(pair) = AnyPair::try_new(self.a.part(i), self.b.part(j)) else {
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

    fn check_motions(&self, a: &RigidMotion<T>, b: &RigidMotion<T>) -> Result<(), CaError> {
        for i in 0..self.a.part_count() {
            for j in 0..self.b.part_count() {
                AnyPair::try_new(self.a.part(i), self.b.part(j))?.check_motions(a, b)?;
            }
        }
        Ok(())
    }
}
