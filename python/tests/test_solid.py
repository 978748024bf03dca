"""Solid meshes: a ball, a box and the bunny starting inside a solid closed
mesh are an initial contact; declared hollow, separated; a mesh with a hole
is refused as solid with a MeshError (a ValueError); by default a mesh is
solid exactly when it is closed and wound outward (trimesh's watertight and
consistently wound meshes)."""

import gzip
import pathlib
import pickle

import numpy as np
import pytest
import trimesh

import motion_bound as mb

DATA = pathlib.Path(__file__).parent.parent.parent / "data"


def bunny(reach):
    """The crate's small bunny, about its centre of mass, at `reach`."""
    with gzip.open(DATA / "bunny-npm-3674.obj.gz", "rt") as f:
        m = trimesh.load(f, file_type="obj", force="mesh", process=False)
    m.apply_translation(-m.center_mass)
    m.apply_scale(reach / np.linalg.norm(m.vertices, axis=1).max())
    return m


def inside_by_parity(m, p, rng):
    """Whether `p` is inside the closed mesh `m`: the parity of the crossings
    of a random ray (Moller-Trumbore in numpy), redrawn near an edge."""
    tri = m.vertices[m.faces]
    while True:
        d = rng.normal(size=3)
        d /= np.linalg.norm(d)
        e1, e2 = tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0]
        h = np.cross(d, e2)
        det = np.einsum("ij,ij->i", e1, h)
        ok = np.abs(det) > 1e-14
        s = p - tri[:, 0]
        u = np.einsum("ij,ij->i", s, h) / np.where(ok, det, 1.0)
        q = np.cross(s, e1)
        v = (q @ d) / np.where(ok, det, 1.0)
        t = np.einsum("ij,ij->i", e2, q) / np.where(ok, det, 1.0)
        near = ok & (t > 0) & (np.minimum(np.minimum(np.abs(u), np.abs(v)), np.abs(1 - u - v)) < 1e-9)
        if near.any():
            continue
        hits = ok & (t > 0) & (u > 0) & (v > 0) & (u + v < 1)
        return bool(hits.sum() % 2)


def still():
    return mb.Motion.still(np.eye(4))


def drifting(at):
    """From `at`, 0.05 along x, spinning."""
    start = np.eye(4)
    start[:3, 3] = at
    return mb.Motion(start, [0.05, 0.0, 0.0], [1.0, 2.0, 3.0])


INNER = {
    "ball": lambda: mb.ball(0.1),
    "box": lambda: mb.box([0.1, 0.05, 0.08]),
    "bunny": lambda: mb.from_trimesh(bunny(0.15)),
}


@pytest.mark.parametrize("inner", sorted(INNER))
@pytest.mark.parametrize("first", [True, False])
def test_a_body_inside_a_solid_box_mesh_is_an_initial_contact(inner, first):
    box = trimesh.creation.box(extents=[2, 2, 2])
    assert box.is_watertight and box.is_winding_consistent
    body = INNER[inner]()
    for container, expected in [
        (mb.from_trimesh(box), "initial_contact"),
        (mb.from_trimesh(box, solid=True), "initial_contact"),
        (mb.from_trimesh(box, solid=False), "separated"),
    ]:
        pair = (container, still(), body, drifting([0.3, -0.2, 0.1]))
        if not first:
            pair = pair[2:] + pair[:2]
        r = mb.time_of_impact(*pair)
        assert r.outcome == expected, (inner, container.solid, r.outcome)
        if expected == "initial_contact":
            assert r.time == 0.0 and r.distance == 0.0
            assert np.array_equal(r.point_a, r.point_b)


@pytest.mark.parametrize("inner", sorted(INNER))
def test_a_body_inside_the_solid_bunny_is_an_initial_contact(inner):
    big = bunny(2.0)
    assert big.is_watertight
    # The bunny's centre of mass, inside by the test's own ray count (and
    # clear of the surface: the query with the bunny hollow is separated).
    inside = np.zeros(3)
    rng = np.random.default_rng(1)
    assert inside_by_parity(big, inside, rng) and not inside_by_parity(big, np.full(3, 3.0), rng)
    body = INNER[inner]()
    solid = mb.from_trimesh(big)
    hollow = mb.from_trimesh(big, solid=False)
    assert solid.solid and not hollow.solid
    r = mb.time_of_impact(solid, still(), body, drifting(inside))
    assert r.outcome == "initial_contact", (inner, r.outcome)
    r = mb.time_of_impact(hollow, still(), body, drifting(inside))
    assert r.outcome == "separated", (inner, r.outcome)


def test_the_default_follows_closedness_and_the_scene_and_compounds_honour_it():
    box = trimesh.creation.box(extents=[2, 2, 2])
    open_box = trimesh.Trimesh(box.vertices, box.faces[:-1], process=False)
    assert not open_box.is_watertight
    assert mb.from_trimesh(box).solid and not mb.from_trimesh(open_box).solid
    assert mb.mesh(box.vertices, box.faces[:, ::-1]).solid is False, "wound inward: hollow"
    assert mb.ball(1.0).solid is None
    solid = mb.from_trimesh(box)
    # In a compound, moved: still solid.
    part = np.eye(4)
    part[:3, 3] = [5.0, 0.0, 0.0]
    both = mb.compound([(mb.ball(0.5), np.eye(4)), (solid, part)])
    start = np.eye(4)
    start[:3, 3] = [5.2, 0.1, 0.0]
    r = mb.time_of_impact(both, still(), mb.ball(0.1), mb.Motion.still(start))
    assert r.outcome == "initial_contact", r.outcome
    # In a scene.
    scene = mb.Scene(1.0)
    scene.add(solid, still())
    scene.add(mb.ball(0.1), drifting([0.2, 0.0, 0.0]))
    ((a, b, report),) = scene.query()
    assert (a, b) == (0, 1) and report.outcome == "initial_contact", report.outcome
    # Pickled, solid or hollow.
    for b in [solid, mb.from_trimesh(box, solid=False)]:
        c = pickle.loads(pickle.dumps(b))
        assert c.solid == b.solid and repr(c) == repr(b)


def test_a_mesh_with_a_hole_is_refused_as_solid():
    box = trimesh.creation.box(extents=[2, 2, 2])
    holed = trimesh.Trimesh(box.vertices, box.faces[:-1], process=False)
    with pytest.raises(mb.MeshError, match="not closed"):
        mb.from_trimesh(holed, solid=True)
    with pytest.raises(ValueError, match="3 unpaired"):
        mb.mesh(holed.vertices, holed.faces, solid=True)
    with pytest.raises(mb.MeshError, match="wound inward"):
        mb.mesh(box.vertices, box.faces[:, ::-1], solid=True)
    # Hollow is always allowed.
    assert mb.from_trimesh(holed, solid=False).solid is False
