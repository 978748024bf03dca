//! The one dispatch: the stepper of every pair of shape kinds.
//!
//! This is the only `match` over pairs of kinds in the crate; scenes, the
//! parry adapter and the Python binding all step their pairs through
//! [`AnyPair`]. A new stepper is one arm of [`AnyPair::try_new`]
//! (`docs/architecture.md`).

use crate::ca::compound::{CompoundPair, PartPair};
use crate::ca::{
    BallPair, CaError, CaParams, CaStep, ConvexPair, GjkProximity, HalfSpacePair, MeshConvexPair,
    MeshPair, MeshParams, MeshWorkspace, Shape, StepResult, VertexSetPair, Witness, Work,
};
use crate::{BoundingBall, Convex, Float, Isometry, PreparedMotion, RigidMotion, Vec3};

/// The stepper of a pair of [`Shape`]s of any kinds, a [`CaStep`]: each
/// pair of kinds has one stepper, taken in either order, and this is where
/// the choice is made.
///
/// | pair of kinds | stepper |
/// |---|---|
/// | mesh, mesh | [`MeshPair`] (with [`MeshParams`] from [`try_with_mesh_params`](Self::try_with_mesh_params)); against a solid closed convex mesh, [`MeshConvexPair`] with its hull |
/// | mesh, convex / vertex set / ball / half-space | [`MeshConvexPair`] |
/// | vertex set, vertex set | [`VertexSetPair`] with GJK ([`bound_counts`](Self::bound_counts)) |
/// | ball, ball | [`BallPair`] |
/// | convex / vertex set / ball, the same or another of the three | [`ConvexPair`] |
/// | convex / vertex set / ball, half-space | [`HalfSpacePair`] |
/// | compound, any | the pairs of its parts, each by this table |
/// | half-space, half-space | none: [`CaError::Unsupported`] |
///
/// A vertex set met by another kind is taken as the polytope of its points
/// ([`Convex::polytope`]), a ball as the convex ball it is.
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
    /// Balls holding A and B in their body frames (none for a half-space).
    balls: Option<(BoundingBall<T>, BoundingBall<T>)>,
    /// A workspace given to a pair that does not descend a mesh.
    spare: Option<MeshWorkspace<T>>,
}

#[derive(Debug)]
enum Kinds<'a, T> {
    Meshes(MeshPair<'a, T>),
    MeshConvex(MeshConvexPair<'a, T>),
    VertexSets(VertexSetPair<'a, T, GjkProximity<'a, T>>),
    Balls(BallPair<T>),
    Convexes(ConvexPair<'a, T>),
    HalfSpace(HalfSpacePair<'a, T>),
    Compound(CompoundPair<'a, T, AnyPair<'a, T>>),
}

/// A vertex set or a ball, met by another kind, as the convex shape it is;
/// other shapes as they are.
fn as_convex<T: Float>(shape: Shape<'_, T>) -> Result<Shape<'_, T>, CaError> {
    Ok(match shape {
        Shape::VertexSet(set) => Shape::Convex(Convex::polytope(set)),
        Shape::Ball(ball) => {
            let convex = Convex::try_ball(ball.radius()).map_err(CaError::Input)?;
            let centre = Vec3::from_array(*ball.centre());
            if centre == Vec3::ZERO {
                Shape::Convex(convex)
            } else {
                let at = Isometry::try_from_translation(centre).map_err(CaError::Input)?;
                Shape::Convex(convex.try_placed(at).map_err(CaError::Input)?)
            }
        }
        other => other,
    })
}

impl<'a, T: Float> AnyPair<'a, T> {
    /// The stepper for bodies of shapes `a` and `b`.
    ///
    /// # Errors
    /// [`CaError::Unsupported`] for two half-spaces; [`CaError::Input`] for a
    /// ball too large to be a convex shape.
    pub fn try_new(a: Shape<'a, T>, b: Shape<'a, T>) -> Result<Self, CaError> {
        use Shape::{Convex as C, HalfSpace as H, Mesh as M};
        let ball = |s: &Shape<'a, T>| match s {
            H(_) => None,
            s => s.bounding_ball().ok(),
        };
        let balls = ball(&a).zip(ball(&b));
        let (pair, swapped) = match (a, b) {
            (Shape::Compound(_), _) | (_, Shape::Compound(_)) => {
                (Kinds::Compound(CompoundPair::new(a, b)), false)
            }
            // A solid closed convex mesh is its hull (Lemma 12.9): the
            // other mesh against that polytope.
            (M(ta), M(tb)) => match (ta.solid_hull(), tb.solid_hull()) {
                (_, Some(hb)) => (Kinds::MeshConvex(MeshConvexPair::new(ta, hb)), false),
                (Some(ha), None) => (Kinds::MeshConvex(MeshConvexPair::new(tb, ha)), true),
                (None, None) => (Kinds::Meshes(MeshPair::new(ta, tb)), false),
            },
            (Shape::VertexSet(va), Shape::VertexSet(vb)) => {
                (Kinds::VertexSets(VertexSetPair::with_gjk(va, vb)), false)
            }
            (Shape::Ball(ba), Shape::Ball(bb)) => (Kinds::Balls(BallPair::new(ba, bb)), false),
            (a, b) => match (as_convex(a)?, as_convex(b)?) {
                (M(t), C(s)) => (Kinds::MeshConvex(MeshConvexPair::new(t, s)), false),
                (C(s), M(t)) => (Kinds::MeshConvex(MeshConvexPair::new(t, s)), true),
                (M(t), H(h)) => (
                    Kinds::MeshConvex(MeshConvexPair::with_half_space(t, h)),
                    false,
                ),
                (H(h), M(t)) => (
                    Kinds::MeshConvex(MeshConvexPair::with_half_space(t, h)),
                    true,
                ),
                (C(sa), C(sb)) => (Kinds::Convexes(ConvexPair::new(sa, sb)), false),
                (C(s), H(h)) => (Kinds::HalfSpace(HalfSpacePair::new(s, h)), false),
                (H(h), C(s)) => (Kinds::HalfSpace(HalfSpacePair::new(s, h)), true),
                _ => return Err(CaError::Unsupported),
            },
        };
        Ok(Self {
            pair,
            swapped,
            balls,
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
            Kinds::MeshConvex(p) => Kinds::MeshConvex(p.with_workspace(workspace)),
            Kinds::Compound(p) => Kinds::Compound(p.with_workspace(workspace)),
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
            Kinds::MeshConvex(p) => p.into_workspace(),
            Kinds::Compound(p) => p.into_workspace(),
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

    /// For a pair of vertex sets, how many steps under
    /// [`BoundChoice::Auto`](crate::ca::BoundChoice::Auto) took NEVQ alone
    /// and how many evaluated EVQ as well
    /// ([`VertexSetPair::bound_counts`]); `(0, 0)` for other pairs.
    #[must_use]
    pub const fn bound_counts(&self) -> (u64, u64) {
        match &self.pair {
            Kinds::VertexSets(p) => p.bound_counts(),
            _ => (0, 0),
        }
    }

    fn inner(&mut self) -> &mut dyn CaStep<T> {
        match &mut self.pair {
            Kinds::Meshes(p) => p,
            Kinds::MeshConvex(p) => p,
            Kinds::VertexSets(p) => p,
            Kinds::Balls(p) => p,
            Kinds::Convexes(p) => p,
            Kinds::HalfSpace(p) => p,
            Kinds::Compound(p) => p,
        }
    }

    fn inner_ref(&self) -> &dyn CaStep<T> {
        match &self.pair {
            Kinds::Meshes(p) => p,
            Kinds::MeshConvex(p) => p,
            Kinds::VertexSets(p) => p,
            Kinds::Balls(p) => p,
            Kinds::Convexes(p) => p,
            Kinds::HalfSpace(p) => p,
            Kinds::Compound(p) => p,
        }
    }
}

impl<'a, T: Float> PartPair<'a, T> for AnyPair<'a, T> {
    fn try_new(a: Shape<'a, T>, b: Shape<'a, T>) -> Result<Self, CaError> {
        Self::try_new(a, b)
    }

    fn with_workspace(self, ws: MeshWorkspace<T>) -> Self {
        self.with_workspace(ws)
    }

    fn into_workspace(self) -> MeshWorkspace<T> {
        self.into_workspace()
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

    fn bounding_balls(&self) -> Option<(BoundingBall<T>, BoundingBall<T>)> {
        self.balls
    }

    fn initial_overlap(
        &mut self,
        t: T,
        a: &PreparedMotion<T>,
        b: &PreparedMotion<T>,
        params: &CaParams<T>,
    ) -> Option<StepResult<T>> {
        if self.swapped {
            self.inner().initial_overlap(t, b, a, params).map(turned)
        } else {
            self.inner().initial_overlap(t, a, b, params)
        }
    }

    fn check_motions(&self, a: &RigidMotion<T>, b: &RigidMotion<T>) -> Result<(), CaError> {
        if self.swapped {
            self.inner_ref().check_motions(b, a)
        } else {
            self.inner_ref().check_motions(a, b)
        }
    }
}
