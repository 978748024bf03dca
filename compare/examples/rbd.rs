//! The seed's Table 1 rigid-body rows, "RBD for Bunnies" and "RBD for
//! Rings", replayed from rapier3d through the scene query
//! (`motion_bound_compare::rbd`, which says how).
//!
//! Run with `cargo run --release -p motion-bound-compare --example rbd`
//! (or `cargo run --release --example rbd` inside `compare/`); `--frames N`
//! changes the 300 frames per scene.

use motion_bound::ca::BoundChoice;
use motion_bound_devkit::Args;

fn main() {
    let mut args = Args::from_env("rbd [--frames 300]");
    let frames = args.value_or("--frames", 300);
    args.finish();
    let _ = motion_bound_compare::rbd::run_both(frames, BoundChoice::Auto, false);
}
