//! Nothing but a home for motion-bound-parry's targets that the published crate leaves out (the
//! ground truth, the solid meshes, the rapier worlds and their test, the bench): they use the
//! workspace's devkit. See `Cargo.toml`, which names each with its path.
