"""motion_bound against python-fcl's continuous collision, both judged by a
ground truth neither of them computes (tests/truth.py: poses by numpy formulas,
python-fcl's exact discrete distances, a sampling walk bounded by a crude speed
bound).

    python scripts/compare_fcl.py [--queries 50] [--seed 7] [--naive-samples 100] [--no-extras]

Scenes: (a) the seed's Table 1 torus knots at 2.8K triangles, the first
`--queries` fly-bys of `mb.table1_scene("2.8K", n)` (the Rust `table1` report's
queries); (b) seeded bunny fly-bys: bunny A starts 1.1-1.6 x (reach A + reach B)
away in a random direction, flies through a random point within 0.8 reach of
the origin at t = 0.5 turning at up to 2 rad per unit time, past bunny B at the
origin turning at up to 0.5. Both bodies start in random orientations; every
motion lasts [0, 1]. Per scene the script prints a label line, then exactly

    python-fcl: missed Mf, late Lf, ms Xf; motion_bound: missed M, late L, ms X

then indented extra lines (python-fcl's other solvers and motion types, and
motion_bound's undecided and false counts) unless --no-extras. `ms` is the mean
wall time per query of the one call (`fcl.continuousCollide`,
`mb.time_of_impact`), measured from Python with time.perf_counter on the same
queries (inputs built outside the timed region). The truth is not timed.

What python-fcl (0.7.0.x, FCL 0.7) offers, read from its fcl.pyx / fcl_defs.pxd
and FCL's continuous_collision-inl.h, conservative_advancement_func_matrix-inl.h
and the motion classes:

* `fcl.continuousCollide(obj_a, tf_goal_a, obj_b, tf_goal_b, request, result)`:
  each object's current transform is its pose at t = 0, the Transform its pose
  at t = 1; FCL builds the path in between from the two poses alone.
  `fcl.ContinuousCollisionRequest(num_max_iterations=10, toc_err=1e-4,
  ccd_motion_type, gjk_solver_type, ccd_solver_type)`.
* `result.is_collide` (bool) and `result.time_of_contact` (1.0 when no contact;
  the Python wrapper ORs/mins into the result object it is given, so a fresh
  result per call); the call returns the time of contact, or -1 for a setting
  FCL does not implement (with a warning on stderr).
* ccd_solver_type: CCDC_NAIVE (tests num_max_iterations evenly spaced poses,
  capped at ceil(1/toc_err), and reports the first colliding sample: by design
  up to one sample spacing late); CCDC_CONSERVATIVE_ADVANCEMENT (for two BVH
  meshes: OBBRSS, the BV type python-fcl builds; it ignores the request's
  toc_err and num_max_iterations and stops when its step falls below a fixed
  1e-5, reporting that time, which is before touching if its motion bounds
  hold); CCDC_RAY_SHOOTING (not implemented: returns -1 for every input);
  CCDC_POLYNOMIAL_SOLVER (meshes with CCDM_TRANS only; it rewrites both BVH
  models' vertices in place, so it gets fresh models here).
* ccd_motion_type: CCDM_TRANS (TranslationMotion: the start rotation is kept,
  the end rotation ignored), CCDM_LINEAR (InterpMotion: rotation
  R(t) = AngleAxis(t theta, axis) R0 about a reference point, and that point
  moving on a line; with the point at the body origin this is exactly
  motion_bound's `Motion(start, v, w)` for |w| <= pi), CCDM_SCREW (ScrewMotion:
  the constant screw, a helix about the screw axis, from start to end),
  CCDM_SPLINE (SplineMotion; not used here).

The choice for the main line, and why. CCDM_LINEAR would be our motion, but in
FCL 0.7 `InterpMotion(tf1, tf2)` never initialises its reference point
(`reference_p`, an Eigen vector; FCL pull request #662 is still open), so the
pivot of the rotation is whatever was on the heap: `linear_probe()` below turns
a small tetrahedron 5 units off its origin by 90 degrees past a box, and the
naive solver finds that contact on every call in one process and on none in
another (0 of 8 at the start of this script; the naive solver with
CCDM_LINEAR also reports knot contacts at times our motion has none). A motion
that is not defined cannot be judged fairly, so the main line gives python-fcl
CCDM_SCREW, its well-defined interpolation, with its conservative-advancement
solver, and judges it by the truth OF THE SCREW PATH
(`ScrewTrajectory`, FCL's ScrewMotion formulas in numpy, fed to the same
truth.first_time_within). Both libraries get the same start and end poses; the
paths agree for a body that only turns about its own origin (the knots' B, the
bunnies' B) and differ for one that also translates across its axis (A).
(For a pure translation FCL's ScrewMotion uses the unnormalised displacement as
its axis and moves |d|^2 instead of |d|; no moving body here is without
rotation, and `ScrewTrajectory` reproduces FCL even there.) CCDM_LINEAR with
conservative advancement is an extra line, judged by our motion's truth.

Contracts, hence the truths:
* motion_bound reports contact when the distance is at most the contact
  distance cd, never later than the first time the distance falls to cd / 2 and
  never missing such a time: missed = truth(cd / 2) finds a time and the
  outcome is "separated"; late = reported time > truth(cd / 2) + 1e-6 (the
  truth's resolution).
* python-fcl has no contact distance; its contract is the time the surfaces
  touch. It is judged by its own contract, truth(0) of the path it was given:
  missed = the bodies touch and is_collide is False; late = time_of_contact >
  truth(0) + 1e-6 + its time quantisation: 1e-5 for conservative advancement
  (its fixed stopping step), 1 / (samples - 1) for the naive solver. A grazing
  pass within cd / 2 that never touches is therefore no miss for python-fcl;
  judging it by motion_bound's cd / 2 could only raise its counts.
* `false` (extra lines): a reported contact at a time when the true distance
  (of the path the method was given) exceeds cd: a contact that is not there.

What this finds with python-fcl 0.7.0.11 (defaults: 50 fly-bys per scene, seed
7; about 35-40 s with the extras, 16 s without, on two cores): conservative
advancement between two meshes misses every touching knot fly-by (48 of 48)
and 40 of the 45 touching bunny fly-bys; its other 5 bunny answers are contacts
at times the bunnies are apart (up to 0.62 late). It also answers no contact
for two unit-cube meshes translating head-on, with every motion type: FCL
issues #120 and #555 and python-fcl issue #38 report the same. The naive solver
is right to within its sample spacing (0 missed, 0 late with 1/99 slack, about
0.3 ms for 100 samples); the polynomial solver reports a contact on every
fly-by, at a time the meshes are apart; ray shooting is not implemented.
motion_bound: 0 missed, 0 late, every contact within the contact distance.
"""

import math
import pathlib
import sys
import time

import fcl
import numpy as np

import motion_bound as mb

HERE = pathlib.Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
sys.path.insert(0, str(HERE.parent / "tests"))
from meshes import load_bunny  # noqa: E402
from devkit import random_rotation, script_parser, unit  # noqa: E402
from truth import (FclBody, Trajectory, distance, first_time_within, homogeneous,  # noqa: E402
                   log_rotation, rodrigues)

RESOLUTION = 1e-6  # the truth's time resolution (truth.first_time_within's default)
FCL_CA_STEP = 1e-5  # FCL's fixed stopping step in mesh conservative advancement (t_err)
BUNNY_SPIN_A, BUNNY_SPIN_B = 2.0, 0.5

M = fcl.CCDMotionType
SOLVER = fcl.CCDSolverType
CA = SOLVER.CCDC_CONSERVATIVE_ADVANCEMENT


# -- FCL's screw path, in numpy ----------------------------------------------------------------


def _axis_angle(r):
    """Eigen's AngleAxis of a rotation matrix: (unit axis, angle in [0, pi])."""
    w = log_rotation(r)
    angle = float(np.linalg.norm(w))
    return (w / angle, angle) if angle > 0.0 else (np.array([1.0, 0.0, 0.0]), 0.0)


class ScrewTrajectory:
    """FCL's ScrewMotion(tf1, tf2) (screw_motion-inl.h: computeScrewParameter
    and integrate) over [0, 1]: R(t) = AngleAxis(t theta, axis) R1,
    T(t) = p + axis t lv + AngleAxis(t theta, axis) (T1 - p). Duck-types
    truth.Trajectory (pose, speed_bound) so first_time_within walks it."""

    def __init__(self, start, end):
        start, end = np.asarray(start, float), np.asarray(end, float)
        self.r1, self.t1 = start[:3, :3], start[:3, 3]
        axis, theta = _axis_angle(end[:3, :3] @ self.r1.T)
        o = end[:3, 3] - self.t1
        if theta < 1e-10:
            # FCL's branch: the axis is the displacement itself, not normalised.
            self.theta, self.axis, self.lv, self.p = 0.0, o, float(np.linalg.norm(o)), self.t1
        else:
            self.theta, self.axis = theta, axis
            self.p = (self.t1 + end[:3, 3] + np.cross(axis, o) / math.tan(theta / 2.0)) * 0.5
            self.lv = float(o @ axis)

    def pose(self, t):
        turn = rodrigues(self.axis * (self.theta * t)) if self.theta > 0 else np.eye(3)
        return turn @ self.r1, self.p + self.axis * (t * self.lv) + turn @ (self.t1 - self.p)

    def speed_bound(self, reach):
        """|axis lv| + theta (distance of the body origin from the axis + reach)."""
        if self.theta == 0.0:
            return float(np.linalg.norm(self.axis) * abs(self.lv))
        off = self.t1 - self.p
        off_axis = float(np.linalg.norm(off - (off @ self.axis) * self.axis))
        return abs(self.lv) + self.theta * (off_axis + reach)


def screw_of(traj):
    """The path FCL's CCDM_SCREW makes of traj's poses at 0 and 1."""
    return ScrewTrajectory(homogeneous(*traj.pose(0.0)), homogeneous(*traj.pose(1.0)))


def translation_only(traj):
    """What FCL's CCDM_TRANS does with our motion: the start rotation kept."""
    start = np.eye(4)
    start[:3, :3], start[:3, 3] = traj.r0, traj.p0
    return Trajectory(start, traj.v, np.zeros(3))


# -- scenes ------------------------------------------------------------------------------------


class FlyBy:
    """One query: mesh i moving by (start_a, v_a, w_a) and mesh j by (start_b, v_b, w_b)."""

    def __init__(self, i, j, start_a, v_a, w_a, start_b, v_b, w_b, motion_a=None, motion_b=None):
        self.i, self.j = i, j
        self.traj_a = Trajectory(start_a, v_a, w_a)
        self.traj_b = Trajectory(start_b, v_b, w_b)
        self.motion_a = motion_a if motion_a is not None else mb.Motion(start_a, v_a, w_a)
        self.motion_b = motion_b if motion_b is not None else mb.Motion(start_b, v_b, w_b)


def knot_scene(queries):
    s = mb.table1_scene("2.8K", queries)
    flybys = []
    for i, j, ma, mb_ in s["queries"]:
        assert ma.duration == 1.0 and mb_.duration == 1.0
        a = (np.array(ma.matrix_at(0.0)), np.array(ma.linear), np.array(ma.angular))
        b = (np.array(mb_.matrix_at(0.0)), np.array(mb_.linear), np.array(mb_.angular))
        flybys.append(FlyBy(i, j, *a, *b, motion_a=ma, motion_b=mb_))
    return {"name": "torus knots 2.8K (Table 1)", "meshes": s["meshes"], "flybys": flybys,
            "contact_distance": s["contact_distance"]}


def bunny_scene(queries, seed, contact_distance=1e-3):
    v, f = load_bunny(0.5)
    reach = float(np.max(np.linalg.norm(v, axis=1)))
    rng = np.random.default_rng(seed)
    flybys = []
    for _ in range(queries):
        p0 = unit(rng) * rng.uniform(1.1, 1.6) * 2 * reach
        target = unit(rng) * 0.8 * reach * rng.uniform() ** (1 / 3)  # uniform in the ball
        start_a = homogeneous(random_rotation(rng), p0)
        w_a = unit(rng) * rng.uniform(0, BUNNY_SPIN_A)
        start_b = homogeneous(random_rotation(rng), np.zeros(3))
        w_b = unit(rng) * rng.uniform(0, BUNNY_SPIN_B)
        flybys.append(FlyBy(0, 0, start_a, 2 * (target - p0), w_a, start_b, np.zeros(3), w_b))
    return {"name": f"bunny pairs ({len(f)} triangles, seed {seed})", "meshes": [(v, f)],
            "flybys": flybys, "contact_distance": contact_distance}


# -- the two libraries -------------------------------------------------------------------------


def fcl_query(a, traj_a, b, traj_b, motion_type, solver, samples=10):
    """fcl.continuousCollide from traj's pose at 0 to its pose at 1; returns
    (is_collide, time_of_contact, return value, seconds of the call)."""
    oa, ob = a.at(*traj_a.pose(0.0)), b.at(*traj_b.pose(0.0))
    ea, eb = fcl.Transform(*traj_a.pose(1.0)), fcl.Transform(*traj_b.pose(1.0))
    request = fcl.ContinuousCollisionRequest(num_max_iterations=samples, toc_err=1e-4,
                                             ccd_motion_type=motion_type, ccd_solver_type=solver)
    result = fcl.ContinuousCollisionResult()
    t0 = time.perf_counter()
    ret = fcl.continuousCollide(oa, ea, ob, eb, request, result)
    elapsed = time.perf_counter() - t0
    return bool(result.is_collide), float(result.time_of_contact), float(ret), elapsed


def mb_query(body_a, motion_a, body_b, motion_b, cd):
    t0 = time.perf_counter()
    r = mb.time_of_impact(body_a, motion_a, body_b, motion_b, contact_distance=cd)
    return r, time.perf_counter() - t0


def linear_probe(calls=4):
    """Is FCL's CCDM_LINEAR the rotation about the body origin? A small
    tetrahedron 5 units out along x turns 90 degrees about z (no translation)
    past a box on its circle at 45 degrees: with the pivot at the origin the
    naive solver must find the contact near t = 0.5, on every call. Returns
    the list of (is_collide, time) per call."""
    v = np.array([[5, 0, 0], [5.1, 0, 0], [5, 0.1, 0], [5, 0, 0.1]], float) - 0.05
    tet = FclBody(v, np.array([[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]]))
    box = fcl.Box(0.2, 0.2, 0.2)
    c = rodrigues([0, 0, math.pi / 4]) @ np.array([5.0, 0, 0])
    out = []
    for _ in range(calls):
        oa = tet.at(np.eye(3), np.zeros(3))
        ob = fcl.CollisionObject(box, fcl.Transform(np.eye(3), c))
        request = fcl.ContinuousCollisionRequest(num_max_iterations=201, toc_err=1e-3,
                                                 ccd_motion_type=M.CCDM_LINEAR,
                                                 ccd_solver_type=SOLVER.CCDC_NAIVE)
        result = fcl.ContinuousCollisionResult()
        fcl.continuousCollide(oa, fcl.Transform(rodrigues([0, 0, math.pi / 2]), np.zeros(3)),
                              ob, fcl.Transform(np.eye(3), c), request, result)
        out.append((bool(result.is_collide), float(result.time_of_contact)))
    return out


# -- judging -----------------------------------------------------------------------------------


class Tally:
    def __init__(self):
        self.missed = self.late = self.false = self.undecided = self.queries = self.contacts = 0
        self.seconds = 0.0
        self.worst_late = 0.0

    def judge(self, truth_time, hit, time_, slack, false=False, undecided=False, seconds=0.0):
        self.queries += 1
        self.seconds += seconds
        if undecided:
            self.undecided += 1
        if truth_time is not None:
            self.contacts += 1
            if not hit and not undecided:
                self.missed += 1
        if (hit or undecided) and truth_time is not None and time_ > truth_time + slack:
            self.late += 1
            self.worst_late = max(self.worst_late, time_ - truth_time)
        if false:
            self.false += 1

    @property
    def ms(self):
        return 1e3 * self.seconds / max(self.queries, 1)


def false_contact(a, traj_a, b, traj_b, hit, time_, cd):
    """A reported contact at a time the true distance exceeds cd."""
    return bool(hit) and distance(a, traj_a, b, traj_b, min(max(time_, 0.0), 1.0)) > cd + 1e-9


def run_scene(scene, extras=True, naive_samples=100):
    """Every fly-by of `scene` through motion_bound and python-fcl; returns a
    dict of Tallies: "mb", "fcl" (main line) and the extras."""
    cd = scene["contact_distance"]
    fcl_bodies = [FclBody(v, f) for v, f in scene["meshes"]]
    mb_bodies = [mb.mesh(v, f) for v, f in scene["meshes"]]
    t = {k: Tally() for k in ("mb", "fcl", "fcl_linear", "fcl_naive", "fcl_poly")}
    for q in scene["flybys"]:
        a, b = fcl_bodies[q.i], fcl_bodies[q.j]
        ta, tb = q.traj_a, q.traj_b

        # motion_bound, judged by truth(cd / 2) of its own motion.
        r, sec = mb_query(mb_bodies[q.i], q.motion_a, mb_bodies[q.j], q.motion_b, cd)
        truth_half = first_time_within(a, ta, b, tb, cd / 2)
        undecided = r.outcome not in ("contact", "initial_contact", "separated")
        t["mb"].judge(truth_half, r.hit, r.time, RESOLUTION, undecided=undecided, seconds=sec,
                      false=false_contact(a, ta, b, tb, r.hit, r.time, cd))

        # python-fcl, conservative advancement, screw motion: judged by truth(0) of the screw path.
        sa, sb = screw_of(ta), screw_of(tb)
        hit, toc, _, sec = fcl_query(a, ta, b, tb, M.CCDM_SCREW, CA)
        truth_touch_screw = first_time_within(a, sa, b, sb, 0.0)
        t["fcl"].judge(truth_touch_screw, hit, toc, RESOLUTION + FCL_CA_STEP, seconds=sec,
                       false=false_contact(a, sa, b, sb, hit, toc, cd))
        if not extras:
            continue

        # Conservative advancement with CCDM_LINEAR (meant to be our motion): truth(0) of ours.
        hit, toc, _, sec = fcl_query(a, ta, b, tb, M.CCDM_LINEAR, CA)
        truth_touch = first_time_within(a, ta, b, tb, 0.0)
        t["fcl_linear"].judge(truth_touch, hit, toc, RESOLUTION + FCL_CA_STEP, seconds=sec,
                              false=false_contact(a, ta, b, tb, hit, toc, cd))

        # Naive sampling with the screw path: late by up to one sample spacing by design.
        hit, toc, _, sec = fcl_query(a, ta, b, tb, M.CCDM_SCREW, SOLVER.CCDC_NAIVE, naive_samples)
        t["fcl_naive"].judge(truth_touch_screw, hit, toc, RESOLUTION + 1.0 / (naive_samples - 1),
                             seconds=sec, false=false_contact(a, sa, b, sb, hit, toc, cd))

        # Polynomial solver: translation only (CCDM_TRANS), on fresh models (it rewrites them).
        pa, pb = translation_only(ta), translation_only(tb)
        fa, fb = FclBody(*scene["meshes"][q.i]), FclBody(*scene["meshes"][q.j])
        hit, toc, _, sec = fcl_query(fa, pa, fb, pb, M.CCDM_TRANS, SOLVER.CCDC_POLYNOMIAL_SOLVER)
        t["fcl_poly"].judge(first_time_within(a, pa, b, pb, 0.0), hit, toc, RESOLUTION, seconds=sec,
                            false=false_contact(a, pa, b, pb, hit, toc, cd))
    return t


def main_line(t):
    f, m = t["fcl"], t["mb"]
    return (f"python-fcl: missed {f.missed}, late {f.late}, ms {f.ms:.2f}; "
            f"motion_bound: missed {m.missed}, late {m.late}, ms {m.ms:.2f}")


def extra_lines(t, naive_samples):
    def line(label, x):
        late = f" (worst {x.worst_late:.3g})" if x.late else ""
        return (f"  {label}: missed {x.missed}, late {x.late}{late}, false {x.false}, "
                f"ms {x.ms:.2f} [{x.contacts} of {x.queries} touch]")

    m = t["mb"]
    return [
        f"  motion_bound: {m.contacts} of {m.queries} come within cd/2; undecided {m.undecided}, "
        f"false {m.false}",
        line("python-fcl conservative advancement, CCDM_SCREW (main line)", t["fcl"]),
        line("python-fcl conservative advancement, CCDM_LINEAR", t["fcl_linear"]),
        line(f"python-fcl naive, {naive_samples} samples, CCDM_SCREW, "
             f"late slack 1/{naive_samples - 1}", t["fcl_naive"]),
        line("python-fcl polynomial solver, CCDM_TRANS (rotation dropped, judged so)",
             t["fcl_poly"]),
    ]


def ray_shooting_status(scene):
    """CCDC_RAY_SHOOTING on one fly-by: FCL 0.7 has no implementation."""
    a = FclBody(*scene["meshes"][0])
    q = scene["flybys"][0]
    hit, toc, ret, _ = fcl_query(a, q.traj_a, a, q.traj_b, M.CCDM_TRANS, SOLVER.CCDC_RAY_SHOOTING)
    return (f"  python-fcl ray shooting: returns {ret:g} (is_collide {hit}, time {toc:g}): "
            "not implemented")


def main(argv=None):
    parser = script_parser(__doc__, 50, "fly-bys per scene", seed_help="seed of the bunny fly-bys")
    parser.add_argument("--naive-samples", type=int, default=100,
                        help="poses the naive solver tests (default 100)")
    parser.add_argument("--no-extras", action="store_true",
                        help="only the main line per scene (python-fcl: conservative "
                        "advancement, screw motion)")
    args = parser.parse_args(argv)
    extras = not args.no_extras
    if extras:
        probe = linear_probe(8)
        found = sorted({round(t, 3) for hit, t in probe if hit})
        print(f"FCL CCDM_LINEAR probe (turn about the body origin; the naive solver must find the "
              f"contact near t = 0.495 every call): found on {sum(h for h, _ in probe)} of "
              f"{len(probe)} calls, at {found}")
    for scene in (knot_scene(args.queries), bunny_scene(args.queries, args.seed)):
        start = time.perf_counter()
        t = run_scene(scene, extras=extras, naive_samples=args.naive_samples)
        print(f"== {scene['name']}: {len(scene['flybys'])} fly-bys, contact distance "
              f"{scene['contact_distance']:g}")
        print(main_line(t))
        if extras:
            for line in extra_lines(t, args.naive_samples):
                print(line)
            print(ray_shooting_status(scene))
        print(f"  ({time.perf_counter() - start:.1f} s with the truth)")
        sys.stdout.flush()


if __name__ == "__main__":
    main()
