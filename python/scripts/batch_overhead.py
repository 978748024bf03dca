"""The binding's overhead: 10,000 motions of a bunny past a still bunny through
`time_of_impact_batch` from Python, against the same batch through the Rust API
(`compare/examples/batch.rs`: `AnyPair` and `time_of_impact`, the calls the
binding makes), serially and on every core, in one sitting.

    python scripts/batch_overhead.py [--queries 10000] [--repeats 3]

Prints, per repeat, both sides' ms per query and the overhead per query, and
checks that both sides found the same contacts at the same times."""

import os
import pathlib
import struct
import subprocess
import sys
import tempfile
import time

import numpy as np

import motion_bound as mb

sys.path.insert(0, str(pathlib.Path(__file__).parent))
from meshes import load_bunny  # noqa: E402

sys.path.insert(0, str(pathlib.Path(__file__).parents[1] / "tests"))
from devkit import cpu_name, random_rotation, script_parser, unit  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parents[2]
CONTACT_DISTANCE = 1e-3


def motions(n, reach, seed):
    """Bunny A from 1.1 to 1.6 reaches away, to a point within 0.8 reach of the
    origin, turning by up to a radian; most touch the still bunny B."""
    rng = np.random.default_rng(seed)
    starts, ends = np.tile(np.eye(4), (n, 1, 1)), np.tile(np.eye(4), (n, 1, 1))
    for i in range(n):
        d, a = unit(rng), unit(rng)
        starts[i, :3, :3] = random_rotation(rng)
        starts[i, :3, 3] = d * 2 * reach * rng.uniform(1.1, 1.6)
        ends[i, :3, 3] = a * 2 * reach * 0.8 * rng.uniform()
        axis = rng.normal(size=3)
        axis *= rng.uniform(0, 1.0) / np.linalg.norm(axis)
        k = np.array([[0, -axis[2], axis[1]], [axis[2], 0, -axis[0]], [-axis[1], axis[0], 0]])
        theta = np.linalg.norm(axis)
        turn = np.eye(3) if theta == 0 else np.eye(3) + np.sin(theta) / theta * k + (1 - np.cos(theta)) / theta**2 * (k @ k)
        ends[i, :3, :3] = turn @ starts[i, :3, :3]
    return starts, ends


def write(path, v, f, starts, ends):
    with open(path, "wb") as out:
        out.write(struct.pack("<QQQd", len(v), len(f), len(starts), CONTACT_DISTANCE))
        out.write(np.ascontiguousarray(v, "<f8").tobytes())
        out.write(np.ascontiguousarray(f, "<u4").tobytes())
        out.write(np.ascontiguousarray(starts, "<f8").tobytes())
        out.write(np.ascontiguousarray(ends, "<f8").tobytes())


def main():
    p = script_parser(__doc__, 10_000, "motions", seed_help="seed of the motions")
    p.add_argument("--repeats", type=int, default=3, help="repeats of the batch (default 3)")
    args = p.parse_args()
    v, f = load_bunny()
    starts, ends = motions(args.queries, 0.5, args.seed)
    bunny = mb.mesh(v, f)
    still = mb.Motion.still(np.eye(4))
    batch = mb.MotionBatch.between(starts, ends)
    print(f"bunny {len(f)} triangles, {args.queries} motions, contact distance {CONTACT_DISTANCE}; CPU {cpu_name()}, {os.cpu_count()} cores")
    with tempfile.TemporaryDirectory() as tmp:
        path = pathlib.Path(tmp) / "batch.bin"
        write(path, v, f, starts, ends)
        cmd = ["cargo", "run", "--release", "--quiet", "-p", "motion-bound-compare", "--example", "batch", "--", str(path)]
        subprocess.run(cmd + ["0"], cwd=ROOT, check=True)  # build first, outside the timing
        for r in range(args.repeats):
            out = {}
            for parallel in (False, True):
                t = time.perf_counter()
                rep = mb.time_of_impact_batch(bunny, batch, bunny, still, contact_distance=CONTACT_DISTANCE, parallel=parallel)
                out[parallel] = (time.perf_counter() - t) * 1e3 / args.queries
            hits = int(rep.hits.sum())
            times = float(np.nansum(rep.times))
            rust = subprocess.run(cmd + ["1"], cwd=ROOT, check=True, capture_output=True, text=True).stdout.strip()
            fields = dict(x.strip().rsplit(" ", 1) for x in rust.split(":", 1)[1].split(","))
            rs, rp = float(fields["serial ms"]), float(fields["parallel ms"])
            same = int(fields["hits"]) == hits and abs(float(fields["sum of times"]) - times) <= 1e-9 * max(1.0, times)
            print(f"repeat {r + 1}: python serial ms {out[False]:.5f}, rust serial ms {rs:.5f}, overhead us per query {1e3 * (out[False] - rs):.2f}; "
                  f"python parallel ms {out[True]:.5f}, rust parallel ms {rp:.5f}; hits {hits}, same answers {same}")
            if not same:
                print("rust:", rust)
                sys.exit("the two sides disagree")


if __name__ == "__main__":
    main()
