//! Nothing but a home for the repository's targets that the published crate leaves out: the
//! tests, examples and benches at the root (`tests/`, `examples/`, `benches/`) that read
//! `data/`, check the repository's files, use the workspace's devkit or load the Panda arm from
//! its URDF. See `Cargo.toml`, which names each with its path.
