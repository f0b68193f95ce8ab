#!/usr/bin/env bash
# The prediction sweeps (experiments/predictions/, analysis/predictions.py) validate with
# `experiments/sweep --check` (every cell possible on its platform, no duplicate), and hold the
# cells docs/predictions.md describes: Tables 1-4 with both visibilities, scene4 filling every
# hypercube of 64..8192 nodes, the rendering grid. Nothing is run. One Python for all of it: the
# sweep tool's own entry (ncube.runner.main, what experiments/sweep calls) checks the three files
# at once, and scene4's cells are loaded again in the same process (each platform asked of
# ./simulate once).
set -euo pipefail
root="$2"
NCUBE_SIMULATE="$1" exec /usr/bin/python3 - "$root" <<'PY'
import contextlib
import io
import sys

sys.path.insert(0, sys.argv[1] + "/analysis")
from ncube import runner
from ncube.sweep import load

folder = sys.argv[1] + "/experiments/predictions/"
expected = {"octree-tables": 62,       # (13 scene1 + 13 scene2 + 5 scene3 configurations) x 2
            "scene4-hypercubes": 24,   # 8 sizes x V in {3, 7, 15}
            "render": 24}              # 2 scenes x 3 configurations x 2 partitions x 2 distributions
out, err = io.StringIO(), io.StringIO()
with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
    code = runner.main([folder + name + ".yaml" for name in expected] + ["--check"])
if code != 0:
    sys.exit(f"FAIL: the prediction sweeps do not validate (exit {code}): {err.getvalue()}")
headers = [line for line in out.getvalue().splitlines() if not line.startswith(" ")]
for name, cells in expected.items():
    if not any(line.startswith(f"{name}: {cells} cells,") for line in headers):
        sys.exit(f"FAIL: {name}: expected {cells} cells, got: {headers}")

# Every scene4 cell uses all nodes of its platform: R x (V + 1) = 2^d of ncube2-d<d>.json.
sweep = load(folder + "scene4-hypercubes.yaml")
sizes = set()
for cell in sweep.cells:
    if cell.R * (cell.V + 1) != cell.nodes:
        sys.exit(f"FAIL: a scene4 cell does not fill its hypercube: {cell.label}, {cell.nodes} nodes")
    sizes.add(cell.nodes)
if sorted(sizes) != [64 << k for k in range(8)]:
    sys.exit(f"FAIL: scene4's hypercubes: {sorted(sizes)}")
print("predictions sweeps: ok")
PY
