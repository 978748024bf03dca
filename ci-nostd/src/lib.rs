//! A `#![no_std]` crate with no allocator that uses motion-bound's bounds:
//! if the library needed `std` or `alloc`, this would not compile.
#![no_std]

use motion_bound::{evq, nevq, Direction, RigidMotion, VertexSet};

/// EVQ and NEVQ speed bounds of a small body, or `None` on invalid input.
pub fn bounds(vertices: &[[f32; 3]], v: [f32; 3], w: [f32; 3], n: [f32; 3]) -> Option<(f32, f32)> {
    let body = VertexSet::try_new(vertices).ok()?;
    let motion = RigidMotion::try_from_arrays([0.0; 3], v, w).ok()?;
    let n = Direction::try_from_array(n).ok()?;
    Some((evq(&body, &motion, n).speed, nevq(&body.summary(), &motion, n).speed))
}
