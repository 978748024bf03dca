//! The Rust side of the Python binding's overhead (`python/scripts/batch_overhead.py`): reads the
//! meshes and motions the script wrote, runs the same batch through the Rust API the binding
//! calls (`AnyPair` with its workspace reused, `time_of_impact`), serially and on every core
//! (rayon, as the binding's batch call), and prints ms per query and the outcomes' checksum so
//! that the script can check both sides answered the same.
//!
//! `cargo run --release -p motion-bound-compare --example batch -- FILE [REPEATS]`
//!
//! The file (little-endian): `u64` vertex count `nv`, triangle count `nt`, motion count `n`;
//! `f64` contact distance; `nv x 3` `f64` vertices; `nt x 3` `u32` indices; `n` start and `n`
//! end poses of body A as row-major 4x4 `f64` matrices (body B is the same mesh, still at the
//! identity).

use std::time::Instant;

use motion_bound::ca::{time_of_impact, AnyPair, CaOutcome, CaParams, MeshWorkspace, Shape};
use motion_bound::{BallTree, Isometry, RigidMotion, Rotation, TriMesh, Vec3};
use motion_bound_devkit::Args;
use rayon::prelude::*;

struct Reader {
    bytes: Vec<u8>,
    at: usize,
}

impl Reader {
    fn take<const N: usize>(&mut self) -> [u8; N] {
        let b: [u8; N] = self.bytes[self.at..self.at + N]
            .try_into()
            .expect("file too short");
        self.at += N;
        b
    }
    fn u64(&mut self) -> u64 {
        u64::from_le_bytes(self.take())
    }
    fn f64(&mut self) -> f64 {
        f64::from_le_bytes(self.take())
    }
    fn u32(&mut self) -> u32 {
        u32::from_le_bytes(self.take())
    }
    fn pose(&mut self) -> Isometry<f64> {
        let m: Vec<f64> = (0..16).map(|_| self.f64()).collect();
        let r = [[m[0], m[1], m[2]], [m[4], m[5], m[6]], [m[8], m[9], m[10]]];
        let rot = Rotation::try_from_matrix(r).expect("a rotation");
        Isometry::try_new(rot, Vec3::new(m[3], m[7], m[11])).expect("finite")
    }
}

fn main() {
    let mut args = Args::from_env("batch FILE [REPEATS]");
    let path: String = args
        .positional("FILE")
        .unwrap_or_else(|| args.fail("FILE is missing"));
    let repeats: usize = args.positional("REPEATS").unwrap_or(3);
    args.finish();
    let mut r = Reader {
        bytes: std::fs::read(&path).expect("readable file"),
        at: 0,
    };
    let (nv, nt, n) = (r.u64() as usize, r.u64() as usize, r.u64() as usize);
    let cd = r.f64();
    let vertices: Vec<[f64; 3]> = (0..nv).map(|_| [r.f64(), r.f64(), r.f64()]).collect();
    let triangles: Vec<[u32; 3]> = (0..nt).map(|_| [r.u32(), r.u32(), r.u32()]).collect();
    let starts: Vec<_> = (0..n).map(|_| r.pose()).collect();
    let ends: Vec<_> = (0..n).map(|_| r.pose()).collect();
    let mesh = TriMesh::try_new(vertices, triangles).expect("a valid mesh");
    let tree = BallTree::try_from_mesh(&mesh).expect("a tree");
    let motions: Vec<RigidMotion<f64>> = starts
        .iter()
        .zip(&ends)
        .map(|(s, e)| RigidMotion::try_between(*s, *e, 1.0).expect("a motion"))
        .collect();
    let still = RigidMotion::try_from_start(
        Isometry::try_from_translation(Vec3::ZERO).expect("0"),
        Vec3::ZERO,
        Vec3::ZERO,
        1.0,
    )
    .expect("still");
    let params = CaParams::default().with_contact_distance(cd);
    let one = |ws: &mut Option<MeshWorkspace<f64>>, m: &RigidMotion<f64>| {
        let mut pair = AnyPair::try_new(Shape::Mesh(&tree), Shape::Mesh(&tree))
            .expect("a pair")
            .with_workspace(ws.take().unwrap_or_default());
        let report = time_of_impact(&mut pair, m, &still, &params).expect("a valid query");
        *ws = Some(pair.into_workspace());
        report
    };
    let checksum = |reports: &[motion_bound::ca::CaReport<f64>]| {
        let hits = reports
            .iter()
            .filter(|r| !matches!(r.outcome, CaOutcome::Separated))
            .count();
        let times: f64 = reports
            .iter()
            .filter_map(|r| r.outcome.earliest_possible_contact())
            .sum();
        (hits, times)
    };
    for _ in 0..repeats {
        let t = Instant::now();
        let mut ws = None;
        let serial: Vec<_> = motions.iter().map(|m| one(&mut ws, m)).collect();
        let serial_ms = t.elapsed().as_secs_f64() * 1e3 / n as f64;
        let t = Instant::now();
        let par: Vec<_> = motions.par_iter().map_init(|| None, one).collect();
        let par_ms = t.elapsed().as_secs_f64() * 1e3 / n as f64;
        let (hits, times) = checksum(&serial);
        assert_eq!(checksum(&par), (hits, times), "serial and parallel agree");
        println!("rust: queries {n}, hits {hits}, sum of times {times:.12}, serial ms {serial_ms:.5}, parallel ms {par_ms:.5}");
    }
}
