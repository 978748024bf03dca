//! Conservative advancement of a chain along joint-space segments against
//! still obstacles and itself.

use alloc::collections::BTreeSet;
use alloc::string::String;
use alloc::vec;
use alloc::vec::Vec;

use crate::bvh::Hierarchy;
use crate::chain::bound::{LinkErrors, LinkMotion};
use crate::chain::model::{Chain, ChainError, JointFrame};
use crate::geometry::closest::triangle_triangle_vec;
use crate::rounding::{advance_down, gamma, gap_down, step_down, sum_reaches};
use crate::{BallTree, Float, Point3, Pose, TriMesh, Vec3};

/// A still body of the chain's surroundings: a mesh (its ball tree) placed
/// in the world.
#[derive(Clone, Debug)]
pub struct Obstacle<T> {
    name: String,
    mesh: TriMesh<T>,
    tree: BallTree<T>,
    pose: Pose<T>,
    /// `|x| + reach`, the magnitude of every placed point.
    reach: T,
    /// The placement's rounding (`gamma_4` of `reach`).
    delta: T,
}

impl<T: Float> Obstacle<T> {
    /// An obstacle from its mesh (in its own frame; its ball tree is built
    /// here, once) and its world pose.
    ///
    /// # Errors
    /// [`ChainError::InvalidParameter`] for a pose that is not finite or
    /// whose rotation has an entry beyond 2 (not a rotation);
    /// [`ChainError::Mesh`] for a mesh a ball tree cannot be built on.
    pub fn try_new(
        name: impl Into<String>,
        mesh: TriMesh<T>,
        pose: Pose<T>,
    ) -> Result<Self, ChainError> {
        if !pose.is_finite()
            || pose.translation.max_abs() > T::MAX_INPUT
            || pose.rotation_max_abs() > T::TWO
        {
            return Err(ChainError::InvalidParameter("an obstacle's pose"));
        }
        let name = name.into();
        let tree = BallTree::try_from_mesh(&mesh)
            .map_err(|e| ChainError::Mesh(alloc::format!("obstacle {name:?}: {e}")))?;
        let reach = (pose.translation.length() + tree.whole.reach) * (T::ONE + gamma::<T>(4));
        let delta = gamma::<T>(8) * reach + T::from_u32(4) * T::ETA_NORMAL;
        Ok(Self {
            name,
            mesh,
            tree,
            pose,
            reach: reach + delta,
            delta,
        })
    }

    /// The obstacle's name.
    #[must_use]
    pub fn name(&self) -> &str {
        &self.name
    }

    /// Its mesh, in its own frame.
    #[must_use]
    pub fn mesh(&self) -> &TriMesh<T> {
        &self.mesh
    }

    /// Its ball tree.
    #[must_use]
    pub fn tree(&self) -> &BallTree<T> {
        &self.tree
    }

    /// Its world pose.
    #[must_use]
    pub fn pose(&self) -> Pose<T> {
        self.pose
    }
}

/// What a query reports touching: a link and an obstacle, or two links.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ChainPair {
    /// Link `link` and obstacle `obstacle` (indices).
    Obstacle {
        /// The link's index.
        link: usize,
        /// The obstacle's index.
        obstacle: usize,
    },
    /// Two links (`a < b`).
    SelfCollision {
        /// The first link's index.
        a: usize,
        /// The second link's index.
        b: usize,
    },
}

/// The first contact found on a segment.
#[derive(Clone, Copy, Debug, PartialEq)]
#[non_exhaustive]
pub struct ChainContact<T> {
    /// The time in `[0, 1]` along the segment: never later than the first
    /// time the pair's surfaces touch.
    pub time: T,
    /// Which pair.
    pub pair: ChainPair,
    /// The computed distance between the closest triangles found (at most
    /// the contact distance).
    pub distance: T,
    /// The witness point on the link (or the first link), in the world.
    pub on_a: Point3<T>,
    /// The witness point on the obstacle (or the second link), in the world.
    pub on_b: Point3<T>,
}

/// What a segment query found.
#[derive(Clone, Copy, Debug, PartialEq)]
#[non_exhaustive]
pub enum SegmentOutcome<T> {
    /// The first contact.
    Contact(ChainContact<T>),
    /// No pair touches over the whole segment (certified).
    Separated,
    /// A pair needed more than [`ChainParams::max_iterations`] steps: no
    /// contact before `time` is certified, nothing after it.
    IterationLimit {
        /// The time up to which the segment is certified free.
        time: T,
        /// The pair that ran out.
        pair: ChainPair,
    },
}

impl<T> SegmentOutcome<T> {
    /// The contact, if any.
    #[must_use]
    pub const fn contact(&self) -> Option<&ChainContact<T>> {
        match self {
            Self::Contact(c) => Some(c),
            _ => None,
        }
    }
}

/// The work a query did, summed over its pairs.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
#[non_exhaustive]
pub struct ChainStats {
    /// Pairs of (link, obstacle) and (link, link) with geometry.
    pub pairs: usize,
    /// Pairs never checked: adjacent links and allowed collisions.
    pub excluded: usize,
    /// Pairs the broad phase (swept balls per sub-interval) showed apart.
    pub culled: usize,
    /// Pairs advanced by conservative advancement.
    pub advanced: usize,
    /// Conservative-advancement iterations over all pairs.
    pub iterations: usize,
    /// Node pairs visited.
    pub node_pairs: usize,
    /// Triangle pairs measured.
    pub leaf_pairs: usize,
}

impl core::ops::AddAssign for ChainStats {
    fn add_assign(&mut self, o: Self) {
        self.pairs += o.pairs;
        self.excluded += o.excluded;
        self.culled += o.culled;
        self.advanced += o.advanced;
        self.iterations += o.iterations;
        self.node_pairs += o.node_pairs;
        self.leaf_pairs += o.leaf_pairs;
    }
}

/// A segment query's answer and work.
#[derive(Clone, Copy, Debug, PartialEq)]
#[non_exhaustive]
pub struct SegmentReport<T> {
    /// What was found.
    pub outcome: SegmentOutcome<T>,
    /// The work done.
    pub stats: ChainStats,
}

/// A path query's answer: the first segment with a contact (or an
/// undecided one), and the work.
#[derive(Clone, Copy, Debug, PartialEq)]
#[non_exhaustive]
pub struct PathReport<T> {
    /// The index of the segment the outcome is on (the last one when the
    /// whole path is separated).
    pub segment: usize,
    /// What was found on it.
    pub outcome: SegmentOutcome<T>,
    /// The work done over the segments checked.
    pub stats: ChainStats,
}

/// A query's parameters.
#[derive(Clone, Copy, Debug, PartialEq)]
#[non_exhaustive]
pub struct ChainParams<T> {
    /// Surfaces this close count as touching (world units; default `1e-3`).
    pub contact_distance: T,
    /// Iterations per pair and segment (default 10,000).
    pub max_iterations: usize,
    /// Sub-intervals of the broad phase's swept balls (1 to 64, default 32).
    pub broad_pieces: usize,
}

impl<T: Float> Default for ChainParams<T> {
    fn default() -> Self {
        Self {
            contact_distance: T::from_f64(1e-3),
            max_iterations: 10_000,
            broad_pieces: 32,
        }
    }
}

impl<T: Float> ChainParams<T> {
    /// With a contact distance.
    #[must_use]
    pub fn with_contact_distance(mut self, d: T) -> Self {
        self.contact_distance = d;
        self
    }

    fn validate(&self) -> Result<(), ChainError> {
        if !(self.contact_distance > T::ZERO && self.contact_distance.is_finite()) {
            return Err(ChainError::InvalidParameter(
                "contact_distance must be positive and finite",
            ));
        }
        if self.max_iterations == 0 || self.broad_pieces == 0 || self.broad_pieces > 64 {
            return Err(ChainError::InvalidParameter(
                "max_iterations and broad_pieces (1 to 64) must be positive",
            ));
        }
        Ok(())
    }
}

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
pub struct ChainScene<T> {
    chain: Chain<T>,
    obstacles: Vec<Obstacle<T>>,
    allowed: BTreeSet<(usize, usize)>,
    params: ChainParams<T>,
    /// For each link, the root of its rigid group (links joined by fixed
    /// joints share one).
    group: Vec<usize>,
}

/// Reusable per-query buffers.
#[derive(Clone, Debug, Default)]
struct Work<T> {
    poses: Vec<Pose<T>>,
    frames: Vec<JointFrame<T>>,
    rate: Vec<T>,
    errors: LinkErrors<T>,
    a: Option<LinkMotion<T>>,
    b: Option<LinkMotion<T>>,
    stack: Vec<(u32, u32)>,
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
            chain,
            obstacles: Vec::new(),
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
    /// checked.
    fn pairs(&self) -> Vec<(ChainPair, bool)> {
        let mut out = Vec::new();
        let n = self.chain.links.len();
        for l in 0..n {
            if self.chain.links[l].tree.is_none() {
                continue;
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
    /// [`ChainError::WrongDof`] and [`ChainError::NonFiniteCoordinate`].
    pub fn check_segment(&self, q0: &[T], q1: &[T]) -> Result<SegmentReport<T>, ChainError> {
        self.chain.check_q(q0)?;
        self.chain.check_q(q1)?;
        let mut work = Work::default();
        Ok(self.segment(q0, q1, &mut work))
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
            self.chain.check_q(q.as_ref())?;
        }
        let mut work = Work::default();
        let mut stats = ChainStats::default();
        for (i, w) in waypoints.windows(2).enumerate() {
            let report = self.segment(w[0].as_ref(), w[1].as_ref(), &mut work);
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
    /// nothing is checked).
    ///
    /// # Errors
    /// [`ChainError::WrongDof`] and [`ChainError::NonFiniteCoordinate`].
    pub fn clearance(&self, q: &[T]) -> Result<(T, Option<ChainPair>), ChainError> {
        self.chain.check_q(q)?;
        let mut work = Work::default();
        work.errors.compute(&self.chain, q, q);
        self.place(&mut work, q, q, T::ZERO);
        work.rate = vec![T::ZERO; self.chain.dofs];
        let mut best = (T::INFINITY, None);
        for (pair, checked) in self.pairs() {
            if !checked {
                continue;
            }
            let Some((ta, tb)) = self.trees(pair) else {
                continue;
            };
            self.fill_motions(&mut work, pair, T::ZERO);
            let (Some(a), Some(b)) = (&work.a, &work.b) else {
                continue;
            };
            let mut stats = ChainStats::default();
            let d = min_gap(
                ta,
                tb,
                a,
                b,
                best.0,
                T::ZERO,
                T::ZERO,
                &mut work.stack,
                &mut stats,
            )
            .gap;
            if d < best.0 {
                best = (d, Some(pair));
            }
        }
        Ok(best)
    }

    /// Whether some checked pair's surfaces meet at configuration `q` (a
    /// triangle pair at computed distance 0): the static check a discrete
    /// motion validator runs at each sample. Stops at the first such pair.
    ///
    /// # Errors
    /// [`ChainError::WrongDof`] and [`ChainError::NonFiniteCoordinate`].
    pub fn collides_at(&self, q: &[T]) -> Result<bool, ChainError> {
        Ok(!self.touching_pairs(q, T::ZERO, true)?.is_empty())
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
                ChainPair::Obstacle { .. } => None,
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
        self.chain.check_q(q)?;
        let mut work = Work::default();
        work.errors.compute(&self.chain, q, q);
        self.place(&mut work, q, q, T::ZERO);
        work.rate = vec![T::ZERO; self.chain.dofs];
        let mut out = Vec::new();
        let mut stats = ChainStats::default();
        for (pair, checked) in self.pairs() {
            if !checked {
                continue;
            }
            let Some((ta, tb)) = self.trees(pair) else {
                continue;
            };
            self.fill_motions(&mut work, pair, T::ZERO);
            let (Some(a), Some(b)) = (&work.a, &work.b) else {
                continue;
            };
            // Node pairs whose certified gap exceeds the distance are not refined.
            let cap = distance + T::ETA_NORMAL + T::TWO * (a.delta + b.delta);
            let near = min_gap(
                ta,
                tb,
                a,
                b,
                cap,
                T::ZERO,
                distance,
                &mut work.stack,
                &mut stats,
            );
            if near.closest.is_some_and(|(d, _, _)| d <= distance) {
                out.push(pair);
                if first {
                    break;
                }
            }
        }
        Ok(out)
    }

    fn place(&self, work: &mut Work<T>, q0: &[T], q1: &[T], t: T) {
        let n = self.chain.links.len();
        work.poses.resize(n, Pose::IDENTITY);
        work.frames.resize(
            self.chain.joints.len(),
            JointFrame {
                axis: Vec3::ZERO,
                point: Vec3::ZERO,
            },
        );
        self.chain.place(
            |d| q0[d] + t * (q1[d] - q0[d]),
            &mut work.poses,
            &mut work.frames,
        );
    }

    /// The number of movable joints two links' paths share (those move both
    /// rigidly).
    fn common_prefix(&self, a: usize, b: usize) -> usize {
        let (pa, pb) = (&self.chain.links[a].path, &self.chain.links[b].path);
        pa.iter().zip(pb.iter()).take_while(|(x, y)| x == y).count()
    }

    /// The two sides' motions over `[t, t + dt]` (`dt` rounded up by the caller).
    fn fill_motions(&self, work: &mut Work<T>, pair: ChainPair, dt: T) {
        let mut a = work
            .a
            .take()
            .unwrap_or_else(|| LinkMotion::still(Pose::IDENTITY, T::ZERO, T::ZERO));
        let mut b = work
            .b
            .take()
            .unwrap_or_else(|| LinkMotion::still(Pose::IDENTITY, T::ZERO, T::ZERO));
        match pair {
            ChainPair::Obstacle { link, obstacle } => {
                a.fill(
                    &self.chain,
                    link,
                    &work.poses,
                    &work.frames,
                    &work.rate,
                    0,
                    dt,
                    &work.errors,
                );
                let o = &self.obstacles[obstacle];
                b = LinkMotion {
                    terms: b.terms,
                    ..LinkMotion::still(o.pose, o.delta, o.reach)
                };
                b.terms.clear();
            }
            ChainPair::SelfCollision { a: la, b: lb } => {
                let skip = self.common_prefix(la, lb);
                a.fill(
                    &self.chain,
                    la,
                    &work.poses,
                    &work.frames,
                    &work.rate,
                    skip,
                    dt,
                    &work.errors,
                );
                b.fill(
                    &self.chain,
                    lb,
                    &work.poses,
                    &work.frames,
                    &work.rate,
                    skip,
                    dt,
                    &work.errors,
                );
            }
        }
        work.a = Some(a);
        work.b = Some(b);
    }

    /// The two hierarchies of a pair (every pair is made of links with
    /// geometry, so both exist): an obstacle with long triangles (a table,
    /// a pole) is taken in pieces against a link of small triangles; links
    /// are taken whole (a coarse collision mesh cut into pieces against
    /// another link multiplies the work).
    fn trees(&self, pair: ChainPair) -> Option<(&Hierarchy<T>, &Hierarchy<T>)> {
        let tree = |l: usize| self.chain.links[l].tree.as_ref();
        match pair {
            ChainPair::Obstacle { link, obstacle } => {
                let (a, b) = (tree(link)?, &self.obstacles.get(obstacle)?.tree);
                Some((&a.whole, b.against(a)))
            }
            ChainPair::SelfCollision { a, b } => Some((&tree(a)?.whole, &tree(b)?.whole)),
        }
    }

    fn segment(&self, q0: &[T], q1: &[T], work: &mut Work<T>) -> SegmentReport<T> {
        let mut stats = ChainStats::default();
        work.errors.compute(&self.chain, q0, q1);
        work.rate.clear();
        work.rate.extend(
            q0.iter()
                .zip(q1)
                .map(|(a, b)| (*b - *a).abs() * (T::ONE + gamma::<T>(2))),
        );
        let pairs = self.pairs();
        let mut live = self.broad_phase(q0, q1, &pairs, work, &mut stats);
        // Pairs whose swept volumes meet earliest first: an early contact
        // found first ends every later pair's advance there.
        live.sort_by_key(|&(_, mask)| mask.trailing_zeros());
        let k = self.params.broad_pieces;
        let piece_start = |i: usize| T::from_u32(i as u32) / T::from_u32(k as u32);
        let mut best: Option<ChainContact<T>> = None;
        let mut limit: Option<(T, ChainPair)> = None;
        let cd = self.params.contact_distance;
        for (pair, mask) in live {
            let Some((ta, tb)) = self.trees(pair) else {
                continue;
            };
            stats.advanced += 1;
            let until = best.map_or(T::ONE, |c| c.time);
            let mut t = T::ZERO;
            let mut iterations = 0;
            // The bounds hold over `[t, t + h]`: a short horizon keeps them
            // tight (the axes turn and the levers grow with `h`, Lemma 13.2);
            // it doubles while steps reach it and follows them when they do not.
            let mut horizon = T::ONE / T::from_u32(8);
            loop {
                // Skip the broad phase's pieces in which the pair's swept
                // volumes are apart (certified free there).
                let mut piece = (t.to_f64() * k as f64) as usize;
                while piece + 1 < k && t >= piece_start(piece + 1) {
                    piece += 1;
                }
                while piece > 0 && t < piece_start(piece) {
                    piece -= 1;
                }
                if mask >> piece & 1 == 0 {
                    match (piece + 1..k).find(|&i| mask >> i & 1 == 1) {
                        Some(next) => t = piece_start(next),
                        None => break,
                    }
                }
                if t >= until {
                    break;
                }
                if iterations >= self.params.max_iterations {
                    if limit.is_none_or(|(lt, _)| t < lt) {
                        limit = Some((t, pair));
                    }
                    break;
                }
                iterations += 1;
                stats.iterations += 1;
                self.place(work, q0, q1, t);
                let h = horizon.min_nan(until - t);
                self.fill_motions(work, pair, h * (T::ONE + gamma::<T>(2)));
                let (Some(a), Some(b)) = (&work.a, &work.b) else {
                    break;
                };
                let step = advance(ta, tb, a, b, cd, h, &mut work.stack, &mut stats);
                match step {
                    Step::Touching {
                        distance,
                        on_a,
                        on_b,
                    } => {
                        best = Some(ChainContact {
                            time: t,
                            pair,
                            distance,
                            on_a: Point3::from_vec3(on_a),
                            on_b: Point3::from_vec3(on_b),
                        });
                        break;
                    }
                    Step::Advance(s) => {
                        if s == T::INFINITY {
                            // Still: free for the rest of the interval.
                            break;
                        }
                        // The bounds hold over `h` only.
                        let s = s.min_nan(h);
                        if sum_reaches(t, s, until) {
                            break;
                        }
                        let next = advance_down(t, s);
                        if s.is_nan() || s <= T::ZERO || next <= t {
                            // No step the rounding can resolve: undecided here.
                            if limit.is_none_or(|(lt, _)| t < lt) {
                                limit = Some((t, pair));
                            }
                            break;
                        }
                        horizon = if s >= h {
                            horizon * T::TWO
                        } else {
                            (s * T::TWO).max_nan(T::ONE / T::from_u32(1 << 20))
                        };
                        t = next;
                    }
                }
            }
        }
        let outcome = match (best, limit) {
            (Some(c), Some((lt, p))) if lt < c.time => {
                SegmentOutcome::IterationLimit { time: lt, pair: p }
            }
            (Some(c), _) => SegmentOutcome::Contact(c),
            (None, Some((lt, p))) => SegmentOutcome::IterationLimit { time: lt, pair: p },
            (None, None) => SegmentOutcome::Separated,
        };
        SegmentReport { outcome, stats }
    }

    /// The broad phase: each link's root ball swept over `broad_pieces`
    /// sub-intervals (its centre at the piece's start, its radius grown by
    /// the undirected speed bound over the piece and twice the placement
    /// error) against each obstacle's world box and each other link's swept
    /// ball over the same piece. Each live pair comes with the mask of the
    /// pieces in which its volumes may meet.
    fn broad_phase(
        &self,
        q0: &[T],
        q1: &[T],
        pairs: &[(ChainPair, bool)],
        work: &mut Work<T>,
        stats: &mut ChainStats,
    ) -> Vec<(ChainPair, u64)> {
        let k = self.params.broad_pieces;
        let n = self.chain.links.len();
        let cd = self.params.contact_distance;
        // balls[piece][link] = (centre, radius), full-chain bound.
        let mut balls: Vec<Vec<(Vec3<T>, T)>> = Vec::with_capacity(k);
        for piece in 0..k {
            let t0 = T::from_u32(piece as u32) / T::from_u32(k as u32);
            let t1 = T::from_u32(piece as u32 + 1) / T::from_u32(k as u32);
            self.place(work, q0, q1, t0);
            let dt = (t1 - t0) * (T::ONE + gamma::<T>(2));
            let mut row = Vec::with_capacity(n);
            let mut m = work
                .a
                .take()
                .unwrap_or_else(|| LinkMotion::still(Pose::IDENTITY, T::ZERO, T::ZERO));
            for l in 0..n {
                match &self.chain.links[l].tree {
                    Some(tree) => {
                        m.fill(
                            &self.chain,
                            l,
                            &work.poses,
                            &work.frames,
                            &work.rate,
                            0,
                            dt,
                            &work.errors,
                        );
                        let root = &tree.whole.nodes[0].ball;
                        let c = m.pose.transform_point(*root.centre());
                        let (_, speed) =
                            m.ball_speed(c, root.radius(), Vec3::new(T::ONE, T::ZERO, T::ZERO));
                        let r = (root.radius() + speed * dt + T::TWO * m.delta)
                            * (T::ONE + gamma::<T>(4));
                        row.push((c, r));
                    }
                    None => row.push((Vec3::ZERO, T::ZERO)),
                }
            }
            work.a = Some(m);
            balls.push(row);
        }
        // Each obstacle's world box, grown by its placement error.
        let boxes: Vec<(Vec3<T>, Vec3<T>)> = self
            .obstacles
            .iter()
            .map(|o| {
                let mut lo = Vec3::new(T::INFINITY, T::INFINITY, T::INFINITY).to_array();
                let mut hi = Vec3::new(-T::INFINITY, -T::INFINITY, -T::INFINITY).to_array();
                for v in o.mesh.vertices() {
                    let p = o.pose.transform_point(*v).to_array();
                    for d in 0..3 {
                        lo[d] = lo[d].min_nan(p[d]);
                        hi[d] = hi[d].max_nan(p[d]);
                    }
                }
                let e = T::TWO * o.delta;
                (
                    Vec3::from_array(lo.map(|x| x - e)),
                    Vec3::from_array(hi.map(|x| x + e)),
                )
            })
            .collect();
        let apart = |(ca, ra): (Vec3<T>, T), (cb, rb): (Vec3<T>, T)| {
            let d = (cb - ca).length() * (T::ONE - gamma::<T>(4));
            d > (ra + rb + cd) * (T::ONE + gamma::<T>(2))
        };
        let apart_box = |(c, r): (Vec3<T>, T), (lo, hi): (Vec3<T>, Vec3<T>)| {
            let (c, lo, hi) = (c.to_array(), lo.to_array(), hi.to_array());
            let near = [0, 1, 2].map(|d| c[d].max_nan(lo[d]).min_nan(hi[d]));
            let d =
                (Vec3::from_array(c) - Vec3::from_array(near)).length() * (T::ONE - gamma::<T>(4));
            d > (r + cd) * (T::ONE + gamma::<T>(2))
        };
        let mut live = Vec::new();
        for &(pair, checked) in pairs {
            stats.pairs += 1;
            if !checked {
                stats.excluded += 1;
                continue;
            }
            let mut mask = 0u64;
            for (i, row) in balls.iter().enumerate() {
                let meet = match pair {
                    ChainPair::Obstacle { link, obstacle } => {
                        !apart_box(row[link], boxes[obstacle])
                    }
                    ChainPair::SelfCollision { a, b } => !apart(row[a], row[b]),
                };
                if meet {
                    mask |= 1 << i;
                }
            }
            if mask != 0 {
                live.push((pair, mask));
            } else {
                stats.culled += 1;
            }
        }
        live
    }
}

/// The relative slack of both phases' branch and bound: a node pair whose
/// gap (or step) is within this fraction of the best found is not refined,
/// its own certified gap (step) kept instead. Steps come out at most this
/// fraction shorter than the best the balls certify; far fewer nodes are
/// visited when the links are far apart (all node pairs then look alike).
const SLACK: f64 = 0.25;

/// One step's answer for a pair.
enum Step<T> {
    Touching {
        distance: T,
        on_a: Vec3<T>,
        on_b: Vec3<T>,
    },
    Advance(T),
}

/// The centre line of two balls as a computed unit vector, or `None`.
#[inline]
fn unit<T: Float>(v: Vec3<T>) -> Option<Vec3<T>> {
    v.try_normalize()
}

/// The certified gap between two placed balls along their centre line
/// (`gap_down` of the centre distance less the radii).
#[inline]
fn ball_gap<T: Float>(
    ca: Vec3<T>,
    ra: T,
    cb: Vec3<T>,
    rb: T,
    a: &LinkMotion<T>,
    b: &LinkMotion<T>,
) -> T {
    let d = (cb - ca).length();
    gap_down(d - ra - rb, a.delta, b.delta, a.reach + b.reach)
}

/// Conservative advancement's step for one pair over `[t, t + rest]`
/// (Lemma 13.4), in two phases:
///
/// 1. the distance: branch and bound for the smallest certified triangle gap
///    `d` (pruned at what the whole links could close over `rest`); touching
///    when a triangle pair is within `cd`. The step `d / (v_A + v_B)` with the
///    links' undirected speeds (their root balls') is certified for any
///    shapes.
/// 2. when that falls short of `rest`, the directed step: both trees
///    descended, a node pair pruned when its own certified directed step is
///    at least the best found, triangle pairs stepped along their witness
///    direction; given up (keeping phase 1's step) past a work budget. The
///    larger of two certified steps is certified.
#[allow(clippy::too_many_arguments)]
fn advance<T: Float>(
    ta: &Hierarchy<T>,
    tb: &Hierarchy<T>,
    a: &LinkMotion<T>,
    b: &LinkMotion<T>,
    cd: T,
    rest: T,
    stack: &mut Vec<(u32, u32)>,
    stats: &mut ChainStats,
) -> Step<T> {
    let (ra0, rb0) = (&ta.nodes[0].ball, &tb.nodes[0].ball);
    let ca0 = a.pose.transform_point(*ra0.centre());
    let cb0 = b.pose.transform_point(*rb0.centre());
    let x = Vec3::new(T::ONE, T::ZERO, T::ZERO);
    let (_, va) = a.ball_speed(ca0, ra0.radius(), x);
    let (_, vb) = b.ball_speed(cb0, rb0.radius(), x);
    if va + vb <= T::ZERO {
        // Nothing of either moves: one distance decides the whole interval.
        let near = min_gap(ta, tb, a, b, cd + cd, T::ZERO, cd, stack, stats);
        return match near.closest {
            Some((distance, on_a, on_b)) if distance.is_nan() || distance <= cd => Step::Touching {
                distance,
                on_a,
                on_b,
            },
            _ => Step::Advance(T::INFINITY),
        };
    }
    // Gaps beyond what both links can close over `rest` need no refining.
    let cap = ((va + vb) * rest * (T::ONE + gamma::<T>(4))).max_nan(cd) + cd;
    let before = stats.node_pairs;
    let near = min_gap(ta, tb, a, b, cap, T::from_f64(SLACK), cd, stack, stats);
    if let Some((distance, on_a, on_b)) = near.closest {
        if distance.is_nan() || distance <= cd {
            return Step::Touching {
                distance,
                on_a,
                on_b,
            };
        }
    }
    let floor = step_down(near.gap, T::ZERO, va, vb);
    if floor >= rest {
        return Step::Advance(rest);
    }
    let budget = stats.node_pairs - before + 256;
    let mut visited = 0usize;
    let mut best = rest;
    let mut kept = T::INFINITY;
    let keep = T::ONE - T::from_f64(SLACK);
    stack.clear();
    stack.push((0, 0));
    while let Some((ia, ib)) = stack.pop() {
        visited += 1;
        if visited > budget {
            stats.node_pairs += visited;
            return Step::Advance(floor);
        }
        let (na, nb) = (&ta.nodes[ia as usize], &tb.nodes[ib as usize]);
        let ca = a.pose.transform_point(*na.ball.centre());
        let cb = b.pose.transform_point(*nb.ball.centre());
        let (ra, rb) = (na.ball.radius(), nb.ball.radius());
        let g = ball_gap(ca, ra, cb, rb, a, b);
        if g > T::ZERO {
            let n = unit(cb - ca).unwrap_or(x);
            let (mu_a, _) = a.ball_speed(ca, ra, n);
            let (mu_b, _) = b.ball_speed(cb, rb, n);
            let s = step_down(g, T::ZERO, mu_a, mu_b);
            if s >= best {
                continue;
            }
            if s >= best * keep {
                kept = kept.min_nan(s);
                continue;
            }
        }
        match (na.leaf(), nb.leaf()) {
            (Some(la), Some(lb)) => {
                stats.leaf_pairs += 1;
                let pa = ta.leaves[la].corners.map(|p| a.pose.transform_point(p));
                let pb = tb.leaves[lb].corners.map(|p| b.pose.transform_point(p));
                // The slab gap along the leaf balls' centre line (cheap; the
                // exact distance's direction would give a longer step).
                let inflate = ta.leaves[la].inflate + tb.leaves[lb].inflate;
                let g = slab_gap(&pa, &pb, cb - ca, a, b, inflate);
                let n = unit(cb - ca).unwrap_or(x);
                let (mu_a, _) = a.ball_speed(ca, ra, n);
                let (mu_b, _) = b.ball_speed(cb, rb, n);
                let s = step_down(g, T::ZERO, mu_a, mu_b);
                if s < best {
                    best = s;
                    if best.min_nan(kept) <= floor {
                        // Phase 1's step is as good: stop here.
                        stats.node_pairs += visited;
                        return Step::Advance(floor);
                    }
                }
            }
            (None, Some(_)) => push_children(stack, na, &ta.nodes, &a.pose, cb, ia, ib, true),
            (Some(_), None) => push_children(stack, nb, &tb.nodes, &b.pose, ca, ia, ib, false),
            (None, None) => {
                if ra >= rb {
                    push_children(stack, na, &ta.nodes, &a.pose, cb, ia, ib, true);
                } else {
                    push_children(stack, nb, &tb.nodes, &b.pose, ca, ia, ib, false);
                }
            }
        }
    }
    stats.node_pairs += visited;
    Step::Advance(best.min_nan(kept).max_nan(floor))
}

/// Pushes the children of the node of the larger ball (of A when
/// `on_a`), the one whose ball centre is nearer the other node's centre last
/// (taken first: a small step is found early and prunes the rest).
#[inline]
#[allow(clippy::too_many_arguments)]
fn push_children<T: Float>(
    stack: &mut Vec<(u32, u32)>,
    node: &crate::bvh::Node<T>,
    children: &[crate::bvh::Node<T>],
    pose: &Pose<T>,
    other: Vec3<T>,
    ia: u32,
    ib: u32,
    on_a: bool,
) {
    let d = |i: u32| {
        let c = pose.transform_point(*children[i as usize].ball.centre());
        (c - other).length() - children[i as usize].ball.radius()
    };
    let (near, far) = if d(node.left) <= d(node.right) {
        (node.left, node.right)
    } else {
        (node.right, node.left)
    };
    if on_a {
        stack.push((far, ib));
        stack.push((near, ib));
    } else {
        stack.push((ia, far));
        stack.push((ia, near));
    }
}

/// The certified gap of two placed triangles along the computed direction
/// `d` (from A towards B): `min_B q.n - max_A p.n`, less the rounding and
/// the pieces' `inflate`
/// (`gap_down`); `-inf` for a zero direction.
fn slab_gap<T: Float>(
    pa: &[Vec3<T>; 3],
    pb: &[Vec3<T>; 3],
    d: Vec3<T>,
    a: &LinkMotion<T>,
    b: &LinkMotion<T>,
    inflate: T,
) -> T {
    let Some(n) = d.try_normalize() else {
        return -T::INFINITY;
    };
    let hi_a = pa.iter().map(|p| p.dot(n)).fold(-T::INFINITY, T::max_nan);
    let lo_b = pb.iter().map(|p| p.dot(n)).fold(T::INFINITY, T::min_nan);
    // A piece's exact points lie within `inflate` of its corners' triangle:
    // taken with the placement error, as `gap_down` rounds it.
    gap_down(lo_b - hi_a, a.delta + inflate, b.delta, a.reach + b.reach)
}

/// What the distance phase found: a certified lower bound of the distance
/// (or of `cap`, when everything is farther), and the closest triangle pair
/// measured (its computed distance and witnesses).
struct Near<T> {
    gap: T,
    closest: Option<(T, Vec3<T>, Vec3<T>)>,
}

/// The smallest certified gap over triangle pairs (branch and bound on the
/// balls; node pairs at least `cap` apart are not refined).
#[allow(clippy::too_many_arguments)]
fn min_gap<T: Float>(
    ta: &Hierarchy<T>,
    tb: &Hierarchy<T>,
    a: &LinkMotion<T>,
    b: &LinkMotion<T>,
    cap: T,
    slack: T,
    cap_touch: T,
    stack: &mut Vec<(u32, u32)>,
    stats: &mut ChainStats,
) -> Near<T> {
    let mut best = cap;
    // The least gap of the node pairs left unrefined within the slack.
    let mut kept = T::INFINITY;
    let keep = T::ONE - slack;
    let mut closest: Option<(T, Vec3<T>, Vec3<T>)> = None;
    stack.clear();
    stack.push((0, 0));
    while let Some((ia, ib)) = stack.pop() {
        stats.node_pairs += 1;
        let (na, nb) = (&ta.nodes[ia as usize], &tb.nodes[ib as usize]);
        let ca = a.pose.transform_point(*na.ball.centre());
        let cb = b.pose.transform_point(*nb.ball.centre());
        let (ra, rb) = (na.ball.radius(), nb.ball.radius());
        let g = ball_gap(ca, ra, cb, rb, a, b);
        if g >= best {
            continue;
        }
        if slack > T::ZERO && g >= best * keep && g > T::ZERO {
            kept = kept.min_nan(g);
            continue;
        }
        match (na.leaf(), nb.leaf()) {
            (Some(la), Some(lb)) => {
                stats.leaf_pairs += 1;
                let pa = ta.leaves[la].corners.map(|p| a.pose.transform_point(p));
                let pb = tb.leaves[lb].corners.map(|p| b.pose.transform_point(p));
                // A piece's exact points are within `inflate` of its corners' triangle.
                let inflate =
                    (ta.leaves[la].inflate + tb.leaves[lb].inflate) * (T::ONE + T::UNIT_ROUNDOFF);
                // First the cheap slab gap along the balls' centre line: a
                // pair it shows farther than the contact distance, and within
                // the slack of the best, needs no exact distance.
                let g0 = slab_gap(&pa, &pb, cb - ca, a, b, inflate);
                if g0 >= best {
                    continue;
                }
                if slack > T::ZERO && g0 > cap_touch && g0 >= best * keep {
                    kept = kept.min_nan(g0);
                    continue;
                }
                let cp = triangle_triangle_vec(&pa, &pb);
                let distance = cp.distance - inflate;
                if closest.is_none_or(|(d, _, _)| distance < d) {
                    closest = Some((distance, cp.on_a, cp.on_b));
                }
                let g = slab_gap(&pa, &pb, cp.on_b - cp.on_a, a, b, inflate).min_nan(distance);
                let g = if g.is_nan() { -T::INFINITY } else { g };
                if g < best {
                    best = g;
                }
            }
            (None, Some(_)) => push_children(stack, na, &ta.nodes, &a.pose, cb, ia, ib, true),
            (Some(_), None) => push_children(stack, nb, &tb.nodes, &b.pose, ca, ia, ib, false),
            (None, None) => {
                if ra >= rb {
                    push_children(stack, na, &ta.nodes, &a.pose, cb, ia, ib, true);
                } else {
                    push_children(stack, nb, &tb.nodes, &b.pose, ca, ia, ib, false);
                }
            }
        }
    }
    Near {
        gap: best.min_nan(kept),
        closest,
    }
}
