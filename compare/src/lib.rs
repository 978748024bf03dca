//! Outside comparisons for motion-bound, kept out of the crate's own build:
//! parry3d's `cast_shapes_nonlinear` on the seed's Table 1 scenes
//! ([`parry`]), the rigid-body scenes driven by rapier3d ([`rbd`]), the
//! `table1` and `report` binaries and the `toi` benchmark.
//!
//! ```sh
//! cargo run --release -p motion-bound-compare --bin report   # everything, with plots in docs/report/
//! cargo run --release -p motion-bound-compare --bin table1   # the torus knots, with parry3d
//! cargo run --release -p motion-bound-compare --example rbd  # the rigid-body rows
//! cargo bench -p motion-bound-compare --bench toi
//! ```

pub mod parry;
pub mod rbd;
