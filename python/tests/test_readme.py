"""The README's Python example runs as printed."""

import pathlib
import re


def test_the_readme_example_runs():
    text = (pathlib.Path(__file__).parent.parent / "README.md").read_text()
    blocks = re.findall(r"```python\n(.*?)```", text, re.S)
    assert blocks, "the README has a python block"
    exec(compile(blocks[0], "README.md", "exec"), {})


def test_the_root_readme_python_example_runs_and_lands_on_time():
    text = (pathlib.Path(__file__).parent.parent.parent / "README.md").read_text()
    blocks = re.findall(r"```python\n(.*?)```", text, re.S)
    assert blocks, "the root README has a python block"
    scope = {}
    exec(compile(blocks[0], "README.md", "exec"), scope)
    r = scope["r"]
    # The box's bottom (0.5 below its centre, whatever its turn about z) meets the
    # ground when the centre, falling from 2 at 3 per unit time, is at 0.5: t = 0.5.
    assert r.outcome == "contact" and 0.5 - 1e-4 / 3 - 1e-9 <= r.time <= 0.5
