//! Outside comparisons for motion-bound, kept out of the crate's own build:
//! parry3d's `cast_shapes_nonlinear` on the seed's Table 1 scenes
//! ([`parry`]), the `table1` report (`src/bin/table1.rs`) and the `toi`
//! benchmark (`benches/toi.rs`).
//!
//! ```sh
//! cargo run --release -p motion-bound-compare --bin table1
//! cargo bench -p motion-bound-compare --bench toi
//! ```

pub mod parry;
