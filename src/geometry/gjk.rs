//! GJK distance between convex bodies given by support maps.
//!
//! The Gilbert-Johnson-Keerthi algorithm (IEEE J. Robotics and Automation
//! 4(2), 1988, [doi:10.1109/56.2083](https://doi.org/10.1109/56.2083)) finds
//! the point `v` of the Minkowski difference `A - B` nearest the origin; its
//! length is the distance. Each iteration asks the support maps for the
//! point `w = s_A(-v) - s_B(v)` of `A - B` farthest along `-v`, adds it to a
//! simplex of at most four points and replaces `v` by the simplex's point
//! nearest the origin (signed volumes, Montanari et al. 2017). Since every
//! `x` in `A - B` has `x . v >= w . v`, each iteration also proves the lower
//! bound `w . v / |v|` of the distance (van den Bergen, "A fast and robust
//! GJK implementation for collision detection of convex objects", J.
//! Graphics Tools 4(2), 1999,
//! [doi:10.1080/10867651.1999.10487502](https://doi.org/10.1080/10867651.1999.10487502)).

use crate::error::{check_components, InputError, Quantity};
use crate::rounding::{polytope_radius_up, polytope_support_slack, separation_down};
use crate::{Direction, Float, Point3, Pose, Vec3};

use super::hull_clusters::{clustered_support, HullCluster};
use super::simplex::nearest;

/// A convex body given by its support map.
///
/// `support(dir)` returns a point of the body farthest along `dir`: a
/// maximiser of `x . dir`. `dir` need not be unit length, and may be zero
/// (any point of the body is then a valid answer).
///
/// [`gjk_distance`]'s certified lower bound needs to know how far a
/// floating-point support map may fall short. [`support_slack`] is a bound
/// `e >= 0` such that, for every `dir` with `|dir| <= 2`,
/// `max_{x in body} x . dir <= support(dir) . dir + e`. The default is 0,
/// which is right for maps evaluated exactly; an implementation that rounds
/// must override it or the lower bound is not certified.
///
/// [`support_slack`]: SupportMap::support_slack
///
/// ```
/// use motion_bound::{gjk_distance, GjkParams, Point3, SupportMap, Vec3};
/// /// A ball, whose support is exact enough to ignore here.
/// struct Ball { centre: Point3<f64>, radius: f64 }
/// impl SupportMap<f64> for Ball {
///     fn support(&self, dir: Vec3<f64>) -> Point3<f64> {
///         self.centre + dir.normalize_or(Vec3::ZERO) * self.radius
///     }
///     fn support_slack(&self) -> f64 {
///         8.0 * f64::EPSILON * (self.centre.to_vec3().norm_l1() + self.radius)
///     }
/// }
/// let a = Ball { centre: Point3::ORIGIN, radius: 1.0 };
/// let b = Ball { centre: Point3::new(3.0, 0.0, 0.0), radius: 1.0 };
/// // Smooth bodies converge only asymptotically: loosen the tolerance.
/// let params = GjkParams::default().with_rel_tol(1e-6);
/// let r = gjk_distance(&a, &b, &params);
/// assert!(r.lower_bound <= 1.0 && r.distance >= r.lower_bound);
/// assert!(r.distance - 1.0 < 1e-5);
/// ```
pub trait SupportMap<T: Float> {
    /// A point of the body farthest along `dir`.
    fn support(&self, dir: Vec3<T>) -> Point3<T>;

    /// A bound of the support's shortfall for directions of length at most
    /// 2 (see the trait documentation). Default 0: exact.
    fn support_slack(&self) -> T {
        T::ZERO
    }
}

impl<T: Float, S: SupportMap<T> + ?Sized> SupportMap<T> for &S {
    #[inline]
    fn support(&self, dir: Vec3<T>) -> Point3<T> {
        (**self).support(dir)
    }
    #[inline]
    fn support_slack(&self) -> T {
        (**self).support_slack()
    }
}

/// A convex polytope: the convex hull of borrowed body-frame vertices `r_i`,
/// placed in the world by a [`Pose`] as `R r_i + x`.
///
/// The support map works in the body frame: it maps `dir` by `R^T`, takes
/// a vertex with the largest computed dot product (on ties, any of them;
/// `O(N)` in four interleaved lanes, no hill climbing), and places it with
/// [`Pose::transform_point`].
///
/// # Support slack
/// Let `m` be the largest `|R_kl|`, `rho >= max_i |r_i|_1` (computed and
/// rounded up) and `u` the unit roundoff. Rounding in `R^T dir`
/// (`gamma_3 m |dir|_1` per component), in the dot products
/// (`gamma_3 |r_i|_1 |R^T dir|_inf` each) and in `R r_j + x`
/// (`gamma_4 (m rho + |x|_inf)` per coordinate) make the returned point fall
/// short of the exact hull of the `R r_i + x` by at most
/// `|dir|_1 gamma_4 (6 m rho + |x|_inf)`; for `|dir| <= 2`, `|dir|_1 < 4`,
/// so [`support_slack`](SupportMap::support_slack) returns
/// `4 gamma_4 (6 m rho + |x|_inf)`, inflated by `1 + gamma_8` for its own
/// rounding, plus `64 eta (1 + m)(1 + rho)` for underflow. `R` need not be
/// orthonormal: the identity `(R r) . d = r . (R^T d)` holds for any matrix.
///
/// ```
/// use motion_bound::{ConvexPolytope, Point3, Pose, SupportMap, Vec3};
/// let square = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [1.0, 1.0, 0.0]];
/// let body = ConvexPolytope::try_new(&square, Pose::from_translation(Vec3::new(0.0, 0.0, 5.0)))?;
/// assert_eq!(body.support(Vec3::new(1.0, 1.0, 0.0)), Point3::new(1.0, 1.0, 5.0));
/// assert!(body.support_slack() < 1e-13);
/// # Ok::<(), motion_bound::InputError>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ConvexPolytope<'a, T> {
    vertices: &'a [[T; 3]],
    /// Clusters of the vertices (empty: the support scans them all).
    clusters: &'a [HullCluster<T>],
    pose: Pose<T>,
    rho: T,
    slack: T,
}

impl<'a, T: Float> ConvexPolytope<'a, T> {
    /// Validates the vertices and the pose (`O(N)`).
    ///
    /// # Errors
    /// [`InputError::EmptyVertexSet`]; [`InputError::NonFinite`] /
    /// [`InputError::TooLarge`] with [`Quantity::Vertex`] naming the first
    /// bad vertex, or with [`Quantity::Pose`] for the pose.
    pub fn try_new(vertices: &'a [[T; 3]], pose: Pose<T>) -> Result<Self, InputError> {
        if vertices.is_empty() {
            return Err(InputError::EmptyVertexSet);
        }
        let mut rho = T::ZERO;
        for (i, r) in vertices.iter().enumerate() {
            check_components(*r, Quantity::Vertex(i))?;
            rho = rho.max_nan(Vec3::from_array(*r).norm_l1());
        }
        // `fl(|r|_1)` may be below `|r|_1` by `gamma_2 |r|_1`.
        let rho = polytope_radius_up(rho);
        Self::placed(vertices, rho, pose)
    }

    /// The same vertices at another pose, without re-reading them (`O(1)`):
    /// what a conservative-advancement loop does at every step.
    ///
    /// # Errors
    /// [`InputError::NonFinite`] / [`InputError::TooLarge`] with
    /// [`Quantity::Pose`].
    pub fn with_pose(&self, pose: Pose<T>) -> Result<Self, InputError> {
        let mut placed = Self::placed(self.vertices, self.rho, pose)?;
        placed.clusters = self.clusters;
        Ok(placed)
    }

    /// The bound `rho` of the vertices' 1-norms, for
    /// [`with_radius`](Self::with_radius) (crate-internal: a validated
    /// polytope's vertices made again without reading them).
    #[cfg(feature = "alloc")]
    #[inline]
    pub(crate) const fn radius_l1(&self) -> T {
        self.rho
    }

    /// Vertices already validated by [`try_new`](Self::try_new), with the
    /// `rho` it computed ([`radius_l1`](Self::radius_l1)), at `pose`
    /// (`O(1)`; the pose is checked as in [`with_pose`](Self::with_pose)).
    #[cfg(feature = "alloc")]
    pub(crate) fn with_radius(
        vertices: &'a [[T; 3]],
        rho: T,
        pose: Pose<T>,
    ) -> Result<Self, InputError> {
        Self::placed(vertices, rho, pose)
    }

    fn placed(vertices: &'a [[T; 3]], rho: T, pose: Pose<T>) -> Result<Self, InputError> {
        for row in pose.rotation {
            check_components(row, Quantity::Pose)?;
        }
        check_components(pose.translation.to_array(), Quantity::Pose)?;
        let m = pose.rotation_max_abs();
        let x = pose.translation.max_abs();
        let slack = polytope_support_slack(m, rho, x);
        Ok(Self {
            vertices,
            clusters: &[],
            pose,
            rho,
            slack,
        })
    }

    /// The same polytope whose support scans `clusters` of its vertices
    /// (made by `hull_clusters::cluster_vertices` over exactly these
    /// vertices, in this order) and skips those that cannot hold the
    /// largest dot product (`proofs/floating-point.md`, "Clustered
    /// support"). Clusters that do not cover the vertices are ignored.
    #[cfg(feature = "alloc")]
    #[must_use]
    pub(crate) fn with_clusters(mut self, clusters: &'a [HullCluster<T>]) -> Self {
        let covers = clusters.first().is_some_and(|c| c.start == 0)
            && clusters.last().map(|c| c.end as usize) == Some(self.vertices.len())
            && clusters.windows(2).all(|w| w[0].end == w[1].start)
            && clusters.iter().all(|c| c.start < c.end);
        if covers {
            self.clusters = clusters;
        }
        self
    }

    /// The body-frame vertices.
    #[inline]
    #[must_use]
    pub const fn vertices(&self) -> &'a [[T; 3]] {
        self.vertices
    }

    /// The placement.
    #[inline]
    #[must_use]
    pub const fn pose(&self) -> &Pose<T> {
        &self.pose
    }
}

impl<T: Float> SupportMap<T> for ConvexPolytope<'_, T> {
    fn support(&self, dir: Vec3<T>) -> Point3<T> {
        let d = self.pose.inverse_transform_vector(dir);
        if !self.clusters.is_empty() {
            let i = clustered_support(self.vertices, self.clusters, d);
            return Point3::from_vec3(
                self.pose
                    .transform_point(Vec3::from_array(self.vertices[i])),
            );
        }
        let dot = |r: &[T; 3]| Vec3::from_array(*r).dot(d);
        // A vertex of the largest computed dot product (which one among ties
        // does not matter: `slack` bounds every vertex's rounding), found in
        // four independent lanes (vertex `4 c + k` in lane `k`), selects
        // without branches, so that the scan's chains overlap.
        let first = dot(&self.vertices[0]);
        let (mut bd, mut bi) = ([first; 4], [0usize; 4]);
        let chunks = self.vertices.chunks_exact(4);
        let rest = chunks.remainder();
        for (c, chunk) in chunks.enumerate() {
            for k in 0..4 {
                let s = dot(&chunk[k]);
                let better = s > bd[k];
                bd[k] = if better { s } else { bd[k] };
                bi[k] = if better { 4 * c + k } else { bi[k] };
            }
        }
        let base = self.vertices.len() - rest.len();
        for (k, r) in rest.iter().enumerate() {
            let s = dot(r);
            if s > bd[0] {
                bd[0] = s;
                bi[0] = base + k;
            }
        }
        let mut lane = 0;
        for k in 1..4 {
            if bd[k] > bd[lane] {
                lane = k;
            }
        }
        let best = Vec3::from_array(self.vertices[bi[lane]]);
        Point3::from_vec3(self.pose.transform_point(best))
    }

    #[inline]
    fn support_slack(&self) -> T {
        self.slack
    }
}

/// Termination controls for [`gjk_distance`].
#[derive(Clone, Copy, Debug, PartialEq)]
#[non_exhaustive]
pub struct GjkParams<T> {
    /// Stop when the gap between the current estimate `|v|` and the
    /// iteration's lower bound `w . v / |v|` is at most `rel_tol |v|`
    /// (van den Bergen's test `|v|^2 - v . w <= rel_tol |v|^2`). Default
    /// `2^8 u` (`2.8e-14` for `f64`, `1.5e-5` for `f32`).
    pub rel_tol: T,
    /// The most support-point iterations. Default 64, far more than a
    /// polytope needs (GJK ends after finitely many steps on polytopes);
    /// smooth bodies converge only asymptotically.
    pub max_iterations: u32,
}

impl<T: Float> Default for GjkParams<T> {
    fn default() -> Self {
        Self {
            rel_tol: T::from_u32(256) * T::UNIT_ROUNDOFF,
            max_iterations: 64,
        }
    }
}

impl<T: Float> GjkParams<T> {
    /// With another relative tolerance.
    #[must_use]
    pub const fn with_rel_tol(mut self, rel_tol: T) -> Self {
        self.rel_tol = rel_tol;
        self
    }

    /// With another iteration limit.
    #[must_use]
    pub const fn with_max_iterations(mut self, max_iterations: u32) -> Self {
        self.max_iterations = max_iterations;
        self
    }
}

/// What [`gjk_distance`] found.
///
/// # Guarantees
/// * **`lower_bound` is certified.** For every `a` in `A` and `b` in `B`,
///   `(b - a) . direction >= lower_bound` and `|b - a| >= lower_bound`,
///   with every rounding of the final check accounted for and the support
///   maps' shortfall covered by their
///   [`support_slack`](SupportMap::support_slack). It is computed from the
///   returned `direction` itself (two extra support calls), so it holds
///   whatever the iteration did, including at the iteration cap. It is 0
///   when nothing positive can be certified (intersection, touching, NaN).
///   When the bound from `-v` falls short of `distance` by more than
///   `max(64 u max|w|, rel_tol distance)`, a second direction, recomputed
///   orthogonal to the final simplex, is certified too (two more support
///   calls) and the better is kept: at a gap far below the bodies' size
///   (1e-9 at unit scale), the rounding of `v` along the simplex alone tilts
///   it enough to certify nothing. The rounding of the support points'
///   differences `w = a - b` (`u |w|` each) remains, so in a general frame a
///   gap below about `sqrt(u) s` (`s` the bodies' scale) may still certify
///   less than the distance, or 0; the bound stays sound.
/// * **`distance` is an estimate from above.** It is `|on_b - on_a|` for
///   convex combinations of support points, so it is at least the true
///   distance up to rounding and support slack. It **can over-estimate** the
///   true distance: when `converged` is true, by about
///   `rel_tol * distance` plus the rounding of the barycentric solve, which
///   is about `u s` (`s` the scale of the points) times the condition number
///   of the final simplex: a point on an edge of a sliver face 0.003 thin
///   converged at `1.46e-12` (about `6,600 u s`) from a true 0, with
///   `intersecting == false` and `lower_bound == 0` (the `gjk` fuzz
///   target's finding). When `converged` is false (iteration cap, or no
///   progress under rounding), by an amount that is not bounded. A
///   conservative-advancement step must
///   therefore use `lower_bound` (an over-estimate of the distance makes the
///   step too long), and `direction` as its `n`.
#[derive(Clone, Copy, Debug, PartialEq)]
#[non_exhaustive]
pub struct GjkResult<T> {
    /// The estimated distance `|on_b - on_a|` (0 when intersecting).
    pub distance: T,
    /// A certified lower bound of the distance, and of the separation
    /// along `direction` (see the type's documentation).
    pub lower_bound: T,
    /// The witness point on `A` (a common point when intersecting).
    pub on_a: Point3<T>,
    /// The witness point on `B` (equal to `on_a` when intersecting).
    pub on_b: Point3<T>,
    /// The unit direction from `A` towards `B` (`-v / |v|`, or its
    /// refinement orthogonal to the final simplex), or `None` when
    /// no positive separation along it can be certified (the bodies
    /// intersect or touch, are too close for a direction, or GJK stopped
    /// with a direction that does not separate them); then `lower_bound` is 0.
    pub direction: Option<Direction<T>>,
    /// The origin was found inside (or within rounding of) `A - B`.
    pub intersecting: bool,
    /// Termination by the tolerance test, a repeated support point or an
    /// intersection, rather than by the iteration cap or a stall.
    pub converged: bool,
    /// The number of support-point iterations taken.
    pub iterations: u32,
}

/// The distance between two convex bodies by GJK, with a certified lower
/// bound (see [`GjkResult`] for exactly what is guaranteed).
///
/// Never loops forever (at most `params.max_iterations` iterations) and
/// never panics; duplicate points, flat or collinear vertex sets and single
/// points are ordinary input. If a support map returns NaN the result has a
/// NaN `distance`, a zero `lower_bound` and `converged == false`.
///
/// ```
/// use motion_bound::{gjk_distance, ConvexPolytope, GjkParams, Pose, Vec3};
/// let cube: Vec<[f64; 3]> = (0..8)
///     .map(|i| [(i & 1) as f64, (i >> 1 & 1) as f64, (i >> 2 & 1) as f64])
///     .collect();
/// let a = ConvexPolytope::try_new(&cube, Pose::IDENTITY)?;
/// let b = ConvexPolytope::try_new(&cube, Pose::from_translation(Vec3::new(3.0, 0.5, 0.0)))?;
/// let r = gjk_distance(&a, &b, &GjkParams::default());
/// assert!(r.converged && !r.intersecting);
/// assert!((r.distance - 2.0).abs() < 1e-12);
/// assert!(r.lower_bound <= 2.0 && r.lower_bound > 2.0 - 1e-12);
/// let n = r.direction.unwrap().get();
/// assert!((n.x - 1.0).abs() < 1e-12);
///
/// let c = ConvexPolytope::try_new(&cube, Pose::from_translation(Vec3::new(0.5, 0.5, 0.5)))?;
/// let r = gjk_distance(&a, &c, &GjkParams::default());
/// assert!(r.intersecting && r.distance == 0.0 && r.lower_bound == 0.0);
/// # Ok::<(), motion_bound::InputError>(())
/// ```
#[must_use]
pub fn gjk_distance<T, A, B>(a: &A, b: &B, params: &GjkParams<T>) -> GjkResult<T>
where
    T: Float,
    A: SupportMap<T> + ?Sized,
    B: SupportMap<T> + ?Sized,
{
    gjk_distance_from(a, b, params, Vec3::new(T::ONE, T::ZERO, T::ZERO))
}

/// [`gjk_distance`] started from the supports along `towards` (`a`'s
/// along it, `b`'s against it): a direction from `a` towards `b` (the line
/// between their centres) starts near the answer and saves iterations. Any
/// direction is sound (only the first simplex point depends on it, and
/// every bound returned is certified along the final direction); a zero or
/// non-finite one is taken as `x`.
#[must_use]
pub(crate) fn gjk_distance_from<T, A, B>(
    a: &A,
    b: &B,
    params: &GjkParams<T>,
    towards: Vec3<T>,
) -> GjkResult<T>
where
    T: Float,
    A: SupportMap<T> + ?Sized,
    B: SupportMap<T> + ?Sized,
{
    let zero = T::ZERO;
    let u = T::UNIT_ROUNDOFF;
    let it = iterate(a, b, params, towards, |_, _| false);
    let (n, w, v, max_w2) = (it.n, it.w, it.v, it.max_w2);
    let (on_a, on_b) = (it.on_a, it.on_b);
    let (intersecting, converged, iterations) = (it.intersecting, it.converged, it.iterations);
    if intersecting {
        let m = Point3::from_vec3(on_a.lerp(on_b, T::HALF));
        return GjkResult {
            distance: zero,
            lower_bound: zero,
            on_a: m,
            on_b: m,
            direction: None,
            intersecting,
            converged,
            iterations,
        };
    }
    let distance = (on_b - on_a).length();
    let mut direction = if v.length() >= T::TINY_LENGTH {
        (-v).try_normalize()
    } else {
        None
    };
    let mut lower_bound =
        direction.map_or(zero, |d| certified_separation(a, b, d).min_nan(distance));
    // A rounded `v` is off the simplex's normal by about `u |w| / |v|`, which
    // at a tiny distance tilts `direction` enough to lose the separation over
    // the bodies' extent. When the bound falls short of the distance by more
    // than rounding, the direction recomputed orthogonal to the support
    // simplex is tried as well; any direction certifies soundly, so the
    // better of the two is kept.
    // A bound short by `rel_tol distance` is GJK's own stopping gap, which a
    // new direction cannot close.
    let short = (T::from_u32(64) * u * max_w2.sqrt()).max_nan(params.rel_tol * distance);
    if !(distance - lower_bound <= short) {
        if let Some(d) = refined_direction(&w[..n], v) {
            let lb = certified_separation(a, b, d).min_nan(distance);
            if lb > lower_bound {
                lower_bound = lb;
                direction = Some(d);
            }
        }
    }
    // A direction is returned only with a positive certified separation
    // along it: one that does not separate the bodies (GJK stopped early, or
    // they touch) certifies nothing, and `lower_bound` is then 0.
    let (lower_bound, direction) = if lower_bound > zero {
        (lower_bound, direction)
    } else {
        (zero, None)
    };
    GjkResult {
        distance,
        lower_bound,
        on_a: Point3::from_vec3(on_a),
        on_b: Point3::from_vec3(on_b),
        // A normalisation of a vector whose squared length is normal (both
        // candidates are), within `gamma_5` of unit length.
        direction: direction.map(Direction::from_normalized),
        intersecting,
        converged,
        iterations,
    }
}

/// Where GJK's iteration ended: the support simplex `w[..n]`, its nearest
/// point `v` to the origin, the witnesses (the same convex combination of
/// the support points of `A` and of `B`), and how it ended.
struct Iterated<T> {
    n: usize,
    w: [Vec3<T>; 4],
    v: Vec3<T>,
    max_w2: T,
    on_a: Vec3<T>,
    on_b: Vec3<T>,
    intersecting: bool,
    converged: bool,
    iterations: u32,
}

/// GJK's iteration (see [`gjk_distance`]; started along `towards` as
/// [`gjk_distance_from`] is), ended also as soon as
/// `stop(v . v, v . w)` holds for the current `v` and the new support point
/// `w` (then `converged` is set): `v . w / |v|` is the iteration's lower
/// bound of the distance (the slab gap of `A - B` along `-v`, before
/// rounding), `|v|` its estimate from above.
fn iterate<T, A, B, F>(
    a: &A,
    b: &B,
    params: &GjkParams<T>,
    towards: Vec3<T>,
    mut stop: F,
) -> Iterated<T>
where
    T: Float,
    A: SupportMap<T> + ?Sized,
    B: SupportMap<T> + ?Sized,
    F: FnMut(T, T) -> bool,
{
    let zero = T::ZERO;
    let u = T::UNIT_ROUNDOFF;
    let e0 = if towards.is_finite() && towards.length_squared() > zero {
        towards
    } else {
        Vec3::new(T::ONE, zero, zero)
    };
    let mut pa = [Vec3::ZERO; 4];
    let mut pb = [Vec3::ZERO; 4];
    let mut w = [Vec3::ZERO; 4];
    pa[0] = a.support(e0).to_vec3();
    pb[0] = b.support(-e0).to_vec3();
    w[0] = pa[0] - pb[0];
    let mut n = 1;
    let mut lambda = [T::ONE, zero, zero, zero];
    let mut v = w[0];
    let mut vv = v.length_squared();
    let mut iterations = 0;
    let mut converged = false;
    let mut intersecting = vv == zero;
    let mut max_w2 = vv;
    if intersecting {
        converged = true;
    }
    while !intersecting && !vv.is_nan() && iterations < params.max_iterations {
        iterations += 1;
        let (sa, sb) = (a.support(-v).to_vec3(), b.support(v).to_vec3());
        let wk = sa - sb;
        let vw = v.dot(wk);
        if vv - vw <= params.rel_tol * vv || w[..n].contains(&wk) || stop(vv, vw) {
            converged = true;
            break;
        }
        let mut trial = w;
        trial[n] = wk;
        let r = nearest(&trial[..=n]);
        if r.contains_origin {
            pa[n] = sa;
            pb[n] = sb;
            n += 1;
            lambda = r.lambda;
            intersecting = true;
            converged = true;
            break;
        }
        let r_vv = r.v.length_squared();
        if !(r_vv < vv) {
            break; // no progress under rounding: keep the previous simplex
        }
        pa[n] = sa;
        pb[n] = sb;
        w[n] = wk;
        max_w2 = max_w2.max_nan(wk.length_squared());
        // Keep the support set, compacted.
        let mut k = 0;
        for i in 0..=n {
            if r.mask & (1 << i) != 0 {
                pa[k] = pa[i];
                pb[k] = pb[i];
                w[k] = w[i];
                lambda[k] = r.lambda[i];
                k += 1;
            }
        }
        n = k;
        v = r.v;
        vv = r_vv;
        // The origin within rounding of the simplex: touching or overlapping.
        let tiny = T::from_u32(64) * u;
        if vv <= tiny * tiny * max_w2 {
            intersecting = true;
            converged = true;
        }
    }
    let mut on_a = Vec3::ZERO;
    let mut on_b = Vec3::ZERO;
    for i in 0..n {
        on_a = on_a + pa[i] * lambda[i];
        on_b = on_b + pb[i] * lambda[i];
    }
    Iterated {
        n,
        w,
        v,
        max_w2,
        on_a,
        on_b,
        intersecting,
        converged,
        iterations,
    }
}

/// The closest points' estimates `(on_a, on_b)` of GJK's iteration ended
/// by the caller's rule `stop(v . v, v . w)` as well as by `params` (see
/// [`iterate`]), with no certification: for a caller that only chooses a
/// direction from them and certifies its own gap along it
/// (`proofs/12-shapes.md`, the lemma "The closest direction, to the
/// stepper's need"). Equal points when the bodies intersect (as far as
/// rounding tells).
pub(crate) fn gjk_closest<T, A, B, F>(
    a: &A,
    b: &B,
    params: &GjkParams<T>,
    stop: F,
) -> (Vec3<T>, Vec3<T>)
where
    T: Float,
    A: SupportMap<T> + ?Sized,
    B: SupportMap<T> + ?Sized,
    F: FnMut(T, T) -> bool,
{
    let it = iterate(a, b, params, Vec3::new(T::ONE, T::ZERO, T::ZERO), stop);
    if it.intersecting {
        let m = it.on_a.lerp(it.on_b, T::HALF);
        (m, m)
    } else {
        (it.on_a, it.on_b)
    }
}

/// The unit direction from the origin's nearest point of the support
/// simplex `w` (two or three points, `v` its rounded nearest point; a single
/// point gives `v = w0` exactly and `None` here) towards the origin,
/// recomputed orthogonal to the simplex. For a segment: `v` minus its
/// component along the edge `e`, `v - e (v . e) / (e . e)`. For a triangle:
/// the plane's nearest point `n (w0 . n) / (n . n)`, `n = e1 x e2`, which
/// does not use `v` at all. This removes the rounding of `v` *along* the
/// simplex, which GJK's barycentric combination leaves at about `u |w|`.
/// It does not remove the rounding of the points `w` themselves (`u |w|`
/// each, perpendicular to the simplex too), nor, for a thin triangle, the
/// rounding of `n` (about `u` times the triangle's conditioning); and in
/// `f32`, `n . n ~ |e|^4` under- or overflows for edges below `2^-37` or
/// above `2^32`, when the refinement returns `None`. Only a candidate: the
/// caller certifies it.
fn refined_direction<T: Float>(w: &[Vec3<T>], v: Vec3<T>) -> Option<Vec3<T>> {
    let r = match *w {
        [w0, w1] => {
            let e = w1 - w0;
            let ee = e.length_squared();
            if !(ee > T::ZERO) {
                return None;
            }
            v - e * (v.dot(e) / ee)
        }
        [w0, w1, w2] => {
            let nrm = (w1 - w0).cross(w2 - w0);
            let nn = nrm.length_squared();
            if !(nn > T::ZERO) {
                return None;
            }
            nrm * (w0.dot(nrm) / nn)
        }
        _ => return None,
    };
    if r.length() >= T::TINY_LENGTH {
        (-r).try_normalize()
    } else {
        None
    }
}

/// A certified lower bound of `min_{a, b} (b - a) . n` and, divided by an
/// upper bound of `|n|`, of the distance, for a computed unit vector `n`
/// (`|n| <= 1 + gamma_6`). With `alpha = fl(s_A(n) . n)` and
/// `beta = fl(s_B(-n) . n)`:
/// `max_a a . n <= alpha + gamma_3 sum|s_A(n)_k n_k| + e_A` and
/// `min_b b . n >= beta - gamma_3 sum|s_B(-n)_k n_k| - e_B`, so the
/// separation is at least `fl(beta - alpha) - M` with `M` the rounding of
/// the subtraction (`u |fl(beta - alpha)|`) plus those terms, `M` inflated by
/// `1 + gamma_4` for its own evaluation and by `8 eta` for underflow; the
/// final subtraction and the division by `1 + gamma_6` are rounded down by
/// the factor `1 - gamma_8`.
fn certified_separation<T, A, B>(a: &A, b: &B, n: Vec3<T>) -> T
where
    T: Float,
    A: SupportMap<T> + ?Sized,
    B: SupportMap<T> + ?Sized,
{
    let (sa, sb) = (a.support(n).to_vec3(), b.support(-n).to_vec3());
    let alpha = sa.dot(n);
    let beta = sb.dot(n);
    let delta = beta - alpha;
    separation_down(
        delta,
        sa.dot_abs(n) + sb.dot_abs(n),
        a.support_slack() + b.support_slack(),
    )
}

#[cfg(test)]
mod tests {
    use super::{gjk_distance, ConvexPolytope, GjkParams, SupportMap};
    use crate::{InputError, Point3, Pose, Quantity, Vec3};

    #[test]
    fn rejects_bad_input() {
        let empty: [[f64; 3]; 0] = [];
        assert_eq!(
            ConvexPolytope::try_new(&empty, Pose::IDENTITY),
            Err(InputError::EmptyVertexSet),
            "empty"
        );
        let bad = [[0.0, f64::NAN, 0.0]];
        assert_eq!(
            ConvexPolytope::try_new(&bad, Pose::IDENTITY),
            Err(InputError::NonFinite(Quantity::Vertex(0))),
            "NaN vertex"
        );
        let ok = [[0.0; 3]];
        let mut pose = Pose::IDENTITY;
        pose.translation.z = f64::INFINITY;
        assert_eq!(
            ConvexPolytope::try_new(&ok, pose),
            Err(InputError::NonFinite(Quantity::Pose)),
            "infinite translation"
        );
    }

    #[test]
    fn single_points_and_duplicates() {
        let p = [[1.0f64, 2.0, 3.0]];
        let q = [[1.0f64, 2.0, 7.0], [1.0, 2.0, 7.0], [1.0, 2.0, 7.0]];
        let a = ConvexPolytope::try_new(&p, Pose::IDENTITY).unwrap();
        let b = ConvexPolytope::try_new(&q, Pose::IDENTITY).unwrap();
        let r = gjk_distance(&a, &b, &GjkParams::default());
        assert_eq!(r.distance, 4.0, "two points");
        assert!(r.converged && !r.intersecting, "converged");
        assert!(
            r.lower_bound <= 4.0 && r.lower_bound > 4.0 - 1e-12,
            "bound {}",
            r.lower_bound
        );
        let r = gjk_distance(&a, &a, &GjkParams::default());
        assert!(r.intersecting && r.distance == 0.0, "a point and itself");
    }

    /// A segment 1e-9 below another at unit scale (found by a random
    /// proptest run of tests/geometry.rs). GJK's `v` is off the normal by
    /// about `u / 1e-9` radians, which over the unit extent loses the whole
    /// separation: the bound was 0. The refined direction keeps it within
    /// rounding of the distance.
    #[test]
    fn a_tiny_gap_is_certified_within_rounding() {
        let y = 0.993_948_810_464_696_4;
        let a = [[-1.0f64, y, 0.0], [-1.0, -1.0, 0.0], [-1.0, y, 0.0]];
        let b = [[0.0f64, 0.0, 1e-9], [0.0, 0.0, 1e-9], [-1.0, 0.5, 1e-9]];
        let pa = ConvexPolytope::try_new(&a, Pose::IDENTITY).unwrap();
        let pb = ConvexPolytope::try_new(&b, Pose::IDENTITY).unwrap();
        for (p, q) in [(&pa, &pb), (&pb, &pa)] {
            let r = gjk_distance(p, q, &GjkParams::default());
            assert!(r.converged && !r.intersecting, "{r:?}");
            // The certificate's own margin: the support slacks (a few
            // hundred `u` at unit scale) and the dot products' rounding
            // (`gamma_3 |s . n|`, at most `4 u` here).
            let u = f64::EPSILON / 2.0;
            let margin = 4.0 * (p.support_slack() + q.support_slack()) + 16.0 * u;
            assert!(
                r.lower_bound <= 1e-9 && r.lower_bound >= 1e-9 - margin,
                "bound {} for a gap of 1e-9",
                r.lower_bound
            );
            assert!(r.direction.is_some(), "a certified direction");
        }
    }

    #[test]
    fn nan_support_terminates() {
        struct Nan;
        impl SupportMap<f64> for Nan {
            fn support(&self, _: Vec3<f64>) -> Point3<f64> {
                Point3::new(f64::NAN, 0.0, 0.0)
            }
        }
        let r = gjk_distance(&Nan, &Nan, &GjkParams::default());
        assert!(
            r.distance.is_nan() && r.lower_bound == 0.0 && !r.converged,
            "{r:?}"
        );
    }

    #[test]
    fn with_pose_keeps_vertices() {
        let tet = [
            [0.0f32, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [0.0, 1.0, 0.0],
            [0.0, 0.0, 1.0],
        ];
        let a = ConvexPolytope::try_new(&tet, Pose::IDENTITY).unwrap();
        let b = a
            .with_pose(Pose::from_translation(Vec3::new(0.0, 0.0, 3.0)))
            .unwrap();
        assert_eq!(b.vertices(), &tet, "same slice");
        let r = gjk_distance(&a, &b, &GjkParams::default());
        assert!(
            (r.distance - 2.0).abs() < 1e-6,
            "f32 distance {}",
            r.distance
        );
        assert!(r.lower_bound <= 2.0, "f32 bound {}", r.lower_bound);
    }
}
