"""Every public class pickles and gives the same answers back (what a Dask or
Ray map over a cluster relies on); poses, motions and reports compare by
value."""

import pathlib
import pickle

import numpy as np
import pytest

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


def test_poses_and_motions_compare_by_value():
    """Equal when the same placement or motion, whatever made them; a pickled
    copy is equal and hashes alike; a different one is not equal."""
    assert mb.Pose() == mb.Pose() == mb.Pose(np.eye(4)) == mb.Pose.from_translation([0, 0, 0])
    assert hash(mb.Pose()) == hash(mb.Pose(np.eye(4)))
    p = mb.Pose.from_xyzw([0.1, 0.2, 0.3, 0.9], [-2.0, 0.1, 0.0])
    assert p == roundtrip(p) and hash(p) == hash(roundtrip(p)) and {p: 1}[roundtrip(p)] == 1
    assert p != mb.Pose() and mb.Pose.from_translation([1e-12, 0, 0]) != mb.Pose()
    assert mb.Pose() != "identity" and mb.Pose() != np.eye(4).tolist()

    m = mb.Motion(p, [4.0, 0, 0], [0, 1.0, 2.0])
    assert m == mb.Motion(p, [4.0, 0, 0], [0, 1.0, 2.0]) == roundtrip(m)
    assert hash(m) == hash(roundtrip(m))
    assert m != mb.Motion(p, [4.0, 0, 0], [0, 1.0, 2.5])
    assert m != mb.Motion(p, [4.0, 0, 0], [0, 1.0, 2.0], duration=2.0)
    assert m != mb.Motion(mb.Pose(), [4.0, 0, 0], [0, 1.0, 2.0])
    b = mb.Motion.between(np.eye(4), pose(random_rotation(np.random.default_rng(1)), [1, 0, 0]))
    assert b == roundtrip(b) and b != m
    assert mb.Motion.still(np.eye(4)) == mb.Motion(np.eye(4), [0, 0, 0], [0, 0, 0])


def test_a_batch_report_compares_by_value():
    v, f = icosphere(0.4, 1)
    sphere = mb.mesh(v, f)
    rng = np.random.default_rng(3)
    starts = np.stack([pose(random_rotation(rng), rng.normal(size=3)) for _ in range(20)])
    batch = mb.MotionBatch(starts, rng.normal(size=(20, 3)) * 3, rng.normal(size=(20, 3)))
    still = mb.Motion.still(np.eye(4))
    rep = mb.time_of_impact_batch(sphere, batch, sphere, still)
    assert rep.hits.any() and not rep.hits.all()
    assert rep == roundtrip(rep)
    assert rep == mb.time_of_impact_batch(sphere, roundtrip(batch), sphere, still)
    # One query less, or another query's answers: not equal.
    fewer = mb.MotionBatch(starts[:19], rng.normal(size=(19, 3)), rng.normal(size=(19, 3)))
    assert rep != mb.time_of_impact_batch(sphere, fewer, sphere, still)
    moved = mb.Motion.still(mb.Pose.from_translation([0.05, 0, 0]))
    assert rep != mb.time_of_impact_batch(sphere, batch, sphere, moved)


def test_a_scene_pickles_with_its_bodies_motions_and_stats():
    v, f = icosphere(0.3, 1)
    sphere = mb.mesh(v, f)
    rng = np.random.default_rng(4)
    scene = mb.Scene()
    for i in range(6):
        body = sphere if i % 2 else mb.box([0.2, 0.1, 0.15])
        start = pose(random_rotation(rng), rng.normal(size=3) * 0.5)
        scene.add(body, mb.Motion(start, rng.normal(size=3) * 2, rng.normal(size=3)))
    scene.add(mb.ball(0.2), mb.Pose.from_translation([0, 0, 0]))
    assert roundtrip(scene).stats is None
    pairs = scene.query(contact_distance=1e-3)
    assert pairs and any(r.hit for _, _, r in pairs)
    back = roundtrip(scene)
    assert len(back) == len(scene) and back.stats == scene.stats
    assert back.query(contact_distance=1e-3) == pairs
    # The copy is a scene of its own: adding to it leaves the original as it was.
    back.add(mb.ball(0.1), np.eye(4))
    assert len(back) == len(scene) + 1


def test_every_public_class_pickles_and_compares_where_a_user_would():
    """Each public class of the module pickles; those a user compares (poses,
    motions, reports) round trip equal; the others are checked by what they
    answer. A new public class must be added here."""
    v, f = icosphere(0.4, 1)
    sphere = mb.mesh(v, f)
    motion = mb.Motion(np.eye(4), [1.0, 0, 0], [0, 0, 1.0])
    starts = np.stack([np.eye(4)] * 3)
    made = {
        "Body": lambda: sphere,
        "Pose": lambda: mb.Pose.from_translation([1, 2, 3]),
        "Motion": lambda: motion,
        "MotionBatch": lambda: mb.MotionBatch(starts, np.ones((3, 3)), np.zeros((3, 3))),
        "Report": lambda: mb.time_of_impact(sphere, motion, sphere, motion),
        "BatchReport": lambda: mb.time_of_impact_batch(
            sphere, mb.MotionBatch(starts, np.ones((3, 3)), np.zeros((3, 3))), sphere, motion),
        "Scene": mb.Scene,
        # The chain's classes are pickled in test_chain.py and in
        # test_chain_reports_pickle_and_compare_by_value below (they need the Panda's URDF).
        "Chain": None,
        "ChainScene": None,
        "EdgeReport": None,
        "SegmentReport": None,
    }
    errors = {n for n in dir(mb) if isinstance(getattr(mb, n), type)
              and issubclass(getattr(mb, n), Exception)}
    classes = {n for n in dir(mb) if isinstance(getattr(mb, n), type)} - errors
    assert classes == set(made), sorted(classes ^ set(made))
    for name, make in made.items():
        if make is None:
            continue
        x = make()
        back = roundtrip(x)
        assert type(back) is type(x) and repr(back) == repr(x), name
        if name in ("Pose", "Motion", "Report", "BatchReport"):
            assert back == x, name
    batch = made["MotionBatch"]()
    assert all(roundtrip(batch)[i] == batch[i] for i in range(len(batch)))
    for name in errors:
        e = getattr(mb, name)(f"{name}: a message")
        back = roundtrip(e)
        assert type(back) is type(e) and back.args == e.args, name


PANDA = pathlib.Path(__file__).resolve().parents[2] / "data" / "arms" / "franka_panda" / "panda.urdf"


@pytest.mark.skipif(not PANDA.is_file(), reason="the Panda's URDF is in the repository's data/")
def test_chain_reports_pickle_and_compare_by_value():
    chain = mb.Chain.from_urdf(PANDA)
    scene = mb.ChainScene(chain)
    v, f = icosphere(0.2, 1)
    scene.add_obstacle(mb.mesh(v, f), mb.Pose.from_translation([0.45, 0, 0.5]), name="ball")
    rng = np.random.default_rng(5)
    limits = chain.limits
    reports = []
    for _ in range(30):
        q0, q1 = (rng.uniform(limits[:, 0], limits[:, 1]) for _ in range(2))
        reports += [scene.check_edge(q0, q1), scene.check_segment(q0, q1)]
    reports.append(scene.check_path(np.stack([rng.uniform(limits[:, 0], limits[:, 1])
                                              for _ in range(4)])))
    outcomes = {r.outcome for r in reports}
    assert "contact" in outcomes and ({"free", "separated"} & outcomes), outcomes
    for r in reports:
        back = roundtrip(r)
        assert back == r and repr(back) == repr(r) and back.stats == r.stats
        for field in ("outcome", "pair", "pair_kind", "pair_indices"):
            assert getattr(back, field) == getattr(r, field)
    # Different answers are not equal.
    contact = next(r for r in reports if r.outcome == "contact")
    other = next(r for r in reports if type(r) is type(contact) and r.outcome != "contact")
    assert contact != other
    # Rebuilding from fields checks them: a pair without its kind and indices is refused.
    with pytest.raises(ValueError, match="pair, pair_kind, pair_indices"):
        mb.EdgeReport("contact", 0.5, 0.6, ("a", "b"), None, None,
                      {"tests": 1, "leaf_tests": 0, "intervals": 1})
    with pytest.raises(ValueError, match="^outcome: unknown"):
        mb.EdgeReport("hit", 0.5, None, None, None, None,
                      {"tests": 1, "leaf_tests": 0, "intervals": 1})
