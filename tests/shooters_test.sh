#!/usr/bin/env bash
# --parallelisation shooters at the command line (docs/model.md, "The shooter-centred
# scheme"): with one node and one shooter an iteration it gives the paper's program's
# radiosities (R = 1), every element's raw radiosity in the --mesh PLY byte for byte; the
# result file records the parallelisation; what it cannot run is one line and exit 2; a
# scene that does not fit on every node is exit 3 naming the node and the bytes (worked out
# in tests/shooter_processor_test.cpp) with a result file whose status says so.
# Called by ctest as: shooters_test.sh SIMULATE REPO_ROOT
set -u
simulate="$1"
root="$2"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
scene0="$root/scenes/scene0.json"

for p in receivers shooters; do
  "$simulate" "$scene0" --R 1 --iterations 25 --samples 16 --parallelisation "$p" \
    --json "$work/$p.json" --mesh "$work/$p.ply" --quiet --threads 1 || fail "$p: exit $?"
done
cmp -s "$work/receivers.ply" "$work/shooters.ply" ||
  fail "R=1: the meshes (every element's radiosity) differ between receivers and shooters"
/usr/bin/python3 - "$work/receivers.json" "$work/shooters.json" <<'PY' || fail "R=1 result files"
import json, sys
r, s = (json.load(open(p)) for p in sys.argv[1:3])
assert "parallelisation" not in r["config"], r["config"]  # the paper's runs keep their files
assert s["config"]["parallelisation"] == "shooters", s["config"]
assert s["config"]["shooters_per_iteration"] == 0
assert r["patch_radiosity"] == s["patch_radiosity"], "patch radiosities differ"
assert r["shooters"] == s["shooters"] and s["iterations"] == 25
PY

# The seam rule: the host's fast occluders and threads give the result file of the readable
# definitions on one thread (apart from host fields); the octree the same radiosities.
for run in "fast:--threads 2" "reference:--reference-visibility --threads 1" "octree:--visibility octree"; do
  "$simulate" "$scene0" --R 4 --iterations 4 --samples 16 --parallelisation shooters ${run#*:} \
    --json "$work/seam-${run%%:*}.json" --quiet || fail "seam ${run%%:*}: exit $?"
done
/usr/bin/python3 - "$work"/seam-{fast,reference,octree}.json <<'PY' || fail "seam rule"
import json, sys
fast, reference, octree = (json.load(open(p)) for p in sys.argv[1:4])
for r in (fast, reference):
    r.pop("host_seconds"); r.pop("provenance")
assert fast == reference, "the fast occluders or threads changed the result file"
assert fast["iterations"] == 4 and len(fast["shooters"]) > 4, fast["shooters"]
assert octree["patch_radiosity"] == fast["patch_radiosity"], "the octree changed the radiosities"
assert octree["counts"]["ray_patch_tests"] < fast["counts"]["ray_patch_tests"]
PY

# One line on stderr (a parse error adds "(see simulate --help)"), the given exit code, and
# no result file, or (exit 3) one with status out_of_memory.
refused() {
  local code="$1" expected="$2"; shift 2
  rm -f "$work/out.json"
  "$simulate" "$@" --json "$work/out.json" --quiet 2> "$work/err"
  local got=$?
  [ "$got" = "$code" ] || fail "$*: exit $got, expected $code ($(cat "$work/err"))"
  [ "$(grep -vc '^(see simulate --help)$' "$work/err")" = 1 ] ||
    fail "$*: not one line: $(cat "$work/err")"
  grep -qF -- "$expected" "$work/err" || fail "$*: '$expected' not in: $(cat "$work/err")"
  if [ "$code" = 3 ]; then
    grep -q '"status": "out_of_memory"' "$work/out.json" || fail "$*: no out-of-memory result file"
  else
    [ ! -e "$work/out.json" ] || fail "$*: a result file was written"
  fi
}
refused 2 "V=1" "$scene0" --parallelisation shooters --R 2 --V 1
refused 2 "--subdivide" "$scene0" --parallelisation shooters --R 2 --subdivide
refused 2 "--shooters-per-iteration 3" "$scene0" --parallelisation shooters --R 2 --shooters-per-iteration 3
refused 2 "applies to --parallelisation shooters only" "$scene0" --R 2 --shooters-per-iteration 2
refused 2 "--parallelisation" "$scene0" --parallelisation senders
refused 2 "--shooters-per-iteration" "$scene0" --parallelisation shooters --shooters-per-iteration -1
refused 3 "node 0 (radiosity processor) is out of memory: needs 4825136 bytes, has 4194304" \
  "$root/scenes/scene2.json" --parallelisation shooters --R 64

[ "$failures" = 0 ] && echo "shooters: ok"
exit "$((failures > 0))"
