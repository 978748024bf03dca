//! Large triangles cut into pieces, so that a large triangle near a much
//! smaller part of the other body costs what that part's neighbourhood
//! costs (`proofs/09-ca-toi.md`, Lemma 9.5).
//!
//! A triangle much longer than the mesh's size scale is cut, in the tree's
//! second hierarchy, by longest-edge bisection in exact barycentric weights
//! (dyadic rationals) down to a fine length. The pieces partition the
//! triangle exactly; their corners are computed from the weights with
//! rounding, each within a certified distance `e` of its exact position
//! (`proofs/floating-point.md`, "Pieces"), and every quantity built from
//! them (volumes, radii, gaps, rates) is widened by `e`. A query takes that
//! hierarchy against a mesh of much smaller triangles, and the whole
//! triangles against one of about the same size.

use alloc::vec::Vec;

use super::node::Leaf;
use crate::rounding::{add_up, piece_corner_error_up};
use crate::{Float, InputError, VertexSet};

/// The deepest a triangle is bisected (`2^12 = 4096` pieces at most): the
/// weights stay exact in `f32`, and a sliver cannot make unbounded work.
pub(crate) const MAX_DEPTH: u32 = 12;

/// Barycentric weights of one corner of a piece (dyadic, exact in `f64`
/// and, at depth at most [`MAX_DEPTH`], in `f32`).
pub(crate) type Weights = [f64; 3];

/// The whole triangle's weights.
pub(crate) const WHOLE: [Weights; 3] = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];

/// The longest edge of a triangle (in `f64`, a choice, not a claim) and the
/// index of the corner opposite it.
pub(crate) fn longest_edge(p: &[[f64; 3]; 3]) -> (f64, usize) {
    let len = |i: usize, j: usize| {
        let d = [0, 1, 2].map(|k| p[i][k] - p[j][k]);
        (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt()
    };
    let e = [len(1, 2), len(2, 0), len(0, 1)];
    let k = if e[0] >= e[1] && e[0] >= e[2] {
        0
    } else if e[1] >= e[2] {
        1
    } else {
        2
    };
    (e[k], k)
}

/// The bisection of one triangle.
pub(crate) struct Cutter<T> {
    corners: [[T; 3]; 3],
    approx: [[f64; 3]; 3],
    /// The certified rounding of every computed piece corner.
    pub(crate) e: T,
    length: f64,
}

impl<T: Float> Cutter<T> {
    /// The bisection of `corners` into pieces whose longest edges are at most
    /// `length` (or [`MAX_DEPTH`] levels deep).
    pub(crate) fn new(corners: [[T; 3]; 3], length: f64) -> Self {
        let l1 = corners
            .iter()
            .fold(T::ZERO, |s, c| s + c[0].abs() + c[1].abs() + c[2].abs());
        Self {
            corners,
            approx: corners.map(|c| c.map(T::to_f64)),
            e: piece_corner_error_up(l1),
            length,
        }
    }

    /// Visits every piece of the bisection, depth first, until `visit`
    /// fails. The stack holds at most one piece a level and one more.
    fn walk<E>(&self, mut visit: impl FnMut(&[Weights; 3]) -> Result<(), E>) -> Result<(), E> {
        let mut stack = [(WHOLE, 0u32); MAX_DEPTH as usize + 2];
        let mut len = 1;
        while len > 0 {
            len -= 1;
            let (ws, level) = stack[len];
            match self.split(&ws, level) {
                Some((first, second)) => {
                    stack[len] = (second, level + 1);
                    stack[len + 1] = (first, level + 1);
                    len += 2;
                }
                None => visit(&ws)?,
            }
        }
        Ok(())
    }

    /// Whether the bisection's pieces number at most `left`, taking them
    /// from it (a dry run, stopped once over).
    pub(crate) fn count_within(&self, left: &mut usize) -> bool {
        self.walk(|_| -> Result<(), ()> {
            *left = left.checked_sub(1).ok_or(())?;
            Ok(())
        })
        .is_ok()
    }

    /// The two halves of the piece `ws` at `level`, or `None` when it is
    /// short enough or deep enough to stay one piece.
    pub(crate) fn split(
        &self,
        ws: &[Weights; 3],
        level: u32,
    ) -> Option<([Weights; 3], [Weights; 3])> {
        let p = ws.map(|w| {
            [0, 1, 2].map(|k| {
                w[0] * self.approx[0][k] + w[1] * self.approx[1][k] + w[2] * self.approx[2][k]
            })
        });
        let (len, k) = longest_edge(&p);
        if level >= MAX_DEPTH || len.partial_cmp(&self.length) != Some(core::cmp::Ordering::Greater)
        {
            return None;
        }
        // Bisect edge k (opposite corner k) at its midpoint: exact.
        let (i, j) = ((k + 1) % 3, (k + 2) % 3);
        let mid: Weights = [0, 1, 2].map(|m| (ws[i][m] + ws[j][m]) * 0.5);
        let (mut first, mut second) = (*ws, *ws);
        first[j] = mid;
        second[i] = mid;
        Some((first, second))
    }

    /// The computed corners of piece `ws`:
    /// `fl(fl(fl(wa a) + fl(wb b)) + fl(wc c))`, each within `e` of exact.
    pub(crate) fn corners_of(&self, ws: &[Weights; 3]) -> [[T; 3]; 3] {
        let c = &self.corners;
        ws.map(|w| {
            let [wa, wb, wc] = w.map(T::from_f64);
            [0, 1, 2].map(|m| wa * c[0][m] + wb * c[1][m] + wc * c[2][m])
        })
    }

    /// Appends the leaves of every piece of the triangle (its bisection
    /// down to the length) to `out`, for triangle `triangle`.
    pub(crate) fn push_pieces(
        &self,
        out: &mut Vec<Leaf<T>>,
        triangle: u32,
    ) -> Result<(), InputError> {
        self.walk(|ws| {
            out.push(self.leaf(ws, triangle)?);
            Ok(())
        })
    }

    /// The leaf of piece `ws` of triangle `triangle`.
    pub(crate) fn leaf(&self, ws: &[Weights; 3], triangle: u32) -> Result<Leaf<T>, InputError> {
        let corners = self.corners_of(ws);
        let set = VertexSet::try_new(&corners)?;
        Ok(Leaf {
            corners,
            r_hat: add_up(set.summary().max_radius(), self.e),
            inflate: self.e,
            triangle,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::{Cutter, Weights, WHOLE};

    /// Every leaf of the bisection of `cut`, by explicit recursion.
    fn pieces(
        cut: &Cutter<f64>,
        ws: [Weights; 3],
        level: u32,
        out: &mut alloc::vec::Vec<[[f64; 3]; 3]>,
    ) {
        match cut.split(&ws, level) {
            Some((a, b)) => {
                pieces(cut, a, level + 1, out);
                pieces(cut, b, level + 1, out);
            }
            None => out.push(cut.corners_of(&ws)),
        }
    }

    #[test]
    fn pieces_cover_the_triangle_and_are_short() {
        let corners = [[0.0f64, 0.0, 0.0], [2.0, 0.0, 0.0], [0.0, 2.0, 0.0]];
        let cut = Cutter::new(corners, 0.3);
        let mut out = alloc::vec::Vec::new();
        pieces(&cut, WHOLE, 0, &mut out);
        assert!(out.len() > 32, "{} pieces", out.len());
        let (mut enough, mut short) = (out.len(), out.len() - 1);
        assert!(cut.count_within(&mut enough) && enough == 0);
        assert!(!cut.count_within(&mut short), "the count is exact");
        let mut area = 0.0;
        for c in &out {
            let e = |i: usize, j: usize| {
                ((c[i][0] - c[j][0]).powi(2) + (c[i][1] - c[j][1]).powi(2)).sqrt()
            };
            assert!(e(0, 1).max(e(1, 2)).max(e(2, 0)) <= 0.3, "{c:?}");
            area += 0.5
                * ((c[1][0] - c[0][0]) * (c[2][1] - c[0][1])
                    - (c[2][0] - c[0][0]) * (c[1][1] - c[0][1]))
                    .abs();
        }
        assert!((area - 2.0).abs() < 1e-12, "pieces' area {area}");
        assert!(cut.e > 0.0 && cut.e < 1e-14, "corner rounding {}", cut.e);
        // A short triangle is one piece, its corners exact.
        let whole = Cutter::new(corners, 3.0);
        assert!(whole.split(&WHOLE, 0).is_none());
        assert_eq!(whole.corners_of(&WHOLE), corners);
    }

    proptest::proptest! {
        /// Every computed corner of every piece lies within the certified
        /// `e` of its exact position (section "Pieces"), in `f32`, against the
        /// weights' sum in `f64` (each product exact there: 13-bit weights
        /// times 24-bit coordinates; the two sums round by at most
        /// `2^-52` of the terms' sum, allowed for).
        #[test]
        fn corner_rounding_is_within_its_bound(
            c in proptest::array::uniform3(proptest::array::uniform3(-1.0f64..1.0)),
            k in -120i32..50,
            spread in 0i32..40,
        ) {
            let scale = |i: usize| 2f64.powi(k + (i as i32 * spread) / 3);
            let corners: [[f32; 3]; 3] = core::array::from_fn(|i| c[i].map(|x| (x * scale(i)) as f32));
            let cut = Cutter::new(corners, 0.0);
            let mut stack = alloc::vec![(WHOLE, 0u32)];
            let wide = corners.map(|p| p.map(f64::from));
            let l1: f64 = wide.iter().flatten().map(|x| x.abs()).sum();
            proptest::prop_assert!(f64::from(cut.e) <= 8.0 * f64::from(f32::EPSILON / 2.0) * l1 + 1e-36, "e {} for 1-norm {l1}", cut.e);
            while let Some((ws, level)) = stack.pop() {
                let got = cut.corners_of(&ws);
                for (w, f) in ws.iter().zip(&got) {
                    let x = [0, 1, 2].map(|m| w[0] * wide[0][m] + w[1] * wide[1][m] + w[2] * wide[2][m]);
                    let d = [0, 1, 2].map(|m| f64::from(f[m]) - x[m]);
                    let dist = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
                    proptest::prop_assert!(dist <= f64::from(cut.e) + 4.0 * f64::EPSILON * l1,
                        "corner {f:?} is {dist} from {x:?}, beyond {}", cut.e);
                }
                if level < 6 {
                    if let Some((a, b)) = cut.split(&ws, level) {
                        stack.push((a, level + 1));
                        stack.push((b, level + 1));
                    }
                }
            }
        }
    }
}
