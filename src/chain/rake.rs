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

use alloc::vec::Vec;

use crate::chain::cover::{up32, LinkCover};
use crate::chain::edge::{Item, Target};
use crate::chain::lanes::{Lane, LaneChain, LanePose, LANES};
use crate::chain::lever::{lane_delta, link_levers, sweep_rate, U32};
use crate::chain::model::Chain;
use crate::chain::obstacle::Obstacle;
use crate::chain::proxy::Proxy;
use crate::chain::shapes::ShapeObstacle;
use crate::Float;

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

/// The balls of a link's cover.
pub(crate) const COVER_BALLS: usize = 16;

impl RakeModel {
    /// The rake's data for `chain`.
    pub(super) fn new<T: Float>(chain: &Chain<T>) -> Self {
        let mut covers = Vec::with_capacity(chain.links.len());
        let mut levers = Vec::with_capacity(chain.links.len());
        for l in 0..chain.links.len() {
            match chain.links[l].mesh.as_ref() {
                Some(mesh) => {
                    covers.push(LinkCover::fit(mesh.vertices(), mesh.triangles(), COVER_BALLS));
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
            .flat_map(|c| c.r.iter())
            .fold((0.0f64, 0usize), |(s, n), &r| (s + f64::from(r), n + 1));
        let sweep = if count > 0 { 0.5 * sum / count as f64 } else { 0.0 };
        if std::env::var_os("RAKE_DEBUG").is_some() {
            for (l, c) in covers.iter().enumerate() {
                if let Some(c) = c {
                    let max = c.r.iter().fold(0.0f32, |a, &b| a.max(b));
                    let mean = c.r.iter().sum::<f32>() / c.r.len() as f32;
                    std::eprintln!("link {l} {}: {} balls, radius max {max:.4} mean {mean:.4}, enclosing {:.4}, levers {:?}", chain.links[l].name, c.len(), c.radius, levers[l]);
                }
            }
            std::eprintln!("sweep target {sweep:.4}");
        }
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
}

/// The rake's reusable buffers and its findings.
#[derive(Clone, Debug, Default)]
pub(super) struct RakeWork {
    /// Per coordinate, the cosine and sine (turning) or the value (sliding)
    /// at every midpoint.
    cos: Vec<f32>,
    sin: Vec<f32>,
    value: Vec<f32>,
    turn: Vec<(Lane, Lane)>,
    slide: Vec<Lane>,
    poses: Vec<LanePose>,
    /// Per motion slot, the speed bound of its link's points.
    rate: Vec<f64>,
    /// Per link, the lanes' placement error and placed reach.
    delta: Vec<f64>,
    reach: Vec<f64>,
    /// Per item, the threshold its lanes' gaps must exceed.
    tau: Vec<f32>,
    /// Per link, where its placed balls start in `placed` (in this chunk),
    /// and whether they (and its enclosing ball) are placed yet.
    offset: Vec<usize>,
    placed: Vec<[Lane; 3]>,
    enclosing: Vec<[Lane; 3]>,
    balls_done: Vec<bool>,
    enc_done: Vec<bool>,
    /// The (sub-interval, item) pairs not cleared, by sub-interval.
    pub(super) fails: Vec<(u32, u32)>,
    /// The number of sub-intervals.
    pub(super) times: u32,
    /// Lane tests made (eight sub-intervals of one ball against one proxy
    /// or ball count one).
    pub(super) tests: usize,
}

/// The lanes (bits) whose `g` is not above `tau` (NaN is not above).
#[inline]
fn not_above(g: &Lane, tau: f32) -> u8 {
    let mut m = 0u8;
    for (l, &x) in g.iter().enumerate() {
        if !(x > tau) {
            m |= 1 << l;
        }
    }
    m
}

impl<T: Float> Rake<'_, T> {
    /// Rakes the edge `q0 -> q1` for the items `initial` (each a checked
    /// pair at its roots) with the motion slots `slots`: `w.fails` the
    /// (sub-interval, item) pairs not cleared, `w.times` the number of
    /// sub-intervals. `false` when the rake does not apply (a chain too deep
    /// for Lemma 13.3 in `f32`): then nothing is cleared.
    pub(super) fn run(
        &self,
        q0: &[T],
        q1: &[T],
        initial: &[Item],
        slots: &[(usize, usize)],
        w: &mut RakeWork,
    ) -> bool {
        let chain = self.chain;
        w.fails.clear();
        w.tests = 0;
        // Speeds per slot, errors per link.
        w.rate.clear();
        let mut fastest = 0.0f64;
        for &(link, skip) in slots {
            let levers = &self.model.levers[link];
            let v = sweep_rate(chain, link, levers, q0, q1, skip);
            if skip == 0 {
                fastest = fastest.max(v);
            }
            w.rate.push(v);
        }
        let n = chain.links.len();
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
        if !fastest.is_finite() {
            return false;
        }
        // K: the least power of two whose half width sweeps at most `sweep`.
        let mut k = 1u32;
        while k < MAX_TIMES && fastest / f64::from(2 * k) > self.sweep {
            k *= 2;
        }
        w.times = k;
        let half = 1.0 / f64::from(2 * k);
        self.thresholds(initial, half, w);
        self.angles(q0, q1, k, w);
        // The balls' places, per link.
        w.offset.clear();
        let mut total = 0;
        for c in &self.model.covers {
            w.offset.push(total);
            total += c.as_ref().map_or(0, LinkCover::len);
        }
        w.placed.resize(total, [[0.0; LANES]; 3]);
        w.enclosing.resize(n, [[0.0; LANES]; 3]);
        let chunks = k.div_ceil(LANES as u32);
        for chunk in 0..chunks {
            let first = chunk * LANES as u32;
            let live = (k - first).min(LANES as u32);
            let valid: u8 = if live as usize == LANES {
                u8::MAX
            } else {
                (1u8 << live) - 1
            };
            self.place_chunk(first, k, w);
            w.balls_done.clear();
            w.balls_done.resize(n, false);
            w.enc_done.clear();
            w.enc_done.resize(n, false);
            for (i, it) in initial.iter().enumerate() {
                let tau = w.tau[i];
                let mask = self.test(it, tau, w) & valid;
                let mut m = mask;
                while m != 0 {
                    let l = m.trailing_zeros();
                    m &= m - 1;
                    w.fails.push((first + l, i as u32));
                }
            }
        }
        w.fails.sort_unstable();
        true
    }

    /// Each item's threshold (Lemma 13.13): its lanes are clear where the
    /// computed gap exceeds both sides' placement errors and sweeps, the
    /// padding and the lanes' rounding.
    fn thresholds(&self, initial: &[Item], half: f64, w: &mut RakeWork) {
        w.tau.clear();
        for it in initial {
            let a = it.link as usize;
            let (da, ra) = (w.delta[a], w.reach[a]);
            let sa = w.rate[it.slot as usize] * half;
            let proxy = |p: Option<&Proxy>| p.map(|p| (p.lambda, p.size, p.tilt * (2.0 * ra + p.offset)));
            let side = match it.target {
                Target::Shape(s) | Target::Cloud(s, _) => {
                    proxy(self.shapes[s as usize].proxy.as_ref()).map(|(l, size, sigma)| (l, size, sigma, 0.0, 0.0))
                }
                Target::Mesh(o, _) => {
                    proxy(self.obstacles[o as usize].proxy.as_ref()).map(|(l, size, sigma)| (l, size, sigma, 0.0, 0.0))
                }
                Target::Link(b, _) => {
                    let b = b as usize;
                    let sb = w.rate[it.slot_b as usize] * half;
                    Some((1.0, w.reach[b], 0.0, w.delta[b], sb))
                }
            };
            let tau = match side {
                Some((lambda, size, sigma, db, sb)) => {
                    let big = ra + size;
                    let t = (da + db + sa + sb + self.padding + sigma) * (1.0 + 1.0 / 1_099_511_627_776.0)
                        + (KAPPA + 2.0) * U32 * big
                        + 3.0 * (lambda - 1.0) * big;
                    if t.is_finite() {
                        up32(t)
                    } else {
                        f32::INFINITY
                    }
                }
                None => f32::INFINITY,
            };
            w.tau.push(tau);
        }
    }

    /// The cosines and sines (turning coordinates) and values (sliding
    /// ones) at the `k` midpoints `(2 i + 1) / (2 k)`: `f64` at the first
    /// midpoint, then the angle-addition recurrence in `f64` (a few ulps of
    /// `f64` per step, far inside Lemma 13.10's budget), rounded to `f32`.
    fn angles(&self, q0: &[T], q1: &[T], k: u32, w: &mut RakeWork) {
        let dofs = q0.len();
        let kk = k as usize;
        w.cos.clear();
        w.sin.clear();
        w.value.clear();
        w.cos.resize(dofs * kk, 0.0);
        w.sin.resize(dofs * kk, 0.0);
        w.value.resize(dofs * kk, 0.0);
        let step = 1.0 / f64::from(k);
        for d in 0..dofs {
            let (a, b) = (q0[d].to_f64(), q1[d].to_f64());
            let dq = b - a;
            let (mut s, mut c) = (a + 0.5 * step * dq).sin_cos();
            let (sd, cd) = (step * dq).sin_cos();
            for i in 0..kk {
                let m = (i as f64 + 0.5) * step;
                w.value[d * kk + i] = (a + m * dq) as f32;
                w.cos[d * kk + i] = c as f32;
                w.sin[d * kk + i] = s as f32;
                let (c2, s2) = (c * cd - s * sd, s * cd + c * sd);
                c = c2;
                s = s2;
            }
        }
    }

    /// The chain placed at the midpoints `first .. first + 8` (the last
    /// one repeated past `k`).
    fn place_chunk(&self, first: u32, k: u32, w: &mut RakeWork) {
        let dofs = w.cos.len() / k as usize;
        let kk = k as usize;
        w.turn.clear();
        w.slide.clear();
        for d in 0..dofs {
            let mut c = [0.0f32; LANES];
            let mut s = [0.0f32; LANES];
            let mut v = [0.0f32; LANES];
            for l in 0..LANES {
                let i = (first as usize + l).min(kk - 1);
                c[l] = w.cos[d * kk + i];
                s[l] = w.sin[d * kk + i];
                v[l] = w.value[d * kk + i];
            }
            w.turn.push((c, s));
            w.slide.push(v);
        }
        self.model
            .lanes
            .place(&self.chain.base, &w.turn, &w.slide, &mut w.poses);
    }

    /// Link `l`'s enclosing ball placed in this chunk's lanes.
    fn enclosing(&self, l: usize, w: &mut RakeWork) -> [Lane; 3] {
        if !w.enc_done[l] {
            if let Some(c) = &self.model.covers[l] {
                w.enclosing[l] = w.poses[l].place(c.centre);
            }
            w.enc_done[l] = true;
        }
        w.enclosing[l]
    }

    /// Link `l`'s cover balls placed in this chunk's lanes.
    fn place_balls(&self, l: usize, w: &mut RakeWork) {
        if w.balls_done[l] {
            return;
        }
        if let Some(c) = &self.model.covers[l] {
            let at = w.offset[l];
            for b in 0..c.len() {
                w.placed[at + b] = w.poses[l].place([c.cx[b], c.cy[b], c.cz[b]]);
            }
        }
        w.balls_done[l] = true;
    }

    /// The lanes in which item `it` is not cleared at threshold `tau`.
    fn test(&self, it: &Item, tau: f32, w: &mut RakeWork) -> u8 {
        if tau == f32::INFINITY {
            return u8::MAX;
        }
        let a = it.link as usize;
        let Some(ca) = self.model.covers[a].as_ref() else {
            return u8::MAX;
        };
        let proxy = match it.target {
            Target::Shape(s) | Target::Cloud(s, _) => self.shapes[s as usize].proxy.as_ref(),
            Target::Mesh(o, _) => self.obstacles[o as usize].proxy.as_ref(),
            Target::Link(b, _) => return self.test_link(a, b as usize, tau, w),
        };
        let Some(p) = proxy else {
            return u8::MAX;
        };
        let enc = self.enclosing(a, w);
        w.tests += 1;
        let mut g = p.phi(&enc);
        for x in &mut g {
            *x -= ca.radius;
        }
        let outer = not_above(&g, tau);
        if outer == 0 {
            return 0;
        }
        self.place_balls(a, w);
        let at = w.offset[a];
        let mut fail = 0u8;
        for b in 0..ca.len() {
            w.tests += 1;
            let mut g = p.phi(&w.placed[at + b]);
            let r = ca.r[b];
            for x in &mut g {
                *x -= r;
            }
            fail |= not_above(&g, tau) & outer;
            if fail == outer {
                break;
            }
        }
        fail
    }

    /// A pair of links: enclosing balls, then `a`'s balls against `b`'s
    /// enclosing ball, then ball pairs.
    fn test_link(&self, a: usize, b: usize, tau: f32, w: &mut RakeWork) -> u8 {
        let (Some(ca), Some(cb)) = (
            self.model.covers[a].as_ref(),
            self.model.covers[b].as_ref(),
        ) else {
            return u8::MAX;
        };
        let ea = self.enclosing(a, w);
        let eb = self.enclosing(b, w);
        w.tests += 1;
        let outer = not_above(&ball_gap(&ea, ca.radius, &eb, cb.radius), tau);
        if outer == 0 {
            return 0;
        }
        self.place_balls(a, w);
        self.place_balls(b, w);
        let (oa, ob) = (w.offset[a], w.offset[b]);
        let mut fail = 0u8;
        for i in 0..ca.len() {
            w.tests += 1;
            let xi = w.placed[oa + i];
            let near = not_above(&ball_gap(&xi, ca.r[i], &eb, cb.radius), tau) & outer & !fail;
            if near == 0 {
                continue;
            }
            for j in 0..cb.len() {
                w.tests += 1;
                let g = ball_gap(&xi, ca.r[i], &w.placed[ob + j], cb.r[j]);
                fail |= not_above(&g, tau) & near;
                if fail & near == near {
                    break;
                }
            }
            if fail == outer {
                break;
            }
        }
        fail
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
