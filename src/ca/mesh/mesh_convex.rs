//! Conservative advancement of a triangle mesh against a convex shape or a
//! half-space: one hierarchy descended against one volume.

use super::found::{Found, Head, NodeStep};
use super::front::{Carry, FrontEntry};
use super::placed::{Placed, PlacedNode};
use super::queue::{MeshWorkspace, Origin, Pending, Queued};
use super::stats::TraversalStats;
use crate::bvh::{BallTree, Hierarchy};
use crate::ca::convex_convex::PlacedCore;
use crate::ca::convex_convex::{certified_gap, enough_within, gjk_tolerance};
use crate::ca::convex_half_space::check_half_space;
use crate::ca::solid::StartCheck;
use crate::ca::step::placement_error;
use crate::ca::{
    CaError, CaParams, CaStep, ConvexPair, MeshParams, Shape, StepResult, Witness, WitnessSearch,
    Work,
};
use crate::geometry::gjk::{gjk_closest, gjk_distance, GjkParams, SupportMap};
use crate::rounding::{diff_up, gap_down, least_resolved_reach, resolution_up, step_down, sum_up};
use crate::shape::convex::Core;
use crate::{
    BoundKind, BoundingBall, Convex, ConvexPolytope, Direction, Float, HalfSpace, Point3, Pose,
    PreparedMotion, RigidMotion, Vec3, VertexSet,
};

/// A node whose gap to B is at least this many times its ball's radius is
/// settled with its own step, not split (`MeshParams::far_ratio`'s default).
const FAR_RATIO: f64 = 6.0;

/// A node's box centre as a support map (a single point), for GJK
/// against B's core (Lemma 12.12).
struct CentrePoint<T>(Vec3<T>);

impl<T: Float> SupportMap<T> for CentrePoint<T> {
    #[inline]
    fn support(&self, _dir: Vec3<T>) -> Point3<T> {
        Point3::from_vec3(self.0)
    }
}

/// What the mesh is taken against.
#[derive(Clone, Copy, Debug)]
enum Other<'a, T> {
    Shape(Convex<'a, T>),
    Plane(HalfSpace<T>),
}

/// Conservative advancement of a triangle mesh (body A, its
/// [`BallTree`]) against a convex shape or a half-space (body B), a
/// [`CaStep`]: a best-first descent of the mesh's hierarchy against the one
/// volume, with the same certified gaps, bounds, work budget, precision limit
/// and closest-pair witness as [`MeshPair`](crate::ca::MeshPair)
/// (`proofs/12-shapes.md`, Lemma 12.4), and the same front carried from
/// step to step (Lemma 9.9, [`with_carry_front`](Self::with_carry_front)):
/// a step of a query takes the last step's cut of nodes when at most half
/// of it is stale against the last step's length.
///
/// A closed convex mesh ([`BallTree::is_closed_convex`]) is first stepped
/// as its hull, a polytope ([`ConvexPair`]): the hull holds the triangles,
/// so a step certified against it is certified against them, and where the
/// shape is certified not to overlap the hull's inside (a plane between
/// them), the hull is exactly as far from it as the triangles are, so the
/// hull's contact is theirs (`proofs/12-shapes.md`, Lemma 12.9). Elsewhere
/// (a shape inside a hollow mesh, a step the hull cannot certify) the step
/// descends the tree as for any mesh.
///
/// ```
/// // `bodies`: the built-in test bodies (feature `bodies`).
/// # #[cfg(feature = "bodies")] {
/// use motion_bound::ca::{time_of_impact, CaParams, MeshConvexPair};
/// use motion_bound::{bodies, BallTree, Convex, HalfSpace, RigidMotion, Vec3};
/// let ring = BallTree::try_from_mesh(&bodies::torus::<f64>(0.5, 0.1, 24, 8)?)?;
/// // A ball falls through the ring's hole: it never touches the ring.
/// let ball = Convex::try_ball(0.2)?;
/// let ring_still = RigidMotion::try_from_arrays([0.0; 3], [0.0; 3], [0.0; 3])?;
/// let falling = RigidMotion::try_from_arrays([0.0, 0.0, 1.0], [0.0, 0.0, -2.0], [0.0; 3])?;
/// let report = time_of_impact(&mut MeshConvexPair::new(&ring, ball), &ring_still, &falling, &CaParams::default())?;
/// assert!(report.outcome.contact().is_none());
/// // The ring dropped on the ground lands when its lowest point (0.1 below
/// // its centre, lying flat) reaches it.
/// let ground = HalfSpace::try_new(Vec3::new(0.0, 0.0, 1.0))?;
/// let dropped = RigidMotion::try_from_arrays([0.0, 0.0, 1.0], [0.0, 0.0, -2.0], [0.0; 3])?;
/// let still = RigidMotion::try_from_arrays([0.0; 3], [0.0; 3], [0.0; 3])?;
/// let report = time_of_impact(&mut MeshConvexPair::with_half_space(&ring, ground), &dropped, &still, &CaParams::default())?;
/// let t = report.outcome.contact().expect("it lands").time;
/// assert!(t <= 0.45 && t > 0.45 - 1e-4, "t = {t}");
/// # }
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug)]
pub struct MeshConvexPair<'a, T> {
    mesh: &'a Hierarchy<T>,
    other: Other<'a, T>,
    ws: MeshWorkspace<T>,
    stats: TraversalStats,
    /// A body starting inside a solid mesh (Lemma 9.7).
    start: StartCheck<'a, T>,
    /// Whether steps carry the front (Lemma 9.9), and what the front in the
    /// workspace is valid for.
    carry_front: bool,
    carry: Option<Carry<T>>,
    /// A closed convex mesh's hull (Lemma 12.9), and whether the mesh is
    /// solid (the hull is then the body itself).
    hull: Option<Convex<'a, T>>,
    solid: bool,
}

impl<'a, T: Float> MeshConvexPair<'a, T> {
    /// The mesh `mesh` (body A) against the convex shape `shape` (body B).
    #[must_use]
    pub fn new(mesh: &'a BallTree<T>, shape: Convex<'a, T>) -> Self {
        Self {
            mesh: &mesh.whole,
            other: Other::Shape(shape),
            ws: MeshWorkspace::new(),
            stats: TraversalStats::default(),
            start: StartCheck::new(Shape::Mesh(mesh), Shape::Convex(shape)),
            carry_front: MeshParams::<T>::default().carry_front,
            carry: None,
            hull: mesh
                .hull
                .as_deref()
                .map(|v| Convex::polytope(VertexSet::from_validated(v))),
            solid: mesh.is_solid(),
        }
    }

    /// The mesh `mesh` (body A) against the half-space `half_space` (body
    /// B), which may translate but not turn
    /// ([`CaError::TurnedHalfSpace`]).
    #[must_use]
    pub fn with_half_space(mesh: &'a BallTree<T>, half_space: HalfSpace<T>) -> Self {
        Self {
            other: Other::Plane(half_space),
            start: StartCheck::new(Shape::Mesh(mesh), Shape::HalfSpace(half_space)),
            hull: None,
            ..Self::new(mesh, Convex::point())
        }
    }

    /// With the scratch space `workspace` (taken back by
    /// [`into_workspace`](Self::into_workspace)).
    #[must_use]
    pub fn with_workspace(mut self, workspace: MeshWorkspace<T>) -> Self {
        self.ws = workspace;
        self.carry = None;
        self
    }

    /// With the front carried from step to step, or not
    /// ([`MeshParams::carry_front`], on by default: the same outcomes; see
    /// its docs for what it saves and costs).
    #[must_use]
    pub fn with_carry_front(mut self, carry: bool) -> Self {
        self.carry_front = carry;
        self.carry = None;
        self
    }

    /// The scratch space, for the next pair.
    #[must_use]
    pub fn into_workspace(self) -> MeshWorkspace<T> {
        self.ws
    }

    /// Whether the mesh is stepped as its hull where the shape is outside
    /// it: a closed convex mesh ([`BallTree::is_closed_convex`]) against a
    /// convex shape (not a half-space).
    #[must_use]
    pub const fn steps_hull(&self) -> bool {
        self.hull.is_some()
    }

    /// The step of the hull (Lemma 12.9): a certified `Advance` (the hull
    /// holds the triangles), or `Touching` where the shape is certified
    /// not to overlap the hull's inside (a plane between them: the
    /// distances are then equal) or the mesh is solid (the hull is the
    /// body); `None` for the tree to decide.
    fn hull_step(
        &self,
        hull: Convex<'a, T>,
        t: T,
        (a, b): (&PreparedMotion<T>, &PreparedMotion<T>),
        params: &CaParams<T>,
    ) -> Option<StepResult<T>> {
        let Other::Shape(shape) = self.other else {
            return None;
        };
        let gap_along = |n: Direction<T>| {
            let (pa, pb) = (a.motion().pose_at(t), b.motion().pose_at(t));
            let (ea, _) = placement_error(a.motion(), t, hull.reach());
            let (eb, _) = placement_error(b.motion(), t, shape.reach());
            certified_gap((&hull, &pa, ea), (&shape, &pb, eb), n.get())
        };
        match ConvexPair::new(hull, shape).step(t, a, b, params) {
            // Where the certified gap along the hull's direction is under
            // half the distance found (in `f32` a curved core's closest
            // direction is off by the closest points' rounding over their
            // distance, which loses the gap along a wide face), the tree
            // decides: its leaves try the triangles' normals too. Either
            // step is certified; this only keeps the longer one's progress.
            r @ StepResult::Advance {
                witness: Some(w),
                normal: Some(n),
                ..
            } => (gap_along(n) * T::TWO >= w.distance).then_some(r),
            r @ StepResult::Advance { .. } => Some(r),
            // The hull's contact is the triangles' where the mesh is solid
            // (the hull is the body) or the shape is certified not to
            // overlap the hull's inside (a plane between them).
            // Overlapping a solid mesh (a distance of zero) is the start
            // check's to report (Lemma 9.7), with its coincident witness.
            r @ StepResult::Touching {
                normal: Some(n),
                witness,
            } => {
                ((self.solid && witness.distance > T::ZERO) || gap_along(n) >= T::ZERO).then_some(r)
            }
            _ => None,
        }
    }

    /// The work done since the pair was made.
    #[must_use]
    pub const fn stats(&self) -> TraversalStats {
        self.stats
    }
}

/// Body B's side at the current time: its shape (a point for a plane), its
/// placement, its error, and the fixed direction of a plane.
struct Side<'s, 'a, T> {
    shape: &'s Convex<'a, T>,
    pose: Pose<T>,
    err: T,
    /// `8 (|x^|_1 + W + rho)`: the reach `gap_down` needs for B's support
    /// (`proofs/12-shapes.md`, "Support").
    weight: T,
    fixed: Option<Direction<T>>,
    motion: &'s PreparedMotion<T>,
}

impl<'s, 'a, T: Float> Side<'s, 'a, T> {
    /// B's side at `t`: `shape` placed by `motion`, its placement error, and
    /// the reach its support needs; with it B's reach over the rest of the
    /// interval (`placement_error`'s second value).
    fn at(
        shape: &'s Convex<'a, T>,
        motion: &'s PreparedMotion<T>,
        t: T,
        fixed: Option<Direction<T>>,
    ) -> (Self, T) {
        let pose = motion.motion().pose_at(t);
        let (err, reach) = placement_error(motion.motion(), t, shape.reach());
        let weight = T::from_u32(8)
            * sum_up(
                sum_up(pose.translation.norm_l1(), shape.weight()),
                shape.radius(),
            );
        let side = Side {
            shape,
            pose,
            err,
            weight,
            fixed,
            motion,
        };
        (side, reach)
    }
}

impl<T: Float> Side<'_, '_, T> {
    /// The least of `x . n` over B's exact points, as computed.
    fn lower(&self, n: Vec3<T>) -> T {
        self.pose.translation.dot(n)
            - self
                .shape
                .core_support_value(self.pose.inverse_transform_vector(-n))
            - self.shape.radius()
    }

    /// B's closing bound along `-n` (one-sided) or speed along `n`: its
    /// support's (Lemma 12.5).
    fn rate(&self, n: Direction<T>, kind: BoundKind, one_sided: bool) -> T {
        if one_sided {
            self.motion.probe(-n).convex_support_rate(self.shape, kind)
        } else {
            self.motion.probe(n).convex_support_speed(self.shape, kind)
        }
    }
}

impl<T: Float> CaStep<T> for MeshConvexPair<'_, T> {
    fn bounding_balls(&self) -> Option<(BoundingBall<T>, BoundingBall<T>)> {
        match &self.other {
            Other::Shape(s) => Some((
                self.mesh.nodes[0].ball,
                BoundingBall::try_new([T::ZERO; 3], s.reach()).ok()?,
            )),
            Other::Plane(_) => None,
        }
    }

    fn check_motions(&self, _a: &RigidMotion<T>, b: &RigidMotion<T>) -> Result<(), CaError> {
        match self.other {
            Other::Plane(_) => check_half_space(b),
            Other::Shape(_) => Ok(()),
        }
    }

    fn step(
        &mut self,
        t: T,
        a: &PreparedMotion<T>,
        b: &PreparedMotion<T>,
        params: &CaParams<T>,
    ) -> StepResult<T> {
        if let Some(hull) = self.hull {
            if let Some(r) = self.hull_step(hull, t, (a, b), params) {
                return r;
            }
        }
        let point = Convex::point();
        let (shape, fixed) = match &self.other {
            Other::Shape(s) => (*s, None),
            Other::Plane(h) => (point, Some(-h.normal())),
        };
        let pa = Placed::new(self.mesh, a, t);
        let (side, reach_b) = Side::at(&shape, b, t, fixed);
        let mut best = diff_up(b.motion().interval().end(), t);
        let (cd, clear) = (params.contact_distance, params.clearance());
        let resolution = resolution_up(pa.err, side.err, pa.reach + reach_b);
        let limited = resolution >= clear || resolution.is_nan();
        if self.mesh.reach < least_resolved_reach::<T>() {
            return StepResult::PrecisionLimit {
                resolution: resolution.max_nan(least_resolved_reach()),
            };
        }
        let kind = params.bound.cheap_kind();
        let first_only = params.witness == WitnessSearch::First;
        let (start, budget) = (self.stats, params.work_budget);
        let mut found = Found::new(params.witness_tolerance);
        // The front of the last step, when it is this query's and at most
        // half of it is stale against the last step's length (Lemma 9.9;
        // no seeds here to estimate this step's).
        let motions = (*a.motion(), *b.motion());
        let key = (cd, clear, kind, params.one_sided);
        let carry = self.carry.take().filter(|c| {
            self.carry_front
                && !limited
                && c.takes(t, (&motions.0, &motions.1), key, self.ws.front.len())
                && 2 * self
                    .ws
                    .front
                    .iter()
                    .filter(|e| e.stale(t, c.last_step))
                    .count()
                    <= self.ws.front.len()
        });
        let front_ok = self.carry_front && !limited;
        let mut complete = true;
        let horizon = a.motion().interval().end();
        let entry = |pair: u32, (step, gap, rate): (T, T, T)| {
            FrontEntry::new((pair, 0), t, horizon, (step, gap, rate, cd))
        };
        let pairs_before = self.stats.node_pairs;
        self.ws.clear();
        self.ws.next.clear();
        if carry.is_some() {
            self.stats.carried += self.ws.enqueue_front(t) as u64;
        } else {
            self.ws.placed.push(pa.place(self.mesh, 0));
            let root = NodeStep::Near(-T::INFINITY).resolved(limited);
            self.ws.enqueue(Pending::new(root, (0, 0), (0, 0)));
        }
        while let Some(slot) = self.ws.pop().map(Queued::slot) {
            let p = self.ws.pending[slot as usize];
            let Pending {
                near,
                key,
                i,
                far,
                origin,
                ..
            } = p;
            let key = T::from_f64(key.0);
            let out_of_work = self.stats.out_of_work(&start, budget);
            match found.head((near, key), (best, T::ONE), first_only, out_of_work) {
                Head::Go => {}
                Head::Stop => break,
                Head::Cut => {
                    self.stats.pruned += self.ws.len() as u64 + 1;
                    best = best.min_nan(key);
                    // Every node left keeps its step: the next front.
                    if front_ok {
                        self.ws.queue_to_front(&p, (t, horizon, cd));
                    }
                    break;
                }
                Head::OutOfWork => return StepResult::WorkLimit,
            }
            self.stats.node_pairs += 1;
            // The nodes to measure: a carried node anew, or a split node's
            // two children (one call site of the node step).
            let (nodes, count) = if let Origin::Carried { .. } = origin {
                self.stats.refreshed += 1;
                ([i; 2], 1)
            } else if far {
                // Splitting a node this far from B for its size would gain
                // little: its own step is safe for everything below it
                // (Lemma 9.2, as `MeshPair`'s settled pairs).
                self.stats.settled += 1;
                best = best.min_nan(key);
                if front_ok {
                    self.ws.next.push(p.front_entry(t, horizon, cd));
                }
                continue;
            } else {
                let node = &self.mesh.nodes[i as usize];
                if let Some(li) = node.leaf() {
                    let measured = self.leaf(
                        &pa,
                        &side,
                        li,
                        (kind, params.one_sided, cd, clear),
                        (&mut best, &mut found),
                    );
                    match measured {
                        Some(m) if front_ok => self.ws.next.push(entry(i, m)),
                        Some(_) => {}
                        None => complete = false,
                    }
                    continue;
                }
                ([node.left, node.right], 2)
            };
            for &child in &nodes[..count] {
                let slot = self.ws.placed.len() as u32;
                self.ws.placed.push(pa.place(self.mesh, child));
                let q = self.ws.placed[slot as usize];
                let near_within = if limited { -T::INFINITY } else { cd };
                let best_step = if found.touching.is_some() {
                    T::ZERO
                } else {
                    best
                };
                let step = self
                    .node_step(
                        &pa,
                        &side,
                        (child, q),
                        (kind, params.one_sided, near_within, clear),
                        best_step,
                    )
                    .resolved(limited);
                if found.queues(step, best) {
                    self.ws.enqueue(Pending::new(step, (child, 0), (slot, 0)));
                } else {
                    self.stats.pruned += 1;
                    if let (
                        true,
                        NodeStep::Apart {
                            step, gap, rate, ..
                        },
                    ) = (front_ok, step)
                    {
                        self.ws.next.push(entry(child, (step, gap, rate)));
                    }
                }
            }
        }
        let result = found.verdict(best, limited, resolution);
        if front_ok && complete && matches!(result, StepResult::Advance { .. }) {
            self.ws.swap_fronts();
            let pairs = self.stats.node_pairs - pairs_before;
            self.carry = Some(Carry::after(carry, (t, best), motions, key, pairs));
        }
        result
    }

    fn work(&self) -> Work {
        self.stats.work().saturating_add(self.start.work())
    }

    fn initial_overlap(
        &mut self,
        t: T,
        a: &PreparedMotion<T>,
        b: &PreparedMotion<T>,
        params: &CaParams<T>,
    ) -> Option<StepResult<T>> {
        self.start.run(t, a, b, params.work_budget)
    }
}

impl<T: Float> MeshConvexPair<'_, T> {
    /// A mesh node against B (Lemma 12.4): the gap between the node's box
    /// and B along the line from the box's centre to B's origin, along
    /// the line to B's point nearest it on that line, and, for a core other
    /// than a point, along the line to the core point nearest the box's
    /// centre (Lemma 12.12), or along a plane's normal; the largest kept;
    /// over the node's ball bound and B's.
    fn node_step(
        &mut self,
        pa: &Placed<'_, T>,
        side: &Side<'_, '_, T>,
        (i, q): (u32, PlacedNode<T>),
        (kind, one_sided, near_within, clearance): (BoundKind, bool, T, T),
        best_step: T,
    ) -> NodeStep<T> {
        let node = &self.mesh.nodes[i as usize];
        let gap = |n: Vec3<T>| {
            let upper = q.centre.dot(n)
                + node
                    .obb
                    .support_up_with(pa.pose.inverse_transform_vector(n), &pa.box_err);
            side.lower(n) - upper
        };
        let mut chosen: Option<(T, Direction<T>)> = None;
        let mut consider = |n: Direction<T>| {
            let g = gap(n.get());
            if g > T::ZERO && chosen.is_none_or(|(best, _)| g > best) {
                chosen = Some((g, n));
            }
        };
        match side.fixed {
            Some(n) => consider(n),
            None => {
                let d = side.pose.translation - q.centre;
                if let Ok(n) = Direction::try_new_fast(d) {
                    consider(n);
                    // B's point farthest towards the node, and the line to it.
                    let local = side
                        .shape
                        .core_support_point(side.pose.inverse_transform_vector(-n.get()));
                    let near = side.pose.transform_point(local.to_vec3());
                    if let Ok(m) = Direction::try_new_fast(near - q.centre) {
                        consider(m);
                    }
                }
                // The line from the box's centre to B's core point nearest
                // it (GJK stopped at the stepper's need, Lemma 12.10's
                // rule): for a core other than a point, the two lines above
                // can be far from the closest direction (a cylinder's axis
                // end or a box's corner), and a node then keeps a gap much
                // below its triangles' (Lemma 12.12).
                if !matches!(side.shape.core(), Core::Point) {
                    let (on_a, on_b) = gjk_closest(
                        &CentrePoint(q.centre),
                        &PlacedCore {
                            shape: side.shape,
                            pose: &side.pose,
                        },
                        &GjkParams::default().with_rel_tol(gjk_tolerance::<T>()),
                        enough_within(side.shape.radius(), near_within, clearance),
                    );
                    if let Ok(m) = Direction::try_new_fast(on_b - on_a) {
                        consider(m);
                    }
                }
            }
        }
        let Some((gap, n)) = chosen else {
            self.stats.overlapping += 1;
            return NodeStep::Near(-T::INFINITY);
        };
        let g = gap_down(gap, pa.err, side.err, pa.reach + side.weight);
        if g.is_nan() || g <= near_within {
            return NodeStep::Near(g);
        }
        if best_step <= T::ZERO {
            // Only gaps matter in the search for the closest pair.
            return NodeStep::Apart {
                step: T::ZERO,
                far: false,
                gap: g,
                rate: T::INFINITY,
            };
        }
        self.stats.bounds += 2;
        let mu_a = if one_sided {
            pa.motion.probe(n).ball_rate(&node.ball, kind)
        } else {
            pa.motion.probe(n).ball_speed(&node.ball, kind)
        };
        let mu_b = side.rate(n, kind, one_sided);
        // Far for its size (`MeshParams::far_ratio`'s default): splitting
        // the node could widen its gap by at most its ball's diameter.
        let far = gap >= T::from_f64(FAR_RATIO) * node.ball.radius();
        NodeStep::Apart {
            step: step_down(g, clearance, mu_a, mu_b),
            far,
            gap: g,
            rate: mu_a + mu_b,
        }
    }

    /// One triangle of the mesh against B: its distance (GJK against B's
    /// core, or its lowest corner above a plane), a contact within the
    /// contact distance, else its own step along its closest direction.
    fn leaf(
        &mut self,
        pa: &Placed<'_, T>,
        side: &Side<'_, '_, T>,
        li: usize,
        (kind, one_sided, cd, clearance): (BoundKind, bool, T, T),
        (best, found): (&mut T, &mut Found<T>),
    ) -> Option<(T, T, T)> {
        let leaf = &self.mesh.leaves[li];
        self.stats.triangle_pairs += 1;
        let corners = pa.corners(leaf);
        let (on_a, on_b, distance, dir) = match side.fixed {
            Some(n) => {
                // The lowest corner above the plane (n = -m).
                let m = -n.get();
                let (mut low, mut h) = (corners[0], T::INFINITY);
                for c in corners {
                    let height = (c - side.pose.translation).dot(m);
                    if height < h {
                        (low, h) = (c, height);
                    }
                }
                (low, low - m * h, h, Ok(n))
            }
            None => {
                let tri = corners.map(Vec3::to_array);
                let closest = ConvexPolytope::try_new(&tri, Pose::IDENTITY).map(|p| {
                    gjk_distance(
                        &p,
                        &PlacedCore {
                            shape: side.shape,
                            pose: &side.pose,
                        },
                        // As `ConvexPair`'s: curved cores converge only
                        // asymptotically, and the direction is only a choice
                        // (the gap along it is measured, Lemma 12.1).
                        &GjkParams::default().with_rel_tol(gjk_tolerance::<T>()),
                    )
                });
                let Ok(c) = closest else {
                    return None;
                };
                let (on_a, core) = (c.on_a.to_vec3(), c.on_b.to_vec3());
                let dir = Direction::try_new(core - on_a);
                let r = side.shape.radius();
                let on_b = dir.map_or(core, |n| core - n.get() * r);
                (on_a, on_b, (core - on_a).length() - r, dir)
            }
        };
        let w = Witness::new(
            distance.max_nan(T::ZERO),
            Point3::from_vec3(on_a),
            Point3::from_vec3(on_b),
        );
        let n = found.keep(w, None, dir.ok(), distance > cd)?;
        let (mut step, mut g, mut mu, mut dir) =
            self.leaf_step(pa, side, (li, corners), n, (kind, one_sided, clearance));
        // Where the closest direction lost more than half the distance (a
        // curved core nearly touching a large triangle in `f32`: the
        // closest points' rounding over their distance), the triangle's
        // normal too, turned towards B; the longer step is taken (both are
        // safe, Lemma 9.1 for any direction).
        if side.fixed.is_none() && g < (distance - clearance) * T::HALF {
            let normal = (corners[1] - corners[0]).cross(corners[2] - corners[0]);
            let normal = if normal.dot(on_b - on_a) < T::ZERO {
                -normal
            } else {
                normal
            };
            if let Ok(m) = Direction::try_new(normal) {
                let other =
                    self.leaf_step(pa, side, (li, corners), m, (kind, one_sided, clearance));
                if other.0 > step {
                    (step, g, mu, dir) = other;
                }
            }
        }
        found.fold(step, dir, best);
        Some((step, g, mu))
    }

    /// A leaf's certified gap along `n` (the slab from its placed `corners`
    /// to B's support), its closing bounds, and the step: `(step, gap, mu, n)`.
    fn leaf_step(
        &mut self,
        pa: &Placed<'_, T>,
        side: &Side<'_, '_, T>,
        (li, corners): (usize, [Vec3<T>; 3]),
        n: Direction<T>,
        (kind, one_sided, clearance): (BoundKind, bool, T),
    ) -> (T, T, T, Direction<T>) {
        let leaf = &self.mesh.leaves[li];
        let nv = n.get();
        let upper = corners[0]
            .dot(nv)
            .max_nan(corners[1].dot(nv))
            .max_nan(corners[2].dot(nv));
        let g = gap_down(
            side.lower(nv) - upper,
            pa.leaf_err(leaf),
            side.err,
            pa.reach + side.weight,
        );
        self.stats.bounds += 2;
        let mu_a = if one_sided {
            pa.leaf_rate(leaf, n, kind)
        } else {
            pa.leaf_speed(leaf, n, kind)
        };
        let mu_b = side.rate(n, kind, one_sided);
        (step_down(g, clearance, mu_a, mu_b), g, mu_a + mu_b, n)
    }
}

#[cfg(test)]
impl<T: Float> MeshConvexPair<'_, T> {
    /// Every node's certified gap to B at `t` (as `node_step` measures it
    /// in a step: `-inf` when no direction separates them), B a shape.
    fn node_gaps(&mut self, t: T, a: &PreparedMotion<T>, b: &PreparedMotion<T>, cd: T) -> Vec<T> {
        let Other::Shape(shape) = self.other else {
            return Vec::new();
        };
        let pa = Placed::new(self.mesh, a, t);
        let (side, _) = Side::at(&shape, b, t, None);
        let kind = BoundKind::Evq;
        (0..self.mesh.nodes.len() as u32)
            .map(|i| {
                let q = pa.place(self.mesh, i);
                let step =
                    self.node_step(&pa, &side, (i, q), (kind, true, cd, cd * T::HALF), T::ZERO);
                match step {
                    NodeStep::Apart { gap, .. } | NodeStep::Near(gap) => gap,
                }
            })
            .collect()
    }
}

#[cfg(test)]
mod tests {
    //! Lemma 12.12 (`proofs/12-shapes.md`): a node's certified gap to a
    //! cylinder or cone (rounded or not), with the line to B's core point
    //! nearest the node's box centre among its directions, against
    //! independent distances: never above the distance of the node's
    //! triangles to B (sampled on the triangles, each sample's distance to
    //! the solid in closed form), and at least the lemma's promise from the
    //! closed-form distance of the box's centre.
    extern crate std;
    use std::vec::Vec;

    use super::MeshConvexPair;
    use crate::ca::convex_convex::tests::project_core;
    use crate::ca::convex_convex::ENOUGH;
    use crate::rng::SplitMix64;
    use crate::{BallTree, Convex, Float, PreparedMotion, RigidMotion, Rotation, Vec3};

    /// A bumpy sphere of radius about `0.5` (not convex): `(vertices,
    /// triangles)`.
    fn bumpy_sphere(rng: &mut SplitMix64) -> (Vec<[f64; 3]>, Vec<[u32; 3]>) {
        let (nu, nv) = (24u32, 12u32);
        let mut vertices = Vec::new();
        for j in 0..=nv {
            let theta = core::f64::consts::PI * f64::from(j) / f64::from(nv);
            for i in 0..nu {
                let phi = core::f64::consts::TAU * f64::from(i) / f64::from(nu);
                let r = 0.5 * (1.0 + 0.08 * rng.range(-1.0, 1.0));
                vertices.push([
                    r * theta.sin() * phi.cos(),
                    r * theta.cos(),
                    r * theta.sin() * phi.sin(),
                ]);
            }
        }
        let mut triangles = Vec::new();
        for j in 0..nv {
            for i in 0..nu {
                let v = |jj: u32, ii: u32| jj * nu + ii % nu;
                triangles.push([v(j, i), v(j + 1, i), v(j + 1, i + 1)]);
                triangles.push([v(j, i), v(j + 1, i + 1), v(j, i + 1)]);
            }
        }
        (vertices, triangles)
    }

    /// The distance from `x` (world, `f64`) to the placed solid (core
    /// `(h, rho)` rotated by `m`, moved to `c`, dilated by `radius`), in
    /// closed form.
    fn to_solid(
        x: [f64; 3],
        cone: bool,
        (h, rho, radius): (f64, f64, f64),
        (m, c): ([[f64; 3]; 3], [f64; 3]),
    ) -> f64 {
        let e = [0, 1, 2].map(|k| x[k] - c[k]);
        let l = [0, 1, 2].map(|i| m[0][i] * e[0] + m[1][i] * e[1] + m[2][i] * e[2]);
        let p = project_core(cone, h, rho, l);
        let d = [0, 1, 2].map(|k| l[k] - p[k]);
        (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt() - radius
    }

    fn node_gaps_are_sound_and_within_the_promise<T: Float>(tol: f64) {
        let mut rng = SplitMix64::new(5511);
        let f = T::from_f64;
        let (vertices, triangles) = bumpy_sphere(&mut rng);
        let tv: Vec<[T; 3]> = vertices.iter().map(|v| v.map(f)).collect();
        let tree = BallTree::try_new(&tv, &triangles).expect("tree");
        let still =
            RigidMotion::try_from_arrays([T::ZERO; 3], [T::ZERO; 3], [T::ZERO; 3]).expect("motion");
        let pa = PreparedMotion::new(&still);
        let (cd, cl) = (1e-3, 0.5e-3);
        let (mut checked, mut worst) = (0usize, 0.0f64);
        for case in 0..48 {
            let cone = case % 2 == 1;
            let (h, rho) = if case % 4 < 2 {
                (0.4, 0.15)
            } else {
                (0.15, 0.35)
            };
            let radius = if case % 3 == 0 { 0.0 } else { 0.05 };
            let core = if cone {
                Convex::try_cone(f(h), f(rho))
            } else {
                Convex::try_cylinder(f(h), f(rho))
            };
            let shape = core.and_then(|s| s.try_rounded(f(radius))).expect("shape");
            let (hh, rr, ra) = (f(h).to_f64(), f(rho).to_f64(), f(radius).to_f64());
            let axis = rng.direction();
            let rot = Rotation::try_from_axis_angle(
                Vec3::from_array(axis.map(f)),
                f(rng.range(0.0, 6.0)),
            )
            .expect("rotation");
            let m = rot.matrix().map(|row| row.map(T::to_f64));
            // B's centre along a random direction, at a gap to the sphere
            // log-uniform in [1e-3, 0.3] (about: the sphere is bumpy).
            let u = rng.direction();
            let gap = 10f64.powf(rng.range(-3.0, -0.5));
            let c = u.map(|x| f(x * (0.55 + gap + 0.5 * rng.unit())).to_f64());
            let mb = RigidMotion::try_from_arrays(c.map(f), [T::ZERO; 3], [T::ZERO; 3])
                .map(|mo| mo.with_orientation(rot))
                .expect("motion");
            let pb = PreparedMotion::new(&mb);
            let mut pair = MeshConvexPair::new(&tree, shape);
            let gaps = pair.node_gaps(T::ZERO, &pa, &pb, f(cd));
            let solid = (hh, rr, ra);
            for (i, &g) in gaps.iter().enumerate() {
                // The node's triangles' distance to B, sampled on them (each
                // sample a point of a triangle, so never below the true
                // distance, up to `f64` rounding).
                let mut stack = std::vec![i as u32];
                let mut sampled = f64::INFINITY;
                while let Some(k) = stack.pop() {
                    let node = &tree.whole.nodes[k as usize];
                    if let Some(li) = node.leaf() {
                        let t = tree.whole.leaves[li].corners.map(|p| p.map(T::to_f64));
                        let n = 12;
                        for a in 0..=n {
                            for b in 0..=n - a {
                                let (wa, wb) =
                                    (f64::from(a) / f64::from(n), f64::from(b) / f64::from(n));
                                let x = [0, 1, 2].map(|k| {
                                    t[0][k] + wa * (t[1][k] - t[0][k]) + wb * (t[2][k] - t[0][k])
                                });
                                sampled = sampled.min(to_solid(x, cone, solid, (m, c)));
                            }
                        }
                    } else {
                        stack.push(node.left);
                        stack.push(node.right);
                    }
                }
                let g = g.to_f64();
                assert!(
                    g <= sampled,
                    "case {case}, node {i}: certified {g} above the sampled {sampled}"
                );
                // The promise: the box's centre `x` is `D_x` from B, and every
                // box point within `e` of it, so the gap along the chosen
                // line is at least `(1 - ENOUGH)(D_x - cl) + cl - e`.
                let node = &tree.whole.nodes[i];
                let x = node.obb.centre.map(T::to_f64);
                let half = node.obb.half.map(T::to_f64);
                let e = (half[0] * half[0] + half[1] * half[1] + half[2] * half[2]).sqrt()
                    + node.obb.rho.to_f64();
                let dx = to_solid(x, cone, solid, (m, c));
                if dx - e <= 2.0 * cd {
                    continue;
                }
                let promised = (1.0 - ENOUGH) * (dx - cl) + cl - e;
                worst = worst.max((promised - g) / dx);
                assert!(
                    g >= promised - tol * dx,
                    "case {case}, node {i}: certified {g}, promised {promised} (centre at {dx}, box {e})"
                );
                checked += 1;
            }
        }
        std::println!(
            "{checked} nodes checked, worst shortfall {worst:e} of the centre's distance"
        );
        assert!(checked >= 1000, "too few nodes checked: {checked}");
    }

    #[test]
    fn node_gaps_to_curved_cores_are_sound_and_within_the_promise_f64() {
        node_gaps_are_sound_and_within_the_promise::<f64>(1e-9);
    }

    #[test]
    fn node_gaps_to_curved_cores_are_sound_and_within_the_promise_f32() {
        node_gaps_are_sound_and_within_the_promise::<f32>(1e-4);
    }
}
