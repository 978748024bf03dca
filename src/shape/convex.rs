//! Convex shapes as a core and a radius: balls, capsules, cuboids,
//! cylinders, cones and polytopes, each possibly rounded.
//!
//! Every convex shape of this crate is the set of points within `radius` of
//! its **core** (`proofs/12-shapes.md`): a ball is a point with a radius, a
//! capsule a segment with a radius, a rounded cuboid a cuboid with a radius.
//! Two things follow, and the rest of the crate uses nothing else:
//!
//! * its **support** along `d` is the core's support plus `radius |d|`, so
//!   the slab between two shapes along a direction is the slab between
//!   their cores less both radii;
//! * its **directed speeds** are the core's plus the radius's own term: a
//!   point `r + e` (`|e| <= radius`) moves along `n` at the speed of `r` plus
//!   `(n x w) . R e`, at most `|n x w| radius`.
//!
//! Shapes live in their body frame (the frame a body's motion places):
//! capsules, cylinders and cones stand along the frame's `y` axis, centred
//! at its origin, as parry's do.

use crate::error::{check_components, InputError, Quantity};
use crate::rounding::gamma;
use crate::rounding::{radius_up, sum_up};
use crate::{Float, Isometry, Point3, Vec3, VertexSet};

/// Which shape a [`Convex`] is (its core's kind; `rounded` when it has a
/// radius beyond what the kind itself has: a ball and a capsule are points
/// and segments with their radius, never "rounded").
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum ConvexKind {
    /// A ball: a point with a radius.
    Ball,
    /// A capsule: a segment with a radius.
    Capsule,
    /// A cuboid (a box), rounded or not.
    Cuboid {
        /// Whether it has a radius.
        rounded: bool,
    },
    /// A cylinder, rounded or not.
    Cylinder {
        /// Whether it has a radius.
        rounded: bool,
    },
    /// A cone, rounded or not.
    Cone {
        /// Whether it has a radius.
        rounded: bool,
    },
    /// The convex hull of a vertex set, rounded or not.
    Polytope {
        /// Whether it has a radius.
        rounded: bool,
    },
}

impl core::fmt::Display for ConvexKind {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        let (name, rounded) = match *self {
            Self::Ball => ("ball", false),
            Self::Capsule => ("capsule", false),
            Self::Cuboid { rounded } => ("cuboid", rounded),
            Self::Cylinder { rounded } => ("cylinder", rounded),
            Self::Cone { rounded } => ("cone", rounded),
            Self::Polytope { rounded } => ("convex polytope", rounded),
        };
        if rounded {
            write!(f, "rounded {name}")
        } else {
            f.write_str(name)
        }
    }
}

/// The core of a convex shape, in the body frame.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Core<'a, T> {
    /// The origin.
    Point,
    /// The segment from `(0, -h, 0)` to `(0, h, 0)`, `h >= 0`.
    Segment { half_height: T },
    /// The box `[-h_0, h_0] x [-h_1, h_1] x [-h_2, h_2]`.
    Cuboid { half: [T; 3] },
    /// The cylinder of axis `y`, `|y| <= h`, `x^2 + z^2 <= rho^2`.
    Cylinder { half_height: T, radius: T },
    /// The cone of axis `y`: apex `(0, h, 0)`, base the disc of radius
    /// `rho` at `y = -h`.
    Cone { half_height: T, radius: T },
    /// The convex hull of the vertices.
    Polytope(VertexSet<'a, T>),
}

/// A convex shape: its core and its radius (the points within `radius` of
/// the core), in its body frame. Made by [`try_ball`](Self::try_ball),
/// [`try_capsule`](Self::try_capsule), [`try_cuboid`](Self::try_cuboid),
/// [`try_cylinder`](Self::try_cylinder), [`try_cone`](Self::try_cone) or
/// [`polytope`](Self::polytope), and rounded by
/// [`try_rounded`](Self::try_rounded).
///
/// ```
/// use motion_bound::{Convex, ConvexKind, InputError};
/// let ball = Convex::<f64>::try_ball(0.5)?;
/// let capsule = Convex::try_capsule(1.0, 0.25)?;
/// let rounded_box = Convex::try_cuboid([1.0, 0.5, 0.25])?.try_rounded(0.1)?;
/// assert_eq!(rounded_box.kind(), ConvexKind::Cuboid { rounded: true });
/// assert_eq!(capsule.radius(), 0.25);
/// // The reach bounds every point's distance from the body origin.
/// assert!(rounded_box.reach() >= (1.0f64 + 0.25 + 0.0625).sqrt() + 0.1);
/// assert_eq!(Convex::<f64>::try_cylinder(0.0, 1.0), Err(InputError::ZeroHeight));
/// assert_eq!(Convex::<f64>::try_ball(-1.0), Err(InputError::NegativeRadius));
/// # Ok::<(), InputError>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Convex<'a, T> {
    core: Core<'a, T>,
    radius: T,
    rounded: bool,
    /// An upper bound of `|r|` over the core's points.
    core_reach: T,
    /// An upper bound of `|r|_1` over the core's points.
    weight: T,
    /// The core's placement in the body frame (a compound's part), if any:
    /// the core is `{M k + t}` for the stored matrix `M` of the rotation.
    placed: Option<Isometry<T>>,
}

/// A finite, non-negative length, or the error naming it.
fn length<T: Float>(x: T, what: Quantity) -> Result<T, InputError> {
    check_components([x, T::ZERO, T::ZERO], what)?;
    if x < T::ZERO {
        return Err(InputError::NegativeRadius);
    }
    Ok(x)
}

/// `(a + b)(1 + gamma_2) >= a + b` for non-negative `a`, `b`
/// (`rounding::sum_up`), applied to three.
fn sum3_up<T: Float>(a: T, b: T, c: T) -> T {
    sum_up(sum_up(a, b), c)
}

impl<'a, T: Float> Convex<'a, T> {
    fn new(core: Core<'a, T>, radius: T, rounded: bool) -> Self {
        // `|r|` and `|r|_1` over the core (proofs/12-shapes.md, "Reach"):
        // the extreme points are the corners, the segment's ends, the rims.
        let (core_reach, weight) = match core {
            Core::Point => (T::ZERO, T::ZERO),
            Core::Segment { half_height: h } => (h, h),
            Core::Cuboid { half: h } => (
                radius_up(h[0] * h[0] + h[1] * h[1] + h[2] * h[2]),
                sum3_up(h[0], h[1], h[2]),
            ),
            Core::Cylinder {
                half_height: h,
                radius: rho,
            }
            | Core::Cone {
                half_height: h,
                radius: rho,
            } => (
                radius_up(h * h + rho * rho),
                // |x| + |z| <= sqrt(2) rho on the rim: 2 rho covers it.
                sum_up(h, rho * T::TWO),
            ),
            Core::Polytope(set) => {
                let w = set
                    .vertices()
                    .iter()
                    .map(|r| Vec3::from_array(*r).norm_l1())
                    .fold(T::ZERO, T::max_nan);
                (
                    set.summary().max_radius(),
                    w * (T::ONE + crate::rounding::gamma::<T>(2)),
                )
            }
        };
        Self {
            core,
            radius,
            rounded,
            core_reach,
            weight,
            placed: None,
        }
    }

    /// The body origin alone (a ball of radius zero): what a half-space's
    /// plane is seen from along its normal.
    pub(crate) fn point() -> Self {
        Self::new(Core::Point, T::ZERO, false)
    }

    /// A ball of radius `radius` centred at the body origin.
    ///
    /// # Errors
    /// [`InputError::NegativeRadius`], or [`InputError::NonFinite`] /
    /// [`InputError::TooLarge`] with [`Quantity::Radius`].
    pub fn try_ball(radius: T) -> Result<Self, InputError> {
        Ok(Self::new(
            Core::Point,
            length(radius, Quantity::Radius)?,
            false,
        ))
    }

    /// A capsule: the segment from `(0, -half_height, 0)` to
    /// `(0, half_height, 0)` with radius `radius`. A zero `half_height` is a
    /// ball.
    ///
    /// # Errors
    /// As [`try_ball`](Self::try_ball), and for the half height with
    /// [`Quantity::Extent`].
    pub fn try_capsule(half_height: T, radius: T) -> Result<Self, InputError> {
        let half_height = length(half_height, Quantity::Extent)?;
        let radius = length(radius, Quantity::Radius)?;
        Ok(Self::new(Core::Segment { half_height }, radius, false))
    }

    /// The box `[-h_0, h_0] x [-h_1, h_1] x [-h_2, h_2]` for the half extents
    /// `h` (zero extents are allowed: a rectangle, a segment, a point).
    ///
    /// # Errors
    /// [`InputError::NegativeRadius`] for a negative extent,
    /// [`InputError::NonFinite`] / [`InputError::TooLarge`] with
    /// [`Quantity::Extent`].
    pub fn try_cuboid(half_extents: [T; 3]) -> Result<Self, InputError> {
        let mut half = [T::ZERO; 3];
        for (h, &x) in half.iter_mut().zip(&half_extents) {
            *h = length(x, Quantity::Extent)?;
        }
        Ok(Self::new(Core::Cuboid { half }, T::ZERO, false))
    }

    /// The cylinder along the body's `y` axis, `|y| <= half_height`, of
    /// radius `radius`.
    ///
    /// # Errors
    /// [`InputError::ZeroHeight`] for a zero half height (a disc: use a
    /// cylinder of the least height you mean, or a rounded one); as
    /// [`try_capsule`](Self::try_capsule) otherwise.
    pub fn try_cylinder(half_height: T, radius: T) -> Result<Self, InputError> {
        let (half_height, radius) = Self::axial(half_height, radius)?;
        Ok(Self::new(
            Core::Cylinder {
                half_height,
                radius,
            },
            T::ZERO,
            false,
        ))
    }

    /// The cone along the body's `y` axis: apex `(0, half_height, 0)`, base
    /// the disc of radius `radius` at `y = -half_height`.
    ///
    /// # Errors
    /// As [`try_cylinder`](Self::try_cylinder).
    pub fn try_cone(half_height: T, radius: T) -> Result<Self, InputError> {
        let (half_height, radius) = Self::axial(half_height, radius)?;
        Ok(Self::new(
            Core::Cone {
                half_height,
                radius,
            },
            T::ZERO,
            false,
        ))
    }

    fn axial(half_height: T, radius: T) -> Result<(T, T), InputError> {
        let h = length(half_height, Quantity::Extent)?;
        let r = length(radius, Quantity::Radius)?;
        if h == T::ZERO {
            return Err(InputError::ZeroHeight);
        }
        Ok((h, r))
    }

    /// The convex hull of a vertex set (validated when it was made).
    #[must_use]
    pub fn polytope(vertices: VertexSet<'a, T>) -> Self {
        Self::new(Core::Polytope(vertices), T::ZERO, false)
    }

    /// The same shape rounded by `radius` more: every point within `radius`
    /// of it. The radii add (rounded up: the shape never shrinks).
    ///
    /// # Errors
    /// [`InputError::NegativeRadius`], or [`InputError::NonFinite`] /
    /// [`InputError::TooLarge`] with [`Quantity::Radius`] (also when the sum
    /// exceeds the largest supported magnitude).
    pub fn try_rounded(self, radius: T) -> Result<Self, InputError> {
        let r = length(radius, Quantity::Radius)?;
        if r == T::ZERO {
            return Ok(self);
        }
        // A float at least the exact sum (TwoSum's residual says which way
        // the rounding went).
        let (total, lo) = crate::rounding::two_sum(self.radius, r);
        let total = if lo > T::ZERO { total.next_up() } else { total };
        check_components([total, T::ZERO, T::ZERO], Quantity::Radius)?;
        let rounded = !matches!(self.core, Core::Point | Core::Segment { .. });
        Ok(Self {
            radius: total,
            rounded,
            ..self
        })
    }

    /// The same shape placed at `pose` in the body frame (a compound's
    /// part at its local pose): its core mapped by the pose's stored matrix
    /// `M` and translation, its radius grown by `||M - R|| |k|` over the
    /// core (`Rotation::matrix_error`, `80 u` at most; `0` for the
    /// identity), so that it holds the exactly rotated shape
    /// (`proofs/12-shapes.md`, "Placed shapes").
    ///
    /// # Errors
    /// [`InputError::AlreadyPlaced`] for a shape placed before (place a
    /// shape once, at its whole pose), or [`InputError::TooLarge`] with
    /// [`Quantity::Radius`] when the grown radius overflows the range.
    ///
    /// ```
    /// use motion_bound::{Convex, Isometry, Rotation, Vec3};
    /// let turned = Rotation::try_from_axis_angle(Vec3::new(0.0, 0.0, 1.0), 0.5)?;
    /// let arm = Convex::try_capsule(0.5, 0.1)?.try_placed(Isometry::try_new(turned, Vec3::new(1.0, 0.0, 0.0))?)?;
    /// assert!(arm.reach() >= 1.0 + 0.5 + 0.1 && arm.radius() >= 0.1 && arm.radius() < 0.1 + 1e-12);
    /// # Ok::<(), motion_bound::InputError>(())
    /// ```
    pub fn try_placed(self, pose: Isometry<T>) -> Result<Self, InputError> {
        if self.placed.is_some() {
            return Err(InputError::AlreadyPlaced);
        }
        let rot = pose.rotation();
        let grown = if rot.is_identity() {
            self
        } else {
            let slack = rot.matrix_error() * self.core_reach * (T::ONE + gamma::<T>(2));
            let rounded = self.rounded;
            let mut shape = self.try_rounded(slack)?;
            shape.rounded = rounded;
            shape
        };
        Ok(Self {
            placed: Some(pose),
            ..grown
        })
    }

    /// Which shape this is.
    #[must_use]
    pub const fn kind(&self) -> ConvexKind {
        let rounded = self.rounded;
        match self.core {
            Core::Point => ConvexKind::Ball,
            Core::Segment { .. } => ConvexKind::Capsule,
            Core::Cuboid { .. } => ConvexKind::Cuboid { rounded },
            Core::Cylinder { .. } => ConvexKind::Cylinder { rounded },
            Core::Cone { .. } => ConvexKind::Cone { rounded },
            Core::Polytope(_) => ConvexKind::Polytope { rounded },
        }
    }

    /// The radius around the core (a ball's, a capsule's, a rounded
    /// shape's; `0` for a sharp one).
    #[inline]
    #[must_use]
    pub const fn radius(&self) -> T {
        self.radius
    }

    /// An upper bound of the distance from the body origin of every point
    /// of the shape.
    #[inline]
    #[must_use]
    pub fn reach(&self) -> T {
        sum_up(self.placed_core_reach(), self.radius)
    }

    /// An upper bound of `|r|` over the placed core's points (the points
    /// whose turn moves the shape's support: its radius around the core
    /// does not turn).
    pub(crate) fn placed_core_reach(&self) -> T {
        match self.placed {
            Some(pose) => {
                let t = pose.translation();
                sum_up(radius_up(t.length_squared()), self.core_reach)
            }
            None => self.core_reach,
        }
    }

    /// An upper bound of `|r|_1` over the core's points: the weight of the
    /// support's rounding (`proofs/12-shapes.md`, "Support").
    #[inline]
    pub(crate) fn weight(&self) -> T {
        match self.placed {
            // `|M k + t|_1 <= |t|_1 + sqrt 3 (1 + 80 u) |k| <= |t|_1 + 2 |k|`.
            Some(pose) => sum_up(pose.translation().norm_l1(), self.core_reach * T::TWO),
            None => self.weight,
        }
    }

    /// The core support value's own rounding: `k` such that the computed
    /// [`core_support_value`](Self::core_support_value) at a computed `d`
    /// is within `gamma_k W |d|_inf` of the exact one at that `d` (`W` the
    /// [`weight`](Self::weight)): 0 for a point, 1 for a segment (one
    /// product), 3 for a cuboid (three products summed) or a hull (three-term
    /// dot products), 4 for a cylinder and 5 for a cone (a square root of a
    /// sum of squares beside a product); `None` for a core placed in the
    /// body frame (a compound's part), whose placement adds its own
    /// (`proofs/12-shapes.md`, section "Support at an exact pose").
    #[cfg(feature = "alloc")]
    pub(crate) const fn support_rounding(&self) -> Option<u32> {
        if self.placed.is_some() {
            return None;
        }
        Some(match self.core {
            Core::Point => 0,
            Core::Segment { .. } => 1,
            Core::Cuboid { .. } | Core::Polytope(_) => 3,
            Core::Cylinder { .. } => 4,
            Core::Cone { .. } => 5,
        })
    }

    pub(crate) const fn core(&self) -> &Core<'a, T> {
        &self.core
    }

    /// Whether the core is placed in the body frame (a compound's part).
    #[cfg(feature = "alloc")]
    pub(crate) const fn is_placed(&self) -> bool {
        self.placed.is_some()
    }

    /// A core point placed in the body frame: `M k + t` for a placed shape
    /// (the same rounded placement as [`core_support_point`](Self::core_support_point)),
    /// `k` itself otherwise.
    pub(crate) fn place_core_point(&self, k: Vec3<T>) -> Vec3<T> {
        match self.placed {
            Some(pose) => pose.rotation().rotate(k) + pose.translation(),
            None => k,
        }
    }

    /// The core's support along the body-frame direction `d`: a point of
    /// the core maximising `r . d` (any one on ties).
    fn local_support_point(&self, d: Vec3<T>) -> Point3<T> {
        let sign = |x: T| if x < T::ZERO { -T::ONE } else { T::ONE };
        match self.core {
            Core::Point => Point3::new(T::ZERO, T::ZERO, T::ZERO),
            Core::Segment { half_height: h } => Point3::new(T::ZERO, sign(d.y) * h, T::ZERO),
            Core::Cuboid { half: h } => {
                Point3::new(sign(d.x) * h[0], sign(d.y) * h[1], sign(d.z) * h[2])
            }
            Core::Cylinder {
                half_height: h,
                radius: rho,
            } => {
                let (x, z) = rim(d, rho);
                Point3::new(x, sign(d.y) * h, z)
            }
            Core::Cone {
                half_height: h,
                radius: rho,
            } => {
                let (x, z) = rim(d, rho);
                // The apex or the base's rim point, whichever is farther.
                let lateral = rho * (d.x * d.x + d.z * d.z).sqrt();
                if d.y * h >= lateral - d.y * h {
                    Point3::new(T::ZERO, h, T::ZERO)
                } else {
                    Point3::new(x, -h, z)
                }
            }
            Core::Polytope(set) => {
                let mut best = set.vertices()[0];
                let mut best_dot = Vec3::from_array(best).dot(d);
                for r in &set.vertices()[1..] {
                    let s = Vec3::from_array(*r).dot(d);
                    if s > best_dot {
                        best = *r;
                        best_dot = s;
                    }
                }
                Point3::from_array(best)
            }
        }
    }

    /// The core's support value `max_r r . d` along the body-frame `d`, as
    /// computed in floating point: within `40 u W |d|_inf` of the exact
    /// value for the computed `d` (`W` the [`weight`](Self::weight);
    /// `proofs/12-shapes.md`, "Support"). The shape's own support adds
    /// `radius |d|`.
    pub(crate) fn core_support_value(&self, d: Vec3<T>) -> T {
        match self.placed {
            Some(pose) => {
                let r = pose.rotation();
                self.local_support_value(r.inverse_rotate(d)) + pose.translation().dot(d)
            }
            None => self.local_support_value(d),
        }
    }

    /// A core point maximising `r . d`, placed.
    pub(crate) fn core_support_point(&self, d: Vec3<T>) -> Point3<T> {
        match self.placed {
            Some(pose) => {
                let r = pose.rotation();
                let local = self.local_support_point(r.inverse_rotate(d));
                Point3::from_vec3(r.rotate(local.to_vec3()) + pose.translation())
            }
            None => self.local_support_point(d),
        }
    }

    /// A point of the core near `p` (both in the body frame): the closest
    /// one, as computed, for a point, segment, cuboid or cylinder core;
    /// `None` for a cone or a hull (ask GJK). Only ever used to choose a
    /// direction: what is certified along it is the support's slab gap
    /// ([`certified_gap`](crate::ca::certified_gap)), so the point need not be
    /// exact.
    #[cfg(feature = "alloc")]
    pub(crate) fn core_closest_point(&self, p: Vec3<T>) -> Option<Vec3<T>> {
        let (local, pose) = match self.placed {
            Some(pose) => (
                pose.rotation().inverse_rotate(p - pose.translation()),
                Some(pose),
            ),
            None => (p, None),
        };
        let z = T::ZERO;
        let clamp = |x: T, h: T| x.max_nan(-h).min_nan(h);
        let q = match self.core {
            Core::Point => Vec3::new(z, z, z),
            Core::Segment { half_height: h } => Vec3::new(z, clamp(local.y, h), z),
            Core::Cuboid { half: h } => Vec3::new(
                clamp(local.x, h[0]),
                clamp(local.y, h[1]),
                clamp(local.z, h[2]),
            ),
            Core::Cylinder {
                half_height: h,
                radius: rho,
            } => {
                let l = (local.x * local.x + local.z * local.z).sqrt();
                let s = if l > rho && l.is_finite() {
                    rho / l
                } else {
                    T::ONE
                };
                Vec3::new(local.x * s, clamp(local.y, h), local.z * s)
            }
            Core::Cone { .. } | Core::Polytope(_) => return None,
        };
        Some(match pose {
            Some(pose) => pose.rotation().rotate(q) + pose.translation(),
            None => q,
        })
    }

    /// The unplaced core's support value along `d`.
    fn local_support_value(&self, d: Vec3<T>) -> T {
        match self.core {
            Core::Point => T::ZERO,
            Core::Segment { half_height: h } => h * d.y.abs(),
            Core::Cuboid { half: h } => h[0] * d.x.abs() + h[1] * d.y.abs() + h[2] * d.z.abs(),
            Core::Cylinder {
                half_height: h,
                radius: rho,
            } => h * d.y.abs() + rho * (d.x * d.x + d.z * d.z).sqrt(),
            Core::Cone {
                half_height: h,
                radius: rho,
            } => (h * d.y).max_nan(rho * (d.x * d.x + d.z * d.z).sqrt() - h * d.y),
            Core::Polytope(set) => set
                .vertices()
                .iter()
                .map(|r| Vec3::from_array(*r).dot(d))
                .fold(-T::INFINITY, T::max_nan),
        }
    }

    /// For a cuboid core not placed in the body frame, the outward normal
    /// (in the world, by `pose`'s matrix) of the face most aligned with the
    /// world direction `d`: a direction along which a flat face's slab is
    /// measured exactly, where a closest direction computed from nearly
    /// touching points is off by their rounding over their distance (`f32`
    /// at `1e-4`: a thousandth of a radian, which a face a metre wide turns
    /// into a millimetre). `None` for other cores. Any direction gives a
    /// sound step (`proofs/12-shapes.md`, Lemma 12.1).
    pub(crate) fn face_normal(&self, pose: &crate::Pose<T>, d: Vec3<T>) -> Option<Vec3<T>> {
        if self.placed.is_some() || !matches!(self.core, Core::Cuboid { .. }) {
            return None;
        }
        let local = pose.inverse_transform_vector(d).to_array();
        let k = (0..3).fold(0, |k, j| {
            if local[j].abs() > local[k].abs() {
                j
            } else {
                k
            }
        });
        let mut e = [T::ZERO; 3];
        e[k] = if local[k] < T::ZERO { -T::ONE } else { T::ONE };
        Some(pose.transform_vector(Vec3::from_array(e)))
    }

    /// For a core symmetric about its frame's `y` axis and not placed in
    /// the body frame (a segment, cylinder or cone: a capsule, cylinder or
    /// cone, rounded or not), an upper bound of the distance from the axis
    /// point `(0, y, 0)` to every point of the core:
    /// `sqrt((h + |y|)^2 + rho_c^2)`, rounded up (`proofs/12-shapes.md`,
    /// Lemma 12.5). `None` for other cores, and for a placed core (its
    /// stored matrix is a rotation only to within rounding, so the stored
    /// set is not exactly symmetric).
    pub(crate) fn axial_reach(&self, y: T) -> Option<T> {
        if self.placed.is_some() {
            return None;
        }
        let (h, rho) = match self.core {
            Core::Segment { half_height } => (half_height, T::ZERO),
            Core::Cylinder {
                half_height,
                radius,
            }
            | Core::Cone {
                half_height,
                radius,
            } => (half_height, radius),
            _ => return None,
        };
        let a = sum_up(h, y.abs());
        Some(radius_up(a * a + rho * rho))
    }

    /// The points whose balls cover the core for the directed bounds
    /// (`proofs/12-shapes.md`, "Bounds"): up to two groups, each a list of
    /// body points (exact floats) and a radius that, added to each point,
    /// covers the core; the shape's own radius is added by the caller.
    pub(crate) fn bound_groups(&self) -> BoundGroups<'a, T> {
        let local = self.local_bound_groups();
        let Some(pose) = self.placed else {
            return local;
        };
        // Placed points are off the exact `M p + t` by at most
        // `16 u (|p| + |t|_1)` (`proofs/12-shapes.md`, "Placed shapes").
        let t = pose.translation();
        let e = T::from_u32(16)
            * T::UNIT_ROUNDOFF
            * sum_up(self.core_reach, t.norm_l1())
            * (T::ONE + gamma::<T>(2));
        let place = |p: [T; 3]| (pose.rotation().rotate(Vec3::from_array(p)) + t).to_array();
        let z = T::ZERO;
        let mut g = BoundGroups {
            small: [[z; 3]; 8],
            len: 0,
            dilation: z,
            second: None,
            set: None,
        };
        if local.set.is_some() {
            // A placed hull: the ball about its placed origin of its reach.
            g.push(t.to_array());
            g.dilation = sum_up(self.core_reach, e);
            return g;
        }
        for &p in local.points() {
            g.push(place(p));
        }
        g.dilation = sum_up(local.dilation, e);
        g.second = local.second.map(|(p, d)| (place(p), sum_up(d, e)));
        g
    }

    fn local_bound_groups(&self) -> BoundGroups<'a, T> {
        let z = T::ZERO;
        let mut g = BoundGroups {
            small: [[z; 3]; 8],
            len: 0,
            dilation: z,
            second: None,
            set: None,
        };
        match self.core {
            Core::Point => g.push([z; 3]),
            Core::Segment { half_height: h } => {
                g.push([z, -h, z]);
                g.push([z, h, z]);
            }
            Core::Cuboid { half: h } => {
                // The corners `(+-h_0, +-h_1, +-h_2)` are exact floats.
                for k in 0..8 {
                    let s = |bit: u32, x: T| if k >> bit & 1 == 1 { x } else { -x };
                    g.push([s(0, h[0]), s(1, h[1]), s(2, h[2])]);
                }
            }
            Core::Cylinder {
                half_height: h,
                radius: rho,
            } => {
                // Each rim's disc lies in the ball of its centre and radius.
                g.push([z, -h, z]);
                g.push([z, h, z]);
                g.dilation = rho;
            }
            Core::Cone {
                half_height: h,
                radius: rho,
            } => {
                g.push([z, -h, z]);
                g.dilation = rho;
                g.second = Some(([z, h, z], z));
            }
            Core::Polytope(set) => g.set = Some(set),
        }
        g
    }
}

/// The rim point of a disc of radius `rho` in the `xz` plane farthest along
/// `d` (its centre when `d` has no `xz` part).
fn rim<T: Float>(d: Vec3<T>, rho: T) -> (T, T) {
    let l = (d.x * d.x + d.z * d.z).sqrt();
    if l > T::ZERO && l.is_finite() {
        (rho * d.x / l, rho * d.z / l)
    } else {
        (T::ZERO, T::ZERO)
    }
}

/// A core's cover for the directed bounds: the balls of radius `dilation`
/// about `points` (or about a vertex set's vertices), and possibly one more
/// point with no dilation (a cone's apex).
#[derive(Clone, Copy, Debug)]
pub(crate) struct BoundGroups<'a, T> {
    small: [[T; 3]; 8],
    len: usize,
    /// The radius of the balls about `points` (a cylinder's or cone's rim).
    pub(crate) dilation: T,
    /// A point with its own dilation (a cone's apex: zero, or a
    /// placement's rounding).
    pub(crate) second: Option<([T; 3], T)>,
    set: Option<VertexSet<'a, T>>,
}

impl<'a, T: Float> BoundGroups<'a, T> {
    fn push(&mut self, p: [T; 3]) {
        self.small[self.len] = p;
        self.len += 1;
    }

    /// The points of the main group.
    pub(crate) fn points(&self) -> &[[T; 3]] {
        match &self.set {
            Some(set) => set.vertices(),
            None => &self.small[..self.len],
        }
    }
}
