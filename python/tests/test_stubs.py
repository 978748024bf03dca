"""The type stubs and the module agree: every name the stubs declare exists,
with the same members, and every public name of the module is declared."""

import ast
import pathlib

import motion_bound as mb

STUBS = pathlib.Path(__file__).parent.parent / "motion_bound.pyi"


def declared():
    tree = ast.parse(STUBS.read_text())
    out = {}
    for node in tree.body:
        if isinstance(node, ast.ClassDef):
            out[node.name] = {n.name for n in node.body if isinstance(n, ast.FunctionDef)} | {
                t.id for n in node.body if isinstance(n, ast.AnnAssign) for t in [n.target]}
        elif isinstance(node, ast.FunctionDef):
            out[node.name] = set()
    return out


def test_stubs_match_the_module():
    stubs = declared()
    for name, members in stubs.items():
        assert hasattr(mb, name), f"{name} is in the stubs, not in the module"
        for m in members - {"__init__"}:
            assert hasattr(getattr(mb, name), m), f"{name}.{m} is in the stubs, not in the module"
    public = {n for n in dir(mb) if not n.startswith("_")} - {"motion_bound"}
    assert public <= set(stubs), f"not in the stubs: {sorted(public - set(stubs))}"


def test_help_shows_the_docs():
    assert "never later" in mb.time_of_impact.__doc__
    assert "4x4" in mb.Pose.__doc__
