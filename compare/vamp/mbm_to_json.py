#!/usr/bin/env python3
"""MotionBenchMaker Panda problems (vamp-planner's problems.tar.bz2) to data/mbm/<set>.json.

Reads the MoveIt scene/request YAML files straight from the tarball (needs only PyYAML), in f64:
  - an object's pose is its `pose` (identity when absent) times `primitive_poses[0]`, as in VAMP's
    resources/problem_tar_to_pkl_json.py; orientations are quaternions stored [x, y, z, w], normalised;
  - "rotation" is the body-to-world matrix, row-major (world = rotation @ local + center);
  - box `dimensions` are full sizes: half_extents = dimensions / 2;
  - cylinder `dimensions` are [height, radius] (shape_msgs/SolidPrimitive), axis = local z:
    half_length = height / 2;
  - start = the seven panda_joint1..7 values of start_state (the fixed fingers dropped),
    goals = [the joint constraints of goal_constraints[0]], ordered panda_joint1..7.

--check PROBLEMS_JSON compares with VAMP's own conversion (resources/panda/problems.json, written by
`python resources/problem_tar_to_pkl_json.py --robot panda`): positions, half extents, radius,
length, start and goals equal; rotation within 1e-12 of Rz(c) Ry(b) Rx(a) for VAMP's
orientation_euler_xyz = (a, b, c).

Usage: mbm_to_json.py --tar .../resources/panda/problems.tar.bz2 --out data/mbm
         [--sets table_pick bookshelf_small cage] [--index 1] [--check .../problems.json]
"""
import argparse
import json
import math
import re
import tarfile
from pathlib import Path

import yaml

try:
    from yaml import CLoader as Loader
except ImportError:  # pragma: no cover
    from yaml import Loader

SOURCE = "vamp-planner 0.6.4 sdist, resources/panda/problems.tar.bz2"
JOINTS = [f"panda_joint{i}" for i in range(1, 8)]


def quat_matrix(q):
    """Rotation matrix of the quaternion [x, y, z, w] (normalised first), f64."""
    x, y, z, w = (float(v) for v in q)
    n = x * x + y * y + z * z + w * w
    s = 2.0 / n
    return [
        [1.0 - s * (y * y + z * z), s * (x * y - z * w), s * (x * z + y * w)],
        [s * (x * y + z * w), 1.0 - s * (x * x + z * z), s * (y * z - x * w)],
        [s * (x * z - y * w), s * (y * z + x * w), 1.0 - s * (x * x + y * y)],
    ]


def matmul(a, b):
    return [[sum(a[i][k] * b[k][j] for k in range(3)) for j in range(3)] for i in range(3)]


def matvec(a, v):
    return [sum(a[i][k] * v[k] for k in range(3)) for i in range(3)]


def pose(p):
    return [float(v) for v in p["position"]], quat_matrix(p["orientation"])


def convert_scene(data):
    cuboids, cylinders, spheres = [], [], []
    for co in data["world"]["collision_objects"]:
        if len(co["primitives"]) != 1 or len(co["primitive_poses"]) != 1:
            raise RuntimeError(f"{co['id']}: expected one primitive")
        if co.get("meshes") or co.get("planes"):
            raise RuntimeError(f"{co['id']}: meshes/planes not handled")
        if "pose" in co:
            bt, br = pose(co["pose"])
        else:
            bt, br = [0.0, 0.0, 0.0], [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]
        pt, pr = pose(co["primitive_poses"][0])
        center = [a + b for a, b in zip(matvec(br, pt), bt)]
        rot = matmul(br, pr)
        prim = co["primitives"][0]
        dims = [float(v) for v in prim["dimensions"]]
        if prim["type"] == "box":
            cuboids.append({"name": co["id"], "center": center, "rotation": rot,
                            "half_extents": [d / 2.0 for d in dims]})
        elif prim["type"] == "cylinder":
            cylinders.append({"name": co["id"], "center": center, "rotation": rot,
                              "radius": dims[1], "half_length": dims[0] / 2.0})
        elif prim["type"] == "sphere":
            spheres.append({"name": co["id"], "center": center, "radius": dims[0]})
        else:
            raise RuntimeError(f"{co['id']}: primitive type {prim['type']}")
    return cuboids, cylinders, spheres


def convert_request(data):
    js = data["start_state"]["joint_state"]
    start = [float(js["position"][js["name"].index(j)]) for j in JOINTS]
    jc = {c["joint_name"]: float(c["position"])
          for c in data["goal_constraints"][0]["joint_constraints"]}
    return start, [[jc[j] for j in JOINTS]]


def dumps(doc):
    """One key per line, one obstacle per line; floats as Python's repr (shortest round trip)."""
    lines = ["{"]
    keys = list(doc)
    for n, k in enumerate(keys):
        v = doc[k]
        end = "," if n + 1 < len(keys) else ""
        if isinstance(v, list) and v and isinstance(v[0], dict):
            lines.append(f" {json.dumps(k)}: [")
            for m, item in enumerate(v):
                lines.append("  " + json.dumps(item) + ("," if m + 1 < len(v) else ""))
            lines.append(" ]" + end)
        else:
            lines.append(f" {json.dumps(k)}: {json.dumps(v)}{end}")
    lines.append("}")
    return "\n".join(lines) + "\n"


def euler_xyz_matrix(e):
    """VAMP's factory: Rz(e[2]) * Ry(e[1]) * Rx(e[0]) (Eigen AngleAxis product), here in f64."""
    a, b, c = e
    ca, sa, cb, sb, cc, sc = math.cos(a), math.sin(a), math.cos(b), math.sin(b), math.cos(c), math.sin(c)
    rz = [[cc, -sc, 0.0], [sc, cc, 0.0], [0.0, 0.0, 1.0]]
    ry = [[cb, 0.0, sb], [0.0, 1.0, 0.0], [-sb, 0.0, cb]]
    rx = [[1.0, 0.0, 0.0], [0.0, ca, -sa], [0.0, sa, ca]]
    return matmul(rz, matmul(ry, rx))


def check(doc, vamp_problem):
    worst = 0.0
    assert doc["start"] == vamp_problem["start"], "start"
    assert doc["goals"] == vamp_problem["goals"], "goals"
    pairs = [("cuboids", "box"), ("cylinders", "cylinder"), ("spheres", "sphere")]
    for ours, theirs in pairs:
        a = sorted(doc[ours], key=lambda o: o["name"])
        b = sorted(vamp_problem[theirs], key=lambda o: o["name"])
        assert [o["name"] for o in a] == [o["name"] for o in b], ours
        for x, y in zip(a, b):
            assert x["center"] == y["position"], (x["name"], "center")
            if ours == "cuboids":
                assert x["half_extents"] == y["half_extents"], x["name"]
            if ours == "cylinders":
                assert x["radius"] == y["radius"] and 2.0 * x["half_length"] == y["length"], x["name"]
            if ours == "spheres":
                assert x["radius"] == y["radius"], x["name"]
                continue
            r = euler_xyz_matrix(y["orientation_euler_xyz"])
            d = max(abs(r[i][j] - x["rotation"][i][j]) for i in range(3) for j in range(3))
            worst = max(worst, d)
    assert worst < 1e-12, worst
    return worst


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--tar", required=True)
    ap.add_argument("--out", required=True)
    ap.add_argument("--sets", nargs="+", default=["table_pick", "bookshelf_small", "cage"])
    ap.add_argument("--index", type=int, default=1)
    ap.add_argument("--check")
    args = ap.parse_args()

    files = {}
    with tarfile.open(args.tar, "r:bz2") as tar:
        for m in tar.getmembers():
            if m.isfile():
                _, problem, filename = m.name.split("/")
                files[(problem.replace("_panda", ""), filename)] = tar.extractfile(m).read()
    vamp_problems = json.load(open(args.check))["problems"] if args.check else None

    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    for s in args.sets:
        indices = sorted(int(re.findall(r"\d+", f)[0]) for (p, f) in files if p == s and "scene" in f)
        idx = args.index
        scene = yaml.load(files[(s, f"scene{idx:04d}.yaml")], Loader=Loader)
        request = yaml.load(files[(s, f"request{idx:04d}.yaml")], Loader=Loader)
        cuboids, cylinders, spheres = convert_scene(scene)
        start, goals = convert_request(request)
        doc = {"set": s, "problem": idx, "source": SOURCE, "start": start, "goals": goals,
               "cuboids": cuboids, "cylinders": cylinders, "spheres": spheres}
        msg = ""
        if vamp_problems is not None:
            vp = next(p for p in vamp_problems[s] if p["index"] == idx)
            msg = f", matches VAMP's problems.json (rotation within {check(doc, vp):.1e}, valid={vp['valid']})"
        (out / f"{s}.json").write_text(dumps(doc))
        print(f"{s}: problem {idx} (indices {indices[0]}..{indices[-1]}), {len(cuboids)} cuboids, "
              f"{len(cylinders)} cylinders, {len(spheres)} spheres{msg}")


if __name__ == "__main__":
    main()
