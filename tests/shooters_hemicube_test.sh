#!/usr/bin/env bash
# --parallelisation shooters with --form-factors hemicube (docs/model.md, "The shooter-centred
# scheme"): every node holds the whole scene, so its hemicube draws every other patch's
# elements as occluders, as the paper's program at R = 1 does. With one node and one shooter
# an iteration the two give every element's raw radiosity in the --mesh PLY byte for byte and
# the same hemicube counts; the hemicube's buffers count in a node's memory (exit 3 where
# they do not fit beside the scene).
# Called by ctest as: shooters_hemicube_test.sh SIMULATE REPO_ROOT
set -u
simulate="$1"
root="$2"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
scene0="$root/scenes/scene0.json"

for p in receivers shooters; do
  "$simulate" "$scene0" --R 1 --iterations 25 --form-factors hemicube --hemicube-resolution 50 \
    --parallelisation "$p" --json "$work/$p.json" --mesh "$work/$p.ply" --quiet --threads 1 ||
    fail "$p: exit $?"
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

# Memory: the scheme's node as with rays plus the hemicube's table and buffers (scene2 at
# R = 64 needs 4825136 bytes with rays, tests/shooters_test.sh; N = 100: a table of
# 100 x 100 + 100 x 50 = 15000 delta form factors of 4 bytes and one face's buffer of
# 100 x 100 cells of 8 bytes, platforms/cost_model.json: 60000 + 80000 = 140000 bytes more).
"$simulate" "$root/scenes/scene2.json" --parallelisation shooters --R 64 --form-factors hemicube \
  --quiet 2> "$work/err"
got=$?
[ "$got" = 3 ] || fail "scene2 shooters hemicube: exit $got, expected 3"
/usr/bin/python3 - "$work/err" <<'PY' || fail "hemicube bytes in the shooters' memory"
import json, re, sys
line = open(sys.argv[1]).read()
needed = int(re.search(r"needs (\d+) bytes", line).group(1))
assert needed == 4825136 + 140000, line
PY

[ "$failures" = 0 ] && echo "shooters_hemicube: ok"
exit "$((failures > 0))"
