"""What the Python scripts and tests share, written once (the Python side of the workspace's
devkit/ crate): draws from numpy's seeded generator (`unit`, `random_rotation`), the
processor's name, and the scripts' command-line parser. It needs numpy alone, so that a script
that judges nothing by python-fcl does not need python-fcl (truth.py does)."""

import argparse

import numpy as np


def unit(rng):
    """A uniformly random unit vector (a normalised Gaussian triple)."""
    d = rng.normal(size=3)
    return d / np.linalg.norm(d)


def random_rotation(rng):
    """A uniformly random rotation matrix (a normalised Gaussian quaternion)."""
    q = rng.normal(size=4)
    w, x, y, z = q / np.linalg.norm(q)
    return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
                     [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
                     [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]])


def cpu_name():
    """The processor's name: the first `model name` line of /proc/cpuinfo, or "unknown CPU"
    where there is none (other systems, some ARM kernels)."""
    try:
        with open("/proc/cpuinfo") as info:
            for line in info:
                if line.startswith("model name"):
                    return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return "unknown CPU"


def script_parser(doc, queries, queries_help, seed=7, seed_help="seed of the random draws"):
    """An argument parser for a script whose docstring is `doc` (its first paragraph the
    description) with the flags the scripts share: --queries (default `queries`) and --seed
    (default `seed`); the script adds its own."""
    parser = argparse.ArgumentParser(description=doc.split("\n\n")[0])
    parser.add_argument("--queries", type=int, default=queries,
                        help=f"{queries_help} (default {queries})")
    parser.add_argument("--seed", type=int, default=seed, help=f"{seed_help} (default {seed})")
    return parser
