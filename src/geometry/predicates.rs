//! Filtered orientation predicates: a sign when it is certain, else zero.
//!
//! Shewchuk's `orient2d` and `orient3d` determinants evaluated once in
//! floating point, with his a-priori error bounds (J. R. Shewchuk, "Adaptive
//! Precision Floating-Point Arithmetic and Fast Robust Geometric Predicates",
//! Discrete Comput. Geom. 18, 1997,
//! [doi:10.1007/PL00009321](https://doi.org/10.1007/PL00009321), section 4.2:
//! `errboundA = (3 + 16u) u` in 2D and `(7 + 56u) u` in 3D, times the
//! permanent), written in the unit roundoff `u` of `T` and extended by an
//! absolute allowance for underflow (each product may lose `eta / 2`).
//!
//! A sign returned as `+1` or `-1` is the exact sign of the determinant of
//! the floating-point inputs; `0` means "zero or too close to call". There is
//! no exact fallback (that needs expansion arithmetic, kept out of the no_std
//! core): callers treat `0` as "touching", the conservative reading for a
//! distance, and verify what they conclude from it.

use crate::{Float, Vec3};

/// A filtered determinant: its computed value and its certain sign (or 0).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Orientation<T> {
    /// `+1` or `-1` when certain, `0` when zero or uncertain.
    pub(crate) sign: i8,
    /// The computed value (only its sign is certain, and only if `sign != 0`).
    pub(crate) value: T,
}

fn filtered<T: Float>(det: T, errbound: T) -> Orientation<T> {
    let sign = if det > errbound {
        1
    } else if -det > errbound {
        -1
    } else {
        // Also NaN: not certain.
        0
    };
    Orientation { sign, value: det }
}

/// `orient3d(a, b, c, d)`: positive when `d` lies below the plane through
/// `a, b, c` oriented counterclockwise seen from above (Shewchuk's
/// convention), i.e. the determinant of the rows `a - d, b - d, c - d`.
pub(crate) fn orient3d<T: Float>(a: Vec3<T>, b: Vec3<T>, c: Vec3<T>, d: Vec3<T>) -> Orientation<T> {
    let (ad, bd, cd) = (a - d, b - d, c - d);
    let bdxcdy = bd.x * cd.y;
    let cdxbdy = cd.x * bd.y;
    let cdxady = cd.x * ad.y;
    let adxcdy = ad.x * cd.y;
    let adxbdy = ad.x * bd.y;
    let bdxady = bd.x * ad.y;
    let det = ad.z * (bdxcdy - cdxbdy) + bd.z * (cdxady - adxcdy) + cd.z * (adxbdy - bdxady);
    let permanent = (bdxcdy.abs() + cdxbdy.abs()) * ad.z.abs()
        + (cdxady.abs() + adxcdy.abs()) * bd.z.abs()
        + (adxbdy.abs() + bdxady.abs()) * cd.z.abs();
    let u = T::UNIT_ROUNDOFF;
    let bound_a = (T::from_u32(7) + T::from_u32(56) * u) * u;
    let underflow = T::from_u32(8) * T::ETA * (T::ONE + ad.z.abs() + bd.z.abs() + cd.z.abs());
    filtered(det, bound_a * permanent + underflow)
}

/// `orient2d(a, b, c)`: positive when `a, b, c` turn counterclockwise.
pub(crate) fn orient2d<T: Float>(a: [T; 2], b: [T; 2], c: [T; 2]) -> Orientation<T> {
    let acx = a[0] - c[0];
    let bcx = b[0] - c[0];
    let acy = a[1] - c[1];
    let bcy = b[1] - c[1];
    let l = acx * bcy;
    let r = acy * bcx;
    let u = T::UNIT_ROUNDOFF;
    let bound_a = (T::from_u32(3) + T::from_u32(16) * u) * u;
    filtered(
        l - r,
        bound_a * (l.abs() + r.abs()) + T::from_u32(4) * T::ETA,
    )
}

/// The projection of `p` onto the coordinate plane orthogonal to axis
/// `drop`, in the cyclic order `(y, z)`, `(z, x)`, `(x, y)`, so that
/// `orient2d` of projected points is the `drop` component of the normal
/// `(b - a) x (c - a)`.
#[inline]
pub(crate) fn project<T: Float>(p: Vec3<T>, drop: usize) -> [T; 2] {
    match drop {
        0 => [p.y, p.z],
        1 => [p.z, p.x],
        _ => [p.x, p.y],
    }
}

/// The coordinate of `p` along axis `k`.
#[inline]
pub(crate) fn coord<T: Float>(p: Vec3<T>, k: usize) -> T {
    match k {
        0 => p.x,
        1 => p.y,
        _ => p.z,
    }
}

#[cfg(test)]
mod tests {
    use super::{orient2d, orient3d, project};
    use crate::Vec3;

    #[test]
    fn signs_of_simple_configurations() {
        let a = Vec3::new(0.0f64, 0.0, 0.0);
        let b = Vec3::new(1.0, 0.0, 0.0);
        let c = Vec3::new(0.0, 1.0, 0.0);
        assert_eq!(
            orient3d(a, b, c, Vec3::new(0.0, 0.0, -1.0)).sign,
            1,
            "below is positive"
        );
        assert_eq!(
            orient3d(a, b, c, Vec3::new(0.3, 0.3, 1.0)).sign,
            -1,
            "above is negative"
        );
        assert_eq!(
            orient3d(a, b, c, Vec3::new(0.3, 7.0, 0.0)).sign,
            0,
            "in the plane"
        );
        assert_eq!(
            orient3d(a, b, c, a).sign,
            0,
            "a repeated vertex is exactly zero"
        );
        assert_eq!(orient2d([0.0, 0.0], [1.0, 0.0], [0.0, 1.0]).sign, 1, "ccw");
        assert_eq!(
            orient2d([0.0f32, 0.0], [1.0, 1.0], [2.0, 2.0]).sign,
            0,
            "collinear"
        );
        let n = (b - a).cross(c - a);
        assert!(n.z > 0.0, "normal along z");
        assert_eq!(
            orient2d(project(a, 2), project(b, 2), project(c, 2)).sign,
            1,
            "the dropped-axis orientation is the normal's component"
        );
    }
}
