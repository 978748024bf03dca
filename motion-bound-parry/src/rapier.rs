//! A certified pass after rapier's step: every CCD body's actual motion
//! over the step, cast against everything it may meet.
//!
//! Rapier 0.36's CCD leaves gaps a dispatcher cannot close: it sweeps a
//! bullet (a dynamic body with CCD enabled) against every body except
//! another bullet, so two fast bullets flying at each other pass through
//! each other (dimforge/rapier#984); it takes each target at its end-of-step
//! pose; it ignores a hit at the start of a sub-step; and it clamps a body
//! along its own interpolation of the motion, not the motion it cast.
//! It needs no wrapping: plain balls, cuboids, capsules, cylinders, cones,
//! hulls, meshes and compounds of CCD bodies are all cast (rapier's own
//! sweeps of balls, boxes and hulls never reach a dispatcher).
//! [`CertifiedPass`] runs after `PhysicsPipeline::step` ([`CertifiedPass::step`]
//! does both for a `PhysicsWorld`): it takes every
//! body's motion over the step from its poses before and after (its centre
//! of mass on a straight line, its rotation at a constant rate about it),
//! casts each CCD body's colliders against every other collider whose swept
//! box meets theirs with the certified cast (both moving, as they did), and
//! moves the dynamic bodies of each group linked by hits back to the pose,
//! on that very motion, at the group's earliest certified time of impact.
//! Velocities are kept: the next step's contact solver resolves the
//! contact. A pair touching at the start is a resting contact, left to the
//! solver as rapier leaves it, unless the step would end it deeper than it
//! began (parry's static penetration depth at both ends, by more than the
//! contact distance): then its bodies are held at their start poses.
//!
//! What it does not do: bodies stopped at different times (two groups, or
//! a group and a body it never met) are each where their own motion put
//! them; a body stopped early may stand where another passes later in the
//! step (rapier's own clamping has the same limit; substeps remove it). Its
//! cost is one cast per pair of colliders whose swept boxes meet, found by
//! a scan of every collider per CCD body: for a few fast bodies, not for
//! thousands.
//!
//! ```
//! use motion_bound_parry::rapier::CertifiedPass;
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
//! let mut pass = CertifiedPass::new();
//! // `pass.step(&mut world)` is these three lines.
//! pass.record(&world.bodies);
//! world.step();
//! let clamped = pass.clamp(&mut world.bodies, &world.colliders, world.integration_parameters.dt);
//! assert_eq!(clamped.bodies, 2);
//! assert!(pass.dispatcher().stats().certified > 0);
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
use rapier3d_f64::pipeline::PhysicsWorld;

use crate::f64::{CastError, CertifiedDispatcher, ShapeCache, Swept};

/// What one [`CertifiedPass::clamp`] did.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
#[non_exhaustive]
pub struct ClampStats {
    /// Collider pairs cast (their swept boxes met).
    pub casts: usize,
    /// Bodies moved back to a time of impact.
    pub bodies: usize,
    /// Pairs touching at the start that the step would have left deeper:
    /// their bodies held at the start.
    pub held: usize,
    /// Casts the adapter could not answer (an unsupported shape or input):
    /// those pairs are left to rapier.
    pub unanswered: usize,
}

/// The certified pass (see the module docs).
///
/// Its casts go through a [`CertifiedDispatcher`] (a new one, or the one
/// given to the narrow phase with [`with_dispatcher`](Self::with_dispatcher)):
/// its cache, its parameters, and its counters, so that
/// [`CertifiedDispatcher::stats`] counts the pass's casts with rapier's.
#[derive(Debug)]
pub struct CertifiedPass {
    dispatcher: CertifiedDispatcher,
    /// Every body's pose before the step, and whether it is swept (a
    /// dynamic body with CCD enabled).
    before: Vec<(RigidBodyHandle, Pose, bool)>,
}

impl Default for CertifiedPass {
    fn default() -> Self {
        Self::new()
    }
}

/// A collider's motion over the step: its body's (about the body's centre
/// of mass, from its poses before and after) composed with its pose on the
/// body, or its own still pose for a collider without a body.
fn collider_motion(
    body: Option<&NonlinearRigidMotion>,
    c: &rapier3d_f64::geometry::Collider,
) -> NonlinearRigidMotion {
    match body {
        Some(m) => c.position_wrt_parent().map_or(*m, |p| m.prepend(*p)),
        None => NonlinearRigidMotion::constant_position(*c.position()),
    }
}

impl CertifiedPass {
    /// With a new dispatcher (a new cache, [`CaParams::default`]).
    #[must_use]
    pub fn new() -> Self {
        Self {
            dispatcher: CertifiedDispatcher::new(),
            before: Vec::new(),
        }
    }

    /// Casting through `dispatcher` (a clone of the one given to the narrow
    /// phase): its cache, its parameters, its counters.
    #[must_use]
    pub fn with_dispatcher(mut self, dispatcher: CertifiedDispatcher) -> Self {
        self.dispatcher = dispatcher;
        self
    }

    /// With the cache `cache` (shared with a `CertifiedDispatcher`).
    #[must_use]
    pub fn with_cache(mut self, cache: Arc<ShapeCache>) -> Self {
        self.dispatcher = self.dispatcher.with_cache(cache);
        self
    }

    /// With conservative advancement's parameters (the contact distance
    /// for your length unit).
    ///
    /// # Errors
    /// [`CastError::Ca`] for invalid parameters.
    pub fn try_with_params(mut self, params: CaParams<f64>) -> Result<Self, CastError> {
        self.dispatcher = self.dispatcher.try_with_params(params)?;
        Ok(self)
    }

    /// The dispatcher the pass casts through (its stats count the pass's
    /// casts).
    #[must_use]
    pub fn dispatcher(&self) -> &CertifiedDispatcher {
        &self.dispatcher
    }

    /// One step of `world` with the pass around it: [`record`](Self::record),
    /// `world.step()`, [`clamp`](Self::clamp) over
    /// `world.integration_parameters.dt`. Call it instead of `world.step()`.
    pub fn step(&mut self, world: &mut PhysicsWorld) -> ClampStats {
        self.record(&world.bodies);
        world.step();
        let dt = world.integration_parameters.dt;
        self.clamp(&mut world.bodies, &world.colliders, dt)
    }

    /// Before `PhysicsPipeline::step`: records every body's pose.
    pub fn record(&mut self, bodies: &RigidBodySet) {
        self.before.clear();
        self.before.extend(
            bodies
                .iter()
                .map(|(h, b)| (h, *b.position(), b.is_dynamic() && b.is_ccd_enabled())),
        );
    }

    /// After `PhysicsPipeline::step` of length `dt`: casts every swept
    /// body's colliders against every other collider (both moving as they
    /// did over the step) and moves the dynamic bodies of each group that
    /// would touch back to the group's earliest certified time of impact.
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
        let contact_distance = self.dispatcher.params().contact_distance;
        // Each body's motion over the step, about its centre of mass.
        let motions: Vec<Option<NonlinearRigidMotion>> = self
            .before
            .iter()
            .map(|(h, start, _)| {
                let b = bodies.get(*h)?;
                let end = b.position();
                let com = b.local_center_of_mass();
                let linvel = (*end * com - *start * com) / dt;
                let turn = end.rotation * start.rotation.inverse();
                let angvel = turn.to_scaled_axis() / dt;
                Some(NonlinearRigidMotion::new(*start, com, linvel, angvel))
            })
            .collect();
        let index: std::collections::HashMap<RigidBodyHandle, usize> = self
            .before
            .iter()
            .enumerate()
            .map(|(k, (h, _, _))| (*h, k))
            .collect();
        // The swept box of a collider's motion: its start and end boxes
        // merged, grown by how far the rotation can carry a point off the
        // segment between them (`|w| dt` times its reach, at most twice the
        // reach), and by the contact distance.
        let swept = |m: &NonlinearRigidMotion, s: &dyn parry3d_f64::shape::Shape| {
            let r = s.compute_local_bounding_sphere();
            let reach = r.center.length() + r.radius + m.local_center.length();
            let a = s.compute_aabb(&m.position_at_time(0.0));
            let b = s.compute_aabb(&m.position_at_time(dt));
            let grow = (m.angvel.length() * dt).min(2.0) * reach;
            a.merged(&b).loosened(grow + contact_distance)
        };
        let mut hits: Vec<(usize, Option<usize>, f64)> = Vec::new();
        for (i, (hi, _, swept_i)) in self.before.iter().enumerate() {
            let (true, Some(mi), Some(bi)) = (*swept_i, &motions[i], bodies.get(*hi)) else {
                continue;
            };
            for ci in bi.colliders() {
                let Some(ci) = colliders.get(*ci) else {
                    continue;
                };
                let m1 = collider_motion(Some(mi), ci);
                let box1 = swept(&m1, ci.shape());
                for (_, cj) in colliders.iter() {
                    // Another body's collider (a swept one once per pair),
                    // or a collider without a body.
                    let j = match cj.parent() {
                        Some(hj) if hj == *hi => continue,
                        Some(hj) => match index.get(&hj) {
                            Some(&j) if self.before[j].2 && j < i => continue,
                            Some(&j) => Some(j),
                            None => continue,
                        },
                        None => None,
                    };
                    let m2 = collider_motion(j.and_then(|j| motions[j].as_ref()), cj);
                    if !box1.intersects(&swept(&m2, cj.shape())) {
                        continue;
                    }
                    stats.casts += 1;
                    match self.dispatcher.cast_certified(
                        &m1,
                        ci.shape(),
                        &m2,
                        cj.shape(),
                        0.0,
                        dt,
                        true,
                    ) {
                        Ok(Some(hit)) if hit.time_of_impact > 0.0 => {
                            hits.push((i, j, hit.time_of_impact));
                        }
                        // Touching at the start: a resting contact, the
                        // solver's, unless the step would end it deeper
                        // than it began (by more than the contact
                        // distance): then the body is held at its start.
                        Ok(Some(_)) => {
                            let depth = |t: f64| {
                                parry3d_f64::query::contact(
                                    &m1.position_at_time(t),
                                    Swept::see_through(ci.shape()),
                                    &m2.position_at_time(t),
                                    Swept::see_through(cj.shape()),
                                    0.0,
                                )
                                .ok()
                                .flatten()
                                .map_or(0.0, |c| (-c.dist).max(0.0))
                            };
                            if depth(dt) > depth(0.0) + contact_distance {
                                stats.held += 1;
                                hits.push((i, j, 0.0));
                            }
                        }
                        Ok(_) => {}
                        Err(_) => stats.unanswered += 1,
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
            if let Some(j) = j {
                let (ri, rj) = (root(&mut group, i), root(&mut group, j));
                group[ri] = rj;
            }
        }
        let mut first = vec![f64::INFINITY; self.before.len()];
        for &(i, _, t) in &hits {
            let r = root(&mut group, i);
            first[r] = first[r].min(t);
        }
        for k in 0..self.before.len() {
            let t = first[root(&mut group, k)];
            let (true, Some(m)) = (t.is_finite(), &motions[k]) else {
                continue;
            };
            if let Some(b) = bodies.get_mut(self.before[k].0) {
                if b.is_dynamic() {
                    b.set_position(m.position_at_time(t), true);
                    stats.bodies += 1;
                }
            }
        }
        stats
    }
}
