"""The first query of a process is no slower than twice the next (issue 41: "the first mesh
query in a process is about ten times slower than the next"). Each process builds two meshes,
then times the same mesh-against-mesh query twice; the minimum over a few fresh processes of
each is compared, so that one process descheduled on a busy machine does not decide.

Where the time went, measured for this test: nothing in the module is built lazily (a mesh's
ball tree, its hierarchy of pieces included, is built by `mesh`); a µs-scale query (the README's
ball past a tetrahedron, 6 µs warm) takes 20 to 40 µs when first, and as long again whenever
other work (a numpy sort of 4 million numbers) has pushed the query's code and data out of the
caches: cold caches, not first-time work. A mesh query of a realistic size pays that once, well
within the factor of two checked here."""

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
