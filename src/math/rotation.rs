//! Rotations given as unit quaternions, what engines hand over for a body's
//! orientation.

use core::ops::Mul;

use crate::error::{InputError, Quantity};
use crate::math::pose::{mat_t_vec, mat_vec};
use crate::{Float, Vec3};

/// A rotation, from a unit quaternion `q = (w, x, y, z)`: the orientation of
/// a body frame in the world frame.
///
/// The quaternion is normalised on construction and its rotation matrix
/// computed once, `M = I + 2 w [v]x + 2 [v]x^2` with `v = (x, y, z)`, so that
/// rotating a vector costs a matrix product. The exact rotation this stands
/// for is that of the stored quaternion ([`quaternion`](Self::quaternion),
/// the input normalised in floating point) normalised exactly; the stored
/// matrix differs from it by at most [`matrix_error`](Self::matrix_error)
/// `= 80 u` in the spectral norm (`proofs/floating-point.md`, section
/// "Orientation"), which every bound and placement of this crate accounts
/// for. The identity is exact.
///
/// ```
/// use motion_bound::{Rotation, Vec3};
/// // A quarter turn about z, from an unnormalised quaternion.
/// let h = core::f64::consts::FRAC_PI_4;
/// let q = Rotation::try_from_quaternion(2.0 * h.cos(), 0.0, 0.0, 2.0 * h.sin())?;
/// let v = q.rotate(Vec3::new(1.0, 0.0, 0.0));
/// assert!((v - Vec3::new(0.0, 1.0, 0.0)).length() < 1e-15);
/// assert!((q.inverse_rotate(v) - Vec3::new(1.0, 0.0, 0.0)).length() < 1e-15);
/// # Ok::<(), motion_bound::InputError>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Rotation<T> {
    /// `(w, x, y, z)`, normalised.
    q: [T; 4],
    /// `M`, row-major.
    m: [[T; 3]; 3],
    /// Exactly the identity (`M = I` exactly): nothing to account for.
    identity: bool,
}

impl<T: Float> Rotation<T> {
    /// The identity rotation (exact).
    pub const IDENTITY: Self = Self {
        q: [T::ONE, T::ZERO, T::ZERO, T::ZERO],
        m: [
            [T::ONE, T::ZERO, T::ZERO],
            [T::ZERO, T::ONE, T::ZERO],
            [T::ZERO, T::ZERO, T::ONE],
        ],
        identity: true,
    };

    /// The rotation of the quaternion `w + x i + y j + z k`, normalised
    /// (any finite nonzero quaternion is accepted; `q` and `-q` are the same
    /// rotation).
    ///
    /// # Errors
    /// [`InputError::NonFinite`] with [`Quantity::Orientation`] for a NaN or
    /// infinite component, [`InputError::ZeroQuaternion`] for `0`.
    pub fn try_from_quaternion(w: T, x: T, y: T, z: T) -> Result<Self, InputError> {
        let q = [w, x, y, z];
        if q.iter().any(|c| !c.is_finite()) {
            return Err(InputError::NonFinite(Quantity::Orientation));
        }
        let m = q.iter().fold(T::ZERO, |m, c| m.max_nan(c.abs()));
        if m == T::ZERO {
            return Err(InputError::ZeroQuaternion);
        }
        if x == T::ZERO && y == T::ZERO && z == T::ZERO {
            // A real quaternion, of either sign: exactly the identity.
            return Ok(Self::IDENTITY);
        }
        // As `Direction::try_new`: divide by the largest component first, so
        // that the squares neither overflow nor vanish.
        let s = q.map(|c| c / m);
        let len = (s[0] * s[0] + s[1] * s[1] + s[2] * s[2] + s[3] * s[3]).sqrt();
        let q = s.map(|c| c / len);
        Ok(Self {
            q,
            m: matrix(q),
            identity: false,
        })
    }

    /// How far from orthonormal a matrix given to
    /// [`try_from_matrix`](Self::try_from_matrix) may be: each entry of
    /// `M^T M - I` at most `1e-6` in magnitude (at least `64` units of
    /// rounding for `f32`, whose own products carry more).
    pub const MATRIX_TOLERANCE: f64 = 1e-6;

    /// The rotation of the matrix `m` (`m[i][j]` in row `i`, column `j`;
    /// `rotate(v) = m v`), as a homogeneous transform's upper-left block
    /// gives it: the rotation of the quaternion nearest to `m`'s by
    /// Shepperd's method, which is `m` itself when `m` is exactly a
    /// rotation. A matrix a little off (rounded, or composed in `f32`) is
    /// accepted within [`MATRIX_TOLERANCE`](Self::MATRIX_TOLERANCE), and the
    /// body is then placed by the returned rotation, which differs from `m`
    /// by about that much times the body's reach.
    ///
    /// # Errors
    /// [`InputError::NonFinite`] with [`Quantity::Orientation`] for a NaN or
    /// infinite entry; [`InputError::NotARotation`] for a matrix farther from
    /// orthonormal, a scaled one, or a reflection.
    ///
    /// ```
    /// use motion_bound::{InputError, Rotation, Vec3};
    /// let quarter = [[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]]; // 90 degrees about z
    /// let r = Rotation::try_from_matrix(quarter)?;
    /// assert!((r.rotate(Vec3::new(1.0, 0.0, 0.0)) - Vec3::new(0.0, 1.0, 0.0)).length() < 1e-15);
    /// let mirror = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, -1.0]];
    /// assert_eq!(Rotation::try_from_matrix(mirror).err(), Some(InputError::NotARotation));
    /// # Ok::<(), InputError>(())
    /// ```
    pub fn try_from_matrix(m: [[T; 3]; 3]) -> Result<Self, InputError> {
        if m.iter().flatten().any(|c| !c.is_finite()) {
            return Err(InputError::NonFinite(Quantity::Orientation));
        }
        let tol = T::from_f64(Self::MATRIX_TOLERANCE).max_nan(T::UNIT_ROUNDOFF * T::from_u32(128));
        for i in 0..3 {
            for j in 0..3 {
                let dot = m[0][i] * m[0][j] + m[1][i] * m[1][j] + m[2][i] * m[2][j];
                let target = if i == j { T::ONE } else { T::ZERO };
                let close = (dot - target).abs() <= tol; // false for NaN
                if !close {
                    return Err(InputError::NotARotation);
                }
            }
        }
        let det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1])
            - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
            + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
        let proper = det > T::ZERO; // false for NaN
        if !proper {
            return Err(InputError::NotARotation);
        }
        // Shepperd: divide by the largest of 4w^2, 4x^2, 4y^2, 4z^2.
        let quarter = T::HALF * T::HALF;
        let trace = m[0][0] + m[1][1] + m[2][2];
        let (w, x, y, z) = if trace > T::ZERO {
            let s = (trace + T::ONE).sqrt() * T::TWO;
            (
                s * quarter,
                (m[2][1] - m[1][2]) / s,
                (m[0][2] - m[2][0]) / s,
                (m[1][0] - m[0][1]) / s,
            )
        } else if m[0][0] > m[1][1] && m[0][0] > m[2][2] {
            let s = (T::ONE + m[0][0] - m[1][1] - m[2][2]).sqrt() * T::TWO;
            (
                (m[2][1] - m[1][2]) / s,
                s * quarter,
                (m[0][1] + m[1][0]) / s,
                (m[0][2] + m[2][0]) / s,
            )
        } else if m[1][1] > m[2][2] {
            let s = (T::ONE + m[1][1] - m[0][0] - m[2][2]).sqrt() * T::TWO;
            (
                (m[0][2] - m[2][0]) / s,
                (m[0][1] + m[1][0]) / s,
                s * quarter,
                (m[1][2] + m[2][1]) / s,
            )
        } else {
            let s = (T::ONE + m[2][2] - m[0][0] - m[1][1]).sqrt() * T::TWO;
            (
                (m[1][0] - m[0][1]) / s,
                (m[0][2] + m[2][0]) / s,
                (m[1][2] + m[2][1]) / s,
                s * quarter,
            )
        };
        Self::try_from_quaternion(w, x, y, z)
    }

    /// The rotation by `angle` radians about `axis` (right-handed; any
    /// finite nonzero axis, normalised).
    ///
    /// # Errors
    /// [`InputError::NonFinite`] for a NaN or infinite axis or angle,
    /// [`InputError::ZeroDirection`] for a zero axis.
    ///
    /// ```
    /// use motion_bound::{Rotation, Vec3};
    /// let r = Rotation::try_from_axis_angle(Vec3::new(0.0, 0.0, 2.0), core::f64::consts::PI)?;
    /// assert!((r.rotate(Vec3::new(1.0, 0.0, 0.0)) + Vec3::new(1.0, 0.0, 0.0)).length() < 1e-15);
    /// # Ok::<(), motion_bound::InputError>(())
    /// ```
    pub fn try_from_axis_angle(axis: Vec3<T>, angle: T) -> Result<Self, InputError> {
        if !angle.is_finite() {
            return Err(InputError::NonFinite(Quantity::Orientation));
        }
        let k = crate::Direction::try_new(axis)?.get();
        let h = angle * T::HALF;
        let (s, c) = (h.sin(), h.cos());
        Self::try_from_quaternion(c, k.x * s, k.y * s, k.z * s)
    }

    /// The normalised quaternion `(w, x, y, z)`.
    #[inline]
    #[must_use]
    pub const fn quaternion(&self) -> [T; 4] {
        self.q
    }

    /// The rotation matrix `M`, row-major (`matrix()[k]` is row `k`).
    #[inline]
    #[must_use]
    pub const fn matrix(&self) -> [[T; 3]; 3] {
        self.m
    }

    /// An upper bound of the spectral norm `||M - Q||` of the difference
    /// between the stored matrix `M` and the exact rotation `Q` of the stored
    /// quaternion normalised exactly: `80 u` (`proofs/floating-point.md`,
    /// "Orientation"; `0` for the identity).
    #[inline]
    #[must_use]
    pub fn matrix_error(&self) -> T {
        if self.identity {
            T::ZERO
        } else {
            crate::rounding::orientation_error()
        }
    }

    /// `true` for the exact identity (no rounding to account for).
    #[inline]
    #[must_use]
    pub const fn is_identity(&self) -> bool {
        self.identity
    }

    /// `M v`: a body-frame vector in the world frame.
    #[inline]
    #[must_use]
    pub fn rotate(&self, v: Vec3<T>) -> Vec3<T> {
        mat_vec(&self.m, v)
    }

    /// `M^T v`: a world vector in the body frame.
    #[inline]
    #[must_use]
    pub fn inverse_rotate(&self, v: Vec3<T>) -> Vec3<T> {
        mat_t_vec(&self.m, v)
    }

    /// The inverse rotation (the conjugate quaternion).
    #[must_use]
    pub fn inverse(&self) -> Self {
        let [w, x, y, z] = self.q;
        if self.identity {
            return *self;
        }
        let q = [w, -x, -y, -z];
        Self {
            q,
            m: matrix(q),
            identity: false,
        }
    }

    /// The rotation vector (axis times angle, the angle in `[0, pi]`) of the
    /// shortest rotation this stands for: `q` and `-q` give the same one.
    #[must_use]
    pub fn to_scaled_axis(&self) -> Vec3<T> {
        let [w, x, y, z] = self.q;
        // The shortest of q and -q: w >= 0.
        let (w, v) = if w < T::ZERO {
            (-w, Vec3::new(-x, -y, -z))
        } else {
            (w, Vec3::new(x, y, z))
        };
        let s = v.length();
        if s == T::ZERO {
            return Vec3::ZERO;
        }
        let angle = T::TWO * s.atan2(w);
        v * (angle / s)
    }
}

impl<T: Float> Default for Rotation<T> {
    #[inline]
    fn default() -> Self {
        Self::IDENTITY
    }
}

impl<T: Float> Mul for Rotation<T> {
    type Output = Self;

    /// The composition `self * rhs` (apply `rhs` first), renormalised.
    fn mul(self, rhs: Self) -> Self {
        if self.identity {
            return rhs;
        }
        if rhs.identity {
            return self;
        }
        let [a0, a1, a2, a3] = self.q;
        let [b0, b1, b2, b3] = rhs.q;
        let w = a0 * b0 - a1 * b1 - a2 * b2 - a3 * b3;
        let x = a0 * b1 + a1 * b0 + a2 * b3 - a3 * b2;
        let y = a0 * b2 - a1 * b3 + a2 * b0 + a3 * b1;
        let z = a0 * b3 + a1 * b2 - a2 * b1 + a3 * b0;
        // A product of unit quaternions is a unit quaternion up to rounding,
        // never zero.
        Self::try_from_quaternion(w, x, y, z).unwrap_or(Self::IDENTITY)
    }
}

/// `M(q) = I + 2 w [v]x + 2 [v]x^2`, entry by entry (`proofs/floating-point.md`,
/// "Orientation").
fn matrix<T: Float>([w, x, y, z]: [T; 4]) -> [[T; 3]; 3] {
    let (xx, yy, zz) = (x * x, y * y, z * z);
    let (xy, xz, yz) = (x * y, x * z, y * z);
    let (wx, wy, wz) = (w * x, w * y, w * z);
    let two = T::TWO;
    [
        [T::ONE - two * (yy + zz), two * (xy - wz), two * (xz + wy)],
        [two * (xy + wz), T::ONE - two * (xx + zz), two * (yz - wx)],
        [two * (xz - wy), two * (yz + wx), T::ONE - two * (xx + yy)],
    ]
}

#[cfg(test)]
mod tests {
    use super::Rotation;
    use crate::{rotate_about_axis, InputError, Vec3};

    #[test]
    fn matches_rodrigues_composes_and_inverts() {
        let axis = Vec3::new(1.0f64, -2.0, 0.5);
        let k = axis.try_normalize().expect("nonzero");
        let r = Rotation::try_from_axis_angle(axis, 0.9).expect("valid");
        let p = Vec3::new(0.3, 1.2, -0.7);
        let want = rotate_about_axis(p, k, 0.9);
        assert!((r.rotate(p) - want).length() < 1e-15, "Rodrigues");
        assert!(
            (r.inverse_rotate(r.rotate(p)) - p).length() < 1e-15,
            "M^T M"
        );
        assert!(
            (r.inverse().rotate(r.rotate(p)) - p).length() < 1e-15,
            "conjugate"
        );
        let twice = r * r;
        let want2 = rotate_about_axis(p, k, 1.8);
        assert!((twice.rotate(p) - want2).length() < 1e-15, "composition");
        let back = twice.to_scaled_axis();
        assert!((back - k * 1.8).length() < 1e-14, "scaled axis {back:?}");
    }

    /// Matrices built by Rodrigues' formula (not by `matrix`), each of
    /// Shepperd's four branches, back to the same rotation; what is not a
    /// rotation is refused.
    #[test]
    fn matrices_turn_back_into_their_rotations() {
        let axes = [
            Vec3::new(1.0f64, -2.0, 0.5),
            Vec3::new(1.0, 0.0, 0.0),
            Vec3::new(0.0, 1.0, 1e-9),
            Vec3::new(0.0, 0.0, 1.0),
            Vec3::new(-0.3, 0.2, 0.9),
        ];
        // Angles near 0 and pi take the trace branch and the diagonal ones.
        let angles = [
            0.0,
            1e-12,
            0.4,
            2.0,
            3.0,
            core::f64::consts::PI,
            core::f64::consts::PI - 1e-4,
        ];
        let probes = [Vec3::new(0.3, 1.2, -0.7), Vec3::new(-2.0, 0.1, 0.4)];
        for axis in axes {
            let k = axis.try_normalize().expect("nonzero");
            for angle in angles {
                let e = [
                    Vec3::new(1.0, 0.0, 0.0),
                    Vec3::new(0.0, 1.0, 0.0),
                    Vec3::new(0.0, 0.0, 1.0),
                ]
                .map(|c| rotate_about_axis(c, k, angle));
                // Columns are the images of the basis vectors.
                let m = [
                    [e[0].x, e[1].x, e[2].x],
                    [e[0].y, e[1].y, e[2].y],
                    [e[0].z, e[1].z, e[2].z],
                ];
                let r = Rotation::try_from_matrix(m).expect("a rotation");
                for p in probes {
                    let want = rotate_about_axis(p, k, angle);
                    assert!((r.rotate(p) - want).length() < 1e-14, "{axis:?} {angle}");
                }
                let scaled = m.map(|row| row.map(|c| c * 1.001));
                assert_eq!(
                    Rotation::try_from_matrix(scaled).err(),
                    Some(InputError::NotARotation)
                );
                let mut mirrored = m;
                mirrored[2] = mirrored[2].map(|c| -c);
                assert_eq!(
                    Rotation::try_from_matrix(mirrored).err(),
                    Some(InputError::NotARotation)
                );
            }
        }
        let mut bad = [[1.0f64, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
        bad[1][2] = f64::NAN;
        assert!(matches!(
            Rotation::try_from_matrix(bad),
            Err(InputError::NonFinite(_))
        ));
        let zero = [[0.0f64; 3]; 3];
        assert_eq!(
            Rotation::try_from_matrix(zero).err(),
            Some(InputError::NotARotation)
        );
        // An f32 rotation rounded entry by entry is still accepted.
        let r = Rotation::try_from_axis_angle(Vec3::new(1.0f32, 2.0, 3.0), 1.0).expect("valid");
        assert!(Rotation::try_from_matrix(r.matrix()).is_ok());
    }

    #[test]
    fn the_shortest_rotation_and_edge_cases() {
        // -q is the same rotation; its scaled axis is the short one.
        let r = Rotation::try_from_axis_angle(Vec3::new(0.0, 0.0, 1.0), 0.5).expect("valid");
        let [w, x, y, z] = r.quaternion();
        let neg = Rotation::try_from_quaternion(-w, -x, -y, -z).expect("valid");
        assert!((neg.to_scaled_axis() - Vec3::new(0.0, 0.0, 0.5)).length() < 1e-15);
        // A turn of 1.5 pi is the turn of -0.5 pi.
        let long =
            Rotation::try_from_axis_angle(Vec3::new(0.0, 0.0, 1.0), 1.5 * core::f64::consts::PI)
                .expect("valid");
        let s = long.to_scaled_axis();
        assert!(
            (s - Vec3::new(0.0, 0.0, -0.5 * core::f64::consts::PI)).length() < 1e-14,
            "{s:?}"
        );
        assert_eq!(
            Rotation::try_from_quaternion(0.0f64, 0.0, 0.0, 0.0),
            Err(InputError::ZeroQuaternion)
        );
        assert!(Rotation::try_from_quaternion(f64::NAN, 0.0, 0.0, 1.0).is_err());
        let id = Rotation::try_from_quaternion(3.0f32, 0.0, 0.0, 0.0).expect("valid");
        assert!(
            id.is_identity(),
            "a positive real quaternion is the exact identity"
        );
        assert_eq!(id.to_scaled_axis(), Vec3::ZERO);
        // Huge and tiny components normalise without overflow or underflow.
        let big = Rotation::try_from_quaternion(1e300f64, 1e300, 0.0, 0.0).expect("valid");
        let tiny = Rotation::try_from_quaternion(1e-300f64, 1e-300, 0.0, 0.0).expect("valid");
        assert!(
            (big.rotate(Vec3::new(0.0, 1.0, 0.0)) - tiny.rotate(Vec3::new(0.0, 1.0, 0.0))).length()
                < 1e-15
        );
    }
}
