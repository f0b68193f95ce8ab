#!/usr/bin/env bash
# --parallelisation shooters with --form-factors hemicube (docs/model.md, "The shooter-centred
# scheme"): every node holds the whole scene, so its hemicube draws every other patch's
# elements as occluders, as the paper's program at R = 1 does. With one node and one shooter
# an iteration the two give every element's raw radiosity in the --mesh PLY byte for byte and
# the same hemicube counts; the hemicube's buffers count in a node's memory (exit 3 where
# they do not fit beside the scene); one hemicube per shot at R = 4, both placements, either
# back-face choice (below).
# Called by ctest as: shooters_hemicube_test.sh SIMULATE REPO_ROOT
set -u
simulate="$1"
root="$2"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
scene0="$root/scenes/scene0.json"

# Every run is made first, in one batch, each forked from build/simulate_server
# (tests/forked_batch.py: about 85 ms of CPU less a run than a new ./simulate); `ran NAME`
# then gives its exit code.
whats=()
case_of() {  # a name, then simulate's arguments (no spaces)
  local name="$1"; shift
  whats+=("$name")
  printf '{"args": [%s], "stdout": null, "stderr": "%s"}\n' \
    "$(printf '"%s", ' "$@" | sed 's/, $//')" "$work/$name.err" >> "$work/cases.jsonl"
}
ran() {
  local k
  for k in "${!whats[@]}"; do
    [ "${whats[k]}" = "$1" ] && { echo "${codes[k]:-none}"; return; }
  done
  echo none
}
cornell="$root/scenes/cornell-box.json"
for p in receivers shooters; do
  case_of "$p" "$scene0" --R 1 --iterations 25 --form-factors hemicube --hemicube-resolution 50 \
    --parallelisation "$p" --json "$work/$p.json" --mesh "$work/$p.ply" --quiet --threads 1
done
for placement in centre elements; do
  for back_faces in block pass; do
    name="$placement-$back_faces"
    hemicube=(--form-factors hemicube --hemicube-resolution 50 --hemicube-placement "$placement"
              --hemicube-back-faces "$back_faces" --quiet --threads 1)
    case_of "r1-$name" "$cornell" --R 1 --iterations 6 "${hemicube[@]}" --mesh "$work/r1-$name.ply"
    case_of "s4-1-$name" "$cornell" --parallelisation shooters --R 4 --shooters-per-iteration 1 --iterations 6 \
      "${hemicube[@]}" --mesh "$work/s4-$name.ply"
    case_of "s4-$name" "$cornell" --parallelisation shooters --R 4 --iterations 3 "${hemicube[@]}" \
      --json "$work/s4-$name.json"
  done
done
case_of memory "$root/scenes/scene2.json" --parallelisation shooters --R 64 --form-factors hemicube --quiet
mapfile -t codes < <(/usr/bin/python3 "$root/tests/forked_batch.py" "$simulate" "$work/cases.jsonl")
[ "${#codes[@]}" = "${#whats[@]}" ] || fail "the batch ran ${#codes[@]} of ${#whats[@]} runs"

for p in receivers shooters; do
  [ "$(ran "$p")" = 0 ] || fail "$p: exit $(ran "$p")"
done
cmp -s "$work/receivers.ply" "$work/shooters.ply" ||
  fail "R=1 hemicube: the meshes (every element's radiosity) differ between receivers and shooters"
/usr/bin/python3 - "$work/receivers.json" "$work/shooters.json" <<'PY' || fail "R=1 result files"
import json, sys
r, s = (json.load(open(p)) for p in sys.argv[1:3])
assert s["config"]["form_factors"] == "hemicube", s["config"]
assert r["patch_radiosity"] == s["patch_radiosity"], "patch radiosities differ"
assert r["shooters"] == s["shooters"] and s["iterations"] == 25
hemicube = {k: v for k, v in r["counts"].items() if k.startswith("hemicube_")}
assert hemicube and hemicube["hemicube_depth_tests"] > 0, r["counts"]
for k, v in hemicube.items():
    assert s["counts"][k] == v, (k, v, s["counts"][k])
PY

# The hemicube's natural parallel form (issue 38 item 6): under the shooters each shot's
# hemicube(s) are rendered once, by the node that shoots, at both placements and with either
# back-face choice. (a) R = 4 with one shooter an iteration gives the paper's program at R = 1
# byte for byte (the exchange adds zeros to the one node's increments); (b) R = 4 with four
# shooters an iteration reads 3 N^2 cells per hemicube, one hemicube per shot at the centre
# and nu x nv (the shooter's elements, from the scene file) at the elements; only pass runs
# record hemicube_back_faces.
for placement in centre elements; do
  for back_faces in block pass; do
    name="$placement-$back_faces"
    [ "$(ran "r1-$name")" = 0 ] || fail "$name: receivers R=1: exit $(ran "r1-$name")"
    [ "$(ran "s4-1-$name")" = 0 ] || fail "$name: shooters R=4 S=1: exit $(ran "s4-1-$name")"
    cmp -s "$work/r1-$name.ply" "$work/s4-$name.ply" ||
      fail "$name: shooters at R=4, one shooter an iteration, differ from receivers at R=1"
    [ "$(ran "s4-$name")" = 0 ] || fail "$name: shooters R=4: exit $(ran "s4-$name")"
    /usr/bin/python3 - "$cornell" "$work/s4-$name.json" "$placement" "$back_faces" <<'PY' || fail "$name: one hemicube per shot"
import json, sys
scene, result = (json.load(open(p)) for p in sys.argv[1:3])
placement, back_faces = sys.argv[3:5]
shots = result["shooters"]
assert result["status"] == "ok" and len(shots) > 3, (result["status"], shots)
per_shot = [1 if placement == "centre" else
            scene["patches"][s]["elements"][0] * scene["patches"][s]["elements"][1] for s in shots]
assert result["counts"]["hemicube_cells_read"] == 3 * 50 * 50 * sum(per_shot), result["counts"]
assert result["config"].get("hemicube_back_faces") == (back_faces if back_faces == "pass" else None)
PY
  done
done

# Memory: the scheme's node as with rays plus the hemicube's table and buffers (scene2 at
# R = 64 needs 4825136 bytes with rays, tests/shooters_test.sh; N = 100: a table of
# 100 x 100 + 100 x 50 = 15000 delta form factors of 4 bytes and one face's buffer of
# 100 x 100 cells of 8 bytes, platforms/cost_model.json: 60000 + 80000 = 140000 bytes more).
cp "$work/memory.err" "$work/err"
got=$(ran memory)
[ "$got" = 3 ] || fail "scene2 shooters hemicube: exit $got, expected 3"
/usr/bin/python3 - "$work/err" <<'PY' || fail "hemicube bytes in the shooters' memory"
import json, re, sys
line = open(sys.argv[1]).read()
needed = int(re.search(r"needs (\d+) bytes", line).group(1))
assert needed == 4825136 + 140000, line
PY

[ "$failures" = 0 ] && echo "shooters_hemicube: ok"
exit "$((failures > 0))"
