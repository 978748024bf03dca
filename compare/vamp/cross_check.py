#!/usr/bin/env python3
"""Cross-check of time_edges' verdicts through VAMP's Python bindings (vamp.panda.validate_motion).

  cross_check.py --scene data/mbm/cage.json --edges EDGES.txt --verdicts VERDICTS.txt [--n 100]

Builds the environment VAMP's own way (vamp.Cuboid / vamp.Cylinder from center + Euler XYZ angles, the
cylinders added with add_capsule, as vamp.problem_dict_to_vamp does), the Euler angles taken from the
JSON's rotation matrix by vamp.transformations.euler_from_matrix (axes 'sxyz': R = Rz(c) Ry(b) Rx(a)).
So it also checks the C++ timer's reading of the rotation (it builds VAMP's Cuboid from the matrix's
columns directly).

The Python binding checks an edge at resolution 1 (eight samples on any edge shorter than 8 rad); the
C++ planner check, validate_motion<Panda, 8, 32>, takes 8 * n samples with n = max(ceil(d / 8 * 32), 1)
(d the edge's length, in f32). Splitting the edge into n equal pieces and calling the binding on each
gives the same sample set (t = k / (8 n), k = 1 .. 8 n), up to f32 rounding of the sample points.
Prints the number of edges compared, the disagreements with the C++ verdicts (1 = in collision), and,
for information, how many single resolution-1 calls on the whole edge disagree.
"""
import argparse
import json
import math

import numpy as np
import vamp
from vamp.transformations import euler_from_matrix


def environment(scene):
    env = vamp.Environment()
    for c in scene["cuboids"]:
        cube = vamp.Cuboid(c["center"], list(euler_from_matrix(np.array(c["rotation"]), "sxyz")),
                           c["half_extents"])
        cube.name = c["name"]
        env.add_cuboid(cube)
    for c in scene["cylinders"]:
        cyl = vamp.Cylinder(c["center"], list(euler_from_matrix(np.array(c["rotation"]), "sxyz")),
                            c["radius"], 2.0 * c["half_length"])
        cyl.name = c["name"]
        env.add_capsule(cyl)
    for c in scene["spheres"]:
        s = vamp.Sphere(c["center"], c["radius"])
        s.name = c["name"]
        env.add_sphere(s)
    return env


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--scene", required=True)
    ap.add_argument("--edges", required=True)
    ap.add_argument("--verdicts", required=True)
    ap.add_argument("--n", type=int, default=100)
    args = ap.parse_args()

    scene = json.load(open(args.scene))
    env = environment(scene)
    edges = [list(map(float, line.split())) for line in open(args.edges)
             if line.strip() and not line.lstrip().startswith("#")][: args.n]
    cpp = [int(line) for line in open(args.verdicts)][: len(edges)]
    resolution = vamp.panda.resolution()

    disagree, disagree_single, colliding = [], 0, 0
    for i, (e, v) in enumerate(zip(edges, cpp)):
        q0 = np.array(e[:7], dtype=np.float32)
        q1 = np.array(e[7:], dtype=np.float32)
        vec = q1 - q0
        d = np.float32(np.sqrt(np.sum(vec * vec, dtype=np.float32)))
        n = max(int(math.ceil(np.float32(d / np.float32(8) * np.float32(resolution)))), 1)
        free = all(
            vamp.panda.validate_motion((q0 + vec * np.float32(k / n)).tolist(),
                                       (q0 + vec * np.float32((k + 1) / n)).tolist(), env)
            for k in range(n))
        ours = 0 if free else 1
        colliding += ours
        if ours != v:
            disagree.append(i)
        single = 0 if vamp.panda.validate_motion(q0.tolist(), q1.tolist(), env) else 1
        disagree_single += single != v

    print(f"python cross-check {scene['set']}: edges {len(edges)}, colliding {colliding}, "
          f"disagreements with time_edges {len(disagree)} {disagree[:10]}; "
          f"(one resolution-1 call per edge instead: {disagree_single} disagreements)")
    raise SystemExit(1 if disagree else 0)


if __name__ == "__main__":
    main()
