"""Scale-out as batch users do it (issue 41): the README's Dask recipe, run as printed, maps a
batch of motions over Dask's process scheduler with two worker processes (the bodies, motions
and reports crossing process boundaries by pickle), and its answers are bit-identical to the
same batch asked serially in this process."""

import pathlib
import re

import numpy as np
import pytest

import motion_bound as mb

pytest.importorskip("dask.bag")

FIELDS = ["outcome_codes", "times", "points_a", "points_b", "normals", "distances", "iterations"]


def readme_block(marker):
    text = (pathlib.Path(__file__).parent.parent / "README.md").read_text()
    blocks = [b for b in re.findall(r"```python\n(.*?)```", text, re.S) if marker in b]
    assert len(blocks) == 1, f"the README has one python block with {marker!r}"
    return blocks[0]


def test_the_readme_dask_recipe_matches_the_serial_batch_bit_for_bit():
    scope = {"__name__": "readme_dask"}  # not importable: cloudpickle sends `ask` by value
    exec(compile(readme_block("dask.bag"), "README.md", "exec"), scope)
    reports = scope["reports"]
    assert len(reports) == 8 and all(isinstance(r, mb.BatchReport) for r in reports)
    serial = mb.time_of_impact_batch(scope["ball"],
                                     mb.MotionBatch.between(scope["starts"], scope["ends"]),
                                     scope["tet"], scope["still"], parallel=False)
    assert len(serial) == scope["n"] == sum(len(r) for r in reports)
    hits = int(serial.hits.sum())
    assert 0 < hits < len(serial), f"{hits} hits: the batch must have hits and misses"
    for field in FIELDS:
        got = np.concatenate([getattr(r, field) for r in reports])
        want = getattr(serial, field)
        assert got.dtype == want.dtype and got.shape == want.shape, field
        assert got.tobytes() == want.tobytes(), f"{field} differs from the serial batch"
    assert scope["times"].tobytes() == serial.times.tobytes()
