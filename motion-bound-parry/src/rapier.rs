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
//! contact. A pair within the contact distance at the start (its first
//! cast is not asked again with a smaller one) is a resting or sliding
//! contact, left to the solver (`proofs/12-shapes.md`, Lemma 12.14): its
//! overlap along the start's contact normal may reach a ceiling, the
//! start's overlap plus the contact distance or the solver's allowed
//! penetration ([`with_allowed_overlap`](CertifiedPass::with_allowed_overlap))
//! when that is more, and its group is stopped at the first time it may
//! pass it (certified, a cast against the half-space at the ceiling: a
//! body the solver pushes on into a thin wall is stopped there, one
//! sliding along the wall or leaving it is not). The pass carries each
//! touching pair's normal and ceiling to the next step: a pair it held
//! keeps its ceiling, and no pair's ceiling rises above the one carried
//! (beyond the allowed penetration), so nothing creeps in a step at a time;
//! and a pair whose overlap, grown by a bound of its approach over the step
//! (its relative speed along the normal and both turns), stays below the
//! ceiling is decided with two support points, no cast. When both bodies
//! turn too fast for the rule, or a shape's extent is not computed
//! (heightfields, polylines, voxels), the pair is asked again with a
//! smaller contact distance, and still touching, the rule is parry's
//! static penetration depth at both ends (deeper at the end by more than
//! the contact distance: the bodies are held at their start poses); that
//! does not see a body pass right through a thin rotating body within one
//! step.
//! A swept body stopped early stands at its stop pose for the rest of the
//! step: every swept body still moving then is cast against it there, and
//! stopped at the hit, in rounds (`proofs/12-shapes.md`, Lemma 12.8).
//!
//! What it does not do: a body without CCD (or kinematic) is where rapier
//! put it, even where a stopped body stands. Its
//! cost: each collider's motion and swept box once per step, then one cast
//! per pair of colliders whose swept boxes meet, unless the balls bounding
//! them about their motions' centres (which move on straight lines) never
//! come within the contact distance ([`ClampStats::apart`], a closed form),
//! or the pair touched at the last step's start and its certificate still
//! covers this step ([`ClampStats::checked`]).
//! The pairs are found by a scan of every collider per CCD collider: for
//! tens of fast bodies, not for thousands.
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
use rapier3d_f64::dynamics::{IntegrationParameters, RigidBodyHandle, RigidBodySet};
use rapier3d_f64::geometry::{ColliderHandle, ColliderSet};
use rapier3d_f64::math::{Pose, Vector};
use rapier3d_f64::parry::query::NonlinearRigidMotion;
use rapier3d_f64::pipeline::PhysicsWorld;

use crate::f64::{CastError, CertifiedDispatcher, PastContact, ShapeCache, Swept, Touching};

/// What one [`CertifiedPass::clamp`] did.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
#[non_exhaustive]
pub struct ClampStats {
    /// Collider pairs cast (their swept boxes met).
    pub casts: usize,
    /// Bodies moved back to a time of impact.
    pub bodies: usize,
    /// Pairs touching at the start that the step would have left deeper:
    /// their bodies stopped where they may start to go deeper (or held at
    /// the start).
    pub held: usize,
    /// Casts the adapter could not answer (an unsupported shape or input):
    /// those pairs are left to rapier.
    pub unanswered: usize,
    /// Pairs whose swept boxes met but whose bounding balls (about each
    /// motion's centre, which moves on a line) never came within the
    /// contact distance: decided apart without a cast.
    pub apart: usize,
    /// Pairs touching at an earlier step whose overlap along that step's
    /// normal is certified to stay below its ceiling by the closed form
    /// (Lemma 12.14): decided with a few support points, no cast.
    pub checked: usize,
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
    /// Scratch kept between steps: by a body handle's slot, its generation
    /// and its index in `before`.
    index: Vec<Option<(u32, usize)>>,
    /// Scratch kept between steps: every collider's motion and swept box.
    placed: Vec<Placed>,
    /// Scratch kept between steps: each recorded body's motion.
    motions: Vec<Option<NonlinearRigidMotion>>,
    /// Scratch kept between steps: the hits `(body, other body, time)`.
    hits: Vec<(usize, Option<usize>, f64)>,
    /// Scratch kept between steps: the pair scan's view of `placed`.
    scan: Vec<Scan>,
    /// Pairs touching at the start of the last step, by their colliders:
    /// the normal their overlap was taken along and its ceiling (Lemma
    /// 12.14), carried to this step.
    touching: Touchings,
    /// Scratch kept between steps: this step's `touching`.
    touching_next: Touchings,
    /// The overlap a touching pair may always reach (the solver's allowed
    /// penetration; Lemma 12.14's floor).
    allowed_overlap: f64,
}

#[path = "rapier/touching.rs"]
mod touching;
use touching::Touchings;

/// A collider as the pair scan reads it (compact: the scan reads every
/// pair's).
#[derive(Clone, Copy, Debug)]
struct Scan {
    swept: parry3d_f64::bounding_volume::Aabb,
    /// Its body's index in [`CertifiedPass::before`], `usize::MAX` for none.
    body: usize,
    /// A swept body's collider with a motion.
    ccd: bool,
}

/// A collider's motion over the step and its swept box, with its body's
/// index in [`CertifiedPass::before`] (`None` for a collider without a
/// body).
#[derive(Debug)]
struct Placed {
    body: Option<usize>,
    /// The motion's centre at the start (it moves at `velocity`).
    centre: parry3d_f64::math::Vector,
    velocity: parry3d_f64::math::Vector,
    /// The largest distance of the collider's points from the centre.
    radius: f64,
    /// The largest distance from the centre of the points whose turn moves
    /// the collider's extent along a direction: `radius`, or for a ball the
    /// distance of its centre (a ball's extent does not turn about it).
    turning: f64,
    motion: NonlinearRigidMotion,
    swept: parry3d_f64::bounding_volume::Aabb,
    handle: ColliderHandle,
}

impl Placed {
    /// Whether the two colliders' balls about their motions' centres stay
    /// more than `reach` apart over `[0, dt]`: then no two points of them
    /// come within `reach` and the pair needs no cast. The centres' least
    /// distance has a closed form (their difference moves on a line); the
    /// test keeps a margin of `1e-9` of the scale, which is far above the
    /// rounding of these few operations in `f64`.
    fn apart_over(&self, other: &Self, dt: f64, reach: f64) -> bool {
        let d0 = other.centre - self.centre;
        let dv = other.velocity - self.velocity;
        let vv = dv.dot(dv);
        let t = if vv > 0.0 {
            (-d0.dot(dv) / vv).clamp(0.0, dt)
        } else {
            0.0
        };
        let least = (d0 + dv * t).length();
        let need = self.radius + other.radius + reach;
        let scale = d0.length() + dt * vv.sqrt() + need;
        // NaN anywhere: not apart (the cast decides).
        least > need + 1e-9 * scale
    }
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
        // A collider at its body's frame moves by the body's motion itself.
        Some(m) => match c.position_wrt_parent() {
            Some(p) if *p != Pose::IDENTITY => m.prepend(*p),
            _ => *m,
        },
        None => NonlinearRigidMotion::constant_position(*c.position()),
    }
}

/// The box of the points a collider moving by `m` over `[0, dt]` passes
/// through, loosened by `reach` (`proofs/12-shapes.md`, Lemma 12.13);
/// `centre` is the motion's centre at the start (`m.start * m.local_center`,
/// which moves on a straight line at `m.linvel`) and every point of the
/// collider is within `radius` of it.
///
/// A still collider: its box. Otherwise a point `x0` at the start is at
/// `x0 + v t + (R(w t) - I)(x0 - c0)` at time `t`, within `min(|w| t, 2)
/// radius` of `x0 + v t` and within `radius` of the centre `c0 + v t`: the
/// swept set is in the box of the ball of that radius along the centre's
/// segment, and in the start box merged with itself moved by `v dt`, grown
/// by `min(|w| dt, 2) radius`. The intersection of the two, or the ball's
/// box alone for a collider turning by a radian or more (then within the
/// other when the start box holds the centre), so that no box of the shape
/// is computed where it would not help (a cylinder's costs as much as the
/// rest of the pass's step).
fn swept_box(
    m: &NonlinearRigidMotion,
    s: &dyn parry3d_f64::shape::Shape,
    centre: parry3d_f64::math::Vector,
    radius: f64,
    dt: f64,
    reach: f64,
) -> parry3d_f64::bounding_volume::Aabb {
    use parry3d_f64::bounding_volume::Aabb;
    // `position_at_time(0)` is `start`; a still motion stays there.
    if m.linvel == Vector::ZERO && m.angvel == Vector::ZERO {
        return s.compute_aabb(&m.start).loosened(reach);
    }
    let travel = m.linvel * dt;
    let end = centre + travel;
    // The rounding of `centre`, `end`, `radius`, the turn and the start
    // box's moved corners (a few operations, relative `2^-53` each, on
    // numbers at most twice `scale`) is far below `1e-9` of the scale, as in
    // `Placed::apart_over`.
    let scale = centre.abs().max_element() + travel.abs().max_element() + radius;
    let pad = reach + 1e-9 * scale;
    let ball = Aabb::new(
        centre.min(end) - Vector::splat(radius + pad),
        centre.max(end) + Vector::splat(radius + pad),
    );
    let turn = (m.angvel.length() * dt).min(2.0);
    if turn >= 1.0 {
        return ball;
    }
    let a = s.compute_aabb(&m.start);
    let grow = Vector::splat(turn * radius + pad);
    let moved = Aabb::new(
        a.mins.min(a.mins + travel) - grow,
        a.maxs.max(a.maxs + travel) + grow,
    );
    // Both hold the swept set, so they meet; NaN: the ball's box.
    moved.intersection(&ball).unwrap_or(ball)
}

impl CertifiedPass {
    /// With a new dispatcher (a new cache, [`CaParams::default`]).
    #[must_use]
    pub fn new() -> Self {
        Self {
            dispatcher: CertifiedDispatcher::new(),
            before: Vec::new(),
            index: Vec::new(),
            placed: Vec::new(),
            motions: Vec::new(),
            hits: Vec::new(),
            scan: Vec::new(),
            touching: Touchings::default(),
            touching_next: Touchings::default(),
            allowed_overlap: IntegrationParameters::default().allowed_linear_error(),
        }
    }

    /// The overlap (along the contact normal) a pair touching at the start
    /// of a step may always reach without being stopped: rapier's allowed
    /// penetration, which its solver leaves resting bodies within
    /// (`IntegrationParameters::allowed_linear_error`, `0.005` for a length
    /// unit of one, the default here; [`step`](Self::step) takes the
    /// world's). Beyond it a touching pair's overlap grows by at most the
    /// contact distance a step, and not at all while the pass holds it
    /// (`proofs/12-shapes.md`, Lemma 12.14). A negative or NaN value counts
    /// as zero.
    #[must_use]
    pub fn with_allowed_overlap(mut self, overlap: f64) -> Self {
        self.allowed_overlap = overlap;
        self
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
        self.allowed_overlap = world.integration_parameters.allowed_linear_error();
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
        let mut motions = core::mem::take(&mut self.motions);
        motions.clear();
        motions.extend(self.before.iter().map(|(h, start, _)| {
            let b = bodies.get(*h)?;
            let end = b.position();
            let com = b.local_center_of_mass();
            if end == start {
                // Not moved (a fixed body, or one the step left in place):
                // the still motion, exactly (no rotation's rounding).
                return Some(NonlinearRigidMotion::new(
                    *start,
                    com,
                    Vector::ZERO,
                    Vector::ZERO,
                ));
            }
            let linvel = (*end * com - *start * com) / dt;
            let turn = end.rotation * start.rotation.inverse();
            let angvel = turn.to_scaled_axis() / dt;
            Some(NonlinearRigidMotion::new(*start, com, linvel, angvel))
        }));
        // Each recorded body's place in `before`, by its handle's slot.
        self.index.fill(None);
        for (k, (h, _, _)) in self.before.iter().enumerate() {
            let (slot, generation) = h.into_raw_parts();
            let slot = slot as usize;
            if self.index.len() <= slot {
                self.index.resize(slot + 1, None);
            }
            self.index[slot] = Some((generation, k));
        }
        // Every collider's motion and swept box, once per step: its body's
        // index (`None` without a body; colliders of bodies not recorded are
        // left out).
        self.placed.clear();
        for (handle, c) in colliders.iter() {
            let j = match c.parent() {
                Some(h) => {
                    let (slot, generation) = h.into_raw_parts();
                    match self.index.get(slot as usize).copied().flatten() {
                        Some((g, j)) if g == generation => Some(j),
                        _ => continue,
                    }
                }
                None => None,
            };
            let m = collider_motion(j.and_then(|j| motions[j].as_ref()), c);
            let ball = c.shape().compute_local_bounding_sphere();
            // Every point of the collider stays within `radius` of its
            // motion's centre, which moves on a straight line.
            let radius = (ball.center - m.local_center).length() + ball.radius;
            let turning = if Swept::see_through(c.shape()).as_ball().is_some() {
                (ball.center - m.local_center).length()
            } else {
                radius
            };
            let centre = m.start * m.local_center;
            let b = swept_box(&m, c.shape(), centre, radius, dt, contact_distance);
            self.placed.push(Placed {
                body: j,
                centre,
                velocity: m.linvel,
                radius,
                turning,
                motion: m,
                swept: b,
                handle,
            });
        }
        let mut hits = core::mem::take(&mut self.hits);
        hits.clear();
        // The scan's compact view of `placed`: each swept box, its body
        // (`usize::MAX` for none) and whether it is a swept body's collider
        // (one with a motion).
        let mut scan = core::mem::take(&mut self.scan);
        scan.clear();
        scan.extend(self.placed.iter().map(|p| {
            Scan {
                swept: p.swept,
                body: p.body.unwrap_or(usize::MAX),
                ccd: p
                    .body
                    .is_some_and(|i| self.before[i].2 && motions[i].is_some()),
            }
        }));
        for (a, sa) in scan.iter().enumerate() {
            if !sa.ccd {
                continue;
            }
            let (pa, i) = (&self.placed[a], sa.body);
            for (b, sb) in scan.iter().enumerate() {
                // Another body's collider (a swept one once per pair), or a
                // collider without a body, whose swept box meets this one's.
                if sb.body == i || (sb.ccd && b < a) || !sa.swept.intersects(&sb.swept) {
                    continue;
                }
                let pb = &self.placed[b];
                if pa.apart_over(pb, dt, contact_distance) {
                    stats.apart += 1;
                    continue;
                }
                let (Some(ci), Some(cj)) = (colliders.get(pa.handle), colliders.get(pb.handle))
                else {
                    continue;
                };
                let j = pb.body;
                let (m1, m2) = (&pa.motion, &pb.motion);
                let key = (pa.handle, pb.handle);
                // Touching at the last step's start: first the closed form
                // along that step's normal, under the carried ceiling (Lemma
                // 12.14): a resting or sliding pair is decided with no cast.
                let carried = self.touching.get(&key).copied();
                if let Some((n, c)) = carried {
                    if let Some(ceiling) = pa.still_below(
                        ci.shape(),
                        pb,
                        cj.shape(),
                        n,
                        c,
                        self.allowed_overlap,
                        contact_distance,
                        dt,
                    ) {
                        stats.checked += 1;
                        self.touching_next.insert(key, (n, ceiling));
                        continue;
                    }
                    if let Some(Touching {
                        answer: PastContact::Never,
                        normal,
                        ceiling,
                        cast,
                        ..
                    }) = self.dispatcher.touching(
                        m1,
                        ci.shape(),
                        m2,
                        cj.shape(),
                        0.0,
                        dt,
                        Some(n),
                        Some(c),
                        self.allowed_overlap,
                    ) {
                        stats.checked += usize::from(!cast);
                        stats.casts += usize::from(cast);
                        self.touching_next.insert(key, (normal, ceiling));
                        continue;
                    }
                }
                stats.casts += 1;
                // First without re-asking: a pair within the contact
                // distance at the start is the touching rule's (along the
                // start's contact normal, the ceiling carried when the pair
                // was held), and only when that cannot decide is it asked
                // again (as rapier's casts are) and, still touching, left
                // to parry's depths.
                let first = self
                    .dispatcher
                    .cast_first(m1, ci.shape(), m2, cj.shape(), 0.0, dt);
                let first = match first {
                    Ok(Some(hit)) if hit.time_of_impact <= 0.0 => {
                        let rule = self.dispatcher.touching(
                            m1,
                            ci.shape(),
                            m2,
                            cj.shape(),
                            0.0,
                            dt,
                            None,
                            carried.map(|(_, c)| c),
                            self.allowed_overlap,
                        );
                        if let Some(t) = rule {
                            if t.answer != PastContact::Unknown {
                                self.touching_next.insert(key, (t.normal, t.ceiling));
                            }
                        }
                        match rule.map(|t| t.answer) {
                            Some(PastContact::Never) => continue,
                            Some(PastContact::At(t)) => {
                                stats.held += 1;
                                hits.push((i, j, t));
                                continue;
                            }
                            _ => self.dispatcher.cast_certified(
                                m1,
                                ci.shape(),
                                m2,
                                cj.shape(),
                                0.0,
                                dt,
                                true,
                            ),
                        }
                    }
                    other => other,
                };
                match first {
                    Ok(Some(hit)) if hit.time_of_impact > 0.0 => {
                        hits.push((i, j, hit.time_of_impact));
                    }
                    // Touching at the start, the rule undecided (both
                    // bodies rotating): a resting contact, the solver's,
                    // unless the step would end it deeper than it began
                    // (by more than the contact distance): then the body
                    // is held at its start.
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
        self.scan = scan;
        // Pairs not met this step are forgotten.
        core::mem::swap(&mut self.touching, &mut self.touching_next);
        self.touching_next.clear();
        if !hits.is_empty() {
            self.stop_groups(bodies, colliders, &motions, &hits, &mut stats, dt);
        }
        self.motions = motions;
        self.hits = hits;
        stats
    }

    /// Moves the bodies of each group linked by `hits` back to the group's
    /// earliest time of impact on its motion, then stops, in rounds, every
    /// swept body that would meet a body stopped before it (see
    /// [`cascade`](Self::cascade)).
    #[allow(clippy::too_many_arguments)]
    fn stop_groups(
        &self,
        bodies: &mut RigidBodySet,
        colliders: &ColliderSet,
        motions: &[Option<NonlinearRigidMotion>],
        hits: &[(usize, Option<usize>, f64)],
        stats: &mut ClampStats,
        dt: f64,
    ) {
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
        for &(i, j, _) in hits {
            if let Some(j) = j {
                let (ri, rj) = (root(&mut group, i), root(&mut group, j));
                group[ri] = rj;
            }
        }
        let mut first = vec![f64::INFINITY; self.before.len()];
        for &(i, _, t) in hits {
            let r = root(&mut group, i);
            first[r] = first[r].min(t);
        }
        // Each body's stop time (`INFINITY`: not stopped); only dynamic
        // bodies with a motion are stopped.
        let mut stop: Vec<f64> = (0..self.before.len())
            .map(|k| {
                let t = first[root(&mut group, k)];
                let dynamic = bodies.get(self.before[k].0).is_some_and(|b| b.is_dynamic());
                if t.is_finite() && dynamic && motions[k].is_some() {
                    t
                } else {
                    f64::INFINITY
                }
            })
            .collect();
        self.cascade(colliders, &mut stop, dt);
        for (k, &t) in stop.iter().enumerate() {
            let (true, Some(m)) = (t.is_finite(), &motions[k]) else {
                continue;
            };
            if let Some(b) = bodies.get_mut(self.before[k].0) {
                b.set_position(m.position_at_time(t), true);
                stats.bodies += 1;
            }
        }
    }

    /// A body stopped at `stop[s]` stands at its pose then for the rest of
    /// the step, where a body of another group, certified apart from it
    /// only along its whole motion, may still pass. In rounds: each swept
    /// body `x` still moving after a body `s` stopped in the last round
    /// (`stop[x] > stop[s]`) is cast over `[stop[s], min(stop[x], dt)]`
    /// against `s` standing still, and stopped at the hit (a new stop for
    /// the next round). Times only decrease; before each its pairs were
    /// certified apart (the first casts along the whole motions up to it,
    /// then these). Still stopping bodies after 8 rounds (a long chain):
    /// every swept body is held at the start (none moves, none passes).
    fn cascade(&self, colliders: &ColliderSet, stop: &mut [f64], dt: f64) {
        const ROUNDS: usize = 8;
        let contact_distance = self.dispatcher.params().contact_distance;
        let mut frontier: Vec<usize> = (0..stop.len()).filter(|&k| stop[k].is_finite()).collect();
        let mut next = Vec::new();
        for _ in 0..ROUNDS {
            if frontier.is_empty() {
                return;
            }
            next.clear();
            for ps in &self.placed {
                let Some(s) = ps.body else { continue };
                if !frontier.contains(&s) {
                    continue;
                }
                let ts = stop[s];
                let pose = ps.motion.position_at_time(ts);
                let Some(cs) = colliders.get(ps.handle) else {
                    continue;
                };
                let still = NonlinearRigidMotion::constant_position(pose);
                let boxed = cs.shape().compute_aabb(&pose).loosened(contact_distance);
                for px in &self.placed {
                    let Some(x) = px.body else { continue };
                    if x == s || !self.before[x].2 || stop[x] <= ts || !px.swept.intersects(&boxed)
                    {
                        continue;
                    }
                    let Some(cx) = colliders.get(px.handle) else {
                        continue;
                    };
                    let end = stop[x].min(dt);
                    if end <= ts {
                        continue;
                    }
                    let hit = self.dispatcher.cast_certified(
                        &px.motion,
                        cx.shape(),
                        &still,
                        cs.shape(),
                        ts,
                        end,
                        true,
                    );
                    let t = match hit {
                        Ok(Some(h)) => h.time_of_impact.max(ts),
                        Ok(None) => continue,
                        // Not answered: held where `s` stopped.
                        Err(_) => ts,
                    };
                    if t < stop[x] {
                        stop[x] = t;
                        if !next.contains(&x) {
                            next.push(x);
                        }
                    }
                }
            }
            core::mem::swap(&mut frontier, &mut next);
        }
        if frontier.is_empty() {
            return;
        }
        // Still stopping after the last round: nothing swept moves.
        for (k, t) in stop.iter_mut().enumerate() {
            if self.before[k].2 {
                *t = 0.0;
            }
        }
    }
}

#[cfg(test)]
#[path = "rapier/tests.rs"]
mod tests;
