//! **Test support** (the `reference` feature): the exact reference (the
//! oracle), closed-form directed speed and displacement, independent of the
//! bound code.
//!
//! For a body point `r`, Rodrigues' formula gives
//! `R(t) r = r cos(theta) + (k x r) sin(theta) + k (k.r)(1 - cos(theta))` with
//! `k = w/|w|`, `theta = |w| t`, and since `c = n x w` is orthogonal to `k`,
//!
//! ```text
//! p'(t) . n = a + P cos(theta) + Q sin(theta),   a = v.n,  P = c.r,  Q = c.(k x r),
//! ```
//!
//! a sinusoid `a + B cos(theta - phi)` with `B = hypot(P, Q)`,
//! `phi = atan2(Q, P)`. Its supremum in absolute value over an arc is attained
//! at an end or where `cos(theta - phi) = +-1`; its integral is taken exactly
//! between the zero crossings `cos(theta - phi) = -a/B` with the antiderivative
//! `a psi + B sin(psi)`, full periods counted in closed form.
//!
//! Everything is evaluated in a [`Real`] type chosen by the caller: `f64`
//! (exact widening of `f32` inputs) or, for `f64` inputs, a higher precision.
//! Nothing here calls the bound code.

pub mod dd {
    //! Double-double arithmetic (the crate's `dd` module, where its
    //! algorithms and error bounds are documented): the reference evaluated
    //! in about 106 bits.
    //!
    //! Note that [`DoubleDouble`] implements both [`Real`](super::Real) and
    //! the `core::ops` operators: with `Real` in scope, call the trait's
    //! methods in path form (`Real::mul(a, b)`) or use the operators
    //! (`a * b`), as `a.mul(b)` is ambiguous.
    //!
    //! ```
    //! use motion_bound::reference::{dd::DoubleDouble, Real};
    //!
    //! let pi = DoubleDouble::PI;
    //! // sin(pi/6) = 1/2 to about 2^-106.
    //! let half = (pi / 6.0).sin();
    //! assert!((half - 0.5).abs().to_f64() < 1e-31);
    //! // 4 atan2(1, 1) = pi, far beyond f64.
    //! let q = DoubleDouble::from_f64(1.0).atan2(DoubleDouble::from_f64(1.0)) * 4.0;
    //! assert!((q - pi).abs().to_f64() < 1e-31);
    //! // The `Real` trait, as the oracle uses it.
    //! let two = <DoubleDouble as Real>::from_f64(2.0);
    //! let r = Real::sqrt(two);
    //! assert!((r * r - two).abs().to_f64() < 1e-31);
    //! ```

    pub use crate::dd::{quick_two_sum, two_prod, two_sum, DoubleDouble};
}
mod real;
#[cfg(feature = "faer")]
pub mod sampled;

pub use dd::DoubleDouble;
pub use real::Real;

use crate::{Direction, Float, RigidMotion};

type V3<R> = [R; 3];

fn dot<R: Real>(a: V3<R>, b: V3<R>) -> R {
    a[0].mul(b[0]).add(a[1].mul(b[1])).add(a[2].mul(b[2]))
}

fn cross<R: Real>(a: V3<R>, b: V3<R>) -> V3<R> {
    [
        a[1].mul(b[2]).sub(a[2].mul(b[1])),
        a[2].mul(b[0]).sub(a[0].mul(b[2])),
        a[0].mul(b[1]).sub(a[1].mul(b[0])),
    ]
}

fn scale<R: Real>(a: V3<R>, s: R) -> V3<R> {
    [a[0].mul(s), a[1].mul(s), a[2].mul(s)]
}

fn widen<T: Float, R: Real>(a: [T; 3]) -> V3<R> {
    [
        R::from_f64(a[0].to_f64()),
        R::from_f64(a[1].to_f64()),
        R::from_f64(a[2].to_f64()),
    ]
}

/// The directed speed of one body point as a function of the angle:
/// `s(theta) = a + p cos(theta) + q sin(theta)` with `theta = omega t`.
#[derive(Clone, Copy, Debug)]
pub struct SpeedProfile<R> {
    /// `v . n^`.
    pub a: R,
    /// `(n^ x w) . r`.
    pub p: R,
    /// `(n^ x w) . (w^ x r)`.
    pub q: R,
    /// `|w|`.
    pub omega: R,
}

/// The motion's quantities in `R`, computed once for all vertices.
#[derive(Clone, Copy, Debug)]
pub struct Frame<R> {
    a: R,
    c: V3<R>,
    k: V3<R>,
    omega: R,
    ta: R,
    tb: R,
    /// The start orientation's exact rotation (of the stored quaternion,
    /// normalised in `R`), row-major.
    rot: [V3<R>; 3],
    /// The rotation centre in the body frame.
    offset: V3<R>,
}

impl<R: Real> Frame<R> {
    /// Widens the motion and direction exactly to `R` and normalises `n`
    /// there; the start orientation's rotation is built in `R` from its
    /// quaternion normalised in `R`, independently of the crate's matrix.
    pub fn new<T: Float>(motion: &RigidMotion<T>, n: Direction<T>) -> Self {
        let n: V3<R> = widen(n.to_array());
        let n = scale(n, R::from_f64(1.0).div(dot(n, n).sqrt()));
        let v: V3<R> = widen(motion.linear().to_array());
        let w: V3<R> = widen(motion.angular().to_array());
        let omega = dot(w, w).sqrt();
        let zero = R::from_f64(0.0);
        let k = if omega > zero {
            scale(w, R::from_f64(1.0).div(omega))
        } else {
            [zero; 3]
        };
        let iv = motion.interval();
        Self {
            a: dot(v, n),
            c: cross(n, w),
            k,
            omega,
            ta: R::from_f64(iv.start().to_f64()),
            tb: R::from_f64(iv.end().to_f64()),
            rot: rotation_matrix(motion.orientation().quaternion()),
            offset: widen(motion.local_centre().to_array()),
        }
    }

    /// The speed profile of body point `r` (in the body frame): its lever
    /// arm at the epoch is `Q0 (r - c)`, computed in `R`.
    pub fn profile<T: Float>(&self, r: [T; 3]) -> SpeedProfile<R> {
        let r: V3<R> = widen(r);
        let d = [
            r[0].sub(self.offset[0]),
            r[1].sub(self.offset[1]),
            r[2].sub(self.offset[2]),
        ];
        let arm = [
            dot(self.rot[0], d),
            dot(self.rot[1], d),
            dot(self.rot[2], d),
        ];
        SpeedProfile {
            a: self.a,
            p: dot(self.c, arm),
            q: dot(self.c, cross(self.k, arm)),
            omega: self.omega,
        }
    }
}

/// The rotation matrix of the quaternion `(w, x, y, z)` normalised in `R`:
/// `(w^2 - |v|^2) I + 2 v v^T + 2 w [v]x` over `|q|^2`.
fn rotation_matrix<T: Float, R: Real>(q: [T; 4]) -> [V3<R>; 3] {
    let [w, x, y, z] = q.map(|c| R::from_f64(c.to_f64()));
    let n2 = w.mul(w).add(x.mul(x)).add(y.mul(y)).add(z.mul(z));
    let two = R::from_f64(2.0);
    let d = w.mul(w).sub(x.mul(x)).sub(y.mul(y)).sub(z.mul(z));
    let e = |a: R, b: R, sign: f64, c: R, e: R| {
        two.mul(a.mul(b).add(R::from_f64(sign).mul(c.mul(e))))
            .div(n2)
    };
    [
        [
            d.add(two.mul(x.mul(x))).div(n2),
            e(x, y, -1.0, w, z),
            e(x, z, 1.0, w, y),
        ],
        [
            e(x, y, 1.0, w, z),
            d.add(two.mul(y.mul(y))).div(n2),
            e(y, z, -1.0, w, x),
        ],
        [
            e(x, z, -1.0, w, y),
            e(y, z, 1.0, w, x),
            d.add(two.mul(z.mul(z))).div(n2),
        ],
    ]
}

impl<R: Real> SpeedProfile<R> {
    /// `s(t)`.
    pub fn speed_at(&self, t: R) -> R {
        let th = self.omega.mul(t);
        self.a.add(self.p.mul(th.cos())).add(self.q.mul(th.sin()))
    }

    /// `sup_{t in [ta, tb]} |s(t)|`, exactly (up to the precision of `R`).
    pub fn sup_abs(&self, ta: R, tb: R) -> R {
        let mut best = self.speed_at(ta).abs().max(self.speed_at(tb).abs());
        let zero = R::from_f64(0.0);
        if self.omega > zero && (self.p.abs() > zero || self.q.abs() > zero) {
            let b = self.p.mul(self.p).add(self.q.mul(self.q)).sqrt();
            let phi = self.q.atan2(self.p);
            let (tha, thb) = (self.omega.mul(ta), self.omega.mul(tb));
            if arc_contains(tha, thb, phi) {
                best = best.max(self.a.add(b).abs());
            }
            if arc_contains(tha, thb, phi.add(R::pi())) {
                best = best.max(self.a.sub(b).abs());
            }
        }
        best
    }

    /// `sup_{t in [ta, tb]} s(t)` (signed: the one-sided bound's target),
    /// exactly (up to the precision of `R`).
    pub fn sup_signed(&self, ta: R, tb: R) -> R {
        let mut best = self.speed_at(ta).max(self.speed_at(tb));
        let zero = R::from_f64(0.0);
        if self.omega > zero && (self.p.abs() > zero || self.q.abs() > zero) {
            let b = self.p.mul(self.p).add(self.q.mul(self.q)).sqrt();
            let phi = self.q.atan2(self.p);
            let (tha, thb) = (self.omega.mul(ta), self.omega.mul(tb));
            if arc_contains(tha, thb, phi) {
                best = best.max(self.a.add(b));
            }
        }
        best
    }

    /// `integral_{ta}^{tb} |s(t)| dt`, exactly (up to the precision of `R`).
    pub fn integral_abs(&self, ta: R, tb: R) -> R {
        let zero = R::from_f64(0.0);
        if self.omega <= zero {
            return self.speed_at(ta).abs().mul(tb.sub(ta));
        }
        let b = self.p.mul(self.p).add(self.q.mul(self.q)).sqrt();
        if b <= zero {
            return self.a.abs().mul(tb.sub(ta));
        }
        let phi = self.q.atan2(self.p);
        let alpha = self.omega.mul(ta).sub(phi);
        // The span is taken from `tb - ta` directly, not as a difference of
        // two large angles, so tiny sweeps keep their relative accuracy.
        let span = self.omega.mul(tb.sub(ta));
        integral_abs_cos(self.a, b, alpha, span).div(self.omega)
    }
}

/// `true` if `theta_a <= x + 2 pi k <= theta_b` for some integer `k`.
fn arc_contains<R: Real>(tha: R, thb: R, x: R) -> bool {
    let two_pi = R::pi().add(R::pi());
    // the smallest x + 2 pi k >= tha
    let k = tha.sub(x).div(two_pi).floor();
    let mut y = x.add(two_pi.mul(k));
    if y < tha {
        y = y.add(two_pi);
    }
    y <= thb
}

/// `integral_alpha^{alpha + span} |a + b cos(psi)| dpsi` for `b > 0`, `span >= 0`.
fn integral_abs_cos<R: Real>(a: R, b: R, alpha: R, span: R) -> R {
    let two_pi = R::pi().add(R::pi());
    let full = span.div(two_pi).floor();
    let zero = R::from_f64(0.0);
    let mut total = zero;
    if full > zero {
        total = full.mul(integral_piece(a, b, zero, two_pi));
    }
    let rest = span.sub(full.mul(two_pi));
    if rest > zero {
        total = total.add(integral_piece(a, b, alpha, rest));
    }
    total
}

/// `integral_alpha^{alpha + span} |a + b cos(psi)| dpsi` over at most one
/// period, split at the zero crossings. Each piece `[z0, z0 + h]` is
/// `|a h + 2 b cos(z0 + h/2) sin(h/2)|`: the identity
/// `sin z1 - sin z0 = 2 cos((z0 + z1)/2) sin((z1 - z0)/2)` avoids the
/// cancellation of `sin z1 - sin z0` for short pieces.
fn integral_piece<R: Real>(a: R, b: R, alpha: R, span: R) -> R {
    let two_pi = R::pi().add(R::pi());
    let zero = R::from_f64(0.0);
    let half = R::from_f64(0.5);
    // cut points as offsets from alpha, in [0, span]
    let mut cuts = [zero; 8];
    let mut m = 1;
    let ratio = zero.sub(a).div(b);
    if ratio > R::from_f64(-1.0) && ratio < R::from_f64(1.0) {
        let psi0 = ratio.acos();
        let base = alpha.div(two_pi).floor().mul(two_pi);
        // alpha is in [base, base + 2 pi) and the piece ends before
        // alpha + 2 pi < base + 4 pi: zeros come from base, base + 2 pi and
        // base + 4 pi (and, for rounding at the ends, base - 2 pi).
        for j in 0..4 {
            let shift = base.add(two_pi.mul(R::from_f64(f64::from(j) - 1.0)));
            for z in [shift.add(psi0), shift.sub(psi0)] {
                let off = z.sub(alpha);
                if off > zero && off < span && m < 7 {
                    cuts[m] = off;
                    m += 1;
                }
            }
        }
    }
    cuts[m] = span;
    m += 1;
    // insertion sort of the few cut points
    for i in 1..m {
        let mut j = i;
        while j > 0 && cuts[j] < cuts[j - 1] {
            cuts.swap(j, j - 1);
            j -= 1;
        }
    }
    let mut total = zero;
    for j in 0..m - 1 {
        let h = cuts[j + 1].sub(cuts[j]);
        let mid = alpha.add(cuts[j]).add(h.mul(half));
        let piece = a.mul(h).add(
            R::from_f64(2.0)
                .mul(b)
                .mul(mid.cos())
                .mul(h.mul(half).sin()),
        );
        total = total.add(piece.abs());
    }
    total
}

/// The exact directed motion of a whole body.
#[derive(Clone, Copy, Debug)]
pub struct Exact<R> {
    /// `sup_t max_i |p_i'(t) . n|` over the motion's interval.
    pub sup_speed: R,
    /// `max_i integral |p_i'(t) . n| dt` over the motion's interval (the seed's `mu`).
    pub displacement: R,
}

/// The exact largest *signed* directed speed `max_i sup_t p_i'(t) . n/|n|`
/// of `vertices` under `motion` over its interval, evaluated in `R`: what a
/// one-sided bound ([`DirectedProbe::rate`](crate::DirectedProbe::rate))
/// must dominate. `-inf` for no vertex.
pub fn exact_sup_signed<T: Float, R: Real>(
    vertices: &[[T; 3]],
    motion: &RigidMotion<T>,
    n: Direction<T>,
) -> R {
    let f: Frame<R> = Frame::new(motion, n);
    let mut sup = R::from_f64(f64::NEG_INFINITY);
    for r in vertices {
        sup = sup.max(f.profile(*r).sup_signed(f.ta, f.tb));
    }
    sup
}

/// The exact directed speed and displacement of `vertices` under `motion`
/// along `n`, evaluated in `R`.
///
/// ```
/// use motion_bound::{reference::exact, Direction, RigidMotion};
/// let m = RigidMotion::try_from_arrays([0.0; 3], [0.0; 3], [0.0, 0.0, core::f64::consts::PI]).unwrap();
/// // The tip of a unit rod turning half a turn about z has velocity
/// // pi (-sin(pi t), cos(pi t), 0): along x, sup pi and integral of pi |sin(pi t)| = 2.
/// let e = exact::<f64, f64>(&[[1.0, 0.0, 0.0]], &m, Direction::X);
/// assert!((e.displacement - 2.0).abs() < 1e-12);
/// assert!((e.sup_speed - core::f64::consts::PI).abs() < 1e-12);
/// ```
pub fn exact<T: Float, R: Real>(
    vertices: &[[T; 3]],
    motion: &RigidMotion<T>,
    n: Direction<T>,
) -> Exact<R> {
    let f: Frame<R> = Frame::new(motion, n);
    let mut sup = R::from_f64(0.0);
    let mut disp = R::from_f64(0.0);
    for r in vertices {
        let prof = f.profile(*r);
        sup = sup.max(prof.sup_abs(f.ta, f.tb));
        disp = disp.max(prof.integral_abs(f.ta, f.tb));
    }
    Exact {
        sup_speed: sup,
        displacement: disp,
    }
}
