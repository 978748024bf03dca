#!/usr/bin/env python3
"""Random planner-sized Panda edges for time_edges / cross_check.py.

  make_edges.py --scene S --n 10000 --seed 1 [--out FILE]

q0 uniform within the Panda's joint limits (VAMP's Panda, resources/panda/panda.urdf of vamp-planner
0.6.4), q1 = q0 + L * u with u a uniformly random unit direction in the 7-D joint space and L uniform in
[0.05, 0.3] rad (Euclidean norm in joint space), then clamped to the limits (so a clamped edge can be
shorter than 0.05). One edge per line: q0[7] then q1[7], 14 numbers printed with full f64 precision.

The edges depend only on --n and --seed (numpy's PCG64 via default_rng(seed)), not on the scene: --scene
(a set name such as cage, or a path to data/mbm/<set>.json) only names the default output,
edges_<set>_<n>_seed<seed>.txt. Needs numpy only.
"""
import argparse
from pathlib import Path

import numpy as np

# VAMP's Panda (vamp-planner 0.6.4, resources/panda/panda.urdf): joint 4 goes up to +0.0873,
# joint 6 from -0.0873 to 3.8223 (vamp/robots/panda.hh has the same values in f32).
LOWER = np.array([-2.9671, -1.8326, -2.9671, -3.1416, -2.9671, -0.0873, -2.9671])
UPPER = np.array([2.9671, 1.8326, 2.9671, 0.0873, 2.9671, 3.8223, 2.9671])
MIN_LEN, MAX_LEN = 0.05, 0.3


def make_edges(n, seed):
    rng = np.random.default_rng(seed)
    q0 = rng.uniform(LOWER, UPPER, size=(n, 7))
    u = rng.standard_normal(size=(n, 7))
    u /= np.linalg.norm(u, axis=1, keepdims=True)
    length = rng.uniform(MIN_LEN, MAX_LEN, size=(n, 1))
    q1 = np.clip(q0 + length * u, LOWER, UPPER)
    return q0, q1


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--scene", required=True, help="set name (cage) or path to data/mbm/<set>.json")
    ap.add_argument("--n", type=int, default=10000)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--out")
    args = ap.parse_args()
    name = Path(args.scene).stem
    out = Path(args.out or f"edges_{name}_{args.n}_seed{args.seed}.txt")
    q0, q1 = make_edges(args.n, args.seed)
    with open(out, "w") as f:
        for a, b in zip(q0, q1):
            f.write(" ".join(repr(float(x)) for x in (*a, *b)) + "\n")
    d = np.linalg.norm(q1 - q0, axis=1)
    print(f"{out}: {args.n} edges, length min {d.min():.4f} mean {d.mean():.4f} max {d.max():.4f} rad, "
          f"{int((d < MIN_LEN).sum())} shorter than {MIN_LEN} after clamping")


if __name__ == "__main__":
    main()
