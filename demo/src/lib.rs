//! Nothing but a home for the example `demo` (`examples/demo.rs` at the repository's root):
//! `cargo run --release --example demo` builds this package's dependencies, motion-bound with
//! `testkit` and `obj` and flate2, and nothing of the crate's dev-dependencies. See `Cargo.toml`.
