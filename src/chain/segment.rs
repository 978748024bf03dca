//! A query's view of the scene along one joint-space segment, and its
//! reusable buffers: the chain placed at a time of the segment, a pair's two
//! motions over a step, and its two hierarchies.

use alloc::vec::Vec;

use crate::bvh::Hierarchy;
use crate::chain::bound::{LinkErrors, LinkMotion};
use crate::chain::model::{Chain, JointFrame};
use crate::chain::obstacle::Obstacle;
use crate::chain::params::ChainParams;
use crate::chain::report::ChainPair;
use crate::{Float, Pose, Vec3};

/// Reusable per-query buffers.
#[derive(Clone, Debug, Default)]
pub(super) struct Work<T> {
    pub(super) poses: Vec<Pose<T>>,
    pub(super) frames: Vec<JointFrame<T>>,
    pub(super) rate: Vec<T>,
    pub(super) errors: LinkErrors<T>,
    pub(super) a: Option<LinkMotion<T>>,
    pub(super) b: Option<LinkMotion<T>>,
    pub(super) stack: Vec<(u32, u32)>,
}

impl<T: Float> Work<T> {
    /// Fills `m` with link `link`'s motion over a step of length `dt` from
    /// the placed poses and frames, the rates and the errors
    /// ([`LinkMotion::fill`]).
    #[inline]
    pub(super) fn fill(
        &self,
        chain: &Chain<T>,
        m: &mut LinkMotion<T>,
        link: usize,
        skip: usize,
        dt: T,
    ) {
        m.fill(
            chain,
            link,
            &self.poses,
            &self.frames,
            &self.rate,
            skip,
            dt,
            &self.errors,
        );
    }
}

/// The motion kept in `slot` (its buffers reused), or a new still one.
#[inline]
pub(super) fn take_motion<T: Float>(slot: &mut Option<LinkMotion<T>>) -> LinkMotion<T> {
    slot.take()
        .unwrap_or_else(|| LinkMotion::still(Pose::IDENTITY, T::ZERO, T::ZERO))
}

/// The scene along the joint-space segment `q(t) = q0 + t (q1 - q0)`
/// (a configuration `q` is the segment from `q` to `q`).
pub(super) struct Segment<'a, T> {
    pub(super) chain: &'a Chain<T>,
    pub(super) obstacles: &'a [Obstacle<T>],
    pub(super) params: &'a ChainParams<T>,
    pub(super) q0: &'a [T],
    pub(super) q1: &'a [T],
}

impl<'a, T: Float> Segment<'a, T> {
    /// Places the chain at time `t`: every link's pose and every joint's
    /// frame, into `work`.
    pub(super) fn place(&self, work: &mut Work<T>, t: T) {
        let (q0, q1) = (self.q0, self.q1);
        let n = self.chain.links.len();
        work.poses.resize(n, Pose::IDENTITY);
        work.frames.resize(
            self.chain.joints.len(),
            JointFrame {
                axis: Vec3::ZERO,
                point: Vec3::ZERO,
            },
        );
        self.chain.place(
            |d| q0[d] + t * (q1[d] - q0[d]),
            &mut work.poses,
            &mut work.frames,
        );
    }

    /// The two sides' motions over `[t, t + dt]` (`dt` rounded up by the caller).
    pub(super) fn fill_motions(&self, work: &mut Work<T>, pair: ChainPair, dt: T) {
        let mut a = take_motion(&mut work.a);
        let mut b = take_motion(&mut work.b);
        match pair {
            ChainPair::Obstacle { link, obstacle } => {
                work.fill(self.chain, &mut a, link, 0, dt);
                let o = &self.obstacles[obstacle];
                b = LinkMotion {
                    terms: b.terms,
                    ..LinkMotion::still(o.pose, o.delta, o.reach)
                };
                b.terms.clear();
            }
            ChainPair::SelfCollision { a: la, b: lb } => {
                let skip = self.chain.common_prefix(la, lb);
                work.fill(self.chain, &mut a, la, skip, dt);
                work.fill(self.chain, &mut b, lb, skip, dt);
            }
            // A shape's side is its own (`dispatch.rs`): the link's motion only.
            ChainPair::Shape { link, .. } => {
                work.fill(self.chain, &mut a, link, 0, dt);
                b.terms.clear();
            }
        }
        work.a = Some(a);
        work.b = Some(b);
    }

    /// The two hierarchies of a pair (every pair is made of links with
    /// geometry, so both exist), whole triangles on both sides: a long
    /// triangle (a table's, a pole's) is bounded by its box's nearest face
    /// (`PlacedNodes::face_gap`), which costs less than its pieces (plates
    /// of 12 triangles: 4.3 ms a segment against 491 ms in pieces,
    /// `examples/narrow_passage.rs`, `docs/performance.md`).
    pub(super) fn trees(&self, pair: ChainPair) -> Option<(&'a Hierarchy<T>, &'a Hierarchy<T>)> {
        let chain = self.chain;
        let tree = |l: usize| chain.links[l].tree.as_ref();
        match pair {
            ChainPair::Obstacle { link, obstacle } => {
                let (a, b) = (tree(link)?, &self.obstacles.get(obstacle)?.tree);
                Some((&a.whole, &b.whole))
            }
            ChainPair::SelfCollision { a, b } => Some((&tree(a)?.whole, &tree(b)?.whole)),
            // A shape has no hierarchy (`dispatch::shape_min_gap` takes it).
            ChainPair::Shape { .. } => None,
        }
    }
}
