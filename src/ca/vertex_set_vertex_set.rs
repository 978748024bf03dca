//! Conservative advancement of two convex bodies through any proximity oracle.

use crate::ca::step::{gap_step, placement_error, precision_limit};
use crate::ca::{BoundChoice, CaParams, CaStep, StepResult, Witness};
use crate::rounding::diff_up;
use crate::{BoundKind, Direction, Float, Point3, Pose, PreparedMotion, Vec3, VertexSet};

/// A distance oracle for a pair of bodies: what another engine plugs in.
///
/// Given both bodies' placements (body points map to the world by
/// `pose.transform_point`), return the closest features, or `None` when the
/// bodies intersect. The distance may be approximate: the stepper never
/// trusts it for soundness, only for declaring contact and choosing the
/// direction `n`, along which it measures the certified gap itself
/// (`proofs/09-ca-toi.md`, Lemma 9.1).
pub trait Proximity<T> {
    /// The closest features of the bodies placed at `pose_a`, `pose_b`.
    fn closest(&mut self, pose_a: &Pose<T>, pose_b: &Pose<T>) -> Option<Witness<T>>;
}

impl<T, F: FnMut(&Pose<T>, &Pose<T>) -> Option<Witness<T>>> Proximity<T> for F {
    fn closest(&mut self, pose_a: &Pose<T>, pose_b: &Pose<T>) -> Option<Witness<T>> {
        self(pose_a, pose_b)
    }
}

/// Conservative advancement of two convex bodies given by their vertices (a
/// [`CaStep`]), with distances from a [`Proximity`] oracle.
///
/// Each step places both vertex sets, measures the gap along the oracle's
/// closest direction, and bounds each body's directed speed with the bound
/// chosen by [`CaParams::bound`]: with [`BoundChoice::Auto`], NEVQ first and
/// EVQ (`O(N)`) only when NEVQ's step would not end the query; one-sided
/// (closing-rate) bounds unless [`CaParams::one_sided`] is off.
///
/// ```
/// use motion_bound::ca::{time_of_impact, CaParams, VertexSetPair, Witness};
/// use motion_bound::{Point3, Pose, RigidMotion, Vec3, VertexSet};
/// // Two unit cubes' corners; a crude oracle: the closest pair of corners
/// // (exact for these face-to-face cubes).
/// let mut cube = [[0.0f64; 3]; 8];
/// for (i, c) in cube.iter_mut().enumerate() {
///     *c = [0, 1, 2].map(|k| if i >> k & 1 == 1 { 0.5 } else { -0.5 });
/// }
/// let body = VertexSet::try_new(&cube)?;
/// let oracle = |pa: &Pose<f64>, pb: &Pose<f64>| {
///     let mut best: Option<Witness<f64>> = None;
///     for p in &cube {
///         for q in &cube {
///             let (a, b) = (pa.transform_point(*p), pb.transform_point(*q));
///             let d = (b - a).length();
///             if best.map_or(true, |w| d < w.distance) {
///                 best = Some(Witness::new(d, Point3::from_vec3(a), Point3::from_vec3(b)));
///             }
///         }
///     }
///     best
/// };
/// let a = RigidMotion::try_from_arrays([0.0; 3], [4.0, 0.0, 0.0], [0.0; 3])?;
/// let b = RigidMotion::try_from_arrays([3.0, 0.0, 0.0], [0.0; 3], [0.0; 3])?;
/// let mut pair = VertexSetPair::new(body, body, oracle);
/// let report = time_of_impact(&mut pair, &a, &b, &CaParams::default())?;
/// // The faces meet at t = 2/4.
/// let t = report.outcome.contact().unwrap().time;
/// assert!(t <= 0.5 && t > 0.5 - 1e-4, "t = {t}");
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug)]
pub struct VertexSetPair<'a, T, P> {
    a: VertexSet<'a, T>,
    b: VertexSet<'a, T>,
    oracle: P,
    evq_skipped: u64,
    evq_evaluated: u64,
    /// Each body's vertex tree, if given: its EVQ bounds by branch and bound.
    #[cfg(feature = "alloc")]
    trees: [Option<&'a crate::VertexTree<T>>; 2],
}

impl<'a, T: Float, P: Proximity<T>> VertexSetPair<'a, T, P> {
    /// The pair of convex bodies `a`, `b` (vertices relative to each body's
    /// rotation centre) with the distance oracle `oracle`.
    #[must_use]
    pub const fn new(a: VertexSet<'a, T>, b: VertexSet<'a, T>, oracle: P) -> Self {
        Self {
            a,
            b,
            oracle,
            evq_skipped: 0,
            evq_evaluated: 0,
            #[cfg(feature = "alloc")]
            trees: [None, None],
        }
    }

    /// With the bodies' vertex trees (built once per body from the same
    /// vertex sets): the EVQ bounds of each step then cost a branch and bound
    /// instead of a scan of every vertex, with the same soundness
    /// (`proofs/08-ball-bound.md`, Lemma 8.2). Worth it for bodies of more
    /// than a few hundred vertices (`docs/performance.md`); the steps'
    /// extents still place every vertex. A tree must be built from its
    /// body's own vertex set; one whose vertex count or summary differs from
    /// the body's is not used (the scan is).
    #[cfg(feature = "alloc")]
    #[must_use]
    pub fn with_vertex_trees(
        mut self,
        a: Option<&'a crate::VertexTree<T>>,
        b: Option<&'a crate::VertexTree<T>>,
    ) -> Self {
        let fits = |t: &&crate::VertexTree<T>, body: &VertexSet<'_, T>| {
            t.len() == body.len() && t.summary() == body.summary()
        };
        self.trees = [
            a.filter(|t| fits(t, &self.a)),
            b.filter(|t| fits(t, &self.b)),
        ];
        self
    }

    /// How many steps under [`BoundChoice::Auto`] took NEVQ alone (its step
    /// already ends the query, or neither body turns, so EVQ equals NEVQ)
    /// and how many evaluated EVQ as well.
    #[must_use]
    pub const fn bound_counts(&self) -> (u64, u64) {
        (self.evq_skipped, self.evq_evaluated)
    }

    /// The oracle.
    pub fn oracle_mut(&mut self) -> &mut P {
        &mut self.oracle
    }
}

#[cfg(feature = "alloc")]
type TreeRef<'a, T> = Option<&'a crate::VertexTree<T>>;
#[cfg(not(feature = "alloc"))]
type TreeRef<'a, T> = Option<&'a core::marker::PhantomData<T>>;

impl<'a, T: Float, P> VertexSetPair<'a, T, P> {
    #[cfg(feature = "alloc")]
    fn trees(&self) -> [TreeRef<'a, T>; 2] {
        self.trees
    }

    #[cfg(not(feature = "alloc"))]
    fn trees(&self) -> [TreeRef<'a, T>; 2] {
        [None, None]
    }
}

/// A body's one-sided rate: by its tree when it has one, else by scan.
#[inline]
fn body_rate<T: Float>(
    probe: &crate::DirectedProbe<T>,
    body: &VertexSet<'_, T>,
    tree: TreeRef<'_, T>,
    kind: BoundKind,
) -> T {
    match tree {
        #[cfg(feature = "alloc")]
        Some(tree) if kind == BoundKind::Evq => tree.rate(probe, kind),
        _ => probe.rate(body, kind),
    }
}

/// A body's speed bound: by its tree when it has one, else by scan.
#[inline]
fn body_speed<T: Float>(
    probe: &crate::DirectedProbe<T>,
    body: &VertexSet<'_, T>,
    tree: TreeRef<'_, T>,
    kind: BoundKind,
) -> T {
    match tree {
        #[cfg(feature = "alloc")]
        Some(tree) if kind == BoundKind::Evq => tree.evq_speed(probe),
        _ => probe.speed(body, kind),
    }
}

/// `max_i fl(fl(pose r_i) . n)` or its minimum, over a vertex set.
fn extent<T: Float>(pose: &Pose<T>, body: &VertexSet<'_, T>, n: Vec3<T>, max: bool) -> T {
    let mut e = if max { -T::INFINITY } else { T::INFINITY };
    for r in body.vertices() {
        let x = pose.transform_point(*r).dot(n);
        e = if max { e.max_nan(x) } else { e.min_nan(x) };
    }
    e
}

impl<T: Float, P: Proximity<T>> CaStep<T> for VertexSetPair<'_, T, P> {
    fn step(
        &mut self,
        t: T,
        a: &PreparedMotion<T>,
        b: &PreparedMotion<T>,
        params: &CaParams<T>,
    ) -> StepResult<T> {
        let (pose_a, pose_b) = (a.motion().pose_at(t), b.motion().pose_at(t));
        let Some(w) = self.oracle.closest(&pose_a, &pose_b) else {
            let (ca, cb) = (pose_a.translation, pose_b.translation);
            return StepResult::Touching {
                witness: Witness {
                    distance: T::ZERO,
                    on_a: Point3::from_vec3(ca),
                    on_b: Point3::from_vec3(cb),
                },
                normal: None,
            };
        };
        let dir = Direction::try_new(w.on_b - w.on_a);
        let (Ok(n), false) = (dir, w.distance <= params.contact_distance) else {
            return StepResult::Touching {
                witness: w,
                normal: dir.ok(),
            };
        };
        let nv = n.get();
        let gap = extent(&pose_b, &self.b, nv, false) - extent(&pose_a, &self.a, nv, true);
        let (ea, ra) = placement_error(a.motion(), t, self.a.summary().max_radius());
        let (eb, rb) = placement_error(b.motion(), t, self.b.summary().max_radius());
        // One-sided (Lemma 10.2): A along n, B along -n; or the seed's
        // absolute speeds (Lemma 9.1).
        let (pa, pb) = (a.probe(n), b.probe(if params.one_sided { -n } else { n }));
        let trees = self.trees();
        let step_with = |kind| {
            let mu = if params.one_sided {
                (
                    body_rate(&pa, &self.a, trees[0], kind),
                    body_rate(&pb, &self.b, trees[1], kind),
                )
            } else {
                (
                    body_speed(&pa, &self.a, trees[0], kind),
                    body_speed(&pb, &self.b, trees[1], kind),
                )
            };
            gap_step(gap, params.clearance(), (ea, eb), (ra, rb), mu).0
        };
        let step = match params.bound {
            BoundChoice::Nevq => step_with(BoundKind::Nevq),
            BoundChoice::Evq => step_with(BoundKind::Evq),
            BoundChoice::Auto => {
                let cheap = step_with(BoundKind::Nevq);
                // NEVQ's step already reaches the end of the bounds' interval,
                // or neither body turns (EVQ's rotational term is then zero:
                // proofs/11-scene.md, Lemma 11.3).
                let turning = a.arc().rotating || b.arc().rotating;
                if !turning || cheap >= diff_up(a.motion().interval().end(), t) {
                    self.evq_skipped += 1;
                    cheap
                } else {
                    self.evq_evaluated += 1;
                    cheap.max_nan(step_with(BoundKind::Evq))
                }
            }
        };
        if let Some(limit) = precision_limit(step, params.clearance(), (ea, eb), (ra, rb)) {
            return limit;
        }
        StepResult::Advance {
            step,
            witness: Some(w),
            normal: Some(n),
        }
    }
}

/// The [`Proximity`] oracle of this crate for convex polytopes: GJK
/// ([`gjk_distance`](crate::gjk_distance)) on the two vertex sets placed at
/// each step.
#[derive(Clone, Copy, Debug)]
pub struct GjkProximity<'a, T> {
    a: &'a [[T; 3]],
    b: &'a [[T; 3]],
    params: crate::GjkParams<T>,
}

impl<'a, T: Float> GjkProximity<'a, T> {
    /// GJK between the convex hulls of `a` and `b` (body points), with
    /// default [`GjkParams`](crate::GjkParams).
    #[must_use]
    pub fn new(a: &'a [[T; 3]], b: &'a [[T; 3]]) -> Self {
        Self {
            a,
            b,
            params: crate::GjkParams::default(),
        }
    }
}

impl<T: Float> Proximity<T> for GjkProximity<'_, T> {
    fn closest(&mut self, pose_a: &Pose<T>, pose_b: &Pose<T>) -> Option<Witness<T>> {
        let pa = crate::ConvexPolytope::try_new(self.a, *pose_a).ok()?;
        let pb = crate::ConvexPolytope::try_new(self.b, *pose_b).ok()?;
        let r = crate::gjk_distance(&pa, &pb, &self.params);
        if r.intersecting {
            return None;
        }
        Some(Witness {
            distance: r.distance,
            on_a: r.on_a,
            on_b: r.on_b,
        })
    }
}

impl<'a, T: Float> VertexSetPair<'a, T, GjkProximity<'a, T>> {
    /// The pair of convex bodies `a`, `b` with GJK distances: conservative
    /// advancement of convex polytopes out of the box.
    ///
    /// ```
    /// use motion_bound::ca::{time_of_impact, CaParams, VertexSetPair};
    /// use motion_bound::{RigidMotion, VertexSet};
    /// let tet = [[1.0, 1.0, 1.0], [1.0, -1.0, -1.0], [-1.0, 1.0, -1.0], [-1.0, -1.0, 1.0]];
    /// let body = VertexSet::try_new(&tet)?;
    /// let a = RigidMotion::try_from_arrays([-4.0, 0.0, 0.0], [8.0, 0.0, 0.0], [0.0, 3.0, 1.0])?;
    /// let b = RigidMotion::try_from_arrays([4.0, 0.0, 0.0], [-2.0, 0.0, 0.0], [2.0, 0.0, 0.0])?;
    /// let report = time_of_impact(&mut VertexSetPair::with_gjk(body, body), &a, &b, &CaParams::default())?;
    /// let t = report.outcome.contact().expect("they collide").time;
    /// assert!(t > 0.0 && t < 0.8);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    #[must_use]
    pub fn with_gjk(a: VertexSet<'a, T>, b: VertexSet<'a, T>) -> Self {
        Self::new(a, b, GjkProximity::new(a.vertices(), b.vertices()))
    }
}
