"""`examples/tutorial.py` runs, prints each of its parts, and its printed times agree with the
closed forms it prints beside them."""

import pathlib
import re
import subprocess
import sys
import time

TUTORIAL = pathlib.Path(__file__).parent.parent / "examples" / "tutorial.py"


def test_the_tutorial_runs_in_a_few_seconds():
    began = time.monotonic()
    out = subprocess.run([sys.executable, str(TUTORIAL)], capture_output=True, text=True,
                         timeout=120, check=True).stdout
    assert time.monotonic() - began < 30
    for part in ("1. ", "2. ", "3. ", "4. ", "5. "):
        assert part in out, out
    # Each "at t = X (closed form Y" pair: never later than the closed form, and close to it
    # (within the tessellation's gap for the mesh).
    pairs = re.findall(r"t = ([0-9.]+) \(closed form ([0-9.]+)", out)
    assert len(pairs) >= 2, out
    for got, want in pairs:
        assert abs(float(got) - float(want)) < 2e-3, (got, want)
