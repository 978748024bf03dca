//! Chains: robot arms and other kinematic trees from a URDF, in still
//! surroundings, and the queries a planner's motion validator calls (the
//! crate's [`motion_bound::chain`], wrapped: no chain logic is written here).
//!
//! A chain (`mb_chain`) is made from URDF text or a file and is immutable.
//! A chain scene (`mb_chain_scene`) holds a copy of a chain, its obstacles
//! (the ABI's shapes at poses, and point clouds) and the link pairs never
//! checked; it is built, then queried from any number of threads at once.

use std::ffi::{c_char, CStr, CString};
use std::path::Path;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Mutex;

use motion_bound::chain::{
    Chain, ChainError, ChainPair, ChainParams, ChainScene, EdgeOutcome, Obstacle, SegmentOutcome,
    ShapeObstacle, UrdfOptions,
};
use motion_bound::{Float, Pose};

use crate::error::{guard, Failure, MbStatus, Res};
use crate::motion::{MbPose, MbVec3};
use crate::ptr::{
    free_handle, handle_mut, handle_ref, read_in, slice_from, write_handle, write_out, Handle,
    Kind, Plain,
};
use crate::shape::MbShape;
use motion_bound::ca::OwnedShape;

/// A kinematic tree read from a URDF: its links' collision meshes (each
/// with its ball tree, built once) and its revolute, continuous, prismatic
/// and fixed joints. Opaque; made by `mb_chain_from_urdf_file` or
/// `mb_chain_from_urdf_string`, freed by `mb_chain_free`; immutable.
#[derive(Debug)]
pub struct MbChain {
    chain: Chain<f64>,
    link_names: Vec<CString>,
}

impl Handle for MbChain {
    const KIND: Kind = Kind::Chain;
    const NAME: &'static str = "chain";
}

/// A chain in still surroundings: what a planner's motion validator asks
/// about. Opaque; made by `mb_chain_scene_new` (which copies the chain),
/// grown by `mb_chain_scene_add_obstacle` and `mb_chain_scene_add_points`,
/// its unchecked pairs set by `mb_chain_scene_allow_collision` and
/// `mb_chain_scene_allow_collisions_at`, freed by `mb_chain_scene_free`.
#[derive(Debug)]
pub struct MbChainScene {
    scene: ChainScene<f64>,
    link_names: Vec<CString>,
    /// The number of obstacles added (`mb_chain_scene_add_*` calls).
    added: usize,
    /// For each of the crate's mesh obstacles, the scene's obstacle index.
    mesh_owner: Vec<usize>,
    /// For each of the crate's shape obstacles, the scene's obstacle index.
    shape_owner: Vec<usize>,
}

impl Handle for MbChainScene {
    const KIND: Kind = Kind::ChainScene;
    const NAME: &'static str = "scene";
}

/// A chain scene's parameters, a plain struct: start from
/// `mb_chain_params_default` and change fields; checked by
/// `mb_chain_scene_set_params` (`MB_STATUS_INVALID_PARAMETER`).
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MbChainParams {
    /// Surfaces this close count as touching in `mb_chain_scene_check_segment`
    /// (world units, positive and finite; default `1e-3`).
    pub contact_distance: f64,
    /// What the edge queries keep between the links and everything else
    /// (world units, finite, at least `0`; default `0`: exact).
    pub padding: f64,
    /// The most items an edge query tests before it answers
    /// `MB_EDGE_OUTCOME_UNDECIDED` (at least `1`; default 250,000).
    pub edge_budget: u64,
    /// Iterations per pair of `mb_chain_scene_check_segment` (at least `1`;
    /// default 10,000).
    pub max_iterations: u64,
    /// Nonzero (the default): the ends of edges and segments must be within
    /// the joints' limits (`MB_STATUS_INVALID_INPUT` otherwise).
    pub within_limits: u32,
}

// SAFETY: a `repr(C)` struct of `f64`, `u64` and `u32` fields (and padding).
unsafe impl Plain for MbChainParams {}

/// What a chain query's pair is (`mb_chain_pair.kind`).
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MbChainPairKind {
    /// No pair (nothing checked, or a free answer).
    None = 0,
    /// Link `a` and obstacle `b` (the index `mb_chain_scene_add_*` returned).
    Obstacle = 1,
    /// Links `a < b` of the chain.
    SelfCollision = 2,
}

/// A pair of a chain query's answer.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct MbChainPair {
    /// What the pair is.
    pub kind: MbChainPairKind,
    /// A link's index (`mb_chain_link_name` names it).
    pub a: usize,
    /// An obstacle's index or a second link's index, by `kind`.
    pub b: usize,
}

const NO_PAIR: MbChainPair = MbChainPair {
    kind: MbChainPairKind::None,
    a: 0,
    b: 0,
};

/// What an edge query ended with (`mb_edge_report.outcome`).
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MbEdgeOutcome {
    /// The whole edge is certified free.
    Free = 0,
    /// Free on `[0, free_until]`; the pair within the contact distance plus
    /// the padding at `at`, never later than the first touch.
    Contact = 1,
    /// The edge budget ran out: free on `[0, free_until]`.
    Undecided = 2,
}

/// The answer of `mb_chain_scene_check_edge`.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MbEdgeReport {
    /// What the query ended with.
    pub outcome: MbEdgeOutcome,
    /// The edge is certified free on `[0, free_until]` (`1` when free).
    pub free_until: f64,
    /// The contact's time (NaN unless a contact).
    pub at: f64,
    /// The pair in contact (`MB_CHAIN_PAIR_KIND_NONE` unless a contact).
    pub pair: MbChainPair,
    /// Items tested.
    pub tests: u64,
    /// Of them, leaf items (triangles, points).
    pub leaf_tests: u64,
    /// Time intervals examined.
    pub intervals: u64,
}

/// What a segment query ended with (`mb_segment_report.outcome`).
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MbSegmentOutcome {
    /// No checked pair comes within the contact distance.
    Separated = 0,
    /// The first contact: its time, pair and witnesses.
    Contact = 1,
    /// A pair ran out of iterations: the segment is certified free up to
    /// `time`.
    IterationLimit = 2,
}

/// The answer of `mb_chain_scene_check_segment`.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MbSegmentReport {
    /// What the query ended with.
    pub outcome: MbSegmentOutcome,
    /// The contact's time (never later than the first touch), or the time
    /// up to which the segment is free for an iteration limit; NaN when
    /// separated.
    pub time: f64,
    /// The pair (`MB_CHAIN_PAIR_KIND_NONE` when separated).
    pub pair: MbChainPair,
    /// The witnesses' distance at `time` (NaN unless a contact).
    pub distance: f64,
    /// The witness on the pair's first member (world coordinates at
    /// `time`; NaN unless a contact).
    pub point_a: MbVec3,
    /// The witness on the second member.
    pub point_b: MbVec3,
    /// Pairs considered.
    pub pairs: u64,
    /// Pairs never checked (adjacent or allowed).
    pub excluded: u64,
    /// Pairs the broad phase ruled out.
    pub culled: u64,
    /// Pairs advanced.
    pub advanced: u64,
    /// Iterations of conservative advancement.
    pub iterations: u64,
    /// Node pairs visited.
    pub node_pairs: u64,
    /// Triangle pairs measured.
    pub leaf_pairs: u64,
}

/// The status and message of a chain's refusal; `what` is the argument.
fn chain_failure(e: ChainError, what: &str) -> Failure {
    match e {
        ChainError::WrongDof { expected, got } => Failure::new(
            MbStatus::InvalidSize,
            format!("{what} has {got} joint coordinates, the chain has {expected}"),
        ),
        ChainError::NonFiniteCoordinate(i) => Failure::new(
            MbStatus::InvalidInput,
            format!("{what}[{i}] is NaN, infinite or beyond the input range"),
        ),
        ChainError::BeyondLimits(i) => Failure::new(
            MbStatus::InvalidInput,
            format!("{what}[{i}] is outside its joint's limits"),
        ),
        ChainError::InvalidParameter(p) => {
            Failure::new(MbStatus::InvalidParameter, format!("{what}: {p}"))
        }
        ChainError::Mesh(m) => Failure::new(MbStatus::InvalidMesh, format!("{what}: {m}")),
        ChainError::Shape(s) => {
            let f = Failure::from(s);
            Failure::new(f.status, format!("{what}: {}", f.message))
        }
        ChainError::UnknownName(n) => Failure::new(
            MbStatus::UnknownName,
            format!("{what}: no link named {n:?}"),
        ),
        other => Failure::new(MbStatus::InvalidUrdf, format!("{what}: {other}")),
    }
}

/// The C string at `ptr` as UTF-8, `None` for `NULL`.
///
/// # Safety
/// `ptr` is `NULL` or a NUL-terminated string, unchanged while the result
/// lives.
unsafe fn c_str<'a>(ptr: *const c_char, what: &str) -> Res<Option<&'a str>> {
    if ptr.is_null() {
        return Ok(None);
    }
    // SAFETY: not NULL, and NUL-terminated and unchanged while `'a` lasts
    // (the caller's contract).
    let s = unsafe { CStr::from_ptr(ptr) };
    s.to_str().map(Some).map_err(|e| {
        Failure::new(
            MbStatus::InvalidInput,
            format!("{what} is not UTF-8 (byte {})", e.valid_up_to()),
        )
    })
}

/// The required C string at `ptr`.
///
/// # Safety
/// As [`c_str`].
unsafe fn required_str<'a>(ptr: *const c_char, what: &str) -> Res<&'a str> {
    // SAFETY: passed on (the caller's contract).
    unsafe { c_str(ptr, what) }?
        .ok_or_else(|| Failure::new(MbStatus::NullPointer, format!("{what} is NULL")))
}

/// The writable array of `len` bytes at `ptr`.
///
/// # Safety
/// For `len > 0`, `ptr` is `NULL` or valid for writing `len` bytes, used by
/// no one else while the slice lives.
unsafe fn bytes_out<'a>(ptr: *mut u8, len: usize, what: &str) -> Res<&'a mut [u8]> {
    if len == 0 {
        return Ok(&mut []);
    }
    if ptr.is_null() {
        return Err(Failure::new(
            MbStatus::NullPointer,
            format!("{what} is NULL"),
        ));
    }
    if len > isize::MAX as usize {
        return Err(Failure::new(
            MbStatus::InvalidSize,
            format!("{what}: {len} items overflow the address space"),
        ));
    }
    // SAFETY: not NULL, `u8` needs no alignment, `len` fits in `isize`
    // (checked); the caller guarantees `len` writable bytes used by no one
    // else while the slice lives.
    Ok(unsafe { std::slice::from_raw_parts_mut(ptr, len) })
}

/// The crate's pose of an ABI pose.
fn pose(p: MbPose, what: &str) -> Res<Pose<f64>> {
    let iso = p.isometry(what)?;
    Ok(Pose {
        rotation: iso.rotation().matrix(),
        translation: iso.translation(),
    })
}

impl MbChain {
    fn new(chain: Chain<f64>) -> Self {
        let link_names = (0..chain.link_count())
            .map(|i| CString::new(chain.link_name(i).unwrap_or("").replace('\0', " ")))
            .map(Result::unwrap_or_default)
            .collect();
        Self { chain, link_names }
    }
}

/// Checks the joint coordinates `q`: the chain's length, finite, within
/// the limits when `limits` (messages name `what[i]`).
fn check_q(chain: &Chain<f64>, q: &[f64], limits: bool, what: &str) -> Res<()> {
    for (i, &x) in q.iter().enumerate() {
        if !x.is_finite() {
            return Err(Failure::new(
                MbStatus::InvalidInput,
                format!("{what}[{i}] is not finite (got {x})"),
            ));
        }
        if x.abs() > <f64 as Float>::MAX_INPUT {
            return Err(Failure::new(
                MbStatus::InvalidInput,
                format!("{what}[{i}] is beyond the input range (got {x})"),
            ));
        }
    }
    if limits {
        for (i, (x, lim)) in q.iter().zip(chain.limits()).enumerate() {
            if let Some([lo, hi]) = lim {
                if *x < lo || *x > hi {
                    let name = chain.joint_names().nth(i).unwrap_or("?");
                    return Err(Failure::new(
                        MbStatus::InvalidInput,
                        format!(
                            "{what}[{i}] is outside joint {name:?}'s limits [{lo}, {hi}] \
                             (got {x}; within_limits = 0 checks it anyway)"
                        ),
                    ));
                }
            }
        }
    }
    Ok(())
}

/// The joint coordinates at `ptr`: `dof` of them, the chain's number,
/// checked as [`check_q`].
///
/// # Safety
/// `ptr` is `NULL` or valid for reading `dof` doubles.
unsafe fn coordinates<'a>(
    chain: &Chain<f64>,
    ptr: *const f64,
    dof: usize,
    limits: bool,
    what: &str,
) -> Res<&'a [f64]> {
    if dof != chain.dof() {
        return Err(Failure::new(
            MbStatus::InvalidSize,
            format!(
                "dof is {dof}, the chain has {} joint coordinates",
                chain.dof()
            ),
        ));
    }
    // SAFETY: `dof` readable doubles (the caller's contract).
    let q = unsafe { slice_from(ptr, dof, what) }?;
    if q.is_empty() {
        // A chain without movable joints: nothing to read, nothing to check.
        return Ok(q);
    }
    check_q(chain, q, limits, what)?;
    Ok(q)
}

impl MbChainScene {
    fn pair(&self, p: ChainPair) -> MbChainPair {
        match p {
            ChainPair::Obstacle { link, obstacle } => MbChainPair {
                kind: MbChainPairKind::Obstacle,
                a: link,
                b: self.mesh_owner[obstacle],
            },
            ChainPair::Shape { link, shape } => MbChainPair {
                kind: MbChainPairKind::Obstacle,
                a: link,
                b: self.shape_owner[shape],
            },
            ChainPair::SelfCollision { a, b } => MbChainPair {
                kind: MbChainPairKind::SelfCollision,
                a,
                b,
            },
            _ => NO_PAIR,
        }
    }

    /// Whether the edge and segment queries check the limits.
    fn limits(&self) -> bool {
        self.scene.params().within_limits
    }

    fn link(&self, name: &str, what: &str) -> Res<usize> {
        self.scene.chain().link_index(name).map_err(|_| {
            Failure::new(
                MbStatus::UnknownName,
                format!("{what}: no link named {name:?}"),
            )
        })
    }

    fn name(&self, name: Option<&str>) -> String {
        name.map_or_else(|| format!("obstacle{}", self.added), str::to_owned)
    }
}

/// The chain of the URDF file at `path` (NUL-terminated, UTF-8): each
/// link's collision elements (OBJ and STL meshes; boxes exactly; cylinders,
/// spheres and capsules as meshes that contain them) merged into one mesh.
/// `package://NAME/...` mesh paths are looked up under `package_root`
/// (`NULL` for none) first, then beside the URDF; plain relative paths are
/// relative to the URDF's folder. Written to `*out`.
///
/// `MB_STATUS_INVALID_URDF` for a file that cannot be read or parsed, an
/// unsupported joint kind or mesh format, a mesh file that cannot be read,
/// or links and joints that do not form one tree.
///
/// **Thread safety**: any thread.
///
/// # Safety
/// `path` and `package_root` are `NULL` or NUL-terminated strings; `out` is
/// `NULL` or valid for writing a pointer.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn mb_chain_from_urdf_file(
    path: *const c_char,
    package_root: *const c_char,
    out: *mut *mut MbChain,
) -> MbStatus {
    guard(|| {
        // SAFETY: the strings are NULL or NUL-terminated (this function's contract).
        let (path, root) = unsafe {
            (
                required_str(path, "path")?,
                c_str(package_root, "package_root")?,
            )
        };
        let mut options = UrdfOptions::default();
        options.package_root = root.map(Into::into);
        let chain =
            Chain::from_urdf_file_with(path, &options).map_err(|e| chain_failure(e, "path"))?;
        // SAFETY: `out` is NULL or writable (this function's contract).
        unsafe { write_handle(out, MbChain::new(chain)) }
    })
}

/// The chain of URDF `text` (NUL-terminated, UTF-8), its relative mesh
/// paths resolved against the folder `mesh_dir` (`NULL`: the current
/// folder) and `package://` paths under `package_root` first (`NULL`: none),
/// as `mb_chain_from_urdf_file`. Written to `*out`.
///
/// **Thread safety**: any thread.
///
/// # Safety
/// The strings are `NULL` or NUL-terminated; `out` is `NULL` or valid for
/// writing a pointer.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn mb_chain_from_urdf_string(
    text: *const c_char,
    mesh_dir: *const c_char,
    package_root: *const c_char,
    out: *mut *mut MbChain,
) -> MbStatus {
    guard(|| {
        // SAFETY: the strings are NULL or NUL-terminated (this function's contract).
        let (text, dir, root) = unsafe {
            (
                required_str(text, "text")?,
                c_str(mesh_dir, "mesh_dir")?,
                c_str(package_root, "package_root")?,
            )
        };
        let mut options = UrdfOptions::default();
        options.package_root = root.map(Into::into);
        let chain = Chain::from_urdf_str(text, Path::new(dir.unwrap_or(".")), &options)
            .map_err(|e| chain_failure(e, "text"))?;
        // SAFETY: `out` is NULL or writable (this function's contract).
        unsafe { write_handle(out, MbChain::new(chain)) }
    })
}

/// Frees a chain (nothing for `NULL`). Scenes made from it keep their own
/// copy.
///
/// **Thread safety**: no other thread may use `chain`.
///
/// # Safety
/// `chain` is not used by another thread during or after the call.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn mb_chain_free(chain: *mut MbChain) -> MbStatus {
    // SAFETY: this function's contract.
    guard(|| unsafe { free_handle(chain, "chain") })
}

/// The chain's number of joint coordinates (its movable joints), written
/// to `*out`: the `dof` every query takes.
///
/// **Thread safety**: any thread.
///
/// # Safety
/// `chain` is not freed during the call; `out` is `NULL` or valid for
/// writing a `size_t`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn mb_chain_dof(chain: *const MbChain, out: *mut usize) -> MbStatus {
    guard(|| {
        // SAFETY: this function's contract.
        unsafe { write_out(out, handle_ref(chain, "chain")?.chain.dof(), "out") }
    })
}

/// The chain's number of links, written to `*out`.
///
/// **Thread safety**: any thread.
///
/// # Safety
/// As `mb_chain_dof`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn mb_chain_link_count(chain: *const MbChain, out: *mut usize) -> MbStatus {
    guard(|| {
        // SAFETY: this function's contract.
        unsafe { write_out(out, handle_ref(chain, "chain")?.chain.link_count(), "out") }
    })
}

/// The index of the link named `name`, written to `*out`;
/// `MB_STATUS_UNKNOWN_NAME` when no link has that name.
///
/// **Thread safety**: any thread.
///
/// # Safety
/// `chain` is not freed during the call; `name` is `NULL` or
/// NUL-terminated; `out` is `NULL` or valid for writing a `size_t`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn mb_chain_link_index(
    chain: *const MbChain,
    name: *const c_char,
    out: *mut usize,
) -> MbStatus {
    guard(|| {
        // SAFETY: this function's contract.
        let (c, name) = unsafe { (handle_ref(chain, "chain")?, required_str(name, "name")?) };
        let i = c.chain.link_index(name).map_err(|_| {
            Failure::new(
                MbStatus::UnknownName,
                format!("name: no link named {name:?}"),
            )
        })?;
        // SAFETY: this function's contract.
        unsafe { write_out(out, i, "out") }
    })
}

/// The name of link `index`, written to `*out` as a NUL-terminated string
/// owned by the chain (valid until it is freed); `MB_STATUS_OUT_OF_RANGE`
/// for an index past the end.
///
/// **Thread safety**: any thread.
///
/// # Safety
/// `chain` is not freed during the call; `out` is `NULL` or valid for
/// writing a pointer.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn mb_chain_link_name(
    chain: *const MbChain,
    index: usize,
    out: *mut *const c_char,
) -> MbStatus {
    guard(|| {
        // SAFETY: this function's contract.
        let c = unsafe { handle_ref(chain, "chain") }?;
        let name = c.link_names.get(index).ok_or_else(|| {
            Failure::new(
                MbStatus::OutOfRange,
                format!(
                    "index is {index}, the chain has {} links",
                    c.link_names.len()
                ),
            )
        })?;
        // SAFETY: this function's contract.
        unsafe { write_out(out, name.as_ptr(), "out") }
    })
}

/// The joints' limits, coordinate by coordinate: `lower[i]` and `upper[i]`
/// for `i < dof` (`dof` must be the chain's); `-INFINITY` and `INFINITY`
/// for a coordinate without limits (a continuous joint).
///
/// **Thread safety**: any thread.
///
/// # Safety
/// `chain` is not freed during the call; `lower` and `upper` are `NULL` or
/// valid for writing `dof` doubles.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn mb_chain_limits(
    chain: *const MbChain,
    lower: *mut f64,
    upper: *mut f64,
    dof: usize,
) -> MbStatus {
    guard(|| {
        // SAFETY: this function's contract.
        let c = unsafe { handle_ref(chain, "chain") }?;
        if dof != c.chain.dof() {
            return Err(Failure::new(
                MbStatus::InvalidSize,
                format!(
                    "dof is {dof}, the chain has {} joint coordinates",
                    c.chain.dof()
                ),
            ));
        }
        let limits = c.chain.limits();
        if dof > 0 && (lower.is_null() || upper.is_null()) {
            let what = if lower.is_null() { "lower" } else { "upper" };
            return Err(Failure::new(
                MbStatus::NullPointer,
                format!("{what} is NULL"),
            ));
        }
        for (i, lim) in limits.iter().enumerate() {
            let [lo, hi] = lim.unwrap_or([f64::NEG_INFINITY, f64::INFINITY]);
            // SAFETY: `i < dof`; `lower` and `upper` hold `dof` writable
            // doubles (this function's contract); `wrapping_add` stays in them.
            unsafe {
                write_out(lower.wrapping_add(i), lo, "lower")?;
                write_out(upper.wrapping_add(i), hi, "upper")?;
            }
        }
        Ok(())
    })
}

/// A scene of a copy of `chain` alone, with the default parameters,
/// written to `*out`. Pairs of adjacent links (joined by one movable
/// joint, or rigidly through fixed joints) are never checked.
///
/// **Thread safety**: any thread.
///
/// # Safety
/// `chain` is not freed during the call; `out` is `NULL` or valid for
/// writing a pointer.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn mb_chain_scene_new(
    chain: *const MbChain,
    out: *mut *mut MbChainScene,
) -> MbStatus {
    guard(|| {
        // SAFETY: this function's contract.
        let c = unsafe { handle_ref(chain, "chain") }?;
        let s = MbChainScene {
            scene: ChainScene::new(c.chain.clone()),
            link_names: c.link_names.clone(),
            added: 0,
            mesh_owner: Vec::new(),
            shape_owner: Vec::new(),
        };
        // SAFETY: this function's contract.
        unsafe { write_handle(out, s) }
    })
}

/// Frees a chain scene (nothing for `NULL`).
///
/// **Thread safety**: no other thread may use `scene`.
///
/// # Safety
/// `scene` is not used by another thread during or after the call.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn mb_chain_scene_free(scene: *mut MbChainScene) -> MbStatus {
    // SAFETY: this function's contract.
    guard(|| unsafe { free_handle(scene, "scene") })
}

/// The default parameters (`contact_distance` 1e-3, `padding` 0,
/// `edge_budget` 250,000, `max_iterations` 10,000, `within_limits` 1).
///
/// **Thread safety**: any thread, any time.
#[unsafe(no_mangle)]
pub extern "C" fn mb_chain_params_default() -> MbChainParams {
    let p = ChainParams::<f64>::default();
    MbChainParams {
        contact_distance: p.contact_distance,
        padding: p.padding,
        edge_budget: p.edge_budget as u64,
        max_iterations: p.max_iterations as u64,
        within_limits: u32::from(p.within_limits),
    }
}

/// Sets the scene's parameters (`NULL`: the defaults);
/// `MB_STATUS_INVALID_PARAMETER` naming the field out of range.
///
/// **Thread safety**: no other thread may use `scene` during the call.
///
/// # Safety
/// `scene` is not used by another thread during the call; `params` is
/// `NULL` or valid for reading an `mb_chain_params`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn mb_chain_scene_set_params(
    scene: *mut MbChainScene,
    params: *const MbChainParams,
) -> MbStatus {
    guard(|| {
        // SAFETY: this function's contract.
        let (s, p) = unsafe { (handle_mut(scene, "scene")?, read_in(params, "params")?) };
        let p = p.unwrap_or_else(|| mb_chain_params_default());
        let bad = |field: &str, rule: &str, got: String| {
            Err(Failure::new(
                MbStatus::InvalidParameter,
                format!("params.{field} must be {rule} (got {got})"),
            ))
        };
        if !(p.contact_distance.is_finite() && p.contact_distance > 0.0) {
            return bad(
                "contact_distance",
                "positive and finite",
                p.contact_distance.to_string(),
            );
        }
        if !(p.padding.is_finite() && p.padding >= 0.0) {
            return bad("padding", "finite and at least 0", p.padding.to_string());
        }
        let budget = usize::try_from(p.edge_budget).ok().filter(|&n| n >= 1);
        let Some(budget) = budget else {
            return bad("edge_budget", "at least 1", p.edge_budget.to_string());
        };
        let iterations = usize::try_from(p.max_iterations).ok().filter(|&n| n >= 1);
        let Some(iterations) = iterations else {
            return bad("max_iterations", "at least 1", p.max_iterations.to_string());
        };
        let mut c = s
            .scene
            .params()
            .with_contact_distance(p.contact_distance)
            .with_padding(p.padding)
            .with_edge_budget(budget)
            .with_within_limits(p.within_limits != 0);
        c.max_iterations = iterations;
        s.scene
            .set_params(c)
            .map_err(|e| chain_failure(e, "params"))
    })
}

/// Adds `shape` still at `pose` as an obstacle named `name` (`NULL`:
/// `"obstacle<i>"`) and writes its obstacle index to `*out_index` (`NULL`
/// to skip). Balls, capsules, cuboids, cylinders, cones (rounded or not)
/// and half-spaces are measured exactly (never meshed); a mesh is its
/// triangles. `MB_STATUS_QUERY_ERROR` for a convex hull (give it as a mesh)
/// or a compound (add its parts one by one). The scene copies what it needs:
/// the shape may be freed after.
///
/// **Thread safety**: no other thread may use `scene` during the call.
///
/// # Safety
/// The handles are not freed during the call and `scene` is not used by
/// another thread; `name` is `NULL` or NUL-terminated; `out_index` is
/// `NULL` or valid for writing a `size_t`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn mb_chain_scene_add_obstacle(
    scene: *mut MbChainScene,
    shape: *const MbShape,
    pose: MbPose,
    name: *const c_char,
    out_index: *mut usize,
) -> MbStatus {
    guard(|| {
        // SAFETY: this function's contract.
        let (s, sh, name) = unsafe {
            (
                handle_mut(scene, "scene")?,
                handle_ref(shape, "shape")?,
                c_str(name, "name")?,
            )
        };
        let name = s.name(name);
        let at = self::pose(pose, "pose")?;
        let what = |e| chain_failure(e, "pose");
        let owner = s.added;
        match &*sh.data {
            OwnedShape::Convex(c) => {
                s.scene
                    .add_shape(ShapeObstacle::try_new(name, *c, at).map_err(what)?);
                s.shape_owner.push(owner);
            }
            OwnedShape::Mesh(m) => {
                s.scene
                    .add_obstacle(Obstacle::try_new(name, m.mesh().clone(), at).map_err(what)?);
                s.mesh_owner.push(owner);
            }
            OwnedShape::HalfSpace(h) => {
                let n = at.transform_vector(h.normal().get());
                s.scene.add_shape(
                    ShapeObstacle::try_half_space(name, n.to_array(), at.translation.to_array())
                        .map_err(what)?,
                );
                s.shape_owner.push(owner);
            }
            OwnedShape::Hull(_) => {
                return Err(Failure::new(
                    MbStatus::QueryError,
                    "shape: a convex hull is not a chain scene obstacle; give its triangles as \
                     mb_shape_mesh",
                ))
            }
            OwnedShape::Compound(_) => {
                return Err(Failure::new(
                    MbStatus::QueryError,
                    "shape: a compound is not a chain scene obstacle; add its parts one by one \
                     at their poses",
                ))
            }
            // `OwnedShape` is `#[non_exhaustive]`: a kind added later is refused until it
            // is mapped here.
            _ => {
                return Err(Failure::new(
                    MbStatus::QueryError,
                    "shape: this kind of shape is not a chain scene obstacle",
                ))
            }
        }
        s.added += 1;
        if !out_index.is_null() {
            // SAFETY: this function's contract.
            unsafe { write_out(out_index, owner, "out_index") }?;
        }
        Ok(())
    })
}

/// Adds a point cloud: a ball of `radius` (at least 0) about each of the
/// `count` points (world coordinates; a depth camera's points with its
/// noise as the radius), measured exactly, named `name` (`NULL`:
/// `"obstacle<i>"`); writes its obstacle index to `*out_index` (`NULL` to
/// skip).
///
/// **Thread safety**: no other thread may use `scene` during the call.
///
/// # Safety
/// `scene` is not freed or used by another thread during the call;
/// `points` is `NULL` or valid for reading `count` `mb_vec3`; `name` is
/// `NULL` or NUL-terminated; `out_index` is `NULL` or valid for writing a
/// `size_t`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn mb_chain_scene_add_points(
    scene: *mut MbChainScene,
    points: *const MbVec3,
    count: usize,
    radius: f64,
    name: *const c_char,
    out_index: *mut usize,
) -> MbStatus {
    guard(|| {
        // SAFETY: this function's contract.
        let (s, pts, name) = unsafe {
            (
                handle_mut(scene, "scene")?,
                slice_from(points, count, "points")?,
                c_str(name, "name")?,
            )
        };
        if pts.is_empty() {
            return Err(Failure::new(
                MbStatus::InvalidSize,
                "count is 0: a point cloud needs points",
            ));
        }
        for (i, p) in pts.iter().enumerate() {
            p.checked(&format!("points[{i}]"))?;
        }
        if !(radius.is_finite() && radius >= 0.0) {
            return Err(Failure::new(
                MbStatus::InvalidInput,
                format!("radius must be finite and at least 0 (got {radius})"),
            ));
        }
        let name = s.name(name);
        let arrays: Vec<[f64; 3]> = pts.iter().map(|p| p.array()).collect();
        let cloud = ShapeObstacle::try_points(name, &arrays, radius)
            .map_err(|e| chain_failure(e, "points"))?;
        let owner = s.added;
        s.scene.add_shape(cloud);
        s.shape_owner.push(owner);
        s.added += 1;
        if !out_index.is_null() {
            // SAFETY: this function's contract.
            unsafe { write_out(out_index, owner, "out_index") }?;
        }
        Ok(())
    })
}

/// Never checks links `link_a` and `link_b` (by name) against each other,
/// as an SRDF's `disable_collisions` lists them; `MB_STATUS_UNKNOWN_NAME`
/// naming the argument for a name that is not a link's.
///
/// **Thread safety**: no other thread may use `scene` during the call.
///
/// # Safety
/// `scene` is not freed or used by another thread during the call; the
/// names are `NULL` or NUL-terminated.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn mb_chain_scene_allow_collision(
    scene: *mut MbChainScene,
    link_a: *const c_char,
    link_b: *const c_char,
) -> MbStatus {
    guard(|| {
        // SAFETY: this function's contract.
        let (s, a, b) = unsafe {
            (
                handle_mut(scene, "scene")?,
                required_str(link_a, "link_a")?,
                required_str(link_b, "link_b")?,
            )
        };
        let (a, b) = (s.link(a, "link_a")?, s.link(b, "link_b")?);
        s.scene.allow_collision(a, b);
        Ok(())
    })
}

/// Never checks again the pairs of links whose surfaces are within
/// `distance` (at least 0) at configuration `q` (an SRDF's pairs in
/// collision by default, fingers closed on each other); writes how many
/// pairs that allowed to `*out_count` (`NULL` to skip). Link pairs only:
/// obstacles of every kind stay checked.
///
/// **Thread safety**: no other thread may use `scene` during the call.
///
/// # Safety
/// `scene` is not freed or used by another thread during the call; `q` is
/// `NULL` or valid for reading `dof` doubles; `out_count` is `NULL` or valid
/// for writing a `size_t`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn mb_chain_scene_allow_collisions_at(
    scene: *mut MbChainScene,
    q: *const f64,
    dof: usize,
    distance: f64,
    out_count: *mut usize,
) -> MbStatus {
    guard(|| {
        // SAFETY: this function's contract.
        let s = unsafe { handle_mut(scene, "scene") }?;
        // SAFETY: this function's contract.
        let q = unsafe { coordinates(s.scene.chain(), q, dof, false, "q") }?;
        if !(distance.is_finite() && distance >= 0.0) {
            return Err(Failure::new(
                MbStatus::InvalidInput,
                format!("distance must be finite and at least 0 (got {distance})"),
            ));
        }
        let pairs = s
            .scene
            .allow_collisions_at(q, distance)
            .map_err(|e| chain_failure(e, "q"))?;
        if !out_count.is_null() {
            // SAFETY: this function's contract.
            unsafe { write_out(out_count, pairs.len(), "out_count") }?;
        }
        Ok(())
    })
}

/// Whether the scene checks links `link_a` and `link_b` (by name) against
/// each other, written to `*out` (`1` or `0`): `0` for a link without
/// geometry, a link with itself, adjacent links and allowed pairs.
///
/// **Thread safety**: any thread, unless another changes `scene`.
///
/// # Safety
/// `scene` is not freed or changed during the call; the names are `NULL`
/// or NUL-terminated; `out` is `NULL` or valid for writing a `uint8_t`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn mb_chain_scene_checks_pair(
    scene: *const MbChainScene,
    link_a: *const c_char,
    link_b: *const c_char,
    out: *mut u8,
) -> MbStatus {
    guard(|| {
        // SAFETY: this function's contract.
        let (s, a, b) = unsafe {
            (
                handle_ref(scene, "scene")?,
                required_str(link_a, "link_a")?,
                required_str(link_b, "link_b")?,
            )
        };
        let (a, b) = (s.link(a, "link_a")?, s.link(b, "link_b")?);
        // SAFETY: this function's contract.
        unsafe { write_out(out, u8::from(s.scene.checks_pair(a, b)), "out") }
    })
}

/// The name of the scene's link `index` (as `mb_chain_link_name`), owned by
/// the scene.
///
/// **Thread safety**: any thread.
///
/// # Safety
/// `scene` is not freed during the call; `out` is `NULL` or valid for
/// writing a pointer.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn mb_chain_scene_link_name(
    scene: *const MbChainScene,
    index: usize,
    out: *mut *const c_char,
) -> MbStatus {
    guard(|| {
        // SAFETY: this function's contract.
        let s = unsafe { handle_ref(scene, "scene") }?;
        let name = s.link_names.get(index).ok_or_else(|| {
            Failure::new(
                MbStatus::OutOfRange,
                format!(
                    "index is {index}, the chain has {} links",
                    s.link_names.len()
                ),
            )
        })?;
        // SAFETY: this function's contract.
        unsafe { write_out(out, name.as_ptr(), "out") }
    })
}

/// Whether the joint-space edge `q0 -> q1` (`q(t) = q0 + t (q1 - q0)`,
/// `t` in `[0, 1]`; `dof` coordinates each) is certified free of every
/// obstacle and checked link pair, with the padding to spare, written to
/// `*out` (`1` free, `0` a contact or an exhausted budget): a planner's
/// motion validator. `MB_STATUS_INVALID_SIZE` for a `dof` other than the
/// chain's; `MB_STATUS_INVALID_INPUT` naming `q0[i]` or `q1[i]` for a NaN,
/// infinite or (with `within_limits`) out-of-limit coordinate.
///
/// **Thread safety**: any number of threads may query one scene at once,
/// unless another changes it.
///
/// # Safety
/// `scene` is not freed or changed during the call; `q0` and `q1` are
/// `NULL` or valid for reading `dof` doubles; `out` is `NULL` or valid for
/// writing a `uint8_t`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn mb_chain_scene_edge_is_free(
    scene: *const MbChainScene,
    q0: *const f64,
    q1: *const f64,
    dof: usize,
    out: *mut u8,
) -> MbStatus {
    guard(|| {
        // SAFETY: this function's contract.
        let s = unsafe { handle_ref(scene, "scene") }?;
        let (chain, lim) = (s.scene.chain(), s.limits());
        // SAFETY: this function's contract.
        let (a, b) = unsafe {
            (
                coordinates(chain, q0, dof, lim, "q0")?,
                coordinates(chain, q1, dof, lim, "q1")?,
            )
        };
        let free = s
            .scene
            .edge_is_free(a, b)
            .map_err(|e| chain_failure(e, "q0, q1"))?;
        // SAFETY: this function's contract.
        unsafe { write_out(out, u8::from(free), "out") }
    })
}

/// `mb_chain_scene_edge_is_free` of `count` edges at once, on `threads`
/// threads (`0`: one per core): `edges` holds `count * 2 * dof` doubles,
/// edge `i` from `edges[(2 i) dof ..]` to `edges[(2 i + 1) dof ..]`;
/// `out[i]` is `1` when edge `i` is certified free, the same answer as one
/// `mb_chain_scene_edge_is_free` per edge. Every end is checked first
/// (messages name it: `edges[3][1][2] is not finite (got nan)`); on a
/// failure nothing is written.
///
/// **Thread safety**: as `mb_chain_scene_edge_is_free`; the call itself
/// runs threads of its own and returns when they are done.
///
/// # Safety
/// `scene` is not freed or changed during the call; `edges` is `NULL` or
/// valid for reading `count * 2 * dof` doubles; `out` is `NULL` or valid for
/// writing `count` bytes.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn mb_chain_scene_edges_are_free(
    scene: *const MbChainScene,
    edges: *const f64,
    count: usize,
    dof: usize,
    threads: usize,
    out: *mut u8,
) -> MbStatus {
    guard(|| {
        // SAFETY: this function's contract.
        let s = unsafe { handle_ref(scene, "scene") }?;
        let chain = s.scene.chain();
        if dof != chain.dof() {
            return Err(Failure::new(
                MbStatus::InvalidSize,
                format!(
                    "dof is {dof}, the chain has {} joint coordinates",
                    chain.dof()
                ),
            ));
        }
        let len = count
            .checked_mul(2)
            .and_then(|n| n.checked_mul(dof))
            .ok_or_else(|| {
                Failure::new(
                    MbStatus::InvalidSize,
                    format!("count: {count} edges of {dof} coordinates overflow the address space"),
                )
            })?;
        // SAFETY: this function's contract.
        let v = unsafe { slice_from(edges, len, "edges") }?;
        if count > 0 && dof > 0 {
            for (k, q) in v.chunks_exact(dof).enumerate() {
                check_q(
                    chain,
                    q,
                    s.limits(),
                    &format!("edges[{}][{}]", k / 2, k % 2),
                )?;
            }
        }
        // SAFETY: this function's contract.
        let out = unsafe { bytes_out(out, count, "out") }?;
        let end = |i: usize, k: usize| &v[(2 * i + k) * dof..(2 * i + k + 1) * dof];
        let threads = if threads == 0 {
            std::thread::available_parallelism().map_or(1, std::num::NonZero::get)
        } else {
            threads
        }
        .min(count.max(1));
        if threads <= 1 {
            let mut checker = s.scene.edge_checker();
            let answers = (0..count)
                .map(|i| {
                    checker
                        .is_free(end(i, 0), end(i, 1))
                        .map_err(|e| chain_failure(e, &format!("edges[{i}]")))
                })
                .collect::<Res<Vec<bool>>>()?;
            for (o, a) in out.iter_mut().zip(answers) {
                *o = u8::from(a);
            }
            return Ok(());
        }
        // Workers take the next edge from a shared counter, each with its
        // own checker; answers land in their edge's slot.
        let next = AtomicUsize::new(0);
        let answers: Vec<Mutex<Option<Result<bool, ChainError>>>> =
            (0..count).map(|_| Mutex::new(None)).collect();
        std::thread::scope(|scope| {
            for _ in 0..threads {
                scope.spawn(|| {
                    let mut checker = s.scene.edge_checker();
                    loop {
                        let i = next.fetch_add(1, Ordering::Relaxed);
                        if i >= count {
                            break;
                        }
                        let a = checker.is_free(end(i, 0), end(i, 1));
                        *answers[i]
                            .lock()
                            .unwrap_or_else(std::sync::PoisonError::into_inner) = Some(a);
                    }
                });
            }
        });
        let mut got = Vec::with_capacity(count);
        for (i, a) in answers.into_iter().enumerate() {
            let a = a
                .into_inner()
                .unwrap_or_else(std::sync::PoisonError::into_inner)
                .ok_or_else(|| {
                    Failure::new(
                        MbStatus::InternalError,
                        format!("edges[{i}] was not checked"),
                    )
                })?
                .map_err(|e| chain_failure(e, &format!("edges[{i}]")))?;
            got.push(a);
        }
        for (o, a) in out.iter_mut().zip(got) {
            *o = u8::from(a);
        }
        Ok(())
    })
}

/// The edge query's full answer for `q0 -> q1` (as
/// `mb_chain_scene_edge_is_free`), written to `*out`: free, a contact (free
/// up to `free_until`, the pair touching at `at`, never later than the
/// first touch) or undecided (the edge budget ran out), and the work done.
///
/// **Thread safety**: as `mb_chain_scene_edge_is_free`.
///
/// # Safety
/// As `mb_chain_scene_edge_is_free`, `out` valid for writing an
/// `mb_edge_report`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn mb_chain_scene_check_edge(
    scene: *const MbChainScene,
    q0: *const f64,
    q1: *const f64,
    dof: usize,
    out: *mut MbEdgeReport,
) -> MbStatus {
    guard(|| {
        // SAFETY: this function's contract.
        let s = unsafe { handle_ref(scene, "scene") }?;
        let (chain, lim) = (s.scene.chain(), s.limits());
        // SAFETY: this function's contract.
        let (a, b) = unsafe {
            (
                coordinates(chain, q0, dof, lim, "q0")?,
                coordinates(chain, q1, dof, lim, "q1")?,
            )
        };
        let r = s
            .scene
            .check_edge(a, b)
            .map_err(|e| chain_failure(e, "q0, q1"))?;
        let (outcome, free_until, at, pair) = match r.outcome {
            EdgeOutcome::Free => (MbEdgeOutcome::Free, 1.0, f64::NAN, NO_PAIR),
            EdgeOutcome::Contact {
                free_until,
                at,
                pair,
            } => (MbEdgeOutcome::Contact, free_until, at, s.pair(pair)),
            EdgeOutcome::Undecided { free_until } => {
                (MbEdgeOutcome::Undecided, free_until, f64::NAN, NO_PAIR)
            }
            _ => (MbEdgeOutcome::Undecided, 0.0, f64::NAN, NO_PAIR),
        };
        let report = MbEdgeReport {
            outcome,
            free_until,
            at,
            pair,
            tests: r.stats.tests as u64,
            leaf_tests: r.stats.leaf_tests as u64,
            intervals: r.stats.intervals as u64,
        };
        // SAFETY: this function's contract.
        unsafe { write_out(out, report, "out") }
    })
}

/// The first contact along the joint-space segment `q0 -> q1` (every
/// obstacle kind: meshes, shapes and point clouds), written to `*out`: its time (never later than the first touch),
/// pair and witnesses; separated; or an iteration limit.
///
/// **Thread safety**: as `mb_chain_scene_edge_is_free`.
///
/// # Safety
/// As `mb_chain_scene_edge_is_free`, `out` valid for writing an
/// `mb_segment_report`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn mb_chain_scene_check_segment(
    scene: *const MbChainScene,
    q0: *const f64,
    q1: *const f64,
    dof: usize,
    out: *mut MbSegmentReport,
) -> MbStatus {
    guard(|| {
        // SAFETY: this function's contract.
        let s = unsafe { handle_ref(scene, "scene") }?;
        let (chain, lim) = (s.scene.chain(), s.limits());
        // SAFETY: this function's contract.
        let (a, b) = unsafe {
            (
                coordinates(chain, q0, dof, lim, "q0")?,
                coordinates(chain, q1, dof, lim, "q1")?,
            )
        };
        let r = s
            .scene
            .check_segment(a, b)
            .map_err(|e| chain_failure(e, "q0, q1"))?;
        let nan = MbVec3 {
            x: f64::NAN,
            y: f64::NAN,
            z: f64::NAN,
        };
        let (outcome, time, pair, distance, pa, pb) = match r.outcome {
            SegmentOutcome::Contact(c) => (
                MbSegmentOutcome::Contact,
                c.time,
                s.pair(c.pair),
                c.distance,
                MbVec3::from_array(c.on_a.to_array()),
                MbVec3::from_array(c.on_b.to_array()),
            ),
            SegmentOutcome::IterationLimit { time, pair } => (
                MbSegmentOutcome::IterationLimit,
                time,
                s.pair(pair),
                f64::NAN,
                nan,
                nan,
            ),
            _ => (
                MbSegmentOutcome::Separated,
                f64::NAN,
                NO_PAIR,
                f64::NAN,
                nan,
                nan,
            ),
        };
        let st = r.stats;
        let report = MbSegmentReport {
            outcome,
            time,
            pair,
            distance,
            point_a: pa,
            point_b: pb,
            pairs: st.pairs as u64,
            excluded: st.excluded as u64,
            culled: st.culled as u64,
            advanced: st.advanced as u64,
            iterations: st.iterations as u64,
            node_pairs: st.node_pairs as u64,
            leaf_pairs: st.leaf_pairs as u64,
        };
        // SAFETY: this function's contract.
        unsafe { write_out(out, report, "out") }
    })
}

/// Whether some checked pair's surfaces meet at configuration `q`
/// (computed distance at most the padding), against meshes, shapes and
/// point clouds, written to `*out` (`1` or `0`): the static check a
/// sampling motion validator runs. `q` must be finite; the limits are not
/// checked.
///
/// **Thread safety**: as `mb_chain_scene_edge_is_free`.
///
/// # Safety
/// `scene` is not freed or changed during the call; `q` is `NULL` or valid
/// for reading `dof` doubles; `out` is `NULL` or valid for writing a
/// `uint8_t`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn mb_chain_scene_collides_at(
    scene: *const MbChainScene,
    q: *const f64,
    dof: usize,
    out: *mut u8,
) -> MbStatus {
    guard(|| {
        // SAFETY: this function's contract.
        let s = unsafe { handle_ref(scene, "scene") }?;
        // SAFETY: this function's contract.
        let q = unsafe { coordinates(s.scene.chain(), q, dof, false, "q") }?;
        let hit = s.scene.collides_at(q).map_err(|e| chain_failure(e, "q"))?;
        // SAFETY: this function's contract.
        unsafe { write_out(out, u8::from(hit), "out") }
    })
}

/// A certified lower bound of the smallest distance over the checked pairs
/// at configuration `q` (`<= 0` for touching or overlapping surfaces, up to
/// rounding; `INFINITY` when nothing is checked), written to `*out_distance`,
/// and the pair attaining it to `*out_pair` (`NULL` to skip). Every
/// obstacle kind: meshes, shapes and point clouds.
///
/// **Thread safety**: as `mb_chain_scene_edge_is_free`.
///
/// # Safety
/// As `mb_chain_scene_collides_at`; `out_distance` is `NULL` or valid for
/// writing a double, `out_pair` for an `mb_chain_pair`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn mb_chain_scene_clearance(
    scene: *const MbChainScene,
    q: *const f64,
    dof: usize,
    out_distance: *mut f64,
    out_pair: *mut MbChainPair,
) -> MbStatus {
    guard(|| {
        // SAFETY: this function's contract.
        let s = unsafe { handle_ref(scene, "scene") }?;
        // SAFETY: this function's contract.
        let q = unsafe { coordinates(s.scene.chain(), q, dof, false, "q") }?;
        if out_distance.is_null() {
            return Err(Failure::new(MbStatus::NullPointer, "out_distance is NULL"));
        }
        let (d, pair) = s.scene.clearance(q).map_err(|e| chain_failure(e, "q"))?;
        let pair = pair.map_or(NO_PAIR, |p| s.pair(p));
        // SAFETY: this function's contract.
        unsafe {
            write_out(out_distance, d, "out_distance")?;
            if !out_pair.is_null() {
                write_out(out_pair, pair, "out_pair")?;
            }
        }
        Ok(())
    })
}
