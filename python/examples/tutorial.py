"""A first tour of motion_bound, printing what it does: two shapes and a time of impact, a
rotation cleaned for a pose, a batch of motions, a scene, and a mesh from trimesh.

Run it from python/ after `maturin develop --release`: `python examples/tutorial.py` (a few
seconds; trimesh is optional: without it, the last part is skipped)."""

import numpy as np

import motion_bound as mb


def translation(x, y, z):
    """A 4x4 pose that only translates."""
    m = np.eye(4)
    m[:3, 3] = [x, y, z]
    return m


# 1. Two shapes and a time of impact. Capsules, cylinders and cones lie along their body's y
#    axis; `box` takes half extents.
ball = mb.ball(0.25)
box = mb.box([0.5, 0.2, 0.2])  # 1.0 x 0.4 x 0.4 in all
flight = mb.Motion.between(translation(-3, 0, 0), translation(3, 0, 0))  # over [0, 1]
still = mb.Motion.still(np.eye(4))
r = mb.time_of_impact(ball, flight, box, still, contact_distance=1e-4)
print("1. a ball flies at 6 m/s into a box 1 m long:")
print(f"   outcome {r.outcome!r} at t = {r.time:.6f} (closed form {(3 - 0.75) / 6:.6f}),")
print(f"   point on the ball {r.point_a}, on the box {r.point_b}, normal {r.normal}")
# A spin is certified too: the box turns a full turn about z while the ball waits beside it.
spin = mb.Motion(np.eye(4), [0, 0, 0], [0, 0, 2 * np.pi])
r = mb.time_of_impact(box, spin, ball, mb.Motion.still(translation(0, 0.6, 0)))
print(f"   a spinning box reaches a ball 0.6 m from its axis: {r.outcome!r} at t = {r.time:.4f}")

# 2. Rotations: a pose's 3x3 block must be orthonormal to within 1e-6. One read from a file
#    with five decimals is not; orthonormalize=True (or mb.orthonormalize) cleans it.
c, s = np.cos(0.3), np.sin(0.3)
rounded = np.round(np.array([[c, -s, 0, 0], [s, c, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]), 5)
try:
    mb.Pose(rounded)
except mb.InputError as e:
    print(f"2. a rotation rounded to 5 decimals is refused: {str(e)[:60]}...")
pose = mb.Pose(rounded, orthonormalize=True)
print(f"   cleaned: quaternion {np.round(pose.wxyz, 6)}")

# 3. A batch: many motions of the same two bodies, on every core.
rng = np.random.default_rng(0)
n = 2000
starts = np.tile(np.eye(4), (n, 1, 1))
directions = rng.normal(size=(n, 3))
starts[:, :3, 3] = directions / np.linalg.norm(directions, axis=1)[:, None] * 1.5  # all clear
batch = mb.MotionBatch(starts, rng.normal(size=(n, 3)) * 2, rng.normal(size=(n, 3)))
report = mb.time_of_impact_batch(box, batch, ball, still)
print(f"3. {n} random motions of the box against the still ball: {report.hits.sum()} hit,")
print(f"   earliest contact at t = {np.nanmin(report.times):.4f}; "
      f"report arrays: times {report.times.shape}, points_a {report.points_a.shape}")

# 4. A scene: every pair's first contact after a certified broad phase (on every core).
scene = mb.Scene()
for i in range(6):
    body = [ball, box, mb.capsule(0.3, 0.1)][i % 3]
    scene.add(body, mb.Motion(translation(i - 2.5, 0, 0), [(-1) ** i * 0.8, 0, 0], [0, 0, 1]))
pairs = [(i, j, rep) for i, j, rep in scene.query() if rep.hit]
print(f"4. a scene of {len(scene)} bodies: {len(pairs)} pairs touch; "
      f"{scene.stats['pairs_culled']} of {scene.stats['pairs_all']} pairs culled")
for i, j, rep in pairs[:3]:
    print(f"   bodies {i} and {j}: {rep.outcome} at t = {rep.time:.4f}")

# 5. Meshes from trimesh: a Trimesh is its triangles; trimesh's primitives are exact shapes,
#    taken as trimesh means them (a capsule along z, a box of full extents).
try:
    import trimesh
except ImportError:
    print("5. (trimesh is not installed: skipped)")
else:
    bunny_like = trimesh.creation.icosphere(subdivisions=3, radius=0.4)
    mesh = mb.from_trimesh(bunny_like)
    print(f"5. {mesh!r} from trimesh ({'solid' if mesh.solid else 'hollow'})")
    r = mb.time_of_impact(mesh, spin, ball, mb.Motion.between(translation(0, 2, 0), np.eye(4)))
    print(f"   a ball dropped onto the spinning sphere touches it at t = {r.time:.4f} "
          f"(closed form {(2 - 0.65) / 2:.4f} for the exact sphere; the triangles lie inside it)")
    cap = mb.from_trimesh(trimesh.primitives.Capsule(radius=0.1, height=1.0))
    r = mb.time_of_impact(cap, still, ball, mb.Motion.between(translation(0, 0, 2), np.eye(4)))
    print(f"   trimesh's capsule (height 1 along z): touched from above at t = {r.time:.4f} "
          f"(closed form {(2 - 0.85) / 2:.4f})")
