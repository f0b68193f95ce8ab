#!/usr/bin/env bash
# The prediction sweeps (experiments/predictions/, analysis/predictions.py) validate with
# `experiments/sweep --check` (every cell possible on its platform, no duplicate), and hold the
# cells docs/predictions.md describes: Tables 1-4 with both visibilities, scene4 filling every
# hypercube of 64..8192 nodes, the rendering grid. Nothing is run.
set -euo pipefail
root="$2"
out=$(mktemp)
trap 'rm -f "$out"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

check() {  # file, expected number of cells
  /usr/bin/python3 "$root/experiments/sweep" "$root/experiments/predictions/$1" --check >"$out" 2>&1 \
    || { cat "$out"; fail "$1 does not validate"; }
  head -1 "$out" | grep -q ": $2 cells," || fail "$1: expected $2 cells, got: $(head -1 "$out")"
}
check octree-tables.yaml 62        # (13 scene1 + 13 scene2 + 5 scene3 configurations) x 2
check scene4-hypercubes.yaml 24    # 8 sizes x V in {3, 7, 15}
check render.yaml 24               # 2 scenes x 3 configurations x 2 partitions x 2 distributions

# Every scene4 cell uses all nodes of its platform: R x (V + 1) = 2^d of ncube2-d<d>.json.
/usr/bin/python3 - "$root" <<'PY' || fail "a scene4 cell does not fill its hypercube"
import sys
sys.path.insert(0, sys.argv[1] + "/analysis")
from ncube.sweep import load
sweep = load(sys.argv[1] + "/experiments/predictions/scene4-hypercubes.yaml")
sizes = set()
for cell in sweep.cells:
    assert cell.R * (cell.V + 1) == cell.nodes, (cell.label, cell.nodes)
    sizes.add(cell.nodes)
assert sorted(sizes) == [64 << k for k in range(8)], sorted(sizes)
PY
echo "predictions sweeps: ok"
