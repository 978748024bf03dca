//! Certified oriented boxes: the tight bounding volume of a node's gap.

use super::eigen::principal_axes;
use crate::rounding::{box_reach_up, box_residual_up, box_weight_up, radius_up, BoxError};
use crate::{Float, Vec3};

/// An oriented box in the body frame, in generator form:
/// `{ c + sum_k y_k u_k + r : |y_k| <= h_k, |r| <= rho }`.
///
/// The axes `u_k` are whatever floats the fit stored; they need not be unit
/// or orthogonal, because containment is certified against them: every
/// corner `p` is `c + sum_k y_k u_k + r` with the computed `y_k` (so
/// `|y_k| <= h_k` exactly) and the residual `r` bounded by `rho`
/// (`proofs/floating-point.md`, "Oriented box"). The set is convex, so it
/// holds the triangles too. Its support along a body-frame direction `m` is
/// `c.m + sum_k h_k |u_k.m| + rho |m|`.
#[derive(Clone, Copy, Debug)]
pub(crate) struct OrientedBox<T> {
    pub(crate) centre: [T; 3],
    /// Axes by decreasing extent: `axes[2]` is the thinnest.
    pub(crate) axes: [[T; 3]; 3],
    pub(crate) half: [T; 3],
    /// The residual radius, times `1 + gamma_7` (so that `rho |n|` is
    /// covered for a computed direction `n`).
    pub(crate) rho: T,
    /// `2 |h|_1`, rounded up: the weight of the rotation's error in the
    /// placed support (`proofs/floating-point.md`, "Oriented box").
    pub(crate) error_weight: T,
}

impl<T: Float> OrientedBox<T> {
    /// The box along the principal axes of `points`, certified to hold
    /// every one of them.
    pub(crate) fn fit<'a>(points: impl Iterator<Item = &'a [T; 3]> + Clone) -> Self
    where
        T: 'a,
    {
        // Principal axes in f64 (a choice, not a claim).
        let mut count = 0.0f64;
        let mut mean = [0.0f64; 3];
        for p in points.clone() {
            count += 1.0;
            for k in 0..3 {
                mean[k] += p[k].to_f64();
            }
        }
        let mean = mean.map(|m| m / count.max(1.0));
        let mut cov = [[0.0f64; 3]; 3];
        for p in points.clone() {
            let d = [0, 1, 2].map(|k| p[k].to_f64() - mean[k]);
            for i in 0..3 {
                for j in 0..3 {
                    cov[i][j] += d[i] * d[j];
                }
            }
        }
        let axes = principal_axes(cov).map(|e| e.map(T::from_f64));
        let u = axes.map(Vec3::from_array);
        // The box's centre: the middle of the projections (any float is fine).
        let origin = Vec3::from_array(mean.map(T::from_f64));
        let (mut lo, mut hi) = ([T::INFINITY; 3], [-T::INFINITY; 3]);
        for p in points.clone() {
            let d = Vec3::from_array(*p) - origin;
            for k in 0..3 {
                let y = d.dot(u[k]);
                lo[k] = lo[k].min_nan(y);
                hi[k] = hi[k].max_nan(y);
            }
        }
        let mut centre = origin;
        for k in 0..3 {
            let mid = lo[k] * T::HALF + hi[k] * T::HALF;
            if mid.is_finite() {
                centre = centre + u[k] * mid;
            }
        }
        // Certify: y_k = fl(fl(p - c).u_k) exactly bounded by h_k, and the
        // residual r = p - c - sum_k y_k u_k bounded by rho.
        let mut half = [T::ZERO; 3];
        let (mut max_sq, mut max_mag) = (T::ZERO, T::ZERO);
        for p in points {
            let pv = Vec3::from_array(*p);
            let d = pv - centre;
            let y = [0, 1, 2].map(|k| d.dot(u[k]));
            for k in 0..3 {
                half[k] = half[k].max_nan(y[k].abs());
            }
            let r = [0, 1, 2].map(|j| {
                let pj = pv.to_array()[j];
                let cj = centre.to_array()[j];
                (((pj - cj) - y[0] * axes[0][j]) - y[1] * axes[1][j]) - y[2] * axes[2][j]
            });
            max_sq = max_sq.max_nan(r[0] * r[0] + r[1] * r[1] + r[2] * r[2]);
            let mag = pv.norm_l1()
                + centre.norm_l1()
                + y[0].abs() * u[0].norm_l1()
                + y[1].abs() * u[1].norm_l1()
                + y[2].abs() * u[2].norm_l1();
            max_mag = max_mag.max_nan(mag);
        }
        // The support is taken along a computed direction of length up to
        // 1 + gamma_5: the residual's part grows with it.
        let rho = box_residual_up(max_sq, max_mag);
        let error_weight = box_weight_up(half[0] + half[1] + half[2]);
        Self {
            centre: centre.to_array(),
            axes,
            half,
            rho,
            error_weight,
        }
    }

    /// The box holding every point within `e` of this one's points: the
    /// residual radius grows by `2 e` (rounded up), which covers `e |n|` for
    /// a computed direction of length up to `1 + gamma_5`
    /// (`proofs/floating-point.md`, "Pieces").
    pub(crate) fn widened(mut self, e: T) -> Self {
        self.rho = crate::rounding::add_up(self.rho, T::TWO * e);
        self
    }

    /// An upper bound of the box's support about its centre along the exact
    /// rotation of the direction whose computed body-frame image is `m`
    /// (`m = fl(R^T n)`, `R` the computed rotation by the angle `a`):
    /// `sum_k h_k |u_k . R^T n| + rho |n|`.
    /// The rotation's angle enters through `err` (`BoxError::new(angle, oriented)`,
    /// computed once per placement).
    #[inline]
    pub(crate) fn support_up_with(&self, m: Vec3<T>, err: &BoxError<T>) -> T {
        err.support_up(self.support_raw(m), self.error_weight)
    }

    /// `fl(sum_k h_k |fl(u_k . m)| + rho)`.
    #[inline]
    pub(crate) fn support_raw(&self, m: Vec3<T>) -> T {
        self.half[0] * Vec3::from_array(self.axes[0]).dot(m).abs()
            + self.half[1] * Vec3::from_array(self.axes[1]).dot(m).abs()
            + self.half[2] * Vec3::from_array(self.axes[2]).dot(m).abs()
            + self.rho
    }

    /// An upper bound of `|c| + sum_k h_k |u_k| + rho`: how far from the
    /// rotation centre any point of the box lies.
    pub(crate) fn reach_up(&self) -> T {
        let c = Vec3::from_array(self.centre);
        let mut sq = c.length_squared();
        let mut ext = self.rho;
        for k in 0..3 {
            let u = Vec3::from_array(self.axes[k]);
            ext += self.half[k] * radius_up(u.length_squared());
        }
        sq = radius_up(sq);
        box_reach_up(sq, ext)
    }
}

#[cfg(test)]
mod tests {
    use super::OrientedBox;
    use crate::Vec3;

    #[test]
    fn a_flat_patch_gets_a_thin_box_that_holds_it() {
        // Points on a tilted plane z = 0.3 x - 0.2 y, plus a bump of 1e-3.
        let mut pts = alloc::vec::Vec::new();
        for i in 0..7 {
            for j in 0..5 {
                let (x, y) = (f64::from(i) * 0.1, f64::from(j) * 0.07);
                let bump = if i == 3 && j == 2 { 1e-3 } else { 0.0 };
                pts.push([x, y, 0.3 * x - 0.2 * y + bump]);
            }
        }
        let b = OrientedBox::fit(pts.iter());
        assert!(b.half[2] < 1e-3, "thin axis {:?}", b.half);
        assert!(b.half[0] > 0.25, "long axis {:?}", b.half);
        // Containment, checked independently: the box's H-form with exact
        // orthonormal axes is implied; here test the support along many
        // directions against every point's projection.
        for k in 0..64 {
            let a = f64::from(k) * 0.37;
            let m = Vec3::new(a.cos() * a.sin(), (2.0 * a).sin(), a.cos());
            let m = m * (1.0 / m.length());
            let s = b.support_up_with(m, &crate::rounding::BoxError::new(0.0, false));
            let c = Vec3::from_array(b.centre).dot(m);
            for p in &pts {
                let proj = Vec3::from_array(*p).dot(m) - c;
                assert!(
                    proj.abs() <= s,
                    "point {p:?} at {proj} beyond {s} along {m:?}"
                );
            }
        }
        assert!(
            b.reach_up()
                >= pts
                    .iter()
                    .map(|p| Vec3::from_array(*p).length())
                    .fold(0.0, f64::max)
        );
    }
}
