//! Outside comparisons for motion-bound, kept out of the crate's own build:
//! parry3d's `cast_shapes_nonlinear` on the seed's Table 1 scenes
//! ([`parry`]), the rigid-body scenes driven by rapier3d ([`rbd`]), the
//! `table1` and `report` binaries and the `toi` benchmark.
//!
//! ```sh
//! cargo run --release -p motion-bound-compare --bin report   # everything, with plots in docs/report/
//! cargo run --release -p motion-bound-compare --bin table1   # the torus knots, with parry3d
//! cargo run --release -p motion-bound-compare --example rbd  # the rigid-body rows
//! cargo bench -p motion-bound-compare --bench toi
//! ```

pub mod parry;
pub mod rbd;

use motion_bound::TriMesh;

/// A mesh shipped in `data/` (`.off.gz` or `.obj.gz`), recentred on its
/// bounding sphere and scaled to radius `0.5`.
///
/// # Panics
/// If the file cannot be read or is not a valid mesh.
#[must_use]
pub fn shipped_mesh(name: &str) -> TriMesh<f64> {
    use std::io::Read;
    let path = format!("{}/../data/{name}", env!("CARGO_MANIFEST_DIR"));
    let file = std::fs::File::open(&path).unwrap_or_else(|e| panic!("{path}: {e}"));
    let mut text = String::new();
    flate2::read::GzDecoder::new(file)
        .read_to_string(&mut text)
        .unwrap_or_else(|e| panic!("{path}: {e}"));
    let mesh = if name.ends_with(".off.gz") {
        TriMesh::from_off_str(&text)
    } else {
        TriMesh::from_obj_str(&text)
    }
    .expect("a shipped mesh");
    let (c, r) = mesh.bounding_sphere();
    mesh.recentred(c)
        .and_then(|m| m.scaled(0.5 / r))
        .expect("valid")
}
