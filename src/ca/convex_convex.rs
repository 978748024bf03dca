//! Conservative advancement of two convex shapes (cores with radii).

use crate::ca::step::{placement_error, precision_limit};
use crate::ca::{CaParams, CaStep, StepResult, Witness};
use crate::geometry::closest::segment_segment_vec;
use crate::geometry::gjk::{gjk_closest, GjkParams, SupportMap};
use crate::rounding::{gap_down, step_down, sum_up};
use crate::shape::convex::Core;
use crate::{BoundingBall, Convex, Direction, Float, Point3, Pose, PreparedMotion, Vec3};

/// Conservative advancement of two convex shapes (a [`CaStep`]): balls,
/// capsules, cuboids, cylinders, cones and polytopes, rounded or not, in any
/// pairing.
///
/// Each step places both cores, finds their closest points (in closed form
/// for points and segments: balls and capsules; by GJK on the cores'
/// support maps otherwise), declares contact when the cores' distance less
/// both radii is at most the contact distance, and otherwise measures the
/// certified slab gap along the closest direction from the shapes' own
/// supports (the cores' support less the radii: `proofs/12-shapes.md`,
/// Lemma 12.1), which it divides by the shapes' directed bounds (Lemma
/// 12.2). GJK's distance is only used to choose the direction and to declare
/// contact, never for soundness.
///
/// ```
/// use motion_bound::ca::{time_of_impact, CaParams, ConvexPair};
/// use motion_bound::{Convex, RigidMotion};
/// // A capsule falls on a cuboid: its lower end (y = -0.5 - 0.25) meets the
/// // box's top (y = 0.5) after 2 - 0.75 - 0.5 = 0.75 at speed 2.
/// let capsule = Convex::try_capsule(0.5, 0.25)?;
/// let slab = Convex::try_cuboid([2.0, 0.5, 2.0])?;
/// let a = RigidMotion::try_from_arrays([0.0, 2.0, 0.0], [0.0, -2.0, 0.0], [0.0; 3])?;
/// let b = RigidMotion::try_from_arrays([0.0; 3], [0.0; 3], [0.0; 3])?;
/// let report = time_of_impact(&mut ConvexPair::new(capsule, slab), &a, &b, &CaParams::default())?;
/// let t = report.outcome.contact().expect("they touch").time;
/// assert!(t <= 0.375 && t > 0.375 - 1e-4, "t = {t}");
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Clone, Copy, Debug)]
pub struct ConvexPair<'a, T> {
    a: Convex<'a, T>,
    b: Convex<'a, T>,
}

impl<'a, T: Float> ConvexPair<'a, T> {
    /// The pair of shapes `a` and `b`, each in its body frame.
    #[must_use]
    pub const fn new(a: Convex<'a, T>, b: Convex<'a, T>) -> Self {
        Self { a, b }
    }
}

/// A core placed by a pose, as a support map for GJK. Its slack is not
/// given (zero): GJK's lower bound is not used, the gap is certified by
/// [`certified_gap`].
pub(crate) struct PlacedCore<'s, 'a, T> {
    pub(crate) shape: &'s Convex<'a, T>,
    pub(crate) pose: &'s Pose<T>,
}

impl<T: Float> SupportMap<T> for PlacedCore<'_, '_, T> {
    fn support(&self, dir: Vec3<T>) -> Point3<T> {
        let local = self
            .shape
            .core_support_point(self.pose.inverse_transform_vector(dir));
        Point3::from_vec3(self.pose.transform_point(local.to_vec3()))
    }
}

/// The ends of a point or segment core, placed in the body frame by the
/// shape's own placement (a compound's part) and in the world by `pose`
/// (`None` for other cores).
fn segment<T: Float>(shape: &Convex<'_, T>, pose: &Pose<T>) -> Option<[Vec3<T>; 2]> {
    let z = T::ZERO;
    let h = match *shape.core() {
        Core::Point => z,
        Core::Segment { half_height } => half_height,
        _ => return None,
    };
    let end = |y: T| pose.transform_point(shape.place_core_point(Vec3::new(z, y, z)));
    Some([end(-h), end(h)])
}

/// A lower bound of the slab gap, along the exact unit `n/|n|`, between
/// shape `A` placed by `pa` and shape `B` placed by `pb` at their exact
/// positions (within `err_*` of the placed ones): `proofs/12-shapes.md`,
/// Lemma 12.1 and section "Support". `<= 0` when not separated along `n`.
pub(crate) fn certified_gap<T: Float>(
    (a, pa, err_a): (&Convex<'_, T>, &Pose<T>, T),
    b: (&Convex<'_, T>, &Pose<T>, T),
    n: Vec3<T>,
) -> T {
    // The largest `x . n` over A: its placed centre's, its core's support
    // along `M^T n`, its radius.
    let upper_a =
        pa.translation.dot(n) + a.core_support_value(pa.inverse_transform_vector(n)) + a.radius();
    certified_gap_to(upper_a, weight(a, pa), err_a, b, n)
}

/// The weight of a placed shape's support evaluation: `|x|_1` of its
/// placement, its core's weight and its radius, rounded up.
fn weight<T: Float>(s: &Convex<'_, T>, p: &Pose<T>) -> T {
    sum_up(sum_up(p.translation.norm_l1(), s.weight()), s.radius())
}

/// [`certified_gap`] from A's computed support value `upper_a` along `n`
/// (the largest computed `x . n` over A, each term within `64 u` of
/// `weight_a`, an upper bound of A's points' `|x|_1`) to shape `B` placed by
/// `pb`, its placed points within `err_b` of the exact ones.
fn certified_gap_to<T: Float>(
    upper_a: T,
    weight_a: T,
    err_a: T,
    (b, pb, err_b): (&Convex<'_, T>, &Pose<T>, T),
    n: Vec3<T>,
) -> T {
    // `gap_down` covers `gamma_8` of the reach it is given; the support's
    // evaluation needs `64 u` of the weights (section "Support").
    let reach = T::from_u32(8) * sum_up(weight_a, weight(b, pb));
    gap_down(lower_support(b, pb, n) - upper_a, err_a, err_b, reach)
}

/// The least computed `x . n` over shape `b` placed by `pb`: its
/// translation's part, less its core's support along `-M^T n` and its
/// radius.
fn lower_support<T: Float>(b: &Convex<'_, T>, pb: &Pose<T>, n: Vec3<T>) -> T {
    pb.translation.dot(n) - b.core_support_value(pb.inverse_transform_vector(-n)) - b.radius()
}

/// An upper bound of how far [`lower_support`] (and the share of it in the
/// gap's subtraction) may be from the exact least `x . n` over shape `b`
/// placed by the **exact** pose `pb` (its numbers taken as exact, as a
/// chain's still obstacles are), for every `n` with `|n| <= 1 + gamma_5`:
/// `u (7 |x|_1 + (8 + k) c W + 8 rho)` rounded up, with `k` the core's own
/// rounding ([`Convex::support_rounding`]), `c` the largest column length of
/// the pose's matrix and `W` the core's weight, plus the underflow terms
/// (`proofs/12-shapes.md`, section "Support at an exact pose"). A core
/// placed in the body frame (a compound's part) takes the rigid bound,
/// `80 u max(c, 1) W'`. Computed once per obstacle.
#[cfg(feature = "alloc")]
pub(crate) fn support_error_up<T: Float>(b: &Convex<'_, T>, pb: &Pose<T>) -> T {
    let u = T::UNIT_ROUNDOFF;
    let x = sum_up(pb.translation.norm_l1(), T::ZERO);
    let (w, rho) = (b.weight(), b.radius());
    // The largest column length of the pose's matrix, rounded up (unused,
    // and not computed, for a point core).
    let c = if w > T::ZERO {
        let m = &pb.rotation;
        let sq = (0..3)
            .map(|i| m[0][i] * m[0][i] + m[1][i] * m[1][i] + m[2][i] * m[2][i])
            .fold(T::ZERO, T::max_nan);
        crate::rounding::radius_up(sq)
    } else {
        T::ZERO
    };
    let cw = c * w;
    let body = match b.support_rounding() {
        Some(k) => T::from_u32(7) * x + T::from_u32(8 + k) * cw + T::from_u32(8) * rho,
        None => T::from_u32(80) * (x + c.max_nan(T::ONE) * w + rho),
    };
    let under = T::from_u32(16) * T::ETA_NORMAL * (T::ONE + cw) + T::TWO * cw * T::SQRT_ETA_UP;
    let e = body * u * (T::ONE + crate::rounding::gamma::<T>(8)) + under;
    if e.is_nan() {
        T::INFINITY
    } else {
        e
    }
}

/// The certified slab gap along the exact unit `n/|n|` from A (its computed
/// largest `x . n` is `upper_a`, within `7 u weight_a` of A's exact one,
/// `|upper_a| <= weight_a`, A's points within `err_a` of their exact
/// places) to shape `B` at the exact pose `pb`, whose support's rounding is
/// at most `e_b` ([`support_error_up`]): what a chain's queries measure
/// from a link's ball, box or triangle to a still shape obstacle
/// (`proofs/13-chains.md`, Lemmas 13.6 and 13.14). `<= 0` when not
/// separated along `n`.
#[cfg(feature = "alloc")]
pub(crate) fn certified_gap_to_exact<T: Float>(
    upper_a: T,
    weight_a: T,
    err_a: T,
    (b, pb, e_b): (&Convex<'_, T>, &Pose<T>, T),
    n: Vec3<T>,
) -> T {
    // `gamma_8 weight_a` covers A's `7 u` and its share of the subtraction.
    gap_down(lower_support(b, pb, n) - upper_a, err_a, e_b, weight_a)
}

impl<T: Float> CaStep<T> for ConvexPair<'_, T> {
    fn bounding_balls(&self) -> Option<(BoundingBall<T>, BoundingBall<T>)> {
        let ball = |s: &Convex<'_, T>| BoundingBall::try_new([T::ZERO; 3], s.reach()).ok();
        Some((ball(&self.a)?, ball(&self.b)?))
    }

    fn step(
        &mut self,
        t: T,
        a: &PreparedMotion<T>,
        b: &PreparedMotion<T>,
        params: &CaParams<T>,
    ) -> StepResult<T> {
        let (pose_a, pose_b) = (a.motion().pose_at(t), b.motion().pose_at(t));
        let (ra, rb) = (self.a.radius(), self.b.radius());
        // The cores' closest points: in closed form for points and
        // segments, else by GJK.
        let (on_a, on_b) = match (segment(&self.a, &pose_a), segment(&self.b, &pose_b)) {
            (Some([p0, p1]), Some([q0, q1])) => {
                let c = segment_segment_vec(p0, p1, q0, q1);
                (c.on_a, c.on_b)
            }
            _ => gjk_closest(
                &PlacedCore {
                    shape: &self.a,
                    pose: &pose_a,
                },
                &PlacedCore {
                    shape: &self.b,
                    pose: &pose_b,
                },
                &GjkParams::default().with_rel_tol(gjk_tolerance::<T>()),
                enough(ra + rb, params),
            ),
        };
        let core_distance = (on_b - on_a).length();
        let dir = Direction::try_new(on_b - on_a);
        let distance = (core_distance - ra - rb).max_nan(T::ZERO);
        let witness = |n: Option<Direction<T>>| {
            let (wa, wb) = match n {
                Some(n) => (on_a + n.get() * ra, on_b - n.get() * rb),
                None => (on_a, on_b),
            };
            Witness::new(distance, Point3::from_vec3(wa), Point3::from_vec3(wb))
        };
        let Ok(n) = dir else {
            return StepResult::Touching {
                witness: witness(None),
                normal: None,
            };
        };
        if distance <= params.contact_distance || distance.is_nan() {
            return StepResult::Touching {
                witness: witness(Some(n)),
                normal: Some(n),
            };
        }
        let (ea, reach_a) = placement_error(a.motion(), t, self.a.reach());
        let (eb, reach_b) = placement_error(b.motion(), t, self.b.reach());
        let g = certified_gap((&self.a, &pose_a, ea), (&self.b, &pose_b, eb), n.get());
        let mu = closing((a, &self.a), (b, &self.b), n, params);
        // Where the closest direction lost more than half the distance (a
        // curved core nearly touching a box in `f32`), a box's face normal
        // too; the longer step is taken (both are safe, Lemma 12.1).
        let clearance = params.clearance();
        let (mut g, mut mu, mut dir) = (g, mu, n);
        if g < (distance - clearance) * T::HALF {
            let faces = [
                self.a.face_normal(&pose_a, n.get()),
                self.b.face_normal(&pose_b, -n.get()).map(|f| -f),
            ];
            for face in faces.into_iter().flatten() {
                let Ok(m) = Direction::try_new(face) else {
                    continue;
                };
                let g2 = certified_gap((&self.a, &pose_a, ea), (&self.b, &pose_b, eb), m.get());
                let mu2 = closing((a, &self.a), (b, &self.b), m, params);
                if step_down(g2, clearance, mu2.0, mu2.1) > step_down(g, clearance, mu.0, mu.1) {
                    (g, mu, dir) = (g2, mu2, m);
                }
            }
        }
        advance(
            g,
            mu,
            ((ea, eb), (reach_a, reach_b)),
            params,
            (witness(Some(n)), dir),
        )
    }
}

/// The bounds on how fast the slab between shapes `A` and `B` along `n`
/// (from A to B) closes: the one-sided rates of A's support along `n` and
/// B's along `-n` (Lemma 10.2 with Lemma 12.5: motion that maps a shape
/// onto itself does not count), or, without one-sided bounds, their
/// absolute speeds.
pub(crate) fn closing<T: Float>(
    (a, sa): (&PreparedMotion<T>, &Convex<'_, T>),
    (b, sb): (&PreparedMotion<T>, &Convex<'_, T>),
    n: Direction<T>,
    params: &CaParams<T>,
) -> (T, T) {
    let kind = params.bound.cheap_kind();
    if params.one_sided {
        (
            a.probe(n).convex_support_rate(sa, kind),
            b.probe(-n).convex_support_rate(sb, kind),
        )
    } else {
        (
            a.probe(n).convex_support_speed(sa, kind),
            b.probe(n).convex_support_speed(sb, kind),
        )
    }
}

/// The step from the certified gap `g` and the closing bounds `mu`, or the
/// precision limit when it is zero and the placement (errors and reaches)
/// cannot resolve the clearance.
pub(crate) fn advance<T: Float>(
    g: T,
    mu: (T, T),
    (err, reach): ((T, T), (T, T)),
    params: &CaParams<T>,
    (witness, n): (Witness<T>, Direction<T>),
) -> StepResult<T> {
    let clearance = params.clearance();
    let step = step_down(g, clearance, mu.0, mu.1);
    if let Some(limit) = precision_limit(step, clearance, err, reach) {
        return limit;
    }
    StepResult::Advance {
        step,
        witness: Some(witness),
        normal: Some(n),
    }
}

/// The share of the useful gap that GJK's duality gap may keep when it
/// stops early for a stepper: `1/32` (`proofs/12-shapes.md`, the lemma
/// "The closest direction, to the stepper's need").
pub(crate) const ENOUGH: f64 = 1.0 / 32.0;

/// GJK's early stop for a stepper whose shapes' radii sum to `r`, as a
/// rule on `(v . v, v . w)` (see `gjk_closest`): the cores' estimate
/// `|v|` already declares contact (`|v| - r <= contact distance`), or the
/// iteration's lower bound `v . w / |v|` is short of `|v|` by at most
/// `ENOUGH` of the gap the step would use, `|v| - r - clearance`: the
/// step along `-v` is then at least `1 - ENOUGH` of the step the exact
/// distance would give, before rounding. Only a choice of direction and
/// of when to declare contact: the gap along the direction is certified
/// by the caller (Lemma 12.1).
pub(crate) fn enough<T: Float>(r: T, params: &CaParams<T>) -> impl Fn(T, T) -> bool {
    enough_within(r, params.contact_distance, params.clearance())
}

/// [`enough`] with the contact distance `cd` and the clearance given
/// apart (a mesh node's direction, `MeshConvexPair`, Lemma 12.12).
pub(crate) fn enough_within<T: Float>(r: T, cd: T, clearance: T) -> impl Fn(T, T) -> bool {
    let kappa = T::from_f64(ENOUGH);
    move |vv: T, vw: T| {
        let d = vv.sqrt();
        d - r <= cd || vv - vw <= kappa * d * (d - r - clearance)
    }
}

/// GJK's relative tolerance for curved cores (which converge only
/// asymptotically): `2^-30`, or `256 u` where that is larger (`f32`). The
/// direction it gives is only a choice (Lemma 12.1 holds for any).
pub(crate) fn gjk_tolerance<T: Float>() -> T {
    (T::from_u32(256) * T::UNIT_ROUNDOFF).max_nan(T::from_f64(1.0 / 1_073_741_824.0))
}

#[cfg(test)]
pub(crate) mod tests {
    //! The early stop's two promises (`proofs/12-shapes.md`, the lemma "The
    //! closest direction, to the stepper's need"), for a curved core placed
    //! at a random rotation near an axis-aligned box, in `f32` and `f64`,
    //! against the distance measured by dense sampling of the true curved
    //! surface: the gap certified along the direction never exceeds it
    //! (sound), and falls short of it by at most the share `ENOUGH` of the
    //! gap the step uses (the early stop costs at most that share of a step).
    extern crate std;
    use std::vec::Vec;

    use super::{certified_gap, enough, gjk_tolerance, PlacedCore, ENOUGH};
    use crate::ca::CaParams;
    use crate::geometry::gjk::{gjk_closest, GjkParams};
    use crate::rng::SplitMix64;
    use crate::{Convex, Float, Pose, Rotation, Vec3};

    /// A curved core's surface points in its frame (`f64`), by the
    /// parameters `(s, t)` in `[0, 1]^2` of three pieces (`piece` 0: the
    /// side, 1 and 2: the ends), exactly on the true surface up to `f64`
    /// rounding.
    fn surface(cone: bool, h: f64, rho: f64, piece: usize, s: f64, t: f64) -> [f64; 3] {
        let phi = s * core::f64::consts::TAU;
        let (c, sn) = (phi.cos(), phi.sin());
        match (piece, cone) {
            // The side: the lateral line from the base rim up.
            (0, false) => [rho * c, h * (2.0 * t - 1.0), rho * sn],
            (0, true) => [
                rho * (1.0 - t) * c,
                h * (2.0 * t - 1.0),
                rho * (1.0 - t) * sn,
            ],
            // The ends: discs (a cone's top is its apex).
            (1, false) => [rho * t * c, h, rho * t * sn],
            (1, true) => [0.0, h, 0.0],
            _ => [rho * t * c, -h, rho * t * sn],
        }
    }

    /// The distance from `x` to the box `[-b, b]` (axis-aligned, at the
    /// origin), in `f64`.
    fn to_box(x: [f64; 3], b: [f64; 3]) -> f64 {
        let e = [0, 1, 2].map(|k| (x[k].abs() - b[k]).max(0.0));
        (e[0] * e[0] + e[1] * e[1] + e[2] * e[2]).sqrt()
    }

    /// The least distance from the placed core's sampled points to the
    /// box: a grid over each piece of its surface, then alternating
    /// projections from the grid's best local minima. Every sample is a
    /// point of the placed core (`M k + t` for a core point `k`, computed
    /// in `f64` from the stored values), so the result is never below the
    /// true distance, up to `f64` rounding.
    fn sampled_distance(
        cone: bool,
        (h, rho): (f64, f64),
        (m, c): ([[f64; 3]; 3], [f64; 3]),
        b: [f64; 3],
    ) -> f64 {
        let place = |p: [f64; 3]| {
            [0, 1, 2].map(|i| m[i][0] * p[0] + m[i][1] * p[1] + m[i][2] * p[2] + c[i])
        };
        let f = |piece: usize, s: f64, t: f64| {
            to_box(place(surface(cone, h, rho, piece, s, t.clamp(0.0, 1.0))), b)
        };
        // Seeds: every local minimum of each piece's grid (periodic in `s`),
        // each refined by a pattern search.
        let (ns, nt) = (128, 16);
        let mut seeds: Vec<(f64, usize, f64, f64)> = Vec::new();
        for piece in 0..3 {
            let grid: Vec<Vec<f64>> = (0..ns)
                .map(|i| {
                    (0..=nt)
                        .map(|j| f(piece, i as f64 / ns as f64, j as f64 / nt as f64))
                        .collect()
                })
                .collect();
            for i in 0..ns {
                for j in 0..=nt {
                    let d = grid[i][j];
                    let mut local = true;
                    for a in [ns - 1, 0, 1] {
                        for b2 in [-1i32, 0, 1] {
                            let jj = j as i32 + b2;
                            if jj >= 0 && jj <= nt as i32 && grid[(i + a) % ns][jj as usize] < d {
                                local = false;
                            }
                        }
                    }
                    if local {
                        seeds.push((d, piece, i as f64 / ns as f64, j as f64 / nt as f64));
                    }
                }
            }
        }
        seeds.sort_by(|x, y| x.0.total_cmp(&y.0));
        // Each of the best seeds refined by alternating projections onto
        // the box and the core (both in closed form, in `f64`): every
        // iterate on the core is a point of the core, and the iteration
        // converges to a closest pair of the two convex sets.
        let mut least = f64::INFINITY;
        for &(d, piece, s, t) in seeds.iter().take(8) {
            least = least.min(d);
            let mut x = surface(cone, h, rho, piece, s, t);
            for _ in 0..4000 {
                let p = place(x);
                least = least.min(to_box(p, b));
                let q = [0, 1, 2].map(|k| p[k].clamp(-b[k], b[k]));
                // Back to the core's frame (`m` is a rotation to within
                // rounding: its transpose inverts it to about `1e-16`).
                let e = [0, 1, 2].map(|k| q[k] - c[k]);
                let l = [0, 1, 2].map(|i| m[0][i] * e[0] + m[1][i] * e[1] + m[2][i] * e[2]);
                x = project_core(cone, h, rho, l);
            }
        }
        least
    }

    /// The closest point of the solid cylinder or cone (in its frame) to
    /// `p`: in the half-plane `(r, y)` of `p`'s radial distance, the
    /// rectangle `[0, rho] x [-h, h]` or the triangle `(0, -h)`, `(rho,
    /// -h)`, `(0, h)`, revolved back.
    pub(crate) fn project_core(cone: bool, h: f64, rho: f64, p: [f64; 3]) -> [f64; 3] {
        let r = (p[0] * p[0] + p[2] * p[2]).sqrt();
        let (r2, y2) = if !cone {
            (r.min(rho), p[1].clamp(-h, h))
        } else {
            // Inside: below the slanted edge and above the base.
            let inside = p[1] >= -h && r * 2.0 * h <= rho * (h - p[1]);
            if inside {
                (r, p[1])
            } else {
                let seg = |a: (f64, f64), bb: (f64, f64)| {
                    let (dx, dy) = (bb.0 - a.0, bb.1 - a.1);
                    let t = (((r - a.0) * dx + (p[1] - a.1) * dy) / (dx * dx + dy * dy))
                        .clamp(0.0, 1.0);
                    let q = (a.0 + t * dx, a.1 + t * dy);
                    ((q.0 - r).powi(2) + (q.1 - p[1]).powi(2), q)
                };
                let (base, slant) = (seg((0.0, -h), (rho, -h)), seg((rho, -h), (0.0, h)));
                if base.0 <= slant.0 {
                    base.1
                } else {
                    slant.1
                }
            }
        };
        if r > 0.0 {
            [p[0] * r2 / r, y2, p[2] * r2 / r]
        } else {
            [0.0, y2, 0.0]
        }
    }

    fn early_stop_is_sound_and_costs_at_most_its_share<T: Float>(tol: f64, min_gap: f64) {
        let mut rng = SplitMix64::new(55);
        let params = CaParams::<T>::default().with_contact_distance(T::from_f64(1e-4));
        let (cd, cl) = (1e-4, 0.5e-4);
        let (mut checked, mut worst) = (0, 0.0f64);
        for case in 0..240 {
            let cone = case % 2 == 1;
            let (h, rho) = if case % 4 < 2 {
                (0.3, 0.05)
            } else {
                (0.1, 0.3)
            };
            let (ra, rb) = if case % 3 == 0 {
                (0.0, 0.0)
            } else {
                (0.02, 0.01)
            };
            let half = [0.2, 0.5, 0.4];
            let f = T::from_f64;
            let core = if cone {
                Convex::try_cone(f(h), f(rho))
            } else {
                Convex::try_cylinder(f(h), f(rho))
            };
            let a = core.and_then(|s| s.try_rounded(f(ra))).expect("shape");
            let b = Convex::try_cuboid(half.map(f))
                .and_then(|s| s.try_rounded(f(rb)))
                .expect("shape");
            let axis = rng.direction();
            let angle = rng.range(0.0, 6.0);
            let rot = Rotation::try_from_axis_angle(Vec3::from_array(axis.map(f)), f(angle))
                .expect("rotation");
            let m = rot.matrix().map(|row| row.map(T::to_f64));
            let (hh, rr) = (f(h).to_f64(), f(rho).to_f64());
            let bb = half.map(|x| f(x).to_f64());
            // A target gap between the shapes, log-uniform in [1e-4, 1]:
            // the centre moved along a random direction until the
            // sampled gap is near it.
            let target = 10f64.powf(rng.range(-4.0, 0.0));
            let u = rng.direction();
            let mut c = u.map(|x| x * 1.5);
            for _ in 0..6 {
                let d = sampled_distance(cone, (hh, rr), (m, c), bb) - ra - rb;
                c = [0, 1, 2].map(|k| c[k] + u[k] * (target - d));
            }
            let c = c.map(|x| f(x).to_f64());
            let pa = Pose {
                rotation: rot.matrix(),
                translation: Vec3::from_array(c.map(f)),
            };
            let pb = Pose::from_translation(Vec3::new(T::ZERO, T::ZERO, T::ZERO));
            let truth =
                sampled_distance(cone, (hh, rr), (m, c), bb) - f(ra).to_f64() - f(rb).to_f64();
            if truth <= cd {
                continue;
            }
            let placed = (
                PlacedCore {
                    shape: &a,
                    pose: &pa,
                },
                PlacedCore {
                    shape: &b,
                    pose: &pb,
                },
            );
            let gjk = GjkParams::default().with_rel_tol(gjk_tolerance::<T>());
            let (on_a, on_b) = gjk_closest(
                &placed.0,
                &placed.1,
                &gjk,
                enough(a.radius() + b.radius(), &params),
            );
            let estimate = (on_b - on_a).length().to_f64() - ra - rb;
            let n = (on_b - on_a)
                .try_normalize()
                .unwrap_or_else(|| panic!("case {case}: no direction at a sampled gap {truth}"));
            let g = certified_gap((&a, &pa, T::ZERO), (&b, &pb, T::ZERO), n).to_f64();
            assert!(
                g <= truth,
                "case {case}: certified {g} above the sampled {truth}"
            );
            // The same iteration run to GJK's own tolerance: its witnesses'
            // distance is an estimate from above too, and may be closer
            // to the true distance than the sampled one.
            let (fa, fb) = gjk_closest(&placed.0, &placed.1, &gjk, |_, _| false);
            let upper = truth.min((fb - fa).length().to_f64() - ra - rb);
            if estimate <= cd {
                // Contact declared: the cores' estimate from above is within
                // the contact distance, and so is every later one.
                assert!(upper <= cd, "case {case}: contact at a sampled gap {truth}");
                continue;
            }
            if upper < min_gap {
                continue;
            }
            // The step uses `g - cl`; the early stop promises at least
            // `1 - ENOUGH` of what the exact distance (at most `upper`)
            // gives, up to rounding.
            let promised = (1.0 - ENOUGH) * (upper - cl) + cl;
            worst = worst.max((promised - g) / upper);
            assert!(
                g >= promised - tol * upper,
                "case {case}: certified {g}, promised {promised} (sampled {truth}, upper {upper})"
            );
            checked += 1;
        }
        std::println!("{checked} cases checked, worst shortfall {worst:e} of the gap");
        assert!(checked >= 100, "too few cases checked: {checked}");
    }

    #[test]
    fn early_stop_is_sound_and_costs_at_most_its_share_f64() {
        // Rounding: the certificate's margins, about `1e3 u` of the weights.
        early_stop_is_sound_and_costs_at_most_its_share::<f64>(1e-9, 0.0);
    }

    #[test]
    fn early_stop_is_sound_and_costs_at_most_its_share_f32() {
        // In `f32` the closest direction's rounding tilts it by about
        // `u |w| / |v|` rad, which loses the gap over the core's extent
        // below about `1e-3` (the stepper then tries a box's face normal
        // too): the promise is checked from `1e-2` up.
        early_stop_is_sound_and_costs_at_most_its_share::<f32>(1e-4, 1e-2);
    }
}

#[cfg(all(test, feature = "alloc"))]
mod exact_pose_tests {
    //! [`support_error_up`] against the exact least `x . n` of a shape at an
    //! exact pose (`proofs/12-shapes.md`, section "Support at an exact
    //! pose"): in `f64` against double-double arithmetic, in `f32` against
    //! `f64`, over every kind, rounded or not, random (not quite
    //! orthonormal) matrices, translations from `1e-3` to `1e3` and
    //! directions normalised in the precision at hand.
    extern crate std;

    use super::{lower_support, support_error_up};
    use crate::dd::DoubleDouble as Dd;
    use crate::rng::SplitMix64;
    use crate::shape::convex::Core;
    use crate::{Convex, Float, Pose, Vec3};

    /// The exact support `h_K(d)` of an unplaced core at `d`.
    fn core_support(core: &Core<'_, f64>, d: [Dd; 3]) -> Dd {
        let xz = (d[0] * d[0] + d[2] * d[2]).sqrt();
        match *core {
            Core::Point => Dd::ZERO,
            Core::Segment { half_height } => d[1].abs() * half_height,
            Core::Cuboid { half } => (0..3).fold(Dd::ZERO, |s, i| s + d[i].abs() * half[i]),
            Core::Cylinder {
                half_height,
                radius,
            } => d[1].abs() * half_height + xz * radius,
            Core::Cone {
                half_height,
                radius,
            } => {
                let top = d[1] * half_height;
                let rim = xz * radius - d[1] * half_height;
                if top.hi >= rim.hi {
                    top
                } else {
                    rim
                }
            }
            Core::Polytope(_) => unreachable!("no hulls here"),
        }
    }

    /// `M^T v` for a row-major `M`, in double-double.
    fn transpose_times(m: &[[f64; 3]; 3], v: [Dd; 3]) -> [Dd; 3] {
        [0, 1, 2].map(|i| (0..3).fold(Dd::ZERO, |s, j| s + v[j] * m[j][i]))
    }

    /// The exact least `x . n` over `{M k + x : k in K}` grown by the ball
    /// of radius `rho` (the shape at the exact pose), for the stored `f64`
    /// numbers: `x . n - h_K(M^T (-n)) - rho |n|`, in double-double
    /// (`f64` numbers' products and sums are exact to about `1e-32`). A
    /// core placed in the body frame by `part = (P, t)` (its stored matrix
    /// and translation) has `h_K(d) = h(P^T d) + t . d`.
    fn exact_lower(
        core: &Core<'_, f64>,
        part: Option<([[f64; 3]; 3], [f64; 3])>,
        rho: f64,
        (m, x): (&[[f64; 3]; 3], [f64; 3]),
        n: [f64; 3],
    ) -> Dd {
        let dot = |a: [f64; 3], b: [Dd; 3]| (0..3).fold(Dd::ZERO, |s, i| s + b[i] * a[i]);
        let nd = n.map(Dd::from_f64);
        let d = transpose_times(m, nd.map(|v| -v));
        let h = match part {
            Some((p, t)) => core_support(core, transpose_times(&p, d)) + dot(t, d),
            None => core_support(core, d),
        };
        let len = (0..3).fold(Dd::ZERO, |s, i| s + nd[i] * n[i]).sqrt();
        dot(x, nd) - h - len * rho
    }

    /// A random shape of every kind in turn (rounded every other time).
    fn shape<T: Float>(rng: &mut SplitMix64, i: usize) -> Convex<'static, T> {
        let mut r = || T::from_f64(rng.range(0.01, 1.0));
        let s = match i % 5 {
            0 => Convex::try_ball(r()),
            1 => Convex::try_capsule(r(), r()),
            2 => Convex::try_cuboid([r(), r(), r()]),
            3 => Convex::try_cylinder(r(), r()),
            _ => Convex::try_cone(r(), r()),
        }
        .expect("valid");
        if i % 10 >= 5 && !i.is_multiple_of(5) {
            s.try_rounded(T::from_f64(0.05)).expect("valid")
        } else {
            s
        }
    }

    /// A random pose: a rotation from a normalised quaternion (rounded, so
    /// only nearly orthonormal) and a translation of magnitude `1e-3` to
    /// `1e3`; and a direction normalised in `T`.
    fn pose_and_direction<T: Float>(rng: &mut SplitMix64) -> (Pose<T>, Vec3<T>) {
        let q = [0; 4].map(|_| rng.signed_unit());
        let m = crate::Rotation::try_from_quaternion(q[0], q[1], q[2], q[3])
            .expect("a nonzero quaternion")
            .matrix();
        let scale = 10f64.powf(rng.range(-3.0, 3.0));
        let x = rng.vec3().map(|v| T::from_f64(v * scale));
        let pose = Pose {
            rotation: m.map(|row| row.map(T::from_f64)),
            translation: Vec3::from_array(x),
        };
        let n = Vec3::from_array(rng.direction().map(T::from_f64));
        (pose, n.try_normalize().expect("a unit direction"))
    }

    /// The largest share of [`support_error_up`] the computed least `x . n`
    /// is from the exact one over `count` random cases (`f64` against
    /// double-double). `drop_translation` leaves the translation's share
    /// out of the bound: the check then fails (the bound is not vacuous).
    fn worst_share_f64(count: usize, drop_translation: bool) -> f64 {
        let mut rng = SplitMix64(0x5EED_0063);
        let mut worst = 0.0f64;
        for i in 0..count {
            let b: Convex<'static, f64> = shape(&mut rng, i);
            let (pose, n) = pose_and_direction::<f64>(&mut rng);
            let mut e = support_error_up(&b, &pose);
            if drop_translation {
                let bare = Pose {
                    translation: Vec3::new(0.0, 0.0, 0.0),
                    ..pose
                };
                e = support_error_up(&b, &bare);
            }
            let computed = lower_support(&b, &pose, n);
            let exact = exact_lower(
                b.core(),
                None,
                b.radius(),
                (&pose.rotation, pose.translation.to_array()),
                n.to_array(),
            );
            // The bound covers the evaluation and its share `u |computed|`
            // of the gap's subtraction.
            let err = (exact - computed).abs().to_f64() + f64::UNIT_ROUNDOFF * computed.abs();
            worst = worst.max(err / e);
        }
        worst
    }

    #[test]
    fn support_at_an_exact_pose_is_within_its_bound_in_f64() {
        let share = worst_share_f64(20_000, false);
        std::println!("f64: the worst error is {share:.3} of the bound");
        assert!(share <= 1.0, "an error {share} times the bound");
        // Sanity: the bound bites where a share is left out.
        let bare = worst_share_f64(20_000, true);
        assert!(bare > 1.0, "without the translation's share: {bare}");
    }

    #[test]
    fn support_at_an_exact_pose_is_within_its_bound_in_f32() {
        let mut rng = SplitMix64(0x5EED_0032);
        let mut worst = 0.0f64;
        for i in 0..20_000 {
            let b: Convex<'static, f32> = shape(&mut rng, i);
            let (pose, n) = pose_and_direction::<f32>(&mut rng);
            let e = f64::from(support_error_up(&b, &pose));
            let computed = f64::from(lower_support(&b, &pose, n));
            // The exact value from the `f32` numbers, in double-double.
            let core: Core<'static, f64> = match *b.core() {
                Core::Point => Core::Point,
                Core::Segment { half_height } => Core::Segment {
                    half_height: half_height.into(),
                },
                Core::Cuboid { half } => Core::Cuboid {
                    half: half.map(f64::from),
                },
                Core::Cylinder {
                    half_height,
                    radius,
                } => Core::Cylinder {
                    half_height: half_height.into(),
                    radius: radius.into(),
                },
                Core::Cone {
                    half_height,
                    radius,
                } => Core::Cone {
                    half_height: half_height.into(),
                    radius: radius.into(),
                },
                Core::Polytope(_) => unreachable!("no hulls here"),
            };
            let m = pose.rotation.map(|row| row.map(f64::from));
            let x = pose.translation.to_array().map(f64::from);
            let exact = exact_lower(
                &core,
                None,
                b.radius().into(),
                (&m, x),
                n.to_array().map(f64::from),
            );
            let err =
                (exact - computed).abs().to_f64() + f64::from(f32::UNIT_ROUNDOFF) * computed.abs();
            worst = worst.max(err / e);
        }
        std::println!("f32: the worst error is {worst:.3} of the bound");
        assert!(worst <= 1.0, "an error {worst} times the bound");
    }

    /// A compound's part (a core placed in the body frame) as an obstacle:
    /// not given a `k`, it keeps the rigid bound (`80 u max(c, 1) W'`),
    /// checked here against double-double with the part's stored matrix.
    #[test]
    fn a_placed_part_keeps_the_rigid_bound_in_f64() {
        use crate::{Isometry, Rotation};
        let mut rng = SplitMix64(0x5EED_0064);
        let mut worst = 0.0f64;
        for i in 0..5_000 {
            let q = [0; 4].map(|_| rng.signed_unit());
            let turn = Rotation::try_from_quaternion(q[0], q[1], q[2], q[3]).expect("valid");
            let t = rng.vec3();
            let at = Isometry::try_new(turn, Vec3::from_array(t)).expect("valid");
            let b: Convex<'static, f64> = shape(&mut rng, i).try_placed(at).expect("valid");
            let (pose, n) = pose_and_direction::<f64>(&mut rng);
            let e = support_error_up(&b, &pose);
            let computed = lower_support(&b, &pose, n);
            let exact = exact_lower(
                b.core(),
                Some((turn.matrix(), t)),
                b.radius(),
                (&pose.rotation, pose.translation.to_array()),
                n.to_array(),
            );
            let err = (exact - computed).abs().to_f64() + f64::UNIT_ROUNDOFF * computed.abs();
            worst = worst.max(err / e);
        }
        std::println!("placed parts: the worst error is {worst:.3} of the bound");
        assert!(worst <= 1.0, "an error {worst} times the bound");
    }
}
