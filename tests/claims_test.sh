#!/usr/bin/env bash
# analysis/claims.py (docs/accuracy.md, "The study") on a two-cell sweep of the Cornell box:
# its table's errors are analysis/ncube/accuracy.py's on the cells' meshes, a second run reuses
# the cells, a scene without a reference is one line and exit 1. About 10 s.
set -u
simulate=$1 root=$2
scratch=$(mktemp -d) && trap 'rm -rf "$scratch"' EXIT
export NCUBE_SIMULATE=$simulate
cat > "$scratch/accuracy-test.yaml" <<'YAML'
name: claims-test
measure: total_seconds
options: {R: 2, V: 1}
grid:
  scene: [cornell-box]
  samples: [1, 4]
YAML
failed=0
fail() { echo "FAIL: $*"; failed=1; }
run() {
  /usr/bin/python3 "$root/analysis/claims.py" --results "$scratch/results" --sweeps "$@" \
    --out "$scratch/claims.md" --figure "$scratch/claims.png"
}
run "$scratch/accuracy-test.yaml" > "$scratch/out" 2>&1 || fail "claims.py: $(cat "$scratch/out")"
[[ -s $scratch/claims.png ]] || fail "no figure"
/usr/bin/python3 - "$root" "$scratch" <<'PY' || failed=1
import re, sys
from pathlib import Path
root, scratch = Path(sys.argv[1]), Path(sys.argv[2])
sys.path.insert(0, str(root / "analysis"))
from ncube import accuracy
meshes = sorted((scratch / "results/claims/cells").glob("cornell-box-R2-V1-*.ply"))
rows = [l for l in (scratch / "claims.md").read_text().splitlines()
        if l.startswith("| ray-traced, R=2 V=1 |")]
problems = []
if len(meshes) != 2 or len(rows) != 2:
    problems.append(f"{len(meshes)} meshes, {len(rows)} rows")
expected = sorted("%.3f %.3f %.3f" % (r["element_rms"], r["patch_rms"], r["patch_max"])
                  for r in (accuracy.accuracy(m, root / "analysis/reference/cornell-box.json")
                            for m in meshes))
shown = sorted(" ".join(re.findall(r"\| ([0-9.]+) ", row + " ")[-3:]) for row in rows)
if expected != shown:
    problems.append(f"table {shown}, accuracy.py {expected}")
for p in problems:
    print("FAIL:", p)
sys.exit(1 if problems else 0)
PY
before=$(stat -c %i "$scratch"/results/claims/cells/*.ply | sort | tr '\n' ' ')
run "$scratch/accuracy-test.yaml" > "$scratch/out" 2>&1 || fail "second run: $(cat "$scratch/out")"
after=$(stat -c %i "$scratch"/results/claims/cells/*.ply | sort | tr '\n' ' ')
[[ $before == "$after" ]] || fail "the second run ran the cells again"
sed 's/cornell-box/scene1/; s/samples: \[1, 4\]/samples: [1]/; s/R: 2, V: 1/R: 1, V: 0/' \
  "$scratch/accuracy-test.yaml" > "$scratch/accuracy-scene1.yaml"
run "$scratch/accuracy-scene1.yaml" > "$scratch/out" 2> "$scratch/err"
rc=$?
[[ $rc != 0 && $(wc -l < "$scratch/err") == 1 && $(cat "$scratch/err") == *"no reference for scene1"* ]] ||
  fail "scene1 without a reference: exit $rc, $(cat "$scratch/err")"
[[ $failed == 0 ]] && echo "claims_test: passed"
exit $failed
