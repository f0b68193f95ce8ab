#!/usr/bin/env bash
# Models in, whole runs: the Cornell box written as OBJ (tests/models/cornell-box.obj, the
# published data) runs as scenes/cornell-box.json does with the same element grids; the
# imported scene exported as JSON (--export-scene) gives the same run again; one scene written
# as glTF and as PLY gives one run; import options on a JSON scene are refused.
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

# Two result files are the same run when they are equal in every field but those that name the
# input (provenance: command_line, scene.file, scene.sha256, scene.parts) and the host's own
# time (host_seconds, different between any two runs): every simulated number, count, element
# radiosity mean and configuration, compared as the text the simulator wrote.
cat > "$work/same_run.py" <<'PY'
import json, sys
def core(path):
    d = json.load(open(path))
    d.pop("host_seconds")
    p = d["provenance"]
    p.pop("command_line")
    for key in ("file", "sha256", "parts"):
        p["scene"].pop(key, None)
    return json.dumps(d, indent=1)
a, b, what = sys.argv[1], sys.argv[2], sys.argv[3]
if core(a) != core(b):
    sys.exit(f"FAIL: {what}: {a} and {b} differ beyond the input's name and hash")
PY
same_run() { "$python" "$work/same_run.py" "$@" || exit 1; }
same_run "$work/obj.json" "$work/exported-run.json" "the exported scene does not give the model's run"
# Beside the grids (set above), cornell-box.json is the generator's own file: its patch order,
# corners, reflectances and emission are what the OBJ gives.
same_run "$work/obj.json" "$work/cornell-run.json" "the Cornell box OBJ does not give scenes/cornell-box.json's run (same grids)"
"$python" - "$work/obj.json" <<'PY' || exit 1
import json, sys
parts = json.load(open(sys.argv[1]))["provenance"]["scene"].get("parts", [])
if [p["file"].rsplit("/", 1)[-1] for p in parts] != ["cornell-box.mtl"]:
    sys.exit(f"FAIL: the OBJ's provenance does not name its MTL: {parts}")
PY

# One scene written by hand as glTF and as PLY with face colours: the same run.
"$simulate" "$root/tests/models/two-quads.gltf" --merge-coplanar "${run[@]}" --json "$work/gltf.json"
"$simulate" "$root/tests/models/two-quads.ply" --light two-quads "${run[@]}" --json "$work/ply.json"
same_run "$work/gltf.json" "$work/ply.json" "two-quads.gltf and two-quads.ply do not give the same run"

for option in "--light white" "--scale 2" "--export-scene $work/x.json" "--flip-faces"; do
  if "$simulate" scene0.json --iterations 1 --quiet $option 2>"$work/err"; then
    fail "$option was taken for a JSON scene"
  fi
  grep -q "apply to model files" "$work/err" || fail "$option: $(cat "$work/err")"
done
echo "PASS: the Cornell box OBJ runs as scenes/cornell-box.json; the exported scene runs the same; two-quads.gltf runs as two-quads.ply"
