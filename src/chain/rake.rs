//! The rake over time: a planner's edge split into `K` sub-intervals (a
//! power of two up to 32), the chain placed at their `K` midpoints at once
//! in `f32` lanes (`lanes.rs`), and every checked pair's link covers
//! (`cover.rs`) swept by one number per link (the static levers of
//! `lever.rs`) and tested against the obstacles' `f32` proxies
//! (`proxy.rs`) or the other link's cover, eight sub-intervals per
//! instruction stream (`proofs/13-chains.md`, Lemmas 13.9 to 13.13).
//!
//! A (pair, sub-interval) the rake clears is certified free; the others are
//! handed to the edge engine (`edge.rs`) with that sub-interval, which
//! halves it, descends the trees or measures the hulls and triangles
//! (Lemmas 13.5 to 13.8): so the cost follows the clearance, not the edge.

// Lane loops index fixed-size arrays by lane: the form the compiler turns
// into SIMD. A gap compared as `!(g > tau)` fails a NaN gap, as it must.
#![allow(clippy::needless_range_loop, clippy::neg_cmp_op_on_partial_ord)]

use alloc::vec::Vec;

use crate::chain::cover::{up32, LinkCover};
use crate::chain::edge::{Item, Target};
use crate::chain::lanes::{Lane, LaneChain, LanePose, LANES};
use crate::chain::lever::{lane_delta, link_levers, sweep_rates, MAX_SKIP, U32};
use crate::chain::model::Chain;
use crate::chain::obstacle::Obstacle;
use crate::chain::proxy::Proxy;
use crate::chain::shapes::ShapeObstacle;
use crate::Float;

/// The least edge budget the rake runs under: a smaller budget asks for a
/// bounded bail-out, which the edge engine alone gives item by item (the
/// rake's pass is a few hundred lane tests; they count against the budget).
pub(crate) const RAKE_MIN_BUDGET: usize = 4096;

/// The most sub-intervals an edge is raked into.
pub(crate) const MAX_TIMES: u32 = 32;

/// Lemma 13.12's multiplier of `u W` for the rounding of a lane's gap
/// (the largest of the proxies' derivations, with room).
const KAPPA: f64 = 64.0;

/// What a scene keeps for the rake, made once with it (Lemmas 13.9 to
/// 13.11): each link's cover and static levers, and the joints in `f32`.
#[derive(Clone, Debug, Default)]
pub(super) struct RakeModel {
    pub(super) covers: Vec<Option<LinkCover>>,
    pub(super) levers: Vec<Vec<f64>>,
    pub(super) lanes: LaneChain,
    /// The sweep a link may have over a sub-interval's half width (half
    /// the covers' mean ball radius): what picks `K`.
    pub(super) sweep: f64,
}

/// The sweep a link may have over a sub-interval's half width, as a
/// fraction of the covers' mean ball radius: what picks `K`.
pub(crate) const SWEEP_FRACTION: f64 = 1.0;

/// The balls of a link's cover.
pub(crate) const COVER_BALLS: usize = 24;

impl RakeModel {
    /// The rake's data for `chain`.
    pub(super) fn new<T: Float>(chain: &Chain<T>) -> Self {
        let mut covers = Vec::with_capacity(chain.links.len());
        let mut levers = Vec::with_capacity(chain.links.len());
        for l in 0..chain.links.len() {
            match chain.links[l].mesh.as_ref() {
                Some(mesh) => {
                    covers.push(LinkCover::fit(
                        mesh.vertices(),
                        mesh.triangles(),
                        COVER_BALLS,
                    ));
                    levers.push(link_levers(chain, l, mesh.vertices()));
                }
                None => {
                    covers.push(None);
                    levers.push(Vec::new());
                }
            }
        }
        let (sum, count) = covers
            .iter()
            .flatten()
            .flat_map(|c| c.r.iter().copied())
            .fold((0.0f64, 0usize), |(s, n), r| (s + f64::from(r), n + 1));
        let sweep = if count > 0 {
            SWEEP_FRACTION * sum / count as f64
        } else {
            0.0
        };
        Self {
            covers,
            levers,
            lanes: LaneChain::new(chain),
            sweep,
        }
    }
}

/// The scene as the rake sees it.
pub(super) struct Rake<'a, T: 'static> {
    pub(super) chain: &'a Chain<T>,
    pub(super) model: &'a RakeModel,
    pub(super) shapes: &'a [ShapeObstacle<T>],
    pub(super) obstacles: &'a [Obstacle<T>],
    pub(super) padding: f64,
    /// The sweep a link may have over a sub-interval's half width: what
    /// picks `K`.
    pub(super) sweep: f64,
    /// What the sweeps are multiplied by in the thresholds: 1, but for the
    /// tests that show the sweep is needed (less than 1 must fail them).
    pub(super) sweep_scale: f64,
}

/// A time the chain is placed at: the middle of sub-interval `index` of
/// `K` equal ones, with each coordinate's cosine, sine and value there
/// (`f64`, at `coords[at..at + dofs]`).
#[derive(Clone, Copy, Debug)]
struct Time {
    at: usize,
}

/// The rake's reusable buffers and its findings.
#[derive(Clone, Debug, Default)]
pub(super) struct RakeWork {
    /// Per time and coordinate: cosine, sine, value (`f64`).
    coords: Vec<[f64; 3]>,
    times: Vec<Time>,
    turn: Vec<(Lane, Lane)>,
    slide: Vec<Lane>,
    poses: Vec<LanePose>,
    /// Per link and number of skipped joints, the speed bound of its
    /// points (`link * (MAX_SKIP + 1) + skip`), and per motion slot.
    rate: Vec<f64>,
    /// Per link, the lanes' placement error and placed reach.
    delta: Vec<f64>,
    reach: Vec<f64>,
    /// Per item, the threshold and the sweep part of it.
    tau: Vec<f32>,
    sweep: Vec<f32>,
    /// Per link, where its balls start in `placed`, their placements in
    /// the current chunk (valid where the link's stamp is the chunk's), and
    /// its enclosing ball's.
    offset: Vec<usize>,
    placed: Vec<[Lane; 3]>,
    stamp: Vec<u32>,
    enclosing: Vec<[Lane; 3]>,
    /// Per link, a ball holding its enclosing balls of every lane of the
    /// chunk: centre and radius (Lemma 13.13, the chunk's first test).
    chunk_ball: Vec<([f32; 3], f64)>,
    chunk: u32,
    /// Per (lane, item) not cleared: the worst margin seen (`gap - tau`).
    margins: Vec<(u32, u32, f32)>,
    /// What the rake hands on: `(order, start, item)`, the sub-interval
    /// `[start / times_count, (start + 1) / times_count]`; `order` puts the
    /// sub-intervals whose covers overlapped most first (likely contacts:
    /// a yes-or-no query ends there), or is zero (time order) for a
    /// first-contact query; sorted.
    pub(super) fails: Vec<(u32, u32, u32)>,
    /// The sub-intervals' count (a power of two).
    pub(super) times_count: u32,
    /// Lane tests made (eight times of one ball against one proxy or ball
    /// count one).
    pub(super) tests: usize,
}

/// The lanes (bits) whose `g` is not above `tau` (NaN is not above).
#[inline]
fn not_above(g: &Lane, tau: f32) -> u8 {
    let mut m = 0u8;
    for (l, &x) in g.iter().enumerate() {
        m |= u8::from(!(x > tau)) << l;
    }
    m
}

/// Sine and cosine in `f64`, with or without `std` (the crate's `Float`).
#[inline]
fn sin_cos(x: f64) -> (f64, f64) {
    (Float::sin(x), Float::cos(x))
}

/// An order-preserving key of a float (smaller first; NaN last).
fn order_key(x: f32) -> u32 {
    if x.is_nan() {
        return u32::MAX;
    }
    let b = x.to_bits();
    if b >> 31 == 1 {
        !b
    } else {
        b | 0x8000_0000
    }
}

impl<T: Float> Rake<'_, T> {
    /// Rakes the edge `q0 -> q1` for the items `initial` (each a checked
    /// pair at its roots) with the motion slots `slots`: `w.fails` the
    /// (sub-interval, item) pairs not cleared, of `w.times_count` equal
    /// sub-intervals, the likeliest contacts first when `any`. `false` when
    /// the rake does not apply (a chain too deep for Lemma 13.3 in `f32`):
    /// then nothing is cleared.
    pub(super) fn run(
        &self,
        q0: &[T],
        q1: &[T],
        initial: &[Item],
        slots: &[(usize, usize)],
        any: bool,
        w: &mut RakeWork,
    ) -> bool {
        let chain = self.chain;
        w.fails.clear();
        w.margins.clear();
        w.tests = 0;
        // Speeds per link and skip, then per slot; errors per link.
        let n = chain.links.len();
        let stride = MAX_SKIP + 1;
        w.rate.clear();
        w.rate.resize(n * stride, 0.0);
        let mut fastest = 0.0f64;
        for l in 0..n {
            if self.model.covers[l].is_some() {
                sweep_rates(
                    chain,
                    l,
                    &self.model.levers[l],
                    q0,
                    q1,
                    &mut w.rate[l * stride..(l + 1) * stride],
                );
                fastest = fastest.max(w.rate[l * stride]);
            }
        }
        w.delta.clear();
        w.reach.clear();
        for l in 0..n {
            let local = self.model.covers[l].as_ref().map_or(0.0, |c| c.reach);
            let (d, r) = lane_delta(chain, q0, q1, l, local);
            if !(d.is_finite() && r.is_finite()) {
                return false;
            }
            w.delta.push(d);
            w.reach.push(r);
        }
        if !fastest.is_finite() || slots.iter().any(|&(_, skip)| skip > MAX_SKIP) {
            return false;
        }
        // K: the least power of two whose half width sweeps at most `sweep`.
        let mut k = 1u32;
        while k < MAX_TIMES && fastest / f64::from(2 * k) > self.sweep {
            k *= 2;
        }
        // The nodes' places, per link.
        w.offset.clear();
        let mut total = 0;
        for c in &self.model.covers {
            w.offset.push(total);
            total += c.as_ref().map_or(0, LinkCover::len);
        }
        if w.placed.len() < total {
            w.placed.resize(total, [[0.0; LANES]; 3]);
        }
        if w.enclosing.len() < n {
            w.enclosing.resize(n, [[0.0; LANES]; 3]);
            w.stamp.resize(n, 0);
        }
        w.chunk_ball.resize(n, ([0.0; 3], 0.0));
        self.first_times(q0, q1, k, w);
        self.thresholds(initial, slots, k, w);
        let chunks = k.div_ceil(LANES as u32);
        for chunk in 0..chunks {
            let first = (chunk as usize) * LANES;
            let live = (k as usize - first).min(LANES);
            let valid: u8 = if live == LANES {
                u8::MAX
            } else {
                (1u8 << live) - 1
            };
            self.place_chunk(first, live, w);
            self.chunk_balls(w);
            for i in 0..initial.len() {
                if self.far(&initial[i], w.tau[i], w) {
                    continue;
                }
                let (mask, worst) = self.test(&initial[i], i, valid, w);
                let mut m = mask;
                while m != 0 {
                    let l = m.trailing_zeros() as usize;
                    m &= m - 1;
                    w.margins.push(((first + l) as u32, i as u32, worst[l]));
                }
            }
        }
        w.times_count = k;
        // The sub-intervals ordered by the worst margin of their pairs
        // (for `any`), or by time.
        w.margins.sort_unstable_by_key(|&(t, i, _)| (t, i));
        let mut at = 0;
        while at < w.margins.len() {
            let t = w.margins[at].0;
            let mut end = at;
            let mut worst = f32::INFINITY;
            while end < w.margins.len() && w.margins[end].0 == t {
                worst = worst.min(w.margins[end].2);
                end += 1;
            }
            let key = if any { order_key(worst) } else { 0 };
            // Within a sub-interval, the pairs that overlapped most first.
            let first = w.fails.len();
            for p in at..end {
                w.fails.push((key, t, w.margins[p].1));
            }
            if any {
                let margins = &w.margins[at..end];
                w.fails[first..].sort_unstable_by_key(|f| {
                    let m = margins
                        .iter()
                        .find(|m| m.1 == f.2)
                        .map_or(f32::NAN, |m| m.2);
                    order_key(m)
                });
            }
            at = end;
        }
        // Sub-intervals by their key and time; the pairs of one keep their
        // order.
        w.fails.sort_by_key(|f| (f.0, f.1));
        true
    }

    /// Each item's threshold at `k` sub-intervals (Lemma 13.13): its lanes
    /// are clear where the computed gap exceeds both sides' placement
    /// errors and sweeps, the padding and the lanes' rounding.
    fn thresholds(&self, initial: &[Item], slots: &[(usize, usize)], k: u32, w: &mut RakeWork) {
        let half = 1.0 / f64::from(2 * k);
        let stride = MAX_SKIP + 1;
        w.tau.clear();
        w.sweep.clear();
        let rate = |slot: u16| {
            let (l, skip) = slots[slot as usize];
            w.rate[l * stride + skip]
        };
        for it in initial {
            let a = it.link as usize;
            let (da, ra) = (w.delta[a], w.reach[a]);
            let sa = rate(it.slot) * half;
            let proxy = |p: Option<&Proxy>| {
                p.map(|p| (p.lambda, p.size, p.tilt * (2.0 * ra + p.offset), 0.0, 0.0))
            };
            let side = match it.target {
                Target::Shape(s) | Target::Cloud(s, _) => {
                    proxy(self.shapes[s as usize].proxy.as_ref())
                }
                Target::Mesh(o, _) => proxy(self.obstacles[o as usize].proxy.as_ref()),
                Target::Link(b, _) => {
                    let b = b as usize;
                    let sb = rate(it.slot_b) * half;
                    Some((1.0, w.reach[b], 0.0, w.delta[b], sb))
                }
            };
            let (tau, sweep) = match side {
                Some((lambda, size, sigma, db, sb)) => {
                    let big = ra + size;
                    let t = (da + db + (sa + sb) * self.sweep_scale + self.padding + sigma)
                        * (1.0 + 1.0 / 1_099_511_627_776.0)
                        + (KAPPA + 2.0) * U32 * big
                        + 3.0 * (lambda - 1.0) * big;
                    let tau = if t.is_finite() {
                        up32(t)
                    } else {
                        f32::INFINITY
                    };
                    (tau, (sa + sb) as f32)
                }
                None => (f32::INFINITY, 0.0),
            };
            w.tau.push(tau);
            w.sweep.push(sweep);
        }
    }

    /// The `k` midpoints `(2 i + 1) / (2 k)` and each coordinate there:
    /// `f64` sine and cosine at the first, then the angle-addition
    /// recurrence in `f64` (a few ulps of `f64` per step, far inside Lemma
    /// 13.10's budget).
    fn first_times(&self, q0: &[T], q1: &[T], k: u32, w: &mut RakeWork) {
        let dofs = q0.len();
        let kk = k as usize;
        w.times.clear();
        w.coords.clear();
        w.coords.resize(dofs * kk, [0.0; 3]);
        for i in 0..kk {
            w.times.push(Time { at: i * dofs });
        }
        let step = 1.0 / f64::from(k);
        for d in 0..dofs {
            let (a, b) = (q0[d].to_f64(), q1[d].to_f64());
            let dq = b - a;
            let (mut s, mut c) = sin_cos(a + 0.5 * step * dq);
            let (sd, cd) = if kk > 1 {
                sin_cos(step * dq)
            } else {
                (0.0, 1.0)
            };
            for i in 0..kk {
                let m = (i as f64 + 0.5) * step;
                w.coords[i * dofs + d] = [c, s, a + m * dq];
                let (c2, s2) = (c * cd - s * sd, s * cd + c * sd);
                c = c2;
                s = s2;
            }
        }
    }

    /// The chain placed at the times `first .. first + live` (the last one
    /// repeated in the other lanes).
    fn place_chunk(&self, first: usize, live: usize, w: &mut RakeWork) {
        let dofs = self.chain.dofs;
        w.turn.clear();
        w.slide.clear();
        for d in 0..dofs {
            let mut c = [0.0f32; LANES];
            let mut s = [0.0f32; LANES];
            let mut v = [0.0f32; LANES];
            for l in 0..LANES {
                let t = w.times[first + l.min(live - 1)];
                let [cc, ss, vv] = w.coords[t.at + d];
                c[l] = cc as f32;
                s[l] = ss as f32;
                v[l] = vv as f32;
            }
            w.turn.push((c, s));
            w.slide.push(v);
        }
        self.model
            .lanes
            .place(&self.chain.base, &w.turn, &w.slide, &mut w.poses);
        w.chunk = w.chunk.wrapping_add(1).max(1);
    }

    /// Each link's ball holding its enclosing balls in every lane of the
    /// chunk: the middle of their centres' box, and the largest distance
    /// from it (computed in `f32`, then widened by `2^-20` of it and more
    /// than the roundings) plus the enclosing radius.
    fn chunk_balls(&self, w: &mut RakeWork) {
        for l in 0..self.chain.links.len() {
            let Some(c) = self.model.covers[l].as_ref() else {
                continue;
            };
            w.enclosing[l] = w.poses[l].place(c.centre);
            let (x, r) = (w.enclosing[l], c.radius);
            let mut mid = [0.0f32; 3];
            for k in 0..3 {
                let (mut lo, mut hi) = (f32::INFINITY, f32::NEG_INFINITY);
                for v in x[k] {
                    lo = lo.min(v);
                    hi = hi.max(v);
                }
                mid[k] = 0.5 * lo + 0.5 * hi;
            }
            let mut far = 0.0f64;
            for lane in 0..LANES {
                let d = [0, 1, 2].map(|k| f64::from(x[k][lane]) - f64::from(mid[k]));
                far = far.max((d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt());
            }
            w.chunk_ball[l] = (mid, (far + f64::from(r)) * (1.0 + 1.0 / 1_048_576.0));
        }
    }

    /// Whether item `it`'s link is clear in every lane of the chunk by its
    /// chunk ball alone (Lemma 13.13): for a proxy `phi(c) - lambda R > tau`
    /// (as `phi` is `lambda`-Lipschitz, each lane's enclosing ball then
    /// clears); for a pair of links the two chunk balls' gap.
    fn far(&self, it: &Item, tau: f32, w: &RakeWork) -> bool {
        let a = it.link as usize;
        // A link without a cover has no chunk ball.
        let covered = |l: usize| self.model.covers[l].is_some();
        if !covered(a) || matches!(it.target, Target::Link(b, _) if !covered(b as usize)) {
            return false;
        }
        let (ca, ra) = w.chunk_ball[a];
        let proxy = match it.target {
            Target::Shape(s) | Target::Cloud(s, _) => self.shapes[s as usize].proxy.as_ref(),
            Target::Mesh(o, _) => self.obstacles[o as usize].proxy.as_ref(),
            Target::Link(b, _) => {
                let (cb, rb) = w.chunk_ball[b as usize];
                let d = [0, 1, 2].map(|k| f64::from(ca[k]) - f64::from(cb[k]));
                let dist = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
                return dist * (1.0 - 4.0 * f64::EPSILON) - ra - rb > f64::from(tau);
            }
        };
        let Some(p) = proxy else { return false };
        let phi = f64::from(p.phi1(ca));
        phi - p.lambda * ra * (1.0 + 4.0 * f64::EPSILON) > f64::from(tau)
    }

    /// Link `l`'s balls placed in this chunk's lanes (once per chunk).
    #[inline]
    fn place_balls(&self, c: &LinkCover, l: usize, w: &mut RakeWork) {
        if w.stamp[l] == w.chunk {
            return;
        }
        let at = w.offset[l];
        let pose = &w.poses[l];
        for k in 0..c.len() {
            w.placed[at + k] = pose.place([c.cx[k], c.cy[k], c.cz[k]]);
        }
        w.stamp[l] = w.chunk;
    }

    /// The lanes of `lanes` in which item `i` (`it`) is not cleared at its
    /// threshold: the link's enclosing ball, then its cover's balls; and per
    /// lane the worst margin (`gap - tau`) of a ball not cleared.
    fn test(&self, it: &Item, i: usize, lanes: u8, w: &mut RakeWork) -> (u8, Lane) {
        let mut worst = [f32::INFINITY; LANES];
        let tau = w.tau[i];
        let a = it.link as usize;
        let (Some(ca), false) = (self.model.covers[a].as_ref(), tau == f32::INFINITY) else {
            return (lanes, [f32::NEG_INFINITY; LANES]);
        };
        let proxy = match it.target {
            Target::Shape(s) | Target::Cloud(s, _) => self.shapes[s as usize].proxy.as_ref(),
            Target::Mesh(o, _) => self.obstacles[o as usize].proxy.as_ref(),
            Target::Link(b, _) => return self.test_link(a, b as usize, tau, lanes, w),
        };
        let Some(p) = proxy else {
            return (lanes, [f32::NEG_INFINITY; LANES]);
        };
        w.tests += 1;
        let mut g = p.phi(&w.enclosing[a]);
        for v in &mut g {
            *v -= ca.radius;
        }
        let outer = not_above(&g, tau) & lanes;
        if outer == 0 {
            return (0, worst);
        }
        self.place_balls(ca, a, w);
        let at = w.offset[a];
        let mut fail = 0u8;
        for k in 0..ca.len() {
            w.tests += 1;
            let mut g = p.phi(&w.placed[at + k]);
            let r = ca.r[k];
            let mut bad = 0u8;
            for l in 0..LANES {
                g[l] -= r;
                bad |= u8::from(!(g[l] > tau)) << l;
                worst[l] = worst[l].min(g[l] - tau);
            }
            fail |= bad & outer;
        }
        (fail, worst)
    }

    /// A pair of links: their enclosing balls, then each ball of `a`'s
    /// cover against `b`'s enclosing ball, then against each of `b`'s balls.
    fn test_link(&self, a: usize, b: usize, tau: f32, lanes: u8, w: &mut RakeWork) -> (u8, Lane) {
        let mut worst = [f32::INFINITY; LANES];
        let (Some(ca), Some(cb)) = (self.model.covers[a].as_ref(), self.model.covers[b].as_ref())
        else {
            return (lanes, [f32::NEG_INFINITY; LANES]);
        };
        w.tests += 1;
        let outer = not_above(
            &ball_gap(&w.enclosing[a], ca.radius, &w.enclosing[b], cb.radius),
            tau,
        ) & lanes;
        if outer == 0 {
            return (0, worst);
        }
        self.place_balls(ca, a, w);
        self.place_balls(cb, b, w);
        let (oa, ob) = (w.offset[a], w.offset[b]);
        let eb = &w.enclosing[b];
        let mut fail = 0u8;
        let mut tests = 0;
        for i in 0..ca.len() {
            let xi = &w.placed[oa + i];
            let ri = ca.r[i];
            tests += 1;
            let near = not_above(&ball_gap(xi, ri, eb, cb.radius), tau) & outer;
            if near == 0 {
                continue;
            }
            for j in 0..cb.len() {
                tests += 1;
                let g = ball_gap(xi, ri, &w.placed[ob + j], cb.r[j]);
                let mut bad = 0u8;
                for l in 0..LANES {
                    bad |= u8::from(!(g[l] > tau)) << l;
                    worst[l] = worst[l].min(g[l] - tau);
                }
                fail |= bad & near;
            }
        }
        w.tests += tests;
        (fail, worst)
    }
}

/// `(|x - y| - ry) - rx` per lane (Lemma 13.12's ball proxy of the other
/// side, then the ball's own radius).
#[inline]
fn ball_gap(x: &[Lane; 3], rx: f32, y: &[Lane; 3], ry: f32) -> Lane {
    let mut out = [0.0f32; LANES];
    for l in 0..LANES {
        let d = [x[0][l] - y[0][l], x[1][l] - y[1][l], x[2][l] - y[2][l]];
        out[l] = ((d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt() - ry) - rx;
    }
    out
}

#[cfg(test)]
mod tests;
