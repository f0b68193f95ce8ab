#!/usr/bin/env bash
# --scale changes the units and nothing else (docs/scene-format.md, "Importing models": only
# ratios of lengths matter): over the whole documented range, 1e-100 to 1e100, every patch's
# radiosity is that of --scale 1 to 1e-9 (relative to the largest channel of the run), with the
# same iterations and patches. The models cover a bent quad cut along its diagonal, a concave
# pentagon ear-clipped, a degenerate face dropped (room.obj), the Cornell box's bent wall and
# a glTF camera (lamp.gltf). Before the face tests ran in units of the face, a bent quad of
# 1e-88 was cut the other way (the normals' dot product, a length to the fourth power,
# underflowed to 0) and --scale 1e-100 moved the Cornell box's radiosities by 2.4 %.
# At most 20 iterations: the Cornell box's first 20 shots (14 of its 17 patches), room.obj
# and lamp.gltf to convergence (19 and 1 iterations, so their counts are compared too).
# Usage: bash tests/model_scale_test.sh <path-to-simulate-binary> <repo-root>
set -euo pipefail
simulate="$1"
root="${2:-$(cd "$(dirname "$0")/.." && pwd)}"
python=/usr/bin/python3
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
export NCUBE_ROOT="$root"

scales=(1e-100 1e-90 1e-60 1e-30 3e-7 1 7e5 1e30 1e60 1e90 1e100)
models=(cornell-box.obj room.obj lamp.gltf)
# The 33 runs in one batch, each forked from build/simulate_server (tests/forked_batch.py:
# about 85 ms of CPU less a run than a new ./simulate).
for model in "${models[@]}"; do
  for s in "${scales[@]}"; do
    printf '{"args": ["%s", "--scale", "%s", "--iterations", "20", "--quiet", "--json", "%s"], "stdout": null, "stderr": "%s"}\n' \
      "$root/tests/models/$model" "$s" "$work/$model-$s.json" "$work/$model-$s.err"
  done
done > "$work/cases.jsonl"
mapfile -t codes < <("$python" "$root/tests/forked_batch.py" "$simulate" "$work/cases.jsonl")
[ "${#codes[@]}" = $((${#models[@]} * ${#scales[@]})) ] || fail "the batch ran ${#codes[@]} runs"
k=0
for model in "${models[@]}"; do
  for s in "${scales[@]}"; do
    [ "${codes[k]}" = 0 ] || fail "$model --scale $s does not run (exit ${codes[k]}): $(head -c 300 "$work/$model-$s.err")"
    k=$((k + 1))
  done
  "$python" - "$work/$model" "${scales[@]}" <<'PY' || fail "$model: radiosities depend on --scale"
import json, sys
stem, scales = sys.argv[1], sys.argv[2:]
runs = {s: json.load(open(f"{stem}-{s}.json")) for s in scales}
base = runs["1"]
largest = max(c for p in base["patch_radiosity"] for c in p)
assert largest > 0
for s, run in runs.items():
    assert run["iterations"] == base["iterations"], (s, run["iterations"], base["iterations"])
    assert len(run["patch_radiosity"]) == len(base["patch_radiosity"]), s
    worst = max(abs(a - b) for p, q in zip(run["patch_radiosity"], base["patch_radiosity"])
                for a, b in zip(p, q)) / largest
    if worst > 1e-9:
        sys.exit(f"--scale {s}: a radiosity differs from --scale 1 by {worst:.3g} of the largest")
PY
done
echo "ok"
