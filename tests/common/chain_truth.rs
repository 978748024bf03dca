//! Ground truth for chains moving along joint-space segments, independent of
//! the code under test: its own forward kinematics (f64 rotation matrices
//! from the joints as given), its own sphere trees over the meshes, exact
//! triangle distances (`try_triangle_triangle`), and dense sampling in joint
//! space whose step is bounded by a crude link-speed bound (each point of a
//! link is within the sum of the joint origins' lengths, the prismatic
//! travel and the mesh's radius of every joint above it), not the tested one.
//!
//! Used by `tests/chain.rs`, `tests/chain_edge.rs` and `examples/arm.rs`
//! (through `#[path]`).

#![allow(dead_code, unreachable_pub)]

use motion_bound::chain::{ChainPair, ChainScene, JointKind};
use motion_bound::{try_triangle_triangle, Point3};

type M3 = [[f64; 3]; 3];
type V3 = [f64; 3];

fn mul(a: &M3, b: &M3) -> M3 {
    let mut o = [[0.0; 3]; 3];
    for i in 0..3 {
        for j in 0..3 {
            o[i][j] = (0..3).map(|k| a[i][k] * b[k][j]).sum();
        }
    }
    o
}

fn apply(a: &M3, v: V3) -> V3 {
    [0, 1, 2].map(|i| a[i][0] * v[0] + a[i][1] * v[1] + a[i][2] * v[2])
}

fn add(a: V3, b: V3) -> V3 {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}

fn sub(a: V3, b: V3) -> V3 {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

fn norm(a: V3) -> f64 {
    (a[0] * a[0] + a[1] * a[1] + a[2] * a[2]).sqrt()
}

/// The rotation by `angle` about the unit `k` (Rodrigues, as a matrix
/// exponential of the cross-product matrix).
fn rot(k: V3, angle: f64) -> M3 {
    let (s, c) = angle.sin_cos();
    let kx = [[0.0, -k[2], k[1]], [k[2], 0.0, -k[0]], [-k[1], k[0], 0.0]];
    let kk = mul(&kx, &kx);
    let mut r = [[0.0; 3]; 3];
    for i in 0..3 {
        for j in 0..3 {
            r[i][j] = f64::from(u8::from(i == j)) + s * kx[i][j] + (1.0 - c) * kk[i][j];
        }
    }
    r
}

#[derive(Clone, Copy, Debug)]
pub struct Place {
    pub r: M3,
    pub x: V3,
}

impl Place {
    fn point(&self, p: V3) -> V3 {
        add(apply(&self.r, p), self.x)
    }
    fn then(&self, o: &Place) -> Place {
        Place {
            r: mul(&self.r, &o.r),
            x: self.point(o.x),
        }
    }
}

/// A sphere tree over a mesh's triangles, in the mesh's frame.
struct Tree {
    tris: Vec<[V3; 3]>,
    /// (centre, radius, left, right); leaves have `left == right == tri`
    /// flagged by `usize::MAX` in `right`.
    nodes: Vec<(V3, f64, usize, usize)>,
    /// The largest distance of a vertex from the frame origin.
    radius: f64,
}

/// Cuts triangles into four at their edges' midpoints until every edge is
/// at most `longest`: the same surface (up to the midpoints' rounding,
/// about 1e-16 of the size), with leaves small enough for sphere bounds.
fn cut(tris: Vec<[V3; 3]>, longest: f64) -> Vec<[V3; 3]> {
    let mut out = Vec::new();
    let mut todo = tris;
    while let Some(t) = todo.pop() {
        let edge = (0..3)
            .map(|i| norm(sub(t[i], t[(i + 1) % 3])))
            .fold(0.0, f64::max);
        if edge <= longest {
            out.push(t);
            continue;
        }
        let mid = |i: usize, j: usize| [0, 1, 2].map(|k| (t[i][k] + t[j][k]) / 2.0);
        let (ab, bc, ca) = (mid(0, 1), mid(1, 2), mid(2, 0));
        todo.extend([[t[0], ab, ca], [ab, t[1], bc], [ca, bc, t[2]], [ab, bc, ca]]);
    }
    out
}

impl Tree {
    fn new(tris: Vec<[V3; 3]>) -> Self {
        let tris = cut(tris, 0.05);
        let radius = tris.iter().flatten().map(|p| norm(*p)).fold(0.0, f64::max);
        let mut t = Tree {
            tris,
            nodes: Vec::new(),
            radius,
        };
        let mut idx: Vec<usize> = (0..t.tris.len()).collect();
        t.build(&mut idx);
        t
    }

    fn build(&mut self, idx: &mut [usize]) -> usize {
        let mut lo = [f64::INFINITY; 3];
        let mut hi = [f64::NEG_INFINITY; 3];
        for &i in idx.iter() {
            for p in &self.tris[i] {
                for k in 0..3 {
                    lo[k] = lo[k].min(p[k]);
                    hi[k] = hi[k].max(p[k]);
                }
            }
        }
        let c = [0, 1, 2].map(|k| (lo[k] + hi[k]) / 2.0);
        let r = idx
            .iter()
            .flat_map(|&i| self.tris[i].iter())
            .map(|p| norm(sub(*p, c)))
            .fold(0.0, f64::max)
            * (1.0 + 1e-12)
            + 1e-300;
        let me = self.nodes.len();
        self.nodes.push((c, r, idx[0], usize::MAX));
        if idx.len() == 1 {
            return me;
        }
        let axis = (0..3)
            .max_by(|&a, &b| (hi[a] - lo[a]).total_cmp(&(hi[b] - lo[b])))
            .unwrap_or(0);
        let key = |i: usize, tris: &Vec<[V3; 3]>| tris[i].iter().map(|p| p[axis]).sum::<f64>();
        let tris = &self.tris;
        idx.sort_by(|&a, &b| key(a, tris).total_cmp(&key(b, tris)));
        let mid = idx.len() / 2;
        let (l, r) = idx.split_at_mut(mid);
        let left = self.build(l);
        let right = self.build(r);
        self.nodes[me].2 = left;
        self.nodes[me].3 = right;
        me
    }
}

/// A lower bound of the distance between two placed trees' triangles,
/// within 20 % of it (a node pair whose sphere gap is within that of the
/// best found is not refined, its gap kept), not refined past `cap`
/// (returns `cap` or more when everything is at least that far); `<= 0`
/// exactly when some triangle pair meets (a sphere gap above zero holds no
/// meeting pair).
fn distance(a: &Tree, pa: &Place, b: &Tree, pb: &Place, cap: f64) -> f64 {
    distance_within(a, pa, b, pb, cap, 0.8)
}

/// [`distance`] with node pairs within `keep` of the best kept unrefined
/// (`keep = 1`: the exact distance, up to the triangle distances' rounding).
fn distance_within(a: &Tree, pa: &Place, b: &Tree, pb: &Place, cap: f64, keep: f64) -> f64 {
    let mut best = cap;
    let mut kept = f64::INFINITY;
    let mut stack = vec![(0usize, 0usize)];
    while let Some((i, j)) = stack.pop() {
        let (ca, ra, la, ra_) = a.nodes[i];
        let (cb, rb, lb, rb_) = b.nodes[j];
        let gap = norm(sub(pb.point(cb), pa.point(ca))) - ra - rb;
        if gap >= best {
            continue;
        }
        if gap > 0.0 && gap >= keep * best {
            kept = kept.min(gap);
            continue;
        }
        let (a_leaf, b_leaf) = (ra_ == usize::MAX, rb_ == usize::MAX);
        if a_leaf && b_leaf {
            let ta = a.tris[la].map(|p| Point3::from_array(pa.point(p)));
            let tb = b.tris[lb].map(|p| Point3::from_array(pb.point(p)));
            let d = try_triangle_triangle(&ta, &tb).map_or(0.0, |c| c.distance);
            best = best.min(d);
        } else if b_leaf || (!a_leaf && ra >= rb) {
            // The child nearer the other node last (taken first).
            let d = |k: usize| norm(sub(pa.point(a.nodes[k].0), pb.point(cb))) - a.nodes[k].1;
            let (near, far) = if d(la) <= d(ra_) {
                (la, ra_)
            } else {
                (ra_, la)
            };
            stack.push((far, j));
            stack.push((near, j));
        } else {
            let d = |k: usize| norm(sub(pb.point(b.nodes[k].0), pa.point(ca))) - b.nodes[k].1;
            let (near, far) = if d(lb) <= d(rb_) {
                (lb, rb_)
            } else {
                (rb_, lb)
            };
            stack.push((i, far));
            stack.push((i, near));
        }
    }
    best.min(kept)
}

struct Joint {
    kind: JointKind,
    parent: usize,
    child: usize,
    origin: Place,
    axis: V3,
    dof: Option<usize>,
    origin_len: f64,
}

/// The chain scene as the truth sees it.
pub struct Truth {
    joints: Vec<Joint>,
    /// Joint indices, parents first.
    order: Vec<usize>,
    root: usize,
    base: Place,
    links: Vec<Option<Tree>>,
    /// The joint above each link.
    parent_joint: Vec<Option<usize>>,
    obstacles: Vec<(Tree, Place)>,
    /// The shape obstacles as the truth sees them ([`Truth::with_shapes`]),
    /// each as `(lower, upper)`: the same shape for an exact kind, two
    /// polytopes about and in a curved one.
    shapes: Vec<(TruthShape, TruthShape)>,
    /// The pairs the scene checks.
    pub pairs: Vec<ChainPair>,
}

/// What dense sampling found on a segment.
#[derive(Clone, Copy, Debug)]
pub struct Sampled {
    /// The first sample at which a pair's surfaces meet (distance 0), and
    /// the pair; no touch before `lower` (the sampling's certified bound).
    pub touch: Option<(f64, f64, ChainPair)>,
    /// The smallest distance seen over the samples.
    pub min_distance: f64,
    /// Samples taken.
    pub samples: usize,
}

impl Truth {
    pub fn new(scene: &ChainScene<f64>) -> Self {
        let chain = scene.chain();
        let n = chain.link_count();
        let mut joints = Vec::new();
        let mut parent_joint = vec![None; n];
        for (j, spec) in chain.joints().enumerate() {
            let a = spec.axis;
            let l = norm(a);
            let axis = if spec.kind == JointKind::Fixed || l == 0.0 {
                [0.0, 0.0, 1.0]
            } else {
                [a[0] / l, a[1] / l, a[2] / l]
            };
            parent_joint[spec.child] = Some(j);
            joints.push(Joint {
                kind: spec.kind,
                parent: spec.parent,
                child: spec.child,
                origin: Place {
                    r: spec.origin.rotation,
                    x: spec.origin.translation.to_array(),
                },
                axis,
                dof: None,
                origin_len: norm(spec.origin.translation.to_array()),
            });
        }
        let mut dof = 0;
        for j in &mut joints {
            if j.kind != JointKind::Fixed {
                j.dof = Some(dof);
                dof += 1;
            }
        }
        let root = (0..n).find(|&l| parent_joint[l].is_none()).unwrap_or(0);
        let mut order = Vec::new();
        let mut frontier = vec![root];
        while let Some(l) = frontier.pop() {
            for (j, joint) in joints.iter().enumerate() {
                if joint.parent == l {
                    order.push(j);
                    frontier.push(joint.child);
                }
            }
        }
        let tree_of = |m: &motion_bound::TriMesh<f64>| Tree::new(m.triangle_corners().collect());
        let links = (0..n).map(|l| chain.link_mesh(l).map(tree_of)).collect();
        let obstacles = scene
            .obstacles()
            .iter()
            .map(|o| {
                let p = o.pose();
                (
                    tree_of(o.mesh()),
                    Place {
                        r: p.rotation,
                        x: p.translation.to_array(),
                    },
                )
            })
            .collect();
        let mut pairs = Vec::new();
        for l in 0..n {
            if chain.link_mesh(l).is_none() {
                continue;
            }
            for o in 0..scene.obstacles().len() {
                pairs.push(ChainPair::Obstacle {
                    link: l,
                    obstacle: o,
                });
            }
            for m in l + 1..n {
                if scene.checks_pair(l, m) {
                    pairs.push(ChainPair::SelfCollision { a: l, b: m });
                }
            }
        }
        let b = chain.base();
        Truth {
            joints,
            order,
            root,
            base: Place {
                r: b.rotation,
                x: b.translation.to_array(),
            },
            links,
            parent_joint,
            obstacles,
            shapes: Vec::new(),
            pairs,
        }
    }

    /// The truth with the scene's shape obstacles given as `shapes` (in the
    /// scene's order; `(lower, upper)` as in [`TruthShape`]), their pairs
    /// with every link with geometry checked.
    pub fn with_shapes(mut self, shapes: Vec<(TruthShape, TruthShape)>) -> Self {
        for l in 0..self.links.len() {
            if self.links[l].is_some() {
                for s in 0..shapes.len() {
                    self.pairs.push(ChainPair::Shape { link: l, shape: s });
                }
            }
        }
        self.shapes = shapes;
        self
    }

    /// The exact distance of one pair at `places` as `(lower, upper)`
    /// (equal but for a curved shape's two polytopes), not refined past `cap`.
    pub fn pair_distance_exact(&self, pair: ChainPair, places: &[Place], cap: f64) -> (f64, f64) {
        match pair {
            ChainPair::Shape { link, shape } => match &self.links[link] {
                Some(t) => {
                    let (lo, hi) = &self.shapes[shape];
                    (
                        shape_distance(t, &places[link], lo, cap),
                        shape_distance(t, &places[link], hi, cap),
                    )
                }
                None => (f64::INFINITY, f64::INFINITY),
            },
            ChainPair::Obstacle { link, obstacle } => {
                let (t, p) = &self.obstacles[obstacle];
                let d = match &self.links[link] {
                    Some(a) => distance_within(a, &places[link], t, p, cap, 1.0),
                    None => f64::INFINITY,
                };
                (d, d)
            }
            ChainPair::SelfCollision { a, b } => {
                let d = match (&self.links[a], &self.links[b]) {
                    (Some(ta), Some(tb)) => {
                        distance_within(ta, &places[a], tb, &places[b], cap, 1.0)
                    }
                    _ => f64::INFINITY,
                };
                (d, d)
            }
            _ => (f64::INFINITY, f64::INFINITY),
        }
    }

    /// The smallest exact distance over the pairs at `q` as `(lower,
    /// upper)`, and the pair attaining the upper one.
    pub fn min_distance_exact(&self, q: &[f64]) -> (f64, f64, Option<ChainPair>) {
        let places = self.places(q);
        let mut best = (f64::INFINITY, f64::INFINITY, None);
        for &p in &self.pairs {
            let (lo, hi) = self.pair_distance_exact(p, &places, best.1);
            best.0 = best.0.min(lo);
            if hi < best.1 {
                best = (best.0, hi, Some(p));
            }
        }
        best
    }

    /// Every link's placement at `q`.
    pub fn places(&self, q: &[f64]) -> Vec<Place> {
        let mut out = vec![self.base; self.links.len()];
        out[self.root] = self.base;
        for &j in &self.order {
            let joint = &self.joints[j];
            let frame = out[joint.parent].then(&joint.origin);
            let motion = match (joint.kind, joint.dof) {
                (JointKind::Revolute | JointKind::Continuous, Some(d)) => Place {
                    r: rot(joint.axis, q[d]),
                    x: [0.0; 3],
                },
                (JointKind::Prismatic, Some(d)) => Place {
                    r: rot(joint.axis, 0.0),
                    x: joint.axis.map(|a| a * q[d]),
                },
                _ => Place {
                    r: rot(joint.axis, 0.0),
                    x: [0.0; 3],
                },
            };
            out[joint.child] = frame.then(&motion);
        }
        out
    }

    /// A crude speed bound of every point of link `l` along the segment:
    /// for each movable joint above it, its rate times the sum of the
    /// origins' lengths below it, the prismatic travel and the mesh radius.
    pub fn crude_speed(&self, l: usize, q0: &[f64], q1: &[f64]) -> f64 {
        let radius = self.links[l].as_ref().map_or(0.0, |t| t.radius);
        let mut lever = radius;
        let mut speed = 0.0;
        let mut at = l;
        while let Some(j) = self.parent_joint[at] {
            let joint = &self.joints[j];
            if let Some(d) = joint.dof {
                let rate = (q1[d] - q0[d]).abs();
                match joint.kind {
                    JointKind::Prismatic => {
                        speed += rate;
                        lever += q0[d].abs().max(q1[d].abs());
                    }
                    _ => speed += rate * lever,
                }
            }
            lever += joint.origin_len;
            at = joint.parent;
        }
        speed * (1.0 + 1e-9)
    }

    /// The distance of one pair at placements `places`, not refined past `cap`.
    pub fn pair_distance(&self, pair: ChainPair, places: &[Place], cap: f64) -> f64 {
        match pair {
            ChainPair::Obstacle { link, obstacle } => {
                let (t, p) = &self.obstacles[obstacle];
                match &self.links[link] {
                    Some(a) => distance(a, &places[link], t, p, cap),
                    None => f64::INFINITY,
                }
            }
            ChainPair::SelfCollision { a, b } => match (&self.links[a], &self.links[b]) {
                (Some(ta), Some(tb)) => distance(ta, &places[a], tb, &places[b], cap),
                _ => f64::INFINITY,
            },
            // A curved shape by the polytope inside it: a touch found is
            // one of the shape's.
            ChainPair::Shape { link, shape } => match &self.links[link] {
                Some(t) => shape_distance(t, &places[link], &self.shapes[shape].1, cap),
                None => f64::INFINITY,
            },
            _ => f64::INFINITY,
        }
    }

    /// The smallest distance over the pairs at `q`, and the pair.
    pub fn min_distance(&self, q: &[f64]) -> (f64, Option<ChainPair>) {
        let places = self.places(q);
        let mut best = (f64::INFINITY, None);
        for &p in &self.pairs {
            let d = self.pair_distance(p, &places, best.0);
            if d < best.0 {
                best = (d, Some(p));
            }
        }
        best
    }

    /// Whether some pair's surfaces meet at `q`.
    pub fn touches_at(&self, q: &[f64]) -> bool {
        let places = self.places(q);
        self.pairs
            .iter()
            .any(|&p| self.pair_distance(p, &places, 1e-300) <= 0.0)
    }

    /// Dense sampling of the segment, pair by pair: from each sample the
    /// next is at `d_p / L_p` (the pair cannot touch before it: `L_p`
    /// bounds how fast its distance falls), at least `tol / L_p` (nothing of
    /// the pair moves more than `tol` between samples); a pair stops at its
    /// first touching sample or at the earliest touch found so far.
    pub fn sample(&self, q0: &[f64], q1: &[f64], tol: f64) -> Sampled {
        let speeds: Vec<f64> = (0..self.links.len())
            .map(|l| self.crude_speed(l, q0, q1))
            .collect();
        let bound = |p: ChainPair| match p {
            ChainPair::Obstacle { link, .. } => speeds[link],
            ChainPair::SelfCollision { a, b } => speeds[a] + speeds[b],
            ChainPair::Shape { link, .. } => speeds[link],
            _ => f64::INFINITY,
        };
        let mut touch: Option<(f64, f64, ChainPair)> = None;
        let mut min_distance = f64::INFINITY;
        let mut samples = 0;
        for &p in &self.pairs {
            let l = bound(p);
            let until = touch.map_or(1.0, |(t, _, _)| t);
            let mut t = 0.0f64;
            let mut lower = 0.0f64;
            loop {
                let q: Vec<f64> = q0.iter().zip(q1).map(|(a, b)| a + t * (b - a)).collect();
                let places = self.places(&q);
                samples += 1;
                // Refine only as far as the step could reach past the end.
                let cap = if l > 0.0 {
                    (until - t) * l * 1.01 + tol
                } else {
                    1e-300
                };
                let d = self.pair_distance(p, &places, cap);
                min_distance = min_distance.min(d);
                if d <= 0.0 {
                    if touch.is_none_or(|(tt, _, _)| t < tt) {
                        touch = Some((t, lower, p));
                    }
                    break;
                }
                if l <= 0.0 {
                    break;
                }
                lower = t + d / l;
                if lower >= until || samples > 50_000_000 {
                    break;
                }
                t = (t + (d / l).max(tol / l)).min(until);
            }
        }
        Sampled {
            touch,
            min_distance,
            samples,
        }
    }
}

/// A shape obstacle as the truth sees it, in world coordinates.
#[derive(Clone, Debug)]
pub enum TruthShape {
    /// A convex polytope: its triangles and its faces' planes `(n, d)`
    /// (unit outward `n`, inside where `n . x <= d`).
    Polytope {
        tris: Vec<[V3; 3]>,
        planes: Vec<(V3, f64)>,
    },
    /// The half-space `n . (x - p) <= 0` (unit `n`).
    Plane { n: V3, p: V3 },
    /// Balls of radius `r` about the points.
    Points { points: Vec<V3>, r: f64 },
}

impl TruthShape {
    /// The convex polytope of `tris` (a closed convex mesh in the frame
    /// `place`, containing the frame's origin), in the world.
    pub fn polytope(tris: &[[V3; 3]], place: &Place) -> Self {
        let tris: Vec<[V3; 3]> = tris.iter().map(|t| t.map(|p| place.point(p))).collect();
        let origin = place.x;
        let planes = tris
            .iter()
            .filter_map(|t| {
                let n = cross(sub(t[1], t[0]), sub(t[2], t[0]));
                let l = norm(n);
                if l == 0.0 {
                    return None;
                }
                let mut n = n.map(|x| x / l);
                if dot(n, sub(t[0], origin)) < 0.0 {
                    n = n.map(|x| -x);
                }
                Some((n, dot(n, t[0])))
            })
            .collect();
        TruthShape::Polytope { tris, planes }
    }

    /// A lower bound of the distance from the ball `(c, rho)` to the shape.
    fn ball_lower(&self, c: V3, rho: f64) -> f64 {
        match self {
            TruthShape::Polytope { planes, .. } => {
                planes
                    .iter()
                    .map(|(n, d)| dot(*n, c) - d)
                    .fold(f64::NEG_INFINITY, f64::max)
                    - rho
            }
            TruthShape::Plane { n, p } => dot(*n, sub(c, *p)) - rho,
            TruthShape::Points { points, r } => {
                points
                    .iter()
                    .map(|p| norm(sub(c, *p)))
                    .fold(f64::INFINITY, f64::min)
                    - r
                    - rho
            }
        }
    }

    /// The exact distance from the triangle `t` (world) to the shape (0
    /// when they meet).
    fn triangle(&self, t: &[V3; 3]) -> f64 {
        match self {
            TruthShape::Polytope { tris, planes } => {
                let inside = |p: &V3| planes.iter().all(|(n, d)| dot(*n, *p) <= *d);
                if t.iter().any(inside) {
                    return 0.0;
                }
                let ta = t.map(Point3::from_array);
                tris.iter()
                    .map(|b| {
                        try_triangle_triangle(&ta, &b.map(Point3::from_array))
                            .map_or(0.0, |c| c.distance)
                    })
                    .fold(f64::INFINITY, f64::min)
            }
            TruthShape::Plane { n, p } => t
                .iter()
                .map(|x| dot(*n, sub(*x, *p)))
                .fold(f64::INFINITY, f64::min)
                .max(0.0),
            TruthShape::Points { points, r } => points
                .iter()
                .map(|p| point_triangle(*p, t) - r)
                .fold(f64::INFINITY, f64::min)
                .max(0.0),
        }
    }
}

fn dot(a: V3, b: V3) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn cross(a: V3, b: V3) -> V3 {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

/// The distance from `p` to the triangle `t` (Ericson's closest point by
/// Voronoi regions, written here, not the crate's).
fn point_triangle(p: V3, t: &[V3; 3]) -> f64 {
    let [a, b, c] = *t;
    let (ab, ac, ap) = (sub(b, a), sub(c, a), sub(p, a));
    let (d1, d2) = (dot(ab, ap), dot(ac, ap));
    if d1 <= 0.0 && d2 <= 0.0 {
        return norm(ap);
    }
    let bp = sub(p, b);
    let (d3, d4) = (dot(ab, bp), dot(ac, bp));
    if d3 >= 0.0 && d4 <= d3 {
        return norm(bp);
    }
    let at = |u: f64, v: f64| norm(sub(p, add(a, add(ab.map(|x| x * u), ac.map(|x| x * v)))));
    let vc = d1 * d4 - d3 * d2;
    if vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0 {
        return at(d1 / (d1 - d3), 0.0);
    }
    let cp = sub(p, c);
    let (d5, d6) = (dot(ab, cp), dot(ac, cp));
    if d6 >= 0.0 && d5 <= d6 {
        return norm(cp);
    }
    let vb = d5 * d2 - d1 * d6;
    if vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0 {
        return at(0.0, d2 / (d2 - d6));
    }
    let va = d3 * d6 - d5 * d4;
    if va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0 {
        let w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
        return norm(sub(p, add(b, sub(c, b).map(|x| x * w))));
    }
    let denom = 1.0 / (va + vb + vc);
    at(vb * denom, vc * denom)
}

/// The exact distance from a placed tree's triangles to a shape (branch
/// and bound with no slack), not refined past `cap`.
fn shape_distance(a: &Tree, pa: &Place, shape: &TruthShape, cap: f64) -> f64 {
    let mut best = cap;
    let mut stack = vec![0usize];
    while let Some(i) = stack.pop() {
        let (c, r, l, rr) = a.nodes[i];
        if shape.ball_lower(pa.point(c), r) >= best {
            continue;
        }
        if rr == usize::MAX {
            best = best.min(shape.triangle(&a.tris[l].map(|p| pa.point(p))));
        } else {
            stack.push(l);
            stack.push(rr);
        }
    }
    best
}
