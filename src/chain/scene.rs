//! [`ChainScene`]: a chain in still surroundings, its checked pairs and its
//! public queries (a segment, a path, the clearance and the collisions at a
//! configuration).

use alloc::collections::BTreeSet;
use alloc::vec;
use alloc::vec::Vec;
use core::ops::ControlFlow;

use crate::chain::dispatch::{first_link, placed_gap, target_of, PlacedPair};
use crate::chain::edge::{Edge, EdgeReport, EdgeWork, Item};
use crate::chain::model::{Chain, ChainError};
use crate::chain::obstacle::Obstacle;
use crate::chain::params::ChainParams;
use crate::chain::rake::{Rake, RakeModel, RakeWork, RAKE_MIN_BUDGET};
use crate::chain::report::{ChainPair, ChainStats, PathReport, SegmentOutcome, SegmentReport};
use crate::chain::segment::{Segment, Work};
use crate::chain::shapes::ShapeObstacle;
use crate::geometry::gjk::ConvexPolytope;
use crate::rounding::gap_slack_up;
use crate::{Float, Pose};

mod first_contact;
mod refine;

/// A chain in still surroundings: what a planner's motion validator asks
/// about. Pairs of adjacent links (joined by one joint, or rigidly through
/// fixed joints) are never checked, nor pairs given to
/// [`allow_collision`](Self::allow_collision) (an SRDF's disabled pairs).
///
/// ```
/// use motion_bound::chain::{ChainBuilder, ChainScene, JointKind, JointSpec, Obstacle, SegmentOutcome};
/// use motion_bound::{Pose, TriMesh, Vec3};
/// // A bar 1 long along x, and a small block.
/// let bar = TriMesh::try_new(
///     vec![[0.0, -0.02, -0.02], [1.0, 0.0, 0.0], [0.0, 0.02, -0.02], [0.0, 0.0, 0.02]],
///     vec![[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]],
/// )?;
/// let block = TriMesh::try_new(
///     vec![[0.0, 0.0, 0.0], [0.05, 0.0, 0.0], [0.0, 0.05, 0.0], [0.0, 0.0, 0.05]],
///     vec![[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]],
/// )?;
/// let mut b = ChainBuilder::new();
/// let base = b.add_link("base", None)?;
/// let arm = b.add_link("arm", Some(bar))?;
/// b.add_joint(JointSpec {
///     name: "shoulder".into(),
///     kind: JointKind::Revolute,
///     parent: base,
///     child: arm,
///     origin: Pose::IDENTITY,
///     axis: [0.0, 0.0, 1.0],
///     limits: None,
/// })?;
/// let mut scene = ChainScene::new(b.build()?);
/// // The block 0.8 from the axis at 1.2 rad: the bar turning from 0 to 3 rad
/// // reaches it a little before 1.2 rad (t = 0.4).
/// let at = Pose::from_translation(Vec3::new(0.8 * 1.2f64.cos(), 0.8 * 1.2f64.sin(), -0.02));
/// scene.add_obstacle(Obstacle::try_new("block", block, at)?);
/// let report = scene.check_segment(&[0.0], &[3.0])?;
/// match report.outcome {
///     SegmentOutcome::Contact(c) => assert!(c.time > 0.3 && c.time < 0.4, "{c:?}"),
///     other => panic!("{other:?}"),
/// }
/// // Turning the other way, nothing is in the way.
/// assert_eq!(scene.check_segment(&[0.0], &[-3.0])?.outcome, SegmentOutcome::Separated);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Clone, Debug)]
pub struct ChainScene<T: 'static> {
    chain: Chain<T>,
    obstacles: Vec<Obstacle<T>>,
    shapes: Vec<ShapeObstacle<T>>,
    allowed: BTreeSet<(usize, usize)>,
    params: ChainParams<T>,
    /// For each link, the root of its rigid group (links joined by fixed
    /// joints share one).
    group: Vec<usize>,
    /// The rake's covers, levers and lanes (`rake.rs`), made once.
    rake: RakeModel,
}

impl<T: Float> ChainScene<T> {
    /// A scene of `chain` alone, with the default parameters.
    #[must_use]
    pub fn new(chain: Chain<T>) -> Self {
        let n = chain.links.len();
        let mut group: Vec<usize> = (0..n).collect();
        // Parents first: a link joined by a fixed joint takes its parent's group.
        for &j in &chain.order {
            let joint = &chain.joints[j];
            if joint.dof.is_none() {
                group[joint.spec.child] = group[joint.spec.parent];
            }
        }
        Self {
            rake: RakeModel::new(&chain),
            chain,
            obstacles: Vec::new(),
            shapes: Vec::new(),
            allowed: BTreeSet::new(),
            params: ChainParams::default(),
            group,
        }
    }

    /// The chain.
    #[must_use]
    pub fn chain(&self) -> &Chain<T> {
        &self.chain
    }

    /// The obstacles.
    #[must_use]
    pub fn obstacles(&self) -> &[Obstacle<T>] {
        &self.obstacles
    }

    /// Adds an obstacle and returns its index.
    pub fn add_obstacle(&mut self, obstacle: Obstacle<T>) -> usize {
        self.obstacles.push(obstacle);
        self.obstacles.len() - 1
    }

    /// Adds a shape obstacle (a primitive, a half-space or a point cloud)
    /// and returns its index. Every query takes it, as it takes meshes:
    /// the first-contact queries ([`check_segment`](Self::check_segment),
    /// [`check_path`](Self::check_path)) through the edge engine depth first
    /// in time, [`clearance`](Self::clearance) and
    /// [`collides_at`](Self::collides_at) by the rigid engine's certified
    /// gaps at the configuration, the edge queries
    /// ([`check_edge`](Self::check_edge), [`edge_is_free`](Self::edge_is_free),
    /// [`edges_are_free`](Self::edges_are_free)) as before.
    pub fn add_shape(&mut self, shape: ShapeObstacle<T>) -> usize {
        self.shapes.push(shape);
        self.shapes.len() - 1
    }

    /// The shape obstacles.
    #[must_use]
    pub fn shapes(&self) -> &[ShapeObstacle<T>] {
        &self.shapes
    }

    /// Never checks links `a` and `b` against each other (an SRDF's
    /// `disable_collisions`).
    pub fn allow_collision(&mut self, a: usize, b: usize) {
        self.allowed.insert((a.min(b), a.max(b)));
    }

    /// Sets the parameters.
    ///
    /// # Errors
    /// [`ChainError::InvalidParameter`].
    pub fn set_params(&mut self, params: ChainParams<T>) -> Result<(), ChainError> {
        params.validate()?;
        self.params = params;
        Ok(())
    }

    /// The parameters.
    #[must_use]
    pub fn params(&self) -> ChainParams<T> {
        self.params
    }

    /// Whether links `a` and `b` are adjacent: in one rigid group, or in
    /// groups joined by one movable joint (`false` for an index out of range).
    #[must_use]
    pub fn adjacent(&self, a: usize, b: usize) -> bool {
        let (Some(&ga), Some(&gb)) = (self.group.get(a), self.group.get(b)) else {
            return false;
        };
        if ga == gb {
            return true;
        }
        let joined = |child_group: usize, parent_group: usize| {
            self.chain
                .parent_link(child_group)
                .is_some_and(|p| self.group[p] == parent_group)
        };
        joined(ga, gb) || joined(gb, ga)
    }

    /// Whether the pair of links is checked (both have geometry, not
    /// adjacent, not allowed).
    #[must_use]
    pub fn checks_pair(&self, a: usize, b: usize) -> bool {
        a != b
            && self.chain.links.get(a).is_some_and(|l| l.tree.is_some())
            && self.chain.links.get(b).is_some_and(|l| l.tree.is_some())
            && !self.adjacent(a, b)
            && !self.allowed.contains(&(a.min(b), a.max(b)))
    }

    /// The pairs a query considers (with geometry), and whether each is
    /// checked: the one list every query takes its pairs from (each served
    /// by its kinds' engine, `dispatch.rs`), per link its shapes, its mesh
    /// obstacles, then the links after it.
    fn pairs(&self) -> Vec<(ChainPair, bool)> {
        let mut out = Vec::new();
        let n = self.chain.links.len();
        for l in 0..n {
            if self.chain.links[l].tree.is_none() {
                continue;
            }
            for s in 0..self.shapes.len() {
                out.push((ChainPair::Shape { link: l, shape: s }, true));
            }
            for o in 0..self.obstacles.len() {
                out.push((
                    ChainPair::Obstacle {
                        link: l,
                        obstacle: o,
                    },
                    true,
                ));
            }
            for m in l + 1..n {
                if self.chain.links[m].tree.is_some() {
                    out.push((
                        ChainPair::SelfCollision { a: l, b: m },
                        self.checks_pair(l, m),
                    ));
                }
            }
        }
        out
    }

    /// The first contact along the joint-space segment
    /// `q(t) = q0 + t (q1 - q0)`, `t` in `[0, 1]`.
    ///
    /// # Errors
    /// [`ChainError::WrongDof`] and [`ChainError::NonFiniteCoordinate`];
    /// [`ChainError::BeyondLimits`] for an end outside the joints' limits
    /// (unless [`ChainParams::within_limits`] is off).
    pub fn check_segment(&self, q0: &[T], q1: &[T]) -> Result<SegmentReport<T>, ChainError> {
        self.check_end(q0)?;
        self.check_end(q1)?;
        let mut work = Work::default();
        let mut checker = self.shape_checker();
        Ok(self.segment(q0, q1, &mut work, checker.as_mut()))
    }

    /// Whether the joint-space edge `q0 -> q1` is certified free of every
    /// obstacle (meshes and shapes) and checked link pair, with
    /// [`ChainParams::padding`] to spare: a planner's motion validator.
    /// A contact or an exhausted work budget is `false`
    /// ([`check_edge`](Self::check_edge) tells them apart). For many edges
    /// reuse one [`EdgeChecker`] ([`edge_checker`](Self::edge_checker)).
    ///
    /// ```
    /// use motion_bound::chain::{ChainBuilder, ChainScene, JointKind, JointSpec, ShapeObstacle};
    /// use motion_bound::{Convex, Pose, TriMesh, Vec3};
    /// // A bar 1 long along x turning about z, and a thin pole at 45 degrees.
    /// let bar = TriMesh::try_new(
    ///     vec![[0.0, -0.02, -0.02], [1.0, 0.0, 0.0], [0.0, 0.02, -0.02], [0.0, 0.0, 0.02]],
    ///     vec![[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]],
    /// )?;
    /// let mut b = ChainBuilder::new();
    /// let base = b.add_link("base", None)?;
    /// let arm = b.add_link("arm", Some(bar))?;
    /// b.add_joint(JointSpec {
    ///     name: "j1".into(), kind: JointKind::Revolute, parent: base, child: arm,
    ///     origin: Pose::IDENTITY, axis: [0.0, 0.0, 1.0], limits: Some([-3.0, 3.0]),
    /// })?;
    /// let mut scene = ChainScene::new(b.build()?);
    /// let pole = Convex::try_cylinder(1.0, 0.005)?; // along its y axis
    /// let upright = Pose { rotation: [[1.0, 0.0, 0.0], [0.0, 0.0, -1.0], [0.0, 1.0, 0.0]],
    ///     translation: Vec3::new(0.5, 0.5, 0.0) };
    /// scene.add_shape(ShapeObstacle::try_new("pole", pole, upright)?);
    /// // Sweeping 0 -> 1.5 rad passes through the pole; samples 0.1 apart would not see it.
    /// assert!(!scene.edge_is_free(&[0.0], &[1.5])?);
    /// assert!(scene.edge_is_free(&[0.0], &[-1.5])?);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    ///
    /// # Errors
    /// As [`check_segment`](Self::check_segment).
    pub fn edge_is_free(&self, q0: &[T], q1: &[T]) -> Result<bool, ChainError> {
        self.edge_checker().is_free(q0, q1)
    }

    /// The edge query's full answer: [`EdgeOutcome::Free`](crate::chain::EdgeOutcome::Free), a contact (the
    /// segment certified free up to its time, never later than the first
    /// touch), or undecided when [`ChainParams::edge_budget`] ran out; and
    /// the work done.
    ///
    /// # Errors
    /// As [`check_segment`](Self::check_segment).
    pub fn check_edge(&self, q0: &[T], q1: &[T]) -> Result<EdgeReport<T>, ChainError> {
        self.edge_checker().check(q0, q1)
    }

    /// Whether each edge `(q0, q1)` is free ([`edge_is_free`](Self::edge_is_free)),
    /// with one checker's buffers for them all.
    ///
    /// # Errors
    /// As [`check_segment`](Self::check_segment), for the first edge refused.
    pub fn edges_are_free<Q: AsRef<[T]>>(&self, edges: &[(Q, Q)]) -> Result<Vec<bool>, ChainError> {
        let mut checker = self.edge_checker();
        edges
            .iter()
            .map(|(a, b)| checker.is_free(a.as_ref(), b.as_ref()))
            .collect()
    }

    /// A checker for many edges of this scene: its buffers and the list of
    /// what is checked, made once.
    #[must_use]
    pub fn edge_checker(&self) -> EdgeChecker<'_, T> {
        let mut initial = Vec::new();
        // A motion slot per link (all its joints) and per link of a pair
        // with the pair's common joints skipped.
        let mut slots: Vec<(usize, usize)> = Vec::new();
        let mut slot = |link: usize, skip: usize| {
            let at = slots
                .iter()
                .position(|&s| s == (link, skip))
                .unwrap_or_else(|| {
                    slots.push((link, skip));
                    slots.len() - 1
                });
            u16::try_from(at).unwrap_or(u16::MAX)
        };
        // The checked pairs (`pairs`, by their first link), each with its
        // kinds' root target (`dispatch.rs`); every link with geometry has
        // its own slot, made before its pairs'.
        let pairs = self.pairs();
        let mut next = 0;
        for l in 0..self.chain.links.len() {
            if self.chain.links[l].tree.is_none() {
                continue;
            }
            let own = slot(l, 0);
            while let Some(&(pair, checked)) = pairs.get(next).filter(|p| first_link(p.0) == l) {
                next += 1;
                if !checked {
                    continue;
                }
                let (slot_a, slot_b) = match pair {
                    ChainPair::SelfCollision { a, b } => {
                        let skip = self.chain.common_prefix(a, b);
                        let sa = slot(a, skip);
                        (sa, slot(b, skip))
                    }
                    _ => (own, own),
                };
                initial.push(Item {
                    link: l as u32,
                    node: 0,
                    target: target_of(pair, &self.shapes),
                    slot: slot_a,
                    slot_b,
                });
            }
        }
        // Each link's hull (its distinct vertices), validated when the chain
        // was built: `None` for a link without geometry or with a vertex GJK
        // refuses (the query then descends its tree alone).
        let hulls = self
            .chain
            .links
            .iter()
            .map(|l| {
                l.hull_rho
                    .and_then(|rho| ConvexPolytope::with_radius(&l.hull, rho, Pose::IDENTITY).ok())
                    .map(|p| p.with_clusters(&l.hull_clusters))
            })
            .collect();
        // Each mesh obstacle's hull, placed by its pose once (Lemma 13.8).
        let obstacle_hulls = self
            .obstacles
            .iter()
            .map(|o| {
                o.hull_rho
                    .and_then(|rho| ConvexPolytope::with_radius(&o.hull, rho, o.pose).ok())
                    .map(|p| p.with_clusters(&o.hull_clusters))
            })
            .collect();
        EdgeChecker {
            scene: self,
            initial,
            slots,
            hulls,
            obstacle_hulls,
            work: EdgeWork::default(),
            rake: RakeWork::default(),
        }
    }

    /// A segment's end: the right length, finite, and within the limits
    /// when [`ChainParams::within_limits`] is on.
    fn check_end(&self, q: &[T]) -> Result<(), ChainError> {
        if self.params.within_limits {
            self.chain.check_q_within_limits(q)
        } else {
            self.chain.check_q(q)
        }
    }

    /// The first contact along a path of waypoints, segment by segment; stops
    /// at the first segment with a contact (or an undecided one).
    ///
    /// # Errors
    /// [`ChainError::InvalidParameter`] for fewer than two waypoints, and as
    /// [`check_segment`](Self::check_segment).
    pub fn check_path<Q: AsRef<[T]>>(&self, waypoints: &[Q]) -> Result<PathReport<T>, ChainError> {
        if waypoints.len() < 2 {
            return Err(ChainError::InvalidParameter("a path needs two waypoints"));
        }
        for q in waypoints {
            self.check_end(q.as_ref())?;
        }
        let mut work = Work::default();
        let mut stats = ChainStats::default();
        let mut checker = self.shape_checker();
        for (i, w) in waypoints.windows(2).enumerate() {
            let report = self.segment(w[0].as_ref(), w[1].as_ref(), &mut work, checker.as_mut());
            stats += report.stats;
            if report.outcome != SegmentOutcome::Separated || i + 2 == waypoints.len() {
                return Ok(PathReport {
                    segment: i,
                    outcome: report.outcome,
                    stats,
                });
            }
        }
        Err(ChainError::InvalidParameter("a path needs two waypoints"))
    }

    /// A certified lower bound of the smallest distance over the checked
    /// pairs at configuration `q` (`<= 0` for touching or overlapping
    /// surfaces, up to rounding), and the pair that attains it (`None` when
    /// nothing is checked): links against mesh obstacles, shape obstacles
    /// (primitives, half-spaces, point clouds) and each other. When what
    /// the nearest pair's bound deducts for the rounding of the forward
    /// kinematics is more than `2^-33` of it, its links are placed again in
    /// double-double arithmetic and it is measured again (so is any pair
    /// still below it). Near contact the bound is then within about `1e-14`
    /// of the distance in `f64` (world coordinates near a metre; measured:
    /// `7e-15` at most, `1e-9` relative at `1e-5`, shape obstacles included,
    /// whose supports' rounding is bounded by kind; `proofs/13-chains.md`,
    /// Lemmas 13.14 and 13.16).
    ///
    /// # Errors
    /// [`ChainError::WrongDof`] and [`ChainError::NonFiniteCoordinate`].
    pub fn clearance(&self, q: &[T]) -> Result<(T, Option<ChainPair>), ChainError> {
        let mut best = T::INFINITY;
        let mut bounds = Vec::new();
        let shapes = &self.shapes;
        self.each_checked_pair_at(q, |p, stack| {
            let mut stats = ChainStats::default();
            let d = placed_gap(&p, shapes, best, T::ZERO, stack, &mut stats).gap;
            if d < best {
                best = d;
            }
            let deducted = gap_slack_up(p.a.delta, p.b.delta, p.a.reach + p.b.reach);
            bounds.push((d, p.pair, deducted));
            ControlFlow::Continue(())
        })?;
        Ok(self.refined_clearance(q, bounds))
    }

    /// Whether some checked pair's surfaces meet at configuration `q` (a
    /// triangle pair, or a triangle and a shape, at computed distance at
    /// most [`ChainParams::padding`], 0 by default): the static check a
    /// discrete motion validator runs at each sample, against meshes and
    /// shapes. Stops at the first such pair
    /// ([`EdgeChecker::collides_at`] reuses its buffers).
    ///
    /// # Errors
    /// [`ChainError::WrongDof`] and [`ChainError::NonFiniteCoordinate`].
    pub fn collides_at(&self, q: &[T]) -> Result<bool, ChainError> {
        self.edge_checker().collides_at(q)
    }

    /// Never checks again the pairs of links whose surfaces are within
    /// `distance` at configuration `q` (an SRDF's pairs "in collision by
    /// default", such as fingers closed on each other), and returns them.
    ///
    /// # Errors
    /// [`ChainError::WrongDof`], [`ChainError::NonFiniteCoordinate`] and
    /// [`ChainError::InvalidParameter`] for a negative or non-finite distance.
    pub fn allow_collisions_at(
        &mut self,
        q: &[T],
        distance: T,
    ) -> Result<Vec<(usize, usize)>, ChainError> {
        if !(distance >= T::ZERO && distance.is_finite()) {
            return Err(ChainError::InvalidParameter(
                "distance must be non-negative and finite",
            ));
        }
        let pairs: Vec<(usize, usize)> = self
            .touching_pairs(q, distance, false)?
            .into_iter()
            .filter_map(|p| match p {
                ChainPair::SelfCollision { a, b } => Some((a, b)),
                _ => None,
            })
            .collect();
        for &(a, b) in &pairs {
            self.allow_collision(a, b);
        }
        Ok(pairs)
    }

    /// The checked pairs with a triangle pair within `distance` at `q`
    /// (computed distances); the first one only when `first`.
    fn touching_pairs(
        &self,
        q: &[T],
        distance: T,
        first: bool,
    ) -> Result<Vec<ChainPair>, ChainError> {
        let mut out = Vec::new();
        let mut stats = ChainStats::default();
        let shapes = &self.shapes;
        self.each_checked_pair_at(q, |p, stack| {
            // Node pairs whose certified gap exceeds the distance are not refined.
            let cap = distance + T::ETA_NORMAL + T::TWO * (p.a.delta + p.b.delta);
            let near = placed_gap(&p, shapes, cap, distance, stack, &mut stats);
            if near.closest.is_some_and(|(d, _, _)| d <= distance) {
                out.push(p.pair);
                if first {
                    return ControlFlow::Break(());
                }
            }
            ControlFlow::Continue(())
        })?;
        Ok(out)
    }

    /// Runs `f` on each checked pair with the chain still at configuration
    /// `q` (both sides' motions with rate zero), with the descent's stack,
    /// until it breaks.
    fn each_checked_pair_at(
        &self,
        q: &[T],
        mut f: impl FnMut(PlacedPair<'_, T>, &mut Vec<(u32, u32)>) -> ControlFlow<()>,
    ) -> Result<(), ChainError> {
        self.chain.check_q(q)?;
        let segment = self.segment_view(q, q);
        let mut work = Work::default();
        work.errors.compute(&self.chain, q, q);
        segment.place(&mut work, T::ZERO);
        work.rate = vec![T::ZERO; self.chain.dofs];
        for (pair, checked) in self.pairs() {
            let Some(tree) = self.chain.links[first_link(pair)].tree.as_ref() else {
                continue;
            };
            if !checked {
                continue;
            }
            let tb = segment.trees(pair).map(|t| t.1);
            segment.fill_motions(&mut work, pair, T::ZERO);
            let (Some(a), Some(b)) = (&work.a, &work.b) else {
                continue;
            };
            let placed = PlacedPair {
                pair,
                ta: &tree.whole,
                tb,
                a,
                b,
            };
            if f(placed, &mut work.stack).is_break() {
                break;
            }
        }
        Ok(())
    }

    /// The scene along the segment from `q0` to `q1`.
    fn segment_view<'a>(&'a self, q0: &'a [T], q1: &'a [T]) -> Segment<'a, T> {
        Segment {
            chain: &self.chain,
            obstacles: &self.obstacles,
            params: &self.params,
            q0,
            q1,
        }
    }
}

/// Checks many edges of one scene ([`ChainScene::edge_checker`]), reusing
/// its buffers: what a planner keeps for its motion validator.
#[derive(Clone, Debug)]
pub struct EdgeChecker<'s, T: 'static> {
    scene: &'s ChainScene<T>,
    initial: Vec<Item>,
    /// The motion slots: a link and how many of its path's joints skipped.
    slots: Vec<(usize, usize)>,
    /// Each link's convex hull (Lemma 13.7).
    hulls: Vec<Option<ConvexPolytope<'s, T>>>,
    /// Each mesh obstacle's convex hull, placed (Lemma 13.8).
    obstacle_hulls: Vec<Option<ConvexPolytope<'s, T>>>,
    work: EdgeWork<T>,
    rake: RakeWork,
}

impl<T: Float> EdgeChecker<'_, T> {
    /// [`ChainScene::check_edge`] with this checker's buffers.
    ///
    /// # Errors
    /// As [`ChainScene::check_segment`].
    pub fn check(&mut self, q0: &[T], q1: &[T]) -> Result<EdgeReport<T>, ChainError> {
        self.run(q0, q1, true)
    }

    /// The query: the first contact when `first_contact`, else any.
    fn run(
        &mut self,
        q0: &[T],
        q1: &[T],
        first_contact: bool,
    ) -> Result<EdgeReport<T>, ChainError> {
        let scene = self.scene;
        scene.check_end(q0)?;
        scene.check_end(q1)?;
        let edge = Edge {
            segment: scene.segment_view(q0, q1),
            shapes: &scene.shapes,
            hulls: &self.hulls,
            obstacle_hulls: &self.obstacle_hulls,
            touch: scene.params.contact_distance + scene.params.padding,
            padding: scene.params.padding,
            budget: scene.params.edge_budget,
            first_contact,
        };
        if scene.params.rake && q0 != q1 && scene.params.edge_budget >= RAKE_MIN_BUDGET {
            let rake = Rake {
                chain: &scene.chain,
                model: &scene.rake,
                shapes: &scene.shapes,
                obstacles: &scene.obstacles,
                padding: scene.params.padding.to_f64(),
                sweep: scene.rake.sweep,
                sweep_scale: 1.0,
            };
            if rake.run(
                q0,
                q1,
                &self.initial,
                &self.slots,
                !first_contact,
                &mut self.rake,
            ) {
                let r = &self.rake;
                return Ok(edge.run_spans(
                    &self.initial,
                    &r.fails,
                    (r.times_count, r.tests),
                    &self.slots,
                    &mut self.work,
                ));
            }
        }
        Ok(edge.run(&self.initial, &self.slots, &mut self.work))
    }

    /// The rake alone on `q0 -> q1` with its sweeps scaled by `sweep_scale`
    /// (1 as the queries run it) and sub-intervals picked for `sweep` times
    /// the scene's sweep: the (sub-interval, item) pairs it does not clear,
    /// the number of sub-intervals, and the items (for tests).
    #[cfg(test)]
    #[allow(clippy::type_complexity)]
    pub(super) fn rake_only(
        &mut self,
        q0: &[T],
        q1: &[T],
        sweep_scale: f64,
        sweep: f64,
    ) -> Option<(Vec<(u32, u32, u32)>, u32, Vec<Item>)> {
        let scene = self.scene;
        let rake = Rake {
            chain: &scene.chain,
            model: &scene.rake,
            shapes: &scene.shapes,
            obstacles: &scene.obstacles,
            padding: scene.params.padding.to_f64(),
            sweep: scene.rake.sweep * sweep,
            sweep_scale,
        };
        rake.run(q0, q1, &self.initial, &self.slots, true, &mut self.rake)
            .then(|| {
                (
                    self.rake.fails.clone(),
                    self.rake.times_count,
                    self.initial.clone(),
                )
            })
    }

    /// [`ChainScene::collides_at`] with this checker's buffers: the pair
    /// found touching at `q`, if any.
    ///
    /// # Errors
    /// [`ChainError::WrongDof`] and [`ChainError::NonFiniteCoordinate`].
    pub fn touching_at(&mut self, q: &[T]) -> Result<Option<ChainPair>, ChainError> {
        let scene = self.scene;
        scene.chain.check_q(q)?;
        let edge = Edge {
            segment: scene.segment_view(q, q),
            shapes: &scene.shapes,
            hulls: &self.hulls,
            obstacle_hulls: &self.obstacle_hulls,
            touch: scene.params.padding,
            padding: scene.params.padding,
            budget: usize::MAX,
            first_contact: true,
        };
        Ok(edge.static_check(&self.initial, &self.slots, &mut self.work))
    }

    /// Whether some checked pair touches at `q` ([`touching_at`](Self::touching_at)).
    ///
    /// # Errors
    /// [`ChainError::WrongDof`] and [`ChainError::NonFiniteCoordinate`].
    pub fn collides_at(&mut self, q: &[T]) -> Result<bool, ChainError> {
        Ok(self.touching_at(q)?.is_some())
    }

    /// [`ChainScene::edge_is_free`] with this checker's buffers.
    ///
    /// # Errors
    /// As [`ChainScene::check_segment`].
    pub fn is_free(&mut self, q0: &[T], q1: &[T]) -> Result<bool, ChainError> {
        Ok(self.check_any(q0, q1)?.outcome.is_free())
    }

    /// [`check`](Self::check) for a yes-or-no answer: the intervals are
    /// taken coarsest first, so a contact anywhere on the edge ends the
    /// query as soon as a sampling shows it (a planner's colliding edges
    /// cost least). The contact reported need not be the first: the
    /// segment is certified free only up to `free_until`, the earliest time
    /// not yet cleared.
    ///
    /// # Errors
    /// As [`ChainScene::check_segment`].
    pub fn check_any(&mut self, q0: &[T], q1: &[T]) -> Result<EdgeReport<T>, ChainError> {
        self.run(q0, q1, false)
    }
}
