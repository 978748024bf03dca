#!/bin/bash
# Builds vamp-planner 0.6.4 from its sdist with local copies of its four GitHub dependencies and CPM.cmake
# (the recipe of ../shared/anchors/vamp/README.md), installs it into a virtual environment, converts the
# MotionBenchMaker problems, and compiles time_edges. Not part of CI. Paths (all optional):
#   WORK  scratch folder: sdist, deps/, build/, time_edges      (default /work/vamp-work)
#   VENV  virtual environment, created if missing               (default /work/venv-vamp)
#   BARE  folder of bare clones; each repository is looked up as $BARE/<owner>+<name>/repo or
#         $BARE/<name>.git and cloned (git clone --bare https://github.com/<owner>/<name>) if neither exists
#                                                               (default $WORK/bare)
#   JOBS  parallel compile jobs                                 (default 2)
# Needs: python3 (3.9+), g++ with AVX2, git, network access to PyPI (and to GitHub unless BARE holds the
# clones), Eigen 3 headers (apt-get install -y libeigen3-dev).
set -euo pipefail
HERE="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
WORK="${WORK:-/work/vamp-work}"
VENV="${VENV:-/work/venv-vamp}"
BARE="${BARE:-$WORK/bare}"
JOBS="${JOBS:-2}"
SDIST_SHA256=d3150c6b67ff941af9ad56480b31d3fb73b12211ea21dc684f7737b059f6daba
CPM_SHA256=117cbf2711572f113bab262933eb5187b08cfc06dce0714a1ee94f2183ddc3ec
SRC="$WORK/vamp_planner-0.6.4"
DEPS="$WORK/deps"
BUILD="$WORK/build"
mkdir -p "$WORK" "$BARE"

test -f /usr/include/eigen3/Eigen/Dense || { echo "Eigen 3 missing: apt-get install -y libeigen3-dev"; exit 1; }

# 1. virtual environment with the build requirements (the sdist asks for scikit-build-core, nanobind,
#    cmake, typing_extensions; ninja and numpy for the build and the module; the rest for VAMP's scripts)
if [ ! -x "$VENV/bin/python" ]; then
  python3 -m venv "$VENV"
fi
"$VENV/bin/pip" install -q cmake ninja scikit-build-core typing_extensions numpy nanobind \
  fire tqdm pyyaml pandas tabulate

# 2. the sdist (--no-build-isolation: otherwise pip builds cmake itself from source to read the metadata)
if [ ! -f "$WORK/vamp_planner-0.6.4.tar.gz" ]; then
  (cd "$WORK" && "$VENV/bin/pip" download vamp-planner==0.6.4 --no-deps --no-binary :all: --no-build-isolation)
fi
echo "$SDIST_SHA256  $WORK/vamp_planner-0.6.4.tar.gz" | sha256sum -c -
rm -rf "$SRC" && tar -xzf "$WORK/vamp_planner-0.6.4.tar.gz" -C "$WORK"

# 3. the dependencies at the commits the sdist's cmake/Dependencies.cmake names
bare() {  # owner name -> path of a bare clone
  local owner=$1 name=$2
  if [ -d "$BARE/$owner+$name/repo" ]; then echo "$BARE/$owner+$name/repo"; return; fi
  if [ ! -d "$BARE/$name.git" ]; then
    git clone -q --bare "https://github.com/$owner/$name" "$BARE/$name.git" >&2
  fi
  echo "$BARE/$name.git"
}
unpack() {  # owner name commit destination [paths...]
  local repo; repo=$(bare "$1" "$2")
  mkdir -p "$4"
  git -C "$repo" archive "$3" "${@:5}" | tar -x -C "$4"
}
rm -rf "$DEPS" && mkdir -p "$DEPS"
unpack KavrakiLab nigh 97130999440647c204e0265d05a997dbd8da4e70 "$DEPS/nigh" LICENSE README.md src demo
unpack orlp pdqsort b1ef26a55cdb60d236a5cb199c4234c704f46726 "$DEPS/pdqsort"
unpack lemire SIMDxorshift 857c1a01df53cf1ee1ae8db3238f0ef42ef8e490 "$DEPS/SIMDxorshift"
unpack wjakob nanobind 9a25aed8a7edfe60ef9ad1c911e57667bc4916c4 "$DEPS/nanobind"
unpack Tessil robin-map 4ec1bf19c6a96125ea22062f38c2cf5b958e448e "$DEPS/nanobind/ext/robin_map"
git -C "$(bare cpm-cmake CPM.cmake)" show v0.40.1:cmake/CPM.cmake \
  | sed 's/1.0.0-development-version/0.40.1/' > "$DEPS/CPM_0.40.1.cmake"
echo "$CPM_SHA256  $DEPS/CPM_0.40.1.cmake" | sha256sum -c -

# 4. build and install the Python module (as the anchor's build.sh: CPM.cmake placed where CMake would
#    download it, each CPMAddPackage pointed at its local copy; only the sphere and panda robots)
ROBOTS="${ROBOTS:-sphere;panda}"
STRUCTS="${STRUCTS:-Sphere;Panda}"
mkdir -p "$BUILD/cmake"
cp "$DEPS/CPM_0.40.1.cmake" "$BUILD/cmake/CPM.cmake"
(cd "$SRC" && CMAKE_BUILD_PARALLEL_LEVEL=$JOBS nice -n 10 "$VENV/bin/pip" install -q --no-build-isolation \
  --no-deps --no-index . \
  -C build-dir="$BUILD" \
  -C cmake.define.CPM_nigh_SOURCE="$DEPS/nigh" \
  -C cmake.define.CPM_pdqsort_SOURCE="$DEPS/pdqsort" \
  -C cmake.define.CPM_SIMDxorshift_SOURCE="$DEPS/SIMDxorshift" \
  -C cmake.define.CPM_nanobind_SOURCE="$DEPS/nanobind" \
  -C "cmake.define.VAMP_ROBOT_MODULES=$ROBOTS" \
  -C "cmake.define.VAMP_ROBOT_STRUCTS=$STRUCTS")
"$VENV/bin/python" -c "import vamp; print('vamp.panda resolution, spheres:', vamp.panda.resolution(), vamp.panda.n_spheres())"

# 5. VAMP's own conversion of the problems (resources/panda/problems.{pkl,json}), used by
#    scripts/evaluate_mbm.py and by mbm_to_json.py --check
(cd "$SRC" && "$VENV/bin/python" resources/problem_tar_to_pkl_json.py --robot panda > /dev/null 2>&1)

# 6. the timer, with the sdist's release flags (cmake/CompilerSettings.cmake on x86_64)
VAMP_FLAGS="-O3 -march=native -mavx2 -fno-math-errno -fno-signed-zeros -fno-trapping-math -fno-rounding-math \
-ffp-contract=fast -fassociative-math"
# shellcheck disable=SC2086
g++ -std=c++17 $VAMP_FLAGS -DNDEBUG -Wall -Wextra -Wno-ignored-attributes \
  -I"$SRC/src/impl" -I"$DEPS/pdqsort" -isystem /usr/include/eigen3 \
  "$HERE/time_edges.cpp" -o "$WORK/time_edges"
echo "built $WORK/time_edges"
