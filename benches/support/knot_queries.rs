//! The Table 1 scenario (torus knot vs torus knot), shared by
//! `benches/toi.rs` and `examples/table1.rs` through `#[path]`, so that the
//! benchmark and the report run the very same queries.
//!
//! For each knot size: [`ORIENTATIONS`] copies of the knot, each turned by a
//! seeded random rotation baked into its body points, with their ball trees
//! (for us) and parry `TriMesh`es (for parry), all built once; then a seeded
//! list of fly-by queries (`testkit::toi::fly_by`): query `i` flies copy
//! `i % 8` past copy `(i + 3) % 8` over `[0, 1]`, A spinning at up to `spin`
//! rad per unit time, B at up to `spin / 4`. The random stream does not
//! depend on the size or on the number of queries, so the first `N` queries
//! are the same list (up to the knots' slightly different reach) for every
//! size, in the benchmark and in the example.

use motion_bound::ca::{time_of_impact, BoundChoice, CaParams, CaReport, MeshPair, TraversalStats};
use motion_bound::scenes::TorusKnotSize;
use motion_bound::testkit::toi::{fly_by, random_rotation, reach, rotate_mesh, FlyBy, Rng};
use motion_bound::{BallTree, RigidMotion, TriMesh};
use parry3d_f64::math::{Pose, Vector};
use parry3d_f64::query::{cast_shapes_nonlinear, NonlinearRigidMotion, ShapeCastStatus};
use parry3d_f64::shape::TriMesh as ParryMesh;

/// The seed of the orientations and the queries (the erratum's date).
pub(crate) const SEED: u64 = 20_061_006;
/// Pre-rotated copies of the knot.
pub(crate) const ORIENTATIONS: usize = 8;
/// The main scenario's spin: body A turns at up to 2 rad per unit time (B at
/// up to 0.5), so A turns at most about 115 degrees over a query.
pub(crate) const SPIN: f64 = 2.0;
/// The contact distance: about `1e-3` of the knot's size (its reach is about
/// 0.53, its diameter about 1.06).
pub(crate) const CONTACT_DISTANCE: f64 = 1e-3;

/// One query: copy `a` moves by `motion.a`, copy `b` by `motion.b`.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Query {
    pub(crate) a: usize,
    pub(crate) b: usize,
    pub(crate) motion: FlyBy,
}

/// One knot size: the rotated copies, their trees and the query list.
pub(crate) struct KnotScene {
    pub(crate) meshes: Vec<TriMesh<f64>>,
    pub(crate) trees: Vec<BallTree<f64>>,
    /// The farthest vertex from the rotation centre.
    pub(crate) reach: f64,
    pub(crate) queries: Vec<Query>,
}

/// A short label of the size: "2.8K", "11K" or "34K".
pub(crate) fn label(size: TorusKnotSize) -> &'static str {
    match size {
        TorusKnotSize::K2_8 => "2.8K",
        TorusKnotSize::K11 => "11K",
        TorusKnotSize::K34 => "34K",
    }
}

impl KnotScene {
    /// The scene of `size` with the first `queries` queries at `spin`.
    pub(crate) fn new(size: TorusKnotSize, queries: usize, spin: f64) -> Self {
        let base = size.mesh::<f64>().expect("the knot sizes are valid");
        let mut rng = Rng::new(SEED);
        let meshes: Vec<_> = (0..ORIENTATIONS)
            .map(|_| rotate_mesh(&base, &random_rotation(&mut rng)))
            .collect();
        let trees = meshes
            .iter()
            .map(|m| BallTree::try_from_mesh(m).expect("a valid mesh has a tree"))
            .collect();
        let r = meshes.iter().map(reach).fold(0.0, f64::max);
        let queries = (0..queries)
            .map(|i| Query {
                a: i % ORIENTATIONS,
                b: (i + 3) % ORIENTATIONS,
                motion: fly_by(&mut rng, r, r, spin),
            })
            .collect();
        Self {
            meshes,
            trees,
            reach: r,
            queries,
        }
    }

    /// The parameters of every query: the contact distance, the default time
    /// tolerance and iteration limit, and `bound`.
    pub(crate) fn params(bound: BoundChoice) -> CaParams<f64> {
        CaParams::default()
            .with_contact_distance(CONTACT_DISTANCE)
            .with_bound(bound)
    }

    /// Runs query `q` with our mesh stepper (making the `MeshPair` is part of
    /// the query): the report and the traversal counters.
    pub(crate) fn ours(
        &self,
        q: &Query,
        params: &CaParams<f64>,
    ) -> (CaReport<f64>, TraversalStats) {
        let mut pair = MeshPair::new(&self.trees[q.a], &self.trees[q.b]);
        let report =
            time_of_impact(&mut pair, &q.motion.a, &q.motion.b, params).expect("valid query");
        (report, pair.stats())
    }
}

/// Our motion `p(t) = x0 + v t + R(|w| t, w/|w|) r` as parry's: start at the
/// translation `x0` with the identity rotation, rotation about the local
/// origin (our rotation centre), `linvel = v`, `angvel = w`. Parry places a
/// local point `r` at `T(c) T(v t) R(w t) T(-c) start r` with
/// `c = start * local_center = x0`, which is `x0 + v t + R(w t) r`.
pub(crate) fn parry_motion(m: &RigidMotion<f64>) -> NonlinearRigidMotion {
    let (c, v, w) = (m.centre(), m.linear(), m.angular());
    NonlinearRigidMotion::new(
        Pose::from_translation(Vector::new(c.x, c.y, c.z)),
        Vector::ZERO,
        Vector::new(v.x, v.y, v.z),
        Vector::new(w.x, w.y, w.z),
    )
}

/// The same rotated copies as parry triangle meshes.
pub(crate) fn parry_meshes(scene: &KnotScene) -> Vec<ParryMesh> {
    scene
        .meshes
        .iter()
        .map(|m| {
            let vertices = m
                .vertices()
                .iter()
                .map(|v| Vector::new(v[0], v[1], v[2]))
                .collect();
            ParryMesh::new(vertices, m.triangles().to_vec()).expect("a valid mesh")
        })
        .collect()
}

/// What parry's nonlinear shape cast answered for one query.
#[derive(Clone, Copy, Debug)]
pub(crate) struct ParryAnswer {
    /// The time of impact, or `None` when parry found no impact in `[0, 1]`.
    pub(crate) time: Option<f64>,
    /// Whether parry's status was `Failed` (it still returns a time).
    pub(crate) failed: bool,
}

/// Parry's `cast_shapes_nonlinear` over `[0, 1]` for query `q`, stopping at
/// penetration (like our initial contact).
pub(crate) fn parry_toi(meshes: &[ParryMesh], q: &Query) -> ParryAnswer {
    let hit = cast_shapes_nonlinear(
        &parry_motion(&q.motion.a),
        &meshes[q.a],
        &parry_motion(&q.motion.b),
        &meshes[q.b],
        0.0,
        1.0,
        true,
    )
    .expect("parry supports triangle mesh against triangle mesh");
    ParryAnswer {
        time: hit.map(|h| h.time_of_impact),
        failed: hit.is_some_and(|h| h.status == ShapeCastStatus::Failed),
    }
}

/// The largest distance, over every vertex of both bodies of `q` at time
/// `t`, between our placement (`RigidMotion::pose_at`) and parry's
/// (`NonlinearRigidMotion::position_at_time`): checks [`parry_motion`].
pub(crate) fn mapping_error(scene: &KnotScene, q: &Query, t: f64) -> f64 {
    let mut worst = 0.0_f64;
    for (mesh, motion) in [
        (&scene.meshes[q.a], &q.motion.a),
        (&scene.meshes[q.b], &q.motion.b),
    ] {
        let ours = motion.pose_at(t);
        let theirs = parry_motion(motion).position_at_time(t);
        for v in mesh.vertices() {
            let p = ours.transform_point(motion_bound::Vec3::from_array(*v));
            let s = theirs.transform_point(Vector::new(v[0], v[1], v[2]));
            let d = ((p.x - s.x).powi(2) + (p.y - s.y).powi(2) + (p.z - s.z).powi(2)).sqrt();
            worst = worst.max(d);
        }
    }
    worst
}
