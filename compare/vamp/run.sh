#!/bin/bash
# VAMP's edge check on the three MotionBenchMaker scenes of data/mbm/, on one core, then the Python
# cross-check of the first 100 verdicts. After build.sh. Paths (optional):
#   WORK   where build.sh put time_edges; edges and verdicts go to $WORK/edges   (default /work/vamp-work)
#   VENV   the virtual environment with vamp                                     (default /work/venv-vamp)
#   EDGES  an edges file to use for every scene instead of generating one per scene (make_edges.py
#          --n $N --seed $SEED: the same edges for every scene)
#   N, SEED, CPU (the core given to taskset)                                     (10000, 1, 1)
set -euo pipefail
HERE="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
DATA="$HERE/../../data/mbm"
WORK="${WORK:-/work/vamp-work}"
VENV="${VENV:-/work/venv-vamp}"
N="${N:-10000}"
SEED="${SEED:-1}"
CPU="${CPU:-1}"
mkdir -p "$WORK/edges"
grep -m1 'model name' /proc/cpuinfo
for s in table_pick bookshelf_small cage; do
  edges="${EDGES:-$WORK/edges/$s.txt}"
  if [ -z "${EDGES:-}" ]; then
    "$VENV/bin/python" "$HERE/make_edges.py" --scene "$s" --n "$N" --seed "$SEED" --out "$edges" > /dev/null
  fi
  taskset -c "$CPU" "$WORK/time_edges" "$DATA/$s.json" "$edges" \
    --verdicts "$WORK/edges/$s.verdicts" --self-verdicts "$WORK/edges/$s.self"
  "$VENV/bin/python" "$HERE/cross_check.py" --scene "$DATA/$s.json" --edges "$edges" \
    --verdicts "$WORK/edges/$s.verdicts" --n 100
done
