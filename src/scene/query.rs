//! The scene, its workspace and its report.

use alloc::vec::Vec;
use core::fmt;

use super::body::{BodyShape, Groups, SceneBody};
use super::broad::{overlapping_pairs, BoxPath, SweptBox};
use crate::ca::{
    time_of_impact, AnyPair, BallPair, CaError, CaParams, CaReport, ConvexPair, MeshPair,
    MeshParams, MeshWorkspace, Shape,
};
use crate::{
    BoundingBall, Convex, Float, InputError, Isometry, RigidMotion, TimeInterval, Vec3, VertexSet,
};

/// What went wrong building or querying a scene.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub enum SceneQueryError {
    /// A body's shape, motion or pose was rejected.
    Input(InputError),
    /// The query's parameters were rejected.
    Ca(CaError),
    /// A body's motion is over another interval than the scene's frame.
    IntervalMismatch {
        /// The body.
        body: usize,
    },
    /// No body of that number.
    UnknownBody(usize),
}

impl fmt::Display for SceneQueryError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Input(e) => write!(f, "invalid input: {e}"),
            Self::Ca(e) => write!(f, "{e}"),
            Self::IntervalMismatch { body } => {
                write!(
                    f,
                    "body {body} moves over another interval than the scene's frame"
                )
            }
            Self::UnknownBody(b) => write!(f, "no body {b}"),
        }
    }
}

impl core::error::Error for SceneQueryError {}

impl From<InputError> for SceneQueryError {
    fn from(e: InputError) -> Self {
        Self::Input(e)
    }
}

impl From<CaError> for SceneQueryError {
    fn from(e: CaError) -> Self {
        Self::Ca(e)
    }
}

/// The parameters of a scene query: those of every pair's
/// conservative-advancement query, and the mesh traversal's knobs.
///
/// ```
/// use motion_bound::ca::CaParams;
/// use motion_bound::scene::SceneParams;
/// let p = SceneParams::<f64>::default().with_ca(CaParams::default().with_contact_distance(1e-3));
/// assert_eq!(p.ca.contact_distance, 1e-3);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
#[non_exhaustive]
pub struct SceneParams<T> {
    /// Every pair's query parameters; the contact distance also widens the
    /// broad phase (boxes closer than it are kept).
    pub ca: CaParams<T>,
    /// The mesh traversal's knobs.
    pub mesh: MeshParams<T>,
}

impl<T: Float> Default for SceneParams<T> {
    fn default() -> Self {
        Self {
            ca: CaParams::default(),
            mesh: MeshParams::default(),
        }
    }
}

impl<T: Float> SceneParams<T> {
    /// With the pairs' query parameters `ca`.
    #[must_use]
    pub const fn with_ca(mut self, ca: CaParams<T>) -> Self {
        self.ca = ca;
        self
    }

    /// With the mesh traversal's knobs `mesh`.
    #[must_use]
    pub const fn with_mesh(mut self, mesh: MeshParams<T>) -> Self {
        self.mesh = mesh;
        self
    }

    /// Checks both parameter sets.
    ///
    /// # Errors
    /// [`CaError::InvalidParameter`] naming the first parameter out of range.
    pub fn validate(&self) -> Result<(), CaError> {
        self.ca.validate()?;
        self.mesh.validate()
    }
}

/// The outcome of one pair that the broad phase kept.
#[derive(Clone, Copy, Debug, PartialEq)]
#[non_exhaustive]
pub struct PairReport<T> {
    /// The first body (the lower number).
    pub a: usize,
    /// The second body.
    pub b: usize,
    /// The pair's conservative-advancement report: its first contact (time,
    /// witnesses, normal from `a` to `b`), or `Separated`.
    pub report: CaReport<T>,
    /// Node pairs visited (mesh pairs; 0 otherwise).
    pub node_pairs: u64,
}

/// What a scene query did, and what it skipped (each count for the last
/// query).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
#[non_exhaustive]
pub struct SceneStats {
    /// Bodies in the scene.
    pub bodies: usize,
    /// Bodies that do not move (`v = 0`, `w = 0`): no rate at all.
    pub static_bodies: usize,
    /// Bodies that move without turning (`w = 0`): the translation-only path,
    /// exact velocities for their boxes, no arc.
    pub translating_bodies: usize,
    /// Bodies that turn: six one-sided ball rates for their boxes.
    pub turning_bodies: usize,
    /// Half-space bodies (tested by their plane, not in the sweep; counted
    /// among the static bodies when they do not move).
    pub half_spaces: usize,
    /// Axis rates evaluated for the swept boxes (six per turning body).
    pub box_rates: usize,
    /// Axis rates skipped (six per static or translating body).
    pub box_rates_skipped: usize,
    /// All pairs of bodies, `n (n - 1) / 2`.
    pub pairs_all: u64,
    /// Pairs of two static bodies: never a query.
    pub pairs_static: u64,
    /// Pairs of two half-spaces, not both static: never a query.
    pub pairs_of_half_spaces: u64,
    /// Pairs whose swept boxes are apart: provably no contact in the frame.
    pub pairs_culled: u64,
    /// Pairs the caller's filter or the bodies' groups excluded (counted
    /// among the pairs the broad phase kept).
    pub pairs_filtered: u64,
    /// Pairs sent to the narrow phase.
    pub pairs_tested: u64,
    /// Conservative-advancement iterations over the tested pairs.
    pub iterations: u64,
    /// Convex-pair steps where the automatic policy took NEVQ alone (NEVQ's
    /// step already ends the query, or neither body turns).
    pub evq_skipped: u64,
    /// Convex-pair steps where it evaluated EVQ as well.
    pub evq_evaluated: u64,
}

/// The answer to a scene query, kept in the [`SceneWorkspace`].
#[derive(Clone, Debug, Default)]
pub struct SceneReport<T> {
    pairs: Vec<PairReport<T>>,
    earliest: Vec<Option<(T, usize)>>,
    stats: SceneStats,
}

impl<T: Float> SceneReport<T> {
    /// Every pair the broad phase kept and the filter passed, in increasing
    /// order of `(a, b)`, with its outcome. A pair not listed provably does
    /// not come within the contact distance during the frame (or was
    /// excluded by the filter, or is of two static bodies).
    #[must_use]
    pub fn pairs(&self) -> &[PairReport<T>] {
        &self.pairs
    }

    /// The pairs that report a contact (or could not rule one out: an
    /// iteration limit), in pair order.
    pub fn contacts(&self) -> impl Iterator<Item = &PairReport<T>> {
        self.pairs
            .iter()
            .filter(|p| p.report.outcome.earliest_possible_contact().is_some())
    }

    /// The earliest possible contact of `body` with any other body: the time
    /// and the other body (the first in pair order among equal times).
    #[must_use]
    pub fn earliest_for(&self, body: usize) -> Option<(T, usize)> {
        self.earliest.get(body).copied().flatten()
    }

    /// The pair with the earliest possible contact over the scene (the first
    /// in pair order among equal times).
    #[must_use]
    pub fn earliest(&self) -> Option<&PairReport<T>> {
        let mut best: Option<(T, &PairReport<T>)> = None;
        for p in &self.pairs {
            if let Some(t) = p.report.outcome.earliest_possible_contact() {
                if best.is_none_or(|(b, _)| t < b) {
                    best = Some((t, p));
                }
            }
        }
        best.map(|(_, p)| p)
    }

    /// What the query did and skipped.
    #[must_use]
    pub const fn stats(&self) -> SceneStats {
        self.stats
    }
}

/// The scratch space and the answer of scene queries: keep one across frames
/// and a query allocates nothing once the vectors have grown to the scene's
/// size (the serial query; the parallel one allocates per thread).
#[derive(Debug)]
pub struct SceneWorkspace<T> {
    boxes: Vec<SweptBox<T>>,
    skip: Vec<bool>,
    order: Vec<(T, u32)>,
    overlapping: Vec<(u32, u32)>,
    candidates: Vec<(u32, u32)>,
    mesh: MeshWorkspace<T>,
    report: SceneReport<T>,
}

impl<T: Float> Default for SceneWorkspace<T> {
    fn default() -> Self {
        Self::new()
    }
}

impl<T: Float> SceneWorkspace<T> {
    /// An empty workspace.
    #[must_use]
    pub fn new() -> Self {
        Self {
            boxes: Vec::new(),
            skip: Vec::new(),
            order: Vec::new(),
            overlapping: Vec::new(),
            candidates: Vec::new(),
            mesh: MeshWorkspace::new(),
            report: SceneReport {
                pairs: Vec::new(),
                earliest: Vec::new(),
                stats: SceneStats::default(),
            },
        }
    }

    /// The last query's answer.
    #[must_use]
    pub const fn report(&self) -> &SceneReport<T> {
        &self.report
    }

    /// Each body's swept box, from the last broad phase.
    #[must_use]
    pub fn swept_boxes(&self) -> &[SweptBox<T>] {
        &self.boxes
    }

    /// The pairs the last broad phase kept for the narrow phase, in order.
    pub fn candidates(&self) -> impl Iterator<Item = (usize, usize)> + '_ {
        self.candidates
            .iter()
            .map(|&(a, b)| (a as usize, b as usize))
    }
}

/// Many bodies moving over one frame, and the query that finds every pair's
/// first contact while skipping what cannot touch.
///
/// A query runs in two phases. The **broad phase** computes each body's
/// certified swept box ([`SweptBox`]) once, and a sweep and prune keeps the
/// pairs whose boxes come within the contact distance (pairs of two static
/// bodies are never kept); the caller's filter and the bodies' [`Groups`]
/// then drop pairs the engine excludes. The **narrow phase** runs
/// conservative advancement on each kept pair with the stepper of its shapes
/// ([`MeshPair`], [`ConvexPair`] with GJK, [`BallPair`]), reusing one mesh
/// workspace. Every skip is sound (`proofs/11-scene.md`) and counted in
/// [`SceneStats`].
///
/// ```
/// use motion_bound::scene::{BodyShape, Scene, SceneParams, SceneWorkspace};
/// use motion_bound::{BoundingBall, Isometry, RigidMotion, TimeInterval, Vec3};
/// let ball = BodyShape::Ball(BoundingBall::try_new([0.0; 3], 0.5)?);
/// let mut scene = Scene::try_new(TimeInterval::try_new(0.0, 1.0)?)?;
/// // A ball flying at a static one, and a third far away.
/// let a = scene.try_add(ball, RigidMotion::try_from_arrays([-3.0, 0.0, 0.0], [4.0, 0.0, 0.0], [0.0; 3])?)?;
/// let b = scene.try_add_static(ball, Isometry::try_from_translation(Vec3::new(0.0, 0.0, 0.0))?)?;
/// let _far = scene.try_add(ball, RigidMotion::try_from_arrays([0.0, 50.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 3.0])?)?;
/// let mut ws = SceneWorkspace::new();
/// let report = scene.query(&mut ws, &SceneParams::default())?;
/// assert_eq!(report.pairs().len(), 1); // the far ball was culled
/// let (t, other) = report.earliest_for(a).unwrap();
/// assert_eq!(other, b);
/// assert!(t <= 0.5 && t > 0.5 - 1e-4); // the balls touch at t = 2 / 4
/// assert_eq!(report.stats().pairs_culled, 2);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Clone, Debug)]
pub struct Scene<'a, T> {
    interval: TimeInterval<T>,
    bodies: Vec<SceneBody<'a, T>>,
}

impl<'a, T: Float> Scene<'a, T> {
    /// An empty scene over the frame `interval`.
    ///
    /// # Errors
    /// None today; kept fallible for future checks of the frame.
    pub fn try_new(interval: TimeInterval<T>) -> Result<Self, SceneQueryError> {
        Ok(Self {
            interval,
            bodies: Vec::new(),
        })
    }

    /// The frame.
    #[must_use]
    pub const fn interval(&self) -> TimeInterval<T> {
        self.interval
    }

    /// The bodies, numbered in the order they were added.
    #[must_use]
    pub fn bodies(&self) -> &[SceneBody<'a, T>] {
        &self.bodies
    }

    /// The number of bodies.
    #[must_use]
    pub fn len(&self) -> usize {
        self.bodies.len()
    }

    /// Whether the scene has no body.
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.bodies.is_empty()
    }

    /// Adds a body moving by `motion` over the scene's frame; returns its
    /// number.
    ///
    /// # Errors
    /// [`SceneQueryError::IntervalMismatch`], or [`SceneQueryError::Input`]
    /// for a vertex set too large for its bounding ball.
    pub fn try_add(
        &mut self,
        shape: BodyShape<'a, T>,
        motion: RigidMotion<T>,
    ) -> Result<usize, SceneQueryError> {
        let body = self.bodies.len();
        self.check(body, &shape, &motion)?;
        self.bodies
            .push(SceneBody::try_new(shape, motion, Groups::ALL)?);
        Ok(body)
    }

    /// Adds a static body at `pose`; returns its number.
    ///
    /// # Errors
    /// As [`try_add`](Self::try_add).
    pub fn try_add_static(
        &mut self,
        shape: BodyShape<'a, T>,
        pose: Isometry<T>,
    ) -> Result<usize, SceneQueryError> {
        let motion = RigidMotion::try_new(
            crate::Point3::from_vec3(pose.translation()),
            Vec3::ZERO,
            Vec3::ZERO,
            self.interval,
        )?
        .with_orientation(pose.rotation());
        self.try_add(shape, motion)
    }

    /// Replaces a body's motion (the next frame's, in a frame loop).
    ///
    /// # Errors
    /// [`SceneQueryError::UnknownBody`], [`SceneQueryError::IntervalMismatch`].
    pub fn try_set_motion(
        &mut self,
        body: usize,
        motion: RigidMotion<T>,
    ) -> Result<(), SceneQueryError> {
        if motion.interval() != self.interval {
            return Err(SceneQueryError::IntervalMismatch { body });
        }
        let b = self
            .bodies
            .get_mut(body)
            .ok_or(SceneQueryError::UnknownBody(body))?;
        b.motion = motion;
        Ok(())
    }

    /// Sets a body's interaction groups.
    ///
    /// # Errors
    /// [`SceneQueryError::UnknownBody`].
    pub fn try_set_groups(&mut self, body: usize, groups: Groups) -> Result<(), SceneQueryError> {
        self.bodies
            .get_mut(body)
            .ok_or(SceneQueryError::UnknownBody(body))?
            .groups = groups;
        Ok(())
    }

    /// Moves every body to the frame `interval` (their motions must then be
    /// replaced by ones over it before the next query).
    pub fn set_interval(&mut self, interval: TimeInterval<T>) {
        self.interval = interval;
    }

    fn check(
        &self,
        body: usize,
        shape: &BodyShape<'a, T>,
        motion: &RigidMotion<T>,
    ) -> Result<(), SceneQueryError> {
        let _ = shape;
        if motion.interval() != self.interval {
            return Err(SceneQueryError::IntervalMismatch { body });
        }
        Ok(())
    }

    /// Every pair's first contact over the frame: [`broad_phase`](Self::broad_phase)
    /// then [`narrow_phase`](Self::narrow_phase), with every pair the
    /// bodies' groups allow.
    ///
    /// # Errors
    /// [`SceneQueryError::Ca`] for bad parameters, [`SceneQueryError::IntervalMismatch`]
    /// for a body left on another frame.
    pub fn query<'w>(
        &self,
        ws: &'w mut SceneWorkspace<T>,
        params: &SceneParams<T>,
    ) -> Result<&'w SceneReport<T>, SceneQueryError> {
        self.query_filtered(ws, params, |_, _| true)
    }

    /// As [`query`](Self::query), testing only the pairs `(a, b)` (`a < b`)
    /// for which `filter(a, b)` holds (and the groups allow).
    ///
    /// # Errors
    /// As [`query`](Self::query).
    pub fn query_filtered<'w>(
        &self,
        ws: &'w mut SceneWorkspace<T>,
        params: &SceneParams<T>,
        filter: impl FnMut(usize, usize) -> bool,
    ) -> Result<&'w SceneReport<T>, SceneQueryError> {
        self.broad_phase(ws, params, filter)?;
        self.narrow_phase(ws, params)
    }

    /// The broad phase alone: each body's swept box, and the pairs kept for
    /// the narrow phase ([`SceneWorkspace::candidates`]); the pairs' reports
    /// are cleared.
    ///
    /// # Errors
    /// As [`query`](Self::query).
    pub fn broad_phase(
        &self,
        ws: &mut SceneWorkspace<T>,
        params: &SceneParams<T>,
        mut filter: impl FnMut(usize, usize) -> bool,
    ) -> Result<(), SceneQueryError> {
        params.validate()?;
        let mut stats = SceneStats {
            bodies: self.bodies.len(),
            ..SceneStats::default()
        };
        ws.boxes.clear();
        ws.skip.clear();
        for (i, body) in self.bodies.iter().enumerate() {
            if body.motion.interval() != self.interval {
                return Err(SceneQueryError::IntervalMismatch { body: i });
            }
            if let BodyShape::HalfSpace(_) = body.shape {
                // Unbounded: out of the sweep, tested by its plane below.
                stats.half_spaces += 1;
                let still =
                    body.motion.linear() == Vec3::ZERO && body.motion.angular() == Vec3::ZERO;
                stats.static_bodies += usize::from(still);
                ws.boxes.push(SweptBox::empty());
                ws.skip.push(still);
                continue;
            }
            let (b, path) = SweptBox::with_path(&body.ball, &body.motion);
            match path {
                BoxPath::Static => {
                    stats.static_bodies += 1;
                    stats.box_rates_skipped += 6;
                }
                BoxPath::Translating => {
                    stats.translating_bodies += 1;
                    stats.box_rates_skipped += 6;
                }
                BoxPath::Turning => {
                    stats.turning_bodies += 1;
                    stats.box_rates += 6;
                }
            }
            ws.boxes.push(b);
            ws.skip.push(path == BoxPath::Static);
        }
        let n = self.bodies.len() as u64;
        let s = stats.static_bodies as u64;
        stats.pairs_all = n * n.saturating_sub(1) / 2;
        stats.pairs_static = s * s.saturating_sub(1) / 2;
        overlapping_pairs(
            &ws.boxes,
            &ws.skip,
            params.ca.contact_distance,
            &mut ws.order,
            &mut ws.overlapping,
        );
        // Half-spaces against every other body whose swept box is not
        // certified above their swept plane (`proofs/11-scene.md`, Lemma
        // 11.4); never two half-spaces.
        if stats.half_spaces > 0 {
            for (h, body) in self.bodies.iter().enumerate() {
                let BodyShape::HalfSpace(half) = body.shape else {
                    continue;
                };
                for (j, other) in self.bodies.iter().enumerate() {
                    if matches!(other.shape, BodyShape::HalfSpace(_)) {
                        if h < j && !(ws.skip[h] && ws.skip[j]) {
                            stats.pairs_of_half_spaces += 1;
                        }
                        continue;
                    }
                    if ws.skip[h] && ws.skip[j] {
                        // Both static: counted among the static pairs.
                        continue;
                    }
                    let clear =
                        ws.boxes[j].is_above(&half, &body.motion, params.ca.contact_distance);
                    if !clear {
                        ws.overlapping.push((index(h.min(j)), index(h.max(j))));
                    }
                }
            }
            ws.overlapping.sort_unstable();
        }
        stats.pairs_culled = stats.pairs_all
            - stats.pairs_static
            - stats.pairs_of_half_spaces
            - ws.overlapping.len() as u64;
        ws.candidates.clear();
        for &(a, b) in &ws.overlapping {
            let (ia, ib) = (a as usize, b as usize);
            let groups = self.bodies[ia]
                .groups
                .interacts_with(self.bodies[ib].groups);
            if groups && filter(ia, ib) {
                ws.candidates.push((a, b));
            } else {
                stats.pairs_filtered += 1;
            }
        }
        stats.pairs_tested = ws.candidates.len() as u64;
        ws.report.pairs.clear();
        ws.report.earliest.clear();
        ws.report.stats = stats;
        Ok(())
    }

    /// The narrow phase over the pairs of the last
    /// [`broad_phase`](Self::broad_phase), in order, on this thread.
    ///
    /// # Errors
    /// As [`query`](Self::query).
    pub fn narrow_phase<'w>(
        &self,
        ws: &'w mut SceneWorkspace<T>,
        params: &SceneParams<T>,
    ) -> Result<&'w SceneReport<T>, SceneQueryError> {
        ws.report.pairs.clear();
        let mut work = PairWork::default();
        for &(a, b) in &ws.candidates {
            let (ia, ib) = (a as usize, b as usize);
            let (report, w) = self.run_pair(ia, ib, params, &mut ws.mesh)?;
            work.add(w);
            ws.report.pairs.push(report);
        }
        Ok(finish(ws, self.bodies.len(), work))
    }

    /// One pair's query, with the stepper of its shapes.
    fn run_pair(
        &self,
        a: usize,
        b: usize,
        params: &SceneParams<T>,
        mesh_ws: &mut MeshWorkspace<T>,
    ) -> Result<(PairReport<T>, PairWork), SceneQueryError> {
        let (ba, bb) = (&self.bodies[a], &self.bodies[b]);
        let (ma, mb) = (&ba.motion, &bb.motion);
        let mut work = PairWork::default();
        let (report, node_pairs) = match (ba.shape, bb.shape) {
            (BodyShape::Mesh(ta), BodyShape::Mesh(tb)) => {
                let mut pair = MeshPair::with_workspace(ta, tb, core::mem::take(mesh_ws))
                    .try_with_params(params.mesh)?;
                let r = time_of_impact(&mut pair, ma, mb, &params.ca);
                let visited = pair.stats().node_pairs;
                *mesh_ws = pair.into_workspace();
                (r?, visited)
            }
            (BodyShape::Convex(va), BodyShape::Convex(vb)) => {
                let mut pair = ConvexPair::with_gjk(va, vb);
                let r = time_of_impact(&mut pair, ma, mb, &params.ca)?;
                let (skipped, evaluated) = pair.bound_counts();
                work.evq_skipped = skipped;
                work.evq_evaluated = evaluated;
                (r, 0)
            }
            (BodyShape::Ball(sa), BodyShape::Ball(sb)) => (
                time_of_impact(&mut BallPair::new(sa, sb), ma, mb, &params.ca)?,
                0,
            ),
            (sa, sb) => {
                // Every other pair of kinds: one stepper per family.
                let mut pair =
                    AnyPair::try_new(any_shape(&sa, &ba.ball)?, any_shape(&sb, &bb.ball)?)?
                        .try_with_mesh_params(params.mesh)?
                        .with_workspace(core::mem::take(mesh_ws));
                let r = time_of_impact(&mut pair, ma, mb, &params.ca);
                *mesh_ws = pair.into_workspace();
                let r = r?;
                let visited = r.work.node_pairs;
                (r, visited)
            }
        };
        work.iterations = u64::from(report.iterations);
        Ok((
            PairReport {
                a,
                b,
                report,
                node_pairs,
            },
            work,
        ))
    }
}

/// The counters one pair's query adds.
#[derive(Clone, Copy, Debug, Default)]
struct PairWork {
    iterations: u64,
    evq_skipped: u64,
    evq_evaluated: u64,
}

impl PairWork {
    fn add(&mut self, o: Self) {
        self.iterations += o.iterations;
        self.evq_skipped += o.evq_skipped;
        self.evq_evaluated += o.evq_evaluated;
    }
}

/// The per-body earliest contacts and the counters, from the pairs' reports.
fn finish<T: Float>(ws: &mut SceneWorkspace<T>, bodies: usize, work: PairWork) -> &SceneReport<T> {
    let report = &mut ws.report;
    report.earliest.clear();
    report.earliest.resize(bodies, None);
    for p in &report.pairs {
        if let Some(t) = p.report.outcome.earliest_possible_contact() {
            for (me, other) in [(p.a, p.b), (p.b, p.a)] {
                let slot = &mut report.earliest[me];
                if slot.is_none_or(|(best, _)| t < best) {
                    *slot = Some((t, other));
                }
            }
        }
    }
    report.stats.iterations = work.iterations;
    report.stats.evq_skipped = work.evq_skipped;
    report.stats.evq_evaluated = work.evq_evaluated;
    &ws.report
}

#[cfg(feature = "parallel")]
impl<T: Float + Send + Sync> Scene<'_, T> {
    /// As [`query`](Self::query), with the narrow phase spread over rayon's
    /// threads: the same report, pair for pair, whatever the thread count.
    ///
    /// # Errors
    /// As [`query`](Self::query).
    #[cfg_attr(docsrs, doc(cfg(feature = "parallel")))]
    pub fn par_query<'w>(
        &self,
        ws: &'w mut SceneWorkspace<T>,
        params: &SceneParams<T>,
    ) -> Result<&'w SceneReport<T>, SceneQueryError> {
        self.broad_phase(ws, params, |_, _| true)?;
        self.par_narrow_phase(ws, params)
    }

    /// As [`narrow_phase`](Self::narrow_phase), across rayon's threads (one
    /// mesh workspace per thread's run of pairs); the reports come back in
    /// pair order.
    ///
    /// # Errors
    /// As [`query`](Self::query).
    #[cfg_attr(docsrs, doc(cfg(feature = "parallel")))]
    pub fn par_narrow_phase<'w>(
        &self,
        ws: &'w mut SceneWorkspace<T>,
        params: &SceneParams<T>,
    ) -> Result<&'w SceneReport<T>, SceneQueryError> {
        use rayon::prelude::*;
        let results: Vec<Result<(PairReport<T>, PairWork), SceneQueryError>> = ws
            .candidates
            .par_iter()
            .map_init(MeshWorkspace::new, |mesh, &(a, b)| {
                self.run_pair(a as usize, b as usize, params, mesh)
            })
            .collect();
        ws.report.pairs.clear();
        let mut work = PairWork::default();
        for r in results {
            let (report, w) = r?;
            work.add(w);
            ws.report.pairs.push(report);
        }
        Ok(finish(ws, self.bodies.len(), work))
    }
}

/// A scene body's shape as the steppers' [`Shape`]: a vertex set as the
/// polytope of its hull, a ball as the point of its centre with its radius.
fn any_shape<'s, T: Float>(
    shape: &BodyShape<'s, T>,
    ball: &'s BoundingBall<T>,
) -> Result<Shape<'s, T>, InputError> {
    Ok(match *shape {
        BodyShape::Mesh(tree) => Shape::Mesh(tree),
        BodyShape::Convex(set) => Shape::Convex(Convex::polytope(set)),
        BodyShape::Ball(b) => {
            let centre = VertexSet::from_validated(core::slice::from_ref(ball.centre()));
            Shape::Convex(Convex::polytope(centre).try_rounded(b.radius())?)
        }
        BodyShape::Shape(s) => Shape::Convex(s),
        BodyShape::HalfSpace(h) => Shape::HalfSpace(h),
        BodyShape::Compound(c) => Shape::Compound(c),
    })
}

/// A body number as the sweep's `u32` (scenes of more than `u32::MAX`
/// bodies are not supported).
fn index(i: usize) -> u32 {
    u32::try_from(i).unwrap_or(u32::MAX)
}
