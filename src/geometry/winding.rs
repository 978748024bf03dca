//! The winding number of a closed triangle surface about a point, decided
//! exactly: the signed count of the triangles that a ray from the point
//! crosses.
//!
//! The ray leaves `p` along `+x`, from `p` moved by `(0, eps, eps^2)` for an
//! infinitesimal `eps > 0` (a symbolic perturbation in the manner of
//! Edelsbrunner and Mücke's simulation of simplicity). Seen along `x`, the
//! moved point lies on no projected edge (a projected edge's orientation
//! against it is a polynomial in `eps` that is not zero unless the edge
//! projects to a point), so the ray passes through no vertex and no edge,
//! meets no triangle parallel to it, and crosses every triangle it meets
//! once, transversally. For a closed surface (every directed edge matched by
//! its reverse, [`EdgeReport::is_closed`](crate::EdgeReport::is_closed)) and
//! a point off it, the signed count of those crossings is the surface's
//! winding number about the point (`proofs/09-ca-toi.md`, Lemma 9.7).
//!
//! Every sign is exact on the floating-point coordinates as given: the
//! orientations are `orient2d` on the `(y, z)` projection and `orient3d`
//! (the filtered predicates, with [`robust`]'s exact fallback), the
//! perturbation's signs are comparisons of coordinates. The exact fallback
//! needs every coordinate of a predicate's points in its exact range after
//! an exact rescaling by a power of two (nonzero coordinates within `2^200`
//! of each other's magnitude): a triangle that fails it is
//! [`Crossing::Undecided`].

use super::predicates::{orient2d, orient3d, points_in_exact_range, project};
use super::scale::Scale;
use crate::{Float, Vec3};

/// What one triangle contributes to the winding number of a point along the
/// perturbed ray.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Crossing {
    /// The ray does not cross the triangle.
    Miss,
    /// The ray crosses it: `+1` where the triangle's right-handed normal
    /// points along `+x` (the ray leaves through an outward-wound face),
    /// `-1` where it points against.
    Cross(i8),
    /// The point lies on the (closed) triangle.
    Surface,
    /// The exact predicates cannot decide on these coordinates.
    Undecided,
}

/// The winding number about a point, or why there is none
/// ([`Winding::add`] accumulates the crossings).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Winding {
    /// The signed count of crossings so far.
    Number(i64),
    /// The point lies on the surface (exact: it dominates every other
    /// finding).
    Surface,
    /// Some crossing could not be decided.
    Undecided,
}

impl Winding {
    /// The winding number with one more triangle's crossing.
    #[inline]
    #[must_use]
    pub(crate) fn add(self, c: Crossing) -> Self {
        match (self, c) {
            (Self::Surface, _) | (_, Crossing::Surface) => Self::Surface,
            (Self::Undecided, _) | (_, Crossing::Undecided) => Self::Undecided,
            (Self::Number(n), Crossing::Cross(s)) => Self::Number(n + i64::from(s)),
            (Self::Number(n), Crossing::Miss) => Self::Number(n),
        }
    }
}

/// The sign of `x - y`, exactly.
#[inline]
fn compare(x: f64, y: f64) -> i8 {
    if x > y {
        1
    } else if x < y {
        -1
    } else {
        0
    }
}

/// The sign of `orient2d(a, b, p + (eps, eps^2))` in the plane `(u, v)`:
/// the exact sign when it is not zero; else the sign of its `eps` term,
/// `a_v - b_v`; else of its `eps^2` term, `b_u - a_u`; `0` only when `a`
/// and `b` coincide (the determinant is affine in `p`, so no other term
/// exists). `scaled` holds `a`, `b` and `p` as the predicate takes them
/// (rescaled exactly), `a` and `b` are unscaled for the comparisons.
#[inline]
fn perturbed_side(scaled: [[f64; 2]; 3], a: [f64; 2], b: [f64; 2]) -> i8 {
    let [sa, sb, sp] = scaled;
    let s = orient2d(sa, sb, sp).sign;
    if s != 0 {
        return s;
    }
    match compare(a[1], b[1]) {
        0 => compare(b[0], a[0]),
        s => s,
    }
}

/// What triangle `tri` contributes to the winding number about `p` along
/// the perturbed ray (the module docs).
pub(crate) fn ray_crossing<T: Float>(p: Vec3<T>, tri: &[Vec3<T>; 3]) -> Crossing {
    let [a, b, c] = *tri;
    // Exact filters: the moved point's y is `p.y + eps`, its z `p.z + eps^2`,
    // so its projection is inside the triangle's only if some corner has
    // y <= p.y and some y > p.y (the same for z); the triangle is behind the
    // ray's origin when every corner has x < p.x.
    let straddles = |k: fn(Vec3<T>) -> T| {
        let (lo, hi) = (
            k(a).min_nan(k(b)).min_nan(k(c)),
            k(a).max_nan(k(b)).max_nan(k(c)),
        );
        lo <= k(p) && k(p) < hi
    };
    if !straddles(|q| q.y) || !straddles(|q| q.z) || a.x.max_nan(b.x).max_nan(c.x) < p.x {
        return Crossing::Miss;
    }
    let wide = [p, a, b, c].map(|q| Vec3::new(q.x.to_f64(), q.y.to_f64(), q.z.to_f64()));
    let scaled = if points_in_exact_range(&wide) {
        wide
    } else {
        let s = Scale::for_points(&wide);
        let scaled = wide.map(|q| s.apply(q));
        if !points_in_exact_range(&scaled) {
            return Crossing::Undecided;
        }
        scaled
    };
    let [_, wa, wb, wc] = wide.map(|q| project(q, 0));
    let [sp, sa, sb, sc] = scaled.map(|q| project(q, 0));
    let s = perturbed_side([sa, sb, sp], wa, wb);
    if s == 0
        || perturbed_side([sb, sc, sp], wb, wc) != s
        || perturbed_side([sc, sa, sp], wc, wa) != s
    {
        return Crossing::Miss;
    }
    // The moved point is strictly inside the projected triangle, whose
    // orientation (the sign of the normal's x component `n_x`) is then `s`.
    // `orient3d(a, b, c, p) = n . (a - p)`: the ray meets the plane at
    // `x = p.x + n . (a - p) / n_x`, ahead of `p` when both signs agree; on
    // the plane, `p` is on the triangle itself.
    let [qp, qa, qb, qc] = scaled;
    match orient3d(qa, qb, qc, qp).sign {
        0 => Crossing::Surface,
        o if o == s => Crossing::Cross(s),
        _ => Crossing::Miss,
    }
}

/// The winding number about `p` of the triangles `triangles` (every
/// triangle's crossing summed).
pub(crate) fn winding_number<T: Float>(
    p: Vec3<T>,
    triangles: impl IntoIterator<Item = [Vec3<T>; 3]>,
) -> Winding {
    let mut w = Winding::Number(0);
    for tri in triangles {
        w = w.add(ray_crossing(p, &tri));
        if w == Winding::Surface {
            break;
        }
    }
    w
}

#[cfg(test)]
mod tests {
    use super::{ray_crossing, winding_number, Crossing, Winding};
    use crate::Vec3;
    use alloc::vec::Vec;

    /// The 12 outward-wound triangles of the box `[lo, hi]^3`.
    fn cube(lo: f64, hi: f64) -> Vec<[Vec3<f64>; 3]> {
        let v = |i: usize| {
            Vec3::new(
                if i & 1 == 0 { lo } else { hi },
                if i & 2 == 0 { lo } else { hi },
                if i & 4 == 0 { lo } else { hi },
            )
        };
        let quads = [
            [0, 2, 3, 1],
            [4, 5, 7, 6],
            [0, 1, 5, 4],
            [2, 6, 7, 3],
            [0, 4, 6, 2],
            [1, 3, 7, 5],
        ];
        quads
            .iter()
            .flat_map(|q| [[v(q[0]), v(q[1]), v(q[2])], [v(q[0]), v(q[2]), v(q[3])]])
            .collect()
    }

    #[test]
    fn the_cube_winds_once_about_its_inside_and_never_outside() {
        let tris = cube(-1.0, 1.0);
        let w = |x: f64, y: f64, z: f64| winding_number(Vec3::new(x, y, z), tris.iter().copied());
        assert_eq!(w(0.0, 0.0, 0.0), Winding::Number(1), "centre");
        // Rays through vertices, along edges and diagonals of faces: the
        // perturbation decides every one.
        assert_eq!(
            w(-2.0, 1.0, 1.0),
            Winding::Number(0),
            "along an edge, outside"
        );
        assert_eq!(
            w(-2.0, -1.0, -1.0),
            Winding::Number(0),
            "through two corners"
        );
        assert_eq!(
            w(-2.0, 0.0, 0.0),
            Winding::Number(0),
            "through face diagonals"
        );
        assert_eq!(w(0.5, 0.0, 0.0), Winding::Number(1), "inside, diagonal");
        assert_eq!(
            w(0.5, 0.3, 0.3),
            Winding::Number(1),
            "inside, diagonal of the exit face"
        );
        assert_eq!(w(2.0, 0.0, 0.0), Winding::Number(0), "beyond");
        assert_eq!(w(0.0, 2.0, 0.0), Winding::Number(0), "beside");
        assert_eq!(w(1.0, 0.25, 0.5), Winding::Surface, "on a face");
        assert_eq!(w(-1.0, 0.0, 0.0), Winding::Surface, "on a face diagonal");
        assert_eq!(w(-1.0, -1.0, -1.0), Winding::Surface, "a corner");
        // A point on the surface may also be taken for the moved point
        // beside it, inside or outside: `(1, 1 + eps, 1 + eps^2)` is
        // outside, `(0, -1 + eps, -1 + eps^2)` inside.
        assert_eq!(w(1.0, 1.0, 1.0), Winding::Number(0), "the opposite corner");
        assert_eq!(w(0.0, -1.0, -1.0), Winding::Number(1), "on an edge");
        // Inward winding: -1 inside.
        let inward: Vec<_> = tris.iter().map(|t| [t[0], t[2], t[1]]).collect();
        assert_eq!(
            winding_number(Vec3::new(0.1, 0.2, 0.3), inward.iter().copied()),
            Winding::Number(-1),
            "inward"
        );
    }

    #[test]
    fn coordinates_out_of_the_exact_range_are_undecided_not_guessed() {
        let tri = [
            Vec3::new(1.0, -1.0, -1.0),
            Vec3::new(1.0, 1e-250, 1.0),
            Vec3::new(1.0, 1.0, -1.0),
        ];
        assert_eq!(
            ray_crossing(Vec3::new(0.0, 0.0, 0.0), &tri),
            Crossing::Undecided,
            "tiny beside large"
        );
        // Large but within 2^200 of each other: rescaled, decided. The
        // triangle turns clockwise seen along x: its normal points to -x.
        let big = [
            Vec3::new(1e300, -1e300, -1e300),
            Vec3::new(1e300, 0.0, 1e300),
            Vec3::new(1e300, 1e300, -1e300),
        ];
        assert_eq!(
            ray_crossing(Vec3::new(0.0, 0.0, 0.0), &big),
            Crossing::Cross(-1),
            "rescaled"
        );
        assert_eq!(
            ray_crossing(Vec3::new(2e300, 0.0, 0.0), &big),
            Crossing::Miss,
            "behind"
        );
    }
}
