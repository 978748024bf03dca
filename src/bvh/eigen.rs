//! Principal axes of a point cloud: the eigenvectors of a symmetric 3x3
//! matrix by cyclic Jacobi rotations.
//!
//! Only the *choice* of a box's axes comes from here; nothing downstream
//! relies on these axes being accurate or orthonormal, because the box built
//! on them is certified afterwards against the stored (rounded) axes
//! (`proofs/floating-point.md`, "Oriented box"). So plain `f64` arithmetic
//! without error analysis is enough.

use crate::Float;

/// The unit eigenvectors of the symmetric matrix `a`, as rows, ordered by
/// eigenvalue from largest to smallest (for a covariance matrix: the
/// direction of greatest spread first, the thinnest last).
///
/// A matrix with a non-finite entry gives the identity (any orthonormal
/// frame is a valid, if loose, choice of box axes).
pub(crate) fn principal_axes(a: [[f64; 3]; 3]) -> [[f64; 3]; 3] {
    let identity = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
    if a.iter().flatten().any(|x| !x.is_finite()) {
        return identity;
    }
    // The eigenvectors do not depend on the matrix's scale, but the sweep's
    // squares of entries would overflow or underflow for a covariance of
    // coordinates far from 1 (fourth powers of lengths: above about `1e77`
    // or below `1e-77` in `f64`), leaving loose, arbitrary boxes. A power of
    // two brings the largest entry into `[1, 2)`, exactly.
    let m = a.iter().flatten().fold(0.0f64, |m, x| m.max(x.abs()));
    if m == 0.0 {
        return identity;
    }
    // `m`'s binary exponent `e` (`2^e <= m < 2^(e+1)`; `-1023` when
    // subnormal), and `2^-e` built from its bits.
    let e = ((m.to_bits() >> 52) & 0x7ff) as i32 - 1023;
    let scale = f64::from_bits(((1023 - e).clamp(1, 2046) as u64) << 52);
    let mut a = a.map(|row| row.map(|x| x * scale));
    // Columns of `v` are the eigenvectors.
    let mut v = identity;
    for _sweep in 0..32 {
        let off = a[0][1] * a[0][1] + a[0][2] * a[0][2] + a[1][2] * a[1][2];
        let diag = a[0][0] * a[0][0] + a[1][1] * a[1][1] + a[2][2] * a[2][2];
        if off <= 1e-32 * diag || off == 0.0 {
            break;
        }
        for (p, q) in [(0, 1), (0, 2), (1, 2)] {
            if a[p][q] == 0.0 {
                continue;
            }
            // Annihilate a[p][q]: tan of the rotation angle, the smaller root.
            let theta = (a[q][q] - a[p][p]) / (2.0 * a[p][q]);
            let t = if theta.abs() > 1e150 {
                0.5 / theta
            } else {
                let s = if theta >= 0.0 { 1.0 } else { -1.0 };
                s / (theta.abs() + Float::sqrt(theta * theta + 1.0))
            };
            let c = 1.0 / Float::sqrt(t * t + 1.0);
            let s = t * c;
            // a <- J^T a J, v <- v J with J the rotation in the (p, q) plane.
            for row in &mut a {
                let (akp, akq) = (row[p], row[q]);
                row[p] = c * akp - s * akq;
                row[q] = s * akp + c * akq;
            }
            let (rp, rq) = (a[p], a[q]);
            for k in 0..3 {
                a[p][k] = c * rp[k] - s * rq[k];
                a[q][k] = s * rp[k] + c * rq[k];
            }
            for row in &mut v {
                let (vp, vq) = (row[p], row[q]);
                row[p] = c * vp - s * vq;
                row[q] = s * vp + c * vq;
            }
        }
    }
    let mut order = [0usize, 1, 2];
    order.sort_by(|&i, &j| a[j][j].total_cmp(&a[i][i]));
    order.map(|k| {
        let e = [v[0][k], v[1][k], v[2][k]];
        let len = Float::sqrt(e[0] * e[0] + e[1] * e[1] + e[2] * e[2]);
        if len > 0.0 && len.is_finite() {
            e.map(|x| x / len)
        } else {
            identity[k]
        }
    })
}

#[cfg(test)]
mod tests {
    use super::principal_axes;

    fn mul(a: &[[f64; 3]; 3], x: &[f64; 3]) -> [f64; 3] {
        [0, 1, 2].map(|i| a[i][0] * x[0] + a[i][1] * x[1] + a[i][2] * x[2])
    }

    #[test]
    fn eigenvectors_satisfy_the_eigen_equation_and_are_sorted() {
        // A symmetric matrix with eigenvalues 5, 2, -1 in a rotated frame,
        // built from an exact closed form: Q diag(5, 2, -1) Q^T.
        let (c, s) = (0.6f64, 0.8f64);
        let q = [[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]];
        let lam = [5.0, 2.0, -1.0];
        let mut a = [[0.0; 3]; 3];
        for i in 0..3 {
            for j in 0..3 {
                a[i][j] = (0..3).map(|k| q[i][k] * lam[k] * q[j][k]).sum();
            }
        }
        let axes = principal_axes(a);
        for (e, l) in axes.iter().zip(lam) {
            let ae = mul(&a, e);
            for k in 0..3 {
                assert!((ae[k] - l * e[k]).abs() < 1e-12, "{ae:?} vs {l} {e:?}");
            }
        }
        // Orthonormal.
        for i in 0..3 {
            for j in 0..3 {
                let d: f64 = (0..3).map(|k| axes[i][k] * axes[j][k]).sum();
                let want = if i == j { 1.0 } else { 0.0 };
                assert!((d - want).abs() < 1e-12);
            }
        }
    }

    /// A covariance of coordinates near `1e100` has entries near `1e200`,
    /// whose squares overflowed in the sweep (and those of `1e-100` underflowed):
    /// the boxes of a mesh scaled by `1e80` took four times the node pairs.
    #[test]
    fn the_axes_do_not_depend_on_the_matrix_scale() {
        let a = [[3.0, 1.0, 0.5], [1.0, 2.0, 0.25], [0.5, 0.25, 1.0]];
        let unit = principal_axes(a);
        for scale in [1e-300, 1e-200, 1e-150, 1e150, 1e200, 1e300] {
            let axes = principal_axes(a.map(|row| row.map(|x| x * scale)));
            for (e, f) in axes.iter().zip(&unit) {
                let dot: f64 = (0..3).map(|k| e[k] * f[k]).sum();
                assert!(
                    dot.abs() > 1.0 - 1e-12,
                    "scale {scale}: {e:?} against {f:?}"
                );
            }
        }
    }

    #[test]
    fn degenerate_and_non_finite_matrices_give_a_frame() {
        let axes = principal_axes([[0.0; 3]; 3]);
        assert_eq!(axes[0], [1.0, 0.0, 0.0]);
        let axes = principal_axes([[f64::NAN, 0.0, 0.0], [0.0; 3], [0.0; 3]]);
        assert_eq!(axes[2], [0.0, 0.0, 1.0]);
        // Repeated eigenvalues: still orthonormal.
        let axes = principal_axes([[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 3.0]]);
        assert_eq!(axes[0], [0.0, 0.0, 1.0]);
    }
}
