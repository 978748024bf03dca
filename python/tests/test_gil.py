"""The GIL is released while a query runs: another Python thread keeps running
during a long batch (were it held, the other thread could not run at all until
the call returned)."""

import threading
import time

import numpy as np

import motion_bound as mb
from test_truth import icosphere


def test_another_thread_runs_during_a_batch():
    v, f = icosphere(0.5, 3)
    body = mb.mesh(v, f)
    n = 400
    starts = np.tile(np.eye(4), (n, 1, 1))
    starts[:, 0, 3] = -2.0
    starts[:, 1, 3] = np.linspace(-0.9, 0.9, n)
    batch = mb.MotionBatch(starts, np.tile([4.0, 0.0, 0.0], (n, 1)), np.tile([0.0, 3.0, 1.0], (n, 1)))
    still = mb.Motion.still(np.eye(4))
    inside = {}

    def run():
        t = time.perf_counter()
        inside["report"] = mb.time_of_impact_batch(body, batch, body, still, parallel=False)
        inside["seconds"] = time.perf_counter() - t

    worker = threading.Thread(target=run)
    ticks = 0
    worker.start()
    time.sleep(0.01)  # let the worker enter the call
    while worker.is_alive():
        ticks += 1
        time.sleep(0.001)
    worker.join()
    assert inside["report"].hits.sum() > 0
    # The batch must take long enough to tell, and the main thread must have run
    # through most of it (at least a tick per 5 ms, far below its 1 ms sleep).
    assert inside["seconds"] > 0.1, inside["seconds"]
    assert ticks >= inside["seconds"] / 0.005, (ticks, inside["seconds"])
