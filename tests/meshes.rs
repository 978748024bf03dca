//! The shipped meshes load with the counts their sources declare and are
//! closed and outward-wound; the generated trefoil is sized like CGAL's knot.

#[path = "common/meshes.rs"]
mod meshes;

use meshes::{load_shipped, SHIPPED};
use motion_bound::bodies::{TorusKnot, TorusKnotSize};
use motion_bound::TriMesh;

#[test]
fn shipped_meshes_have_their_declared_counts_and_are_closed() {
    for s in SHIPPED {
        let m = load_shipped(s.name);
        assert_eq!(
            (m.vertex_count(), m.triangle_count()),
            (s.vertices, s.triangles),
            "{}: counts",
            s.name
        );
        let r = m.edge_report();
        assert!(r.is_closed(), "{}: not closed: {r:?}", s.name);
        assert!(m.signed_volume() > 0.0, "{}: not outward-wound", s.name);
        // As a body: recentred on its centre of mass, usable by the bounds.
        let c = m.volume_centroid().expect("closed meshes have a centroid");
        let body = m.recentred(c).expect("recentring stays in range");
        assert!(
            body.vertex_set().summary().max_radius() > 0.0,
            "{}: radius",
            s.name
        );
    }
}

#[test]
fn shipped_meshes_survive_an_off_round_trip() {
    let m = load_shipped("bunny-npm-3674.obj.gz");
    let back = TriMesh::from_off_str(&m.to_off_string()).unwrap();
    assert_eq!(back, m, "OBJ -> OFF -> mesh is the identity");
}

/// Extent, volume and area of a mesh, for the knot comparison.
struct Shape {
    radius_xy: f64,
    half_height: f64,
    volume: f64,
    area: f64,
}

fn shape(m: &TriMesh<f64>) -> Shape {
    let radius_xy = m
        .vertices()
        .iter()
        .map(|v| v[0].hypot(v[1]))
        .fold(0.0, f64::max);
    let half_height = m.vertices().iter().map(|v| v[2].abs()).fold(0.0, f64::max);
    Shape {
        radius_xy,
        half_height,
        volume: m.signed_volume(),
        area: m.surface_area(),
    }
}

fn report(name: &str, s: &Shape) {
    println!(
        "{name:>22}: radius about z {:.4}, half-height {:.4}, volume {:.4}, area {:.4}",
        s.radius_xy, s.half_height, s.volume, s.area
    );
}

#[test]
fn generated_knots_are_sized_like_cgals() {
    let cgal = load_shipped("knot.off.gz");
    let c = shape(&cgal);
    report("CGAL knot.off", &c);
    // CGAL's knot is centred on the origin with its axis along z.
    let centre = cgal.volume_centroid().unwrap();
    assert!(
        centre.iter().all(|x| x.abs() < 1e-3),
        "CGAL knot centred: {centre:?}"
    );
    let trefoil = TorusKnotSize::K2_8.mesh::<f64>().unwrap();
    let t = shape(&trefoil);
    report("trefoil K2_8", &t);
    let coil = TorusKnot::CGAL_COIL.mesh::<f64>(140, 10).unwrap();
    let k = shape(&coil);
    report("CGAL_COIL 140 x 10", &k);
    let within = |a: f64, b: f64, tol: f64| (a / b - 1.0).abs() < tol;
    for (name, s) in [("trefoil", &t), ("coil", &k)] {
        // Both fill the same cylinder and volume (documented at TREFOIL)...
        assert!(within(s.radius_xy, c.radius_xy, 0.01), "{name}: radius");
        assert!(within(s.half_height, c.half_height, 0.01), "{name}: height");
        assert!(within(s.volume, c.volume, 0.01), "{name}: volume");
        // ...with a longer, thinner tube than CGAL's non-circular one.
        assert!(
            s.area > c.area && within(s.area, c.area, 0.12),
            "{name}: area"
        );
    }
}

/// The number of closed curves in which the plane `d(p) = 0` cuts the mesh,
/// counting only curves through points where `keep` holds (to cut by a
/// half-plane). Each triangle crossing the plane joins its two crossing
/// edges; the curves are the connected groups of crossing edges.
fn section_curves(
    m: &TriMesh<f64>,
    d: impl Fn([f64; 3]) -> f64,
    keep: impl Fn([f64; 3]) -> bool,
) -> usize {
    use std::collections::HashMap;
    let side: Vec<bool> = m.vertices().iter().map(|&v| d(v) < 0.0).collect();
    let mut id: HashMap<(u32, u32), usize> = HashMap::new();
    let mut parent: Vec<usize> = Vec::new();
    let mut point: Vec<[f64; 3]> = Vec::new();
    fn find(parent: &mut [usize], mut i: usize) -> usize {
        while parent[i] != i {
            parent[i] = parent[parent[i]];
            i = parent[i];
        }
        i
    }
    for &[a, b, c] in m.triangles() {
        let mut crossing = Vec::new();
        for (x, y) in [(a, b), (b, c), (c, a)] {
            if side[x as usize] != side[y as usize] {
                let key = (x.min(y), x.max(y));
                let next = parent.len();
                let i = *id.entry(key).or_insert_with(|| {
                    parent.push(next);
                    let (p, q) = (m.vertices()[x as usize], m.vertices()[y as usize]);
                    let s = d(p) / (d(p) - d(q));
                    point.push([0, 1, 2].map(|k| p[k] + s * (q[k] - p[k])));
                    next
                });
                crossing.push(i);
            }
        }
        if let [i, j] = crossing[..] {
            let (ri, rj) = (find(&mut parent, i), find(&mut parent, j));
            parent[ri] = rj;
        }
    }
    let mut roots: Vec<usize> = (0..parent.len())
        .filter(|&i| keep(point[i]))
        .map(|i| find(&mut parent, i))
        .collect();
    roots.sort_unstable();
    roots.dedup();
    roots.len()
}

/// `(curves cut by each of 12 half-planes through the z axis, curves cut by
/// the plane z = 0)`: for a `(p, q)` torus knot about z, `(p, 2 q)`.
fn windings(m: &TriMesh<f64>) -> (Vec<usize>, usize) {
    let half_planes = (0..12)
        .map(|i| {
            let a = std::f64::consts::PI * f64::from(i) / 6.0 + 0.01;
            let (s, c) = a.sin_cos();
            section_curves(m, |v| c * v[1] - s * v[0], |v| c * v[0] + s * v[1] > 0.0)
        })
        .collect();
    (half_planes, section_curves(m, |v| v[2], |_| true))
}

#[test]
fn cgals_knot_is_a_one_four_coil() {
    let (half, equator) = windings(&load_shipped("knot.off.gz"));
    assert_eq!((half, equator), (vec![1; 12], 8), "CGAL knot.off");
    let coil = TorusKnot::CGAL_COIL.mesh::<f64>(140, 10).unwrap();
    assert_eq!(windings(&coil), (vec![1; 12], 8), "CGAL_COIL");
    let trefoil = TorusKnotSize::K2_8.mesh::<f64>().unwrap();
    assert_eq!(windings(&trefoil), (vec![2; 12], 6), "trefoil");
}
