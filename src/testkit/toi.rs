//! Time-of-impact query generators shared by tests, benchmarks and examples:
//! a small deterministic random source, random rotations, and motions that
//! fly one body through another's neighbourhood with rotation.

extern crate std;
use std::vec::Vec;

use crate::rng::SplitMix64;
use crate::{Float, RigidMotion, TriMesh, Vec3};

/// The deterministic random source of the time-of-impact generators: the
/// testkit's [`SplitMix64`], with the draws they need.
pub type Rng = SplitMix64;

/// A uniformly random rotation matrix (row-major), from a random unit
/// quaternion (Shoemake's method).
pub fn random_rotation(rng: &mut Rng) -> [[f64; 3]; 3] {
    let (u1, u2, u3) = (rng.unit(), rng.unit(), rng.unit());
    let tau = core::f64::consts::TAU;
    let (a, b) = ((1.0 - u1).sqrt(), u1.sqrt());
    let (x, y, z, w) = (
        a * (tau * u2).sin(),
        a * (tau * u2).cos(),
        b * (tau * u3).sin(),
        b * (tau * u3).cos(),
    );
    [
        [
            1.0 - 2.0 * (y * y + z * z),
            2.0 * (x * y - z * w),
            2.0 * (x * z + y * w),
        ],
        [
            2.0 * (x * y + z * w),
            1.0 - 2.0 * (x * x + z * z),
            2.0 * (y * z - x * w),
        ],
        [
            2.0 * (x * z - y * w),
            2.0 * (y * z + x * w),
            1.0 - 2.0 * (x * x + y * y),
        ],
    ]
}

/// `mesh` with every vertex multiplied by `rotation` (a body's orientation
/// at the epoch, baked into its body points).
///
/// # Panics
/// If the rotated mesh is invalid (it cannot be, for a rotation matrix and a
/// valid mesh well inside the input range).
#[must_use]
pub fn rotate_mesh<T: Float>(mesh: &TriMesh<T>, rotation: &[[f64; 3]; 3]) -> TriMesh<T> {
    let vertices: Vec<[T; 3]> = mesh
        .vertices()
        .iter()
        .map(|v| {
            let v = v.map(Float::to_f64);
            rotation.map(|row| T::from_f64(row[0] * v[0] + row[1] * v[1] + row[2] * v[2]))
        })
        .collect();
    TriMesh::try_new(vertices, mesh.triangles().to_vec()).expect("a rotated valid mesh is valid")
}

/// A query: body A flies past body B (both spinning) over `[0, 1]`.
#[derive(Clone, Copy, Debug)]
pub struct FlyBy {
    /// Body A's motion.
    pub a: RigidMotion<f64>,
    /// Body B's motion.
    pub b: RigidMotion<f64>,
}

/// A random fly-by for bodies within `reach_a` and `reach_b` of their
/// rotation centres: B sits at the origin spinning at up to `spin / 4`;
/// A starts `1.1` to `1.6` times `reach_a + reach_b` away in a random
/// direction, aims at a random point within `0.8 (reach_a + reach_b)` of
/// the origin (most queries collide, some pass close by), and spins at up to
/// `spin` rad per unit time about a random axis.
pub fn fly_by(rng: &mut Rng, reach_a: f64, reach_b: f64, spin: f64) -> FlyBy {
    let reach = reach_a + reach_b;
    let start = rng.direction().map(|x| x * reach * rng.range(1.1, 1.6));
    let aim = rng.direction().map(|x| x * reach * 0.8 * rng.unit());
    let v = [0, 1, 2].map(|k| aim[k] - start[k]);
    let wa = rng.direction().map(|x| x * spin * rng.unit());
    let wb = rng.direction().map(|x| x * spin * 0.25 * rng.unit());
    FlyBy {
        a: RigidMotion::try_from_arrays(start, v, wa).expect("finite"),
        b: RigidMotion::try_from_arrays([0.0; 3], [0.0; 3], wb).expect("finite"),
    }
}

/// The `q`-th fly-by of the shape pair benchmarks (`benches/shapes.rs`,
/// `compare/examples/shapes.rs`): A from 1.1 to 1.5 away aimed within 0.4 of
/// B's centre, spins of 0, 2 or 8 rad per unit time by `q`; or, with
/// `ground`, A falling from 0.8 to 1.4 above a still ground at the origin.
pub fn shape_fly_by(rng: &mut Rng, q: usize, ground: bool) -> (RigidMotion<f64>, RigidMotion<f64>) {
    let spin = [0.0, 2.0, 8.0][q % 3];
    if ground {
        let start = [
            rng.range(-0.5, 0.5),
            rng.range(0.8, 1.4),
            rng.range(-0.5, 0.5),
        ];
        let v = [
            rng.range(-1.0, 1.0),
            -rng.range(0.5, 2.0),
            rng.range(-1.0, 1.0),
        ];
        let w = rng.direction().map(|x| x * spin * rng.unit());
        (
            RigidMotion::try_from_arrays(start, v, w).expect("finite"),
            RigidMotion::try_from_arrays([0.0; 3], [0.0; 3], [0.0; 3]).expect("finite"),
        )
    } else {
        let start = rng.direction().map(|x| x * rng.range(1.1, 1.5));
        let aim = rng.direction().map(|x| x * 0.4 * rng.unit());
        let v = [0, 1, 2].map(|k| aim[k] - start[k]);
        let wa = rng.direction().map(|x| x * spin * rng.unit());
        let wb = rng.direction().map(|x| x * spin * 0.25 * rng.unit());
        (
            RigidMotion::try_from_arrays(start, v, wa).expect("finite"),
            RigidMotion::try_from_arrays([0.0; 3], [0.0; 3], wb).expect("finite"),
        )
    }
}

/// The farthest vertex distance from the rotation centre.
#[must_use]
pub fn reach<T: Float>(mesh: &TriMesh<T>) -> f64 {
    mesh.vertices()
        .iter()
        .map(|v| Vec3::from_array(v.map(Float::to_f64)).length())
        .fold(0.0, f64::max)
}
