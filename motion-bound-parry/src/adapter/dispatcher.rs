//! [`CertifiedDispatcher`]: a query dispatcher for parry and rapier whose
//! nonlinear cast is the certified one, every other query parry's (through
//! any [`Swept`]), with its counters ([`DispatchStats`]).

use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::Arc;

use motion_bound::ca::{CaParams, Ceiling};

use super::cache::ShapeCache;
use super::error::CastError;
use super::parry;
use super::past_contact::{past_contact_below_parry, past_contact_parry, PastContact, Touching};
use super::swept::Swept;
use parry::math::{Pose, Real, Vector};
use parry::query::{
    ClosestPoints, Contact, DefaultQueryDispatcher, NonlinearRigidMotion, QueryDispatcher,
    ShapeCastHit, ShapeDistance, ShapeIntersection, Unsupported,
};
use parry::shape::Shape;

/// How many casts a [`CertifiedDispatcher`] answered, and how many it
/// handed to parry.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
#[non_exhaustive]
pub struct DispatchStats {
    /// Casts answered by the certified conservative advancement.
    pub certified: u64,
    /// Casts handed to parry's `cast_shapes_nonlinear`: a shape this
    /// adapter does not take, or an input it refuses (the `CastError` is
    /// counted, parry answers as it would without this dispatcher).
    pub handed_to_parry: u64,
}

/// A query dispatcher for parry and rapier whose `cast_shapes_nonlinear`
/// is the certified one ([`ShapeCache::cast_shapes_nonlinear`]), every
/// other query going to parry's [`DefaultQueryDispatcher`]. Give it to
/// rapier's narrow phase:
///
/// ```
/// use motion_bound_parry::CertifiedDispatcher;
/// use rapier3d_f64::prelude::NarrowPhase;
/// let narrow_phase = NarrowPhase::with_query_dispatcher(CertifiedDispatcher::new());
/// # let _ = narrow_phase;
/// ```
///
/// A pair it cannot take (a heightfield, a polyline, voxels, a custom
/// shape) or an input it refuses goes to parry's own nonlinear cast, and is
/// counted ([`stats`](Self::stats)).
///
/// Every query sees through a [`Swept`] shape (either shape, any query:
/// contacts, distances, casts), so that a collider wrapped to have its CCD
/// answered here makes the same contacts as unwrapped. Rapier calls
/// `cast_shapes_nonlinear` only for the pairs its own sweeps do not take
/// (cylinders, cones, half-spaces, custom shapes such as [`Swept`]): alone,
/// it certifies nothing for balls, cuboids, capsules, hulls or meshes. To
/// certify every CCD body with plain shapes, run `rapier::CertifiedPass`
/// (feature `rapier`) around each step, made with a clone of this
/// dispatcher (its casts then counted here too); or wrap the colliders in
/// [`Swept`] (see its docs for what that costs).
///
/// A clone shares the cache and the counters: keep one to read the stats
/// of the one given to rapier.
#[derive(Clone, Debug, Default)]
pub struct CertifiedDispatcher {
    cache: Arc<ShapeCache>,
    params: CaParams<Real>,
    counters: Arc<Counters>,
}

/// A dispatcher's counters, shared by its clones.
#[derive(Debug, Default)]
struct Counters {
    certified: AtomicU64,
    handed_to_parry: AtomicU64,
}

impl CertifiedDispatcher {
    /// With [`CaParams::default`] and a new cache.
    #[must_use]
    pub fn new() -> Self {
        Self::default()
    }

    /// With conservative advancement's parameters `params` (the contact
    /// distance for your length unit, the iteration and work budgets).
    ///
    /// # Errors
    /// [`CastError::Ca`] for invalid parameters.
    pub fn try_with_params(mut self, params: CaParams<Real>) -> Result<Self, CastError> {
        params.validate()?;
        self.params = params;
        Ok(self)
    }

    /// With the cache `cache` (shared with other dispatchers or with the
    /// program, which may [register](ShapeCache::register) its shapes).
    #[must_use]
    pub fn with_cache(mut self, cache: Arc<ShapeCache>) -> Self {
        self.cache = cache;
        self
    }

    /// The cache.
    #[must_use]
    pub fn cache(&self) -> &Arc<ShapeCache> {
        &self.cache
    }

    /// Conservative advancement's parameters.
    #[must_use]
    pub fn params(&self) -> &CaParams<Real> {
        &self.params
    }

    /// Casts answered and handed over so far, by this dispatcher and its
    /// clones (and by a `rapier::CertifiedPass` made with one of them).
    #[must_use]
    pub fn stats(&self) -> DispatchStats {
        DispatchStats {
            certified: self.counters.certified.load(Ordering::Relaxed),
            handed_to_parry: self.counters.handed_to_parry.load(Ordering::Relaxed),
        }
    }

    /// The certified cast with this dispatcher's cache and parameters
    /// ([`ShapeCache::cast_shapes_nonlinear`]), counted in
    /// [`DispatchStats::certified`] when answered. Unlike the
    /// [`QueryDispatcher`] method, nothing goes to parry: a pair it cannot
    /// take is the error (and is not counted). `rapier::CertifiedPass` casts
    /// through it, so that one dispatcher counts rapier's casts and the
    /// pass's.
    ///
    /// # Errors
    /// The cast's [`CastError`] (an unsupported shape, an invalid input).
    #[allow(clippy::too_many_arguments)] // parry's `cast_shapes_nonlinear`'s own.
    pub fn cast_certified(
        &self,
        motion1: &NonlinearRigidMotion,
        g1: &dyn Shape,
        motion2: &NonlinearRigidMotion,
        g2: &dyn Shape,
        start_time: Real,
        end_time: Real,
        stop_at_penetration: bool,
    ) -> Result<Option<ShapeCastHit>, CastError> {
        let hit = self.cache.cast_shapes_nonlinear(
            motion1,
            g1,
            motion2,
            g2,
            start_time,
            end_time,
            stop_at_penetration,
            &self.params,
        )?;
        self.counters.certified.fetch_add(1, Ordering::Relaxed);
        Ok(hit)
    }
}

impl CertifiedDispatcher {
    /// [`cast_certified`](Self::cast_certified) with no re-asking: shapes
    /// within the contact distance at `start_time` are a hit at the start
    /// (the pass decides those with `past_contact`).
    #[allow(clippy::too_many_arguments)]
    #[allow(dead_code)] // the rapier pass's: the f64 adapter's, with the `rapier` feature
    pub(crate) fn cast_first(
        &self,
        motion1: &NonlinearRigidMotion,
        g1: &dyn Shape,
        motion2: &NonlinearRigidMotion,
        g2: &dyn Shape,
        start_time: Real,
        end_time: Real,
    ) -> Result<Option<ShapeCastHit>, CastError> {
        let hit = self.cache.cast_with_attempts(
            motion1,
            g1,
            motion2,
            g2,
            start_time,
            end_time,
            true,
            &self.params,
            0,
        )?;
        self.counters.certified.fetch_add(1, Ordering::Relaxed);
        Ok(hit)
    }
}

impl CertifiedDispatcher {
    /// For shapes touching at `start_time`: whether shape 1 goes deeper
    /// into shape 2 over `[start_time, end_time]`, with nothing carried
    /// (`past_contact.rs`; the core's Lemma 12.11).
    #[allow(clippy::too_many_arguments)]
    pub(crate) fn past_contact(
        &self,
        motion1: &NonlinearRigidMotion,
        g1: &dyn Shape,
        motion2: &NonlinearRigidMotion,
        g2: &dyn Shape,
        start_time: Real,
        end_time: Real,
    ) -> PastContact {
        past_contact_parry(
            &self.cache,
            &self.params,
            motion1,
            g1,
            motion2,
            g2,
            start_time,
            end_time,
        )
    }

    /// The same rule along `normal` (parry's contact normal at the start
    /// when `None`) with the ceiling `last` carried from the last step
    /// (`past_contact.rs`; the core's Lemma 12.14).
    #[allow(clippy::too_many_arguments)]
    #[allow(dead_code)] // the rapier pass's: the f64 adapter's, with the `rapier` feature
    pub(crate) fn touching(
        &self,
        motion1: &NonlinearRigidMotion,
        g1: &dyn Shape,
        motion2: &NonlinearRigidMotion,
        g2: &dyn Shape,
        start_time: Real,
        end_time: Real,
        normal: Option<Vector>,
        last: Option<Ceiling<Real>>,
        floor: Real,
    ) -> Option<Touching> {
        past_contact_below_parry(
            &self.cache,
            &self.params,
            motion1,
            g1,
            motion2,
            g2,
            start_time,
            end_time,
            normal,
            last,
            floor,
        )
    }
}

/// Both shapes with any [`Swept`] layers removed: what each query handed to
/// parry's dispatcher gives it.
fn seen<'a, 'b>(g1: &'a dyn Shape, g2: &'b dyn Shape) -> (&'a dyn Shape, &'b dyn Shape) {
    (Swept::see_through(g1), Swept::see_through(g2))
}

impl QueryDispatcher for CertifiedDispatcher {
    fn intersection_test(
        &self,
        pos12: &Pose,
        g1: &dyn Shape,
        g2: &dyn Shape,
    ) -> Result<ShapeIntersection, Unsupported> {
        let (g1, g2) = seen(g1, g2);
        DefaultQueryDispatcher.intersection_test(pos12, g1, g2)
    }

    fn distance(
        &self,
        pos12: &Pose,
        g1: &dyn Shape,
        g2: &dyn Shape,
    ) -> Result<ShapeDistance, Unsupported> {
        let (g1, g2) = seen(g1, g2);
        DefaultQueryDispatcher.distance(pos12, g1, g2)
    }

    fn contact(
        &self,
        pos12: &Pose,
        g1: &dyn Shape,
        g2: &dyn Shape,
        prediction: Real,
    ) -> Result<Option<Contact>, Unsupported> {
        let (g1, g2) = seen(g1, g2);
        DefaultQueryDispatcher.contact(pos12, g1, g2, prediction)
    }

    fn closest_points(
        &self,
        pos12: &Pose,
        g1: &dyn Shape,
        g2: &dyn Shape,
        max_dist: Real,
    ) -> Result<ClosestPoints, Unsupported> {
        let (g1, g2) = seen(g1, g2);
        DefaultQueryDispatcher.closest_points(pos12, g1, g2, max_dist)
    }

    fn cast_shapes(
        &self,
        pos12: &Pose,
        local_vel12: Vector,
        g1: &dyn Shape,
        g2: &dyn Shape,
        options: parry::query::ShapeCastOptions,
    ) -> Result<Option<ShapeCastHit>, Unsupported> {
        let (g1, g2) = seen(g1, g2);
        DefaultQueryDispatcher.cast_shapes(pos12, local_vel12, g1, g2, options)
    }

    fn cast_shapes_nonlinear(
        &self,
        motion1: &NonlinearRigidMotion,
        g1: &dyn Shape,
        motion2: &NonlinearRigidMotion,
        g2: &dyn Shape,
        start_time: Real,
        end_time: Real,
        stop_at_penetration: bool,
    ) -> Result<Option<ShapeCastHit>, Unsupported> {
        match self.cast_certified(
            motion1,
            g1,
            motion2,
            g2,
            start_time,
            end_time,
            stop_at_penetration,
        ) {
            // Touching at the start, asked as rapier's CCD asks (a solid
            // pair, `stop_at_penetration` off): rapier ignores a hit at the
            // start, so the answer is whether the motion goes deeper
            // (`past_contact`): no (sliding along or leaving: parry's
            // answer for shapes moving out of a penetration), or the first
            // time it may, which rapier clamps at.
            Ok(Some(hit)) if !stop_at_penetration && hit.time_of_impact <= start_time => {
                match self.past_contact(motion1, g1, motion2, g2, start_time, end_time) {
                    PastContact::Never => Ok(None),
                    PastContact::At(t) if t > start_time => Ok(Some(ShapeCastHit {
                        time_of_impact: t,
                        ..hit
                    })),
                    PastContact::At(_) | PastContact::Unknown => Ok(Some(hit)),
                }
            }
            Ok(hit) => Ok(hit),
            Err(_) => {
                self.counters
                    .handed_to_parry
                    .fetch_add(1, Ordering::Relaxed);
                let (g1, g2) = seen(g1, g2);
                DefaultQueryDispatcher.cast_shapes_nonlinear(
                    motion1,
                    g1,
                    motion2,
                    g2,
                    start_time,
                    end_time,
                    stop_at_penetration,
                )
            }
        }
    }
}

impl<ManifoldData, ContactData> parry::query::PersistentQueryDispatcher<ManifoldData, ContactData>
    for CertifiedDispatcher
where
    ManifoldData: Default + Clone + Send + Sync,
    ContactData: Default + Copy + Send + Sync,
{
    fn contact_manifolds(
        &self,
        pos12: &Pose,
        g1: &dyn Shape,
        g2: &dyn Shape,
        prediction: Real,
        manifolds: &mut Vec<parry::query::ContactManifold<ManifoldData, ContactData>>,
        workspace: &mut Option<parry::query::ContactManifoldsWorkspace>,
    ) -> Result<(), Unsupported> {
        let (g1, g2) = seen(g1, g2);
        parry::query::PersistentQueryDispatcher::contact_manifolds(
            &DefaultQueryDispatcher,
            pos12,
            g1,
            g2,
            prediction,
            manifolds,
            workspace,
        )
    }

    fn contact_manifold_convex_convex(
        &self,
        pos12: &Pose,
        g1: &dyn Shape,
        g2: &dyn Shape,
        normal_constraints1: Option<&dyn parry::query::details::NormalConstraints>,
        normal_constraints2: Option<&dyn parry::query::details::NormalConstraints>,
        prediction: Real,
        manifold: &mut parry::query::ContactManifold<ManifoldData, ContactData>,
    ) -> Result<(), Unsupported> {
        let (g1, g2) = seen(g1, g2);
        parry::query::PersistentQueryDispatcher::contact_manifold_convex_convex(
            &DefaultQueryDispatcher,
            pos12,
            g1,
            g2,
            normal_constraints1,
            normal_constraints2,
            prediction,
            manifold,
        )
    }
}
