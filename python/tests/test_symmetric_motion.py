"""Motion that maps a shape onto itself is not motion (proofs/12-shapes.md,
Lemma 12.5): a spinning ball sliding or rolling, a rolling wheel, a capsule and
a cone spinning about their axes, 1.01 to 10 contact distances above a floor,
rounded or not, are separated within three iterations over an engine's step;
the same motions turned towards the floor still touch."""

import numpy as np
import pytest

import motion_bound as mb

CONTACT = 1e-4
DT = 1.0 / 60.0


def pose(rotation=None, translation=(0.0, 0.0, 0.0)):
    m = np.eye(4)
    if rotation is not None:
        m[:3, :3] = rotation
    m[:3, 3] = translation
    return m


# The shape's y axis turned onto z (a wheel's axle) and onto x (a lying capsule).
Y_TO_Z = np.array([[1.0, 0.0, 0.0], [0.0, 0.0, -1.0], [0.0, 1.0, 0.0]])
Y_TO_X = np.array([[0.0, 1.0, 0.0], [-1.0, 0.0, 0.0], [0.0, 0.0, 1.0]])


def cases(gap, toward, rounding):
    r = 0.05 + rounding
    yield "ball sliding and spinning", mb.ball(r), pose(None, (0.3, gap + r, -0.2)), (
        3.0, -toward, 1.0), (14.0, 9.0, -17.0)
    yield "ball rolling", mb.ball(r), pose(None, (0.3, gap + r, -0.2)), (
        2.0, -toward, 0.0), (0.0, 0.0, -2.0 / r)
    yield "wheel rolling", mb.cylinder(0.02, 0.05, rounding), pose(Y_TO_Z, (0.0, gap + r, 0.0)), (
        3.0, -toward, 0.0), (0.0, 0.0, -3.0 / r)
    yield "capsule spinning", mb.capsule(0.2, r), pose(Y_TO_X, (0.0, gap + r, 0.0)), (
        0.0, -toward, 1.5), (40.0, 0.0, 0.0)
    yield "cone spinning", mb.cone(0.1, 0.06, rounding), pose(None, (0.1, gap + rounding + 0.1, 0.1)), (
        1.0, -toward, -1.0), (0.0, 30.0, 0.0)


def floors():
    yield "half-space", mb.half_space([0.0, 1.0, 0.0]), pose()
    yield "box", mb.box([2.0, 0.05, 2.0]), pose(None, (0.0, -0.05, 0.0))


@pytest.mark.parametrize("rounding", [0.0, 0.01])
@pytest.mark.parametrize("gap", [1.01 * CONTACT, 2.0 * CONTACT, 10.0 * CONTACT])
def test_symmetric_spins_are_separated_within_three_iterations(gap, rounding):
    for name, body, start, linear, angular in cases(gap, 0.0, rounding):
        motion = mb.Motion(start, linear, angular, DT)
        for floor_name, floor, at in floors():
            r = mb.time_of_impact(body, motion, floor, mb.Motion.still(at, DT), contact_distance=CONTACT)
            assert r.outcome == "separated" and r.iterations <= 3, (name, floor_name, r.outcome, r.iterations)


def test_the_same_motions_towards_the_floor_still_touch():
    gap = 10.0 * CONTACT
    for name, body, start, linear, angular in cases(gap, 1.0, 0.0):
        motion = mb.Motion(start, linear, angular, DT)
        for floor_name, floor, at in floors():
            r = mb.time_of_impact(body, motion, floor, mb.Motion.still(at, DT), contact_distance=CONTACT)
            assert r.hit, (name, floor_name, r.outcome)
            assert gap - CONTACT - 1e-9 <= r.time <= gap - CONTACT / 2 + 1e-12, (name, floor_name, r.time)


def test_through_a_scene_symmetric_spins_are_separated():
    scene = mb.Scene(DT)
    scene.add(mb.box([2.0, 0.05, 2.0]), pose(None, (0.0, -0.05, 0.0)))
    for k, (name, body, start, linear, angular) in enumerate(cases(1.01 * CONTACT, 0.0, 0.01)):
        start = start.copy()
        start[2, 3] += 0.5 * k - 1.0
        scene.add(body, mb.Motion(start, linear, angular, DT))
    reports = scene.query(contact_distance=CONTACT)
    # Every body against the floor (body 0), and any neighbours the broad phase kept.
    assert sorted(b for a, b, _ in reports if a == 0) == [1, 2, 3, 4, 5]
    for a, b, report in reports:
        assert report.outcome == "separated" and report.iterations <= 3, (a, b, report.outcome, report.iterations)
