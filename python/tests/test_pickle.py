"""Bodies, motions, motion batches and reports pickle and give the same answers
back (what a Dask or Ray map over a cluster relies on)."""

import pickle

import numpy as np

import motion_bound as mb
from test_truth import icosphere
from devkit import random_rotation
from truth import homogeneous as pose


def roundtrip(x):
    return pickle.loads(pickle.dumps(x))


def test_every_kind_of_body_pickles_and_answers_the_same():
    v, f = icosphere(0.4, 1)
    sphere = mb.mesh(v, f)
    bodies = [sphere, mb.ball(0.3), mb.capsule(0.2, 0.1), mb.box([0.2, 0.3, 0.1], 0.01),
              mb.cylinder(0.2, 0.1, 0.02), mb.cone(0.3, 0.2), mb.convex_hull(v * 0.5, 0.01),
              mb.compound([(sphere, mb.Pose.from_translation([0.3, 0, 0])),
                           (mb.box([0.1, 0.1, 0.1]), pose(random_rotation(np.random.default_rng(0)), [0, 0.2, 0]))])]
    start = mb.Pose.from_xyzw([0.1, 0.2, 0.3, 0.9], [-2.0, 0.1, 0.0])
    ma = mb.Motion(start, [4.0, 0, 0], [0, 1.0, 2.0])
    mb_ = mb.Motion.between(np.eye(4), pose(random_rotation(np.random.default_rng(1)), [0, 0, 0]))
    for a in bodies:
        a2 = roundtrip(a)
        assert a2.kind == a.kind and repr(a2) == repr(a)
        one = mb.time_of_impact(a, ma, sphere, mb_, contact_distance=1e-3)
        two = mb.time_of_impact(a2, roundtrip(ma), roundtrip(sphere), roundtrip(mb_),
                                contact_distance=1e-3)
        assert one.hit and one == two
    ground = mb.half_space([0, 0, 1])
    assert roundtrip(ground).kind == "half_space"


def test_a_motion_batch_and_its_report_pickle():
    v, f = icosphere(0.4, 1)
    sphere = mb.mesh(v, f)
    rng = np.random.default_rng(2)
    n = 50
    starts = np.stack([pose(random_rotation(rng), rng.normal(size=3) * 1.5) for _ in range(n)])
    ends = np.stack([pose(random_rotation(rng), rng.normal(size=3) * 0.3) for _ in range(n)])
    for batch in (mb.MotionBatch.between(starts, ends),
                  mb.MotionBatch(starts, rng.normal(size=(n, 3)), rng.normal(size=(n, 3)))):
        still = mb.Motion.still(np.eye(4))
        rep = mb.time_of_impact_batch(sphere, batch, sphere, still, contact_distance=1e-3)
        again = mb.time_of_impact_batch(roundtrip(sphere), roundtrip(batch), sphere, still,
                                        contact_distance=1e-3)
        back = roundtrip(rep)
        assert len(back) == len(rep) == n
        assert rep.hits.any()
        for i in range(n):
            assert back[i] == rep[i] == again[i]
        for name in ("outcome_codes", "times", "points_a", "points_b", "normals", "distances",
                     "iterations"):
            np.testing.assert_array_equal(getattr(back, name), getattr(rep, name))
