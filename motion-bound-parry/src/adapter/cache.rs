//! [`ShapeCache`]: converted bodies kept across queries (a mesh's tree
//! built once per shape), how a cached shape is recognised, and the cast
//! through the cache.

use std::collections::HashMap;
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::{Arc, Mutex, MutexGuard, PoisonError, Weak};

use motion_bound::ca::{CaParams, MeshWorkspace};

use super::cast::{cast_bodies, RESOLVE_ATTEMPTS};
use super::convert::Body;
use super::error::CastError;
use super::parry;
use super::swept::Swept;
use parry::math::{Pose, Real, Vector};
use parry::query::{NonlinearRigidMotion, ShapeCastHit};
use parry::shape::{Shape, SharedShape, TypedShape};

/// What identifies a cached body's parry shape.
#[derive(Debug)]
enum Identity {
    /// A registered shared shape: while it lives, nothing else sits at its
    /// address, and while the cache holds a `Weak` to it, it cannot be
    /// changed in place (`Arc::get_mut` and `Arc::make_mut` move it).
    Shared(Weak<dyn Shape>),
    /// A mesh met through a `&dyn Shape`: a copy of its vertices and
    /// triangles, compared in full at every lookup (exact, `O(n)`).
    Mesh {
        vertices: Vec<Vector>,
        indices: Vec<[u32; 3]>,
    },
    /// A compound met through a `&dyn Shape`: its parts' shared shapes
    /// (held, so that none is freed and replaced) and poses.
    Compound(Vec<(Pose, SharedShape)>),
}

impl Identity {
    fn of(shape: &dyn Shape) -> Option<Self> {
        match shape.as_typed_shape() {
            TypedShape::TriMesh(m) => Some(Self::Mesh {
                vertices: m.vertices().to_vec(),
                indices: m.indices().to_vec(),
            }),
            TypedShape::Compound(c) => Some(Self::Compound(c.shapes().to_vec())),
            _ => None,
        }
    }

    fn matches(&self, shape: &dyn Shape) -> bool {
        match (self, shape.as_typed_shape()) {
            (Self::Shared(w), _) => w.strong_count() > 0,
            (Self::Mesh { vertices, indices }, TypedShape::TriMesh(m)) => {
                m.vertices() == vertices.as_slice() && m.indices() == indices.as_slice()
            }
            (Self::Compound(parts), TypedShape::Compound(c)) => {
                parts.len() == c.shapes().len()
                    && parts
                        .iter()
                        .zip(c.shapes())
                        .all(|((p0, s0), (p1, s1))| p0 == p1 && Arc::ptr_eq(&s0.0, &s1.0))
            }
            _ => false,
        }
    }
}

#[derive(Debug)]
struct Entry {
    identity: Identity,
    body: Arc<Body>,
}

/// How a [`ShapeCache`] has been used.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
#[non_exhaustive]
pub struct CacheStats {
    /// Bodies built (a tree for each mesh among them).
    pub built: u64,
    /// Lookups answered by a cached body.
    pub hits: u64,
    /// Bodies in the cache now.
    pub len: usize,
}

/// Converted bodies kept across queries: a mesh's tree is built once per
/// shape, and a [`SharedShape`] cloned into a thousand colliders is one
/// shape (one address). Primitive shapes are converted at every query
/// (a few arithmetic operations) and never stored.
///
/// A shape is recognised by its address, and the match is made sure of:
/// a shape [registered](Self::register) as a [`SharedShape`] by a `Weak`
/// reference (`O(1)`: while it lives no other shape has its address, and
/// while the cache holds the `Weak` it cannot be changed in place); any
/// other mesh by comparing its vertices and triangles with a copy (`O(n)`
/// per query, exact); a compound by its parts' shared shapes, which the
/// cache holds. A stale entry is replaced, never used.
///
/// ```
/// use motion_bound_parry::ShapeCache;
/// use parry3d_f64::math::Vector;
/// use parry3d_f64::shape::SharedShape;
/// let tetra = SharedShape::trimesh(
///     vec![Vector::ZERO, Vector::X, Vector::Y, Vector::Z],
///     vec![[0, 1, 2], [0, 1, 3], [0, 2, 3], [1, 2, 3]],
/// )?;
/// let cache = ShapeCache::new();
/// cache.register(&tetra);
/// let clone = tetra.clone(); // a second collider's shape: the same tree
/// let a = cache.body(tetra.as_ref())?;
/// let b = cache.body(clone.as_ref())?;
/// assert!(std::sync::Arc::ptr_eq(&a, &b));
/// assert_eq!(cache.stats().built, 1);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Default)]
pub struct ShapeCache {
    entries: Mutex<HashMap<usize, Entry>>,
    workspaces: Mutex<Vec<MeshWorkspace<Real>>>,
    built: AtomicU64,
    hits: AtomicU64,
}

fn address(shape: &dyn Shape) -> usize {
    std::ptr::from_ref(shape).cast::<()>() as usize
}

/// `m` locked, poisoned or not (a panic while it was held leaves the cache
/// usable).
fn lock<T>(m: &Mutex<T>) -> MutexGuard<'_, T> {
    m.lock().unwrap_or_else(PoisonError::into_inner)
}

impl ShapeCache {
    /// An empty cache.
    #[must_use]
    pub fn new() -> Self {
        Self::default()
    }

    /// Builds `shape`'s body now (when it holds a mesh) and recognises the
    /// shape in `O(1)` from then on, as long as it lives. Registering a
    /// shape twice, or a clone of it, does nothing more. A [`Swept`] is
    /// registered as its inner shape (the same entry, wrapped or not).
    ///
    /// # Errors
    /// As [`Body::try_new`].
    pub fn try_register(&self, shape: &SharedShape) -> Result<(), CastError> {
        let shape = Swept::see_through_shared(shape);
        let key = address(shape.as_ref());
        let shared = || Identity::Shared(Arc::downgrade(&shape.0));
        let mut entries = lock(&self.entries);
        if let Some(e) = entries.get(&key) {
            if let Identity::Shared(w) = &e.identity {
                if w.strong_count() > 0 {
                    return Ok(());
                }
            }
            if e.identity.matches(shape.as_ref()) {
                let body = e.body.clone();
                entries.insert(
                    key,
                    Entry {
                        identity: shared(),
                        body,
                    },
                );
                return Ok(());
            }
        }
        drop(entries);
        let body = Body::try_new(shape.as_ref())?;
        if body.has_tree() {
            self.built.fetch_add(1, Ordering::Relaxed);
            self.insert(key, shared(), Arc::new(body));
        }
        Ok(())
    }

    /// [`try_register`](Self::try_register), ignoring a shape this adapter
    /// cannot take (its queries go to parry, or fail, as unregistered).
    pub fn register(&self, shape: &SharedShape) {
        let _ = self.try_register(shape);
    }

    /// The body of `shape`: the cached one when it holds a mesh, else a
    /// fresh conversion. A [`Swept`] is looked up as its inner shape.
    ///
    /// # Errors
    /// As [`Body::try_new`].
    pub fn body(&self, shape: &dyn Shape) -> Result<Arc<Body>, CastError> {
        let shape = Swept::see_through(shape);
        if !matches!(
            shape.as_typed_shape(),
            TypedShape::TriMesh(_) | TypedShape::Compound(_)
        ) {
            return Ok(Arc::new(Body::try_new(shape)?));
        }
        let key = address(shape);
        {
            let entries = lock(&self.entries);
            if let Some(e) = entries.get(&key) {
                if e.identity.matches(shape) {
                    self.hits.fetch_add(1, Ordering::Relaxed);
                    return Ok(e.body.clone());
                }
            }
        }
        let body = Arc::new(Body::try_new(shape)?);
        self.built.fetch_add(1, Ordering::Relaxed);
        if let Some(identity) = Identity::of(shape) {
            self.insert(key, identity, body.clone());
        }
        Ok(body)
    }

    /// Keeps `body` for the shape at `key`, recognised by `identity`.
    fn insert(&self, key: usize, identity: Identity, body: Arc<Body>) {
        lock(&self.entries).insert(key, Entry { identity, body });
    }

    /// Drops the bodies of registered shapes that no longer live.
    pub fn prune(&self) {
        lock(&self.entries)
            .retain(|_, e| !matches!(&e.identity, Identity::Shared(w) if w.strong_count() == 0));
    }

    /// Drops every cached body.
    pub fn clear(&self) {
        lock(&self.entries).clear();
    }

    /// Bodies built, lookups answered, bodies held.
    #[must_use]
    pub fn stats(&self) -> CacheStats {
        CacheStats {
            built: self.built.load(Ordering::Relaxed),
            hits: self.hits.load(Ordering::Relaxed),
            len: lock(&self.entries).len(),
        }
    }

    /// [`cast_shapes_nonlinear`] with this cache's bodies, its scratch
    /// space, and `params`.
    ///
    /// # Errors
    /// As [`cast_shapes_nonlinear`].
    ///
    /// [`cast_shapes_nonlinear`]: super::cast_shapes_nonlinear
    #[allow(clippy::too_many_arguments)]
    pub fn cast_shapes_nonlinear(
        &self,
        motion1: &NonlinearRigidMotion,
        g1: &dyn Shape,
        motion2: &NonlinearRigidMotion,
        g2: &dyn Shape,
        start_time: Real,
        end_time: Real,
        stop_at_penetration: bool,
        params: &CaParams<Real>,
    ) -> Result<Option<ShapeCastHit>, CastError> {
        self.cast_with_attempts(
            motion1,
            g1,
            motion2,
            g2,
            start_time,
            end_time,
            stop_at_penetration,
            params,
            RESOLVE_ATTEMPTS,
        )
    }

    /// [`cast_shapes_nonlinear`](Self::cast_shapes_nonlinear), a cast
    /// starting within the contact distance asked again at most `attempts`
    /// times (`0`: such a cast is a hit at the start).
    #[allow(clippy::too_many_arguments)]
    pub(crate) fn cast_with_attempts(
        &self,
        motion1: &NonlinearRigidMotion,
        g1: &dyn Shape,
        motion2: &NonlinearRigidMotion,
        g2: &dyn Shape,
        start_time: Real,
        end_time: Real,
        stop_at_penetration: bool,
        params: &CaParams<Real>,
        attempts: u32,
    ) -> Result<Option<ShapeCastHit>, CastError> {
        let b1 = self.body(g1)?;
        let b2 = self.body(g2)?;
        let ws = lock(&self.workspaces).pop().unwrap_or_default();
        let (hit, ws) = cast_bodies(
            motion1,
            &b1,
            motion2,
            &b2,
            start_time,
            end_time,
            stop_at_penetration,
            params,
            attempts,
            ws,
        );
        lock(&self.workspaces).push(ws);
        hit
    }
}
