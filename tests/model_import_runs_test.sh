#!/usr/bin/env bash
# Models in, whole runs: the Cornell box written as OBJ (tests/models/cornell-box.obj, the
# published data) runs as scenes/cornell-box.json does with the same element grids; the
# imported scene exported as JSON (--export-scene) gives the same run again; import options
# on a JSON scene are refused.
# Usage: bash tests/model_import_runs_test.sh <path-to-simulate-binary> <repo-root>
set -euo pipefail
simulate="$1"
root="${2:-$(cd "$(dirname "$0")/.." && pwd)}"
python=/usr/bin/python3
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
export NCUBE_ROOT="$root"

run=(--R 2 --V 1 --iterations 20 --quiet)
"$simulate" "$root/tests/models/cornell-box.obj" "${run[@]}" --json "$work/obj.json" \
  --export-scene "$work/exported.json" || fail "the Cornell box OBJ does not run"
"$simulate" "$work/exported.json" "${run[@]}" --json "$work/exported-run.json"
# The Cornell box scene with the importer's element grids (the OBJ has none of its own).
"$python" - "$root/scenes/cornell-box.json" "$work/exported.json" "$work/cornell.json" <<'PY'
import json, sys
cornell, exported = json.load(open(sys.argv[1])), json.load(open(sys.argv[2]))
for a, b in zip(cornell["patches"], exported["patches"]):
    a["elements"] = b["elements"]
json.dump(cornell, open(sys.argv[3], "w"))
PY
"$simulate" "$work/cornell.json" "${run[@]}" --json "$work/cornell-run.json"

"$python" - "$work/obj.json" "$work/exported-run.json" "$work/cornell-run.json" <<'PY' || exit 1
import json, sys
def core(path):
    d = json.load(open(path))
    return {k: d[k] for k in ("patch_radiosity", "counts", "simulated_seconds", "iteration_seconds",
                              "shooters", "elements_at_end", "iterations")}
obj, exported, cornell = (core(p) for p in sys.argv[1:4])
if obj != exported:
    sys.exit("FAIL: the exported scene does not give the model's run")
if obj != cornell:
    sys.exit("FAIL: the Cornell box OBJ does not give scenes/cornell-box.json's run (same grids)")
PY

for option in "--light white" "--scale 2" "--export-scene $work/x.json" "--flip-faces"; do
  if "$simulate" scene0.json --iterations 1 --quiet $option 2>"$work/err"; then
    fail "$option was taken for a JSON scene"
  fi
  grep -q "apply to model files" "$work/err" || fail "$option: $(cat "$work/err")"
done
echo "PASS: the Cornell box OBJ runs as scenes/cornell-box.json; the exported scene runs the same"
