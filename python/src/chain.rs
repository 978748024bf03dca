//! Robot arms: `Chain` (a kinematic tree from a URDF, its links' collision
//! meshes with their ball trees) and `ChainScene` (a chain in still
//! surroundings: the first contact along a joint-space segment or path, the
//! static check at a configuration, and a planner's certified edge checks,
//! one at a time or a batch on every core).
//!
//! Obstacles are the module's bodies: convex primitives, half-spaces and
//! compounds of them become the crate's shape obstacles (measured exactly,
//! never meshed), meshes its mesh obstacles; point clouds come from numpy
//! arrays. A `ChainScene` remembers what was added, in order, and pickles
//! as its chain (a URDF path) and those additions.

use std::path::PathBuf;
use std::time::Instant;

use motion_bound::chain::{
    Chain as RustChain, ChainError, ChainPair, ChainParams, ChainScene as RustScene, ChainStats,
    EdgeOutcome, Obstacle, SegmentOutcome, ShapeObstacle, UrdfOptions,
};
use motion_bound::{Pose as RPose, Vec3};
use pyo3::exceptions::{PyFileNotFoundError, PyKeyError, PyTypeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList, PyTuple};
use rayon::prelude::*;

use crate::arrays::{floats, index, rows3, to_numpy, vec3};
use crate::body::{Body, Source};
use crate::errors::{InputError, MeshError, MotionBoundError, QueryError, UrdfError};
use crate::motion::{pose_arg, Pose};
use crate::query::next_chunk;
use motion_bound::ca::OwnedShape;

/// A chain's refusal, as the module's typed errors; `what` is the argument
/// it is about (`"q0"`, `"edges[3][1]"`, `"path"`).
fn chain_error(e: ChainError, what: &str) -> PyErr {
    match e {
        ChainError::WrongDof { expected, got } => PyValueError::new_err(format!(
            "{what} must have {expected} joint coordinates, got {got}"
        )),
        ChainError::NonFiniteCoordinate(i) => InputError::new_err(format!(
            "{what}[{i}] is NaN, infinite or beyond the input range"
        )),
        ChainError::BeyondLimits(i) => InputError::new_err(format!(
            "{what}[{i}] is outside its joint's limits (within_limits=False checks it anyway)"
        )),
        ChainError::InvalidParameter(p) => QueryError::new_err(format!("{what}: {p}")),
        ChainError::Urdf(m) => UrdfError::new_err(format!("{what}: {m}")),
        ChainError::Mesh(m) => MeshError::new_err(format!("{what}: {m}")),
        ChainError::Shape(e) => InputError::new_err(format!("{what}: {e}")),
        ChainError::UnknownName(n) => PyKeyError::new_err(format!("{what}: no link named {n:?}")),
        other => MotionBoundError::new_err(format!("{what}: {other}")),
    }
}

/// The crate's pose of a Python `Pose`.
fn rust_pose(p: &Pose) -> RPose<f64> {
    RPose {
        rotation: p.iso.rotation().matrix(),
        translation: p.iso.translation(),
    }
}

/// `a` then `b`: the pose of a part placed by `b` in a body placed by `a`.
fn compose(a: &RPose<f64>, b: &RPose<f64>) -> RPose<f64> {
    let mut r = [[0.0; 3]; 3];
    for (i, row) in r.iter_mut().enumerate() {
        for (j, x) in row.iter_mut().enumerate() {
            *x = (0..3).map(|k| a.rotation[i][k] * b.rotation[k][j]).sum();
        }
    }
    RPose {
        rotation: r,
        translation: a.transform_point(b.translation),
    }
}

/// A kinematic tree read from a URDF file: its links' collision meshes (each
/// with its ball tree, built once) and joints. `Chain.from_urdf(path)`;
/// immutable, picklable (as its URDF path: the file and its meshes must be
/// readable where it is unpickled).
#[pyclass(frozen, module = "motion_bound")]
pub struct Chain {
    pub(crate) chain: RustChain<f64>,
    path: PathBuf,
    package_root: Option<PathBuf>,
    base: Option<Pose>,
}

impl Chain {
    /// The coordinates `obj` as a vector of the chain's length, finite.
    fn coordinates(&self, obj: &Bound<'_, PyAny>, what: &str) -> PyResult<Vec<f64>> {
        let (v, shape) = floats(obj, what)?;
        let dof = self.chain.dof();
        if shape != [dof] {
            return Err(PyValueError::new_err(format!(
                "{what} must have shape ({dof},) (the chain's joint coordinates), got {shape:?}"
            )));
        }
        self.check_finite(&v, what)?;
        Ok(v)
    }

    /// `InputError` naming the first coordinate that is NaN, infinite or
    /// beyond the input range.
    fn check_finite(&self, q: &[f64], what: &str) -> PyResult<()> {
        use motion_bound::Float;
        for (i, &x) in q.iter().enumerate() {
            if !x.is_finite() {
                return Err(InputError::new_err(format!(
                    "{what}[{i}] is not finite (got {x})"
                )));
            }
            if x.abs() > <f64 as Float>::MAX_INPUT {
                return Err(InputError::new_err(format!(
                    "{what}[{i}] is beyond the input range (got {x})"
                )));
            }
        }
        Ok(())
    }

    /// `InputError` naming the first coordinate outside its joint's limits.
    fn check_limits(&self, q: &[f64], what: &str) -> PyResult<()> {
        let limits = self.chain.limits();
        for (k, (x, lim)) in q.iter().zip(&limits).enumerate() {
            if let Some([lo, hi]) = lim {
                if x < lo || x > hi {
                    let name = self.chain.joint_names().nth(k).unwrap_or("?");
                    return Err(InputError::new_err(format!(
                        "{what}[{k}] = {x} is outside joint {name:?}'s limits [{lo}, {hi}] \
                         (within_limits=False checks it anyway)"
                    )));
                }
            }
        }
        Ok(())
    }

    /// A link's index from its name or (possibly negative) index.
    fn link(&self, obj: &Bound<'_, PyAny>, what: &str) -> PyResult<usize> {
        if let Ok(i) = obj.extract::<isize>() {
            return index(i, self.chain.link_count(), what);
        }
        if let Ok(name) = obj.extract::<String>() {
            return self
                .chain
                .link_index(&name)
                .map_err(|_| PyKeyError::new_err(format!("{what}: no link named {name:?}")));
        }
        Err(PyTypeError::new_err(format!(
            "{what} must be a link's name (str) or index (int), got {}",
            obj.get_type().name()?
        )))
    }

    fn link_name(&self, i: usize) -> String {
        self.chain.link_name(i).unwrap_or("?").to_string()
    }
}

#[pymethods]
impl Chain {
    /// The chain of the URDF file at `path` (a `str` or `os.PathLike`):
    /// revolute, continuous, prismatic and fixed joints; each link's
    /// collision elements (OBJ and STL meshes; boxes exactly, cylinders,
    /// spheres and capsules as meshes that contain them) merged into one mesh.
    /// `package://NAME/...` paths are looked up under `package_root` first,
    /// then beside the URDF. `base` (a pose) places the root link in the
    /// world (default: the identity).
    ///
    /// Raises `FileNotFoundError` for a missing file, `UrdfError` for a file
    /// that cannot be parsed or uses what is not read (COLLADA meshes, a
    /// planar joint), `MeshError` for a link mesh without a ball tree.
    #[staticmethod]
    #[pyo3(signature = (path, base = None, package_root = None))]
    fn from_urdf(
        py: Python<'_>,
        path: PathBuf,
        base: Option<&Bound<'_, PyAny>>,
        package_root: Option<PathBuf>,
    ) -> PyResult<Self> {
        if !path.is_file() {
            return Err(PyFileNotFoundError::new_err(format!(
                "path: no such file: {}",
                path.display()
            )));
        }
        let path = path
            .canonicalize()
            .map_err(|e| PyFileNotFoundError::new_err(format!("path: {e}")))?;
        let base = base.map(|b| pose_arg(b, "base")).transpose()?;
        let mut options = UrdfOptions::default();
        options.package_root.clone_from(&package_root);
        let chain = py
            .detach(|| RustChain::<f64>::from_urdf_file_with(&path, &options))
            .map_err(|e| chain_error(e, "path"))?;
        let chain = match &base {
            Some(b) => chain
                .try_with_base(rust_pose(b))
                .map_err(|e| chain_error(e, "base"))?,
            None => chain,
        };
        Ok(Self {
            chain,
            path,
            package_root,
            base,
        })
    }

    /// The number of joint coordinates (movable joints).
    #[getter]
    fn dof(&self) -> usize {
        self.chain.dof()
    }

    /// The links' names, by index.
    #[getter]
    fn link_names(&self) -> Vec<String> {
        (0..self.chain.link_count())
            .map(|i| self.link_name(i))
            .collect()
    }

    /// The movable joints' names, in coordinate order.
    #[getter]
    fn joint_names(&self) -> Vec<String> {
        self.chain.joint_names().map(str::to_string).collect()
    }

    /// The joints' limits as a `(dof, 2)` array of `[lower, upper]`
    /// (`[-inf, inf]` for a continuous joint).
    #[getter]
    fn limits<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let flat: Vec<f64> = self
            .chain
            .limits()
            .iter()
            .flat_map(|l| l.unwrap_or([f64::NEG_INFINITY, f64::INFINITY]))
            .collect();
        to_numpy(py, flat, &[self.chain.dof(), 2])
    }

    /// The path of the URDF file (absolute).
    #[getter]
    fn path(&self) -> String {
        self.path.display().to_string()
    }

    /// A link's index by name (`KeyError` when there is none).
    fn link_index(&self, name: &str) -> PyResult<usize> {
        self.chain
            .link_index(name)
            .map_err(|_| PyKeyError::new_err(format!("name: no link named {name:?}")))
    }

    /// Link `link`'s (a name or an index) collision mesh in its own frame, as
    /// `(vertices, faces)` arrays (`(n, 3)` float64, `(m, 3)` int64), or
    /// `None` for a link without geometry.
    fn link_mesh<'py>(
        &self,
        py: Python<'py>,
        link: &Bound<'py, PyAny>,
    ) -> PyResult<Option<(Bound<'py, PyAny>, Bound<'py, PyAny>)>> {
        let l = self.link(link, "link")?;
        let Some(m) = self.chain.link_mesh(l) else {
            return Ok(None);
        };
        let v = to_numpy(py, m.vertices().concat(), &[m.vertices().len(), 3])?;
        let flat: Vec<i64> = m
            .triangles()
            .iter()
            .flatten()
            .map(|&i| i64::from(i))
            .collect();
        use numpy::PyArrayMethods;
        let f = numpy::PyArray1::from_vec(py, flat)
            .reshape(vec![m.triangles().len(), 3])?
            .into_any();
        Ok(Some((v, f)))
    }

    /// Every link's world pose at configuration `q`, as an `(links, 4, 4)`
    /// array of homogeneous matrices (link order as `link_names`).
    fn forward_kinematics<'py>(
        &self,
        py: Python<'py>,
        q: &Bound<'py, PyAny>,
    ) -> PyResult<Bound<'py, PyAny>> {
        let q = self.coordinates(q, "q")?;
        let poses = self
            .chain
            .try_forward_kinematics(&q)
            .map_err(|e| chain_error(e, "q"))?;
        let mut flat = Vec::with_capacity(poses.len() * 16);
        for p in &poses {
            for i in 0..3 {
                flat.extend_from_slice(&p.rotation[i]);
                flat.push(p.translation.to_array()[i]);
            }
            flat.extend_from_slice(&[0.0, 0.0, 0.0, 1.0]);
        }
        to_numpy(py, flat, &[poses.len(), 4, 4])
    }

    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> PyResult<Bound<'py, PyTuple>> {
        let py = slf.py();
        let this = slf.get();
        let f = py.get_type::<Self>().getattr("from_urdf")?;
        let base = match &this.base {
            Some(b) => Bound::new(py, b.clone())?.into_any(),
            None => py.None().into_bound(py),
        };
        let root = match &this.package_root {
            Some(r) => r.display().to_string().into_pyobject(py)?.into_any(),
            None => py.None().into_bound(py),
        };
        let path = this
            .path
            .display()
            .to_string()
            .into_pyobject(py)?
            .into_any();
        PyTuple::new(py, [f, PyTuple::new(py, [path, base, root])?.into_any()])
    }

    fn __repr__(&self) -> String {
        format!(
            "Chain({:?}, {} links, {} joint coordinates)",
            self.path.display().to_string(),
            self.chain.link_count(),
            self.chain.dof()
        )
    }
}

/// What was added to a scene, in order (how it pickles).
enum Added {
    Body {
        body: Py<Body>,
        pose: Box<Pose>,
        name: String,
    },
    Points {
        points: Vec<[f64; 3]>,
        radius: f64,
        name: String,
    },
}

/// A pair a query reports: a link and an obstacle (the scene's index), or
/// two links.
#[derive(Clone, Debug, PartialEq)]
struct PairInfo {
    kind: &'static str,
    a: usize,
    b: usize,
    names: (String, String),
}

/// One of a chain scene's obstacles, made for the crate.
enum Made {
    Shape(ShapeObstacle<f64>),
    Mesh(Obstacle<f64>),
}

/// A chain in still surroundings: what a planner's motion validator asks
/// about. `ChainScene(chain, contact_distance=1e-3, padding=0.0,
/// edge_budget=400000, within_limits=True, max_iterations=10000)`; obstacles
/// by `add_obstacle(body, pose)` and `add_points(points, radius)`; link pairs
/// never checked by `allow_collision(a, b)` and `allow_collisions_at(q)`.
///
/// Queries: `check_edge`, `edge_is_free` and `edges_are_free` (a planner's
/// certified edge checks: every obstacle kind and every checked link pair);
/// `check_segment`, `check_path`, `collides_at` and `clearance` (the first
/// contact, the static check and the distance at a configuration), on every
/// obstacle kind too: meshes, primitives, half-spaces and point clouds,
/// mixed in one scene. Every query releases the
/// GIL. Picklable (its chain as a URDF path, then what was added, replayed).
#[pyclass(module = "motion_bound")]
pub struct ChainScene {
    chain: Py<Chain>,
    scene: RustScene<f64>,
    added: Vec<Added>,
    /// For each of the crate's mesh obstacles, the scene's obstacle index.
    mesh_owner: Vec<usize>,
    /// For each of the crate's shape obstacles, the scene's obstacle index.
    shape_owner: Vec<usize>,
    /// The pairs allowed, in the order given (for pickling).
    allowed: Vec<(usize, usize)>,
}

impl ChainScene {
    fn chain(&self) -> &Chain {
        self.chain.get()
    }

    /// `body` placed at `at` as the crate's obstacles named `name`.
    fn make(&self, body: &Body, at: &RPose<f64>, name: &str, out: &mut Vec<Made>) -> PyResult<()> {
        let what = |e| chain_error(e, "pose");
        match (&body.shape, &body.source) {
            (OwnedShape::Convex(convex), _) => out.push(Made::Shape(
                ShapeObstacle::try_new(name, *convex, *at).map_err(what)?,
            )),
            (OwnedShape::Mesh(m), _) => out.push(Made::Mesh(
                Obstacle::try_new(name, m.mesh().clone(), *at).map_err(what)?,
            )),
            (_, Source::HalfSpace(normal)) => {
                let n = Vec3::from_array(*normal);
                let world = Vec3::from_array(at.rotation.map(|row| {
                    row[0] * n.to_array()[0] + row[1] * n.to_array()[1] + row[2] * n.to_array()[2]
                }));
                out.push(Made::Shape(
                    ShapeObstacle::try_half_space(
                        name,
                        world.to_array(),
                        at.translation.to_array(),
                    )
                    .map_err(what)?,
                ));
            }
            (_, Source::Compound(given)) => {
                for (part, pose) in given {
                    let placed = compose(at, &rust_pose(pose));
                    self.make(part.get(), &placed, name, out)?;
                }
            }
            _ => {
                return Err(PyValueError::new_err(
                    "body: a convex_hull is not a chain scene obstacle; give its triangles as \
                     mesh(vertices, faces)",
                ))
            }
        }
        Ok(())
    }

    fn add_made(&mut self, made: Vec<Made>) -> usize {
        let owner = self.added.len();
        for m in made {
            match m {
                Made::Shape(s) => {
                    self.scene.add_shape(s);
                    self.shape_owner.push(owner);
                }
                Made::Mesh(o) => {
                    self.scene.add_obstacle(o);
                    self.mesh_owner.push(owner);
                }
            }
        }
        owner
    }

    fn obstacle_name(&self, i: usize) -> String {
        match &self.added[i] {
            Added::Body { name, .. } | Added::Points { name, .. } => name.clone(),
        }
    }

    fn pair(&self, p: ChainPair) -> PairInfo {
        let chain = self.chain();
        let obstacle = |link: usize, owner: usize| PairInfo {
            kind: "obstacle",
            a: link,
            b: owner,
            names: (chain.link_name(link), self.obstacle_name(owner)),
        };
        match p {
            ChainPair::Obstacle { link, obstacle: o } => obstacle(link, self.mesh_owner[o]),
            ChainPair::Shape { link, shape } => obstacle(link, self.shape_owner[shape]),
            ChainPair::SelfCollision { a, b } => PairInfo {
                kind: "self",
                a,
                b,
                names: (chain.link_name(a), chain.link_name(b)),
            },
            _ => PairInfo {
                kind: "unknown",
                a: 0,
                b: 0,
                names: (String::new(), String::new()),
            },
        }
    }

    /// An end of a segment or edge: the chain's length, finite, within the
    /// limits when `within_limits` is on.
    fn end(&self, obj: &Bound<'_, PyAny>, what: &str) -> PyResult<Vec<f64>> {
        let q = self.chain().coordinates(obj, what)?;
        if self.scene.params().within_limits {
            self.chain().check_limits(&q, what)?;
        }
        Ok(q)
    }

    fn set(&mut self, p: ChainParams<f64>, name: &str) -> PyResult<()> {
        self.scene.set_params(p).map_err(|e| chain_error(e, name))
    }

    /// The segment report of a first-contact query.
    fn segment_report(
        &self,
        outcome: SegmentOutcome<f64>,
        stats: ChainStats,
        segment: Option<usize>,
    ) -> SegmentReport {
        let (kind, time, pair, distance, points) = match outcome {
            SegmentOutcome::Contact(c) => (
                "contact",
                Some(c.time),
                Some(self.pair(c.pair)),
                Some(c.distance),
                Some((c.on_a.to_array(), c.on_b.to_array())),
            ),
            SegmentOutcome::IterationLimit { time, pair } => (
                "iteration_limit",
                Some(time),
                Some(self.pair(pair)),
                None,
                None,
            ),
            SegmentOutcome::Separated => ("separated", None, None, None, None),
            _ => ("unknown", None, None, None, None),
        };
        SegmentReport {
            outcome: kind,
            time,
            pair,
            distance,
            points,
            segment,
            stats: [
                ("pairs", stats.pairs),
                ("excluded", stats.excluded),
                ("culled", stats.culled),
                ("advanced", stats.advanced),
                ("iterations", stats.iterations),
                ("node_pairs", stats.node_pairs),
                ("leaf_pairs", stats.leaf_pairs),
            ],
        }
    }

    /// The `(n, 2, dof)` edges, each end checked (names `edges[i][0]`).
    fn edges(&self, obj: &Bound<'_, PyAny>) -> PyResult<(Vec<f64>, usize)> {
        let (v, shape) = floats(obj, "edges")?;
        let dof = self.chain().chain.dof();
        if shape.len() != 3 || shape[1] != 2 || shape[2] != dof {
            return Err(PyValueError::new_err(format!(
                "edges must have shape (n, 2, {dof}) (n edges, their two ends, the chain's \
                 joint coordinates), got {shape:?}"
            )));
        }
        let within = self.scene.params().within_limits;
        for (k, q) in v.chunks_exact(dof).enumerate() {
            let what = format!("edges[{}][{}]", k / 2, k % 2);
            self.chain().check_finite(q, &what)?;
            if within {
                self.chain().check_limits(q, &what)?;
            }
        }
        Ok((v, shape[0]))
    }
}

#[pymethods]
impl ChainScene {
    #[new]
    #[pyo3(signature = (chain, contact_distance = 1e-3, padding = 0.0, edge_budget = 400_000, within_limits = true, max_iterations = 10_000))]
    fn py_new(
        chain: Bound<'_, Chain>,
        contact_distance: f64,
        padding: f64,
        edge_budget: i64,
        within_limits: bool,
        max_iterations: i64,
    ) -> PyResult<Self> {
        let mut s = Self {
            scene: RustScene::new(chain.get().chain.clone()),
            chain: chain.unbind(),
            added: Vec::new(),
            mesh_owner: Vec::new(),
            shape_owner: Vec::new(),
            allowed: Vec::new(),
        };
        s.set_contact_distance(contact_distance)?;
        s.set_padding(padding)?;
        s.set_edge_budget(edge_budget)?;
        s.set_within_limits(within_limits)?;
        s.set_max_iterations(max_iterations)?;
        Ok(s)
    }

    /// The chain.
    #[getter(chain)]
    fn get_chain(&self, py: Python<'_>) -> Py<Chain> {
        self.chain.clone_ref(py)
    }

    /// Adds `body` (`ball`, `capsule`, `box`, `cylinder`, `cone`,
    /// `half_space`, `mesh` or a `compound` of them) still at `pose` (a
    /// `Pose` or a 4x4 array; default the identity) and returns its obstacle
    /// index. Primitives and half-spaces are measured exactly (never meshed);
    /// a mesh obstacle is its triangles (a link wholly inside it is not a
    /// contact). Capsules, cylinders and cones lie along their **y** axis.
    /// `name` (default `"obstacle<i>"`) is what reports name.
    #[pyo3(signature = (body, pose = None, name = None))]
    fn add_obstacle(
        &mut self,
        body: Bound<'_, PyAny>,
        pose: Option<&Bound<'_, PyAny>>,
        name: Option<String>,
    ) -> PyResult<usize> {
        let body: Bound<'_, Body> = body.cast_into().map_err(|e| {
            PyTypeError::new_err(format!(
                "body must be a Body (ball, box, mesh, ...), got {}",
                e.into_inner()
                    .get_type()
                    .name()
                    .map(|n| n.to_string())
                    .unwrap_or_default()
            ))
        })?;
        let pose = match pose {
            Some(p) => pose_arg(p, "pose")?,
            None => Pose::from_source(crate::motion::PoseSource::Quaternion {
                wxyz: [1.0, 0.0, 0.0, 0.0],
                translation: [0.0; 3],
            })?,
        };
        let name = name.unwrap_or_else(|| format!("obstacle{}", self.added.len()));
        let mut made = Vec::new();
        self.make(body.get(), &rust_pose(&pose), &name, &mut made)?;
        let i = self.add_made(made);
        self.added.push(Added::Body {
            body: body.unbind(),
            pose: Box::new(pose),
            name,
        });
        Ok(i)
    }

    /// Adds a point cloud: a ball of `radius` (at least 0) about each row of
    /// `points` (an `(n, 3)` array, world coordinates; a depth camera's
    /// points with its noise as the radius), measured exactly; returns its
    /// obstacle index.
    #[pyo3(signature = (points, radius, name = None))]
    fn add_points(
        &mut self,
        points: &Bound<'_, PyAny>,
        radius: f64,
        name: Option<String>,
    ) -> PyResult<usize> {
        let pts = rows3(points, "points")?;
        crate::errors::length_arg(radius, "radius")?;
        let name = name.unwrap_or_else(|| format!("obstacle{}", self.added.len()));
        let shape =
            ShapeObstacle::try_points(&name, &pts, radius).map_err(|e| chain_error(e, "points"))?;
        let i = self.add_made(vec![Made::Shape(shape)]);
        self.added.push(Added::Points {
            points: pts,
            radius,
            name,
        });
        Ok(i)
    }

    /// The number of obstacles added.
    fn __len__(&self) -> usize {
        self.added.len()
    }

    /// The obstacles' names, by index.
    #[getter]
    fn obstacle_names(&self) -> Vec<String> {
        (0..self.added.len())
            .map(|i| self.obstacle_name(i))
            .collect()
    }

    /// Never checks links `a` and `b` (names or indices) against each other
    /// (an SRDF's `disable_collisions`).
    fn allow_collision(&mut self, a: &Bound<'_, PyAny>, b: &Bound<'_, PyAny>) -> PyResult<()> {
        let a = self.chain().link(a, "a")?;
        let b = self.chain().link(b, "b")?;
        self.scene.allow_collision(a, b);
        self.allowed.push((a, b));
        Ok(())
    }

    /// Never checks again the pairs of links whose surfaces are within
    /// `distance` (default 0: touching) at configuration `q` (an SRDF's
    /// pairs in collision by default, fingers closed on each other), and
    /// returns them as name pairs (link pairs only: obstacles of any kind
    /// stay checked).
    #[pyo3(signature = (q, distance = 0.0))]
    fn allow_collisions_at(
        &mut self,
        py: Python<'_>,
        q: &Bound<'_, PyAny>,
        distance: f64,
    ) -> PyResult<Vec<(String, String)>> {
        let q = self.chain().coordinates(q, "q")?;
        crate::errors::length_arg(distance, "distance")?;
        let scene = &mut self.scene;
        let pairs = py
            .detach(|| scene.allow_collisions_at(&q, distance))
            .map_err(|e| chain_error(e, "q"))?;
        self.allowed.extend(&pairs);
        let chain = self.chain();
        Ok(pairs
            .into_iter()
            .map(|(a, b)| (chain.link_name(a), chain.link_name(b)))
            .collect())
    }

    /// Surfaces this close count as touching (world units, positive; default
    /// 1e-3).
    #[getter]
    fn contact_distance(&self) -> f64 {
        self.scene.params().contact_distance
    }

    #[setter]
    fn set_contact_distance(&mut self, d: f64) -> PyResult<()> {
        if !(d.is_finite() && d > 0.0) {
            return Err(QueryError::new_err(format!(
                "contact_distance must be positive and finite (got {d})"
            )));
        }
        let p = self.scene.params().with_contact_distance(d);
        self.set(p, "contact_distance")
    }

    /// What the edge queries keep between the links and everything else
    /// (world units, default 0: exact).
    #[getter]
    fn padding(&self) -> f64 {
        self.scene.params().padding
    }

    #[setter]
    fn set_padding(&mut self, d: f64) -> PyResult<()> {
        if !(d.is_finite() && d >= 0.0) {
            return Err(QueryError::new_err(format!(
                "padding must be finite and at least 0 (got {d})"
            )));
        }
        let p = self.scene.params().with_padding(d);
        self.set(p, "padding")
    }

    /// The most items (a ball or triangle against what it is checked
    /// against) an edge query tests before it answers `"undecided"`
    /// (default 400,000: about 50 ms on the Panda).
    #[getter]
    fn edge_budget(&self) -> usize {
        self.scene.params().edge_budget
    }

    #[setter]
    fn set_edge_budget(&mut self, n: i64) -> PyResult<()> {
        let n = usize::try_from(n).ok().filter(|&n| n >= 1).ok_or_else(|| {
            QueryError::new_err(format!(
                "edge_budget must be an integer at least 1 (got {n})"
            ))
        })?;
        let p = self.scene.params().with_edge_budget(n);
        self.set(p, "edge_budget")
    }

    /// Whether the ends of segments, paths and edges must be within the
    /// joints' limits (`InputError` otherwise; default True).
    #[getter]
    fn within_limits(&self) -> bool {
        self.scene.params().within_limits
    }

    #[setter]
    fn set_within_limits(&mut self, on: bool) -> PyResult<()> {
        let p = self.scene.params().with_within_limits(on);
        self.set(p, "within_limits")
    }

    /// Iterations per pair and segment of `check_segment` and `check_path`
    /// (default 10,000).
    #[getter]
    fn max_iterations(&self) -> usize {
        self.scene.params().max_iterations
    }

    #[setter]
    fn set_max_iterations(&mut self, n: i64) -> PyResult<()> {
        let n = usize::try_from(n).ok().filter(|&n| n >= 1).ok_or_else(|| {
            QueryError::new_err(format!(
                "max_iterations must be an integer at least 1 (got {n})"
            ))
        })?;
        let mut p = self.scene.params();
        p.max_iterations = n;
        self.set(p, "max_iterations")
    }

    /// The parameters as a dict (`contact_distance`, `padding`,
    /// `edge_budget`, `within_limits`, `max_iterations`).
    #[getter]
    fn params<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let p = self.scene.params();
        let d = PyDict::new(py);
        d.set_item("contact_distance", p.contact_distance)?;
        d.set_item("padding", p.padding)?;
        d.set_item("edge_budget", p.edge_budget)?;
        d.set_item("within_limits", p.within_limits)?;
        d.set_item("max_iterations", p.max_iterations)?;
        Ok(d)
    }

    /// The certified check of the joint-space edge `q0 -> q1` (straight in
    /// joint space) against every obstacle and checked link pair: an
    /// `EdgeReport` whose `outcome` is `"free"` (certified), `"contact"`
    /// (free on `[0, free_until]`, the pair within the contact distance plus
    /// the padding at `at`, never later than the first touch) or
    /// `"undecided"` (the edge budget ran out: free on `[0, free_until]`).
    fn check_edge(
        &self,
        py: Python<'_>,
        q0: &Bound<'_, PyAny>,
        q1: &Bound<'_, PyAny>,
    ) -> PyResult<EdgeReport> {
        let (a, b) = (self.end(q0, "q0")?, self.end(q1, "q1")?);
        let scene = &self.scene;
        let r = py
            .detach(|| scene.check_edge(&a, &b))
            .map_err(|e| chain_error(e, "q0, q1"))?;
        let (outcome, free_until, at, pair) = match r.outcome {
            EdgeOutcome::Free => ("free", 1.0, None, None),
            EdgeOutcome::Contact {
                free_until,
                at,
                pair,
            } => ("contact", free_until, Some(at), Some(self.pair(pair))),
            EdgeOutcome::Undecided { free_until } => ("undecided", free_until, None, None),
            _ => ("undecided", 0.0, None, None),
        };
        Ok(EdgeReport {
            outcome,
            free_until,
            at,
            pair,
            stats: [
                ("tests", r.stats.tests),
                ("leaf_tests", r.stats.leaf_tests),
                ("intervals", r.stats.intervals),
            ],
        })
    }

    /// Whether the edge `q0 -> q1` is certified free (`check_edge`'s
    /// `"free"`; a contact or an undecided edge is `False`).
    fn edge_is_free(
        &self,
        py: Python<'_>,
        q0: &Bound<'_, PyAny>,
        q1: &Bound<'_, PyAny>,
    ) -> PyResult<bool> {
        let (a, b) = (self.end(q0, "q0")?, self.end(q1, "q1")?);
        let scene = &self.scene;
        py.detach(|| scene.edge_is_free(&a, &b))
            .map_err(|e| chain_error(e, "q0, q1"))
    }

    /// `edge_is_free` of each edge of `edges`, an `(n, 2, dof)` array (edge
    /// `i` from `edges[i, 0]` to `edges[i, 1]`), as a bool array of length
    /// `n`: the same answers as one `edge_is_free` per edge. Every end is
    /// checked first (an error names it: `edges[3][1][2] is not finite`).
    /// On every core by default (one edge checker per worker), with the GIL
    /// released; in chunks of about 20 ms, between which Ctrl-C is honoured
    /// and `progress(done, total)` called (as `time_of_impact_batch`).
    #[pyo3(signature = (edges, parallel = true, progress = None))]
    fn edges_are_free<'py>(
        &self,
        py: Python<'py>,
        edges: &Bound<'py, PyAny>,
        parallel: bool,
        progress: Option<&Bound<'py, PyAny>>,
    ) -> PyResult<Bound<'py, PyAny>> {
        if let Some(cb) = progress {
            if !cb.is_callable() {
                return Err(PyTypeError::new_err(
                    "progress must be callable as progress(done, total)",
                ));
            }
        }
        let (v, n) = self.edges(edges)?;
        let dof = self.chain().chain.dof();
        let scene = &self.scene;
        let end = |i: usize, k: usize| &v[(2 * i + k) * dof..(2 * i + k + 1) * dof];
        let threads = if parallel {
            rayon::current_num_threads()
        } else {
            1
        };
        let mut out: Vec<bool> = Vec::with_capacity(n);
        let mut serial = scene.edge_checker();
        let mut chunk = threads;
        while out.len() < n {
            let (lo, hi) = (out.len(), (out.len() + chunk).min(n));
            let clock = Instant::now();
            py.detach(|| -> PyResult<()> {
                if parallel {
                    let part: Result<Vec<bool>, ChainError> = (lo..hi)
                        .into_par_iter()
                        .map_init(
                            || scene.edge_checker(),
                            |c, i| c.is_free(end(i, 0), end(i, 1)),
                        )
                        .collect();
                    out.extend(part.map_err(|e| chain_error(e, "edges"))?);
                } else {
                    for i in lo..hi {
                        out.push(
                            serial
                                .is_free(end(i, 0), end(i, 1))
                                .map_err(|e| chain_error(e, &format!("edges[{i}]")))?,
                        );
                    }
                }
                Ok(())
            })?;
            chunk = next_chunk(hi - lo, clock.elapsed().as_secs_f64(), threads);
            py.check_signals()?;
            if let Some(cb) = progress {
                cb.call1((hi, n))?;
            }
        }
        Ok(numpy::PyArray1::from_vec(py, out).into_any())
    }

    /// The first contact along the joint-space segment `q0 -> q1` (every
    /// obstacle kind): a `SegmentReport` (`"contact"` with its `time`, never
    /// later than the first touch, the pair and the witness points;
    /// `"separated"`; or `"iteration_limit"` with the time up to which the
    /// segment is certified free).
    fn check_segment(
        &self,
        py: Python<'_>,
        q0: &Bound<'_, PyAny>,
        q1: &Bound<'_, PyAny>,
    ) -> PyResult<SegmentReport> {
        let (a, b) = (self.end(q0, "q0")?, self.end(q1, "q1")?);
        let scene = &self.scene;
        let r = py
            .detach(|| scene.check_segment(&a, &b))
            .map_err(|e| chain_error(e, "q0, q1"))?;
        Ok(self.segment_report(r.outcome, r.stats, None))
    }

    /// The first contact along a path of waypoints (an `(n, dof)` array, `n`
    /// at least 2), segment by segment, stopping at the first segment with a
    /// contact or an undecided one (every obstacle kind): a `SegmentReport`
    /// whose `segment` is that segment's index (the last one when the whole
    /// path is separated) and whose `time` is along that segment.
    fn check_path(&self, py: Python<'_>, path: &Bound<'_, PyAny>) -> PyResult<SegmentReport> {
        let (v, shape) = floats(path, "path")?;
        let dof = self.chain().chain.dof();
        if shape.len() != 2 || shape[1] != dof || shape[0] < 2 {
            return Err(PyValueError::new_err(format!(
                "path must have shape (n, {dof}) with n at least 2 (waypoints of the chain's \
                 joint coordinates), got {shape:?}"
            )));
        }
        let within = self.scene.params().within_limits;
        let waypoints: Vec<&[f64]> = v.chunks_exact(dof).collect();
        for (k, q) in waypoints.iter().enumerate() {
            let what = format!("path[{k}]");
            self.chain().check_finite(q, &what)?;
            if within {
                self.chain().check_limits(q, &what)?;
            }
        }
        let scene = &self.scene;
        let r = py
            .detach(|| scene.check_path(&waypoints))
            .map_err(|e| chain_error(e, "path"))?;
        Ok(self.segment_report(r.outcome, r.stats, Some(r.segment)))
    }

    /// Whether some checked pair's surfaces meet at configuration `q`
    /// (computed distance at most the padding, 0 by default), against
    /// meshes, shapes and point clouds: the static check a sampling motion
    /// validator runs.
    fn collides_at(&self, py: Python<'_>, q: &Bound<'_, PyAny>) -> PyResult<bool> {
        let q = self.chain().coordinates(q, "q")?;
        let scene = &self.scene;
        py.detach(|| scene.collides_at(&q))
            .map_err(|e| chain_error(e, "q"))
    }

    /// A certified lower bound of the smallest distance over the checked
    /// pairs at `q` (every obstacle kind), and that pair's names (`None`
    /// when nothing is checked).
    fn clearance(
        &self,
        py: Python<'_>,
        q: &Bound<'_, PyAny>,
    ) -> PyResult<(f64, Option<(String, String)>)> {
        let q = self.chain().coordinates(q, "q")?;
        let scene = &self.scene;
        let (d, pair) = py
            .detach(|| scene.clearance(&q))
            .map_err(|e| chain_error(e, "q"))?;
        Ok((d, pair.map(|p| self.pair(p).names)))
    }

    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> PyResult<Bound<'py, PyTuple>> {
        let py = slf.py();
        let this = slf.borrow();
        let cls = py.get_type::<Self>().into_any();
        let args = PyTuple::new(py, [this.chain.clone_ref(py).into_bound(py).into_any()])?;
        let obstacles = PyList::empty(py);
        for a in &this.added {
            let item = match a {
                Added::Body { body, pose, name } => PyTuple::new(
                    py,
                    [
                        "body".into_pyobject(py)?.into_any(),
                        body.clone_ref(py).into_bound(py).into_any(),
                        Bound::new(py, Pose::clone(pose))?.into_any(),
                        name.into_pyobject(py)?.into_any(),
                    ],
                )?,
                Added::Points {
                    points,
                    radius,
                    name,
                } => PyTuple::new(
                    py,
                    [
                        "points".into_pyobject(py)?.into_any(),
                        to_numpy(py, points.concat(), &[points.len(), 3])?,
                        radius.into_pyobject(py)?.into_any(),
                        name.into_pyobject(py)?.into_any(),
                    ],
                )?,
            };
            obstacles.append(item)?;
        }
        let state = PyDict::new(py);
        state.set_item("params", this.params(py)?)?;
        state.set_item("obstacles", obstacles)?;
        state.set_item("allowed", this.allowed.clone())?;
        PyTuple::new(py, [cls, args.into_any(), state.into_any()])
    }

    fn __setstate__(&mut self, state: &Bound<'_, PyDict>) -> PyResult<()> {
        let get = |k: &str| -> PyResult<Bound<'_, PyAny>> {
            state
                .get_item(k)?
                .ok_or_else(|| PyValueError::new_err(format!("state: no {k:?}")))
        };
        let params = get("params")?;
        let params: &Bound<'_, PyDict> = params.cast()?;
        for (k, v) in params.iter() {
            let k: String = k.extract()?;
            match k.as_str() {
                "contact_distance" => self.set_contact_distance(v.extract()?)?,
                "padding" => self.set_padding(v.extract()?)?,
                "edge_budget" => self.set_edge_budget(v.extract()?)?,
                "within_limits" => self.set_within_limits(v.extract()?)?,
                "max_iterations" => self.set_max_iterations(v.extract()?)?,
                other => {
                    return Err(PyValueError::new_err(format!(
                        "state: no parameter {other:?}"
                    )))
                }
            }
        }
        for item in get("obstacles")?.try_iter()? {
            let (kind, x, y, name): (String, Bound<'_, PyAny>, Bound<'_, PyAny>, String) =
                item?.extract()?;
            if kind == "body" {
                self.add_obstacle(x, Some(&y), Some(name))?;
            } else {
                self.add_points(&x, y.extract()?, Some(name))?;
            }
        }
        let allowed: Vec<(usize, usize)> = get("allowed")?.extract()?;
        for (a, b) in allowed {
            self.scene.allow_collision(a, b);
            self.allowed.push((a, b));
        }
        Ok(())
    }

    fn __repr__(&self) -> String {
        format!(
            "ChainScene({}, {} obstacles, {} pairs allowed)",
            self.chain().__repr__(),
            self.added.len(),
            self.allowed.len()
        )
    }
}

/// `value` as the one of `names` it equals (a report's outcome or pair kind, rebuilt), or an
/// error naming `what` and the choices.
fn one_of(value: &str, names: &[&'static str], what: &str) -> PyResult<&'static str> {
    names.iter().copied().find(|n| *n == value).ok_or_else(|| {
        PyValueError::new_err(format!(
            "{what}: unknown value {value:?} (one of {})",
            names.join(", ")
        ))
    })
}

/// A report's pair from its three fields, all given or all None.
fn pair_of(
    pair: Option<(String, String)>,
    pair_kind: Option<&str>,
    pair_indices: Option<(usize, usize)>,
) -> PyResult<Option<PairInfo>> {
    match (pair, pair_kind, pair_indices) {
        (Some(names), Some(kind), Some((a, b))) => Ok(Some(PairInfo {
            kind: one_of(kind, &["obstacle", "self", "unknown"], "pair_kind")?,
            a,
            b,
            names,
        })),
        (None, None, None) => Ok(None),
        _ => Err(PyValueError::new_err(
            "pair, pair_kind, pair_indices: give all three or none",
        )),
    }
}

/// A report's counters from its `stats` dict, in the order of `keys`.
fn stats_of<const N: usize>(
    stats: &Bound<'_, PyDict>,
    keys: [&'static str; N],
) -> PyResult<[(&'static str, usize); N]> {
    let mut out = [("", 0); N];
    for (slot, key) in out.iter_mut().zip(keys) {
        let v = stats
            .get_item(key)?
            .ok_or_else(|| PyKeyError::new_err(format!("stats: no {key:?}")))?;
        *slot = (key, v.extract()?);
    }
    Ok(out)
}

/// The counters of an `EdgeReport`, in order.
const EDGE_STATS: [&str; 3] = ["tests", "leaf_tests", "intervals"];

/// The counters of a `SegmentReport`, in order.
const SEGMENT_STATS: [&str; 7] = [
    "pairs",
    "excluded",
    "culled",
    "advanced",
    "iterations",
    "node_pairs",
    "leaf_pairs",
];

/// What `ChainScene.check_edge` found: `outcome` (`"free"`, `"contact"` or
/// `"undecided"`), `free` (certified free), `free_until` (the edge is
/// certified free on `[0, free_until]`; 1 when free), `at` (a contact's
/// time, `free_until <= at`, else None), `pair` (a contact's names: the link
/// and the obstacle or the other link, else None), `pair_kind`
/// (`"obstacle"` or `"self"`), `pair_indices` (the link's index and the
/// obstacle's or other link's), `stats` (the work: `tests`, `leaf_tests`,
/// `intervals`).
#[pyclass(frozen, module = "motion_bound")]
#[derive(Debug, PartialEq)]
pub struct EdgeReport {
    outcome: &'static str,
    free_until: f64,
    at: Option<f64>,
    pair: Option<PairInfo>,
    stats: [(&'static str, usize); 3],
}

#[pymethods]
impl EdgeReport {
    /// Rebuilds a report from its fields (what pickling does).
    #[new]
    #[pyo3(signature = (outcome, free_until, at, pair, pair_kind, pair_indices, stats))]
    fn py_new(
        outcome: &str,
        free_until: f64,
        at: Option<f64>,
        pair: Option<(String, String)>,
        pair_kind: Option<&str>,
        pair_indices: Option<(usize, usize)>,
        stats: &Bound<'_, PyDict>,
    ) -> PyResult<Self> {
        Ok(Self {
            outcome: one_of(outcome, &["free", "contact", "undecided"], "outcome")?,
            free_until,
            at,
            pair: pair_of(pair, pair_kind, pair_indices)?,
            stats: stats_of(stats, EDGE_STATS)?,
        })
    }

    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> PyResult<Bound<'py, PyTuple>> {
        let py = slf.py();
        let r = slf.get();
        let args = (
            r.outcome,
            r.free_until,
            r.at,
            r.pair(),
            r.pair_kind(),
            r.pair_indices(),
            r.stats(py)?,
        )
            .into_pyobject(py)?;
        PyTuple::new(py, [py.get_type::<Self>().into_any(), args.into_any()])
    }

    /// Equal when every field is (a pickled copy is equal).
    fn __eq__(&self, other: &Self) -> bool {
        self == other
    }

    /// `"free"`, `"contact"` or `"undecided"`.
    #[getter]
    fn outcome(&self) -> &'static str {
        self.outcome
    }

    /// Whether the edge is certified free.
    #[getter]
    fn free(&self) -> bool {
        self.outcome == "free"
    }

    /// The edge is certified free on `[0, free_until]` (1 when free).
    #[getter]
    fn free_until(&self) -> f64 {
        self.free_until
    }

    /// A contact's time (the pair within the contact distance plus the
    /// padding), else None.
    #[getter]
    fn at(&self) -> Option<f64> {
        self.at
    }

    /// A contact's pair as names, else None.
    #[getter]
    fn pair(&self) -> Option<(String, String)> {
        self.pair.as_ref().map(|p| p.names.clone())
    }

    /// `"obstacle"` or `"self"` for a contact, else None.
    #[getter]
    fn pair_kind(&self) -> Option<&'static str> {
        self.pair.as_ref().map(|p| p.kind)
    }

    /// A contact's pair as indices (the link, then the obstacle or the
    /// other link), else None.
    #[getter]
    fn pair_indices(&self) -> Option<(usize, usize)> {
        self.pair.as_ref().map(|p| (p.a, p.b))
    }

    /// The work done.
    #[getter]
    fn stats<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let d = PyDict::new(py);
        for (k, v) in self.stats {
            d.set_item(k, v)?;
        }
        Ok(d)
    }

    fn __repr__(&self) -> String {
        match (&self.pair, self.at) {
            (Some(p), Some(at)) => format!(
                "EdgeReport({}, free_until={}, at={}, pair=({:?}, {:?}))",
                self.outcome, self.free_until, at, p.names.0, p.names.1
            ),
            _ if self.outcome == "free" => "EdgeReport(free)".to_string(),
            _ => format!(
                "EdgeReport({}, free_until={})",
                self.outcome, self.free_until
            ),
        }
    }
}

/// What `ChainScene.check_segment` and `check_path` found: `outcome`
/// (`"contact"`, `"separated"` or `"iteration_limit"`), `hit`, `time` (the
/// contact's time, never later than the first touch, or the time up to
/// which the segment is certified free; None when separated), `pair`,
/// `pair_kind`, `pair_indices` (as `EdgeReport`), `distance` and `point_a`,
/// `point_b` (a contact's computed distance and witness points in the world,
/// on the link and on the obstacle or second link), `segment` (a path's
/// segment index; None for `check_segment`), `stats`.
#[pyclass(frozen, module = "motion_bound")]
#[derive(Debug, PartialEq)]
pub struct SegmentReport {
    outcome: &'static str,
    time: Option<f64>,
    pair: Option<PairInfo>,
    distance: Option<f64>,
    points: Option<([f64; 3], [f64; 3])>,
    segment: Option<usize>,
    stats: [(&'static str, usize); 7],
}

#[pymethods]
impl SegmentReport {
    /// Rebuilds a report from its fields (what pickling does).
    #[new]
    #[pyo3(signature = (outcome, time, pair, pair_kind, pair_indices, distance, point_a, point_b, segment, stats))]
    #[allow(clippy::too_many_arguments)]
    fn py_new(
        outcome: &str,
        time: Option<f64>,
        pair: Option<(String, String)>,
        pair_kind: Option<&str>,
        pair_indices: Option<(usize, usize)>,
        distance: Option<f64>,
        point_a: Option<&Bound<'_, PyAny>>,
        point_b: Option<&Bound<'_, PyAny>>,
        segment: Option<usize>,
        stats: &Bound<'_, PyDict>,
    ) -> PyResult<Self> {
        let points = match (point_a, point_b) {
            (Some(a), Some(b)) => Some((vec3(a, "point_a")?, vec3(b, "point_b")?)),
            (None, None) => None,
            _ => return Err(PyValueError::new_err("point_a, point_b: give both or none")),
        };
        Ok(Self {
            outcome: one_of(
                outcome,
                &["contact", "separated", "iteration_limit", "unknown"],
                "outcome",
            )?,
            time,
            pair: pair_of(pair, pair_kind, pair_indices)?,
            distance,
            points,
            segment,
            stats: stats_of(stats, SEGMENT_STATS)?,
        })
    }

    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> PyResult<Bound<'py, PyTuple>> {
        let py = slf.py();
        let r = slf.get();
        let args = (
            r.outcome,
            r.time,
            r.pair(),
            r.pair_kind(),
            r.pair_indices(),
            r.distance,
            r.point_a(py)?,
            r.point_b(py)?,
            r.segment,
            r.stats(py)?,
        )
            .into_pyobject(py)?;
        PyTuple::new(py, [py.get_type::<Self>().into_any(), args.into_any()])
    }

    /// Equal when every field is (a pickled copy is equal).
    fn __eq__(&self, other: &Self) -> bool {
        self == other
    }

    /// `"contact"`, `"separated"` or `"iteration_limit"`.
    #[getter]
    fn outcome(&self) -> &'static str {
        self.outcome
    }

    /// Whether a contact was found.
    #[getter]
    fn hit(&self) -> bool {
        self.outcome == "contact"
    }

    /// The contact's time, or the certified free time of an iteration
    /// limit; None when separated.
    #[getter]
    fn time(&self) -> Option<f64> {
        self.time
    }

    /// The pair as names, else None.
    #[getter]
    fn pair(&self) -> Option<(String, String)> {
        self.pair.as_ref().map(|p| p.names.clone())
    }

    /// `"obstacle"` or `"self"`, else None.
    #[getter]
    fn pair_kind(&self) -> Option<&'static str> {
        self.pair.as_ref().map(|p| p.kind)
    }

    /// The pair as indices, else None.
    #[getter]
    fn pair_indices(&self) -> Option<(usize, usize)> {
        self.pair.as_ref().map(|p| (p.a, p.b))
    }

    /// A contact's computed distance (at most the contact distance).
    #[getter]
    fn distance(&self) -> Option<f64> {
        self.distance
    }

    /// A contact's witness point on the link (the first link), in the world.
    #[getter]
    fn point_a<'py>(&self, py: Python<'py>) -> PyResult<Option<Bound<'py, PyAny>>> {
        self.points
            .map(|(a, _)| to_numpy(py, a.to_vec(), &[3]))
            .transpose()
    }

    /// A contact's witness point on the obstacle (the second link).
    #[getter]
    fn point_b<'py>(&self, py: Python<'py>) -> PyResult<Option<Bound<'py, PyAny>>> {
        self.points
            .map(|(_, b)| to_numpy(py, b.to_vec(), &[3]))
            .transpose()
    }

    /// A path's segment index (None for `check_segment`).
    #[getter]
    fn segment(&self) -> Option<usize> {
        self.segment
    }

    /// The work done.
    #[getter]
    fn stats<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let d = PyDict::new(py);
        for (k, v) in self.stats {
            d.set_item(k, v)?;
        }
        Ok(d)
    }

    fn __repr__(&self) -> String {
        let seg = self
            .segment
            .map(|s| format!(", segment={s}"))
            .unwrap_or_default();
        match (&self.pair, self.time) {
            (Some(p), Some(t)) => format!(
                "SegmentReport({}, time={t}, pair=({:?}, {:?}){seg})",
                self.outcome, p.names.0, p.names.1
            ),
            _ => format!("SegmentReport({}{seg})", self.outcome),
        }
    }
}

pub(crate) fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<Chain>()?;
    m.add_class::<ChainScene>()?;
    m.add_class::<EdgeReport>()?;
    m.add_class::<SegmentReport>()?;
    Ok(())
}
