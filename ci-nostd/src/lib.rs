//! A `#![no_std]` crate with no allocator that uses motion-bound's bounds:
//! if the library needed `std` or `alloc`, this would not compile.
#![no_std]

use motion_bound::{evq, nevq, Direction, RigidMotion, VertexSet};

/// EVQ and NEVQ speed bounds of a small body, or `None` on invalid input.
pub fn bounds(vertices: &[[f32; 3]], v: [f32; 3], w: [f32; 3], n: [f32; 3]) -> Option<(f32, f32)> {
    let body = VertexSet::try_new(vertices).ok()?;
    let motion = RigidMotion::try_from_arrays([0.0; 3], v, w).ok()?;
    let n = Direction::try_from_array(n).ok()?;
    Some((
        evq(&body, &motion, n).speed,
        nevq(&body.summary(), &motion, n).speed,
    ))
}

/// Conservative advancement of two convex bodies with the caller's own
/// distance oracle (here: the closest pair of vertices, exact for the
/// face-to-face boxes of this check), without `std` or `alloc`: the first
/// contact time, or `None`.
pub fn time_of_impact(
    a: &[[f32; 3]],
    b: &[[f32; 3]],
    va: [f32; 3],
    wa: [f32; 3],
    xb: [f32; 3],
) -> Option<f32> {
    use motion_bound::ca::{self, CaParams, VertexSetPair, Witness};
    use motion_bound::{Point3, Pose};
    let oracle = |pa: &Pose<f32>, pb: &Pose<f32>| {
        let mut best: Option<Witness<f32>> = None;
        for p in a {
            for q in b {
                let (x, y) = (
                    pa.transform_point(*p),
                    pb.transform_point(*q),
                );
                let d = (y - x).length();
                if best.is_none_or(|w| d < w.distance) {
                    best = Some(Witness::new(d, Point3::from_vec3(x), Point3::from_vec3(y)));
                }
            }
        }
        best
    };
    let (sa, sb) = (VertexSet::try_new(a).ok()?, VertexSet::try_new(b).ok()?);
    let ma = RigidMotion::try_from_arrays([0.0; 3], va, wa).ok()?;
    let mb = RigidMotion::try_from_arrays(xb, [0.0; 3], [0.0; 3]).ok()?;
    let report = ca::time_of_impact(
        &mut VertexSetPair::new(sa, sb, oracle),
        &ma,
        &mb,
        &CaParams::default(),
    )
    .ok()?;
    report.outcome.contact().map(|c| c.time)
}
