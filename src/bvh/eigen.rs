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
    let mut a = a;
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
