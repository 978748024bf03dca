"""The first query of a process is no slower than twice the next (issue 41: "the first mesh
query in a process is about ten times slower than the next"). Each process builds two meshes,
then times the same mesh-against-mesh query twice; the minimum over a few fresh processes of
each is compared, so that one process descheduled on a busy machine does not decide.

Where the ten times went, measured for this test: nothing in the module or the crate is built
lazily (a mesh's ball tree, its hierarchy of pieces included, is built by `mesh`; no OnceCell,
no cache), and a query starts no thread. A µs-scale query (the README's ball past a tetrahedron,
6 µs warm) took 25 to 50 µs when first in its process, and 32 to 80 µs again, after it had run,
once a numpy sort of 4 million numbers had pushed the query's code and data out of the caches:
cold caches, not first-time work. Running tiny queries at import changed nothing measurable
(the user's own numpy work evicts them again), so there is none. A mesh query of a realistic
size (0.3 to 1 ms) pays those tens of µs once: 1.2 to 1.4 times the second, within the factor
of two checked here."""

import subprocess
import sys

PROGRAM = r"""
import sys, time
sys.path.insert(0, sys.argv[1])
import numpy as np
import motion_bound as mb
from test_truth import icosphere
a = mb.mesh(*icosphere(0.5, 3))
b = mb.mesh(*icosphere(0.4, 2))
start, end = np.eye(4), np.eye(4)
start[:3, 3], end[:3, 3] = [-2.0, 0.3, 0.1], [2.0, 0.3, 0.1]
moving, still = mb.Motion(start, [4.0, 0.0, 0.0], [0.0, 3.0, 1.0]), mb.Motion.still(np.eye(4))
times = []
for _ in range(2):
    t = time.perf_counter()
    r = mb.time_of_impact(a, moving, b, still)
    times.append(time.perf_counter() - t)
assert r.outcome == "contact", r
print(times[0], times[1])
"""


def test_the_first_query_takes_at_most_twice_the_second():
    here = __import__("pathlib").Path(__file__).parent
    firsts, seconds = [], []
    for _ in range(5):
        out = subprocess.run([sys.executable, "-c", PROGRAM, str(here)], capture_output=True,
                             text=True, check=True).stdout.split()
        firsts.append(float(out[0]))
        seconds.append(float(out[1]))
    first, second = min(firsts), min(seconds)
    print(f"first query {first * 1e3:.3f} ms, second {second * 1e3:.3f} ms (min of 5 processes)")
    assert first <= 2 * second, (firsts, seconds)
