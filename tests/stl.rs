//! The STL reader: binary and ASCII give the same welded mesh, bad input
//! gives typed errors, the shipped KUKA iiwa link loads, and random
//! triangle soups written as binary (and ASCII) STL read back as the same
//! triangles.

use std::collections::BTreeSet;
use std::fmt::Write as _;
use std::path::PathBuf;

use motion_bound::{InputError, MeshError, Quantity, TriMesh};
use proptest::prelude::*;

type Facet = [[f32; 3]; 3];

/// The tetrahedron (0,0,0), (1,0,0), (0,1,0), (0,0,1), wound outward, as a
/// soup of four facets.
fn tetrahedron() -> Vec<Facet> {
    let p = [
        [0.0f32, 0.0, 0.0],
        [1.0, 0.0, 0.0],
        [0.0, 1.0, 0.0],
        [0.0, 0.0, 1.0],
    ];
    [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]]
        .iter()
        .map(|f| f.map(|i| p[i]))
        .collect()
}

/// Binary STL: an 80-byte header, the count, 50 bytes per facet.
fn binary(header: &[u8; 80], facets: &[Facet]) -> Vec<u8> {
    let mut out = header.to_vec();
    let n = u32::try_from(facets.len()).expect("few facets");
    out.extend_from_slice(&n.to_le_bytes());
    for f in facets {
        // A made-up normal: the reader ignores it.
        for x in [0.0f32, 0.0, 1.0] {
            out.extend_from_slice(&x.to_le_bytes());
        }
        for x in f.iter().flatten() {
            out.extend_from_slice(&x.to_le_bytes());
        }
        out.extend_from_slice(&[0; 2]);
    }
    out
}

/// ASCII STL with each coordinate in Rust's shortest round-trip form.
fn ascii(facets: &[Facet]) -> String {
    let mut s = String::from("solid soup\n");
    for f in facets {
        s.push_str("  facet normal 0 0 1\n    outer loop\n");
        for [x, y, z] in f {
            writeln!(s, "      vertex {x:?} {y:?} {z:?}").expect("writing to a String");
        }
        s.push_str("    endloop\n  endfacet\n");
    }
    s.push_str("endsolid soup\n");
    s
}

fn header(text: &[u8]) -> [u8; 80] {
    let mut h = [b' '; 80];
    h[..text.len()].copy_from_slice(text);
    h
}

#[test]
fn binary_and_ascii_tetrahedra_are_the_same_mesh() {
    let soup = tetrahedron();
    let from_binary = TriMesh::<f64>::from_stl_bytes(&binary(&header(b"tetra"), &soup))
        .expect("binary tetrahedron");
    // Binary files that start with `solid` are still binary.
    let from_solid_binary = TriMesh::<f64>::from_stl_bytes(&binary(&header(b"solid tetra"), &soup))
        .expect("binary tetrahedron with a `solid` header");
    let from_ascii =
        TriMesh::<f64>::from_stl_bytes(ascii(&soup).as_bytes()).expect("ASCII tetrahedron");
    assert_eq!(
        (from_binary.vertex_count(), from_binary.triangle_count()),
        (4, 4),
        "twelve corners welded into four vertices"
    );
    assert_eq!(from_ascii, from_binary, "ASCII and binary agree");
    assert_eq!(
        from_solid_binary, from_binary,
        "a `solid` header does not matter"
    );
    assert!(from_binary.is_closed(), "the tetrahedron is closed");
    assert!(
        (from_binary.signed_volume() - 1.0 / 6.0).abs() < 1e-15,
        "outward, volume 1/6"
    );
}

#[test]
fn bad_input_gives_typed_errors() {
    let soup = tetrahedron();
    for head in [header(b"tetra"), header(b"solid tetra")] {
        let good = binary(&head, &soup);
        let cut = &good[..good.len() - 1];
        assert_eq!(
            TriMesh::<f64>::from_stl_bytes(cut),
            Err(MeshError::StlLength {
                len: 283,
                triangles: Some(4)
            }),
            "truncated by a byte"
        );
        let mut long = good.clone();
        long.push(0);
        assert!(
            matches!(
                TriMesh::<f64>::from_stl_bytes(&long),
                Err(MeshError::StlLength { len: 285, .. })
            ),
            "a byte after the last facet"
        );
        // Shorter than the header: without a NUL byte in it, the header's
        // first 50 bytes are text, and with `solid` at the start they are
        // (bad) ASCII STL.
        let short = TriMesh::<f64>::from_stl_bytes(&good[..50]);
        if head.starts_with(b"solid") {
            assert_eq!(
                short,
                Err(MeshError::StlSyntax {
                    line: 1,
                    expected: "`facet` or `endsolid`"
                }),
                "a `solid` header alone"
            );
        } else {
            assert_eq!(
                short,
                Err(MeshError::StlLength {
                    len: 50,
                    triangles: None
                }),
                "shorter than the header"
            );
        }
    }

    assert_eq!(
        TriMesh::<f64>::from_stl_bytes(b"garbage"),
        Err(MeshError::StlLength {
            len: 7,
            triangles: None
        }),
        "garbage"
    );
    let garbage: Vec<u8> = (0..=255u8).cycle().take(1000).collect();
    assert!(
        matches!(
            TriMesh::<f64>::from_stl_bytes(&garbage),
            Err(MeshError::StlLength { len: 1000, .. })
        ),
        "binary garbage"
    );
    assert_eq!(
        TriMesh::<f64>::from_stl_bytes(b"solid x\n  facet normal 0 0 1\n    outer loop\n loop"),
        Err(MeshError::StlSyntax {
            line: 4,
            expected: "`vertex`"
        }),
        "ASCII garbage"
    );
    let text = ascii(&soup).replace("vertex 1.0 0.0 0.0", "vertex 1.0 0.0");
    assert!(
        matches!(
            TriMesh::<f64>::from_stl_bytes(text.as_bytes()),
            Err(MeshError::StlSyntax {
                expected: "a number",
                ..
            })
        ),
        "two coordinates"
    );

    // NaN and infinity in either format; the index counts the file's corners.
    let mut nan = soup.clone();
    nan[1][2][0] = f32::NAN;
    let expected = MeshError::Vertex(InputError::NonFinite(Quantity::Vertex(5)));
    assert_eq!(
        TriMesh::<f64>::from_stl_bytes(&binary(&header(b""), &nan)),
        Err(expected.clone()),
        "binary NaN"
    );
    assert_eq!(
        TriMesh::<f32>::from_stl_bytes(ascii(&nan).as_bytes()),
        Err(expected),
        "ASCII NaN"
    );
    let mut inf = soup.clone();
    inf[0][0][2] = f32::NEG_INFINITY;
    assert_eq!(
        TriMesh::<f64>::from_stl_bytes(&binary(&header(b""), &inf)),
        Err(MeshError::Vertex(InputError::NonFinite(Quantity::Vertex(
            0
        )))),
        "binary infinity"
    );

    // Empty meshes.
    assert_eq!(
        TriMesh::<f64>::from_stl_bytes(&binary(&header(b""), &[])),
        Err(MeshError::NoTriangles),
        "binary, no facet"
    );
    assert_eq!(
        TriMesh::<f64>::from_stl_bytes(b"solid empty\nendsolid empty\n"),
        Err(MeshError::NoTriangles),
        "ASCII, no facet"
    );
    let flat = [[[1.0f32, 2.0, 3.0], [1.0, 2.0, 3.0], [0.0, 0.0, 0.0]]];
    assert_eq!(
        TriMesh::<f64>::from_stl_bytes(&binary(&header(b""), &flat)),
        Err(MeshError::NoTriangles),
        "only a degenerate facet"
    );

    assert_eq!(
        TriMesh::<f64>::load_stl("/nonexistent/x.stl"),
        Err(MeshError::Io(std::io::ErrorKind::NotFound)),
        "missing file"
    );
}

fn shipped(path: &str) -> PathBuf {
    PathBuf::from(concat!(env!("CARGO_MANIFEST_DIR"), "/..")).join(path)
}

/// The KUKA iiwa's link 1 as shipped (`data/arms/kuka_iiwa/meshes/link_1.stl`,
/// a Blender export) is not closed: exact welding leaves 85 unpaired edges
/// (holes and cracks in the collision mesh, not near-duplicate vertices:
/// most of their endpoints have no other vertex within micrometres). It is
/// manifold and consistently wound where its triangles meet, and no facet
/// is degenerate.
#[test]
fn kuka_iiwa_link_1_loads() {
    let path = shipped("data/arms/kuka_iiwa/meshes/link_1.stl");
    let m = TriMesh::<f64>::load_stl(&path).expect("link_1.stl loads");

    // The header's count, and the degenerate facets counted independently.
    let bytes = std::fs::read(&path).expect("link_1.stl reads");
    let count = u32::from_le_bytes(bytes[80..84].try_into().expect("4 bytes"));
    assert_eq!(count, 2759, "the header's facet count");
    assert_eq!(bytes.len(), 84 + 50 * 2759, "a binary file");
    let degenerate = bytes[84..]
        .chunks_exact(50)
        .filter(|facet| {
            let corner = |k: usize| {
                let at = 12 + 12 * k;
                key([0, 4, 8].map(|o| {
                    f32::from_le_bytes(facet[at + o..at + o + 4].try_into().expect("4 bytes"))
                }))
            };
            let [a, b, c] = [corner(0), corner(1), corner(2)];
            a == b || b == c || c == a
        })
        .count();

    let report = m.edge_report();
    println!(
        "link_1.stl: {} vertices, {} triangles, {degenerate} degenerate facets dropped, \
         signed volume {:.6e}, {report:?}",
        m.vertex_count(),
        m.triangle_count(),
        m.signed_volume()
    );
    assert_eq!(
        m.triangle_count(),
        2759 - degenerate,
        "every facet but the degenerate ones"
    );
    assert_eq!(degenerate, 0, "no facet is degenerate");
    assert_eq!(m.vertex_count(), 1407, "welded vertices");
    if !report.is_closed() {
        assert_eq!(
            (
                report.unpaired,
                report.repeated,
                report.degenerate_triangles
            ),
            (85, 0, 0),
            "open as shipped, but manifold and consistently wound"
        );
    }
    assert_eq!(
        TriMesh::<f32>::load_stl(&path).expect("link_1.stl loads as f32"),
        m.try_convert::<f32>().expect("f32 coordinates"),
        "f32 and f64 read the same coordinates"
    );
}

fn config() -> ProptestConfig {
    let cases = std::env::var("PROPTEST_CASES")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(512);
    ProptestConfig::with_cases(cases)
}

/// Coordinates from a small grid (so corners repeat, facets share
/// vertices, and some facets are degenerate), signed zeros, and arbitrary
/// finite values within the mesh's input range.
fn coordinate() -> impl Strategy<Value = f32> + Clone {
    prop_oneof![
        4 => (-2i8..=2).prop_map(f32::from),
        1 => Just(-0.0f32),
        2 => -1e17f32..1e17f32,
    ]
}

fn soup() -> impl Strategy<Value = Vec<Facet>> {
    let point = [coordinate(), coordinate(), coordinate()];
    prop::collection::vec([point.clone(), point.clone(), point], 1..40)
}

/// The key the reader welds on: the coordinates' bits, with -0 as 0.
fn key(p: [f32; 3]) -> [u32; 3] {
    p.map(|x| (x + 0.0).to_bits())
}

proptest! {
    #![proptest_config(config())]

    #[test]
    fn soups_round_trip(soup in soup()) {
        let kept: Vec<Facet> = soup
            .iter()
            .copied()
            .filter(|f| {
                let [a, b, c] = f.map(key);
                a != b && b != c && c != a
            })
            .collect();
        let read = TriMesh::<f64>::from_stl_bytes(&binary(&header(b"solid soup"), &soup));
        if kept.is_empty() {
            prop_assert_eq!(read, Err(MeshError::NoTriangles), "all facets degenerate");
            return Ok(());
        }
        let m = read.expect("a valid soup reads");
        let corners: Vec<[[f64; 3]; 3]> = m.triangle_corners().collect();
        let expected: Vec<[[f64; 3]; 3]> =
            kept.iter().map(|f| f.map(|p| p.map(f64::from))).collect();
        prop_assert_eq!(corners, expected, "the same triangles, in order");
        let distinct: BTreeSet<[u32; 3]> = kept.iter().flatten().map(|&p| key(p)).collect();
        prop_assert_eq!(m.vertex_count(), distinct.len(), "one vertex per distinct corner");
        let from_ascii = TriMesh::<f64>::from_stl_bytes(ascii(&soup).as_bytes());
        prop_assert_eq!(from_ascii, Ok(m), "ASCII reads the same mesh");
    }

    #[test]
    fn arbitrary_bytes_never_panic(bytes in prop::collection::vec(any::<u8>(), 0..400)) {
        let _ = TriMesh::<f32>::from_stl_bytes(&bytes);
        let mut solid = b"solid ".to_vec();
        solid.extend_from_slice(&bytes);
        let _ = TriMesh::<f64>::from_stl_bytes(&solid);
    }
}
