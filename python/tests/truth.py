"""Ground truth independent of motion_bound: poses by our own formulas in numpy,
exact mesh distances from python-fcl (its BVH distance query), and a sampling
walk whose steps are bounded by a crude speed bound, so that it never steps over
the first time the distance falls to a threshold.

A body moving by motion_bound's `Motion(start, v, w)` has, at time t, the pose
R(t) = exp(t [w]x) R0 and p(t) = p0 + t v (it turns about its origin);
`Motion.between(start, end, T)` is the same with v = (p1 - p0) / T and
w = axis * angle / T for the rotation R1 R0^T (the shortest angle). Every point
r of the body then moves at most |v| + |w| |r| per unit time, so the distance
between two bodies changes at most at L = the sum of both bodies' such bounds.
"""

import math

import fcl
import numpy as np


def rodrigues(axis_angle):
    """The rotation matrix of the scaled axis `axis_angle`."""
    theta = float(np.linalg.norm(axis_angle))
    if theta == 0.0:
        return np.eye(3)
    k = np.asarray(axis_angle, float) / theta
    kx = np.array([[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]])
    return np.eye(3) + math.sin(theta) * kx + (1 - math.cos(theta)) * (kx @ kx)


def log_rotation(r):
    """The scaled axis (angle in [0, pi]) of the rotation matrix `r`."""
    c = max(-1.0, min(1.0, (np.trace(r) - 1.0) / 2.0))
    angle = math.acos(c)
    if angle < 1e-12:
        return np.zeros(3)
    if angle > math.pi - 1e-6:
        # Near pi: the axis from the symmetric part.
        m = (r + np.eye(3)) / 2.0
        k = np.sqrt(np.maximum(np.diag(m), 0.0))
        i = int(np.argmax(k))
        k[:] = m[i] / k[i]
        return k / np.linalg.norm(k) * angle
    w = np.array([r[2, 1] - r[1, 2], r[0, 2] - r[2, 0], r[1, 0] - r[0, 1]])
    return w / (2.0 * math.sin(angle)) * angle


def homogeneous(rotation, translation):
    """The 4x4 matrix of a rotation and a translation."""
    m = np.eye(4)
    m[:3, :3], m[:3, 3] = rotation, translation
    return m


class Trajectory:
    """A rigid motion given by its start pose and constant velocities."""

    def __init__(self, start, linear, angular):
        start = np.asarray(start, float)
        self.r0 = start[:3, :3]
        self.p0 = start[:3, 3]
        self.v = np.asarray(linear, float)
        self.w = np.asarray(angular, float)

    @classmethod
    def between(cls, start, end, duration=1.0):
        start, end = np.asarray(start, float), np.asarray(end, float)
        w = log_rotation(end[:3, :3] @ start[:3, :3].T) / duration
        return cls(start, (end[:3, 3] - start[:3, 3]) / duration, w)

    def pose(self, t):
        return rodrigues(self.w * t) @ self.r0, self.p0 + self.v * t

    def speed_bound(self, reach):
        return float(np.linalg.norm(self.v) + np.linalg.norm(self.w) * reach)


class FclBody:
    """A mesh as a python-fcl BVH model, with its reach from the origin."""

    def __init__(self, vertices, faces):
        self.vertices = np.asarray(vertices, float)
        self.faces = np.asarray(faces, np.int64)
        model = fcl.BVHModel()
        model.beginModel(len(self.vertices), len(self.faces))
        model.addSubModel(self.vertices, self.faces)
        model.endModel()
        self.model = model
        self.reach = float(np.max(np.linalg.norm(self.vertices, axis=1)))

    def at(self, rotation, translation):
        return fcl.CollisionObject(self.model, fcl.Transform(rotation, translation))


def distance(a, ta, b, tb, t):
    """The exact distance of the two meshes' surfaces at time t (0 when they meet)."""
    oa, ob = a.at(*ta.pose(t)), b.at(*tb.pose(t))
    if fcl.collide(oa, ob, fcl.CollisionRequest(), fcl.CollisionResult()) > 0:
        return 0.0
    return max(0.0, fcl.distance(oa, ob, fcl.DistanceRequest(), fcl.DistanceResult()))


def first_time_within(a, ta, b, tb, threshold, duration=1.0, resolution=1e-6):
    """The first sampled time in [0, duration] at which the distance is at most
    `threshold`, or None. Steps are (d - threshold) / L, which never pass the
    first such time, and at least `resolution`: a dip below the threshold
    shorter than that can be stepped over (a contact the truth misses, never
    one it invents), and the first time is found to within `resolution`."""
    speed = ta.speed_bound(a.reach) + tb.speed_bound(b.reach)
    t = 0.0
    while t <= duration:
        d = distance(a, ta, b, tb, t)
        if d <= threshold:
            return t
        if speed == 0.0:
            return None
        t += max((d - threshold) / speed, resolution)
    return None
