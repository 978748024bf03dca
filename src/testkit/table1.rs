//! The Table 1 scenario (torus knot vs torus knot), shared by the
//! benchmarks, the `table1` report and the tests, so that all of them run the
//! very same queries.
//!
//! For each knot size: [`ORIENTATIONS`] copies of the knot, each turned by a
//! seeded random rotation baked into its body points, with their ball trees,
//! all built once; then a seeded list of fly-by queries
//! ([`fly_by`]): query `i` flies copy `i % 8` past copy
//! `(i + 3) % 8` over `[0, 1]`, A spinning at up to `spin` rad per unit time,
//! B at up to `spin / 4`. The random stream does not depend on the size or
//! on the number of queries, so the first `N` queries are the same list (up
//! to the knots' slightly different reach) for every size.

extern crate std;
use std::vec::Vec;

use super::toi::{fly_by, random_rotation, reach, rotate_mesh, FlyBy, Rng};
use crate::bodies::TorusKnotSize;
use crate::ca::{
    time_of_impact, BoundChoice, CaParams, CaReport, MeshPair, MeshParams, TraversalStats,
};
use crate::{BallTree, TriMesh};

/// The seed of the orientations and the queries (the erratum's date).
pub const SEED: u64 = 20_061_006;
/// Pre-rotated copies of the knot.
pub const ORIENTATIONS: usize = 8;
/// The main scenario's spin: body A turns at up to 2 rad per unit time (B at
/// up to 0.5), so A turns at most about 115 degrees over a query.
pub const SPIN: f64 = 2.0;
/// The contact distance: about `1e-3` of the knot's size (its reach is about
/// 0.53, its diameter about 1.06).
pub const CONTACT_DISTANCE: f64 = 1e-3;

/// One query: copy `a` moves by `motion.a`, copy `b` by `motion.b`.
#[derive(Clone, Copy, Debug)]
pub struct Query {
    /// The copy that moves by `motion.a`.
    pub a: usize,
    /// The copy that moves by `motion.b`.
    pub b: usize,
    /// The two motions over `[0, 1]`.
    pub motion: FlyBy,
}

/// One knot size: the rotated copies, their trees and the query list.
#[derive(Debug)]
pub struct KnotScene {
    /// The rotated copies of the knot.
    pub meshes: Vec<TriMesh<f64>>,
    /// Their ball trees.
    pub trees: Vec<BallTree<f64>>,
    /// The farthest vertex from the rotation centre.
    pub reach: f64,
    /// The queries.
    pub queries: Vec<Query>,
}

/// A short label of the size: "2.8K", "11K" or "34K".
#[must_use]
pub const fn label(size: TorusKnotSize) -> &'static str {
    match size {
        TorusKnotSize::K2_8 => "2.8K",
        TorusKnotSize::K11 => "11K",
        TorusKnotSize::K34 => "34K",
    }
}

impl KnotScene {
    /// The scene of `size` with the first `queries` queries at `spin`.
    ///
    /// # Panics
    /// Never for the shipped sizes (their meshes are valid).
    #[must_use]
    pub fn new(size: TorusKnotSize, queries: usize, spin: f64) -> Self {
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
    #[must_use]
    pub fn params(bound: BoundChoice) -> CaParams<f64> {
        CaParams::default()
            .with_contact_distance(CONTACT_DISTANCE)
            .with_bound(bound)
    }

    /// Runs query `q` with the mesh stepper (making the `MeshPair` is part of
    /// the query): the report and the traversal counters.
    ///
    /// # Panics
    /// Never for valid parameters.
    #[must_use]
    pub fn run(&self, q: &Query, params: &CaParams<f64>) -> (CaReport<f64>, TraversalStats) {
        self.run_with(q, params, MeshParams::default())
    }

    /// The same with the traversal's knobs `mesh`.
    ///
    /// # Panics
    /// On knobs out of range ([`MeshParams::validate`]).
    #[must_use]
    pub fn run_with(
        &self,
        q: &Query,
        params: &CaParams<f64>,
        mesh: MeshParams<f64>,
    ) -> (CaReport<f64>, TraversalStats) {
        let mut pair = MeshPair::new(&self.trees[q.a], &self.trees[q.b])
            .try_with_params(mesh)
            .expect("valid knobs");
        let report =
            time_of_impact(&mut pair, &q.motion.a, &q.motion.b, params).expect("valid query");
        (report, pair.stats())
    }
}
