//! The directed motion bound of a link of a kinematic chain
//! (`proofs/13-chains.md`, Lemmas 13.1 to 13.3) and the placement error of
//! forward kinematics, against an independent oracle: forward kinematics
//! and point velocities written out here in double-double arithmetic
//! (`motion_bound::reference::dd`) from the chain's definition, never from
//! the crate's kinematics. The exact chain is the one the proofs certify:
//! unit axes `axis / |axis|` of the stored axes, the exact coordinates
//! `q0 + s (q1 - q0)` of the stored `q0`, `q1`, stored translations, and as
//! rotations of the base and the joint origins the exact rotations the
//! stored matrices were rounded from (Assumption O of Lemma 13.3: any exact
//! rotation within `48 u` of each stored matrix will do).
//!
//! **The oracle's own error.** Every double-double operation errs by at
//! most `4 u^2` relative (`u = 2^-53`), sine and cosine by `2e-32`
//! absolute (`src/dd.rs`); a chain of at most 8 levels takes
//! fewer than 200 operations per level on values below 30, so a velocity
//! component errs by less than `8 * 200 * 4 u^2 * 30 < 2^-88` times the
//! scale of `Model::tolerance` (the sum of the rates times the levers the
//! velocity is made of), and a placed point by less than `2^-88 (1 + |p|)`.
//! Every comparison below allows `2^-86` times that scale (four times the
//! estimate): a bound below the exact value by less than about `1e-26` of
//! the scale would go unseen. No other tolerance is used.
//!
//! Chains are drawn from a seed by a small generator biased to the hard
//! cases (axes along the coordinate axes or parallel to their parent's,
//! points on an axis, zero rates, directions near an axis or along the
//! velocity, degenerate and short intervals); a failing seed is printed.

use motion_bound::chain::{Chain, ChainBuilder, JointKind, JointSpec};
use motion_bound::reference::dd::DoubleDouble as D;
use motion_bound::testkit::toi::Rng;
use motion_bound::{Float, Pose, TriMesh, Vec3};
use proptest::prelude::*;
use proptest::test_runner::TestCaseError;

// ---------------------------------------------------------------------------
// Double-double vectors and matrices.

type V = [D; 3];
type M = [[D; 3]; 3];

const ZERO: V = [D::ZERO, D::ZERO, D::ZERO];
const IDENTITY: M = [
    [D::ONE, D::ZERO, D::ZERO],
    [D::ZERO, D::ONE, D::ZERO],
    [D::ZERO, D::ZERO, D::ONE],
];

fn dd(x: f64) -> D {
    D::from_f64(x)
}

fn v_dd(a: [f64; 3]) -> V {
    a.map(dd)
}

fn add(a: V, b: V) -> V {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}

fn sub(a: V, b: V) -> V {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

fn scale_v(a: V, s: D) -> V {
    [a[0] * s, a[1] * s, a[2] * s]
}

fn dot(a: V, b: V) -> D {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn cross(a: V, b: V) -> V {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

fn norm(a: V) -> D {
    dot(a, a).sqrt()
}

fn unit(a: V) -> V {
    let n = norm(a);
    [a[0] / n, a[1] / n, a[2] / n]
}

fn mat_mul(a: &M, b: &M) -> M {
    let mut out = [[D::ZERO; 3]; 3];
    for (i, row) in out.iter_mut().enumerate() {
        for (j, e) in row.iter_mut().enumerate() {
            *e = a[i][0] * b[0][j] + a[i][1] * b[1][j] + a[i][2] * b[2][j];
        }
    }
    out
}

fn mat_vec(m: &M, v: V) -> V {
    [dot(m[0], v), dot(m[1], v), dot(m[2], v)]
}

/// The rotation by `angle` about the unit `k` (Rodrigues:
/// `R = cos I + sin [k]x + (1 - cos) k k^T`).
fn rotation(k: V, angle: D) -> M {
    let (s, c) = angle.sin_cos();
    let t = D::ONE - c;
    let [x, y, z] = k;
    [
        [c + x * x * t, x * y * t - z * s, x * z * t + y * s],
        [y * x * t + z * s, c + y * y * t, y * z * t - x * s],
        [z * x * t - y * s, z * y * t + x * s, c + z * z * t],
    ]
}

fn to_f64(a: V) -> [f64; 3] {
    a.map(D::to_f64)
}

// ---------------------------------------------------------------------------
// The testkit's deterministic generator (SplitMix64), with the draws these
// tests need.

/// The draws of these tests beyond the testkit's `unit` and `range`.
trait Draws {
    fn below(&mut self, n: usize) -> usize;
    fn chance(&mut self, p: f64) -> bool;
    fn cube(&mut self, r: f64) -> [f64; 3];
    fn nonzero_vector(&mut self) -> [f64; 3];
}

impl Draws for Rng {
    fn below(&mut self, n: usize) -> usize {
        (self.next_u64() % n as u64) as usize
    }
    fn chance(&mut self, p: f64) -> bool {
        self.unit() < p
    }
    fn cube(&mut self, r: f64) -> [f64; 3] {
        [self.range(-r, r), self.range(-r, r), self.range(-r, r)]
    }
    /// A nonzero vector, a coordinate axis a quarter of the time (not the
    /// testkit's unit `direction`).
    fn nonzero_vector(&mut self) -> [f64; 3] {
        if self.chance(0.25) {
            let mut a = [0.0; 3];
            a[self.below(3)] = if self.chance(0.5) { 1.0 } else { -1.0 };
            return a;
        }
        loop {
            let a = self.cube(1.0);
            if a.iter().any(|x| x.abs() > 0.05) {
                return a;
            }
        }
    }
}

// ---------------------------------------------------------------------------
// Chains as drawn (precision-free), built in `T`, and their exact model.

#[derive(Clone, Debug)]
struct JointDesc {
    kind: JointKind,
    /// The parent link (joint `i` always has child link `i + 1`).
    parent: usize,
    axis: [f64; 3],
    /// The origin's rotation: axis (any length) and angle.
    turn: ([f64; 3], f64),
    shift: [f64; 3],
    q: [f64; 2],
}

#[derive(Clone, Debug)]
struct ChainDesc {
    base_turn: ([f64; 3], f64),
    base_shift: [f64; 3],
    joints: Vec<JointDesc>,
    /// A random tetrahedron per link (vertices within 1 of its frame's origin).
    meshes: Vec<Option<[[f64; 3]; 4]>>,
}

fn random_turn(rng: &mut Rng, p_identity: f64) -> ([f64; 3], f64) {
    if rng.chance(p_identity) {
        return ([0.0, 0.0, 1.0], 0.0);
    }
    if rng.chance(0.2) {
        // A quarter turn about a coordinate axis, as URDFs often have.
        let mut a = [0.0; 3];
        a[rng.below(3)] = 1.0;
        let s = if rng.chance(0.5) { 1.0 } else { -1.0 };
        return (a, s * core::f64::consts::FRAC_PI_2);
    }
    (rng.nonzero_vector(), rng.range(-1.2, 1.2))
}

fn random_chain(rng: &mut Rng, max_joints: usize, with_meshes: bool) -> ChainDesc {
    let n = 1 + rng.below(max_joints);
    let tree = rng.chance(0.4);
    let mut joints: Vec<JointDesc> = Vec::with_capacity(n);
    for i in 0..n {
        let parent = if tree { rng.below(i + 1) } else { i };
        let kind = match rng.below(20) {
            0..=7 => JointKind::Revolute,
            8..=10 => JointKind::Continuous,
            11..=15 => JointKind::Prismatic,
            _ => JointKind::Fixed,
        };
        let axis = match (parent, rng.chance(0.15)) {
            // Parallel to the parent's axis (shoulder and elbow).
            (p, true) if p > 0 => joints[p - 1].axis,
            _ => rng.nonzero_vector(),
        };
        let shift = if rng.chance(0.2) {
            [0.0; 3]
        } else if rng.chance(0.2) {
            let mut a = [0.0; 3];
            a[rng.below(3)] = rng.range(-1.0, 1.0);
            a
        } else {
            rng.cube(1.0)
        };
        let reach = if kind == JointKind::Prismatic {
            0.5
        } else {
            3.0
        };
        let q0 = rng.range(-reach, reach);
        let q1 = match rng.below(10) {
            0 | 1 => q0,
            2 => q0 + 1e-9,
            _ => rng.range(-reach, reach),
        };
        joints.push(JointDesc {
            kind,
            parent,
            axis,
            turn: random_turn(rng, 0.3),
            shift,
            q: [q0, q1],
        });
    }
    let base_turn = random_turn(rng, 0.5);
    let base_shift = if rng.chance(0.5) {
        [0.0; 3]
    } else {
        rng.cube(1.0)
    };
    let meshes = (0..=n)
        .map(|_| {
            (with_meshes && rng.chance(0.8))
                .then(|| [rng.cube(1.0), rng.cube(1.0), rng.cube(1.0), rng.cube(1.0)])
        })
        .collect();
    ChainDesc {
        base_turn,
        base_shift,
        joints,
        meshes,
    }
}

/// The exact rotation of a drawn turn, in double-double.
fn exact_turn((axis, angle): ([f64; 3], f64)) -> M {
    rotation(unit(v_dd(axis)), dd(angle))
}

/// A double-double matrix rounded to `T` (through `f64`: within `2 u` of
/// the exact rotation per entry, so within `2 sqrt(3) u < 48 u` in norm).
fn stored<T: Float>(m: &M) -> [[T; 3]; 3] {
    m.map(|row| row.map(|e| T::from_f64(e.to_f64())))
}

fn vec_t<T: Float>(a: [f64; 3]) -> [T; 3] {
    a.map(T::from_f64)
}

fn widen<T: Float>(a: [T; 3]) -> V {
    a.map(|x| dd(x.to_f64()))
}

#[derive(Clone, Copy, Debug)]
struct ModelJoint {
    kind: JointKind,
    parent: usize,
    /// The exact unit axis `axis / |axis|` of the stored axis.
    k: V,
    rot: M,
    shift: V,
    dof: Option<usize>,
}

/// The exact chain (in double-double) of a chain built in `T`.
struct Model {
    base_rot: M,
    base_shift: V,
    joints: Vec<ModelJoint>,
    q0: Vec<D>,
    q1: Vec<D>,
}

/// Every link's world pose and every joint's world axis and axis point.
struct Placed {
    rot: Vec<M>,
    pos: Vec<V>,
    axis: Vec<V>,
    point: Vec<V>,
}

impl Model {
    /// The joint coordinates at `s`: `q0 + s (q1 - q0)`.
    fn q_at(&self, s: D) -> Vec<D> {
        self.q0
            .iter()
            .zip(&self.q1)
            .map(|(&a, &b)| a + s * (b - a))
            .collect()
    }

    fn place(&self, q: &[D]) -> Placed {
        let n = self.joints.len() + 1;
        let mut p = Placed {
            rot: vec![IDENTITY; n],
            pos: vec![ZERO; n],
            axis: vec![ZERO; n - 1],
            point: vec![ZERO; n - 1],
        };
        p.rot[0] = self.base_rot;
        p.pos[0] = self.base_shift;
        for (j, joint) in self.joints.iter().enumerate() {
            let (pr, px) = (p.rot[joint.parent], p.pos[joint.parent]);
            let frame_rot = mat_mul(&pr, &joint.rot);
            let frame_pos = add(mat_vec(&pr, joint.shift), px);
            let axis = mat_vec(&frame_rot, joint.k);
            p.axis[j] = axis;
            p.point[j] = frame_pos;
            let (rot, pos) = match (joint.kind, joint.dof) {
                (JointKind::Revolute | JointKind::Continuous, Some(d)) => {
                    (mat_mul(&frame_rot, &rotation(joint.k, q[d])), frame_pos)
                }
                (JointKind::Prismatic, Some(d)) => (frame_rot, add(frame_pos, scale_v(axis, q[d]))),
                _ => (frame_rot, frame_pos),
            };
            p.rot[j + 1] = rot;
            p.pos[j + 1] = pos;
        }
        p
    }

    /// The movable joints from the root to `link`, root first.
    fn path(&self, link: usize) -> Vec<usize> {
        let mut out = Vec::new();
        let mut at = link;
        while at > 0 {
            let j = at - 1;
            if self.joints[j].dof.is_some() {
                out.push(j);
            }
            at = self.joints[j].parent;
        }
        out.reverse();
        out
    }

    /// The velocity of the world point `x` of link `link` and the link's
    /// angular velocity, both at the placement `placed` (Lemma 13.1's sum:
    /// `sum_turning dq_j a_j x (x - o_j) + sum_sliding dq_j a_j`).
    fn velocity(&self, placed: &Placed, link: usize, x: V) -> (V, V) {
        let mut v = ZERO;
        let mut w = ZERO;
        for j in self.path(link) {
            let joint = &self.joints[j];
            let d = joint.dof.expect("a movable joint");
            let dq = self.q1[d] - self.q0[d];
            let a = placed.axis[j];
            if matches!(joint.kind, JointKind::Prismatic) {
                v = add(v, scale_v(a, dq));
            } else {
                v = add(v, scale_v(cross(a, sub(x, placed.point[j])), dq));
                w = add(w, scale_v(a, dq));
            }
        }
        (v, w)
    }

    /// What the oracle's comparisons allow for its own rounding (module
    /// docs): `2^-86` times the sum over the path's joints of the rate
    /// times `1 + |x| + |o_j| + rho`.
    fn tolerance(&self, placed: &Placed, link: usize, x: V, rho: f64) -> D {
        let mut scale = 0.0;
        for j in self.path(link) {
            let d = self.joints[j].dof.expect("movable");
            let rate = (self.q1[d] - self.q0[d]).abs().to_f64();
            scale += rate * (1.0 + norm(x).to_f64() + norm(placed.point[j]).to_f64() + rho);
        }
        dd(scale * 2f64.powi(-86))
    }
}

/// The chain of `desc` built in `T`, its exact model, and `q0`, `q1` in `T`.
fn build<T: Float>(desc: &ChainDesc) -> (Chain<T>, Model, Vec<T>, Vec<T>) {
    let mut b = ChainBuilder::<T>::new();
    for (l, mesh) in desc.meshes.iter().enumerate() {
        let mesh = mesh.map(|v| {
            TriMesh::try_new(
                v.iter().map(|p| vec_t::<T>(*p)).collect(),
                vec![[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]],
            )
            .expect("a tetrahedron")
        });
        b.add_link(format!("l{l}"), mesh).expect("a link");
    }
    let mut rots = Vec::new();
    for (i, j) in desc.joints.iter().enumerate() {
        let rot = exact_turn(j.turn);
        b.add_joint(JointSpec {
            name: format!("j{i}"),
            kind: j.kind,
            parent: j.parent,
            child: i + 1,
            origin: Pose::new(stored::<T>(&rot), Vec3::from_array(vec_t::<T>(j.shift))),
            axis: vec_t::<T>(j.axis),
            limits: None,
        })
        .expect("a joint");
        rots.push(rot);
    }
    let base_rot = exact_turn(desc.base_turn);
    let base = Pose::new(
        stored::<T>(&base_rot),
        Vec3::from_array(vec_t::<T>(desc.base_shift)),
    );
    let chain = b.build().expect("a tree").with_base(base);
    // The model reads back what the chain holds (its specs), so that it
    // certainly describes the stored numbers.
    let joints: Vec<ModelJoint> = chain
        .joints()
        .enumerate()
        .map(|(i, spec)| ModelJoint {
            kind: spec.kind,
            parent: spec.parent,
            k: unit(widen(spec.axis)),
            rot: rots[i],
            shift: widen(spec.origin.translation.to_array()),
            dof: chain.joint_coordinate(i),
        })
        .collect();
    let mut q0 = vec![T::ZERO; chain.dof()];
    let mut q1 = vec![T::ZERO; chain.dof()];
    for (i, j) in desc.joints.iter().enumerate() {
        if let Some(d) = chain.joint_coordinate(i) {
            q0[d] = T::from_f64(j.q[0]);
            q1[d] = T::from_f64(j.q[1]);
        }
    }
    let model = Model {
        base_rot,
        base_shift: widen(chain.base().translation.to_array()),
        joints,
        q0: q0.iter().map(|x| dd(x.to_f64())).collect(),
        q1: q1.iter().map(|x| dd(x.to_f64())).collect(),
    };
    (chain, model, q0, q1)
}

// ---------------------------------------------------------------------------
// Queries: a ball on a link, a direction, a sub-interval.

#[derive(Clone, Debug)]
struct Query {
    link: usize,
    centre: [f64; 3],
    radius: f64,
    n: [f64; 3],
    interval: [f64; 2],
}

/// A query on `desc`, biased: centres at the link frame's origin (on the
/// parent joint's axis), directions along or near a path joint's axis at
/// `t0` (where the directed bound is smallest and its margins matter) or
/// along the centre's velocity (where it is tight).
fn random_query(rng: &mut Rng, desc: &ChainDesc, model: &Model) -> Query {
    let link = rng.below(desc.joints.len() + 1);
    let centre = match rng.below(10) {
        0 => [0.0; 3],
        // On (or a hair off) the parent joint's axis, which passes through
        // the link frame's origin along the joint's own axis: the distance
        // to the axis is then all rounding, what `2 delta` and
        // `epsilon_R |c - o|` of Lemma 13.3 cover.
        1..=3 if link > 0 => {
            let k = to_f64(model.joints[link - 1].k);
            let (l, e) = (rng.range(-1.0, 1.0), rng.cube(1e-6));
            [k[0] * l + e[0], k[1] * l + e[1], k[2] * l + e[2]]
        }
        _ => rng.cube(1.0),
    };
    let radius = if rng.chance(0.3) {
        0.0
    } else {
        rng.range(0.0, 0.3)
    };
    let interval = match rng.below(4) {
        0 => [0.0, 1.0],
        1 => {
            let a = rng.unit();
            [a, a]
        }
        2 => {
            let h = [0.125, 1e-3, 1e-6][rng.below(3)];
            let a = rng.range(0.0, 1.0 - h);
            [a, a + h]
        }
        _ => {
            let (a, b) = (rng.unit(), rng.unit());
            [a.min(b), a.max(b)]
        }
    };
    let placed = model.place(&model.q_at(dd(interval[0])));
    let path = model.path(link);
    // A sliding joint below a turning one: `n` across both axes at `t0`, so
    // that the slide's part `r |n . a(s)|` is 0 at `t0` and grows only as its
    // axis turns (what the angle `theta` of Lemma 13.2 covers).
    let slide_under_turn = path.iter().enumerate().find_map(|(i, &j)| {
        (model.joints[j].kind == JointKind::Prismatic)
            .then(|| {
                path[..i]
                    .iter()
                    .rev()
                    .find(|&&k| model.joints[k].kind != JointKind::Prismatic)
                    .map(|&k| (k, j))
            })
            .flatten()
    });
    if let (Some((turn, slide)), true) = (slide_under_turn, rng.chance(0.3)) {
        let n = cross(placed.axis[slide], placed.axis[turn]);
        if norm(n).to_f64() > 1e-3 {
            let centre = if rng.chance(0.5) {
                [0.0; 3]
            } else {
                rng.cube(0.2)
            };
            return Query {
                link,
                centre,
                radius: if rng.chance(0.5) {
                    0.0
                } else {
                    rng.range(0.0, 0.05)
                },
                n: to_f64(n),
                interval,
            };
        }
    }
    let n = match rng.below(10) {
        0..=2 if !path.is_empty() => {
            let a = to_f64(placed.axis[path[rng.below(path.len())]]);
            if rng.chance(0.5) {
                a
            } else {
                let e = rng.cube(1e-9);
                [a[0] + e[0], a[1] + e[1], a[2] + e[2]]
            }
        }
        3 | 4 => {
            let c = add(mat_vec(&placed.rot[link], v_dd(centre)), placed.pos[link]);
            let v = model.velocity(&placed, link, c).0;
            if norm(v).to_f64() > 1e-6 {
                to_f64(v)
            } else {
                rng.nonzero_vector()
            }
        }
        _ => rng.nonzero_vector(),
    };
    Query {
        link,
        centre,
        radius,
        n,
        interval,
    }
}

/// The exact supremum over the ball of `|p'.n|` and of `|p'|` at one
/// placement: with `v` the centre's velocity and `w` the link's angular
/// velocity, `p' = v + w x d` for `p = c + d`, so
/// `max |p'.n| = |v.n| + rho |n x w|` and
/// `max |p'| = sqrt((v.w^)^2 + (|v - (v.w^) w^| + rho |w|)^2)`.
fn ball_sup(v: V, w: V, n: V, rho: D) -> (D, D) {
    let directed = dot(v, n).abs() + rho * norm(cross(n, w));
    let wl = norm(w);
    let undirected = if wl.to_f64() == 0.0 {
        norm(v)
    } else {
        let wu = scale_v(w, D::ONE / wl);
        let along = dot(v, wu);
        let across = norm(sub(v, scale_v(wu, along))) + rho * wl;
        (along * along + across * across).sqrt()
    };
    (directed, undirected)
}

/// What one check saw: the largest sampled values and the bounds.
#[derive(Clone, Copy, Debug, Default)]
struct Seen {
    directed: f64,
    undirected: f64,
    sup_directed: f64,
    sup_undirected: f64,
}

/// Checks the bound of `query` on the chain of `desc` in `T` at `samples + 1`
/// times of the interval (and 8 more drawn from `rng`), over the exact
/// supremum over the ball and at sampled points of it.
fn check<T: Float>(
    desc: &ChainDesc,
    query: &Query,
    samples: usize,
    rng: &mut Rng,
) -> Result<Seen, String> {
    let (chain, model, q0, q1) = build::<T>(desc);
    let centre = vec_t::<T>(query.centre);
    let radius = T::from_f64(query.radius);
    let n_t = vec_t::<T>(query.n);
    let [t0, t1] = query.interval.map(T::from_f64);
    let (directed, undirected) = chain
        .directed_speed_bound(&q0, &q1, query.link, centre, radius, n_t, [t0, t1])
        .map_err(|e| format!("bound refused: {e}"))?;
    let (bd, bu) = (dd(directed.to_f64()), dd(undirected.to_f64()));
    if !(directed >= T::ZERO && undirected >= T::ZERO) {
        return Err(format!("bounds {directed:?}, {undirected:?}"));
    }
    let n = unit(widen(n_t));
    let c_local = widen(centre);
    let rho = dd(radius.to_f64());
    let (t0, t1) = (dd(t0.to_f64()), dd(t1.to_f64()));
    let mut times: Vec<D> = (0..=samples)
        .map(|k| t0 + (t1 - t0) * (k as f64 / samples as f64))
        .collect();
    times.extend((0..8).map(|_| t0 + (t1 - t0) * rng.unit()));
    let mut seen = Seen {
        directed: directed.to_f64(),
        undirected: undirected.to_f64(),
        ..Seen::default()
    };
    for s in times {
        let placed = model.place(&model.q_at(s));
        let c = add(
            mat_vec(&placed.rot[query.link], c_local),
            placed.pos[query.link],
        );
        let (v, w) = model.velocity(&placed, query.link, c);
        let tol = model.tolerance(&placed, query.link, c, query.radius);
        let (sd, su) = ball_sup(v, w, n, rho);
        seen.sup_directed = seen.sup_directed.max(sd.to_f64());
        seen.sup_undirected = seen.sup_undirected.max(su.to_f64());
        if sd > bd + tol || su > bu + tol {
            return Err(format!(
                "at s = {:e}: sup over the ball |p'.n| = {:e}, |p'| = {:e}; bounds {:e}, {:e}",
                s.to_f64(),
                sd.to_f64(),
                su.to_f64(),
                bd.to_f64(),
                bu.to_f64()
            ));
        }
        // Points of the ball: its centre, the point where `|p'.n|` peaks,
        // and points of the sphere in random directions.
        let mut points = vec![c];
        let nw = cross(n, w);
        if norm(nw).to_f64() > 0.0 {
            let sign = if dot(v, n).to_f64() < 0.0 { -1.0 } else { 1.0 };
            points.push(add(c, scale_v(unit(nw), rho * sign)));
        }
        for _ in 0..4 {
            points.push(add(c, scale_v(unit(v_dd(rng.nonzero_vector())), rho)));
        }
        for p in points {
            let (vp, _) = model.velocity(&placed, query.link, p);
            let (along, speed) = (dot(vp, n).abs(), norm(vp));
            if along > bd + tol || speed > bu + tol {
                return Err(format!(
                    "at s = {:e}, a point of the ball: |p'.n| = {:e}, |p'| = {:e}; bounds {:e}, {:e}",
                    s.to_f64(),
                    along.to_f64(),
                    speed.to_f64(),
                    bd.to_f64(),
                    bu.to_f64()
                ));
            }
        }
    }
    Ok(seen)
}

fn case<T: Float>(seed: u64) -> Result<(), TestCaseError> {
    let mut rng = Rng::new(seed);
    let desc = random_chain(&mut rng, 7, false);
    let (_, model, _, _) = build::<T>(&desc);
    let query = random_query(&mut rng, &desc, &model);
    check::<T>(&desc, &query, 24, &mut rng)
        .map(|_| ())
        .map_err(|e| TestCaseError::fail(format!("seed {seed}: {e}\n{desc:?}\n{query:?}")))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(1500))]

    /// Lemmas 13.1 to 13.3 in `f64`: 0 violations over random chains.
    #[test]
    fn directed_and_undirected_chain_bounds_hold_f64(seed in any::<u64>()) {
        case::<f64>(seed)?;
    }

    /// The same in `f32` (the oracle on the `f32` inputs widened exactly).
    #[test]
    fn directed_and_undirected_chain_bounds_hold_f32(seed in any::<u64>()) {
        case::<f32>(seed)?;
    }

    /// Lemma 13.3: every computed placed mesh vertex (and every link
    /// frame's origin) of an `f32` chain, at a computed coordinate
    /// `q0 + t (q1 - q0)`, is within `placement_error_bound` of its exact
    /// place.
    #[test]
    fn placed_points_are_within_the_placement_error_f32(seed in any::<u64>()) {
        placement::<f32>(seed).map_err(TestCaseError::fail)?;
    }

    /// The same in `f64`.
    #[test]
    fn placed_points_are_within_the_placement_error_f64(seed in any::<u64>()) {
        placement::<f64>(seed).map_err(TestCaseError::fail)?;
    }
}

/// The largest ratio of a placement error to its bound over one chain and
/// one time, or the violation.
fn placement<T: Float>(seed: u64) -> Result<f64, String> {
    let mut rng = Rng::new(seed);
    let desc = random_chain(&mut rng, 7, true);
    let (chain, model, q0, q1) = build::<T>(&desc);
    let t = T::from_f64(if rng.chance(0.2) { 1.0 } else { rng.unit() });
    // The coordinates as the crate computes them at `t`.
    let q: Vec<T> = q0.iter().zip(&q1).map(|(&a, &b)| a + t * (b - a)).collect();
    let poses = chain
        .try_forward_kinematics(&q)
        .map_err(|e| e.to_string())?;
    let placed = model.place(&model.q_at(dd(t.to_f64())));
    let mut worst: f64 = 0.0;
    for (l, pose) in poses.iter().enumerate() {
        let delta = chain
            .placement_error_bound(&q0, &q1, l)
            .map_err(|e| e.to_string())?;
        let mut points = vec![[T::ZERO; 3]];
        if let Some(mesh) = chain.link_mesh(l) {
            points.extend(mesh.vertices().iter().copied());
        }
        for p in points {
            let got = widen(pose.transform_point(p).to_array());
            let exact = add(mat_vec(&placed.rot[l], widen(p)), placed.pos[l]);
            let err = norm(sub(got, exact));
            let tol = dd((1.0 + norm(exact).to_f64()) * 2f64.powi(-86));
            if err > dd(delta.to_f64()) + tol {
                return Err(format!(
                    "seed {seed}: link {l}, point {p:?} at t = {t:?}: error {:e} above the bound {:e}\n{desc:?}",
                    err.to_f64(),
                    delta.to_f64()
                ));
            }
            worst = worst.max(err.to_f64() / delta.to_f64());
        }
    }
    Ok(worst)
}

/// The oracle itself: its velocity (Lemma 13.1's sum, evaluated from the
/// placed axes) is the derivative of its own forward kinematics, checked by
/// central differences (step `2^-20`: truncation about `1e-12` of the
/// speed, far below the `1e-9` asked).
#[test]
fn oracle_velocity_is_the_derivative_of_its_positions() {
    let mut rng = Rng::new(0x05ee_d0f0_ac1e);
    for _ in 0..200 {
        let desc = random_chain(&mut rng, 7, false);
        let (_, model, _, _) = build::<f64>(&desc);
        let link = rng.below(desc.joints.len() + 1);
        let local = v_dd(rng.cube(1.0));
        let s = dd(rng.unit());
        let h = dd(2f64.powi(-20));
        let at = |s: D| {
            let p = model.place(&model.q_at(s));
            add(mat_vec(&p.rot[link], local), p.pos[link])
        };
        let placed = model.place(&model.q_at(s));
        let x = at(s);
        let (v, _) = model.velocity(&placed, link, x);
        let fd = scale_v(sub(at(s + h), at(s - h)), D::ONE / (h * 2.0));
        let err = norm(sub(v, fd)).to_f64();
        let size = 1.0 + norm(v).to_f64();
        assert!(
            err <= 1e-9 * size,
            "velocity {:?} against central differences {:?}",
            to_f64(v),
            to_f64(fd)
        );
    }
}

/// The stored unit axis of every movable joint (`Chain::joint_axis`) is
/// within `4.5 u` of the exact `axis / |axis|` (Lemma 13.3's `|k^ - k|`),
/// for axes whose squares do not underflow.
#[test]
fn stored_unit_axes_are_within_their_budget() {
    fn run<T: Float>() {
        let mut rng = Rng::new(0x000a_c5e5);
        let u = T::UNIT_ROUNDOFF.to_f64();
        let mut worst: f64 = 0.0;
        for _ in 0..400 {
            let desc = random_chain(&mut rng, 7, false);
            let (chain, model, _, _) = build::<T>(&desc);
            for (j, joint) in model.joints.iter().enumerate() {
                if joint.dof.is_none() {
                    continue;
                }
                let got = widen(chain.joint_axis(j).expect("a joint").to_array());
                let err = norm(sub(got, joint.k)).to_f64() / u;
                assert!(err <= 4.5, "axis {j}: {err} u from the exact unit axis");
                worst = worst.max(err);
            }
        }
        println!("stored unit axes: worst {worst:.2} u from the exact");
    }
    run::<f64>();
    run::<f32>();
}

/// A direction scaled by `2^-600` or `2^600` (`f64`), `2^-70` or `2^70`
/// (`f32`) gives the bound of the direction itself, bit for bit: the bound
/// scales `n` by its largest component before normalising it (an early
/// version normalised directly: squares of components below about `1e-154`
/// underflowed, so it refused these directions, and normalised ones a little
/// larger off unit length).
#[test]
fn tiny_and_huge_directions_give_the_unit_direction_bound() {
    fn run<T: Float>(k: i32) {
        let mut rng = Rng::new(0x714e);
        for _ in 0..200 {
            let desc = random_chain(&mut rng, 5, false);
            let (chain, model, q0, q1) = build::<T>(&desc);
            let q = random_query(&mut rng, &desc, &model);
            let n = vec_t::<T>(q.n);
            let go = |n: [T; 3]| {
                chain
                    .directed_speed_bound(
                        &q0,
                        &q1,
                        q.link,
                        vec_t::<T>(q.centre),
                        T::from_f64(q.radius),
                        n,
                        q.interval.map(T::from_f64),
                    )
                    .expect("a bound")
            };
            let plain = go(n);
            for e in [-k, k] {
                let s = T::from_f64(2f64.powi(e));
                let scaled = go(n.map(|x| x * s));
                assert_eq!(
                    (scaled.0.to_f64().to_bits(), scaled.1.to_f64().to_bits()),
                    (plain.0.to_f64().to_bits(), plain.1.to_f64().to_bits()),
                    "n scaled by 2^{e}"
                );
            }
        }
    }
    run::<f64>(600);
    run::<f32>(70);
}

/// Tightness where the bound is exact: a point turning about one revolute
/// joint whose axis is fixed in the world (fixed joints above and below it,
/// any base), `n` with its part across the axis along the point's velocity,
/// over `[t0, t0]` and `[t0, t0 + 1e-12]`. The exact supremum is then
/// `r |n x a| dist(p, axis)` (Lemma 13.1 is an equality), and the bound is
/// within `1 + 1e-9` of it (its excess is rounding only: `epsilon_R`,
/// `2 delta` and the `gamma` factors, about `1e-13` here).
#[test]
fn single_fixed_axis_revolute_joint_bound_is_tight() {
    let mut rng = Rng::new(0x0007_1647);
    let mut worst: f64 = 1.0;
    for _ in 0..300 {
        let mut desc = random_chain(&mut rng, 1, false);
        let above = rng.below(3);
        let below = rng.below(3);
        let mut joints = Vec::new();
        let fixed = |rng: &mut Rng, parent: usize| JointDesc {
            kind: JointKind::Fixed,
            parent,
            axis: [0.0, 0.0, 1.0],
            turn: random_turn(rng, 0.3),
            shift: rng.cube(1.0),
            q: [0.0, 0.0],
        };
        for i in 0..above {
            joints.push(fixed(&mut rng, i));
        }
        let q0 = rng.range(-3.0, 3.0);
        let mut q1 = rng.range(-3.0, 3.0);
        if (q1 - q0).abs() < 0.1 {
            q1 = q0 + 1.0;
        }
        joints.push(JointDesc {
            kind: JointKind::Revolute,
            parent: above,
            axis: rng.nonzero_vector(),
            turn: random_turn(&mut rng, 0.3),
            shift: rng.cube(1.0),
            q: [q0, q1],
        });
        for i in 0..below {
            joints.push(fixed(&mut rng, above + 1 + i));
        }
        desc.meshes = vec![None; joints.len() + 1];
        desc.joints = joints;
        let link = above + below + 1;
        let (chain, model, q0, q1) = build::<f64>(&desc);
        let centre = rng.cube(1.0);
        let t0 = rng.unit();
        let placed = model.place(&model.q_at(dd(t0)));
        let j = above;
        let (a, o) = (placed.axis[j], placed.point[j]);
        let c = add(mat_vec(&placed.rot[link], v_dd(centre)), placed.pos[link]);
        let radial = sub(sub(c, o), scale_v(a, dot(sub(c, o), a)));
        if norm(radial).to_f64() < 0.05 {
            continue;
        }
        // n: a unit mix of the velocity direction and the axis.
        let tangent = unit(cross(a, radial));
        let beta = rng.range(-1.2, 1.2);
        let n = to_f64(add(
            scale_v(tangent, dd(beta.cos())),
            scale_v(a, dd(beta.sin())),
        ));
        for t1 in [t0, (t0 + 1e-12).min(1.0)] {
            let (bound, _) = chain
                .directed_speed_bound(&q0, &q1, link, centre, 0.0, n, [t0, t1])
                .expect("a bound");
            let (v, _) = model.velocity(&placed, link, c);
            let exact = dot(v, unit(v_dd(n))).abs().to_f64();
            let ratio = bound / exact;
            assert!(
                (1.0..=1.0 + 1e-9).contains(&ratio),
                "bound {bound:e} against the exact supremum {exact:e}: ratio {ratio}"
            );
            worst = worst.max(ratio);
        }
    }
    println!(
        "single fixed-axis revolute joint: worst bound/exact = 1 + {:.2e}",
        worst - 1.0
    );
}

/// How much of Lemma 13.3's `delta` the placement errors use: the largest
/// and median ratio of the error of a placed mesh vertex (or frame origin)
/// to `placement_error_bound`, over 1,000 random chains with meshes per
/// precision (run with `--nocapture`).
#[test]
fn placement_error_bound_slack_is_reported() {
    fn run<T: Float>(name: &str) {
        let mut ratios: Vec<f64> = (0..1000u64)
            .map(|k| placement::<T>(0x0009_1ace ^ (k << 20)).expect("within the bound"))
            .collect();
        ratios.sort_by(f64::total_cmp);
        println!(
            "{name}: placement error / delta: median {:.2e}, max {:.2e}",
            ratios[ratios.len() / 2],
            ratios[ratios.len() - 1]
        );
    }
    run::<f32>("f32");
    run::<f64>("f64");
}

/// The excess of the bound over the sampled supremum over random chains
/// (the figures of `proofs/13-chains.md`; run with `--nocapture`). Directed
/// and undirected, in `f64`, over the whole segment, over the query's
/// first horizon (`h = 1/8`) and at one instant; the supremum is the exact
/// one over the ball at 129 times. Cases whose sampled supremum is below
/// `1e-9` (a direction the ball never moves along) are counted apart.
#[test]
fn chain_bound_excess_over_sampled_supremum_is_reported() {
    let mut rng = Rng::new(0x0000_ec55);
    println!("| interval | bound | cases | median | mean | 90th pct | max | sup < 1e-9 |");
    println!("|---|---|---|---|---|---|---|---|");
    for (name, h) in [("[0, 1]", 1.0), ("h = 1/8", 0.125), ("h = 0", 0.0)] {
        let mut dir = Vec::new();
        let mut und = Vec::new();
        let mut tiny = 0;
        let mut single = Vec::new();
        for _ in 0..500 {
            let desc = random_chain(&mut rng, 7, false);
            let (_, model, _, _) = build::<f64>(&desc);
            let mut q = random_query(&mut rng, &desc, &model);
            if model.path(q.link).is_empty() {
                q.link = desc.joints.len();
            }
            if model.path(q.link).is_empty() {
                continue;
            }
            let a = rng.range(0.0, 1.0 - h);
            q.interval = [a, a + h];
            let seen = check::<f64>(&desc, &q, 128, &mut rng).expect("sound");
            if seen.sup_directed < 1e-9 {
                tiny += 1;
            } else {
                dir.push(seen.directed / seen.sup_directed);
                if model.path(q.link).len() == 1 {
                    single.push(seen.directed / seen.sup_directed);
                }
            }
            if seen.sup_undirected >= 1e-9 {
                und.push(seen.undirected / seen.sup_undirected);
            }
        }
        for (kind, v) in [
            ("directed", &mut dir),
            ("undirected", &mut und),
            ("directed, one movable joint", &mut single),
        ] {
            if v.is_empty() {
                continue;
            }
            v.sort_by(f64::total_cmp);
            let mean = v.iter().sum::<f64>() / v.len() as f64;
            let pick = |f: f64| v[((v.len() - 1) as f64 * f) as usize];
            println!(
                "| {name} | {kind} | {} | {:.3} | {:.3} | {:.3} | {:.3} | {} |",
                v.len(),
                pick(0.5),
                mean,
                pick(0.9),
                v[v.len() - 1],
                if kind == "directed" {
                    tiny.to_string()
                } else {
                    "-".into()
                }
            );
        }
    }
}
