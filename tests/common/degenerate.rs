//! Degenerate meshes as scanned and CAD meshes carry them (issue 38): copies
//! of one triangle, triangles on one point, near copies, a mesh with every
//! vertex doubled and zero-area triangles added; and the fly-bys that run
//! them against the bunny. Shared by `tests/degenerate.rs` and
//! `examples/degenerate_meshes.rs`:
//! `#[path = "../tests/common/degenerate.rs"] mod degenerate;` from
//! `examples/`, `#[path = "common/degenerate.rs"] mod degenerate;` from
//! `tests/`.

#![allow(dead_code, unreachable_pub)]

use motion_bound::testkit::toi::Rng;
use motion_bound::{Point3, RigidMotion, TimeInterval, TriMesh, Vec3};

/// The triangle, `(0, -1, -1)`, `(0, 1, -1)`, `(0, 0, 1)`, times
/// `scale`: the size of the bunny scaled to reach 1 at `scale = 1`.
pub fn triangle(scale: f64) -> [[f64; 3]; 3] {
    [[0.0, -1.0, -1.0], [0.0, 1.0, -1.0], [0.0, 0.0, 1.0]].map(|c| c.map(|x| x * scale))
}

/// `n` copies of `corners`, each with its own three vertices.
pub fn copies(corners: [[f64; 3]; 3], n: usize) -> TriMesh<f64> {
    let mut v = Vec::with_capacity(3 * n);
    let mut t = Vec::with_capacity(n);
    for i in 0..n as u32 {
        v.extend(corners);
        t.push([3 * i, 3 * i + 1, 3 * i + 2]);
    }
    TriMesh::try_new(v, t).expect("copies of a triangle")
}

/// `n` copies of `corners` whose every corner is moved by up to `jitter`
/// in each coordinate: near duplicates, which no exact test can merge.
pub fn near_copies(corners: [[f64; 3]; 3], n: usize, jitter: f64, rng: &mut Rng) -> TriMesh<f64> {
    let mut v = Vec::with_capacity(3 * n);
    let mut t = Vec::with_capacity(n);
    for i in 0..n as u32 {
        for c in corners {
            v.push(c.map(|x| x + rng.range(-jitter, jitter)));
        }
        t.push([3 * i, 3 * i + 1, 3 * i + 2]);
    }
    TriMesh::try_new(v, t).expect("near copies of a triangle")
}

/// `n` triangles whose corners are all the one point `p`.
pub fn on_one_point(p: [f64; 3], n: usize) -> TriMesh<f64> {
    let t = (0..n as u32)
        .map(|i| [i % 3, (i + 1) % 3, (i + 2) % 3])
        .collect();
    TriMesh::try_new(vec![p; 3], t).expect("triangles on one point")
}

/// `mesh` with every vertex doubled (vertex `i` and `i + n` are the same
/// point; each triangle's corners reference either copy at random) and
/// `extra` zero-area triangles added, in thirds: a point (one vertex three
/// times, through its copies), a segment between two random vertices (a
/// corner repeated through its copy), and a segment with its midpoint
/// (collinear corners, exactly so when the midpoint rounds onto the line).
pub fn doubled_with_slivers(mesh: &TriMesh<f64>, extra: usize, rng: &mut Rng) -> TriMesh<f64> {
    let n = mesh.vertices().len() as u32;
    let mut v: Vec<[f64; 3]> = mesh.vertices().to_vec();
    v.extend_from_slice(mesh.vertices());
    let pick = |i: u32, rng: &mut Rng| if rng.unit() < 0.5 { i } else { i + n };
    let mut t: Vec<[u32; 3]> = mesh
        .triangles()
        .iter()
        .map(|tri| tri.map(|i| pick(i, rng)))
        .collect();
    for k in 0..extra {
        let a = (rng.next_u64() % u64::from(n)) as u32;
        let b = (rng.next_u64() % u64::from(n)) as u32;
        let tri = match k % 3 {
            0 => [a, a + n, pick(a, rng)],
            1 => [a, b, b + n],
            _ => {
                let (pa, pb) = (v[a as usize], v[b as usize]);
                v.push([0, 1, 2].map(|j| 0.5 * (pa[j] + pb[j])));
                [pick(a, rng), v.len() as u32 - 1, pick(b, rng)]
            }
        };
        t.push(tri);
    }
    TriMesh::try_new(v, t).expect("a doubled mesh")
}

/// Fly-by `k` of the degenerate body (A) past the bunny (B, reach about
/// 1, at the origin) over `[0, 1]`: A starts 3 to the left at a height and
/// depth picked by `k` (head on, grazing, passing by), moves right at 6 per
/// unit time and turns at up to 5 rad per unit time; B turns slowly.
pub fn fly_by(k: usize) -> (RigidMotion<f64>, RigidMotion<f64>) {
    const OFFSETS: [[f64; 2]; 6] = [
        [0.0, 0.0],
        [0.4, -0.3],
        [1.1, 0.2],
        [-0.9, 0.9],
        [2.5, 0.0],
        [0.0, -4.0],
    ];
    const SPINS: [[f64; 3]; 6] = [
        [0.0, 0.0, 0.0],
        [0.0, 3.0, 1.0],
        [5.0, 0.0, 0.0],
        [1.0, -2.0, 2.0],
        [0.0, 0.0, 4.0],
        [2.0, 2.0, 0.0],
    ];
    let [y, z] = OFFSETS[k % OFFSETS.len()];
    let a = RigidMotion::try_new(
        Point3::new(-3.0, y, z),
        Vec3::new(6.0, 0.0, 0.0),
        Vec3::from_array(SPINS[k % SPINS.len()]),
        TimeInterval::UNIT,
    )
    .expect("a valid motion");
    let b = RigidMotion::try_new(
        Point3::new(0.0, 0.0, 0.0),
        Vec3::ZERO,
        Vec3::new(0.0, 0.3, 0.0),
        TimeInterval::UNIT,
    )
    .expect("a valid motion");
    (a, b)
}
