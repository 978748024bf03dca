"""Certified continuous collision detection: the first time of contact of two
moving bodies, never late and never missed (conservative advancement with proven
motion bounds; the Rust crate motion-bound)."""

import os
from typing import Any, Iterable, Literal, Optional, Tuple, Union

import numpy as np
import numpy.typing as npt
from typing import Callable

__version__: str

ArrayLike = npt.ArrayLike
PoseLike = Union["Pose", npt.ArrayLike]
LinkLike = Union[str, int]
Outcome = Literal[
    "contact", "initial_contact", "separated", "iteration_limit", "work_limit", "precision_limit"
]

class MotionBoundError(ValueError):
    """Base class of motion_bound's errors: bad input or parameters."""

class InputError(MotionBoundError):
    """A number the core refuses (NaN, infinity, out of range, a zero direction,
    a matrix that is not a rotation, a negative radius, an empty vertex set).
    The message begins with the argument's name, with its index in an array
    (`starts[3]: ...`, `half_extents[1] is negative`)."""

class MeshError(MotionBoundError):
    """A triangle mesh the crate cannot use (no triangle, an index out of range)."""

class QueryError(MotionBoundError):
    """A query that cannot run (a parameter out of range, motions over different
    intervals, a turning half-space, two half-spaces)."""

class UrdfError(MotionBoundError):
    """A URDF file that cannot be parsed or uses what is not read (a COLLADA
    mesh, a planar or floating joint, a mesh file that cannot be read)."""

class Body:
    """A shape in its own frame (a mesh with its ball tree, built once);
    immutable, thread-safe, picklable. No `==`: bodies compare by identity
    (compare `kind` and answers; a mesh's tree is not compared)."""

    @property
    def kind(
        self,
    ) -> Literal[
        "mesh", "ball", "capsule", "box", "cylinder", "cone", "convex_hull", "half_space", "compound"
    ]: ...
    @property
    def vertices(self) -> Optional[np.ndarray]:
        """A mesh's `(n, 3)` vertices (a hull's points), else None."""
    @property
    def faces(self) -> Optional[np.ndarray]:
        """A mesh's `(m, 3)` int64 triangles, else None."""
    @property
    def solid(self) -> Optional[bool]:
        """A mesh's: solid (a body starting inside is in contact) or hollow; else None."""
    @property
    def reach(self) -> float:
        """An upper bound of every point's distance from the body origin."""

def mesh(vertices: ArrayLike, faces: ArrayLike, solid: Optional[bool] = None) -> Body:
    """A triangle mesh: `(n, 3)` real vertices, `(m, 3)` integer faces. `solid=None`: solid
    (a body starting inside is in contact) when closed and wound outward, else hollow;
    `True`: solid or `MeshError`; `False`: hollow."""

def from_trimesh(mesh: Any, solid: Optional[bool] = None) -> Body:
    """The body of a trimesh object. trimesh's exact primitives are taken as
    trimesh means them, as exact convex shapes: `trimesh.primitives.Sphere`
    (`radius`), `Box` (full `extents`, halved here), `Capsule` (`height`
    between the sphere centres, along z) and `Cylinder` (whole `height`, along
    z), each at its `primitive.transform` (a capsule, a cylinder or a placed
    primitive comes back as a one-part `compound`); a primitive is solid
    (`solid=False` is refused). Any other `trimesh.Trimesh`: its vertices and
    faces, `solid` as for `mesh`. A `trimesh.Scene` (what `trimesh.load`
    returns for many GLB and OBJ files): one mesh of all its meshes, each
    placed by the scene graph (`scene.to_mesh()`); a scene without triangles
    is a `ValueError` naming `force="mesh"`."""

def ball(radius: float) -> Body:
    """A ball of `radius` (finite, at least 0) at the body origin."""

def capsule(half_height: float, radius: float) -> Body:
    """Along the body's **y** axis: the segment from (0, -half_height, 0) to
    (0, half_height, 0) rounded by `radius`. trimesh's `Capsule(height,
    radius)` lies along z with `height` between the sphere centres: it is
    `capsule(height / 2, radius)` turned a quarter turn about x."""

def box(half_extents: ArrayLike, rounding: float = 0.0) -> Body:
    """The box [-h0, h0] x [-h1, h1] x [-h2, h2] of the **half** extents h.
    trimesh's `Box(extents)` takes full extents: it is `box(extents / 2)`."""

def cylinder(half_height: float, radius: float, rounding: float = 0.0) -> Body:
    """Along the body's **y** axis, |y| <= half_height. trimesh's
    `Cylinder(radius, height)` lies along z with its whole height: it is
    `cylinder(height / 2, radius)` turned a quarter turn about x."""

def cone(half_height: float, radius: float, rounding: float = 0.0) -> Body:
    """Along the body's **y** axis, apex at (0, half_height, 0), base at
    y = -half_height."""

def convex_hull(points: ArrayLike, rounding: float = 0.0) -> Body: ...
def half_space(normal: ArrayLike) -> Body:
    """The solid {x : normal . x <= 0}; it may translate, not turn."""

def compound(parts: Iterable[Tuple[Body, PoseLike]]) -> Body:
    """Meshes and convex shapes at poses in the compound's frame, moving as one."""

def orthonormalize(matrix: ArrayLike) -> np.ndarray:
    """The nearest rotation (polar decomposition, Newton's `R <- (R + R^-T)/2`)
    of a 3x3 matrix, of a 4x4 pose's rotation block, or of each of a stack
    `(..., 3, 3)` / `(..., 4, 4)`; same shape, float64. Refused (`InputError`)
    for a matrix not near a rotation: not finite, det <= 0, or an entry of
    R^T R - I beyond 1e-2. Points at distance d from the origin move by at most
    about 3 * d * max|R^T R - I|."""

class Pose:
    """A rigid placement. `Pose(matrix)`: a 4x4 homogeneous matrix whose 3x3
    block R is a rotation to within 1e-6 (every entry of R^T R - I at most 1e-6,
    det R > 0), else `InputError`; `Pose(matrix, orthonormalize=True)` first
    replaces R by the nearest rotation (see `orthonormalize`). `Pose()` is the
    identity. Equal (and hashing alike) when the matrices are, entry by entry:
    `Pose() == Pose(numpy.eye(4))`. Pickles."""

    def __init__(self, matrix: Optional[ArrayLike] = None, orthonormalize: bool = False) -> None: ...
    def __eq__(self, other: object) -> bool: ...
    def __hash__(self) -> int: ...
    @staticmethod
    def from_wxyz(quaternion: ArrayLike, translation: Optional[ArrayLike] = None) -> Pose: ...
    @staticmethod
    def from_xyzw(quaternion: ArrayLike, translation: Optional[ArrayLike] = None) -> Pose: ...
    @staticmethod
    def from_translation(translation: ArrayLike) -> Pose: ...
    @property
    def matrix(self) -> np.ndarray: ...
    @property
    def wxyz(self) -> np.ndarray: ...
    @property
    def translation(self) -> np.ndarray: ...

class Motion:
    """A rigid motion over [0, duration]: the start pose, a constant linear
    velocity of the body origin, a constant angular velocity about it (world
    vectors, radians per unit time). Equal (and hashing alike) when the same
    motion bit for bit: start pose, velocities, interval. Pickles."""

    def __init__(
        self, start: PoseLike, linear: ArrayLike, angular: ArrayLike, duration: float = 1.0
    ) -> None: ...
    def __eq__(self, other: object) -> bool: ...
    def __hash__(self) -> int: ...
    @staticmethod
    def between(start: PoseLike, end: PoseLike, duration: float = 1.0) -> Motion: ...
    @staticmethod
    def still(pose: PoseLike, duration: float = 1.0) -> Motion: ...
    @property
    def duration(self) -> float: ...
    @property
    def linear(self) -> np.ndarray: ...
    @property
    def angular(self) -> np.ndarray: ...
    @property
    def start(self) -> Pose:
        """The pose at t = 0, as given."""
    @property
    def end(self) -> Pose:
        """The pose at t = duration (the `end` given to `between`)."""
    def matrix_at(self, t: float) -> np.ndarray:
        """The 4x4 pose at time t."""
    def pose_at(self, t: float) -> Pose:
        """The pose at time t."""

class MotionBatch:
    """Many motions over the same [0, duration]."""

    def __init__(
        self, starts: ArrayLike, linear: ArrayLike, angular: ArrayLike, duration: float = 1.0
    ) -> None: ...
    @staticmethod
    def between(starts: ArrayLike, ends: ArrayLike, duration: float = 1.0) -> MotionBatch: ...
    def __len__(self) -> int: ...
    def __getitem__(self, i: int) -> Motion: ...

class Report:
    """One query's answer. Equal when every field is, bit for bit. Pickles."""

    def __init__(
        self,
        outcome: Outcome,
        time: Optional[float],
        point_a: Optional[ArrayLike],
        point_b: Optional[ArrayLike],
        normal: Optional[ArrayLike],
        distance: Optional[float],
        iterations: int,
    ) -> None: ...
    @property
    def outcome(self) -> Outcome: ...
    @property
    def hit(self) -> bool:
        """True unless the query certified that the bodies never touch."""
    @property
    def time(self) -> Optional[float]:
        """The contact time, or the safe time reached when undecided."""
    @property
    def point_a(self) -> Optional[np.ndarray]:
        """The closest point on A at the contact: float64, shape (3,)."""
    @property
    def point_b(self) -> Optional[np.ndarray]:
        """The closest point on B at the contact: float64, shape (3,)."""
    @property
    def normal(self) -> Optional[np.ndarray]:
        """The unit normal from A to B: float64, shape (3,)."""
    @property
    def distance(self) -> Optional[float]: ...
    @property
    def iterations(self) -> int: ...

class BatchReport:
    """A batch's answers as arrays, one entry per query. Equal when every
    query's report is. Pickles."""

    OUTCOMES: list[str]
    def __init__(
        self,
        outcome_codes: ArrayLike,
        times: ArrayLike,
        points_a: ArrayLike,
        points_b: ArrayLike,
        normals: ArrayLike,
        distances: ArrayLike,
        iterations: ArrayLike,
    ) -> None: ...
    def __len__(self) -> int: ...
    def __getitem__(self, i: int) -> Report: ...
    @property
    def outcome_codes(self) -> np.ndarray: ...
    @property
    def hits(self) -> np.ndarray: ...
    @property
    def times(self) -> np.ndarray: ...
    @property
    def points_a(self) -> np.ndarray: ...
    @property
    def points_b(self) -> np.ndarray: ...
    @property
    def normals(self) -> np.ndarray: ...
    @property
    def distances(self) -> np.ndarray: ...
    @property
    def iterations(self) -> np.ndarray: ...

def time_of_impact(
    a: Body,
    motion_a: Motion,
    b: Body,
    motion_b: Motion,
    contact_distance: float = 1e-4,
    tolerance: float = 1e-9,
    max_iterations: int = 100,
) -> Report:
    """The first time of contact (distance at most `contact_distance`), never
    later than the first time the distance falls to half of it, never missed;
    the GIL released."""

def time_of_impact_batch(
    a: Body,
    motions_a: Union[Motion, MotionBatch],
    b: Body,
    motions_b: Union[Motion, MotionBatch],
    contact_distance: float = 1e-4,
    tolerance: float = 1e-9,
    max_iterations: int = 100,
    parallel: bool = True,
    progress: Optional[Callable[[int, int], Any]] = None,
) -> BatchReport:
    """One query per motion, on every core, the GIL released. Runs in chunks of
    about 20 ms; between them, `progress(done, total)` is called (if given) and
    Ctrl-C raises `KeyboardInterrupt`."""

def past_contact(
    a: Body,
    motion_a: Motion,
    b: Body,
    motion_b: Motion,
    normal: ArrayLike,
    contact_distance: float = 1e-4,
    tolerance: float = 1e-9,
    max_iterations: int = 100,
) -> Tuple[Literal["never", "at", "undecided"], Optional[float]]:
    """For bodies within the contact distance at the start: whether `a` goes
    deeper into `b` along `normal` (from A to B) over the interval, certified
    with one cast against the plane just past the start's separating plane.
    `("never", None)`, `("at", t)` (from `t` on; `0.0` when already deeper
    than the contact distance) or `("undecided", None)` (both rotate, or a
    half-space). The GIL released."""

class Scene:
    """Many bodies over [0, duration]; every pair's first contact after a
    certified broad phase. Pickles (bodies, motions, the last `stats`); no
    `==` (compare `query()` results)."""

    def __init__(self, duration: float = 1.0) -> None: ...
    def add(self, body: Body, motion: Union[Motion, PoseLike]) -> int: ...
    def query(
        self,
        contact_distance: float = 1e-4,
        tolerance: float = 1e-9,
        max_iterations: int = 100,
        parallel: bool = True,
    ) -> list[Tuple[int, int, Report]]:
        """Every pair's first contact; on every core by default (as
        `time_of_impact_batch`), the same answers bit for bit as `parallel=False`."""
    @property
    def stats(self) -> Optional[dict[str, int]]: ...
    def __len__(self) -> int: ...

def table1_scene(size: Literal["2.8K", "11K", "34K"] = "2.8K", queries: int = 200) -> dict[str, Any]:
    """The seed's Table 1 torus knots and the Rust report's fly-by queries."""

class Chain:
    """A kinematic tree read from a URDF: its links' collision meshes (ball
    trees built once) and joints. Immutable; pickles as its URDF path (the
    file and its meshes must be readable where it is unpickled)."""

    @staticmethod
    def from_urdf(
        path: Union[str, "os.PathLike[str]"],
        base: Optional[PoseLike] = None,
        package_root: Optional[Union[str, "os.PathLike[str]"]] = None,
    ) -> Chain:
        """Revolute, continuous, prismatic and fixed joints; OBJ and STL meshes
        (boxes exact; cylinders, spheres, capsules as containing meshes).
        `FileNotFoundError`, `UrdfError`, `MeshError`."""
    @property
    def dof(self) -> int: ...
    @property
    def link_names(self) -> list[str]: ...
    @property
    def joint_names(self) -> list[str]:
        """The movable joints, in coordinate order."""
    @property
    def limits(self) -> np.ndarray:
        """`(dof, 2)` of `[lower, upper]` (`[-inf, inf]` for a continuous joint)."""
    @property
    def path(self) -> str: ...
    def link_index(self, name: str) -> int: ...
    def link_mesh(self, link: LinkLike) -> Optional[Tuple[np.ndarray, np.ndarray]]:
        """`(vertices, faces)` of the link's collision mesh in its frame, or None."""
    def forward_kinematics(self, q: ArrayLike) -> np.ndarray:
        """`(links, 4, 4)`: every link's world pose at `q`."""

class EdgeReport:
    """`ChainScene.check_edge`'s answer: free (certified), a contact (free on
    `[0, free_until]`, the pair within the contact distance plus the padding at
    `at`), or undecided (the edge budget ran out). Equal when every field is.
    Pickles."""

    def __init__(
        self,
        outcome: Literal["free", "contact", "undecided"],
        free_until: float,
        at: Optional[float],
        pair: Optional[Tuple[str, str]],
        pair_kind: Optional[Literal["obstacle", "self"]],
        pair_indices: Optional[Tuple[int, int]],
        stats: dict[str, int],
    ) -> None: ...
    def __eq__(self, other: object) -> bool: ...
    @property
    def outcome(self) -> Literal["free", "contact", "undecided"]: ...
    @property
    def free(self) -> bool: ...
    @property
    def free_until(self) -> float: ...
    @property
    def at(self) -> Optional[float]: ...
    @property
    def pair(self) -> Optional[Tuple[str, str]]: ...
    @property
    def pair_kind(self) -> Optional[Literal["obstacle", "self"]]: ...
    @property
    def pair_indices(self) -> Optional[Tuple[int, int]]: ...
    @property
    def stats(self) -> dict[str, int]: ...

class SegmentReport:
    """`ChainScene.check_segment` and `check_path`'s answer: the first contact
    (never later than the first touch), separated, or an iteration limit.
    Equal when every field is. Pickles."""

    def __init__(
        self,
        outcome: Literal["contact", "separated", "iteration_limit"],
        time: Optional[float],
        pair: Optional[Tuple[str, str]],
        pair_kind: Optional[Literal["obstacle", "self"]],
        pair_indices: Optional[Tuple[int, int]],
        distance: Optional[float],
        point_a: Optional[ArrayLike],
        point_b: Optional[ArrayLike],
        segment: Optional[int],
        stats: dict[str, int],
    ) -> None: ...
    def __eq__(self, other: object) -> bool: ...
    @property
    def outcome(self) -> Literal["contact", "separated", "iteration_limit"]: ...
    @property
    def hit(self) -> bool: ...
    @property
    def time(self) -> Optional[float]: ...
    @property
    def pair(self) -> Optional[Tuple[str, str]]: ...
    @property
    def pair_kind(self) -> Optional[Literal["obstacle", "self"]]: ...
    @property
    def pair_indices(self) -> Optional[Tuple[int, int]]: ...
    @property
    def distance(self) -> Optional[float]: ...
    @property
    def point_a(self) -> Optional[np.ndarray]: ...
    @property
    def point_b(self) -> Optional[np.ndarray]: ...
    @property
    def segment(self) -> Optional[int]: ...
    @property
    def stats(self) -> dict[str, int]: ...

class ChainScene:
    """A chain in still surroundings, for a planner's motion validator.
    Obstacles: primitives, half-spaces and compounds of them (shape obstacles,
    measured exactly), meshes, point clouds, mixed in one scene. Every query
    takes every kind: `check_edge`, `edge_is_free`, `edges_are_free`,
    `collides_at`, `check_segment`, `check_path`, `clearance` and
    `allow_collisions_at`. Every query releases the GIL; picklable
    (the chain's URDF path, then what was added, replayed)."""

    def __init__(
        self,
        chain: Chain,
        contact_distance: float = 1e-3,
        padding: float = 0.0,
        edge_budget: int = 400000,
        within_limits: bool = True,
        max_iterations: int = 10000,
    ) -> None: ...
    @property
    def chain(self) -> Chain: ...
    def add_obstacle(self, body: Body, pose: Optional[PoseLike] = None, name: Optional[str] = None) -> int:
        """A still body (capsules, cylinders and cones along their **y** axis);
        returns its obstacle index. A convex_hull is refused (give it as a mesh)."""
    def add_points(self, points: ArrayLike, radius: float, name: Optional[str] = None) -> int:
        """A point cloud: a ball of `radius` about each row of the `(n, 3)` array."""
    def __len__(self) -> int: ...
    @property
    def obstacle_names(self) -> list[str]: ...
    def allow_collision(self, a: LinkLike, b: LinkLike) -> None: ...
    def allow_collisions_at(self, q: ArrayLike, distance: float = 0.0) -> list[Tuple[str, str]]: ...
    contact_distance: float
    padding: float
    edge_budget: int
    within_limits: bool
    max_iterations: int
    @property
    def params(self) -> dict[str, Any]: ...
    def check_edge(self, q0: ArrayLike, q1: ArrayLike) -> EdgeReport: ...
    def edge_is_free(self, q0: ArrayLike, q1: ArrayLike) -> bool: ...
    def edges_are_free(
        self,
        edges: ArrayLike,
        parallel: bool = True,
        progress: Optional[Callable[[int, int], Any]] = None,
    ) -> np.ndarray:
        """`(n, 2, dof)` edges to a bool array of `n`, the same answers as one
        `edge_is_free` each; on every core, the GIL released, in chunks of about
        20 ms (Ctrl-C, `progress(done, total)`)."""
    def check_segment(self, q0: ArrayLike, q1: ArrayLike) -> SegmentReport: ...
    def check_path(self, path: ArrayLike) -> SegmentReport: ...
    def collides_at(self, q: ArrayLike) -> bool: ...
    def clearance(self, q: ArrayLike) -> Tuple[float, Optional[Tuple[str, str]]]: ...
