//! Conservative advancement of two convex shapes (cores with radii).

use crate::ca::step::{placement_error, precision_limit};
use crate::ca::{CaParams, CaStep, StepResult, Witness};
use crate::geometry::closest::segment_segment_vec;
use crate::geometry::gjk::{gjk_distance, GjkParams, SupportMap};
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
/// `pb`: what a chain's edge query measures from a link's ball or triangle
/// to a shape obstacle (`proofs/13-chains.md`, Lemma 13.6).
pub(crate) fn certified_gap_to<T: Float>(
    upper_a: T,
    weight_a: T,
    err_a: T,
    (b, pb, err_b): (&Convex<'_, T>, &Pose<T>, T),
    n: Vec3<T>,
) -> T {
    // The least `x . n` over B along `-n`.
    let lower_b =
        pb.translation.dot(n) - b.core_support_value(pb.inverse_transform_vector(-n)) - b.radius();
    // `gap_down` covers `gamma_8` of the reach it is given; the support's
    // evaluation needs `64 u` of the weights (section "Support").
    let reach = T::from_u32(8) * sum_up(weight_a, weight(b, pb));
    gap_down(lower_b - upper_a, err_a, err_b, reach)
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
            _ => {
                let gjk = gjk_distance(
                    &PlacedCore {
                        shape: &self.a,
                        pose: &pose_a,
                    },
                    &PlacedCore {
                        shape: &self.b,
                        pose: &pose_b,
                    },
                    &GjkParams::default().with_rel_tol(gjk_tolerance::<T>()),
                );
                (gjk.on_a.to_vec3(), gjk.on_b.to_vec3())
            }
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

/// GJK's relative tolerance for curved cores (which converge only
/// asymptotically): `2^-30`, or `256 u` where that is larger (`f32`). The
/// direction it gives is only a choice (Lemma 12.1 holds for any).
pub(crate) fn gjk_tolerance<T: Float>() -> T {
    (T::from_u32(256) * T::UNIT_ROUNDOFF).max_nan(T::from_f64(1.0 / 1_073_741_824.0))
}
