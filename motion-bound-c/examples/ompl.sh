#!/usr/bin/env bash
# OMPL's RRT-Connect from C++ for the Panda in MotionBenchMaker's three scenes (data/mbm/), with
# motion-bound's certified MotionValidator (examples/ompl/ompl_panda.cpp, through the C ABI) beside
# OMPL's DiscreteMotionValidator at 0.01 and 0.005. Installs Debian's libompl-dev and cmake with
# apt-get when missing, builds the library in release and the example with CMake, writes the
# scenes as plain text and runs it: one line per scene and validator,
#   scene S validator V: solved N of M, median ms X, touching K
# Fails when a path of ours touches an obstacle.
# Usage: motion-bound-c/examples/ompl.sh [plans per scene and validator, default 30]
#        [--build-only] (compile, do not run: CI's step)
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
root="$(cd "$here/.." && pwd)"
plans=30; build_only=0
for a in "$@"; do
  case "$a" in
    --build-only) build_only=1 ;;
    *) plans="$a" ;;
  esac
done
if ! pkg-config --exists ompl 2>/dev/null || ! command -v cmake >/dev/null; then
  sudo_=""; [ "$(id -u)" -ne 0 ] && sudo_="sudo"
  $sudo_ apt-get update -q
  $sudo_ apt-get install -y -q libompl-dev cmake pkg-config g++
fi
cd "$root"
cargo build --release --quiet -p motion-bound-c
target="$(cargo metadata --format-version 1 --no-deps | python3 -c 'import json,sys; print(json.load(sys.stdin)["target_directory"])')"
build="$target/ompl-example"
cmake -S "$here/examples/ompl" -B "$build" -DCMAKE_BUILD_TYPE=Release \
  -DMOTION_BOUND_LIB="$target/release/libmotion_bound_c.a" > /dev/null
cmake --build "$build" -j 2 > /dev/null
[ "$build_only" -eq 1 ] && { echo "built $build/ompl_panda"; exit 0; }

# The scenes as plain text: problem 1 of each file, boxes and cylinders with their poses as
# quaternions (MotionBenchMaker's cylinders lie along their local z, ours along y: turned). The
# cage's Cube1 is the box its goal grasps, which our Panda's fingers (0.04 m open) overlap there:
# left out, as MoveIt's allowed collision matrix lets a hand touch what it grasps (as
# python/examples/ompl_panda.py does).
scenes="$build/scenes"; mkdir -p "$scenes"
python3 - "$root/data/mbm" "$scenes" <<'PY'
import json, math, pathlib, sys
src, out = pathlib.Path(sys.argv[1]), pathlib.Path(sys.argv[2])
def quat(m):
    t = m[0][0] + m[1][1] + m[2][2]
    if t > 0:
        s = math.sqrt(t + 1) * 2
        return (0.25 * s, (m[2][1] - m[1][2]) / s, (m[0][2] - m[2][0]) / s, (m[1][0] - m[0][1]) / s)
    i = max(range(3), key=lambda k: m[k][k]); j, k = (i + 1) % 3, (i + 2) % 3
    s = math.sqrt(1 + m[i][i] - m[j][j] - m[k][k]) * 2
    q = [0.0] * 4
    q[0] = (m[k][j] - m[j][k]) / s; q[1 + i] = 0.25 * s
    q[1 + j] = (m[j][i] + m[i][j]) / s; q[1 + k] = (m[k][i] + m[i][k]) / s
    return tuple(q)
def mul(a, b):
    return [[sum(a[i][k] * b[k][j] for k in range(3)) for j in range(3)] for i in range(3)]
y_to_z = [[1, 0, 0], [0, 0, -1], [0, 1, 0]]
for name in ("table_pick", "bookshelf_small", "cage"):
    d = json.loads((src / f"{name}.json").read_text())
    lines = [f"name {name}", "start " + " ".join(map(repr, d["start"])),
             "goal " + " ".join(map(repr, d["goals"][0]))]
    for c in d["cuboids"]:
        if name == "cage" and c["name"] == "Cube1":
            continue
        p = " ".join(map(repr, list(c["center"]) + list(quat(c["rotation"])) + list(c["half_extents"])))
        lines.append(f"box {c['name']} {p}")
    for c in d["cylinders"]:
        q = quat(mul(c["rotation"], y_to_z))
        p = " ".join(map(repr, list(c["center"]) + list(q) + [c["half_length"], c["radius"]]))
        lines.append(f"cylinder {c['name']} {p}")
    assert not d["spheres"], name
    (out / f"{name}.txt").write_text("\n".join(lines) + "\n")
PY
echo "OMPL $(pkg-config --modversion ompl) RRT-Connect (default range), the Panda (meshes), $plans plans per scene and validator, fine check every 1e-3 rad; CPU: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')"
"$build/ompl_panda" "$root/data/arms/franka_panda/panda.urdf" \
  "$scenes/table_pick.txt" "$scenes/bookshelf_small.txt" "$scenes/cage.txt" --plans "$plans"
