"""The API's rough edges, each against an independent computation: rotations cleaned by
`orthonormalize` (numpy's SVD), errors that name their argument, trimesh's primitives taken as
trimesh means them (closed-form times and trimesh's own tessellation), the scene's parallel
default (its serial answers), reports' arrays (the batch's rows), a motion's start and end
(Rodrigues in numpy)."""

import io
import pickle

import numpy as np
import pytest
import trimesh

import motion_bound as mb
from devkit import random_rotation
from truth import homogeneous, rodrigues

TET_V = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], float)
TET_F = np.array([[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]])
MIRROR = np.diag([1.0, 1.0, -1.0, 1.0])
# A quarter turn about x: takes our y axis (capsules, cylinders) to trimesh's z (exact entries;
# Rodrigues gives it to within rounding).
Y_TO_Z = np.array([[1.0, 0, 0, 0], [0, 0, -1, 0], [0, 1, 0, 0], [0, 0, 0, 1]])
assert np.allclose(Y_TO_Z[:3, :3], rodrigues([np.pi / 2, 0, 0]), atol=1e-15)


# 1. Rotations: the documented tolerance, and a way to clean one.


def polar(r):
    """The nearest rotation by numpy's SVD (the independent computation)."""
    u, _, vt = np.linalg.svd(r)
    return u @ vt


def deviation(r):
    """The largest entry of R^T R - I: what the tolerance is about."""
    r = np.asarray(r, float)
    return np.abs(r.T @ r - np.eye(3)).max()


def box_hit_time(rotation, contact_distance):
    """A ball flying along x into a still box turned by `rotation`: the report."""
    box = mb.box([0.3, 0.2, 0.1])
    still = mb.Motion.still(homogeneous(rotation, [0, 0, 0]) if not isinstance(rotation, mb.Pose)
                            else rotation)
    fly = mb.Motion.between(mb.Pose.from_translation([-2, 0.05, 0.02]),
                            mb.Pose.from_translation([2, 0.05, 0.02]))
    return mb.time_of_impact(box, still, mb.ball(0.1), fly, contact_distance=contact_distance)


def check_same_answer(exact, cleaned):
    """The query with the cleaned rotation answers as with the exact one, within the documented
    tolerance: every point of the box (reach |h|) moves by at most |h| * |Q - R|_2, which moves
    the first contact by at most that over the closing speed (4 |n_x|), plus each answer's own
    window (half the contact distance over the same speed) and the time tolerance."""
    c = 1e-6
    want = box_hit_time(exact, c)
    got = box_hit_time(mb.Pose(homogeneous(cleaned, [0, 0, 0])), c)
    assert want.outcome == got.outcome == "contact"
    speed = 4.0 * abs(want.normal[0])
    assert speed > 0.5, "the fly-by hits a face head-on enough to bound the time"
    moved = np.linalg.norm([0.3, 0.2, 0.1]) * np.linalg.norm(cleaned - exact, 2)
    assert abs(got.time - want.time) <= (moved + c) / speed + 2e-9, (got.time, want.time)


def test_a_rotation_rounded_to_five_decimals_is_refused_then_cleaned():
    exact = random_rotation(np.random.default_rng(3))
    rounded = np.round(exact, 5)
    assert deviation(rounded) > 1e-6  # beyond the tolerance, as the docs say
    with pytest.raises(mb.InputError, match=r"matrix: matrix is not a rotation.*1e-6.*orthonormalize"):
        mb.Pose(homogeneous(rounded, [0, 0, 0]))
    pose = mb.Pose(homogeneous(rounded, [0.5, 0, 0]), orthonormalize=True)
    np.testing.assert_allclose(pose.matrix[:3, :3], polar(rounded), atol=1e-14)
    np.testing.assert_array_equal(pose.matrix[:3, 3], [0.5, 0, 0])
    cleaned = mb.orthonormalize(rounded)
    np.testing.assert_allclose(cleaned, polar(rounded), atol=1e-14)
    assert deviation(cleaned) < 1e-15 and np.linalg.det(cleaned) > 0
    # The documented bound: a point at distance d moves by at most 3 d max|R^T R - I|.
    assert np.linalg.norm(cleaned - rounded, 2) <= 3 * deviation(rounded)
    check_same_answer(exact, cleaned)
    # Pickled, the cleaned pose comes back as the same pose.
    assert np.array_equal(pickle.loads(pickle.dumps(pose)).matrix, pose.matrix)


@pytest.mark.parametrize("seed", range(10))
def test_a_product_of_200_float32_rotations(seed):
    rng = np.random.default_rng(seed)
    rotations = [random_rotation(rng) for _ in range(200)]
    exact, single = np.eye(3), np.eye(3, dtype=np.float32)
    for r in rotations:
        exact, single = exact @ r, single @ r.astype(np.float32)
    m = homogeneous(single.astype(float), [0, 0, 0])
    if deviation(single) > 1e-6:
        with pytest.raises(mb.InputError, match="not a rotation"):
            mb.Pose(m)
    else:
        mb.Pose(m)  # within the documented tolerance: accepted as it is
    cleaned = mb.Pose(m, orthonormalize=True).matrix[:3, :3]
    np.testing.assert_allclose(cleaned, polar(single.astype(float)), atol=1e-14)
    assert np.linalg.norm(cleaned - single, 2) <= 3 * deviation(single)
    check_same_answer(exact, cleaned)


def test_some_float32_product_is_beyond_the_tolerance():
    """The seeds above do exercise the refusal (the products drift past 1e-6)."""
    drifts = []
    for seed in range(10):
        rng = np.random.default_rng(seed)
        single = np.eye(3, dtype=np.float32)
        for _ in range(200):
            single = single @ random_rotation(rng).astype(np.float32)
        drifts.append(deviation(single))
    assert max(drifts) > 1e-6


def test_orthonormalize_takes_poses_and_stacks_and_refuses_what_is_no_rotation():
    rng = np.random.default_rng(5)
    stack = np.stack([homogeneous(np.round(random_rotation(rng), 4), rng.normal(size=3))
                      for _ in range(6)]).reshape(2, 3, 4, 4)
    out = mb.orthonormalize(stack)
    assert out.shape == stack.shape and out.dtype == np.float64
    for i in range(2):
        for j in range(3):
            np.testing.assert_allclose(out[i, j, :3, :3], polar(stack[i, j, :3, :3]), atol=1e-14)
            np.testing.assert_array_equal(out[i, j, :3, 3], stack[i, j, :3, 3])
            np.testing.assert_array_equal(out[i, j, 3], [0, 0, 0, 1])
    # A batch of cleaned poses is accepted as it is.
    flat = out.reshape(6, 4, 4)
    assert len(mb.MotionBatch.between(flat, flat)) == 6
    bad = stack.copy()
    bad[1, 2] = MIRROR
    with pytest.raises(mb.InputError, match=r"matrix\[1, 2\].*determinant"):
        mb.orthonormalize(bad)
    with pytest.raises(mb.InputError, match="not near a rotation"):
        mb.orthonormalize(np.diag([1.0, 1.0, 1.1]))  # 21% off: not a rounded rotation
    with pytest.raises(mb.InputError, match="determinant"):
        mb.orthonormalize(np.zeros((3, 3)))  # singular
    with pytest.raises(mb.InputError, match="not finite"):
        mb.orthonormalize(np.full((3, 3), np.nan))
    with pytest.raises(ValueError, match=r"shape"):
        mb.orthonormalize(np.eye(2))


# 2. Every error names its argument (and, in an array, the index).

BALL = mb.ball(0.1)
STILL = mb.Motion.still(np.eye(4))
GROUND = mb.half_space([0, 0, 1])
STARTS = np.tile(np.eye(4), (5, 1, 1))


def with_entry(a, index, value):
    a = np.array(a, float)
    a[index] = value
    return a


def toi(**kw):
    return mb.time_of_impact(BALL, STILL, BALL, STILL, **kw)


def batch(**kw):
    return mb.time_of_impact_batch(BALL, STILL, BALL, STILL, **kw)


def turned_scene():
    scene = mb.Scene()
    scene.add(BALL, np.eye(4))
    scene.add(GROUND, mb.Motion(np.eye(4), [0, 0, 0], [0, 0, 1]))
    return scene


BAD_INPUTS = {
    "batch start pose not finite": (
        lambda: mb.MotionBatch.between(with_entry(STARTS, (3, 0, 0), np.nan), STARTS),
        r"^starts\[3\]: orientation is not finite"),
    "batch end pose mirrored": (
        lambda: mb.MotionBatch.between(STARTS, with_entry(STARTS, (1, 2, 2), -1.0)),
        r"^ends\[1\]: matrix is not a rotation"),
    "batch start last row": (
        lambda: mb.MotionBatch(with_entry(STARTS, (2, 3, 0), 1.0), np.zeros((5, 3)),
                               np.zeros((5, 3))),
        r"^starts\[2\]: a pose's last row"),
    "batch linear velocity": (
        lambda: mb.MotionBatch(STARTS, with_entry(np.zeros((5, 3)), (2, 1), np.inf),
                               np.zeros((5, 3))),
        r"^linear\[2\]"),
    "batch angular velocity": (
        lambda: mb.MotionBatch(STARTS, np.zeros((5, 3)),
                               with_entry(np.zeros((5, 3)), (4, 0), np.nan)),
        r"^angular\[4\]"),
    "batch duration": (lambda: mb.MotionBatch.between(STARTS, STARTS, duration=0.0),
                       r"^duration"),
    "batch lengths": (lambda: mb.MotionBatch(STARTS, np.zeros((4, 3)), np.zeros((5, 3))),
                      r"^linear"),
    "box half extent negative": (lambda: mb.box([1, -2, 1]), r"^half_extents\[1\] is negative"),
    "box half extent nan": (lambda: mb.box([1, 1, np.nan]), r"^half_extents\[2\] is not finite"),
    "box shape": (lambda: mb.box([1, 1]), r"^half_extents must have shape"),
    "box rounding": (lambda: mb.box([1, 1, 1], rounding=-1), r"^rounding is negative"),
    "ball radius": (lambda: mb.ball(-1.0), r"^radius is negative"),
    "ball too large": (lambda: mb.ball(1e300), r"^radius"),
    "capsule half height": (lambda: mb.capsule(-1.0, 0.1), r"^half_height is negative"),
    "capsule radius": (lambda: mb.capsule(1.0, np.nan), r"^radius is not finite"),
    "cylinder half height": (lambda: mb.cylinder(0.0, 1.0), r"^half_height must be positive"),
    "cylinder radius": (lambda: mb.cylinder(1.0, -1.0), r"^radius is negative"),
    "cone rounding": (lambda: mb.cone(1.0, 1.0, rounding=np.inf), r"^rounding is not finite"),
    "hull point": (lambda: mb.convex_hull(with_entry(TET_V, (2, 1), np.nan)),
                   r"^points: vertex 2"),
    "hull empty": (lambda: mb.convex_hull(np.zeros((0, 3))), r"^points"),
    "hull rounding": (lambda: mb.convex_hull(TET_V, rounding=-0.1), r"^rounding"),
    "half-space normal": (lambda: mb.half_space([0, 0, 0]), r"^normal"),
    "mesh vertex": (lambda: mb.mesh(with_entry(TET_V, (2, 0), np.inf), TET_F),
                    r"^vertices: .*vertex 2"),
    "mesh face index": (lambda: mb.mesh(TET_V, [[0, 1, 9]]), r"^faces: triangle 0"),
    "mesh no face": (lambda: mb.mesh(TET_V, np.zeros((0, 3), int)), r"^faces"),
    "mesh negative index": (lambda: mb.mesh(TET_V, [[0, 1, -1]]), r"^faces: triangle 0"),
    "mesh float faces": (lambda: mb.mesh(TET_V, TET_F.astype(float)), r"^faces must hold"),
    "mesh open but solid": (lambda: mb.mesh(TET_V, TET_F[:3], solid=True), r"^solid=True"),
    "compound empty": (lambda: mb.compound([]), r"^parts"),
    "compound half-space": (lambda: mb.compound([(BALL, np.eye(4)), (GROUND, np.eye(4))]),
                            r"^parts\[1\] is a half_space"),
    "compound pose": (lambda: mb.compound([(BALL, MIRROR)]), r"^parts\[0\]\[1\]"),
    "compound body": (lambda: mb.compound([("ball", np.eye(4))]), r"^parts\[0\]\[0\]"),
    "compound pair": (lambda: mb.compound([BALL]), r"^parts\[0\]"),
    "pose matrix": (lambda: mb.Pose(MIRROR), r"^matrix: matrix is not a rotation"),
    "pose last row": (lambda: mb.Pose(with_entry(np.eye(4), (3, 0), 0.5)), r"^matrix: .*last row"),
    "pose shape": (lambda: mb.Pose(np.eye(3)), r"^matrix must have shape"),
    "pose quaternion": (lambda: mb.Pose.from_wxyz([0, 0, 0, 0]), r"^quaternion"),
    "pose xyzw": (lambda: mb.Pose.from_xyzw([np.nan, 0, 0, 1]), r"^quaternion"),
    "pose translation": (lambda: mb.Pose.from_translation([np.nan, 0, 0]), r"^translation"),
    "motion start": (lambda: mb.Motion(MIRROR, [0, 0, 0], [0, 0, 0]), r"^start"),
    "motion linear": (lambda: mb.Motion(np.eye(4), [np.nan, 0, 0], [0, 0, 0]), r"^linear"),
    "motion linear large": (lambda: mb.Motion(np.eye(4), [1e300, 0, 0], [0, 0, 0]), r"^linear"),
    "motion angular": (lambda: mb.Motion(np.eye(4), [0, 0, 0], [0, np.inf, 0]), r"^angular"),
    "motion duration": (lambda: mb.Motion(np.eye(4), [0, 0, 0], [0, 0, 0], duration=0.0),
                        r"^duration"),
    "between end": (lambda: mb.Motion.between(np.eye(4), MIRROR), r"^end"),
    "between duration": (lambda: mb.Motion.between(np.eye(4), np.eye(4), duration=-1.0),
                         r"^duration"),
    "still pose": (lambda: mb.Motion.still(MIRROR), r"^pose"),
    "still duration": (lambda: mb.Motion.still(np.eye(4), duration=np.nan), r"^duration"),
    "pose_at time": (lambda: STILL.pose_at(np.nan), r"^t is not finite"),
    "contact distance": (lambda: toi(contact_distance=-1.0), r"^contact_distance"),
    "contact distance zero": (lambda: toi(contact_distance=0.0), r"^contact_distance"),
    "tolerance": (lambda: toi(tolerance=-1.0), r"^tolerance must be"),
    "tolerance nan": (lambda: toi(tolerance=np.nan), r"^tolerance must be"),
    "max iterations negative": (lambda: toi(max_iterations=-1), r"^max_iterations"),
    "max iterations zero": (lambda: toi(max_iterations=0), r"^max_iterations"),
    "max iterations beyond u32": (lambda: toi(max_iterations=2**40), r"^max_iterations"),
    "max iterations beyond i64": (lambda: toi(max_iterations=2**70), r"^max_iterations.*\(got 1180591620717411303424\)"),
    "batch max iterations beyond i64": (lambda: batch(max_iterations=-(2**200)), r"^max_iterations"),
    "scene max iterations beyond i64": (lambda: mb.Scene().query(max_iterations=2**64), r"^max_iterations"),
    "max iterations not an int": (lambda: toi(max_iterations=1.5), r"^max_iterations must be an int \(got float\)"),
    "batch max iterations": (lambda: batch(max_iterations=-1), r"^max_iterations"),
    "batch tolerance": (lambda: batch(tolerance=-1.0), r"^tolerance"),
    "batch motions": (lambda: mb.time_of_impact_batch(BALL, "motions", BALL, STILL),
                      r"^motions_a"),
    "two half-spaces": (lambda: mb.time_of_impact(GROUND, STILL, GROUND, STILL),
                        r"a=half_space, b=half_space.*supported"),
    "turning half-space": (lambda: mb.time_of_impact(
        BALL, STILL, GROUND, mb.Motion(np.eye(4), [0, 0, 0], [0, 0, 1])), r"^b: a half-space"),
    "intervals": (lambda: mb.time_of_impact(BALL, STILL, BALL, mb.Motion.still(np.eye(4), 2.0)),
                  r"motions of a and b have different intervals"),
    "scene duration": (lambda: mb.Scene(0.0), r"^duration"),
    "scene motion": (lambda: mb.Scene().add(BALL, mb.Motion.still(np.eye(4), duration=2.0)),
                     r"^motion: body 0"),
    "scene turned half-space": (lambda: turned_scene().query(), r"^body 1: a half-space"),
    "scene pose": (lambda: mb.Scene().add(BALL, MIRROR), r"^motion: matrix is not a rotation"),
    "scene not a motion": (lambda: mb.Scene().add(BALL, "still"), r"^motion must be"),
    "scene tolerance": (lambda: mb.Scene().query(tolerance=-1.0), r"^tolerance"),
    "scene max iterations": (lambda: mb.Scene().query(max_iterations=-5), r"^max_iterations"),
    "orthonormalize": (lambda: mb.orthonormalize(np.stack([np.eye(3), -np.eye(3)])),
                       r"^matrix\[1\]"),
    "from_trimesh object": (lambda: mb.from_trimesh("mesh"), r"^mesh"),
    "from_trimesh hollow primitive": (
        lambda: mb.from_trimesh(trimesh.primitives.Box(), solid=False), r"^solid=False"),
    "from_trimesh bad primitive": (
        lambda: mb.from_trimesh(trimesh.primitives.Sphere(radius=-1.0)), r"^mesh\.primitive"),
    "report outcome": (lambda: mb.Report("hit", 0.5, None, None, None, None, 1), r"^outcome"),
    "report point": (lambda: mb.Report("contact", 0.5, [0, 0], None, None, None, 1),
                     r"^point_a"),
    "batch report codes": (lambda: mb.BatchReport([7], [0.5], [[0, 0, 0]], [[0, 0, 0]],
                                                  [[1, 0, 0]], [0.0], [3]), r"^outcome_codes\[0\]"),
    "batch report iterations": (lambda: mb.BatchReport([0], [0.5], [[0, 0, 0]], [[0, 0, 0]],
                                                       [[1, 0, 0]], [0.0], [-3]),
                                r"^iterations\[0\]"),
    "table1 size": (lambda: mb.table1_scene("1K"), r"^size"),
    "table1 queries": (lambda: mb.table1_scene(queries=-1), r"^queries"),
}


@pytest.mark.parametrize("case", sorted(BAD_INPUTS))
def test_every_error_names_its_argument(case):
    call, pattern = BAD_INPUTS[case]
    # ValueError (MotionBoundError and its kinds are ValueErrors) or TypeError for a wrong type;
    # never a bare OverflowError or a message without the argument's name.
    with pytest.raises((ValueError, TypeError)) as info:
        call()
    assert not isinstance(info.value, OverflowError)
    import re

    assert re.search(pattern, str(info.value)), f"{case}: {info.value!r} does not match {pattern}"


def test_errors_keep_their_kinds():
    with pytest.raises(mb.InputError):
        mb.box([1, -2, 1])
    with pytest.raises(mb.QueryError):
        toi(max_iterations=-1)
    with pytest.raises(mb.QueryError):
        mb.time_of_impact(GROUND, STILL, GROUND, STILL)
    with pytest.raises(mb.MeshError):
        mb.mesh(TET_V, [[0, 1, 9]])


# 3. Axis conventions and half extents: trimesh's primitives as trimesh means them.


def rigid(seed):
    rng = np.random.default_rng(seed)
    return homogeneous(random_rotation(rng), rng.normal(size=3))


def fly(transform, local_from, local_to):
    """A motion between two points given in the primitive's frame (world = transform . local)."""
    a = (transform @ np.append(local_from, 1.0))[:3]
    b = (transform @ np.append(local_to, 1.0))[:3]
    return mb.Motion.between(mb.Pose.from_translation(a), mb.Pose.from_translation(b))


def hit(body, motion, c=1e-6):
    r = mb.time_of_impact(body, STILL, mb.ball(0.15), motion, contact_distance=c)
    assert r.outcome == "contact", r
    return r


def tessellation_gap(mesh, transform, inside):
    """How far trimesh's triangles fall inside the exact surface: the most negative of
    `inside` (a signed distance to the exact surface, in the primitive's own frame) over a fine
    barycentric grid of every triangle (taken back from the world by `transform`), doubled for
    what the grid misses."""
    k = 12
    w = np.array([(i, j, k - i - j) for i in range(k + 1) for j in range(k + 1 - i)], float) / k
    points = np.einsum("sk,fkd->fsd", w, mesh.triangles).reshape(-1, 3)
    back = np.linalg.inv(transform)
    local = points @ back[:3, :3].T + back[:3, 3]
    return 2.0 * max(0.0, -inside(local).min())


def segment_distance(points, half):
    """The distance of points to the segment from (0, 0, -half) to (0, 0, half)."""
    z = np.clip(points[:, 2], -half, half)
    return np.linalg.norm(points - np.stack([0 * z, 0 * z, z], axis=1), axis=1)


def test_trimesh_capsule_is_along_z_with_height_between_centres():
    t = rigid(11)
    cap = trimesh.primitives.Capsule(radius=0.2, height=1.0, transform=t)
    ours = mb.from_trimesh(cap)
    by_hand = mb.compound([(mb.capsule(0.5, 0.2), t @ Y_TO_Z)])
    c = 1e-6
    # Along trimesh's axis into the top cap: contact when the ball's centre is at
    # z = 0.5 + 0.2 + 0.15 (the closed form); speed 3.
    down = fly(t, [0, 0, 3.0], [0, 0, 0.0])
    want = (3.0 - 0.85) / 3.0
    for body in (ours, by_hand, mb.from_trimesh(cap.to_mesh())):
        r = hit(body, down, c)
        assert want - (c + 1e-9) / 3.0 - 1e-12 <= r.time <= want + 1e-12 or body.kind == "mesh"
    assert hit(ours, down, c) == hit(by_hand, down, c)
    assert hit(pickle.loads(pickle.dumps(ours)), down, c) == hit(ours, down, c)
    # From the side (trimesh's x-y plane, between its vertices): the exact capsule against
    # trimesh's own triangles, which lie inside it by at most the tessellation's gap.
    side = fly(t, [3.0 * np.cos(0.123), 3.0 * np.sin(0.123), 0.1], [0, 0, 0.1])
    exact = hit(ours, side, c)
    want = (3.0 - 0.35) / 3.0
    assert want - (c + 1e-9) / 3.0 - 1e-12 <= exact.time <= want + 1e-12
    gap = tessellation_gap(cap, t, lambda p: segment_distance(p, 0.5) - 0.2)
    tess = hit(mb.mesh(cap.vertices, cap.faces), side, c)
    assert 0 < gap < 0.01
    assert exact.time - 1e-9 <= tess.time <= exact.time + (gap + c) / 3.0, (tess.time, gap)
    # An unmoved capsule is along z too (no transform: still a turned compound).
    plain = mb.from_trimesh(trimesh.primitives.Capsule(radius=0.2, height=1.0))
    r = hit(plain, fly(np.eye(4), [0, 0, 3.0], [0, 0, 0.0]), c)
    assert abs(r.time - (3.0 - 0.85) / 3.0) <= 1e-6


def test_trimesh_cylinder_is_along_z_with_its_whole_height():
    t = rigid(12)
    cyl = trimesh.primitives.Cylinder(radius=0.25, height=0.8, transform=t)
    ours = mb.from_trimesh(cyl)
    by_hand = mb.compound([(mb.cylinder(0.4, 0.25), t @ Y_TO_Z)])
    c = 1e-6
    down = fly(t, [0.05, 0, 3.0], [0.05, 0, 0.0])
    want = (3.0 - (0.4 + 0.15)) / 3.0  # onto the flat top at z = 0.4
    for body in (ours, by_hand, mb.mesh(cyl.vertices, cyl.faces)):
        r = hit(body, down, c)
        assert want - (c + 1e-9) / 3.0 - 1e-12 <= r.time <= want + 1e-12
    assert hit(ours, down, c) == hit(by_hand, down, c)
    side = fly(t, [3.0 * np.cos(0.05), 3.0 * np.sin(0.05), 0.1], [0, 0, 0.1])
    exact = hit(ours, side, c)
    assert abs(exact.time - (3.0 - 0.4) / 3.0) <= (c + 1e-9) / 3.0
    gap = tessellation_gap(cyl, t, lambda p: np.linalg.norm(p[:, :2], axis=1) - 0.25
                           + np.where(np.abs(p[:, 2]) < 0.4 - 1e-9, 0.0, np.inf))
    tess = hit(mb.mesh(cyl.vertices, cyl.faces), side, c)
    assert 0 < gap < 0.01
    assert exact.time - 1e-9 <= tess.time <= exact.time + (gap + c) / 3.0, (tess.time, gap)


def test_trimesh_box_takes_full_extents():
    t = rigid(13)
    box = trimesh.primitives.Box(extents=[0.6, 0.4, 1.0], transform=t)
    ours = mb.from_trimesh(box)
    by_hand = mb.compound([(mb.box([0.3, 0.2, 0.5]), t)])
    c = 1e-6
    for local, half in (([3.0, 0.05, 0.1], 0.3), ([0.05, 3.0, 0.1], 0.2), ([0.05, 0.1, 3.0], 0.5)):
        motion = fly(t, local, [0.0, 0.0, 0.0])
        speed = np.linalg.norm(local)
        want = (1.0 - (half + 0.15) / max(local)) * 1.0  # the largest coordinate hits its face
        for body in (ours, by_hand, mb.mesh(box.vertices, box.faces)):
            r = hit(body, motion, c)
            assert want - (c + 1e-9) / speed - 1e-12 <= r.time <= want + 1e-12, (local, r.time)
        assert hit(ours, motion, c) == hit(by_hand, motion, c)
    # At the identity, a plain box of half the extents.
    plain = mb.from_trimesh(trimesh.primitives.Box(extents=[0.6, 0.4, 1.0]))
    assert plain.kind == "box" and repr(plain) == repr(mb.box([0.3, 0.2, 0.5]))


def test_trimesh_sphere_and_other_meshes():
    s = trimesh.primitives.Sphere(radius=0.3, center=[1.0, 2.0, 3.0])
    ours = mb.from_trimesh(s)
    r = hit(ours, fly(np.eye(4), [4.0, 2.0, 3.0], [1.0, 2.0, 3.0]))
    assert abs(r.time - (3.0 - 0.45) / 3.0) <= 1e-6
    assert mb.from_trimesh(trimesh.primitives.Sphere(radius=0.3)).kind == "ball"
    # A plain Trimesh is still its triangles.
    ico = trimesh.creation.icosphere(subdivisions=1, radius=0.3)
    assert mb.from_trimesh(ico).kind == "mesh" and mb.from_trimesh(ico).solid


# 4. The scene runs on every core by default, with the serial answers bit for bit.


def test_scene_query_defaults_to_parallel_with_the_serial_answers():
    assert "parallel=True" in mb.Scene.query.__text_signature__
    rng = np.random.default_rng(21)
    v, f = trimesh.creation.icosphere(subdivisions=2, radius=0.3).vertices, \
        trimesh.creation.icosphere(subdivisions=2, radius=0.3).faces
    scene = mb.Scene()
    for i in range(14):
        body = [mb.mesh(v, f), mb.ball(0.25), mb.box([0.2, 0.1, 0.3]), mb.capsule(0.2, 0.1)][i % 4]
        start = homogeneous(random_rotation(rng), rng.uniform(-1.5, 1.5, size=3))
        scene.add(body, mb.Motion(start, rng.normal(size=3), rng.normal(size=3) * 2))
    default = scene.query(contact_distance=1e-4)
    serial = scene.query(contact_distance=1e-4, parallel=False)
    assert len(default) == len(serial) > 3
    for (i, j, a), (k, m, b) in zip(default, serial):
        assert (i, j) == (k, m) and a == b  # Report equality is bit for bit


# 5. Reports give numpy arrays, as the batch does.


def test_report_vectors_are_float64_arrays_equal_to_the_batch_rows():
    v, f = trimesh.creation.icosphere(subdivisions=1, radius=0.4).vertices, \
        trimesh.creation.icosphere(subdivisions=1, radius=0.4).faces
    sphere = mb.mesh(v, f)
    motion = mb.Motion(mb.Pose.from_translation([-2, 0.1, 0]), [4, 0, 0], [0, 1, 2])
    one = mb.time_of_impact(sphere, motion, mb.ball(0.2), STILL)
    rows = mb.time_of_impact_batch(sphere, mb.MotionBatch(
        motion.matrix_at(0)[None], motion.linear[None], motion.angular[None]), mb.ball(0.2), STILL)
    for name, batch_name in (("point_a", "points_a"), ("point_b", "points_b"),
                             ("normal", "normals")):
        x = getattr(one, name)
        assert isinstance(x, np.ndarray) and x.dtype == np.float64 and x.shape == (3,)
        np.testing.assert_array_equal(x, getattr(rows, batch_name)[0])
    back = pickle.loads(pickle.dumps(one))
    assert back == one and np.array_equal(back.normal, one.normal)
    miss = mb.time_of_impact(sphere, STILL, mb.ball(0.2), mb.Motion.still(
        mb.Pose.from_translation([5, 0, 0])))
    assert miss.point_a is None and miss.normal is None
    assert pickle.loads(pickle.dumps(miss)) == miss


# 6. A motion gives back its start and end.


def test_motion_start_and_end():
    rng = np.random.default_rng(8)
    s = homogeneous(random_rotation(rng), rng.normal(size=3))
    e = homogeneous(random_rotation(rng), rng.normal(size=3))
    m = mb.Motion.between(s, e, duration=2.0)
    assert isinstance(m.start, mb.Pose) and isinstance(m.end, mb.Pose)
    np.testing.assert_array_equal(m.start.matrix, mb.Pose(s).matrix)
    np.testing.assert_array_equal(m.end.matrix, mb.Pose(e).matrix)
    np.testing.assert_allclose(m.start.matrix, s, atol=1e-15)
    # From velocities: the end by Rodrigues (the body turns about its origin).
    v, w = rng.normal(size=3), rng.normal(size=3)
    q = mb.Pose.from_xyzw([0.1, 0.2, 0.3, 0.9], [1, 2, 3])
    m = mb.Motion(q, v, w, duration=1.5)
    assert np.array_equal(m.start.matrix, q.matrix) and np.array_equal(m.start.wxyz, q.wxyz)
    want = homogeneous(rodrigues(w * 1.5) @ q.matrix[:3, :3], q.matrix[:3, 3] + 1.5 * v)
    np.testing.assert_allclose(m.end.matrix, want, atol=1e-12)
    np.testing.assert_allclose(m.pose_at(0.5).matrix, m.matrix_at(0.5), atol=0)
    # start and end rebuild the motion.
    again = mb.Motion.between(m.start, m.end, duration=1.5)
    np.testing.assert_allclose(again.matrix_at(0.7), m.matrix_at(0.7), atol=1e-12)


def two_placed_boxes():
    """A trimesh.Scene of two unit cubes, one node at (2, 0, 0), one at (0, 3, 0)
    (both from one geometry at the origin: only the scene graph places them)."""
    scene = trimesh.Scene()
    cube = trimesh.creation.box(extents=[1, 1, 1])
    for at in ([2.0, 0, 0], [0, 3.0, 0]):
        scene.add_geometry(cube, geom_name="cube", node_name=f"cube at {at}",
                           transform=trimesh.transformations.translation_matrix(at))
    return scene


def test_from_trimesh_takes_a_scene_placed_by_its_graph():
    """`trimesh.load` returns a Scene for many GLB and OBJ files: its meshes
    count where the scene graph puts them. A ball of radius 0.1 from the
    origin at speed 4 along x first touches the cube at x = 2 (face at 1.5)
    at t = 1.4 / 4; along y the cube at y = 3 (face at 2.5) at t = 2.4 / 4."""
    scene = two_placed_boxes()
    glb = trimesh.load(io.BytesIO(scene.export(file_type="glb")), file_type="glb")
    assert isinstance(glb, trimesh.Scene)
    still = mb.Motion.still(np.eye(4))
    for where in (scene, glb):
        boxes = mb.from_trimesh(where)
        assert boxes.kind == "mesh"
        for direction, touch in (([4.0, 0, 0], 1.4 / 4), ([0, 4.0, 0], 2.4 / 4)):
            r = mb.time_of_impact(mb.ball(0.1), mb.Motion(np.eye(4), direction, [0, 0, 0]),
                                  boxes, still, contact_distance=1e-4)
            assert r.outcome == "contact", (direction, r)
            assert touch - 1e-3 <= r.time <= touch, (direction, r.time, touch)
    # Closed and outward-wound: solid, so a ball inside the cube at x = 2 is in contact.
    inside = mb.time_of_impact(mb.ball(0.1), mb.Motion.still(mb.Pose.from_translation([2, 0, 0])),
                               mb.from_trimesh(scene), still)
    assert inside.outcome == "initial_contact"


def test_from_trimesh_refuses_a_scene_without_triangles_naming_force_mesh():
    points = trimesh.Scene(trimesh.PointCloud(np.random.default_rng(0).normal(size=(5, 3))))
    for scene in (trimesh.Scene(), points):
        with pytest.raises(ValueError, match=r'^mesh: .*force="mesh"'):
            mb.from_trimesh(scene)
