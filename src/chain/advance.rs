//! Conservative advancement of one pair along a segment: the loop of steps
//! from the start to a contact, to the end or to where no step is certified,
//! and each step in two phases (a distance, then directed node-pair steps).

use alloc::vec::Vec;

use crate::bvh::Hierarchy;
use crate::chain::bound::LinkMotion;
use crate::chain::gap::{min_gap, placed_corners, slab_gap, PlacedNodes};
use crate::chain::report::{ChainContact, ChainPair, ChainStats};
use crate::chain::segment::{Segment, Work};
use crate::rounding::{advance_down, gamma, step_down, sum_reaches};
use crate::{Float, Point3, Vec3};

/// The relative slack of both phases' branch and bound: a node pair whose
/// gap (or step) is within this fraction of the best found is not refined,
/// its own certified gap (step) kept instead. Steps come out at most this
/// fraction shorter than the best the balls certify; far fewer nodes are
/// visited when the links are far apart (all node pairs then look alike).
const SLACK: f64 = 0.25;

/// How a pair's advance along a segment ended.
pub(super) enum PairEnd<T> {
    /// Its first contact (before the time it was advanced to).
    Contact(ChainContact<T>),
    /// Undecided from this time on: the iteration limit, or no step the
    /// rounding can resolve.
    Undecided(T),
    /// Free up to the time it was advanced to.
    Free,
}

/// Advances `pair` from `t = 0` to `until` (no later than the earliest
/// contact found so far) through the broad phase's pieces in `mask`, and
/// counts its work in `stats`.
pub(super) fn advance_pair<T: Float>(
    segment: &Segment<'_, T>,
    pair: ChainPair,
    mask: u64,
    until: T,
    work: &mut Work<T>,
    stats: &mut ChainStats,
) -> PairEnd<T> {
    let Some((ta, tb)) = segment.trees(pair) else {
        return PairEnd::Free;
    };
    stats.advanced += 1;
    let params = segment.params;
    let k = params.broad_pieces;
    let piece_start = |i: usize| T::from_u32(i as u32) / T::from_u32(k as u32);
    let cd = params.contact_distance;
    let mut t = T::ZERO;
    let mut iterations = 0;
    // The bounds hold over `[t, t + h]`: a short horizon keeps them
    // tight (the axes turn and the levers grow with `h`, Lemma 13.2);
    // it doubles while steps reach it and follows them when they do not.
    let mut horizon = T::ONE / T::from_u32(8);
    loop {
        // Skip the broad phase's pieces in which the pair's swept
        // volumes are apart (certified free there).
        let mut piece = (t.to_f64() * k as f64) as usize;
        while piece + 1 < k && t >= piece_start(piece + 1) {
            piece += 1;
        }
        while piece > 0 && t < piece_start(piece) {
            piece -= 1;
        }
        if mask >> piece & 1 == 0 {
            match (piece + 1..k).find(|&i| mask >> i & 1 == 1) {
                Some(next) => t = piece_start(next),
                None => return PairEnd::Free,
            }
        }
        if t >= until {
            return PairEnd::Free;
        }
        if iterations >= params.max_iterations {
            return PairEnd::Undecided(t);
        }
        iterations += 1;
        stats.iterations += 1;
        segment.place(work, t);
        let h = horizon.min_nan(until - t);
        segment.fill_motions(work, pair, h * (T::ONE + gamma::<T>(2)));
        let (Some(a), Some(b)) = (&work.a, &work.b) else {
            return PairEnd::Free;
        };
        let step = advance(ta, tb, a, b, cd, h, &mut work.stack, stats);
        match step {
            Step::Touching {
                distance,
                on_a,
                on_b,
            } => {
                return PairEnd::Contact(ChainContact {
                    time: t,
                    pair,
                    distance,
                    on_a: Point3::from_vec3(on_a),
                    on_b: Point3::from_vec3(on_b),
                });
            }
            Step::Advance(s) => {
                if s == T::INFINITY {
                    // Still: free for the rest of the interval.
                    return PairEnd::Free;
                }
                // The bounds hold over `h` only.
                let s = s.min_nan(h);
                if sum_reaches(t, s, until) {
                    return PairEnd::Free;
                }
                let next = advance_down(t, s);
                if s.is_nan() || s <= T::ZERO || next <= t {
                    // No step the rounding can resolve: undecided here.
                    return PairEnd::Undecided(t);
                }
                horizon = if s >= h {
                    horizon * T::TWO
                } else {
                    (s * T::TWO).max_nan(T::ONE / T::from_u32(1 << 20))
                };
                t = next;
            }
        }
    }
}

/// One step's answer for a pair.
enum Step<T> {
    Touching {
        distance: T,
        on_a: Vec3<T>,
        on_b: Vec3<T>,
    },
    Advance(T),
}

/// Conservative advancement's step for one pair over `[t, t + rest]`
/// (Lemma 13.4), in two phases:
///
/// 1. the distance: branch and bound for the smallest certified triangle gap
///    `d` (pruned at what the whole links could close over `rest`); touching
///    when a triangle pair is within `cd`. The step `d / (v_A + v_B)` with the
///    links' undirected speeds (their root balls') is certified for any
///    shapes.
/// 2. when that falls short of `rest`, the directed step: both trees
///    descended, a node pair pruned when its own certified directed step is
///    at least the best found, triangle pairs stepped along their witness
///    direction; given up (keeping phase 1's step) past a work budget. The
///    larger of two certified steps is certified.
#[allow(clippy::too_many_arguments)]
fn advance<T: Float>(
    ta: &Hierarchy<T>,
    tb: &Hierarchy<T>,
    a: &LinkMotion<T>,
    b: &LinkMotion<T>,
    cd: T,
    rest: T,
    stack: &mut Vec<(u32, u32)>,
    stats: &mut ChainStats,
) -> Step<T> {
    let (ra0, rb0) = (&ta.nodes[0].ball, &tb.nodes[0].ball);
    let ca0 = a.pose.transform_point(*ra0.centre());
    let cb0 = b.pose.transform_point(*rb0.centre());
    let x = Vec3::new(T::ONE, T::ZERO, T::ZERO);
    let (_, va) = a.ball_speed(ca0, ra0.radius(), x);
    let (_, vb) = b.ball_speed(cb0, rb0.radius(), x);
    if va + vb <= T::ZERO {
        // Nothing of either moves: one distance decides the whole interval.
        let near = min_gap(ta, tb, a, b, cd + cd, T::ZERO, cd, stack, stats);
        return match near.closest {
            Some((distance, on_a, on_b)) if distance.is_nan() || distance <= cd => Step::Touching {
                distance,
                on_a,
                on_b,
            },
            _ => Step::Advance(T::INFINITY),
        };
    }
    // Gaps beyond what both links can close over `rest` need no refining.
    let cap = ((va + vb) * rest * (T::ONE + gamma::<T>(4))).max_nan(cd) + cd;
    let before = stats.node_pairs;
    let near = min_gap(ta, tb, a, b, cap, T::from_f64(SLACK), cd, stack, stats);
    if let Some((distance, on_a, on_b)) = near.closest {
        if distance.is_nan() || distance <= cd {
            return Step::Touching {
                distance,
                on_a,
                on_b,
            };
        }
    }
    let floor = step_down(near.gap, T::ZERO, va, vb);
    if floor >= rest {
        return Step::Advance(rest);
    }
    let budget = stats.node_pairs - before + 256;
    let mut visited = 0usize;
    let mut best = rest;
    let mut kept = T::INFINITY;
    let keep = T::ONE - T::from_f64(SLACK);
    stack.clear();
    stack.push((0, 0));
    while let Some((ia, ib)) = stack.pop() {
        visited += 1;
        if visited > budget {
            stats.node_pairs += visited;
            return Step::Advance(floor);
        }
        let nodes = PlacedNodes::new(ta, tb, a, b, ia, ib);
        let g = nodes.ball_gap(a, b);
        let mut s = if g > T::ZERO {
            nodes.step(g, a, b, x)
        } else {
            T::ZERO
        };
        if s < best {
            // The boxes' gap along the larger's nearest face, stepped at
            // the balls' speeds along that direction.
            if let (g, Some(n)) = nodes.face_gap(a, b) {
                let (mu_a, _) = a.ball_speed(nodes.ca, nodes.ra, n);
                let (mu_b, _) = b.ball_speed(nodes.cb, nodes.rb, n);
                s = s.max_nan(step_down(g, T::ZERO, mu_a, mu_b));
            }
        }
        if s > T::ZERO {
            if s >= best {
                continue;
            }
            if s >= best * keep {
                kept = kept.min_nan(s);
                continue;
            }
        }
        match (nodes.na.leaf(), nodes.nb.leaf()) {
            (Some(la), Some(lb)) => {
                stats.leaf_pairs += 1;
                let pa = placed_corners(ta, la, a);
                let pb = placed_corners(tb, lb, b);
                // The slab gap along the leaf balls' centre line (cheap; the
                // exact distance's direction would give a longer step).
                let inflate = ta.leaves[la].inflate + tb.leaves[lb].inflate;
                let g = slab_gap(&pa, &pb, nodes.cb - nodes.ca, a, b, inflate);
                let s = nodes.step(g, a, b, x);
                if s < best {
                    best = s;
                    if best.min_nan(kept) <= floor {
                        // Phase 1's step is as good: stop here.
                        stats.node_pairs += visited;
                        return Step::Advance(floor);
                    }
                }
            }
            _ => nodes.descend(stack, ta, tb, a, b, ia, ib),
        }
    }
    stats.node_pairs += visited;
    Step::Advance(best.min_nan(kept).max_nan(floor))
}
