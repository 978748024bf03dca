//! Parry's solid meshes (`TriMeshFlags::ORIENTED`) are `motion-bound`'s
//! solid meshes (`TriMesh::try_solid`, `proofs/09-ca-toi.md`, Lemma 9.7): a
//! ball, a box and a non-convex mesh (a torus knot) starting inside a closed,
//! outward-wound mesh flagged `ORIENTED` (a box, and a torus: non-convex)
//! are hit at the start; without the flag (a surface) they pass; a mesh
//! flagged `ORIENTED` that is not closed, or is wound inward, is
//! `CastError::NotSolid`, which the dispatcher hands to parry.

use motion_bound::bodies::{cuboid, torus, torus_knot};
use motion_bound::TriMesh as OurMesh;
use motion_bound_parry::{cast_shapes_nonlinear, CastError, CertifiedDispatcher, ShapeCache};
use parry3d_f64::math::{Pose, Vector};
use parry3d_f64::query::{NonlinearRigidMotion, QueryDispatcher, ShapeCastStatus};
use parry3d_f64::shape::{Ball, Cuboid, SharedShape, TriMeshFlags};

fn parry_mesh(m: &OurMesh<f64>, flags: TriMeshFlags) -> SharedShape {
    let v = m
        .vertices()
        .iter()
        .map(|p| Vector::new(p[0], p[1], p[2]))
        .collect();
    SharedShape::trimesh_with_flags(v, m.triangles().to_vec(), flags).expect("a parry mesh")
}

fn drifting(at: Vector) -> NonlinearRigidMotion {
    NonlinearRigidMotion::new(
        Pose::from_translation(at),
        Vector::ZERO,
        Vector::new(0.05, 0.0, 0.0),
        Vector::new(1.0, 2.0, 3.0),
    )
}

#[test]
fn a_ball_a_box_and_a_knot_inside_an_oriented_mesh_are_hit_at_the_start() {
    let knot = torus_knot::<f64>(2, 3, 64, 8, 0.06, 0.03, 0.012).unwrap();
    let inner = [
        ("ball", SharedShape::new(Ball::new(0.08))),
        (
            "box",
            SharedShape::new(Cuboid::new(Vector::new(0.08, 0.04, 0.06))),
        ),
        ("knot", parry_mesh(&knot, TriMeshFlags::empty())),
        ("solid knot", parry_mesh(&knot, TriMeshFlags::ORIENTED)),
    ];
    let box_mesh = cuboid::<f64>([2.0, 2.0, 2.0]).unwrap();
    let ring = torus::<f64>(1.0, 0.4, 48, 24).unwrap();
    let in_ring = [1.0, 0.0, 0.0];
    assert_eq!(ring.winding_number(in_ring), Some(1), "inside the tube");
    let cache = ShapeCache::new();
    for (name, mesh, at) in [
        ("box", &box_mesh, Vector::new(0.3, -0.2, 0.1)),
        (
            "torus",
            &ring,
            Vector::new(in_ring[0], in_ring[1], in_ring[2]),
        ),
    ] {
        for (flags, solid) in [
            (TriMeshFlags::ORIENTED, true),
            (TriMeshFlags::empty(), false),
        ] {
            let container = parry_mesh(mesh, flags);
            cache.register(&container);
            let still = NonlinearRigidMotion::constant_position(Pose::IDENTITY);
            for (inner_name, body) in &inner {
                for first in [true, false] {
                    let (m1, g1, m2, g2) = if first {
                        (&still, &container, &drifting(at), body)
                    } else {
                        (&drifting(at), body, &still, &container)
                    };
                    for cached in [true, false] {
                        let hit = if cached {
                            cache.cast_shapes_nonlinear(
                                m1,
                                g1.as_ref(),
                                m2,
                                g2.as_ref(),
                                0.0,
                                1.0,
                                true,
                                &Default::default(),
                            )
                        } else {
                            cast_shapes_nonlinear(m1, g1.as_ref(), m2, g2.as_ref(), 0.0, 1.0, true)
                        }
                        .expect("a certified answer");
                        let what =
                            format!("{inner_name} in the {name} (solid {solid}, first {first})");
                        if solid {
                            let hit = hit.unwrap_or_else(|| panic!("{what}: missed"));
                            assert_eq!(hit.time_of_impact, 0.0, "{what}");
                            assert_eq!(
                                hit.status,
                                ShapeCastStatus::PenetratingOrWithinTargetDist,
                                "{what}"
                            );
                        } else {
                            assert!(hit.is_none(), "{what}: {hit:?}");
                        }
                    }
                }
            }
        }
    }
}

#[test]
fn an_oriented_mesh_that_is_open_or_inward_is_refused_and_parry_answers() {
    let b = cuboid::<f64>([2.0, 2.0, 2.0]).unwrap();
    let (v, t) = b.clone().into_parts();
    let open = OurMesh::try_new(v.clone(), t[..11].to_vec()).unwrap();
    let inward = OurMesh::try_new(v, t.iter().map(|&[a, b, c]| [a, c, b]).collect()).unwrap();
    let ball = Ball::new(0.1);
    let still = NonlinearRigidMotion::constant_position(Pose::IDENTITY);
    let moving = drifting(Vector::new(0.2, 0.0, 0.0));
    for (mesh, closed) in [(&open, false), (&inward, true)] {
        let solid = parry_mesh(mesh, TriMeshFlags::ORIENTED);
        let r = cast_shapes_nonlinear(&still, solid.as_ref(), &moving, &ball, 0.0, 1.0, true);
        let e = r.expect_err("refused");
        assert_eq!(e, CastError::NotSolid { closed }, "closed {closed}");
        assert!(e.to_string().contains("ORIENTED"), "{e}");
        // Without the flag: a surface the ball inside never meets.
        let hollow = parry_mesh(mesh, TriMeshFlags::empty());
        let r = cast_shapes_nonlinear(&still, hollow.as_ref(), &moving, &ball, 0.0, 1.0, true);
        assert!(matches!(r, Ok(None)), "hollow, closed {closed}: {r:?}");
        // The dispatcher hands the refused mesh to parry.
        let dispatcher = CertifiedDispatcher::new();
        let _ = dispatcher.cast_shapes_nonlinear(
            &still,
            solid.as_ref(),
            &moving,
            &ball,
            0.0,
            1.0,
            true,
        );
        assert_eq!(dispatcher.stats().handed_to_parry, 1, "closed {closed}");
    }
}
