//! The real meshes shipped in `data/` (see README, "Meshes and credits"),
//! gunzipped and parsed. Shared by tests, examples and benches:
//! `#[path = "../tests/common/meshes.rs"] mod meshes;` from `examples/` or
//! `benches/`, `#[path = "common/meshes.rs"] mod meshes;` from `tests/`.

#![allow(dead_code, unreachable_pub)]

use std::io::Read;
use std::path::PathBuf;

use motion_bound::TriMesh;

/// A shipped mesh with the counts its source declares.
#[derive(Clone, Copy, Debug)]
pub struct Shipped {
    /// The file name in `data/`.
    pub name: &'static str,
    /// Vertices.
    pub vertices: usize,
    /// Triangles.
    pub triangles: usize,
}

/// Every shipped mesh, smallest first, with the counts of
/// `shared/meshes/SOURCES.md`.
pub const SHIPPED: [Shipped; 4] = [
    Shipped {
        name: "knot.off.gz",
        vertices: 2_080,
        triangles: 4_160,
    },
    Shipped {
        name: "bunny-npm-3674.obj.gz",
        vertices: 1_839,
        triangles: 3_674,
    },
    Shipped {
        name: "armadillo.off.gz",
        vertices: 26_002,
        triangles: 52_000,
    },
    Shipped {
        name: "bunny00.off.gz",
        vertices: 37_706,
        triangles: 75_408,
    },
];

/// The path of a file in the repository's `data/`: beside the manifest of the crate, or one
/// level up for the workspace members that build the root's examples and tests from their files
/// (`demo/`, `repo-targets/`).
pub fn data_path(name: &str) -> PathBuf {
    let here = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    let data = if here.join("data").is_dir() {
        here.join("data")
    } else {
        here.join("..").join("data")
    };
    data.join(name)
}

/// The gunzipped text of `data/<name>`, or why it could not be read.
pub fn read_shipped(name: &str) -> Result<String, String> {
    let path = data_path(name);
    let file = std::fs::File::open(&path).map_err(|e| format!("{}: {e}", path.display()))?;
    let mut text = String::new();
    flate2::read::GzDecoder::new(file)
        .read_to_string(&mut text)
        .map_err(|e| format!("{}: {e}", path.display()))?;
    Ok(text)
}

/// `data/<name>` (`*.off.gz` or `*.obj.gz`) as a mesh, or why not.
pub fn try_load_shipped(name: &str) -> Result<TriMesh<f64>, String> {
    let text = read_shipped(name)?;
    let mesh = if name.ends_with(".off.gz") {
        TriMesh::from_off_str(&text)
    } else if name.ends_with(".obj.gz") {
        TriMesh::from_obj_str(&text)
    } else {
        return Err(format!("{name}: neither .off.gz nor .obj.gz"));
    };
    mesh.map_err(|e| format!("{name}: {e}"))
}

/// `data/<name>` as a mesh; panics with the reason if it cannot be loaded
/// (a test or benchmark cannot go on without it).
pub fn load_shipped(name: &str) -> TriMesh<f64> {
    try_load_shipped(name).unwrap_or_else(|e| panic!("loading a shipped mesh: {e}"))
}
