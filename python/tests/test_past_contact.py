"""`past_contact` (proofs/12-shapes.md, Lemma 12.11) against the boxes' corners sampled
densely by our own pose formulas (truth.py): until the answer's time (over the whole
interval for "never"), A's extent along the normal beyond B's least stays below its
start's (or 0) plus the contact distance."""

import numpy as np
import pytest

import motion_bound as mb
from devkit import random_rotation, unit
from truth import Trajectory, homogeneous

CONTACT = 1e-4
DT = 1.0 / 60.0
SAMPLES = 4001
SIGNS = np.array([[sx, sy, sz] for sx in (-1, 1) for sy in (-1, 1) for sz in (-1, 1)], float)


def extents(half, trajectory, n, times):
    """The greatest and least `n . x` over a box's corners at each time (the pose
    R(t) = exp(t [w]x) R0, p(t) = p0 + t v of truth.py, by Rodrigues' formula)."""
    theta = np.linalg.norm(trajectory.w)
    k = trajectory.w / theta if theta > 0.0 else np.zeros(3)
    kx = np.array([[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]])
    # n . (R(t) R0 c + p(t)) for every corner c: R(t)^T n turns n, not the corners.
    s, c = np.sin(theta * times), np.cos(theta * times)
    m = np.eye(3), kx, kx @ kx
    turned = n @ m[0] + np.outer(s, n @ m[1]) + np.outer(1.0 - c, n @ m[2])
    local = (SIGNS * half) @ trajectory.r0.T
    x = turned @ local.T + (trajectory.p0 @ n + times * (trajectory.v @ n))[:, None]
    return x.max(axis=1), x.min(axis=1)


def draw(rng, deep=False):
    """Box A spinning and moving, touching (or `deep` in) wall B, which translates."""
    n = unit(rng)
    half_a = rng.uniform(0.05, 0.3, size=3)
    rot_a = random_rotation(rng)
    wall = np.array([0.5, 2.0, 2.0])
    # The wall's x axis along n: its face x = -0.5 (the least n . x) at the origin.
    rot_b = np.linalg.qr(np.column_stack([n, unit(rng), unit(rng)]))[0]
    rot_b *= np.sign(rot_b[:, 0] @ n)
    rot_b[:, 2] *= np.linalg.det(rot_b)
    p_b = 0.5 * n
    # A's greatest n . x placed `gap` short of the face.
    reach = np.abs((SIGNS * half_a) @ rot_a.T @ n).max()
    gap = -rng.uniform(1.5, 3.0) * CONTACT if deep else rng.uniform(0.0, 0.99) * CONTACT
    p_a = (-gap - reach) * n + (np.eye(3) - np.outer(n, n)) @ rng.uniform(-0.5, 0.5, size=3)
    v_a = rng.uniform(-2.0, 2.0, size=3) + rng.uniform(-0.05, 0.05) * n
    w_a = unit(rng) * rng.uniform(0.0, 20.0)
    v_b = rng.uniform(-1.0, 1.0, size=3)
    return n, (half_a, homogeneous(rot_a, p_a), v_a, w_a), (wall, homogeneous(rot_b, p_b), v_b)


def test_the_answer_holds_against_the_sampled_corners():
    rng = np.random.default_rng(7)
    seen = {"never": 0, "at": 0, "undecided": 0}
    times = np.linspace(0.0, DT, SAMPLES)
    for k in range(120):
        n, (half_a, start_a, v_a, w_a), (half_b, start_b, v_b) = draw(rng, deep=k % 10 == 9)
        motion_a = mb.Motion(start_a, v_a, w_a, DT)
        motion_b = mb.Motion(start_b, v_b, [0.0, 0.0, 0.0], DT)
        outcome, time = mb.past_contact(
            mb.box(half_a), motion_a, mb.box(half_b), motion_b, n, contact_distance=CONTACT)
        seen[outcome] += 1
        hi, _ = extents(half_a, Trajectory(start_a, v_a, w_a), n, times)
        _, lo = extents(half_b, Trajectory(start_b, v_b, [0.0, 0.0, 0.0]), n, times)
        over = hi - lo
        limit = max(over[0], 0.0) + CONTACT
        if outcome == "never":
            assert time is None
            assert over.max() < limit, (k, over.max() - limit)
        else:
            assert outcome == "at", (k, outcome)
            assert 0.0 <= time <= DT
            if over[0] > CONTACT:
                assert time == 0.0, k
            before = times < time
            assert not before.any() or over[before].max() < limit, (k, time)
    assert seen["never"] >= 20 and seen["at"] >= 20, seen


def test_the_roles_swap_when_only_b_turns():
    # A still box beside a spinning wall pushed onto it: B is cast along -normal.
    n = np.array([1.0, 0.0, 0.0])
    a = mb.box([0.1, 0.1, 0.1])
    wall = mb.box([0.5, 2.0, 2.0])
    still_a = mb.Motion.still(homogeneous(np.eye(3), [-0.1 - 5e-5, 0.0, 0.0]), DT)
    spin_in = mb.Motion(homogeneous(np.eye(3), [0.5, 0.0, 0.0]), [-1.0, 0.0, 0.0], [3.0, 0.0, 0.0], DT)
    outcome, time = mb.past_contact(a, still_a, wall, spin_in, n, contact_distance=CONTACT)
    # The wall's face reaches 1e-4 into A at t = 1.5e-4 / 1: never later.
    assert outcome == "at" and 0.0 < time <= 1.5e-4
    away = mb.Motion(homogeneous(np.eye(3), [0.5, 0.0, 0.0]), [1.0, 0.0, 0.0], [3.0, 0.0, 0.0], DT)
    assert mb.past_contact(a, still_a, wall, away, n, contact_distance=CONTACT) == ("never", None)


def test_both_turning_or_a_half_space_is_undecided():
    n = np.array([1.0, 0.0, 0.0])
    a, wall = mb.box([0.1, 0.1, 0.1]), mb.box([0.5, 2.0, 2.0])
    spin_a = mb.Motion(homogeneous(np.eye(3), [-0.1, 0.0, 0.0]), [0.0, 1.0, 0.0], [0.0, 0.0, 2.0], DT)
    spin_b = mb.Motion(homogeneous(np.eye(3), [0.5, 0.0, 0.0]), [0.0, 0.0, 0.0], [1.0, 0.0, 0.0], DT)
    assert mb.past_contact(a, spin_a, wall, spin_b, n) == ("undecided", None)
    floor = mb.half_space([-1.0, 0.0, 0.0])
    still = mb.Motion.still(np.eye(4), DT)
    assert mb.past_contact(a, spin_a, floor, still, n) == ("undecided", None)


@pytest.mark.parametrize("normal", [[0.0, 0.0, 0.0], [np.nan, 1.0, 0.0], [np.inf, 0.0, 0.0]])
def test_a_zero_or_non_finite_normal_is_refused_by_name(normal):
    a = mb.box([0.1, 0.1, 0.1])
    still = mb.Motion.still(np.eye(4), DT)
    with pytest.raises(mb.InputError, match="^normal"):
        mb.past_contact(a, still, a, still, normal)


def test_bad_parameters_and_intervals_are_query_errors():
    a = mb.box([0.1, 0.1, 0.1])
    still = mb.Motion.still(np.eye(4), DT)
    with pytest.raises(mb.QueryError, match="contact_distance"):
        mb.past_contact(a, still, a, still, [1.0, 0.0, 0.0], contact_distance=-1.0)
    with pytest.raises(mb.QueryError, match="intervals"):
        mb.past_contact(a, still, a, mb.Motion.still(np.eye(4), 2 * DT), [1.0, 0.0, 0.0])
    with pytest.raises(ValueError, match="normal"):
        mb.past_contact(a, still, a, still, [1.0, 0.0])
