//! The certified broad phase: each body's swept box, a sweep and prune over
//! the boxes, half-spaces by their plane, then the groups and the caller's
//! filter (`proofs/11-scene.md`).
//!
//! The sweep and prune is written here rather than taken from a crate: it is
//! forty lines over our own certified boxes, generic over `f32` and `f64`,
//! needs only `alloc` (the scene query works without `std`), allocates
//! nothing once its vectors have grown, and reports pairs in a fixed order.
//! The broad-phase crates we looked at are tied to one float type or to
//! `std`, or return pairs in an order that depends on insertion or on
//! threads; at the measured share (a few percent of a sparse frame, see
//! `docs/performance.md`) a tree would not pay for the dependency.

use alloc::vec::Vec;

use super::params::{SceneParams, SceneQueryError};
use super::query::Scene;
use super::report::{SceneStats, SceneWorkspace};
use super::swept_box::{BoxPath, SweptBox};
use crate::ca::Shape;
use crate::rounding::sub_down;
use crate::{Float, Vec3};

impl<T: Float> Scene<'_, T> {
    /// The broad phase alone: each body's swept box, and the pairs kept for
    /// the narrow phase ([`SceneWorkspace::candidates`]); the pairs' reports
    /// are cleared.
    ///
    /// # Errors
    /// As [`query`](Self::query).
    pub fn broad_phase(
        &self,
        ws: &mut SceneWorkspace<T>,
        params: &SceneParams<T>,
        mut filter: impl FnMut(usize, usize) -> bool,
    ) -> Result<(), SceneQueryError> {
        params.validate()?;
        let mut stats = SceneStats {
            bodies: self.bodies.len(),
            ..SceneStats::default()
        };
        ws.boxes.clear();
        ws.skip.clear();
        for (i, body) in self.bodies.iter().enumerate() {
            if body.motion.interval() != self.interval {
                return Err(SceneQueryError::IntervalMismatch { body: i });
            }
            if let Shape::HalfSpace(_) = body.shape {
                // Unbounded: out of the sweep, tested by its plane below.
                stats.half_spaces += 1;
                let still =
                    body.motion.linear() == Vec3::ZERO && body.motion.angular() == Vec3::ZERO;
                stats.static_bodies += usize::from(still);
                ws.boxes.push(SweptBox::empty());
                ws.skip.push(still);
                continue;
            }
            let (b, path) = SweptBox::with_path(&body.ball, &body.motion);
            match path {
                BoxPath::Static => {
                    stats.static_bodies += 1;
                    stats.box_rates_skipped += 6;
                }
                BoxPath::Translating => {
                    stats.translating_bodies += 1;
                    stats.box_rates_skipped += 6;
                }
                BoxPath::Turning => {
                    stats.turning_bodies += 1;
                    stats.box_rates += 6;
                }
            }
            ws.boxes.push(b);
            ws.skip.push(path == BoxPath::Static);
        }
        let n = self.bodies.len() as u64;
        let s = stats.static_bodies as u64;
        stats.pairs_all = n * n.saturating_sub(1) / 2;
        stats.pairs_static = s * s.saturating_sub(1) / 2;
        overlapping_pairs(
            &ws.boxes,
            &ws.skip,
            params.ca.contact_distance,
            &mut ws.order,
            &mut ws.overlapping,
        );
        // Half-spaces against every other body whose swept box is not
        // certified above their swept plane (`proofs/11-scene.md`, Lemma
        // 11.4); never two half-spaces.
        if stats.half_spaces > 0 {
            for (h, body) in self.bodies.iter().enumerate() {
                let Shape::HalfSpace(half) = body.shape else {
                    continue;
                };
                for (j, other) in self.bodies.iter().enumerate() {
                    if matches!(other.shape, Shape::HalfSpace(_)) {
                        if h < j && !(ws.skip[h] && ws.skip[j]) {
                            stats.pairs_of_half_spaces += 1;
                        }
                        continue;
                    }
                    if ws.skip[h] && ws.skip[j] {
                        // Both static: counted among the static pairs.
                        continue;
                    }
                    let clear =
                        ws.boxes[j].is_above(&half, &body.motion, params.ca.contact_distance);
                    if !clear {
                        ws.overlapping.push((index(h.min(j)), index(h.max(j))));
                    }
                }
            }
            ws.overlapping.sort_unstable();
        }
        stats.pairs_culled = stats.pairs_all
            - stats.pairs_static
            - stats.pairs_of_half_spaces
            - ws.overlapping.len() as u64;
        ws.candidates.clear();
        for &(a, b) in &ws.overlapping {
            let (ia, ib) = (a as usize, b as usize);
            let groups = self.bodies[ia]
                .groups
                .interacts_with(self.bodies[ib].groups);
            if groups && filter(ia, ib) {
                ws.candidates.push((a, b));
            } else {
                stats.pairs_filtered += 1;
            }
        }
        stats.pairs_tested = ws.candidates.len() as u64;
        ws.report.pairs.clear();
        ws.report.earliest.clear();
        ws.report.stats = stats;
        Ok(())
    }
}

/// Every pair `(i, j)`, `i < j`, of boxes that are not apart by more than
/// `distance`, except pairs where both `skip[i]` and `skip[j]`, in increasing
/// order: a sweep and prune along the axis on which the boxes' centres
/// spread most. `order` is scratch space; both vectors are cleared first.
pub(super) fn overlapping_pairs<T: Float>(
    boxes: &[SweptBox<T>],
    skip: &[bool],
    distance: T,
    order: &mut Vec<(T, u32)>,
    out: &mut Vec<(u32, u32)>,
) {
    out.clear();
    order.clear();
    if boxes.len() < 2 {
        return;
    }
    let axis = spread_axis(boxes);
    order.extend(
        boxes
            .iter()
            .enumerate()
            .map(|(i, b)| (b.lo[axis], index(i))),
    );
    // Keys are unique (ties broken by index): the order is deterministic.
    order.sort_unstable_by(|a, b| {
        a.0.partial_cmp(&b.0)
            .unwrap_or(core::cmp::Ordering::Equal)
            .then(a.1.cmp(&b.1))
    });
    for (n, &(_, i)) in order.iter().enumerate() {
        let a = &boxes[i as usize];
        for &(lo_j, j) in &order[n + 1..] {
            // Sorted by lo: every later box is at least as far along the axis.
            if sub_down(lo_j, a.hi[axis]) > distance {
                break;
            }
            if skip[i as usize] && skip[j as usize] {
                continue;
            }
            let b = &boxes[j as usize];
            let other = [(axis + 1) % 3, (axis + 2) % 3];
            if other.iter().any(|&k| a.is_apart_along(b, k, distance))
                || a.is_apart_along(b, axis, distance)
            {
                continue;
            }
            out.push((i.min(j), i.max(j)));
        }
    }
    out.sort_unstable();
}

/// The axis along which the boxes' centres have the largest variance.
fn spread_axis<T: Float>(boxes: &[SweptBox<T>]) -> usize {
    let n = boxes.len() as f64;
    let mut best = (0, -1.0);
    for k in 0..3 {
        let centre = |b: &SweptBox<T>| {
            let c = 0.5 * b.lo[k].to_f64() + 0.5 * b.hi[k].to_f64();
            if c.is_finite() {
                c
            } else {
                0.0
            }
        };
        let mean = boxes.iter().map(centre).sum::<f64>() / n;
        let var = boxes
            .iter()
            .map(|b| (centre(b) - mean) * (centre(b) - mean))
            .sum::<f64>();
        if var > best.1 {
            best = (k, var);
        }
    }
    best.0
}

/// A body number as the sweep's `u32` (scenes of more than `u32::MAX`
/// bodies are not supported).
fn index(i: usize) -> u32 {
    u32::try_from(i).unwrap_or(u32::MAX)
}
