"""Robot arms from Python (issue 39, point 6): the Panda from its URDF in
MotionBenchMaker's scenes and in a scene of every obstacle kind, judged by
independent computations:

* the forward kinematics against one computed here from the URDF's XML
  (numpy, no motion_bound);
* the edge checks against python-fcl: the link meshes placed by that forward
  kinematics, the obstacles as FCL's own primitives in their own conventions
  (MotionBenchMaker's cylinders and FCL's capsules and cylinders along z,
  ours along y), sampled densely along each edge: an edge we certify free
  must show no contact at any sample, and a contact's `free_until` must not
  be past the first sample FCL finds touching;
* the shape scene against a mesh-only scene of the same boxes sampled densely
  with `collides_at` (the static check, another code path);
* the batch against the one-by-one calls; bad input; pickling.

The data files are read from the repository (`data/`, two folders above this
one): CI runs these tests from `python/tests` of the checkout against the
installed wheel.
"""

import json
import math
import pathlib
import pickle
import xml.etree.ElementTree as ET

import numpy as np
import pytest

import motion_bound as mb

ROOT = pathlib.Path(__file__).resolve().parents[2]
PANDA = ROOT / "data" / "arms" / "franka_panda" / "panda.urdf"
MBM = ROOT / "data" / "mbm"
if not PANDA.is_file():
    pytest.skip(f"the Panda's URDF is not at {PANDA} (run from the repository)",
                allow_module_level=True)

FINGERS = 0.04  # both fingers open, as examples/planner_edges.rs holds them
# Our capsules and cylinders lie along y; FCL's and MotionBenchMaker's along z.
# Y_TO_Z turns our y axis onto z (columns: the images of x, y, z).
Y_TO_Z = np.array([[1.0, 0, 0], [0, 0, -1], [0, 1, 0]])


def homogeneous(r, t):
    m = np.eye(4)
    m[:3, :3], m[:3, 3] = r, t
    return m


# --- an independent forward kinematics, from the URDF's XML --------------------------------

def rpy_matrix(rpy):
    r, p, y = rpy
    rx = np.array([[1, 0, 0], [0, math.cos(r), -math.sin(r)], [0, math.sin(r), math.cos(r)]])
    ry = np.array([[math.cos(p), 0, math.sin(p)], [0, 1, 0], [-math.sin(p), 0, math.cos(p)]])
    rz = np.array([[math.cos(y), -math.sin(y), 0], [math.sin(y), math.cos(y), 0], [0, 0, 1]])
    return rz @ ry @ rx


def axis_angle(axis, angles):
    """Rotations about the unit `axis` by each of `angles`: `(n, 3, 3)`."""
    k = np.array([[0, -axis[2], axis[1]], [axis[2], 0, -axis[0]], [-axis[1], axis[0], 0]])
    s, c = np.sin(angles)[:, None, None], np.cos(angles)[:, None, None]
    return np.eye(3) + s * k + (1 - c) * (k @ k)


class UrdfFk:
    """Link poses from the URDF's joints: origin (xyz, rpy), axis, type; the
    movable joints take the coordinates in file order."""

    def __init__(self, path):
        root = ET.parse(path).getroot()
        self.links = [l.get("name") for l in root.findall("link")]
        self.joints = []
        for j in root.findall("joint"):
            o = j.find("origin")
            xyz = [float(x) for x in (o.get("xyz", "0 0 0") if o is not None else "0 0 0").split()]
            rpy = [float(x) for x in (o.get("rpy", "0 0 0") if o is not None else "0 0 0").split()]
            a = j.find("axis")
            axis = np.array([float(x) for x in (a.get("xyz") if a is not None else "1 0 0").split()])
            self.joints.append(dict(name=j.get("name"), kind=j.get("type"),
                                    parent=j.find("parent").get("link"),
                                    child=j.find("child").get("link"),
                                    origin=homogeneous(rpy_matrix(rpy), xyz),
                                    axis=axis / (np.linalg.norm(axis) or 1.0)))
        self.movable = [j["name"] for j in self.joints if j["kind"] != "fixed"]

    def poses(self, qs):
        """`qs` `(n, dof)` to `{link: (n, 4, 4)}`."""
        qs = np.atleast_2d(qs)
        n = len(qs)
        out = {}
        children = {j["child"] for j in self.joints}
        for link in self.links:
            if link not in children:
                out[link] = np.tile(np.eye(4), (n, 1, 1))
        pending = list(self.joints)
        while pending:
            j = next(j for j in pending if j["parent"] in out)
            pending.remove(j)
            m = out[j["parent"]] @ j["origin"]
            motion = np.tile(np.eye(4), (n, 1, 1))
            if j["kind"] in ("revolute", "continuous"):
                motion[:, :3, :3] = axis_angle(j["axis"], qs[:, self.movable.index(j["name"])])
            elif j["kind"] == "prismatic":
                motion[:, :3, 3] = qs[:, self.movable.index(j["name"]), None] * j["axis"]
            out[j["child"]] = m @ motion
        return out


# --- scenes ---------------------------------------------------------------------------------

@pytest.fixture(scope="module")
def panda():
    return mb.Chain.from_urdf(PANDA)


@pytest.fixture(scope="module")
def fk():
    return UrdfFk(PANDA)


def mbm_obstacles(name):
    """A MotionBenchMaker scene (data/SOURCES.md) as `(kind, size, 4x4 pose)` in
    its own conventions (cylinders along their local z)."""
    d = json.loads((MBM / f"{name}.json").read_text())
    out = []
    for c in d["cuboids"]:
        out.append(("box", c["half_extents"], homogeneous(c["rotation"], c["center"])))
    for c in d["cylinders"]:
        out.append(("cylinder", (c["radius"], c["half_length"]),
                    homogeneous(c["rotation"], c["center"])))
    for c in d["spheres"]:
        out.append(("ball", c["radius"], homogeneous(np.eye(3), c["center"])))
    return out, d


def add_mbm(scene, obstacles):
    for kind, size, pose in obstacles:
        if kind == "box":
            scene.add_obstacle(mb.box(size), pose)
        elif kind == "cylinder":
            r, h = size
            at = pose.copy()
            at[:3, :3] = pose[:3, :3] @ Y_TO_Z
            scene.add_obstacle(mb.cylinder(h, r), at)
        else:
            scene.add_obstacle(mb.ball(size), pose)


def fcl_obstacles(obstacles):
    """The same obstacles as FCL's primitives, in FCL's (and MBM's) conventions."""
    import fcl
    objs = []
    for kind, size, pose in obstacles:
        if kind == "box":
            g = fcl.Box(*(2 * np.asarray(size)))
        elif kind == "cylinder":
            g = fcl.Cylinder(size[0], 2 * size[1])  # along z, the whole length
        elif kind == "capsule":
            g = fcl.Capsule(size[0], 2 * size[1])  # along z, between the sphere centres
        else:
            g = fcl.Sphere(size)
        objs.append(fcl.CollisionObject(g, fcl.Transform(pose[:3, :3], pose[:3, 3])))
    return objs


class FclArm:
    """The Panda's link meshes (as loaded, `Chain.link_mesh`) in FCL, placed by
    the independent forward kinematics, against FCL obstacles; a half-space
    `{x : n . x <= d}` is checked here exactly (a mesh meets it when one of its
    vertices is in it), not by FCL (whose broad phase takes no unbounded
    object)."""

    def __init__(self, chain, fk, obstacles):
        import fcl
        self.fcl, self.fk = fcl, fk
        self.links = []
        self.vertices = {}
        self.halfspaces = [size for kind, size, _ in obstacles if kind == "halfspace"]
        for name in chain.link_names:
            m = chain.link_mesh(name)
            if m is None:
                continue
            v, f = m
            self.vertices[name] = v
            model = fcl.BVHModel()
            model.beginModel(len(v), len(f))
            model.addSubModel(v, f.astype(np.int32))
            model.endModel()
            self.links.append((name, fcl.CollisionObject(model, fcl.Transform())))
        self.arm = fcl.DynamicAABBTreeCollisionManager()
        self.arm.registerObjects([o for _, o in self.links])
        self.arm.setup()
        self.world = fcl.DynamicAABBTreeCollisionManager()
        # Kept: the manager does not own its objects.
        self.objects = fcl_obstacles([o for o in obstacles if o[0] != "halfspace"])
        self.world.registerObjects(self.objects)
        self.world.setup()

    def touching(self, qs):
        """For each configuration of `qs`, whether a link meets an obstacle."""
        poses = self.fk.poses(qs)
        out = np.zeros(len(qs), bool)
        for k in range(len(qs)):
            for name, obj in self.links:
                p = poses[name][k]
                obj.setTransform(self.fcl.Transform(p[:3, :3], p[:3, 3]))
                world = self.vertices[name] @ p[:3, :3].T + p[:3, 3]
                for n, d in self.halfspaces:
                    out[k] |= bool(np.any(world @ np.asarray(n) <= d))
            self.arm.update()
            data = self.fcl.CollisionData()
            self.arm.collide(self.world, data, self.fcl.defaultCollisionCallback)
            out[k] |= data.result.is_collision
        return out


def random_edges(chain, n, seed, lengths=(0.05, 0.3)):
    """`(n, 2, 9)` edges of the seven arm joints within the limits, each of a
    joint-space length drawn from `lengths`; the fingers open."""
    rng = np.random.default_rng(seed)
    lim = chain.limits[:7]
    out = np.zeros((n, 2, chain.dof))
    k = 0
    while k < n:
        q0 = rng.uniform(lim[:, 0], lim[:, 1])
        d = rng.normal(size=7)
        q1 = q0 + d / np.linalg.norm(d) * rng.uniform(*lengths)
        if np.all((q1 >= lim[:, 0]) & (q1 <= lim[:, 1])):
            out[k, 0, :7], out[k, 1, :7] = q0, q1
            k += 1
    out[:, :, 7:] = FINGERS
    return out


def samples(q0, q1, step):
    """Configurations along `q0 -> q1` at most `step` apart in each joint, and
    their times."""
    n = max(2, int(np.ceil(np.max(np.abs(q1 - q0)) / step)) + 1)
    t = np.linspace(0.0, 1.0, n)
    return q0 + t[:, None] * (q1 - q0), t


# --- tests ----------------------------------------------------------------------------------

def test_the_chain_matches_the_urdf_read_independently(panda, fk):
    assert panda.dof == 9 and panda.joint_names == fk.movable
    assert panda.link_names == fk.links
    rng = np.random.default_rng(3)
    lim = panda.limits
    assert lim.shape == (9, 2) and np.all(lim[:, 0] <= lim[:, 1])
    qs = rng.uniform(lim[:, 0], lim[:, 1], size=(20, 9))
    want = fk.poses(qs)
    for k, q in enumerate(qs):
        got = panda.forward_kinematics(q)
        for i, name in enumerate(panda.link_names):
            np.testing.assert_allclose(got[i], want[name][k], atol=1e-12)


@pytest.mark.parametrize("name", ["cage", "bookshelf_small", "table_pick"])
def test_free_edges_in_mbm_scenes_never_touch_by_fcl_and_contacts_are_never_late(panda, fk, name):
    pytest.importorskip("fcl")
    obstacles, _ = mbm_obstacles(name)
    scene = mb.ChainScene(panda)
    add_mbm(scene, obstacles)
    truth = FclArm(panda, fk, obstacles)
    edges = random_edges(panda, 120, seed={"cage": 1, "bookshelf_small": 2, "table_pick": 3}[name])
    reports = [scene.check_edge(a, b) for a, b in edges]
    free = np.array([r.free for r in reports])
    touching_edges = 0
    for (q0, q1), r in zip(edges, reports):
        qs, t = samples(q0, q1, 2e-3)
        hit = truth.touching(qs)
        if hit.any():
            touching_edges += 1
            assert not r.free, f"{name}: FCL finds a contact on an edge certified free: {q0} {q1}"
            first = t[np.argmax(hit)]
            assert r.free_until <= first, f"{name}: late: free_until {r.free_until}, FCL {first}"
    assert free.any(), f"{name}: no free edge: the test would not test soundness"
    assert touching_edges > 0, f"{name}: FCL finds no contact: the test would not test lateness"


def every_kind_scene(panda):
    """The Panda before a wall (a half-space), a ball, a capsule and a cylinder
    (turned), a turned box, a compound of a ball and a box, a point cloud; and
    the same as FCL obstacles in FCL's conventions."""
    rng = np.random.default_rng(11)

    def turned(t):
        q = rng.normal(size=4)
        return mb.Pose.from_wxyz(q, t).matrix

    scene = mb.ChainScene(panda)
    fcl_side = []
    scene.add_obstacle(mb.half_space([-1.0, 0, 0]), mb.Pose.from_translation([0.75, 0, 0]),
                       name="wall")
    fcl_side.append(("halfspace", ([-1.0, 0, 0], -0.75), np.eye(4)))
    scene.add_obstacle(mb.ball(0.08), mb.Pose.from_translation([0.4, 0.3, 0.5]), name="ball")
    fcl_side.append(("ball", 0.08, homogeneous(np.eye(3), [0.4, 0.3, 0.5])))
    cap = turned([0.3, -0.4, 0.4])
    scene.add_obstacle(mb.capsule(0.15, 0.04), cap, name="capsule")
    fcl_side.append(("capsule", (0.04, 0.15), cap @ homogeneous(Y_TO_Z.T, [0, 0, 0])))
    cyl = turned([-0.3, 0.4, 0.6])
    scene.add_obstacle(mb.cylinder(0.2, 0.05), cyl, name="cylinder")
    fcl_side.append(("cylinder", (0.05, 0.2), cyl @ homogeneous(Y_TO_Z.T, [0, 0, 0])))
    bx = turned([-0.4, -0.3, 0.3])
    scene.add_obstacle(mb.box([0.1, 0.05, 0.15]), bx, name="box")
    fcl_side.append(("box", [0.1, 0.05, 0.15], bx))
    at = homogeneous(np.eye(3), [0.0, 0.5, 0.9])
    scene.add_obstacle(mb.compound([(mb.ball(0.05), np.eye(4)),
                                    (mb.box([0.1, 0.02, 0.02]), homogeneous(np.eye(3), [0.1, 0, 0]))]),
                       at, name="compound")
    fcl_side.append(("ball", 0.05, at))
    fcl_side.append(("box", [0.1, 0.02, 0.02], at @ homogeneous(np.eye(3), [0.1, 0, 0])))
    cloud = rng.uniform([0.2, -0.6, 0.0], [0.6, -0.2, 0.8], size=(40, 3))
    scene.add_points(cloud, 0.02, name="cloud")
    fcl_side += [("ball", 0.02, homogeneous(np.eye(3), p)) for p in cloud]
    return scene, fcl_side


def test_every_obstacle_kind_against_fcl(panda, fk):
    """Capsules and cylinders along y here, along z in FCL: a wrong turn would
    show as edges certified free that FCL sees touching."""
    pytest.importorskip("fcl")
    scene, fcl_side = every_kind_scene(panda)
    assert scene.obstacle_names == ["wall", "ball", "capsule", "cylinder", "box", "compound",
                                    "cloud"]
    truth = FclArm(panda, fk, fcl_side)
    edges = random_edges(panda, 80, seed=5)
    reports = [scene.check_edge(a, b) for a, b in edges]
    kinds = set()
    touching_edges = 0
    for (q0, q1), r in zip(edges, reports):
        qs, t = samples(q0, q1, 2e-3)
        hit = truth.touching(qs)
        if r.pair_kind == "obstacle":
            kinds.add(r.pair[1])
        if hit.any():
            touching_edges += 1
            assert not r.free, f"FCL finds a contact on an edge certified free: {q0} {q1}"
            assert r.free_until <= t[np.argmax(hit)]
    assert any(r.free for r in reports) and touching_edges > 0
    # Static checks at random configurations: where FCL sees a contact, ours must too.
    qs = random_edges(panda, 300, seed=6)[:, 0]
    hit = truth.touching(qs)
    for q, h in zip(qs, hit):
        r = scene.check_edge(q, q)
        if h:
            assert not r.free, f"FCL finds a contact at {q}, ours none"
        if r.pair_kind == "obstacle":
            kinds.add(r.pair[1])
    assert hit.any() and not hit.all()
    assert len(kinds) >= 4, f"contacts with too few kinds: {kinds}"


def box_mesh(h):
    v = np.array([[sx * h[0], sy * h[1], sz * h[2]]
                  for sx in (-1, 1) for sy in (-1, 1) for sz in (-1, 1)])
    f = np.array([[0, 1, 3], [0, 3, 2], [4, 6, 7], [4, 7, 5], [0, 4, 5], [0, 5, 1],
                  [2, 3, 7], [2, 7, 6], [0, 2, 6], [0, 6, 4], [1, 5, 7], [1, 7, 3]])
    return v, f


def test_the_shape_scene_against_dense_static_checks_of_the_mesh_scene(panda):
    """The cage's boxes as shapes (edge checks) and as meshes (`collides_at`
    every 2e-3 rad): an edge certified free never has a sample in contact, and a
    contact's `free_until` is never past the first sample in contact."""
    obstacles, _ = mbm_obstacles("cage")
    shapes, meshes = mb.ChainScene(panda), mb.ChainScene(panda)
    add_mbm(shapes, obstacles)
    for kind, size, pose in obstacles:
        v, f = box_mesh(size)
        meshes.add_obstacle(mb.mesh(v, f), pose)
    edges = random_edges(panda, 25, seed=8)
    free = shapes.edges_are_free(edges)
    assert free.any() and not free.all()
    touching_edges = 0
    for (q0, q1), ok in zip(edges, free):
        qs, t = samples(q0, q1, 2e-3)
        hit = [meshes.collides_at(q) for q in qs]
        if any(hit):
            touching_edges += 1
            assert not ok, f"a sample in contact on an edge certified free: {q0} {q1}"
            assert shapes.check_edge(q0, q1).free_until <= t[hit.index(True)]
        # The mesh scene's own edge check agrees in the certified direction.
        if meshes.edge_is_free(q0, q1):
            assert not any(hit)
    assert touching_edges > 0
    # The first-contact query on the mesh scene: never later than a sample in contact.
    for q0, q1 in edges[:8]:
        r = meshes.check_segment(q0, q1)
        qs, t = samples(q0, q1, 2e-3)
        hit = [meshes.collides_at(q) for q in qs]
        if any(hit):
            assert r.hit and r.time <= t[hit.index(True)]
            assert r.pair_kind in ("obstacle", "self") and r.point_a.shape == (3,)
        if r.outcome == "separated":
            assert not any(hit)
    # A path stops at its first segment with a contact, as the segments one by one.
    path = np.concatenate([edges[:6, 0], edges[5:6, 1]])
    p = meshes.check_path(path)
    one_by_one = [meshes.check_segment(a, b) for a, b in zip(path[:-1], path[1:])]
    first = next((i for i, r in enumerate(one_by_one) if r.outcome != "separated"), len(path) - 2)
    assert p.segment == first and p.outcome == one_by_one[first].outcome


def test_the_batch_agrees_with_one_edge_at_a_time(panda):
    obstacles, _ = mbm_obstacles("cage")
    scene = mb.ChainScene(panda)
    add_mbm(scene, obstacles)
    scene.add_points(np.random.default_rng(1).uniform(-0.1, 0.1, (100, 3)) + [0.5, 0.3, 0.3], 0.01)
    edges = random_edges(panda, 400, seed=2)
    one = np.array([scene.edge_is_free(a, b) for a, b in edges])
    checked = np.array([scene.check_edge(a, b).free for a, b in edges])
    calls = []
    many = scene.edges_are_free(edges, progress=lambda done, total: calls.append((done, total)))
    serial = scene.edges_are_free(edges.tolist(), parallel=False)
    assert many.dtype == bool and many.shape == (400,)
    np.testing.assert_array_equal(many, one)
    np.testing.assert_array_equal(serial, one)
    np.testing.assert_array_equal(checked, one)
    assert 0 < one.sum() < len(one)
    assert calls and calls[-1] == (400, 400) and all(a[0] < b[0] for a, b in zip(calls, calls[1:]))
    assert scene.edges_are_free(np.zeros((0, 2, 9))).shape == (0,)


def test_contacts_name_the_pair_and_allowed_pairs_are_skipped(panda):
    scene = mb.ChainScene(panda)
    # A box about link 4's origin at the upright pose (all zeros).
    q = np.zeros(9)
    at = panda.forward_kinematics(q)[panda.link_index("panda_link4")][:3, 3]
    i = scene.add_obstacle(mb.box([0.05, 0.05, 0.05]), mb.Pose.from_translation(at),
                           name="above")
    assert i == 0 and len(scene) == 1
    r = scene.check_edge(q, q)
    assert r.outcome == "contact" and r.pair_kind == "obstacle" and r.pair[1] == "above"
    assert r.pair_indices[1] == 0 and r.at is not None and r.free_until <= r.at
    assert isinstance(r.stats["tests"], int)
    # The obstacle alone: allowing its link pairs does not hide it; a self pair allowed does.
    fingers = mb.ChainScene(panda)
    closed = np.array([0, -0.785, 0, -2.356, 0, 1.571, 0.785, 0.0, 0.0])
    pairs = fingers.allow_collisions_at(closed, 0.005)
    assert ("panda_leftfinger", "panda_rightfinger") in pairs
    assert fingers.check_edge(closed, closed).free
    again = mb.ChainScene(panda)
    again.allow_collision("panda_leftfinger", panda.link_index("panda_rightfinger"))
    assert again.check_edge(closed, closed).outcome == fingers.check_edge(closed, closed).outcome


def test_bad_input_is_refused_naming_the_argument(panda, tmp_path):
    scene = mb.ChainScene(panda)
    scene.add_obstacle(mb.box([0.1, 0.1, 0.1]), mb.Pose.from_translation([0.6, 0, 0.3]))
    q = np.array([0, -0.785, 0, -2.356, 0, 1.571, 0.785, 0.04, 0.04])
    with pytest.raises(ValueError, match=r"q0 must have shape \(9,\)"):
        scene.check_edge(q[:7], q)
    bad = q.copy()
    bad[3] = np.nan
    with pytest.raises(mb.InputError, match=r"q1\[3\] is not finite"):
        scene.edge_is_free(q, bad)
    beyond = q.copy()
    beyond[3] = 0.5  # joint 4's upper limit is 0
    with pytest.raises(mb.InputError, match=r"q1\[3\] = 0.5 is outside joint \"panda_joint4\""):
        scene.check_edge(q, beyond)
    scene.within_limits = False
    scene.check_edge(q, beyond)
    scene.within_limits = True
    edges = np.stack([np.stack([q, q])] * 3)
    with pytest.raises(ValueError, match=r"edges must have shape \(n, 2, 9\)"):
        scene.edges_are_free(edges[:, :, :7])
    with pytest.raises(ValueError, match=r"edges must have shape"):
        scene.edges_are_free(edges[0])
    edges[2, 1, 4] = np.inf
    with pytest.raises(mb.InputError, match=r"edges\[2\]\[1\]\[4\] is not finite"):
        scene.edges_are_free(edges)
    with pytest.raises(TypeError, match="edges must hold real numbers"):
        scene.edges_are_free(np.full((1, 2, 9), "a"))
    with pytest.raises(TypeError, match="progress must be callable"):
        scene.edges_are_free(edges[:1], progress=3)
    # The static check takes shapes too: touching there is never a free edge.
    if scene.collides_at(q):
        assert scene.check_edge(q, q).outcome != "free"
    # Every query takes every obstacle kind (issue 63).
    assert scene.check_segment(q, q).outcome in ("contact", "separated", "iteration_limit")
    assert isinstance(scene.allow_collisions_at(q), list)
    with pytest.raises(KeyError, match="no link named"):
        scene.allow_collision("panda_link99", 0)
    with pytest.raises(IndexError, match="b index out of range"):
        scene.allow_collision(0, 99)
    with pytest.raises(TypeError, match="a must be a link's name"):
        scene.allow_collision(1.5, 0)
    with pytest.raises(ValueError, match="convex_hull"):
        scene.add_obstacle(mb.convex_hull(np.vstack([np.zeros(3), np.eye(3)])))
    with pytest.raises(TypeError, match="body must be a Body"):
        scene.add_obstacle("box")
    with pytest.raises(mb.InputError, match="pose"):
        scene.add_obstacle(mb.ball(0.1), np.diag([2.0, 1, 1, 1]))
    with pytest.raises(ValueError, match=r"points must have shape \(n, 3\)"):
        scene.add_points(np.zeros((4, 2)), 0.01)
    with pytest.raises(mb.InputError, match="radius is negative"):
        scene.add_points(np.zeros((4, 3)), -0.01)
    with pytest.raises(mb.InputError, match="points"):
        scene.add_points(np.full((4, 3), np.nan), 0.01)
    assert len(scene) == 1  # nothing refused was added
    with pytest.raises(mb.QueryError, match="contact_distance must be positive"):
        scene.contact_distance = 0.0
    with pytest.raises(mb.QueryError, match="padding"):
        mb.ChainScene(panda, padding=-1.0)
    with pytest.raises(mb.QueryError, match="edge_budget"):
        scene.edge_budget = 0
    with pytest.raises(ValueError, match=r"path must have shape \(n, 9\)"):
        mb.ChainScene(panda).check_path(q[None, :])
    with pytest.raises(FileNotFoundError, match="no such file"):
        mb.Chain.from_urdf(tmp_path / "missing.urdf")
    broken = tmp_path / "broken.urdf"
    broken.write_text("<robot name='x'><link name='a'/><joint name='j' type='planar'>"
                      "<parent link='a'/><child link='b'/></joint><link name='b'/></robot>")
    with pytest.raises(mb.UrdfError):
        mb.Chain.from_urdf(broken)
    assert issubclass(mb.UrdfError, mb.MotionBoundError)


def test_parameters(panda):
    scene = mb.ChainScene(panda, contact_distance=2e-3, padding=0.01, edge_budget=1000)
    assert scene.params == {"contact_distance": 2e-3, "padding": 0.01, "edge_budget": 1000,
                            "within_limits": True, "max_iterations": 10000}
    scene.edge_budget = 10
    obstacles, _ = mbm_obstacles("cage")
    add_mbm(scene, obstacles)
    edges = random_edges(panda, 20, seed=4)
    outcomes = {scene.check_edge(a, b).outcome for a, b in edges}
    assert "undecided" in outcomes and "free" not in outcomes
    # Padding: an edge free with padding is free without it.
    scene.edge_budget = 400_000
    padded = scene.edges_are_free(edges)
    scene.padding = 0.0
    assert np.all(scene.edges_are_free(edges)[padded])


def test_chain_and_scene_pickle_and_answer_the_same(panda):
    chain2 = pickle.loads(pickle.dumps(panda))
    assert chain2.link_names == panda.link_names and chain2.path == panda.path
    q = np.linspace(-0.5, 0.5, 9)
    np.testing.assert_array_equal(chain2.forward_kinematics(q), panda.forward_kinematics(q))
    based = mb.Chain.from_urdf(str(PANDA), base=mb.Pose.from_translation([0.1, 0.2, 0.3]))
    np.testing.assert_array_equal(pickle.loads(pickle.dumps(based)).forward_kinematics(q),
                                  based.forward_kinematics(q))
    scene, _ = every_kind_scene(panda)
    v, f = box_mesh([0.05, 0.05, 0.05])
    scene.add_obstacle(mb.mesh(v, f), mb.Pose.from_translation([-0.5, 0, 0.2]), name="mesh")
    scene.allow_collision("panda_hand", "panda_link5")
    scene.padding = 0.002
    back = pickle.loads(pickle.dumps(scene))
    assert back.obstacle_names == scene.obstacle_names and back.params == scene.params
    assert repr(back) == repr(scene)
    edges = random_edges(panda, 60, seed=9)
    for a, b in edges:
        x, y = scene.check_edge(a, b), back.check_edge(a, b)
        assert (x.outcome, x.free_until, x.at, x.pair) == (y.outcome, y.free_until, y.at, y.pair)


def test_the_readme_planner_loop_runs(monkeypatch):
    import re
    here = pathlib.Path(__file__).resolve().parent.parent
    text = (here / "README.md").read_text()
    blocks = [b for b in re.findall(r"```python\n(.*?)```", text, re.S) if "ChainScene" in b]
    assert len(blocks) == 1, "the README has one python block with a ChainScene"
    monkeypatch.chdir(here)  # the block reads the URDF from python/
    scope = {}
    exec(compile(blocks[0], "README.md", "exec"), scope)
    tree, scene = scope["tree"], scope["scene"]
    assert len(tree) > 1
    # Every node the loop added is the end of an edge certified free from some node.
    assert all(scene.check_edge(q, q).free for q in tree[:50])
