//! Typed errors for meshes: construction, transformation and file parsing.
//!
//! [`MeshError`] is its own type rather than more variants of
//! [`InputError`]: `InputError` is the small `Copy` error of the `no_std`,
//! allocation-free bound API, and every user of the bounds matches on it;
//! mesh errors carry line numbers and parser details that only mesh users
//! need. A bad vertex is still reported as the [`InputError`] the bounds
//! would give for it ([`MeshError::Vertex`]), so the two agree on what a
//! valid body point is.

use core::fmt;

use crate::InputError;

/// Why a mesh was rejected.
///
/// Returned by [`TriMesh::try_new`](crate::TriMesh::try_new), the
/// transformations ([`TriMesh::translated`](crate::TriMesh::translated), ...)
/// and the file readers. No function of the mesh module panics on bad input.
#[derive(Clone, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub enum MeshError {
    /// The mesh has no vertex.
    NoVertices,
    /// The mesh has no triangle.
    NoTriangles,
    /// A vertex is not finite or exceeds
    /// [`Float::MAX_INPUT`](crate::Float::MAX_INPUT): the error the bounds'
    /// [`VertexSet::try_new`](crate::VertexSet::try_new) gives for it, with
    /// [`Quantity::Vertex`](crate::Quantity::Vertex) naming the first bad
    /// vertex.
    Vertex(InputError),
    /// A triangle names a vertex that does not exist.
    IndexOutOfRange {
        /// The triangle's index.
        triangle: usize,
        /// The offending vertex index.
        index: u32,
        /// The number of vertices.
        vertex_count: usize,
    },
    /// A scale factor that is zero, negative or not finite (a negative factor
    /// would mirror the mesh and turn its outward winding inward).
    InvalidScale,
    /// A mesh declared solid ([`TriMesh::try_solid`](crate::TriMesh::try_solid))
    /// is not closed: some directed edge is not matched by exactly one
    /// reverse edge (a hole, a crack, a flipped or doubled triangle, an
    /// edge shared by more than two triangles), or a triangle repeats a
    /// vertex index: the counts of
    /// [`EdgeReport`](crate::EdgeReport).
    NotClosed {
        /// Distinct directed edges whose reverse no triangle has.
        unpaired: usize,
        /// Extra occurrences of directed edges that occur more than once.
        repeated: usize,
        /// Triangles that repeat a vertex index.
        degenerate_triangles: usize,
    },
    /// A mesh declared solid ([`TriMesh::try_solid`](crate::TriMesh::try_solid))
    /// is closed but wound inward, or encloses nothing: its
    /// [`signed_volume`](crate::TriMesh::signed_volume) is not positive.
    /// Reversing every triangle (`[a, b, c]` to `[a, c, b]`) turns an
    /// inward-wound mesh outward.
    InsideOut,
    /// An OFF file could not be read.
    Off(OffError),
    /// An OBJ file could not be read.
    #[cfg(feature = "obj")]
    Obj(ObjError),
    /// Input to the STL reader that is neither ASCII STL (it does not begin
    /// with `solid`) nor a binary STL of the `84 + 50 n` bytes that the
    /// triangle count `n` in its header announces: a truncated file, or
    /// bytes after the last facet.
    StlLength {
        /// The input's length in bytes.
        len: usize,
        /// The header's triangle count, `None` for input shorter than the
        /// 84-byte header.
        triangles: Option<u32>,
    },
    /// ASCII STL text with an unexpected token, or that ends early.
    StlSyntax {
        /// The 1-based line number of the token (of the last token, for an
        /// early end).
        line: usize,
        /// What the reader expected there (`"a number"`, `` "`vertex`" ``, ...).
        expected: &'static str,
    },
    /// A mesh file could not be read: the [`std::io::Error`]'s kind.
    #[cfg(feature = "std")]
    Io(std::io::ErrorKind),
}

/// Where and why an OFF file could not be read.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub struct OffError {
    /// The 1-based line number (`0` for an empty input).
    pub line: usize,
    /// What is wrong on that line.
    pub kind: OffErrorKind,
}

/// What is wrong in an OFF file.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub enum OffErrorKind {
    /// The first content line is not `OFF` (or `COFF`, `NOFF`, `CNOFF`).
    BadHeader,
    /// The counts line is not `V F E` with non-negative integers.
    BadCounts,
    /// A vertex line has fewer than three numbers, or a token that is not a
    /// number.
    BadVertexLine,
    /// A plain `OFF` vertex line has more than three numbers.
    TrailingTokens,
    /// A parsed vertex is not finite or too large (see [`MeshError::Vertex`]).
    BadVertex(InputError),
    /// A face line does not start with a vertex count, or has fewer indices
    /// than it announces, or an index that is not a non-negative integer.
    BadFaceLine,
    /// A face with fewer than three vertices.
    FaceTooSmall(usize),
    /// A face names a vertex beyond the vertex count.
    IndexOutOfRange {
        /// The offending index.
        index: u32,
        /// The number of vertices.
        vertex_count: usize,
    },
    /// The file ends before all announced vertices and faces.
    UnexpectedEnd,
    /// Content follows the last announced face.
    TrailingContent,
}

impl fmt::Display for MeshError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::NoVertices => f.write_str("mesh has no vertex"),
            Self::NoTriangles => f.write_str("mesh has no triangle"),
            Self::Vertex(e) => write!(f, "invalid mesh vertex: {e}"),
            Self::IndexOutOfRange {
                triangle,
                index,
                vertex_count,
            } => write!(
                f,
                "triangle {triangle} names vertex {index}, but the mesh has {vertex_count} vertices"
            ),
            Self::InvalidScale => f.write_str("scale factor is not positive and finite"),
            Self::NotClosed {
                unpaired,
                repeated,
                degenerate_triangles,
            } => write!(
                f,
                "mesh is not closed, so it cannot be solid: {unpaired} unpaired and {repeated} repeated directed edges, {degenerate_triangles} triangles repeating a vertex"
            ),
            Self::InsideOut => f.write_str(
                "mesh is wound inward or encloses nothing (signed volume not positive), so it cannot be solid",
            ),
            Self::Off(e) => write!(f, "{e}"),
            #[cfg(feature = "obj")]
            Self::Obj(e) => write!(f, "{e}"),
            Self::StlLength {
                len,
                triangles: None,
            } => write!(
                f,
                "STL: {len} bytes, not ASCII and shorter than a binary file's 84-byte header"
            ),
            Self::StlLength {
                len,
                triangles: Some(n),
            } => write!(
                f,
                "STL: {len} bytes, not ASCII and not the {} bytes of a binary file of {n} facets, as its header says",
                84 + 50 * u64::from(*n)
            ),
            Self::StlSyntax { line, expected } => write!(f, "STL line {line}: expected {expected}"),
            #[cfg(feature = "std")]
            Self::Io(kind) => write!(f, "cannot read the mesh file: {kind}"),
        }
    }
}

impl fmt::Display for OffError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "OFF line {}: {}", self.line, self.kind)
    }
}

impl fmt::Display for OffErrorKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::BadHeader => f.write_str("expected the header `OFF`"),
            Self::BadCounts => f.write_str("expected the counts `V F E`"),
            Self::BadVertexLine => f.write_str("expected three coordinates `x y z`"),
            Self::TrailingTokens => f.write_str("more than three coordinates on a vertex line"),
            Self::BadVertex(e) => write!(f, "{e}"),
            Self::BadFaceLine => f.write_str("expected a face `k i_0 ... i_(k-1)`"),
            Self::FaceTooSmall(k) => write!(f, "a face needs at least 3 vertices, not {k}"),
            Self::IndexOutOfRange {
                index,
                vertex_count,
            } => write!(
                f,
                "vertex index {index} out of range for {vertex_count} vertices"
            ),
            Self::UnexpectedEnd => f.write_str("file ends before the announced vertices and faces"),
            Self::TrailingContent => f.write_str("content after the last announced face"),
        }
    }
}

impl core::error::Error for MeshError {
    fn source(&self) -> Option<&(dyn core::error::Error + 'static)> {
        match self {
            Self::Vertex(e) => Some(e),
            Self::Off(e) => Some(e),
            #[cfg(feature = "obj")]
            Self::Obj(e) => Some(e),
            _ => None,
        }
    }
}

impl core::error::Error for OffError {}

impl From<OffError> for MeshError {
    fn from(e: OffError) -> Self {
        Self::Off(e)
    }
}

#[cfg(feature = "obj")]
/// Why tobj could not read an OBJ file: tobj's own error, kept opaque so that
/// tobj's version is not part of this crate's API ([`source`] gives it).
///
/// [`source`]: core::error::Error::source
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ObjError(pub(super) tobj::LoadError);

// tobj's `LoadError` is a field-less enum whose `PartialEq` is the derived,
// reflexive one, so equality is an equivalence.
#[cfg(feature = "obj")]
impl Eq for ObjError {}

#[cfg(feature = "obj")]
impl fmt::Display for ObjError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "OBJ: {}", self.0)
    }
}

#[cfg(feature = "obj")]
impl core::error::Error for ObjError {
    fn source(&self) -> Option<&(dyn core::error::Error + 'static)> {
        Some(&self.0)
    }
}
