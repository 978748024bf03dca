//! Reading STL (stereolithography) files, binary and ASCII, without a
//! dependency: the format robot descriptions (URDF) name for collision
//! meshes.
//!
//! An STL file is a triangle soup: each facet lists its three corners by
//! coordinates, so a corner shared by six facets is written six times. The
//! reader welds corners with exactly equal coordinates into one vertex,
//! which is what makes a closed surface's [`TriMesh::edge_report`] see it as
//! closed; it merges nothing that is merely close.

use alloc::collections::btree_map::{BTreeMap, Entry};
use alloc::vec::Vec;

use crate::error::{check_components, Quantity};
use crate::mesh::MeshError;
use crate::{Float, TriMesh};

/// A binary STL's header: 80 free bytes, then the triangle count.
const HEADER: usize = 84;
/// A binary STL's facet: normal, three corners (twelve `f32`), and a `u16`
/// attribute byte count.
const FACET: usize = 50;

/// The triangle count in a binary header, if `bytes` is long enough to hold
/// one.
fn binary_count(bytes: &[u8]) -> Option<u32> {
    let count: [u8; 4] = bytes.get(80..HEADER)?.try_into().ok()?;
    Some(u32::from_le_bytes(count))
}

/// The error for input that is not a binary STL of the right length.
fn length_error(bytes: &[u8]) -> MeshError {
    MeshError::StlLength {
        len: bytes.len(),
        triangles: binary_count(bytes),
    }
}

/// Whether `bytes` begins (after blanks) with the keyword `solid`, as ASCII
/// STL does (and, alas, many binary headers).
fn starts_with_solid(bytes: &[u8]) -> bool {
    let text = bytes.trim_ascii_start();
    text.get(..5)
        .is_some_and(|k| k.eq_ignore_ascii_case(b"solid"))
        && text.get(5).is_none_or(u8::is_ascii_whitespace)
}

/// The facets' corners of a binary STL whose length has been checked.
fn binary_facets(bytes: &[u8]) -> impl Iterator<Item = [[f32; 3]; 3]> + '_ {
    let body = bytes.get(HEADER..).unwrap_or_default();
    body.chunks_exact(FACET).map(|facet| {
        // Skip the normal (12 bytes); the corners are the next 36.
        let mut words = facet[12..48]
            .chunks_exact(4)
            .map(|w| f32::from_le_bytes([w[0], w[1], w[2], w[3]]));
        let mut corner = || [(); 3].map(|()| words.next().unwrap_or(0.0));
        [corner(), corner(), corner()]
    })
}

/// The error for ASCII text with `expected` missing on `line`.
fn syntax(line: usize, expected: &'static str) -> MeshError {
    MeshError::StlSyntax { line, expected }
}

/// The whitespace-separated tokens of ASCII STL, with their line numbers.
struct Tokens<'a> {
    bytes: &'a [u8],
    pos: usize,
    /// The 1-based line of `pos`.
    line: usize,
    /// The line of the last token (where an early end is reported).
    last: usize,
}

impl<'a> Tokens<'a> {
    fn new(bytes: &'a [u8]) -> Self {
        Self {
            bytes,
            pos: 0,
            line: 1,
            last: 1,
        }
    }

    /// Moves past blanks and line breaks; `true` if a token follows.
    fn skip_blanks(&mut self) -> bool {
        while let Some(&b) = self.bytes.get(self.pos) {
            if b == b'\n' {
                self.line += 1;
            } else if !b.is_ascii_whitespace() {
                return true;
            }
            self.pos += 1;
        }
        false
    }

    /// Moves to the end of the current line (past a solid's name).
    fn skip_line(&mut self) {
        while self.bytes.get(self.pos).is_some_and(|&b| b != b'\n') {
            self.pos += 1;
        }
    }

    /// The next token and its line.
    fn next(&mut self) -> Option<(usize, &'a [u8])> {
        if !self.skip_blanks() {
            return None;
        }
        let start = self.pos;
        while self
            .bytes
            .get(self.pos)
            .is_some_and(|b| !b.is_ascii_whitespace())
        {
            self.pos += 1;
        }
        self.last = self.line;
        Some((self.line, self.bytes.get(start..self.pos)?))
    }

    /// The next token, which must be `keyword` (in any letter case).
    fn keyword(&mut self, keyword: &str, expected: &'static str) -> Result<(), MeshError> {
        match self.next() {
            Some((_, t)) if t.eq_ignore_ascii_case(keyword.as_bytes()) => Ok(()),
            Some((line, _)) => Err(syntax(line, expected)),
            None => Err(syntax(self.last, expected)),
        }
    }

    /// The next token as an `f32` (correctly rounded; `nan` and `inf` are
    /// numbers here and are rejected later as vertices).
    fn number(&mut self) -> Result<f32, MeshError> {
        let (line, token) = self.next().ok_or(syntax(self.last, "a number"))?;
        core::str::from_utf8(token)
            .ok()
            .and_then(|s| s.parse().ok())
            .ok_or(syntax(line, "a number"))
    }

    fn point(&mut self) -> Result<[f32; 3], MeshError> {
        Ok([self.number()?, self.number()?, self.number()?])
    }
}

/// The facets' corners of ASCII STL: one or more
/// `solid ... facet normal ... outer loop vertex x y z (x3) endloop endfacet ... endsolid`.
fn ascii_facets(bytes: &[u8]) -> Result<Vec<[[f32; 3]; 3]>, MeshError> {
    let mut tokens = Tokens::new(bytes);
    let mut facets = Vec::new();
    loop {
        tokens.keyword("solid", "`solid`")?;
        tokens.skip_line();
        loop {
            match tokens.next() {
                Some((_, t)) if t.eq_ignore_ascii_case(b"endsolid") => {
                    tokens.skip_line();
                    break;
                }
                Some((_, t)) if t.eq_ignore_ascii_case(b"facet") => {}
                Some((line, _)) => return Err(syntax(line, "`facet` or `endsolid`")),
                None => return Err(syntax(tokens.last, "`facet` or `endsolid`")),
            }
            tokens.keyword("normal", "`normal` after `facet`")?;
            // The normal is ignored (the winding says where outside is), but
            // must be three numbers.
            tokens.point()?;
            tokens.keyword("outer", "`outer loop`")?;
            tokens.keyword("loop", "`outer loop`")?;
            let mut corners = [[0.0f32; 3]; 3];
            for c in &mut corners {
                tokens.keyword("vertex", "`vertex`")?;
                *c = tokens.point()?;
            }
            tokens.keyword("endloop", "`endloop` after three vertices")?;
            tokens.keyword("endfacet", "`endfacet`")?;
            facets.push(corners);
        }
        // Several solids may follow each other.
        if !tokens.skip_blanks() {
            return Ok(facets);
        }
    }
}

/// Welds the corners into vertices and builds the mesh: facets with a
/// repeated corner are dropped before their corners become vertices.
fn weld<T: Float>(
    facets: impl Iterator<Item = [[f32; 3]; 3]>,
    facet_count: usize,
) -> Result<TriMesh<T>, MeshError> {
    let mut index: BTreeMap<[u32; 3], u32> = BTreeMap::new();
    let mut vertices: Vec<[T; 3]> = Vec::new();
    let mut triangles: Vec<[u32; 3]> = Vec::with_capacity(facet_count);
    for (t, facet) in facets.enumerate() {
        let mut corners = [([0u32; 3], [T::ZERO; 3]); 3];
        for (k, (c, p)) in corners.iter_mut().zip(facet).enumerate() {
            // `+ 0.0` turns -0.0 into 0.0, so the two weld.
            let p = p.map(|x| x + 0.0);
            let v = p.map(|x| T::from_f64(f64::from(x)));
            let corner = t.saturating_mul(3).saturating_add(k);
            check_components(v, Quantity::Vertex(corner)).map_err(MeshError::Vertex)?;
            *c = (p.map(f32::to_bits), v);
        }
        let [a, b, c] = corners.map(|(key, _)| key);
        if a == b || b == c || c == a {
            continue;
        }
        let mut tri = [0u32; 3];
        for (slot, (key, v)) in tri.iter_mut().zip(corners) {
            let next = vertices.len();
            *slot = match index.entry(key) {
                Entry::Occupied(e) => *e.get(),
                Entry::Vacant(e) => {
                    let i = u32::try_from(next).map_err(|_| MeshError::IndexOutOfRange {
                        triangle: triangles.len(),
                        index: u32::MAX,
                        vertex_count: next,
                    })?;
                    vertices.push(v);
                    *e.insert(i)
                }
            };
        }
        triangles.push(tri);
    }
    if triangles.is_empty() {
        return Err(MeshError::NoTriangles);
    }
    TriMesh::try_new(vertices, triangles)
}

impl<T: Float> TriMesh<T> {
    /// Reads a mesh from the bytes of an STL file, binary or ASCII.
    ///
    /// **Binary** STL is an 80-byte header, a little-endian `u32` triangle
    /// count `n`, and `n` facets of 50 bytes (a normal, three corners as
    /// little-endian `f32` triples, a 2-byte attribute count). Input whose
    /// length is exactly `84 + 50 n` is read as binary, whatever its header
    /// says: many binary files begin with `solid` too.
    ///
    /// **ASCII** STL is read otherwise, if the input begins with `solid`:
    ///
    /// ```text
    /// solid name
    ///   facet normal nx ny nz
    ///     outer loop
    ///       vertex x y z      (three vertex lines)
    ///     endloop
    ///   endfacet
    ///   ...
    /// endsolid name
    /// ```
    ///
    /// Keywords are matched in any letter case, tokens may be split across
    /// lines in any way except that a solid's name runs to the end of its
    /// line, and several solids may follow each other (they become one
    /// mesh). Coordinates are read as `f32` (correctly rounded), like binary
    /// ones, so an ASCII file and its binary conversion give the same mesh.
    ///
    /// Facet normals are ignored: the winding of the corners gives the
    /// outside, as STL requires. Corners with equal coordinates (as `f32`,
    /// so `0.0` and `-0.0` are one) are welded into one vertex, numbered in
    /// order of first appearance, each converted to `T` exactly; a facet
    /// with two equal corners has no area and is dropped (its corners
    /// become vertices only if another facet has them).
    /// The reader never panics, and allocates in proportion to the input's
    /// length.
    ///
    /// # Errors
    /// - [`MeshError::StlLength`] for input that is neither ASCII STL (it
    ///   does not begin with `solid`) nor exactly as long as its binary
    ///   header says: a truncated file, bytes after the last facet, or
    ///   fewer than 84 bytes. Input beginning with `solid` that fails to
    ///   parse as ASCII but contains a NUL byte is also taken for a binary
    ///   file of the wrong length.
    /// - [`MeshError::StlSyntax`] with the line number for ASCII text with
    ///   an unexpected token or an early end.
    /// - [`MeshError::Vertex`] for a corner that is not finite or beyond
    ///   [`Float::MAX_INPUT`]; its [`Quantity::Vertex`] index counts the
    ///   file's corners (`3 t + k` for corner `k` of facet `t`), not the
    ///   welded vertices.
    /// - [`MeshError::NoTriangles`] for a file without facets, or whose
    ///   facets all have repeated corners.
    ///
    /// ```
    /// use motion_bound::{MeshError, TriMesh};
    /// // A binary STL of the tetrahedron (0,0,0), (1,0,0), (0,1,0), (0,0,1),
    /// // wound outward.
    /// let p = [[0.0f32, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
    /// let faces = [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]];
    /// let mut stl = vec![0u8; 80];
    /// stl.extend_from_slice(&4u32.to_le_bytes());
    /// for f in faces {
    ///     stl.extend_from_slice(&[0; 12]); // the normal, ignored
    ///     for i in f {
    ///         for x in p[i] {
    ///             stl.extend_from_slice(&x.to_le_bytes());
    ///         }
    ///     }
    ///     stl.extend_from_slice(&[0; 2]); // the attribute byte count
    /// }
    /// let m = TriMesh::<f64>::from_stl_bytes(&stl)?;
    /// // Twelve corners welded into four vertices.
    /// assert_eq!((m.vertex_count(), m.triangle_count()), (4, 4));
    /// assert!(m.is_closed() && m.signed_volume() > 0.0);
    ///
    /// let cut = TriMesh::<f64>::from_stl_bytes(&stl[..150]);
    /// assert_eq!(cut, Err(MeshError::StlLength { len: 150, triangles: Some(4) }));
    /// # Ok::<(), MeshError>(())
    /// ```
    pub fn from_stl_bytes(bytes: &[u8]) -> Result<Self, MeshError> {
        if let Some(n) = binary_count(bytes) {
            let expected = HEADER as u64 + FACET as u64 * u64::from(n);
            if bytes.len() as u64 == expected {
                // `n` facets fit in memory: the input holds them.
                return weld(binary_facets(bytes), n as usize);
            }
        }
        if !starts_with_solid(bytes) {
            return Err(length_error(bytes));
        }
        match ascii_facets(bytes) {
            Ok(facets) => {
                let n = facets.len();
                weld(facets.into_iter(), n)
            }
            // ASCII text has no NUL byte; binary coordinates nearly always
            // do: a `solid` header on a truncated binary file.
            Err(MeshError::StlSyntax { .. }) if bytes.contains(&0) => Err(length_error(bytes)),
            Err(e) => Err(e),
        }
    }

    /// Reads a mesh from an STL file
    /// ([`from_stl_bytes`](Self::from_stl_bytes)).
    ///
    /// # Errors
    /// [`MeshError::Io`] with the I/O error's kind when the file cannot be
    /// read; otherwise as [`from_stl_bytes`](Self::from_stl_bytes).
    #[cfg(feature = "std")]
    #[cfg_attr(docsrs, doc(cfg(feature = "std")))]
    pub fn load_stl<P: AsRef<std::path::Path>>(path: P) -> Result<Self, MeshError> {
        let bytes = std::fs::read(path).map_err(|e| MeshError::Io(e.kind()))?;
        Self::from_stl_bytes(&bytes)
    }
}

#[cfg(test)]
mod tests {
    use crate::{InputError, MeshError, Quantity, TriMesh};

    const TRIANGLE: &str = "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\n\
                            vertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\nendsolid t\n";

    fn syntax(text: &str) -> (usize, &'static str) {
        match TriMesh::<f64>::from_stl_bytes(text.as_bytes()) {
            Err(MeshError::StlSyntax { line, expected }) => (line, expected),
            other => panic!("expected an STL syntax error for {text:?}, got {other:?}"),
        }
    }

    #[test]
    fn ascii_dialect_and_errors() {
        let m = TriMesh::<f32>::from_stl_bytes(TRIANGLE.as_bytes()).unwrap();
        assert_eq!(m.triangles(), &[[0, 1, 2]], "one triangle");
        let loose = "  SOLID\n facet normal -nan nan inf outer loop vertex 0 0 0 vertex 1 0 0\n\
                     vertex 0 1 0 endloop endfacet endsolid\nsolid b\nendsolid b";
        assert_eq!(
            TriMesh::<f64>::from_stl_bytes(loose.as_bytes())
                .unwrap()
                .triangle_count(),
            1,
            "case, line breaks, NaN normals, two solids"
        );
        assert_eq!(syntax("solid x\n"), (1, "`facet` or `endsolid`"), "no end");
        assert_eq!(
            syntax(&TRIANGLE.replace("outer loop", "outer")),
            (4, "`outer loop`"),
            "half a keyword"
        );
        assert_eq!(
            syntax(&TRIANGLE.replace("1 0 0", "1 zero 0")),
            (5, "a number"),
            "bad number"
        );
        assert_eq!(
            syntax(&TRIANGLE.replace("endsolid t\n", "endsolid t\nfacet\n")),
            (10, "`solid`"),
            "content after the solid"
        );
        assert_eq!(
            TriMesh::<f64>::from_stl_bytes(TRIANGLE.replace("1 0 0", "1 1e39 0").as_bytes()),
            Err(MeshError::Vertex(InputError::NonFinite(Quantity::Vertex(
                1
            )))),
            "f32 overflow"
        );
        assert_eq!(
            TriMesh::<f32>::from_stl_bytes(TRIANGLE.replace("1 0 0", "1 1e30 0").as_bytes()),
            Err(MeshError::Vertex(InputError::TooLarge(Quantity::Vertex(1)))),
            "beyond MAX_INPUT"
        );
        assert_eq!(
            TriMesh::<f64>::from_stl_bytes(b"solid empty\nendsolid empty\n"),
            Err(MeshError::NoTriangles),
            "no facet"
        );
        let degenerate = TRIANGLE.replace("1 0 0", "-0 0 0");
        assert_eq!(
            TriMesh::<f64>::from_stl_bytes(degenerate.as_bytes()),
            Err(MeshError::NoTriangles),
            "-0 welds with 0: the only facet is dropped"
        );
    }

    #[test]
    fn binary_lengths() {
        assert_eq!(
            TriMesh::<f64>::from_stl_bytes(b""),
            Err(MeshError::StlLength {
                len: 0,
                triangles: None
            }),
            "empty input"
        );
        let mut empty = [0u8; 84].to_vec();
        assert_eq!(
            TriMesh::<f64>::from_stl_bytes(&empty),
            Err(MeshError::NoTriangles),
            "zero facets"
        );
        empty.push(0);
        assert_eq!(
            TriMesh::<f64>::from_stl_bytes(&empty),
            Err(MeshError::StlLength {
                len: 85,
                triangles: Some(0)
            }),
            "a byte too many"
        );
        let mut huge = b"solid".to_vec();
        huge.resize(80, b' ');
        huge.extend_from_slice(&u32::MAX.to_le_bytes());
        huge.extend_from_slice(&[0; 50]);
        assert_eq!(
            TriMesh::<f64>::from_stl_bytes(&huge),
            Err(MeshError::StlLength {
                len: 134,
                triangles: Some(u32::MAX)
            }),
            "a `solid` header on a short binary file, no allocation"
        );
        let e = TriMesh::<f64>::from_stl_bytes(&huge).unwrap_err();
        assert!(std::format!("{e}").starts_with("STL: "), "display: {e}");
    }
}
