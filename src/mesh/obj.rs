//! Reading Wavefront OBJ with [`tobj`](https://crates.io/crates/tobj).
//!
//! tobj's `load_obj_buf` reads from any `BufRead`, so loading from a string
//! or a reader is direct; the only awkward part is that it always asks a
//! closure for the material libraries an OBJ names, and materials do not
//! matter for collision: [`TriMesh::from_obj_reader`] hands it one that loads
//! nothing. tobj reads positions as `f32` unless its `use_f64` feature is on;
//! this module converts with `f64::from`, which compiles for either, and
//! does not turn `use_f64` on itself, because a feature that changes tobj's
//! public types would break any other crate in the build that uses tobj.
//! So OBJ coordinates reach a `TriMesh<f64>` rounded to `f32` (about 7
//! significant digits, which is what the shipped OBJ files hold anyway).
//! Read OFF ([`TriMesh::from_off_str`]) when every bit matters.

use alloc::vec::Vec;
use std::io::BufRead;
use std::path::Path;

use super::error::{MeshError, ObjError};
use crate::{Float, TriMesh};

#[allow(
    clippy::needless_update,
    reason = "tobj's `merging` and `reordering` features add fields"
)]
fn options() -> tobj::LoadOptions {
    tobj::LoadOptions {
        // Faces index positions directly: one vertex per position, so shared
        // corners stay shared (a single index would split them by normal or
        // texture coordinate and open the mesh).
        single_index: false,
        triangulate: true,
        ignore_points: true,
        ignore_lines: true,
        ..tobj::LoadOptions::default()
    }
}

fn from_models<T: Float>(models: &[tobj::Model]) -> Result<TriMesh<T>, MeshError> {
    let mut vertices: Vec<[T; 3]> = Vec::new();
    let mut triangles: Vec<[u32; 3]> = Vec::new();
    for model in models {
        let m = &model.mesh;
        let base = vertices.len();
        for p in m.positions.chunks_exact(3) {
            vertices.push([
                T::from_f64(f64::from(p[0])),
                T::from_f64(f64::from(p[1])),
                T::from_f64(f64::from(p[2])),
            ]);
        }
        for (t, tri) in m.indices.chunks_exact(3).enumerate() {
            let mut out = [0u32; 3];
            for (o, &i) in out.iter_mut().zip(tri) {
                let global = usize::try_from(i).ok().and_then(|i| i.checked_add(base));
                *o = global.and_then(|g| u32::try_from(g).ok()).ok_or(
                    MeshError::IndexOutOfRange {
                        triangle: triangles.len() + t,
                        index: i,
                        vertex_count: vertices.len(),
                    },
                )?;
            }
            triangles.push(out);
        }
    }
    TriMesh::try_new(vertices, triangles)
}

/// Whether OBJ text has a position line (`v x y z`).
fn has_position(text: &[u8]) -> bool {
    text.split(|&b| b == b'\n').any(|line| {
        let line = line.trim_ascii_start();
        line.len() > 1 && line[0] == b'v' && line[1].is_ascii_whitespace()
    })
}

impl<T: Float> TriMesh<T> {
    /// Reads a mesh from OBJ text in `reader`: positions (`v`) and faces
    /// (`f`, triangulated as fans); normals, texture coordinates, points,
    /// lines and material libraries are ignored. The objects and groups of
    /// the file become one mesh, their vertex lists concatenated (so a
    /// position shared by two objects appears twice).
    ///
    /// # Errors
    /// [`MeshError::Obj`] for what tobj rejects or an input that cannot be
    /// read; [`MeshError::NoTriangles`] for positions without a face,
    /// [`MeshError::NoVertices`] for neither; the [`TriMesh::try_new`]
    /// errors for what tobj accepts but the mesh does not (a vertex beyond
    /// [`Float::MAX_INPUT`]).
    pub fn from_obj_reader<R: BufRead>(reader: &mut R) -> Result<Self, MeshError> {
        let mut text = Vec::new();
        reader
            .read_to_end(&mut text)
            .map_err(|_| MeshError::Obj(ObjError(tobj::LoadError::ReadError)))?;
        let (models, _materials) = tobj::load_obj_buf(&mut text.as_slice(), &options(), |_| {
            Ok((Vec::new(), std::collections::HashMap::new()))
        })
        .map_err(|e| MeshError::Obj(ObjError(e)))?;
        if models.iter().all(|m| m.mesh.indices.is_empty()) {
            // tobj keeps no model without a face, so its vertices are gone
            // too: say which of the two the file lacks.
            return Err(if has_position(&text) {
                MeshError::NoTriangles
            } else {
                MeshError::NoVertices
            });
        }
        from_models(&models)
    }

    /// Reads a mesh from OBJ text ([`from_obj_reader`](Self::from_obj_reader)).
    ///
    /// # Errors
    /// As [`from_obj_reader`](Self::from_obj_reader).
    ///
    /// ```
    /// use motion_bound::TriMesh;
    /// let obj = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//1 4//1\n";
    /// let m = TriMesh::<f64>::from_obj_str(obj)?;
    /// assert_eq!(m.triangles(), &[[0, 1, 2], [0, 2, 3]]);
    /// # Ok::<(), motion_bound::MeshError>(())
    /// ```
    pub fn from_obj_str(text: &str) -> Result<Self, MeshError> {
        Self::from_obj_reader(&mut text.as_bytes())
    }

    /// Reads a mesh from an OBJ file ([`from_obj_reader`](Self::from_obj_reader));
    /// material libraries are not opened.
    ///
    /// # Errors
    /// [`MeshError::Obj`] wrapping tobj's `OpenFileFailed` when the file
    /// cannot be opened; otherwise as
    /// [`from_obj_reader`](Self::from_obj_reader).
    pub fn load_obj<P: AsRef<Path>>(path: P) -> Result<Self, MeshError> {
        let file = std::fs::File::open(path)
            .map_err(|_| MeshError::Obj(ObjError(tobj::LoadError::OpenFileFailed)))?;
        Self::from_obj_reader(&mut std::io::BufReader::new(file))
    }
}

#[cfg(test)]
mod tests {
    use crate::{MeshError, TriMesh};

    #[test]
    fn groups_concatenate_and_errors_are_typed() {
        let two =
            "o a\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\no b\nv 5 0 0\nv 6 0 0\nv 5 1 0\nf 4 5 6\n";
        let m = TriMesh::<f32>::from_obj_str(two).unwrap();
        assert_eq!(m.vertex_count(), 6, "vertices of both objects");
        assert_eq!(m.triangles(), &[[0, 1, 2], [3, 4, 5]], "reindexed");
        assert!(
            matches!(
                TriMesh::<f64>::from_obj_str("v 0 0 0\nf 1 2 3\n"),
                Err(MeshError::Obj(_))
            ),
            "face beyond the vertices"
        );
        // Positions without a face: said so (tobj drops such models).
        assert_eq!(
            TriMesh::<f64>::from_obj_str("v 0 0 0\nv 1 0 0\n  v 0 1 0\n"),
            Err(MeshError::NoTriangles),
            "no face"
        );
        assert_eq!(
            TriMesh::<f64>::from_obj_str("# nothing\nvn 0 0 1\n"),
            Err(MeshError::NoVertices),
            "no position"
        );
        assert!(
            matches!(
                TriMesh::<f64>::load_obj("/nonexistent/x.obj"),
                Err(MeshError::Obj(_))
            ),
            "missing file"
        );
        let e = TriMesh::<f64>::from_obj_str("v 0 0 0\nf 1 2 3\n").unwrap_err();
        assert!(std::format!("{e}").starts_with("OBJ: "), "display: {e}");
    }
}
