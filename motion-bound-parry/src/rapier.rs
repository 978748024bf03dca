//! A certified pass for the pairs rapier's CCD never casts: two bullets.
//!
//! Rapier 0.36 sweeps a bullet (a dynamic body with CCD enabled) against
//! every body except another bullet, and takes each target at its end-of-step
//! pose; two fast bullets flying at each other are cast against nothing and
//! pass through each other (dimforge/rapier#984). [`BulletPairs`] runs after
//! `PhysicsPipeline::step`: it takes each bullet's motion over the step from
//! its poses before and after (its centre of mass on a straight line, its
//! rotation at a constant rate about it: the motion rapier's own sweeps
//! interpolate), casts every pair of bullets whose swept boxes meet with the
//! certified cast (both bodies moving, as they did), and moves each body that
//! would touch another back to its pose at the earliest certified time of
//! impact of its group (the bullets linked by hits), as rapier's CCD does
//! with the pairs it casts. Velocities are kept: the next step's contact
//! solver resolves the contact.
//!
//! What it does not do: bodies stopped at different times (two groups, or
//! a group and a bullet it never met) are each where their own motion put
//! them; a body stopped early may stand where another passes later in the
//! step. Rapier's own clamping has the same limit; substeps remove it.
//!
//! ```
//! use motion_bound_parry::rapier::BulletPairs;
//! use rapier3d_f64::prelude::*;
//! let mut world = PhysicsWorld::default();
//! world.gravity = Vector::ZERO;
//! // Two small balls at 60 m/s towards each other, 1 m apart: one step of
//! // 1/60 s carries each 1 m, through the other.
//! for (x, v) in [(-0.5, 60.0), (0.5, -60.0)] {
//!     let rb = RigidBodyBuilder::dynamic()
//!         .translation(Vector::new(x, 0.0, 0.0))
//!         .linvel(Vector::new(v, 0.0, 0.0))
//!         .ccd_enabled(true);
//!     world.insert(rb, ColliderBuilder::ball(0.1));
//! }
//! let mut pass = BulletPairs::new();
//! pass.record(&world.bodies);
//! world.step();
//! let clamped = pass.clamp(&mut world.bodies, &world.colliders, world.integration_parameters.dt);
//! assert_eq!(clamped.bodies, 2);
//! // Both stopped where they touch, not past each other.
//! let xs: Vec<f64> = world.bodies.iter().map(|(_, b)| b.translation().x).collect();
//! assert!(xs[0] < xs[1] && xs[1] - xs[0] > 0.2 - 1e-3, "{xs:?}");
//! ```

use std::sync::Arc;

use motion_bound::ca::CaParams;
use parry3d_f64::bounding_volume::BoundingVolume;
use rapier3d_f64::dynamics::{RigidBodyHandle, RigidBodySet};
use rapier3d_f64::geometry::ColliderSet;
use rapier3d_f64::math::Pose;
use rapier3d_f64::parry::query::NonlinearRigidMotion;

use crate::f64::ShapeCache;

/// What one [`BulletPairs::clamp`] did.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
#[non_exhaustive]
pub struct ClampStats {
    /// Collider pairs cast (their swept boxes met).
    pub casts: usize,
    /// Bodies moved back to a time of impact.
    pub bodies: usize,
    /// Casts the adapter could not answer (an unsupported shape or input):
    /// those pairs are left to rapier.
    pub unanswered: usize,
}

/// The certified pass over pairs of bullets (see the module docs).
#[derive(Debug)]
pub struct BulletPairs {
    cache: Arc<ShapeCache>,
    params: CaParams<f64>,
    before: Vec<(RigidBodyHandle, Pose)>,
}

impl Default for BulletPairs {
    fn default() -> Self {
        Self::new()
    }
}

impl BulletPairs {
    /// With a new cache and [`CaParams::default`].
    #[must_use]
    pub fn new() -> Self {
        Self {
            cache: Arc::default(),
            params: CaParams::default(),
            before: Vec::new(),
        }
    }

    /// With the cache `cache` (shared with a `CertifiedDispatcher`).
    #[must_use]
    pub fn with_cache(mut self, cache: Arc<ShapeCache>) -> Self {
        self.cache = cache;
        self
    }

    /// With conservative advancement's parameters (the contact distance
    /// for your length unit).
    #[must_use]
    pub fn with_params(mut self, params: CaParams<f64>) -> Self {
        self.params = params;
        self
    }

    /// Before `PhysicsPipeline::step`: records every bullet's pose.
    pub fn record(&mut self, bodies: &RigidBodySet) {
        self.before.clear();
        self.before.extend(
            bodies
                .iter()
                .filter(|(_, b)| b.is_dynamic() && b.is_ccd_enabled())
                .map(|(h, b)| (h, *b.position())),
        );
    }

    /// After `PhysicsPipeline::step` of length `dt`: casts the recorded
    /// bullets pairwise over the step and moves each that would touch
    /// another back to its earliest certified time of impact.
    pub fn clamp(
        &mut self,
        bodies: &mut RigidBodySet,
        colliders: &ColliderSet,
        dt: f64,
    ) -> ClampStats {
        let mut stats = ClampStats::default();
        if dt <= 0.0 {
            return stats;
        }
        // Each bullet's motion over the step, about its centre of mass.
        let motions: Vec<Option<NonlinearRigidMotion>> = self
            .before
            .iter()
            .map(|(h, start)| {
                let b = bodies.get(*h)?;
                let end = b.position();
                let com = b.local_center_of_mass();
                let linvel = (*end * com - *start * com) / dt;
                let turn = end.rotation * start.rotation.inverse();
                let angvel = turn.to_scaled_axis() / dt;
                Some(NonlinearRigidMotion::new(*start, com, linvel, angvel))
            })
            .collect();
        let mut hits: Vec<(usize, usize, f64)> = Vec::new();
        for i in 0..self.before.len() {
            for j in i + 1..self.before.len() {
                let (Some(mi), Some(mj)) = (&motions[i], &motions[j]) else {
                    continue;
                };
                let (Some(bi), Some(bj)) =
                    (bodies.get(self.before[i].0), bodies.get(self.before[j].0))
                else {
                    continue;
                };
                for ci in bi.colliders() {
                    for cj in bj.colliders() {
                        let (Some(ci), Some(cj)) = (colliders.get(*ci), colliders.get(*cj)) else {
                            continue;
                        };
                        let at =
                            |m: &NonlinearRigidMotion, c: &rapier3d_f64::geometry::Collider| {
                                c.position_wrt_parent().map_or(*m, |p| m.prepend(*p))
                            };
                        let (m1, m2) = (at(mi, ci), at(mj, cj));
                        // The swept boxes: start and end boxes merged, grown
                        // by how far the rotation can carry a point off
                        // the segment between them (|w| dt times the reach,
                        // at most twice the reach).
                        let swept =
                            |m: &NonlinearRigidMotion, s: &dyn parry3d_f64::shape::Shape| {
                                let r = s.compute_local_bounding_sphere();
                                let reach = r.center.length() + r.radius + m.local_center.length();
                                let a = s.compute_aabb(&m.position_at_time(0.0));
                                let b = s.compute_aabb(&m.position_at_time(dt));
                                let grow = (m.angvel.length() * dt).min(2.0) * reach;
                                a.merged(&b).loosened(grow + self.params.contact_distance)
                            };
                        if !swept(&m1, ci.shape()).intersects(&swept(&m2, cj.shape())) {
                            continue;
                        }
                        stats.casts += 1;
                        match self.cache.cast_shapes_nonlinear(
                            &m1,
                            ci.shape(),
                            &m2,
                            cj.shape(),
                            0.0,
                            dt,
                            true,
                            &self.params,
                        ) {
                            // A hit at the start is a resting contact: the
                            // solver's, as rapier leaves it.
                            Ok(Some(hit)) if hit.time_of_impact > 0.0 => {
                                hits.push((i, j, hit.time_of_impact));
                            }
                            Ok(_) => {}
                            Err(_) => stats.unanswered += 1,
                        }
                    }
                }
            }
        }
        // Bodies linked by hits stop together, at their group's earliest
        // time: no pair of a group touches before it (each pair's cast
        // certifies no contact before its own time), and stopped at one
        // time they are where the motions put them then.
        let mut group: Vec<usize> = (0..self.before.len()).collect();
        fn root(g: &mut [usize], mut k: usize) -> usize {
            while g[k] != k {
                g[k] = g[g[k]];
                k = g[k];
            }
            k
        }
        for &(i, j, _) in &hits {
            let (ri, rj) = (root(&mut group, i), root(&mut group, j));
            group[ri] = rj;
        }
        let mut first = vec![f64::INFINITY; self.before.len()];
        for &(i, _, t) in &hits {
            let r = root(&mut group, i);
            first[r] = first[r].min(t);
        }
        let earliest: Vec<f64> = (0..self.before.len())
            .map(|k| first[root(&mut group, k)])
            .collect();
        for (k, t) in earliest.iter().enumerate() {
            if let (true, Some(m)) = (t.is_finite(), &motions[k]) {
                if let Some(b) = bodies.get_mut(self.before[k].0) {
                    b.set_position(m.position_at_time(*t), true);
                    stats.bodies += 1;
                }
            }
        }
        stats
    }
}
