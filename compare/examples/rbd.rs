//! The seed's Table 1 rigid-body rows, "RBD for Bunnies" and "RBD for
//! Rings", replayed from rapier3d through the scene query
//! (`motion_bound_compare::rbd`, which says how).
//!
//! Run with `cargo run --release -p motion-bound-compare --example rbd`
//! (or `cargo run --release --example rbd` inside `compare/`); `--frames N`
//! changes the 300 frames per scene.

use motion_bound::ca::BoundChoice;

fn main() {
    let mut frames = 300;
    let mut args = std::env::args().skip(1);
    while let Some(a) = args.next() {
        match a.as_str() {
            "--frames" => {
                frames = args
                    .next()
                    .and_then(|s| s.parse().ok())
                    .expect("--frames N")
            }
            other => panic!("unknown argument {other}"),
        }
    }
    let _ = motion_bound_compare::rbd::run_both(frames, BoundChoice::Auto, false);
}
