//! Reading and writing the OFF format (Geomview's Object File Format, what
//! CGAL's data files use); the dialect is described at
//! `TriMesh::from_off_str`.

use alloc::string::String;
use alloc::vec::Vec;
use core::fmt;
use core::str::FromStr;

use crate::error::{check_components, Quantity};
use crate::mesh::{MeshError, OffError, OffErrorKind};
use crate::{Float, TriMesh};

/// The content lines of an OFF text: `(1-based line number, text before any
/// '#')`, blank ones skipped.
fn content_lines(text: &str) -> impl Iterator<Item = (usize, &str)> {
    text.lines().enumerate().filter_map(|(i, line)| {
        let line = line.split('#').next().unwrap_or("").trim();
        (!line.is_empty()).then_some((i + 1, line))
    })
}

fn err(line: usize, kind: OffErrorKind) -> MeshError {
    MeshError::Off(OffError { line, kind })
}

/// Parses the counts `V F [E]` from `tokens`.
fn parse_counts<'a>(mut tokens: impl Iterator<Item = &'a str>) -> Option<(usize, usize)> {
    let v = tokens.next()?.parse().ok()?;
    let f = tokens.next()?.parse().ok()?;
    // E is optional in practice and ignored, but must be an integer if there.
    if let Some(e) = tokens.next() {
        e.parse::<usize>().ok()?;
    }
    tokens.next().is_none().then_some((v, f))
}

impl<T: Float + FromStr> TriMesh<T> {
    /// Reads a mesh from OFF text:
    ///
    /// ```text
    /// OFF
    /// # comments run from '#' to the end of the line
    /// V F E            (counts: vertices, faces, edges; E is ignored)
    /// x y z            (V vertex lines)
    /// k i_0 ... i_k-1  (F face lines, 0-based vertex indices)
    /// ```
    ///
    /// The reader is line-based (one vertex or face per line, as every OFF
    /// file in practice writes them), accepts the counts on the header line
    /// (`OFF 8 6 12`), skips blank lines and comments, triangulates a polygon
    /// `k >= 4` as the fan `(i_0, i_j, i_j+1)`, ignores anything after a
    /// face's indices (face colours), and for the `COFF`, `NOFF` and `CNOFF`
    /// variants ignores the extra per-vertex values. It never panics, reports
    /// the first problem with its line number, and allocates in proportion
    /// to the text's length, not to the counts it announces.
    ///
    /// Numbers are parsed directly in `T` (correctly rounded, so `f32`
    /// meshes written by [`write_off`](Self::write_off) read back exactly).
    ///
    /// # Errors
    /// [`MeshError::Off`] with the line number and an [`OffErrorKind`] for
    /// malformed text, a vertex that is not finite or too large, or a bad
    /// index; [`MeshError::NoVertices`] / [`MeshError::NoTriangles`] for a
    /// well-formed file with zero counts.
    ///
    /// ```
    /// use motion_bound::{MeshError, OffErrorKind, TriMesh};
    /// let square = "OFF\n4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n";
    /// let m = TriMesh::<f64>::from_off_str(square)?;
    /// assert_eq!(m.triangles(), &[[0, 1, 2], [0, 2, 3]]);
    ///
    /// let bad = TriMesh::<f32>::from_off_str("OFF\n1 1 0\n0 0 zero\n3 0 0 0\n");
    /// assert!(matches!(bad, Err(MeshError::Off(e)) if e.line == 3
    ///     && e.kind == OffErrorKind::BadVertexLine));
    /// # Ok::<(), MeshError>(())
    /// ```
    pub fn from_off_str(text: &str) -> Result<Self, MeshError> {
        let mut lines = content_lines(text);
        let mut last_line = 0;

        // Header, possibly with the counts on the same line.
        let (line, header) = lines.next().ok_or(err(0, OffErrorKind::BadHeader))?;
        let mut tokens = header.split_whitespace();
        let extra_vertex_values = match tokens.next() {
            Some("OFF") => false,
            Some("COFF" | "NOFF" | "CNOFF") => true,
            _ => return Err(err(line, OffErrorKind::BadHeader)),
        };
        let rest: Vec<&str> = tokens.collect();
        let (count_line, (nv, nf)) = if rest.is_empty() {
            let (line, counts) = lines.next().ok_or(err(line, OffErrorKind::UnexpectedEnd))?;
            let c = parse_counts(counts.split_whitespace());
            (line, c.ok_or(err(line, OffErrorKind::BadCounts))?)
        } else {
            let c = parse_counts(rest.into_iter());
            (line, c.ok_or(err(line, OffErrorKind::BadCounts))?)
        };
        last_line = last_line.max(count_line);

        // A vertex line takes at least 6 bytes ("0 0 0\n"), a face line 8:
        // never reserve more than the text could hold.
        let mut vertices: Vec<[T; 3]> = Vec::with_capacity(nv.min(text.len() / 6));
        for _ in 0..nv {
            let (line, l) = lines
                .next()
                .ok_or(err(last_line, OffErrorKind::UnexpectedEnd))?;
            last_line = line;
            let mut tokens = l.split_whitespace();
            let mut v = [T::ZERO; 3];
            for x in &mut v {
                *x = tokens
                    .next()
                    .and_then(|t| t.parse::<T>().ok())
                    .ok_or(err(line, OffErrorKind::BadVertexLine))?;
            }
            if !extra_vertex_values && tokens.next().is_some() {
                return Err(err(line, OffErrorKind::TrailingTokens));
            }
            check_components(v, Quantity::Vertex(vertices.len()))
                .map_err(|e| err(line, OffErrorKind::BadVertex(e)))?;
            vertices.push(v);
        }

        let mut triangles: Vec<[u32; 3]> = Vec::with_capacity(nf.min(text.len() / 8));
        let mut polygon: Vec<u32> = Vec::new();
        for _ in 0..nf {
            let (line, l) = lines
                .next()
                .ok_or(err(last_line, OffErrorKind::UnexpectedEnd))?;
            last_line = line;
            let mut tokens = l.split_whitespace();
            let k: usize = tokens
                .next()
                .and_then(|t| t.parse().ok())
                .ok_or(err(line, OffErrorKind::BadFaceLine))?;
            if k < 3 {
                return Err(err(line, OffErrorKind::FaceTooSmall(k)));
            }
            polygon.clear();
            for _ in 0..k {
                let index: u32 = tokens
                    .next()
                    .and_then(|t| t.parse().ok())
                    .ok_or(err(line, OffErrorKind::BadFaceLine))?;
                if index as usize >= nv {
                    return Err(err(
                        line,
                        OffErrorKind::IndexOutOfRange {
                            index,
                            vertex_count: nv,
                        },
                    ));
                }
                polygon.push(index);
            }
            // Anything after the indices (a face colour) is ignored.
            if let [first, rest @ ..] = polygon.as_slice() {
                for pair in rest.windows(2) {
                    triangles.push([*first, pair[0], pair[1]]);
                }
            }
        }

        if let Some((line, _)) = lines.next() {
            return Err(err(line, OffErrorKind::TrailingContent));
        }
        Self::try_new(vertices, triangles)
    }
}

impl<T: Float> TriMesh<T> {
    /// Writes the mesh as OFF: the header, `V F 0`, one vertex per line with
    /// each coordinate in Rust's shortest round-trip form (so
    /// [`from_off_str`](Self::from_off_str) reads back the same bits), and
    /// one `3 a b c` line per triangle.
    ///
    /// # Errors
    /// Only those of `out`.
    ///
    /// ```
    /// use motion_bound::TriMesh;
    /// let m = TriMesh::try_new(vec![[0.1f32, 0.0, -1e-30]; 3], vec![[0, 1, 2]])?;
    /// let text = m.to_off_string();
    /// assert_eq!(text, "OFF\n3 1 0\n0.1 0.0 -1e-30\n0.1 0.0 -1e-30\n0.1 0.0 -1e-30\n3 0 1 2\n");
    /// assert_eq!(TriMesh::from_off_str(&text)?, m);
    /// # Ok::<(), motion_bound::MeshError>(())
    /// ```
    pub fn write_off<W: fmt::Write>(&self, out: &mut W) -> fmt::Result {
        writeln!(out, "OFF")?;
        writeln!(out, "{} {} 0", self.vertex_count(), self.triangle_count())?;
        for v in self.vertices() {
            // Debug is the shortest representation that parses back to the
            // same value, with an exponent for very large or small numbers.
            writeln!(out, "{:?} {:?} {:?}", v[0], v[1], v[2])?;
        }
        for t in self.triangles() {
            writeln!(out, "3 {} {} {}", t[0], t[1], t[2])?;
        }
        Ok(())
    }

    /// The mesh as OFF text ([`write_off`](Self::write_off) into a `String`).
    #[must_use]
    pub fn to_off_string(&self) -> String {
        let mut s = String::new();
        // Writing to a String cannot fail.
        let _ = self.write_off(&mut s);
        s
    }
}

#[cfg(test)]
mod tests {
    use crate::{InputError, MeshError, OffError, OffErrorKind, Quantity, TriMesh};

    fn kind_at(text: &str) -> (usize, OffErrorKind) {
        match TriMesh::<f64>::from_off_str(text) {
            Err(MeshError::Off(OffError { line, kind })) => (line, kind),
            other => panic!("expected an OFF error for {text:?}, got {other:?}"),
        }
    }

    #[test]
    fn each_malformation_has_its_error_and_line() {
        use OffErrorKind::*;
        assert_eq!(kind_at(""), (0, BadHeader), "empty");
        assert_eq!(
            kind_at("# only a comment\n"),
            (0, BadHeader),
            "comment only"
        );
        assert_eq!(kind_at("PLY\n"), (1, BadHeader), "not OFF");
        assert_eq!(kind_at("OFF\n"), (1, UnexpectedEnd), "no counts");
        assert_eq!(kind_at("OFF\n3 x 0\n"), (2, BadCounts), "bad counts");
        assert_eq!(kind_at("OFF\n3 1 0 7\n"), (2, BadCounts), "four counts");
        assert_eq!(kind_at("OFF\n-3 1 0\n"), (2, BadCounts), "negative");
        assert_eq!(
            kind_at("OFF 1 1\n0 0\n"),
            (2, BadVertexLine),
            "short vertex"
        );
        assert_eq!(
            kind_at("OFF\n1 1 0\n0 0 0 1\n"),
            (3, TrailingTokens),
            "4 coordinates"
        );
        assert_eq!(
            kind_at("OFF\n1 1 0\n\n# c\n0 1e999 0\n"),
            (5, BadVertex(InputError::NonFinite(Quantity::Vertex(0)))),
            "overflowing number"
        );
        assert_eq!(
            kind_at("OFF\n1 1 0\n0 nan 0\n"),
            (3, BadVertex(InputError::NonFinite(Quantity::Vertex(0)))),
            "NaN"
        );
        assert_eq!(
            kind_at("OFF\n1 1 0\n0 1e300 0\n"),
            (3, BadVertex(InputError::TooLarge(Quantity::Vertex(0)))),
            "too large"
        );
        let v3 = "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n";
        assert_eq!(kind_at(v3), (5, UnexpectedEnd), "missing face");
        assert_eq!(
            kind_at(&format!("{v3}2 0 1\n")),
            (6, FaceTooSmall(2)),
            "edge"
        );
        assert_eq!(
            kind_at(&format!("{v3}3 0 1\n")),
            (6, BadFaceLine),
            "short face"
        );
        assert_eq!(
            kind_at(&format!("{v3}3 0 -1 2\n")),
            (6, BadFaceLine),
            "negative"
        );
        assert_eq!(
            kind_at(&format!("{v3}3 0 1 3\n")),
            (
                6,
                IndexOutOfRange {
                    index: 3,
                    vertex_count: 3
                }
            ),
            "index out of range"
        );
        assert_eq!(
            kind_at(&format!("{v3}3 0 1 2\n3 0 1 2\n")),
            (7, TrailingContent),
            "extra face"
        );
        assert_eq!(
            kind_at("OFF\n99999999999999 1 0\n"),
            (2, UnexpectedEnd),
            "huge count, no allocation"
        );
    }

    #[test]
    fn dialect_features() {
        let text = "# a comment first\nOFF 4 2 5 # counts on the header\n\n\
                    0 0 0\n1 0 0 # trailing comment\n1 1 0\n0 1 0\n\
                    3 0 1 2 255 0 0\n3   0 2 3\n";
        let m = TriMesh::<f32>::from_off_str(text).unwrap();
        assert_eq!(m.triangles(), &[[0, 1, 2], [0, 2, 3]], "faces with colour");
        let coff = "COFF\n3 1 0\n0 0 0 1 0 0 1\n1 0 0 1 0 0 1\n0 1 0 1 0 0 1\n3 0 1 2\n";
        assert_eq!(
            TriMesh::<f64>::from_off_str(coff).unwrap().vertex_count(),
            3,
            "COFF colours ignored"
        );
        let hexagon = "OFF\n6 1 0\n1 0 0\n2 0 0\n3 1 0\n2 2 0\n1 2 0\n0 1 0\n6 0 1 2 3 4 5\n";
        let m = TriMesh::<f64>::from_off_str(hexagon).unwrap();
        assert_eq!(m.triangle_count(), 4, "fan of k - 2 triangles");
        assert_eq!(
            TriMesh::<f64>::from_off_str("OFF\n0 0 0\n"),
            Err(MeshError::NoVertices),
            "zero counts"
        );
        assert_eq!(
            TriMesh::<f64>::from_off_str("OFF\n1 0 0\n0 0 0\n"),
            Err(MeshError::NoTriangles),
            "no face"
        );
    }
}
