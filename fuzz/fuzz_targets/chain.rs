//! Kinematic chains moving along joint-space segments (`motion_bound::chain`):
//! a fuzzed small tree of one to five joints (revolute, continuous,
//! prismatic, fixed; any parent before the child; random, axis-aligned,
//! zero, tiny, huge and NaN axes; random origins, some invalid; limits, some
//! reversed or NaN), links with small meshes (tetrahedra, flat and repeated
//! corner ones included, boxes) or none, a fuzzed base pose, one or two box
//! obstacles, fuzzed parameters and allowed pairs, and `q0`, `q1` (in range,
//! many turns, huge but accepted, NaN, infinite, beyond `MAX_INPUT`, wrong
//! lengths).
//!
//! * Every constructor and query returns `Ok` or exactly the documented
//!   typed error (the first bad coordinate of `q0`, then of `q1`), never a
//!   panic; an accepted axis is the given one normalised (to `1e-14`).
//! * **Speed** (`Chain::directed_speed_bound`): for points of the queried
//!   ball at times of the queried sub-interval, the exact velocity
//!   `p'(s) = sum_turning dq_j a_j x (p - o_j) + sum_sliding dq_j a_j` from
//!   this target's own forward kinematics satisfies `|p'.n| <= directed` and
//!   `|p'| <= undirected`.
//! * **Never late** (`ChainScene::check_segment`): 2,001 samples `t = i /
//!   2000` of the segment, placed by this target's own forward kinematics,
//!   every checked pair (each link with a mesh against each obstacle, and the
//!   link pairs `checks_pair` accepts) measured with exact triangle distances
//!   (`try_triangle_triangle`, brute force over the tiny meshes, behind
//!   conservative sphere and box culls). `Separated` with a touching sample
//!   (distance 0), a contact later than the first touching sample, or an
//!   iteration limit certifying a touching sample free, is a failure.
//!   (Contact is declared within `contact_distance`, so early is fine.)
//! * `check_path` of the two waypoints agrees with `check_segment`; the
//!   report's contact is a checked pair at a time in `[0, 1]` within the
//!   contact distance; the work counters add up; `clearance` is at most the
//!   sampled truth's distance.
//! * **The edge query** (`check_edge`, `edge_is_free`, `edges_are_free`, a
//!   reused `EdgeChecker`; see [`edges`]): the same scene with up to three
//!   fuzzed shape obstacles (primitives of zero, tiny and huge sizes,
//!   half-spaces of any normal, point clouds), a padding and a work budget;
//!   the same typed errors, one answer from every entry point, and never
//!   free (nor free until a later time) where one of 2,001 samples finds a
//!   checked pair touching or within the padding, the shapes measured as
//!   triangles inscribed in them; on that scene `check_segment` and
//!   `check_path` never late nor missed by the same samples, `clearance` at
//!   `q0` never above the sampled truth's distance (issue 63: every query
//!   takes shapes and point clouds).
//!
//! An axis whose squared length is subnormal (components below about
//! `1e-154`) was normalised off unit length (the `AXIS` failure, fixed in
//! `src/chain/model.rs`: axes are scaled by their largest component first).
//! The environment variable `CHAIN_FUZZ_SKIP_TINY_AXES` still gives such
//! axes as their direction instead.
//!
//! The oracle checks run when every coordinate is at most [`ORACLE_Q`]; the
//! others only check that the query answers. The input is raw bytes read as
//! bounded numbers (missing bytes read as zero).

#![no_main]

use libfuzzer_sys::fuzz_target;
use motion_bound::chain::{
    Chain, ChainBuilder, ChainError, ChainPair, ChainParams, ChainScene, EdgeOutcome, JointKind,
    JointSpec, Obstacle, SegmentOutcome, ShapeObstacle,
};
use motion_bound::{try_triangle_triangle, Convex, Float, InputError, Point3, Pose, TriMesh, Vec3};
use motion_bound_fuzz::Bytes;

/// Sampled intervals of the segment (2,001 samples).
const SAMPLES: usize = 2000;

/// The oracle checks run only when every coordinate is at most this in
/// magnitude: the oracle's own `q(t) = q0 + t (q1 - q0)` is then within
/// `2 u 128` of the exact value, so its angles (and the positions and
/// velocities they give) are exact to far better than [`ORACLE_REL`].
const ORACLE_Q: f64 = 64.0;

/// The oracle's own rounding, relative. The velocity is evaluated in `f64`
/// from this target's forward kinematics (products of up to five 3x3
/// matrices, Rodrigues' formula, a sum of at most five terms); each term
/// `dq_j a_j x (p - o_j)` is wrong by at most a few hundred `u` times
/// `|dq_j| (|p| + |o_j|)` (the operands' magnitudes, not the result's: `p`
/// and `o_j` are computed positions), and a sliding term by a few `u` of
/// `|dq_j|`. `1e-12` of that sum (about `4500 u`) covers it with a margin;
/// the bound under test is compared with the exact value less this
/// allowance, and nowhere else is anything relaxed.
const ORACLE_REL: f64 = 1e-12;

/// The sphere and box culls of the truth are widened by this (world units):
/// the oracle's placed points are within about `1e-13` of exact for the
/// coordinates this target builds (positions within a few hundred units),
/// so no pair that touches is ever culled.
const CULL_MARGIN: f64 = 1e-9;

type V3 = [f64; 3];
type M3 = [[f64; 3]; 3];

const I3: M3 = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];

fn add(a: V3, b: V3) -> V3 {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}

fn sub(a: V3, b: V3) -> V3 {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

fn scale(a: V3, s: f64) -> V3 {
    a.map(|x| x * s)
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

fn norm(a: V3) -> f64 {
    dot(a, a).sqrt()
}

fn mat_mul(a: &M3, b: &M3) -> M3 {
    let mut o = [[0.0; 3]; 3];
    for (i, row) in o.iter_mut().enumerate() {
        for (j, x) in row.iter_mut().enumerate() {
            *x = a[i][0] * b[0][j] + a[i][1] * b[1][j] + a[i][2] * b[2][j];
        }
    }
    o
}

fn mat_vec(a: &M3, v: V3) -> V3 {
    [dot(a[0], v), dot(a[1], v), dot(a[2], v)]
}

/// `v / |v|` computed on `v` scaled by its largest component first, so that
/// no square underflows or overflows; `None` for a zero or non-finite `v`.
fn unit(v: V3) -> Option<V3> {
    let m = v.iter().fold(0.0f64, |a, x| a.max(x.abs()));
    if !(m > 0.0 && m.is_finite()) {
        return None;
    }
    let s = v.map(|x| x / m);
    let l = norm(s);
    Some(s.map(|x| x / l))
}

/// The turn by `angle` about the unit `k`: `I + sin K + (1 - cos) K^2` with
/// `K` the cross-product matrix of `k`.
fn rodrigues(k: V3, angle: f64) -> M3 {
    let (s, c) = angle.sin_cos();
    let kx = [[0.0, -k[2], k[1]], [k[2], 0.0, -k[0]], [-k[1], k[0], 0.0]];
    let kk = mat_mul(&kx, &kx);
    let mut r = I3;
    for i in 0..3 {
        for j in 0..3 {
            r[i][j] += s * kx[i][j] + (1.0 - c) * kk[i][j];
        }
    }
    r
}

/// The rotation matrix of the normalised quaternion `(w, x, y, z)`, or the
/// identity when it is (nearly) zero.
fn quaternion_matrix(q: [f64; 4]) -> M3 {
    let l = (q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]).sqrt();
    if l < 1e-3 {
        return I3;
    }
    let [w, x, y, z] = q.map(|c| c / l);
    [
        [
            1.0 - 2.0 * (y * y + z * z),
            2.0 * (x * y - w * z),
            2.0 * (x * z + w * y),
        ],
        [
            2.0 * (x * y + w * z),
            1.0 - 2.0 * (x * x + z * z),
            2.0 * (y * z - w * x),
        ],
        [
            2.0 * (x * z - w * y),
            2.0 * (y * z + w * x),
            1.0 - 2.0 * (x * x + y * y),
        ],
    ]
}

/// A placement `p |-> r p + x` (this target's own, not the crate's `Pose`).
#[derive(Clone, Copy, Debug)]
struct Place {
    r: M3,
    x: V3,
}

impl Place {
    const IDENTITY: Self = Self { r: I3, x: [0.0; 3] };

    fn point(&self, p: V3) -> V3 {
        add(mat_vec(&self.r, p), self.x)
    }

    fn then(&self, o: &Place) -> Place {
        Place {
            r: mat_mul(&self.r, &o.r),
            x: self.point(o.x),
        }
    }

    fn pose(&self) -> Pose<f64> {
        Pose::new(self.r, Vec3::from_array(self.x))
    }
}

fn vector(b: &mut Bytes<'_>, half: f64) -> V3 {
    [
        b.range(-half, half),
        b.range(-half, half),
        b.range(-half, half),
    ]
}

/// A fuzzed rotation: the identity or a normalised quaternion's matrix.
fn rotation(b: &mut Bytes<'_>) -> M3 {
    if b.u8().is_multiple_of(2) {
        I3
    } else {
        quaternion_matrix([0; 4].map(|_| b.range(-1.0, 1.0)))
    }
}

/// A mesh as this target built it.
#[derive(Clone, Debug)]
struct Mesh {
    vertices: Vec<V3>,
    triangles: Vec<[u32; 3]>,
}

const TETRA: [[u32; 3]; 4] = [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]];

fn box_mesh(centre: V3, half: V3) -> Mesh {
    let vertices = (0..8)
        .map(|i| {
            [0, 1, 2].map(|k| {
                let s = if i >> k & 1 == 1 { 1.0 } else { -1.0 };
                centre[k] + s * half[k]
            })
        })
        .collect();
    // Corners by bits (x = 1, y = 2, z = 4); two outward triangles a face.
    let triangles = vec![
        [0, 2, 3],
        [0, 3, 1],
        [4, 5, 7],
        [4, 7, 6],
        [0, 1, 5],
        [0, 5, 4],
        [2, 6, 7],
        [2, 7, 3],
        [0, 4, 6],
        [0, 6, 2],
        [1, 3, 7],
        [1, 7, 5],
    ];
    Mesh {
        vertices,
        triangles,
    }
}

/// A link's mesh: none, a tetrahedron, a flat or pinched one, or a box.
fn link_mesh(b: &mut Bytes<'_>) -> Option<Mesh> {
    match b.u8() % 5 {
        0 => None,
        1 | 2 => Some(Mesh {
            vertices: (0..4).map(|_| vector(b, 0.3)).collect(),
            triangles: TETRA.to_vec(),
        }),
        3 => {
            // Degenerate: all corners in one plane, or a repeated corner.
            let mut v: Vec<V3> = (0..4).map(|_| vector(b, 0.3)).collect();
            if b.u8().is_multiple_of(2) {
                let z = v[0][2];
                for p in &mut v {
                    p[2] = z;
                }
            } else {
                v[3] = v[0];
            }
            Some(Mesh {
                vertices: v,
                triangles: TETRA.to_vec(),
            })
        }
        _ => {
            let c = vector(b, 0.2);
            let h = [0; 3].map(|_| b.range(0.01, 0.3));
            Some(box_mesh(c, h))
        }
    }
}

/// Whether a fuzzed axis must be refused, may be (tiny or huge: its squared
/// length may underflow or overflow), or must be accepted.
#[derive(Clone, Copy, Debug, PartialEq)]
enum AxisClass {
    Good,
    Either,
    Bad,
}

fn axis(b: &mut Bytes<'_>) -> (V3, AxisClass) {
    match b.u8() % 10 {
        0..=3 => (vector(b, 1.0), AxisClass::Good),
        4 | 5 => {
            let mut a = [0.0; 3];
            a[usize::from(b.u8() % 3)] = if b.u8().is_multiple_of(2) { 1.0 } else { -1.0 };
            (a, AxisClass::Good)
        }
        6 => ([0.0; 3], AxisClass::Bad),
        7 => {
            let mut a = vector(b, 1.0);
            a[usize::from(b.u8() % 3)] =
                [f64::NAN, f64::INFINITY, f64::NEG_INFINITY][usize::from(b.u8() % 3)];
            (a, AxisClass::Bad)
        }
        8 => {
            // Tiny: 2^-450 to 2^-1000, near and below where |a|^2 underflows.
            let e = -450 - i32::from(b.u8()) * 2;
            (scale(vector(b, 1.0), 2f64.powi(e)), AxisClass::Either)
        }
        _ => {
            // Huge: 2^400 to 2^910 (|a|^2 overflows above about 2^511).
            let e = 400 + i32::from(b.u8()) * 2;
            (scale(vector(b, 1.0), 2f64.powi(e)), AxisClass::Either)
        }
    }
}

/// A joint origin: its pose, and whether it is valid.
fn origin(b: &mut Bytes<'_>) -> (Place, bool) {
    let x = vector(b, 0.5);
    let r = rotation(b);
    let place = Place { r, x };
    match b.u8() % 16 {
        0 => (
            Place {
                x: [f64::NAN, 0.0, 0.0],
                ..place
            },
            false,
        ),
        1 => {
            let mut r = r;
            r[1][1] = 3.0; // not a rotation: an entry beyond 2
            (Place { r, x }, false)
        }
        2 => (
            Place {
                x: [0.0, 2f64.powi(508), 0.0],
                ..place
            },
            false,
        ),
        _ => (place, true),
    }
}

/// Limits, and whether they are valid.
fn limits(b: &mut Bytes<'_>) -> (Option<[f64; 2]>, bool) {
    let (lo, hi) = (b.range(-3.0, 0.0), b.range(0.0, 3.0));
    match b.u8() % 8 {
        0 | 1 => (None, true),
        2 => (Some([hi + 0.5, lo]), false),
        3 => (Some([f64::NAN, hi]), false),
        _ => (Some([lo, hi]), true),
    }
}

const KINDS: [JointKind; 4] = [
    JointKind::Revolute,
    JointKind::Continuous,
    JointKind::Prismatic,
    JointKind::Fixed,
];

/// A joint as the oracle sees it.
#[derive(Clone, Debug)]
struct JointModel {
    parent: usize,
    child: usize,
    kind: JointKind,
    /// Unit axis (this target's normalisation of the given one).
    axis: V3,
    origin: Place,
    dof: Option<usize>,
}

/// The chain as the oracle sees it (joint `i`'s child is link `i + 1`, its
/// parent an earlier link).
#[derive(Clone, Debug)]
struct Model {
    base: Place,
    joints: Vec<JointModel>,
    meshes: Vec<Option<Mesh>>,
}

impl Model {
    /// Every link's placement and every joint's world axis and origin.
    fn fk(&self, q: &[f64]) -> (Vec<Place>, Vec<(V3, V3)>) {
        let mut poses = vec![Place::IDENTITY; self.meshes.len()];
        let mut frames = vec![([0.0; 3], [0.0; 3]); self.joints.len()];
        poses[0] = self.base;
        for (j, jm) in self.joints.iter().enumerate() {
            let frame = poses[jm.parent].then(&jm.origin);
            let a = mat_vec(&frame.r, jm.axis);
            frames[j] = (a, frame.x);
            poses[jm.child] = match (jm.kind, jm.dof) {
                (JointKind::Revolute | JointKind::Continuous, Some(d)) => frame.then(&Place {
                    r: rodrigues(jm.axis, q[d]),
                    x: [0.0; 3],
                }),
                (JointKind::Prismatic, Some(d)) => Place {
                    r: frame.r,
                    x: add(frame.x, scale(a, q[d])),
                },
                _ => frame,
            };
        }
        (poses, frames)
    }

    /// The joints from the root to `link` (link `l > 0` hangs from joint `l - 1`).
    fn path(&self, link: usize) -> Vec<usize> {
        let mut path = Vec::new();
        let mut at = link;
        while at > 0 {
            path.push(at - 1);
            at = self.joints[at - 1].parent;
        }
        path.reverse();
        path
    }

    /// `q0 + t (q1 - q0)`, as the crate evaluates it.
    fn at(q0: &[f64], q1: &[f64], t: f64) -> Vec<f64> {
        q0.iter().zip(q1).map(|(a, b)| a + t * (b - a)).collect()
    }
}

/// A mesh's triangles in its own frame (or the world's) with a sphere
/// around them (centre, radius).
type Bounded = (Vec<[V3; 3]>, V3, f64);

/// Placed triangles, each with its box.
type Placed = Vec<([V3; 3], (V3, V3))>;

/// What the truth measures: the meshes' triangles and bounding spheres in
/// their own frames, the obstacles' in the world, and the checked pairs.
#[derive(Clone)]
struct Truth {
    link_tris: Vec<Option<Bounded>>,
    obstacles: Vec<Bounded>,
    pairs: Vec<ChainPair>,
}

fn triangles_of(m: &Mesh) -> Vec<[V3; 3]> {
    m.triangles
        .iter()
        .map(|t| t.map(|i| m.vertices[i as usize]))
        .collect()
}

/// A sphere around every vertex (the mean, the largest distance, rounded up).
fn sphere(tris: &[[V3; 3]]) -> (V3, f64) {
    let n = (tris.len() * 3) as f64;
    let c = tris
        .iter()
        .flatten()
        .fold([0.0; 3], |a, p| add(a, scale(*p, 1.0 / n)));
    let r = tris
        .iter()
        .flatten()
        .map(|p| norm(sub(*p, c)))
        .fold(0.0f64, f64::max);
    (c, r * (1.0 + 1e-12) + 1e-300)
}

fn aabb(t: &[V3; 3]) -> (V3, V3) {
    let lo = [0, 1, 2].map(|k| t[0][k].min(t[1][k]).min(t[2][k]));
    let hi = [0, 1, 2].map(|k| t[0][k].max(t[1][k]).max(t[2][k]));
    (lo, hi)
}

/// A lower bound of the distance of two boxes.
fn aabb_gap(a: &(V3, V3), b: &(V3, V3)) -> f64 {
    (0..3)
        .map(|k| (b.0[k] - a.1[k]).max(a.0[k] - b.1[k]))
        .fold(0.0f64, f64::max)
}

impl Truth {
    /// The smallest exact triangle distance over the checked pairs at `q`
    /// below `cutoff` (pairs and triangle pairs certainly at least `cutoff`
    /// apart are skipped; `cutoff` when none is nearer), with its pair;
    /// stops at the first distance 0.
    fn min_distance(&self, model: &Model, q: &[f64], cutoff: f64) -> (f64, Option<ChainPair>) {
        let (poses, _) = model.fk(q);
        let mut placed: Vec<Option<Placed>> = vec![None; poses.len()];
        let place = |l: usize, placed: &mut Vec<Option<Placed>>| {
            if placed[l].is_none() {
                let tris = &self.link_tris[l].as_ref().expect("a link with a mesh").0;
                placed[l] = Some(
                    tris.iter()
                        .map(|t| {
                            let p = t.map(|v| poses[l].point(v));
                            (p, aabb(&p))
                        })
                        .collect(),
                );
            }
        };
        let obstacle_tris: Vec<Placed> = self
            .obstacles
            .iter()
            .map(|(t, _, _)| t.iter().map(|t| (*t, aabb(t))).collect())
            .collect();
        let mut best = (cutoff, None);
        for &pair in &self.pairs {
            let (ca, ra, cb, rb) = match pair {
                ChainPair::Obstacle { link, obstacle } => {
                    let (_, c, r) = self.link_tris[link].as_ref().expect("mesh");
                    let (_, co, ro) = &self.obstacles[obstacle];
                    (poses[link].point(*c), *r, *co, *ro)
                }
                ChainPair::SelfCollision { a, b } => {
                    let (_, c, r) = self.link_tris[a].as_ref().expect("mesh");
                    let (_, d, s) = self.link_tris[b].as_ref().expect("mesh");
                    (poses[a].point(*c), *r, poses[b].point(*d), *s)
                }
                _ => unreachable!("the truth measures shapes as obstacles"),
            };
            if norm(sub(cb, ca)) - ra - rb - CULL_MARGIN >= best.0 {
                continue;
            }
            let (la, lb) = match pair {
                ChainPair::Obstacle { link, .. } => (link, None),
                ChainPair::SelfCollision { a, b } => (a, Some(b)),
                _ => unreachable!("the truth measures shapes as obstacles"),
            };
            place(la, &mut placed);
            if let Some(lb) = lb {
                place(lb, &mut placed);
            }
            let ta = placed[la].as_ref().expect("placed");
            let tb = match (pair, lb) {
                (ChainPair::Obstacle { obstacle, .. }, _) => &obstacle_tris[obstacle],
                (_, Some(lb)) => placed[lb].as_ref().expect("placed"),
                _ => unreachable!("a self pair has two links"),
            };
            for (pa, ba) in ta {
                for (pb, bb) in tb {
                    if aabb_gap(ba, bb) - CULL_MARGIN >= best.0 {
                        continue;
                    }
                    let d = try_triangle_triangle(
                        &pa.map(Point3::from_array),
                        &pb.map(Point3::from_array),
                    )
                    .expect("finite placed corners")
                    .distance;
                    if d < best.0 {
                        best = (d, Some(pair));
                        if d == 0.0 {
                            return best;
                        }
                    }
                }
            }
        }
        best
    }
}

/// Whether `CHAIN_FUZZ_SKIP_TINY_AXES` is set: then axes whose squared
/// length is subnormal are not given as such (see the module docs).
fn skip_tiny_axes() -> bool {
    static SKIP: std::sync::OnceLock<bool> = std::sync::OnceLock::new();
    *SKIP.get_or_init(|| std::env::var_os("CHAIN_FUZZ_SKIP_TINY_AXES").is_some())
}

/// What a query must answer for `q0`, `q1`: the first bad vector's error.
fn expected_error(dof: usize, qs: &[&[f64]]) -> Option<ChainError> {
    for q in qs {
        if q.len() != dof {
            return Some(ChainError::WrongDof {
                expected: dof,
                got: q.len(),
            });
        }
        if let Some(i) = q
            .iter()
            .position(|x| !x.is_finite() || x.abs() > <f64 as Float>::MAX_INPUT)
        {
            return Some(ChainError::NonFiniteCoordinate(i));
        }
    }
    None
}

/// Joint coordinates: turns within `[-4, 4]` (or `[-60, 60]`, many turns,
/// when `wide`), slides within `[-0.6, 0.6]`.
fn coords(b: &mut Bytes<'_>, kinds: &[JointKind], wide: bool) -> Vec<f64> {
    kinds
        .iter()
        .map(|k| match (k.is_rotational(), wide) {
            (true, false) => b.range(-4.0, 4.0),
            (true, true) => b.range(-60.0, 60.0),
            (false, _) => b.range(-0.6, 0.6),
        })
        .collect()
}

/// `q0` and `q1`, some of them invalid or out of the oracle's range.
fn segment(b: &mut Bytes<'_>, kinds: &[JointKind]) -> (Vec<f64>, Vec<f64>) {
    let dof = kinds.len();
    let mode = b.u8() % 20;
    let wide = mode == 7;
    let mut q0 = coords(b, kinds, wide);
    let mut q1 = coords(b, kinds, wide);
    let pick = usize::from(b.u8());
    let which = b.u8();
    match mode {
        0 => q1.push(0.5),
        1 => {
            if dof > 0 {
                q0.pop();
            } else {
                q0.push(0.0);
            }
        }
        2 if dof > 0 => {
            let bad = [
                f64::NAN,
                f64::INFINITY,
                f64::NEG_INFINITY,
                2f64.powi(508),
                -f64::MAX,
                <f64 as Float>::MAX_INPUT.next_up(),
            ][usize::from(which) % 6];
            let q = if pick.is_multiple_of(2) {
                &mut q0
            } else {
                &mut q1
            };
            q[pick % dof] = bad;
        }
        3 if dof > 0 => {
            // Huge but accepted: the query must answer (no oracle).
            let big = [
                <f64 as Float>::MAX_INPUT,
                -<f64 as Float>::MAX_INPUT,
                1e100,
                1e20,
                1e6,
            ][usize::from(which) % 5];
            let q = if pick.is_multiple_of(2) {
                &mut q0
            } else {
                &mut q1
            };
            q[pick % dof] = big;
        }
        4 if dof > 0 => q1[pick % dof] = q0[pick % dof] + 300.0,
        5 => q1.clone_from(&q0),
        6 if dof > 0 => {
            let keep = pick % dof;
            for (i, x) in q1.iter_mut().enumerate() {
                if i != keep {
                    *x = q0[i];
                }
            }
        }
        _ => {}
    }
    (q0, q1)
}

fn run(data: &[u8]) {
    let mut b = Bytes::new(data);
    let joints = 1 + usize::from(b.u8() % 5);
    let links = joints + 1;
    let meshes: Vec<Option<Mesh>> = (0..links).map(|_| link_mesh(&mut b)).collect();
    let mut builder = ChainBuilder::<f64>::new();
    for (l, m) in meshes.iter().enumerate() {
        let mesh = m.as_ref().map(|m| {
            TriMesh::try_new(m.vertices.clone(), m.triangles.clone())
                .expect("finite vertices and indices in range")
        });
        assert_eq!(
            builder.add_link(format!("link{l}"), mesh),
            Ok(l),
            "links are numbered in order"
        );
    }
    assert_eq!(
        builder.add_link("link0", None),
        Err(ChainError::DuplicateName("link0".into())),
        "a repeated link name"
    );

    // Joints: joint i hangs link i + 1 from an earlier link.
    let mut model_joints = Vec::with_capacity(joints);
    let mut kinds = Vec::new();
    for i in 0..joints {
        let parent = usize::from(b.u8()) % (i + 1);
        let child = i + 1;
        let kind = KINDS[usize::from(b.u8() % 4)];
        let (given_axis, class) = axis(&mut b);
        // The known issue's switch: an axis whose squared length is below
        // the normal range is given as its direction instead.
        let given_axis = if skip_tiny_axes() && dot(given_axis, given_axis) < f64::MIN_POSITIVE {
            unit(given_axis).unwrap_or(given_axis)
        } else {
            given_axis
        };
        let (origin, origin_ok) = origin(&mut b);
        let (lim, limits_ok) = limits(&mut b);
        let spec = JointSpec {
            name: format!("joint{i}"),
            kind,
            parent,
            child,
            origin: origin.pose(),
            axis: given_axis,
            limits: lim,
        };
        let must_refuse_joint = (kind.is_movable() && class == AxisClass::Bad) || !origin_ok;
        let may_refuse_joint =
            must_refuse_joint || (kind.is_movable() && class == AxisClass::Either);
        let result = builder.add_joint(spec.clone());
        let accepted = match &result {
            Ok(j) => {
                assert_eq!(*j, i, "joints are numbered in order");
                assert!(
                    !must_refuse_joint && limits_ok,
                    "ACCEPTED a bad joint: {spec:?}"
                );
                true
            }
            Err(ChainError::BadJoint(n)) => {
                assert!(
                    may_refuse_joint && *n == spec.name,
                    "REFUSED a good joint (BadJoint): {spec:?} {result:?}"
                );
                false
            }
            Err(ChainError::BadLimits(n)) => {
                assert!(
                    !must_refuse_joint && !limits_ok && *n == spec.name,
                    "BadLimits for {spec:?}"
                );
                false
            }
            Err(e) => panic!("UNEXPECTED ERROR {e:?} for {spec:?}"),
        };
        let spec = if accepted {
            spec
        } else {
            // The same joint made valid.
            let spec = JointSpec {
                origin: Pose::IDENTITY,
                axis: [0.0, 0.0, 1.0],
                limits: None,
                ..spec
            };
            assert_eq!(builder.add_joint(spec.clone()), Ok(i), "a valid joint");
            spec
        };
        let unit_axis = if kind.is_movable() {
            unit(spec.axis).expect("an accepted axis has a direction")
        } else {
            [0.0, 0.0, 1.0]
        };
        let dof = kind.is_movable().then_some(kinds.len());
        if kind.is_movable() {
            kinds.push(kind);
        }
        model_joints.push(JointModel {
            parent,
            child,
            kind,
            axis: unit_axis,
            origin: Place {
                r: spec.origin.rotation,
                x: spec.origin.translation.to_array(),
            },
            dof,
        });
    }
    let dof = kinds.len();
    assert!(
        matches!(
            builder.add_joint(JointSpec {
                name: "dangling".into(),
                kind: JointKind::Fixed,
                parent: 0,
                child: links,
                origin: Pose::IDENTITY,
                axis: [0.0, 0.0, 1.0],
                limits: None,
            }),
            Err(ChainError::NoSuchLink(l)) if l == links
        ),
        "a joint to a link that does not exist"
    );
    {
        // Link 1 hung from a second joint; a link hung from nothing.
        let mut two = builder.clone();
        two.add_joint(JointSpec {
            name: "second".into(),
            kind: JointKind::Fixed,
            parent: 0,
            child: 1,
            origin: Pose::IDENTITY,
            axis: [0.0, 0.0, 1.0],
            limits: None,
        })
        .expect("a valid joint");
        assert_eq!(
            two.build().err(),
            Some(ChainError::TwoParents("link1".into())),
            "two parents"
        );
        let mut loose = builder.clone();
        loose.add_link("loose", None).expect("a new name");
        assert_eq!(loose.build().err(), Some(ChainError::NotATree), "two roots");
    }
    let base = if b.u8().is_multiple_of(2) {
        Place::IDENTITY
    } else {
        Place {
            r: rotation(&mut b),
            x: vector(&mut b, 1.0),
        }
    };
    let chain: Chain<f64> = builder
        .build()
        .expect("a tree of valid joints and meshes")
        .with_base(base.pose());
    assert_eq!(chain.dof(), dof, "one coordinate per movable joint");
    assert_eq!(chain.coordinate_kinds(), kinds, "coordinate kinds");
    for (j, jm) in model_joints.iter().enumerate() {
        assert_eq!(chain.joint_coordinate(j), jm.dof, "joint {j}'s coordinate");
        if jm.kind.is_movable() {
            let a = chain.joint_axis(j).expect("a joint").to_array();
            let off = sub(a, jm.axis).iter().fold(0.0f64, |m, x| m.max(x.abs()));
            assert!(
                off <= 1e-14,
                "AXIS: joint {j}'s axis {:?} normalised to {a:?}, not {:?} ({off:e} off)",
                chain.joints().nth(j).map(|s| s.axis),
                jm.axis
            );
        }
    }
    let model = Model {
        base,
        joints: model_joints,
        meshes,
    };

    // The scene.
    let mut scene = ChainScene::new(chain);
    let obstacles = 1 + usize::from(b.u8() % 2);
    let mut obstacle_truth = Vec::new();
    for o in 0..obstacles {
        let half = [0; 3].map(|_| b.range(0.02, 0.4));
        let place = Place {
            r: rotation(&mut b),
            x: vector(&mut b, 1.5),
        };
        let mesh = box_mesh([0.0; 3], half);
        let tri = TriMesh::try_new(mesh.vertices.clone(), mesh.triangles.clone()).expect("a box");
        if o == 0 {
            let bad = Pose::from_translation(Vec3::new(f64::NAN, 0.0, 0.0));
            assert!(
                matches!(
                    Obstacle::try_new("bad", tri.clone(), bad),
                    Err(ChainError::InvalidParameter(_))
                ),
                "a NaN obstacle pose"
            );
        }
        let obstacle = Obstacle::try_new(format!("box{o}"), tri, place.pose()).expect("a box");
        assert_eq!(scene.add_obstacle(obstacle), o, "obstacles in order");
        let world: Vec<[V3; 3]> = triangles_of(&mesh)
            .iter()
            .map(|t| t.map(|v| place.point(v)))
            .collect();
        let (c, r) = sphere(&world);
        obstacle_truth.push((world, c, r));
    }

    // Parameters, valid and not.
    // Segments anywhere in joint space: the limit check
    // (`ChainError::BeyondLimits`) is `tests/chain.rs`'s.
    let mut params = ChainParams::default().with_within_limits(false);
    params.contact_distance = [1e-3, 1e-6, 1e-2, 1e-3][usize::from(b.u8() % 4)];
    params.broad_pieces = [8, 1, 3, 8][usize::from(b.u8() % 4)];
    params.max_iterations = [10_000, 10_000, 10_000, 40][usize::from(b.u8() % 4)];
    let mut bads = [params; 5];
    bads[0].contact_distance = 0.0;
    bads[1].contact_distance = f64::NAN;
    bads[2].broad_pieces = 0;
    bads[3].broad_pieces = 1025;
    bads[4].max_iterations = 0;
    for bad in bads {
        assert!(
            matches!(scene.set_params(bad), Err(ChainError::InvalidParameter(_))),
            "invalid parameters {bad:?}"
        );
    }
    scene.set_params(params).expect("valid parameters");
    assert_eq!(scene.params(), params, "the parameters set");

    // Allowed pairs.
    match b.u8() % 4 {
        0 => {
            let (a, c) = (usize::from(b.u8()) % links, usize::from(b.u8()) % links);
            scene.allow_collision(a, c);
            assert!(!scene.checks_pair(a, c), "an allowed pair is not checked");
        }
        1 => {
            let q = coords(&mut b, &kinds, false);
            let d = b.range(0.0, 0.05);
            assert!(
                matches!(
                    scene.allow_collisions_at(&q, -1.0),
                    Err(ChainError::InvalidParameter(_))
                ),
                "a negative distance"
            );
            let allowed = scene.allow_collisions_at(&q, d).expect("a valid query");
            for (a, c) in allowed {
                assert!(!scene.checks_pair(a, c), "an allowed pair is not checked");
            }
        }
        _ => {}
    }

    // The checked pairs, as the truth measures them.
    let with_mesh: Vec<usize> = (0..links).filter(|&l| model.meshes[l].is_some()).collect();
    let mut pairs = Vec::new();
    let mut all_pairs = 0;
    for &l in &with_mesh {
        for o in 0..obstacles {
            pairs.push(ChainPair::Obstacle {
                link: l,
                obstacle: o,
            });
            all_pairs += 1;
        }
        for &m in with_mesh.iter().filter(|&&m| m > l) {
            all_pairs += 1;
            if scene.checks_pair(l, m) {
                pairs.push(ChainPair::SelfCollision { a: l, b: m });
            }
        }
    }
    let truth = Truth {
        link_tris: model
            .meshes
            .iter()
            .map(|m| {
                m.as_ref().map(|m| {
                    let t = triangles_of(m);
                    let (c, r) = sphere(&t);
                    (t, c, r)
                })
            })
            .collect(),
        obstacles: obstacle_truth,
        pairs,
    };

    // The segment.
    let (q0, q1) = segment(&mut b, &kinds);
    let expected = expected_error(dof, &[&q0, &q1]);
    let oracle = q0.iter().chain(&q1).all(|x| x.abs() <= ORACLE_Q);
    if !oracle {
        // Huge coordinates (no oracle) make every step tiny: fewer
        // iterations keep such inputs quick.
        let mut fewer = params;
        fewer.max_iterations = fewer.max_iterations.min(200);
        scene.set_params(fewer).expect("valid parameters");
    }
    let expected0 = expected_error(dof, &[&q0]);
    let chain = scene.chain();
    assert_eq!(
        chain.try_forward_kinematics(&q0).err(),
        expected0,
        "forward kinematics' error for {q0:?}"
    );
    assert_eq!(
        scene.collides_at(&q0).err(),
        expected0,
        "collides_at's error for {q0:?}"
    );
    let clearance = scene.clearance(&q0);
    assert_eq!(
        clearance.as_ref().err(),
        expected0.as_ref(),
        "clearance's error for {q0:?}"
    );
    let report = scene.check_segment(&q0, &q1);
    assert_eq!(
        report.as_ref().err(),
        expected.as_ref(),
        "check_segment's error for {q0:?} -> {q1:?}"
    );
    let path = scene.check_path(&[q0.clone(), q1.clone()]);
    assert_eq!(
        path.as_ref().err(),
        expected.as_ref(),
        "check_path's error for {q0:?} -> {q1:?}"
    );
    assert!(
        matches!(
            scene.check_path(std::slice::from_ref(&q0)),
            Err(ChainError::InvalidParameter(_))
        ),
        "a path of one waypoint"
    );
    assert_eq!(
        chain
            .directed_speed_bound(&q0, &q1, links, [0.0; 3], 0.0, [1.0, 0.0, 0.0], [0.0, 1.0])
            .err(),
        Some(expected.clone().unwrap_or(ChainError::NoSuchLink(links))),
        "directed_speed_bound with a link that does not exist"
    );

    // The speed bound (read before the early return, so that inputs keep
    // their meaning whatever the segment).
    let mut speed_queries = Vec::new();
    for _ in 0..3 {
        let link = usize::from(b.u8()) % links;
        let centre = vector(&mut b, 0.5);
        let radius = if b.u8().is_multiple_of(4) {
            0.0
        } else {
            b.range(0.0, 0.3)
        };
        let (n, n_ok) = match b.u8() % 16 {
            0 => ([0.0; 3], false),
            1 => ([f64::NAN, 1.0, 0.0], false),
            2 => ([0.0, 0.0, 1.0], true),
            _ => (vector(&mut b, 1.0), true),
        };
        let (f0, f1) = (b.range(0.0, 1.0), b.range(0.0, 1.0));
        let (interval, interval_ok) = match b.u8() % 16 {
            0 => ([f0.max(f1), f0.min(f1) - 0.01], false),
            1 => ([0.0, 1.0], true),
            2 => ([f0, f0], true),
            _ => ([f0.min(f1), f0.max(f1)], true),
        };
        let dirs: Vec<V3> = (0..3).map(|_| vector(&mut b, 1.0)).collect();
        speed_queries.push((link, centre, radius, n, n_ok, interval, interval_ok, dirs));
    }

    'segment: {
        let (Ok(report), Ok(path), Ok(clearance)) = (report, path, clearance) else {
            break 'segment;
        };
        assert_eq!(path.segment, 0, "one segment");
        assert_eq!(
            path.outcome, report.outcome,
            "check_path and check_segment disagree"
        );
        let stats = report.stats;
        assert_eq!(stats.pairs, all_pairs, "pairs counted: {stats:?}");
        assert_eq!(
            stats.pairs,
            stats.excluded + stats.culled + stats.advanced,
            "every pair excluded, culled or advanced: {stats:?}"
        );
        let cd = params.contact_distance;
        let limit = match report.outcome {
            SegmentOutcome::Contact(c) => {
                assert!(
                    (0.0..=1.0).contains(&c.time),
                    "a contact time outside [0, 1]: {report:?}"
                );
                assert!(
                    c.distance <= cd,
                    "a contact farther than the contact distance: {report:?}"
                );
                assert!(
                    truth.pairs.contains(&c.pair),
                    "a contact of a pair not checked: {report:?}"
                );
                c.time
            }
            SegmentOutcome::IterationLimit { time, pair } => {
                assert!(
                    (0.0..=1.0).contains(&time) && truth.pairs.contains(&pair),
                    "an iteration limit outside [0, 1] or of a pair not checked: {report:?}"
                );
                time
            }
            SegmentOutcome::Separated => f64::INFINITY,
            other => panic!("an unknown outcome {other:?}"),
        };

        if !oracle {
            break 'segment;
        }

        // (a) The speed bound against the exact velocity.
        for (link, centre, radius, n, n_ok, interval, interval_ok, dirs) in speed_queries {
            let bound = chain.directed_speed_bound(&q0, &q1, link, centre, radius, n, interval);
            if !n_ok || !interval_ok {
                assert!(
                    matches!(bound, Err(ChainError::InvalidParameter(_))),
                    "directed_speed_bound with n {n:?}, interval {interval:?}: {bound:?}"
                );
                continue;
            }
            let (directed, undirected) = bound.expect("a valid query");
            assert!(
                directed >= 0.0 && undirected >= 0.0,
                "a negative or NaN bound ({directed}, {undirected})"
            );
            let nu = unit(n).expect("a nonzero n");
            let path = model.path(link);
            let mut points = vec![centre];
            for k in 0..3 {
                for s in [-1.0, 1.0] {
                    let mut p = centre;
                    p[k] += s * radius;
                    points.push(p);
                }
            }
            for d in &dirs {
                if let Some(u) = unit(*d) {
                    points.push(add(centre, scale(u, radius * norm(*d).min(1.0))));
                }
            }
            for k in 0..=8 {
                let s = (interval[0] + (interval[1] - interval[0]) * f64::from(k) / 8.0)
                    .min(interval[1]);
                let q = Model::at(&q0, &q1, s);
                let (poses, frames) = model.fk(&q);
                for &c in &points {
                    let p = poses[link].point(c);
                    let mut v = [0.0; 3];
                    let mut magnitude = 0.0;
                    for &j in &path {
                        let jm = &model.joints[j];
                        let Some(d) = jm.dof else { continue };
                        let dq = q1[d] - q0[d];
                        let (a, o) = frames[j];
                        if jm.kind.is_rotational() {
                            v = add(v, scale(cross(a, sub(p, o)), dq));
                            magnitude += dq.abs() * (norm(p) + norm(o));
                        } else {
                            v = add(v, scale(a, dq));
                            magnitude += dq.abs();
                        }
                    }
                    let allowance = ORACLE_REL * magnitude;
                    let along = dot(v, nu).abs();
                    assert!(
                    along - allowance <= directed,
                    "DIRECTED SPEED: |p'.n| = {along:e} > bound {directed:e} (allowance {allowance:e}) \
                     for link {link}, point {c:?} (radius {radius} about {centre:?}), n {n:?}, \
                     s = {s}, interval {interval:?}, q0 {q0:?}, q1 {q1:?}"
                );
                    let speed = norm(v);
                    assert!(
                    speed - allowance <= undirected,
                    "SPEED: |p'| = {speed:e} > bound {undirected:e} (allowance {allowance:e}) \
                     for link {link}, point {c:?}, s = {s}, interval {interval:?}, q0 {q0:?}, q1 {q1:?}"
                );
                }
            }
        }

        // clearance: a lower bound of the distance at q0.
        let (crate_clearance, crate_pair) = clearance;
        let (exact, _) = truth.min_distance(&model, &q0, f64::INFINITY);
        if truth.pairs.is_empty() {
            assert!(
                crate_clearance == f64::INFINITY && crate_pair.is_none(),
                "clearance with nothing checked: {clearance:?}"
            );
        } else {
            assert!(
                crate_clearance <= exact + 1e-9,
                "CLEARANCE {crate_clearance:e} above the distance {exact:e} at q0 {q0:?}"
            );
            assert!(
                crate_pair.is_none_or(|p| truth.pairs.contains(&p)),
                "clearance names a pair not checked: {clearance:?}"
            );
        }

        // (b) Never late: the first touching sample before the reported time.
        for i in 0..=SAMPLES {
            let t = i as f64 / SAMPLES as f64;
            if t >= limit {
                break;
            }
            let q = Model::at(&q0, &q1, t);
            let (d, pair) = truth.min_distance(&model, &q, f64::MIN_POSITIVE);
            if d == 0.0 {
                let what = match report.outcome {
                    SegmentOutcome::Separated => "MISSED: Separated",
                    SegmentOutcome::Contact(_) => "LATE: a contact",
                    _ => "LATE: an iteration limit",
                };
                panic!(
                    "{what}, but {pair:?} touches at t = {t} (sample {i}): {report:?}; \
                 q0 {q0:?}, q1 {q1:?}, q(t) {q:?}"
                );
            }
        }
    }

    // (c) The edge query, with shape obstacles.
    edges(&mut b, &scene, &model, &truth, &q0, &q1, expected, oracle);
}

/// A surface of revolution about the body's `y` axis through the profile's
/// points `(rho, y)` (first and last with `rho = 0`: the poles), `SIDES`
/// points a ring, pulled towards the body origin by `1e-12` of themselves:
/// every vertex on or inside a convex solid about the origin whose surface
/// the profile follows, so every triangle is inside it.
fn lathe(profile: &[(f64, f64)]) -> Vec<[V3; 3]> {
    const SIDES: u32 = 8;
    let shrink = 1.0 - 1e-12;
    let ring = |(rho, y): (f64, f64)| -> Vec<V3> {
        (0..SIDES)
            .map(|k| {
                let phi = f64::from(k) * std::f64::consts::TAU / f64::from(SIDES);
                [
                    rho * phi.cos() * shrink,
                    y * shrink,
                    rho * phi.sin() * shrink,
                ]
            })
            .collect()
    };
    let rings: Vec<Vec<V3>> = profile.iter().map(|&p| ring(p)).collect();
    let mut out = Vec::new();
    let n = SIDES as usize;
    for w in rings.windows(2) {
        for k in 0..n {
            let (a, b) = (w[0][k], w[0][(k + 1) % n]);
            let (c, d) = (w[1][k], w[1][(k + 1) % n]);
            out.push([a, b, d]);
            out.push([a, d, c]);
        }
    }
    out
}

/// The capsule of the segment `|y| <= h` and radius `r` (a ball for
/// `h = 0`), inscribed.
fn capsule_tris(h: f64, r: f64) -> Vec<[V3; 3]> {
    let mut profile = vec![(0.0, -h - r)];
    for i in 1..=3 {
        let a = f64::from(i) / 3.0 * std::f64::consts::FRAC_PI_2;
        profile.push((r * a.sin(), -h - r * a.cos()));
    }
    for i in (0..3).rev() {
        let a = f64::from(i) / 3.0 * std::f64::consts::FRAC_PI_2;
        profile.push((r * a.sin(), h + r * a.cos()));
    }
    lathe(&profile)
}

/// A small tetrahedron inside the ball of radius `r` about `p`.
fn tetra_in_ball(p: V3, r: f64) -> Vec<[V3; 3]> {
    let s = r * (1.0 - 1e-9) / 3f64.sqrt();
    let c = [
        [1.0, 1.0, 1.0],
        [1.0, -1.0, -1.0],
        [-1.0, 1.0, -1.0],
        [-1.0, -1.0, 1.0],
    ]
    .map(|c: V3| add(p, scale(c, s)));
    TETRA.iter().map(|t| t.map(|i| c[i as usize])).collect()
}

/// A rotation whose third column is the unit `m`.
fn frame_with_z(m: V3) -> M3 {
    let a = if m[0].abs() < 0.9 {
        [1.0, 0.0, 0.0]
    } else {
        [0.0, 1.0, 0.0]
    };
    let u = unit(cross(a, m)).expect("a unit normal has a perpendicular");
    let w = cross(m, u);
    [0, 1, 2].map(|i| [u[i], w[i], m[i]])
}

/// A radius or extent: zero, tiny, ordinary or huge.
fn length(b: &mut Bytes<'_>) -> f64 {
    match b.u8() % 8 {
        0 => 0.0,
        1 => 1e-12,
        2 => 1e-6,
        3 => 5.0,
        _ => b.range(0.001, 0.4),
    }
}

/// A fuzzed shape obstacle: the shape (or `None` when the input is refused,
/// after checking the refusal is the documented error) and its inscribed
/// triangles in the world (a touch of them is a touch of the shape).
fn shape_obstacle(b: &mut Bytes<'_>) -> Option<(ShapeObstacle<f64>, Vec<[V3; 3]>)> {
    let place = Place {
        r: rotation(b),
        x: vector(b, 1.5),
    };
    let bad_pose = b.u8().is_multiple_of(16);
    let kind = b.u8() % 8;
    let rounded = if b.u8().is_multiple_of(4) {
        length(b)
    } else {
        0.0
    };
    let (shape, local): (Convex<'static, f64>, Vec<[V3; 3]>) = match kind {
        0 | 1 => {
            let h = [length(b), length(b), length(b)];
            let m = box_mesh([0.0; 3], h);
            (Convex::try_cuboid(h).expect("a cuboid"), triangles_of(&m))
        }
        2 => {
            let r = length(b);
            (Convex::try_ball(r).expect("a ball"), capsule_tris(0.0, r))
        }
        3 => {
            let (h, r) = (length(b), length(b));
            (
                Convex::try_capsule(h, r).expect("a capsule"),
                capsule_tris(h, r),
            )
        }
        4 => {
            let (h, r) = (length(b), length(b));
            match Convex::try_cylinder(h, r) {
                Ok(c) => (c, lathe(&[(0.0, -h), (r, -h), (r, h), (0.0, h)])),
                Err(e) => {
                    assert_eq!(e, InputError::ZeroHeight, "a cylinder of height {h}");
                    return None;
                }
            }
        }
        5 => {
            let (h, r) = (length(b), length(b));
            match Convex::try_cone(h, r) {
                Ok(c) => (c, lathe(&[(0.0, -h), (r, -h), (0.0, h)])),
                Err(e) => {
                    assert_eq!(e, InputError::ZeroHeight, "a cone of height {h}");
                    return None;
                }
            }
        }
        6 => {
            // A half-space: a box 40 wide and 4 deep just below its plane.
            let (normal, class) = axis(b);
            let point = vector(b, 1.0);
            let made = ShapeObstacle::try_half_space("half", normal, point);
            let m = match (class, unit(normal)) {
                (AxisClass::Bad, _) | (_, None) => {
                    assert!(
                        matches!(made, Err(ChainError::Shape(_))),
                        "a half-space of normal {normal:?}: {made:?}"
                    );
                    return None;
                }
                (_, Some(m)) => m,
            };
            let Ok(made) = made else {
                assert!(
                    class == AxisClass::Either,
                    "a half-space of normal {normal:?}: {made:?}"
                );
                return None;
            };
            let depth = 2.0;
            let at = Place {
                r: frame_with_z(m),
                x: sub(point, scale(m, depth + 1e-9)),
            };
            let tris = triangles_of(&box_mesh([0.0; 3], [20.0, 20.0, depth]))
                .iter()
                .map(|t| t.map(|v| at.point(v)))
                .collect();
            return Some((made, tris));
        }
        _ => {
            // A cloud: one to eight points (repeats included), one radius.
            let n = 1 + usize::from(b.u8() % 8);
            let mut points: Vec<V3> = Vec::new();
            for i in 0..n {
                let p = if i > 0 && b.u8().is_multiple_of(4) {
                    points[i - 1]
                } else {
                    vector(b, 1.0)
                };
                points.push(p);
            }
            let r = length(b);
            let refused = match b.u8() % 16 {
                0 => Some(ShapeObstacle::try_points("cloud", &points, -r - 1e-3)),
                1 => Some(ShapeObstacle::try_points("cloud", &points, f64::NAN)),
                2 => Some(ShapeObstacle::try_points("cloud", &[], r)),
                3 => {
                    let mut bad = points.clone();
                    bad[0][1] = f64::INFINITY;
                    Some(ShapeObstacle::try_points("cloud", &bad, r))
                }
                _ => None,
            };
            if let Some(refused) = refused {
                assert!(
                    matches!(refused, Err(ChainError::Shape(_))),
                    "a bad cloud: {refused:?}"
                );
            }
            let made = ShapeObstacle::try_points("cloud", &points, r).expect("a cloud");
            assert_eq!(made.points().map(<[_]>::len), Some(n), "every point kept");
            let tris = points.iter().flat_map(|p| tetra_in_ball(*p, r)).collect();
            return Some((made, tris));
        }
    };
    let shape = shape.try_rounded(rounded).expect("a rounding");
    let tris = local.iter().map(|t| t.map(|v| place.point(v))).collect();
    if bad_pose {
        let bad = Pose::from_translation(Vec3::new(0.0, f64::NAN, 0.0));
        assert!(
            matches!(
                ShapeObstacle::try_new("bad", shape, bad),
                Err(ChainError::InvalidParameter(_))
            ),
            "a NaN shape pose"
        );
    }
    let made = ShapeObstacle::try_new("shape", shape, place.pose()).expect("a shape");
    Some((made, tris))
}

/// The edge query (`check_edge`, `edge_is_free`, `edges_are_free`,
/// `EdgeChecker`) on the scene with up to three fuzzed shape obstacles
/// (primitives with zero, tiny and huge sizes, rounded or not; half-spaces
/// of any normal; point clouds), a padding and a work budget:
///
/// * the same typed error as `check_segment` for a bad `q0`, `q1`; bad
///   shapes and parameters refused with the documented error; never a panic;
/// * the outcome well formed (`0 <= free_until <= at <= 1`, a checked pair,
///   at most the budget's tests and one more), and the same from every
///   entry point and a reused checker;
/// * **never free where a sample touches**: at 2,001 samples before the
///   outcome's `free_until` (all of them for `Free`), no checked pair (the
///   shapes as inscribed triangles) is at distance 0 or nearer than the
///   padding (less `1e-9`); a contact of a mesh or self pair is within the
///   contact distance plus the padding at its `at` (exact distance).
#[allow(clippy::too_many_arguments)]
fn edges(
    b: &mut Bytes<'_>,
    scene: &ChainScene<f64>,
    model: &Model,
    truth: &Truth,
    q0: &[f64],
    q1: &[f64],
    expected: Option<ChainError>,
    oracle: bool,
) {
    let mut scene = scene.clone();
    let mut truth = truth.clone();
    let meshes = scene.obstacles().len();
    let with_mesh: Vec<usize> = (0..model.meshes.len())
        .filter(|&l| model.meshes[l].is_some())
        .collect();
    let mut shape_links = Vec::new();
    for _ in 0..b.u8() % 4 {
        let Some((shape, tris)) = shape_obstacle(b) else {
            continue;
        };
        let s = scene.add_shape(shape);
        let (c, r) = if tris.is_empty() {
            ([0.0; 3], 0.0)
        } else {
            sphere(&tris)
        };
        truth.obstacles.push((tris, c, r));
        for &l in &with_mesh {
            truth.pairs.push(ChainPair::Obstacle {
                link: l,
                obstacle: meshes + s,
            });
            shape_links.push(ChainPair::Shape { link: l, shape: s });
        }
    }
    let mut params = scene.params();
    params.padding = [0.0, 0.0, 1e-3, 0.05][usize::from(b.u8() % 4)];
    params.edge_budget = [400_000, 1, 64, 5_000][usize::from(b.u8() % 4)];
    if !oracle {
        params.edge_budget = params.edge_budget.min(20_000);
    }
    for bad in [
        params.with_padding(-1.0),
        params.with_padding(f64::NAN),
        params.with_edge_budget(0),
    ] {
        assert!(
            matches!(scene.set_params(bad), Err(ChainError::InvalidParameter(_))),
            "invalid edge parameters {bad:?}"
        );
    }
    scene.set_params(params).expect("valid parameters");
    // The first-contact and static queries take the shapes too (issue 63).
    let segment = scene.check_segment(q0, q1);
    assert_eq!(
        segment.as_ref().err(),
        expected.as_ref(),
        "check_segment's error with shapes for {q0:?} -> {q1:?}"
    );
    let path = scene.check_path(&[q0.to_vec(), q1.to_vec()]);
    assert_eq!(
        path.as_ref().err(),
        expected.as_ref(),
        "check_path's error with shapes"
    );
    if let (Ok(segment), Ok(path)) = (&segment, &path) {
        assert_eq!(
            segment.outcome, path.outcome,
            "check_path and check_segment with shapes"
        );
    }
    let clearance = scene.clearance(q0);
    let collides = scene.collides_at(q0);
    if expected.is_none() {
        assert!(
            clearance.is_ok() && collides.is_ok(),
            "clearance, collides_at with shapes"
        );
    }
    let report = scene.check_edge(q0, q1);
    assert_eq!(
        report.as_ref().err(),
        expected.as_ref(),
        "check_edge's error for {q0:?} -> {q1:?}"
    );
    let free = scene.edge_is_free(q0, q1);
    assert_eq!(
        free.as_ref().err(),
        expected.as_ref(),
        "edge_is_free's error"
    );
    let batch = scene.edges_are_free(&[(q0.to_vec(), q1.to_vec())]);
    assert_eq!(
        batch.as_ref().err(),
        expected.as_ref(),
        "edges_are_free's error"
    );
    let (Ok(report), Ok(free), Ok(batch)) = (report, free, batch) else {
        return;
    };
    assert_eq!(batch, vec![free], "edges_are_free and edge_is_free");
    assert_eq!(
        free,
        report.outcome.is_free(),
        "edge_is_free and check_edge"
    );
    let mut checker = scene.edge_checker();
    let again = checker.check(q0, q1).expect("accepted once");
    let twice = checker.check(q0, q1).expect("accepted once");
    assert_eq!(again.outcome, report.outcome, "a checker and check_edge");
    assert_eq!(twice.outcome, report.outcome, "a reused checker");
    assert!(
        report.stats.tests <= params.edge_budget + 1,
        "tests beyond the budget: {report:?}"
    );
    let checked = |p: &ChainPair| truth.pairs.contains(p) || shape_links.contains(p);
    let (limit, contact) = match report.outcome {
        EdgeOutcome::Free => (f64::INFINITY, None),
        EdgeOutcome::Contact {
            free_until,
            at,
            pair,
        } => {
            assert!(
                (0.0..=1.0).contains(&free_until) && (free_until..=1.0).contains(&at),
                "a malformed contact: {report:?}"
            );
            assert!(
                checked(&pair),
                "a contact of a pair not checked: {report:?}"
            );
            (free_until, Some((at, pair)))
        }
        EdgeOutcome::Undecided { free_until } => {
            assert!(
                (0.0..=1.0).contains(&free_until),
                "a malformed undecided: {report:?}"
            );
            (free_until, None)
        }
        other => panic!("an unknown outcome {other:?}"),
    };
    if !oracle {
        return;
    }
    // check_segment: never late, never missed (no touching sample before
    // its time); the clearance at q0 never above the truth's distance.
    if let Ok(segment) = &segment {
        let until = match segment.outcome {
            SegmentOutcome::Contact(c) => c.time,
            SegmentOutcome::IterationLimit { time, .. } => time,
            _ => f64::INFINITY,
        };
        for i in 0..=SAMPLES {
            let t = i as f64 / SAMPLES as f64;
            if t >= until {
                break;
            }
            let (d, pair) = truth.min_distance(model, &Model::at(q0, q1, t), f64::MIN_POSITIVE);
            assert!(
                d >= f64::MIN_POSITIVE,
                "SEGMENT LATE or MISSED with shapes: {pair:?} touches at t = {t}: {segment:?}; \
                 shapes {:?}; q0 {q0:?}, q1 {q1:?}",
                scene.shapes()
            );
        }
    }
    if let Ok((c, _)) = clearance {
        let (d, pair) = truth.min_distance(model, &Model::at(q0, q1, 0.0), f64::INFINITY);
        assert!(
            c <= d * (1.0 + 1e-9) + 1e-12,
            "CLEARANCE {c:e} above the truth's {d:e} ({pair:?}) with shapes; q0 {q0:?}"
        );
    }
    let pad = params.padding;
    if let Some((at, pair @ (ChainPair::Obstacle { .. } | ChainPair::SelfCollision { .. }))) =
        contact
    {
        let one = Truth {
            pairs: vec![pair],
            ..truth.clone()
        };
        let (d, _) = one.min_distance(model, &Model::at(q0, q1, at), f64::INFINITY);
        let touch = params.contact_distance + pad;
        assert!(
            d <= touch * (1.0 + 1e-9) + 1e-12,
            "FAR: a contact of {pair:?} at {at} with the surfaces {d:e} apart: {report:?}; q0 {q0:?}, q1 {q1:?}"
        );
    }
    // Free where no sample comes within the padding (or touches).
    let cutoff = if pad > 0.0 {
        pad - 1e-9
    } else {
        f64::MIN_POSITIVE
    };
    for i in 0..=SAMPLES {
        let t = i as f64 / SAMPLES as f64;
        if t >= limit {
            break;
        }
        let q = Model::at(q0, q1, t);
        let (d, pair) = truth.min_distance(model, &q, cutoff);
        if d < cutoff {
            let what = if limit.is_infinite() {
                "EDGE MISSED: Free"
            } else {
                "EDGE LATE: free until a later time"
            };
            panic!(
                "{what}, but {pair:?} is {d:e} apart (padding {pad}) at t = {t} (sample {i}): {report:?}; \
                 shapes {:?}; q0 {q0:?}, q1 {q1:?}",
                scene.shapes()
            );
        }
    }
}

fuzz_target!(|data: &[u8]| run(data));
