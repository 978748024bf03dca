"""Bad input gets a typed exception carrying the Rust crate's message: never a
crash, never a silent conversion that changes the numbers."""

import numpy as np
import pytest

import motion_bound as mb

TET_V = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], float)
TET_F = np.array([[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]])


def test_the_exceptions_form_a_hierarchy_of_value_errors():
    for e in (mb.InputError, mb.MeshError, mb.QueryError):
        assert issubclass(e, mb.MotionBoundError)
    assert issubclass(mb.MotionBoundError, ValueError)


@pytest.mark.parametrize("bad", [np.nan, np.inf, -np.inf])
def test_non_finite_vertices_are_refused(bad):
    v = TET_V.copy()
    v[2, 1] = bad
    with pytest.raises(mb.MeshError, match="vertex 2"):
        mb.mesh(v, TET_F)
    with pytest.raises(mb.InputError):
        mb.convex_hull(v)


def test_absurd_magnitudes_are_refused():
    with pytest.raises((mb.MeshError, mb.InputError)):
        mb.mesh(TET_V * 1e300, TET_F)
    with pytest.raises(mb.InputError):
        mb.ball(1e300)
    with pytest.raises(mb.InputError):
        mb.Motion(np.eye(4), [1e300, 0, 0], [0, 0, 0])


@pytest.mark.parametrize("shape", [(4,), (4, 2), (4, 4), (2, 4, 3), ()])
def test_wrong_vertex_shapes_are_value_errors(shape):
    with pytest.raises(ValueError, match=r"shape \(n, 3\)"):
        mb.mesh(np.zeros(shape), TET_F)


def test_wrong_face_shapes_and_indices():
    with pytest.raises(ValueError, match=r"shape \(m, 3\)"):
        mb.mesh(TET_V, TET_F[:, :2])
    with pytest.raises(mb.MeshError, match="vertex 9"):
        mb.mesh(TET_V, [[0, 1, 9]])
    with pytest.raises(ValueError, match="-1"):
        mb.mesh(TET_V, [[0, 1, -1]])
    with pytest.raises(mb.MeshError):
        mb.mesh(TET_V, np.zeros((0, 3), int))


def test_wrong_dtypes_are_type_errors():
    # Float indices would be truncated: refused, not converted.
    with pytest.raises(TypeError, match="integers"):
        mb.mesh(TET_V, TET_F.astype(float))
    with pytest.raises(TypeError, match="real numbers"):
        mb.mesh(TET_V.astype(complex), TET_F)
    with pytest.raises((TypeError, ValueError)):
        mb.mesh([["a", "b", "c"]], TET_F)
    with pytest.raises(TypeError):
        mb.mesh(np.array([object()] * 3).reshape(1, 3), TET_F)


def test_other_real_dtypes_lists_and_strided_views_are_read_as_float64():
    ref = mb.time_of_impact(mb.mesh(TET_V, TET_F), mb.Motion(np.eye(4), [1, 0, 0], [0, 0, 1]),
                            mb.ball(0.2), mb.Motion.still(mb.Pose.from_translation([1.5, 0.3, 0.3])))
    wide = np.zeros((4, 6))
    wide[:, ::2] = TET_V  # a non-contiguous view
    for v, f in [(TET_V.tolist(), TET_F.tolist()), (TET_V.astype(np.float32), TET_F.astype(np.uint16)),
                 (wide[:, ::2], TET_F[:, :].T.copy().T), (TET_V.astype(np.int32), TET_F)]:
        r = mb.time_of_impact(mb.mesh(v, f), mb.Motion(np.eye(4), [1, 0, 0], [0, 0, 1]),
                              mb.ball(0.2), mb.Motion.still(mb.Pose.from_translation([1.5, 0.3, 0.3])))
        assert r == ref


def test_poses_must_be_rigid():
    with pytest.raises(mb.InputError, match="not a rotation"):
        mb.Pose(np.diag([1.0, 1.0, -1.0, 1.0]))  # a mirror
    with pytest.raises(mb.InputError, match="not a rotation"):
        mb.Pose(np.diag([2.0, 2.0, 2.0, 1.0]))  # scaled
    m = np.eye(4)
    m[3, 0] = 0.5
    with pytest.raises(ValueError, match="last row"):
        mb.Pose(m)
    with pytest.raises(mb.InputError):
        mb.Pose.from_wxyz([0, 0, 0, 0])
    with pytest.raises(mb.InputError):
        mb.Pose.from_wxyz([np.nan, 0, 0, 1])
    with pytest.raises(ValueError, match=r"\(4, 4\)"):
        mb.Motion.still(np.eye(3))


def test_bad_shapes_directions_and_durations():
    with pytest.raises(mb.InputError):
        mb.ball(-1.0)
    with pytest.raises(mb.InputError):
        mb.cylinder(0.0, 1.0)
    with pytest.raises(mb.InputError):
        mb.half_space([0, 0, 0])
    with pytest.raises(mb.InputError):
        mb.convex_hull(np.zeros((0, 3)))
    with pytest.raises(mb.InputError):
        mb.compound([])
    with pytest.raises(ValueError):
        mb.compound([(mb.half_space([0, 0, 1]), np.eye(4))])
    with pytest.raises(TypeError):
        mb.compound([("not a body", np.eye(4))])
    with pytest.raises(mb.InputError):
        mb.Motion.still(np.eye(4), duration=0.0)
    with pytest.raises(mb.InputError):
        mb.Motion.still(np.eye(4), duration=np.nan)


def test_bad_queries():
    ball = mb.ball(0.1)
    still = mb.Motion.still(np.eye(4))
    with pytest.raises(mb.QueryError, match="different intervals"):
        mb.time_of_impact(ball, still, ball, mb.Motion.still(np.eye(4), duration=2.0))
    for kw in ({"contact_distance": -1.0}, {"contact_distance": np.nan}, {"contact_distance": 0.0},
               {"tolerance": -1.0},
               {"max_iterations": 0}):
        with pytest.raises(mb.QueryError):
            mb.time_of_impact(ball, still, ball, still, **kw)
    ground = mb.half_space([0, 0, 1])
    with pytest.raises(mb.QueryError, match="half-space"):
        mb.time_of_impact(ground, mb.Motion(np.eye(4), [0, 0, 0], [0, 0, 1]), ball, still)
    with pytest.raises(mb.QueryError):
        mb.time_of_impact(ground, still, ground, still)
    with pytest.raises(TypeError):
        mb.time_of_impact_batch(ball, "motions", ball, still)
    n3 = mb.MotionBatch(np.tile(np.eye(4), (3, 1, 1)), np.zeros((3, 3)), np.zeros((3, 3)))
    n2 = mb.MotionBatch(np.tile(np.eye(4), (2, 1, 1)), np.zeros((2, 3)), np.zeros((2, 3)))
    with pytest.raises(ValueError, match="3 motions but"):
        mb.time_of_impact_batch(ball, n3, ball, n2)
    with pytest.raises(ValueError):
        mb.MotionBatch(np.tile(np.eye(4), (3, 1, 1)), np.zeros((2, 3)), np.zeros((3, 3)))
    with pytest.raises(IndexError):
        n3[3]
    with pytest.raises(mb.QueryError):
        mb.Scene().add(ball, mb.Motion.still(np.eye(4), duration=2.0))


def test_reports_rebuilt_from_bad_fields_are_refused():
    ok = ([0], [0.5], [[0, 0, 0]], [[0, 0, 0]], [[1, 0, 0]], [0.0], [3])
    assert mb.BatchReport(*ok)[0].outcome == "contact"
    for k, bad in ((0, [6]), (0, [-1]), (0, [1.5]), (6, [-2]), (6, [2.0**40])):
        args = list(ok)
        args[k] = bad
        with pytest.raises(ValueError):
            mb.BatchReport(*args)
    with pytest.raises(ValueError, match="unknown outcome"):
        mb.Report("hit", 0.5, None, None, None, None, 1)
