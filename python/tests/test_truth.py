"""motion_bound against ground truth it does not compute: python-fcl's exact
mesh distances along poses from our own formulas (truth.py), and the closed form
of two translating balls. 0 missed and 0 late, every contact at a time the
bodies really are within the contact distance."""

import numpy as np
import pytest

import motion_bound as mb
from devkit import random_rotation, unit
from truth import FclBody, Trajectory, distance, first_time_within
from truth import homogeneous as pose

RESOLUTION = 1e-6


def box_mesh(half):
    """A closed box as 8 vertices and 12 triangles."""
    hx, hy, hz = half
    v = np.array([[x, y, z] for x in (-hx, hx) for y in (-hy, hy) for z in (-hz, hz)], float)
    f = np.array([[0, 1, 3], [0, 3, 2], [4, 6, 7], [4, 7, 5], [0, 4, 5], [0, 5, 1],
                  [2, 3, 7], [2, 7, 6], [0, 2, 6], [0, 6, 4], [1, 5, 7], [1, 7, 3]])
    return v, f


def icosphere(radius, subdivisions=1):
    t = (1 + 5 ** 0.5) / 2
    v = [[-1, t, 0], [1, t, 0], [-1, -t, 0], [1, -t, 0], [0, -1, t], [0, 1, t], [0, -1, -t],
         [0, 1, -t], [t, 0, -1], [t, 0, 1], [-t, 0, -1], [-t, 0, 1]]
    f = [[0, 11, 5], [0, 5, 1], [0, 1, 7], [0, 7, 10], [0, 10, 11], [1, 5, 9], [5, 11, 4],
         [11, 10, 2], [10, 7, 6], [7, 1, 8], [3, 9, 4], [3, 4, 2], [3, 2, 6], [3, 6, 8],
         [3, 8, 9], [4, 9, 5], [2, 4, 11], [6, 2, 10], [8, 6, 7], [9, 8, 1]]
    v = [list(np.array(p) / np.linalg.norm(p)) for p in v]
    for _ in range(subdivisions):
        mid = {}

        def m(a, b):
            key = (min(a, b), max(a, b))
            if key not in mid:
                p = (np.array(v[a]) + np.array(v[b])) / 2
                v.append(list(p / np.linalg.norm(p)))
                mid[key] = len(v) - 1
            return mid[key]

        f = [g for a, b, c in f for g in
             ([a, m(a, b), m(c, a)], [b, m(b, c), m(a, b)], [c, m(c, a), m(b, c)],
              [m(a, b), m(b, c), m(c, a)])]
    return np.array(v) * radius, np.array(f)


def fly_by(rng, reach, spin):
    """A flies past B (both spinning), most fly-bys touching, some passing close."""
    start = unit(rng) * reach * rng.uniform(1.1, 1.6)
    aim = unit(rng) * reach * 0.8 * rng.uniform()
    wa = rng.normal(size=3) * spin / 2
    wb = rng.normal(size=3) * spin / 8
    return (pose(random_rotation(rng), start), aim - start, wa,
            pose(random_rotation(rng), np.zeros(3)), np.zeros(3), wb)


def check(body_a, fcl_a, body_b, fcl_b, queries, seed, cd, spin=2.0, between=False):
    rng = np.random.default_rng(seed)
    reach = fcl_a.reach + fcl_b.reach
    contacts = 0
    for _ in range(queries):
        sa, va, wa, sb, vb, wb = fly_by(rng, reach, spin)
        if between:
            # The same motion given by its end pose: the end from our own formula.
            ta = Trajectory(sa, va, wa)
            ea = pose(*ta.pose(1.0))
            ma, ta = mb.Motion.between(sa, ea), Trajectory.between(sa, ea)
        else:
            ma, ta = mb.Motion(sa, va, wa), Trajectory(sa, va, wa)
        mb_, tb = mb.Motion(sb, vb, wb), Trajectory(sb, vb, wb)
        truth = first_time_within(fcl_a, ta, fcl_b, tb, cd / 2, resolution=RESOLUTION)
        r = mb.time_of_impact(body_a, ma, body_b, mb_, contact_distance=cd)
        if truth is not None:
            contacts += 1
            assert r.hit, f"missed: truth {truth}, ours {r}"
            assert r.time <= truth + RESOLUTION, f"late: truth {truth}, ours {r.time}"
        if r.outcome in ("contact", "initial_contact"):
            # A contact is real: the bodies are within the contact distance then
            # (plus the witness search's and fcl's rounding).
            d = distance(fcl_a, ta, fcl_b, tb, r.time)
            assert d <= cd + 1e-9, f"contact at {r.time} with distance {d}"
            assert abs(np.linalg.norm(np.subtract(r.point_b, r.point_a)) - r.distance) < 1e-9
        else:
            assert r.outcome == "separated", r
    return contacts


def test_icospheres_against_fcl_truth():
    v, f = icosphere(0.5, 2)
    body, ref = mb.mesh(v, f), FclBody(v, f)
    contacts = check(body, ref, body, ref, queries=40, seed=1, cd=1e-3)
    assert contacts >= 20  # the fly-bys do touch: the test tests contacts


def test_boxes_and_spheres_against_fcl_truth_with_end_poses():
    bv, bf = box_mesh([0.6, 0.2, 0.05])
    sv, sf = icosphere(0.3, 1)
    contacts = check(mb.mesh(bv, bf), FclBody(bv, bf), mb.mesh(sv, sf), FclBody(sv, sf),
                     queries=40, seed=2, cd=1e-3, spin=6.0, between=True)
    assert contacts >= 15


def test_translating_balls_match_the_closed_form():
    """|p + t u| = r: the first root of a quadratic."""
    rng = np.random.default_rng(3)
    cd = 1e-4
    for _ in range(200):
        ra, rb = rng.uniform(0.05, 0.5, size=2)
        p = rng.normal(size=3) * 2
        aim = rng.normal(size=3) * 0.4
        u = aim - p  # A's velocity, B still at the origin
        r = ra + rb
        a2, b1, c0 = u @ u, 2 * p @ u, p @ p - r * r
        disc = b1 * b1 - 4 * a2 * c0
        t_touch = (-b1 - np.sqrt(disc)) / (2 * a2) if disc >= 0 else None
        rep = mb.time_of_impact(mb.ball(ra), mb.Motion(mb.Pose.from_translation(p), u, [0, 0, 0]),
                                mb.ball(rb), mb.Motion.still(np.eye(4)), contact_distance=cd)
        if c0 <= 0:
            assert rep.outcome == "initial_contact"
        elif t_touch is not None and 0 <= t_touch <= 1:
            assert rep.outcome == "contact"
            assert rep.time <= t_touch + 1e-12
            # Not early by more than the contact distance allows.
            assert np.linalg.norm(p + rep.time * u) <= r + cd + 1e-12
        else:
            # Separated unless it passes within the contact distance.
            closest = min(np.linalg.norm(p + t * u) for t in np.linspace(0, 1, 10001))
            if closest > r + cd:
                assert rep.outcome == "separated", (rep, closest - r)


def test_the_batch_matches_one_query_at_a_time():
    v, f = icosphere(0.5, 1)
    body = mb.mesh(v, f)
    rng = np.random.default_rng(4)
    n = 64
    starts, ends = np.zeros((n, 4, 4)), np.zeros((n, 4, 4))
    for i in range(n):
        sa, va, wa, *_ = fly_by(rng, 1.0, 2.0)
        starts[i] = sa
        ends[i] = pose(*Trajectory(sa, va, wa).pose(1.0))
    batch = mb.MotionBatch.between(starts, ends)
    still = mb.Motion.still(np.eye(4))
    for parallel in (True, False):
        rep = mb.time_of_impact_batch(body, batch, body, still, contact_distance=1e-3,
                                      parallel=parallel)
        assert len(rep) == n
        for i in range(n):
            one = mb.time_of_impact(body, batch[i], body, still, contact_distance=1e-3)
            assert rep[i] == one
        assert rep.hits.sum() > 0 and (~rep.hits).sum() >= 0
        assert np.array_equal(np.isnan(rep.times), ~rep.hits)


def test_mixed_shapes_in_a_scene():
    """A scene's pairs agree with the pair queries, and the broad phase culls
    the pair that cannot meet."""
    ground = mb.half_space([0, 0, 1])
    box = mb.box([0.5, 0.5, 0.5])
    capsule = mb.capsule(0.3, 0.1)
    drop = np.eye(4)
    drop[:3, 3] = [0, 0, 2]
    land = np.eye(4)
    land[:3, 3] = [0, 0, -1]
    far = np.eye(4)
    far[:3, 3] = [50, 0, 0]
    scene = mb.Scene()
    scene.add(ground, np.eye(4))
    scene.add(box, mb.Motion.between(drop, land))
    scene.add(capsule, far)
    pairs = scene.query(contact_distance=1e-4)
    assert [(i, j) for i, j, _ in pairs] == [(0, 1)]
    alone = mb.time_of_impact(ground, mb.Motion.still(np.eye(4)), box,
                              mb.Motion.between(drop, land), contact_distance=1e-4)
    assert pairs[0][2] == alone
    # The box's bottom (z = -0.5 in its frame) reaches the plane when its centre is at 0.5.
    assert alone.outcome == "contact" and 0.5 - 1e-4 <= alone.time <= 0.5
    assert scene.stats["pairs_culled"] + scene.stats["pairs_static"] >= 1
