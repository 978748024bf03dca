"""A batch shows its progress and honours Ctrl-C (issue 41): it runs in chunks of about 20 ms
with the GIL released, and between chunks the calling thread runs Python's signal handlers and
the `progress(done, total)` callback. Ctrl-C (a SIGINT sent by a timer thread, as the terminal
sends it) must stop a 40,000-query batch with `KeyboardInterrupt` within a tenth of a second;
the callback must see increasing counts, from the calling thread, ending at the total; and the
chunks must change no answer (each query against its own `time_of_impact`)."""

import os
import signal
import threading
import time

import numpy as np
import pytest

import motion_bound as mb
from test_truth import icosphere


def fly_bys(n):
    """`n` turning fly-bys past a body at the origin, offsets spread across it (about half hit)."""
    starts = np.tile(np.eye(4), (n, 1, 1))
    starts[:, 0, 3] = -2.0
    starts[:, 1, 3] = np.linspace(-0.9, 0.9, n)
    return mb.MotionBatch(starts, np.tile([4.0, 0.0, 0.0], (n, 1)), np.tile([0.0, 3.0, 1.0], (n, 1)))


STILL = mb.Motion.still(np.eye(4))


@pytest.mark.parametrize("parallel", [True, False])
def test_progress_counts_up_to_the_total_and_the_chunks_change_no_answer(parallel):
    sphere = mb.mesh(*icosphere(0.5, 2))
    ball = mb.ball(0.1)
    n = 3000
    batch = fly_bys(n)
    calls = []
    me = threading.get_ident()

    def progress(done, total):
        calls.append((done, total, threading.get_ident()))

    out = mb.time_of_impact_batch(ball, batch, sphere, STILL, parallel=parallel, progress=progress)
    assert calls, "progress was never called"
    assert all(total == n for _, total, _ in calls), calls[:3]
    assert all(thread == me for _, _, thread in calls), "progress called from another thread"
    done = [d for d, _, _ in calls]
    assert all(a < b for a, b in zip(done, done[1:])), done
    assert done[-1] == n, done[-3:]
    assert out.hits.sum() > 0 and (~out.hits).sum() > 0, "the batch must have hits and misses"
    for i in range(n):
        assert out[i] == mb.time_of_impact(ball, batch[i], sphere, STILL), i


def test_an_exception_in_progress_stops_the_batch():
    sphere = mb.mesh(*icosphere(0.5, 2))
    calls = []

    def progress(done, total):
        calls.append(done)
        raise RuntimeError("stop here")

    with pytest.raises(RuntimeError, match="stop here"):
        mb.time_of_impact_batch(mb.ball(0.1), fly_bys(3000), sphere, STILL, progress=progress)
    assert len(calls) == 1
    with pytest.raises(TypeError, match="progress"):
        mb.time_of_impact_batch(mb.ball(0.1), fly_bys(10), sphere, STILL, progress=3)


def test_ctrl_c_stops_a_40000_query_batch_within_a_tenth_of_a_second():
    sphere = mb.mesh(*icosphere(0.5, 3))
    n = 40_000
    batch = fly_bys(n)
    sent = {}
    done = [0]

    def interrupt():
        sent["at"] = time.perf_counter()
        os.kill(os.getpid(), signal.SIGINT)

    previous = signal.signal(signal.SIGINT, signal.default_int_handler)
    timer = threading.Timer(0.3, interrupt)
    try:
        start = time.perf_counter()
        timer.start()
        with pytest.raises(KeyboardInterrupt):
            mb.time_of_impact_batch(sphere, batch, sphere, STILL,
                                    progress=lambda d, t: done.__setitem__(0, d))
        caught = time.perf_counter()
    finally:
        timer.cancel()
        signal.signal(signal.SIGINT, previous)
    assert "at" in sent, "the batch ended before the signal was sent"
    delay = caught - sent["at"]
    print(f"Ctrl-C after {sent['at'] - start:.3f} s, {done[0]} of {n} queries done; "
          f"KeyboardInterrupt {delay * 1e3:.1f} ms after the signal")
    assert 0 < done[0] < n, done[0]
    assert delay < 0.1, f"KeyboardInterrupt {delay:.3f} s after SIGINT"
