"""The shipped bunny (data/bunny-npm-3674.obj.gz), read without trimesh: its
vertices recentred on their bounding box and scaled to a reach of 0.5."""

import gzip
import pathlib

import numpy as np

DATA = pathlib.Path(__file__).resolve().parents[2] / "data"


def load_bunny(reach=0.5):
    vertices, faces = [], []
    with gzip.open(DATA / "bunny-npm-3674.obj.gz", "rt") as f:
        for line in f:
            parts = line.split()
            if not parts:
                continue
            if parts[0] == "v":
                vertices.append([float(x) for x in parts[1:4]])
            elif parts[0] == "f":
                idx = [int(p.split("/")[0]) - 1 for p in parts[1:]]
                for k in range(1, len(idx) - 1):  # fan polygons into triangles
                    faces.append([idx[0], idx[k], idx[k + 1]])
    v = np.array(vertices, float)
    v -= (v.min(axis=0) + v.max(axis=0)) / 2
    v *= reach / np.max(np.linalg.norm(v, axis=1))
    return v, np.array(faces, np.int64)
