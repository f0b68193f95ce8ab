#!/usr/bin/env bash
# build/embree_floor (bench/embree_floor.cpp), the library's floor that bench/long_runs.py
# reports beside a run: it must trace the run's own rays, each distinct shot once. Checked
# against values worked out independently from the scene file and the result file:
#  1. the rays traced are, summed over the distinct shooters of the result, every element not
#     on the shooter's patch times M (the scene's element grids give the elements);
#  2. the distinct shots and the shots are those of the result's shooter list (scene0 to
#     convergence repeats shooters);
#  3. bad use: no result file or an unknown mode exits 2, an unreadable file exits 3.
# Called by ctest as: embree_floor_test.sh SIMULATE REPO_ROOT
set -u
simulate="$1"
root="$2"
export NCUBE_ROOT="$root"
floor="$(dirname "$simulate")/embree_floor"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

"$simulate" "$root/scenes/scene0.json" --R 2 --V 3 --samples 9 --json "$work/result.json" --quiet \
  || fail "simulate scene0 failed"
expected="$(/usr/bin/python3 - "$root/scenes/scene0.json" "$work/result.json" <<'PY'
import json, sys
scene = json.load(open(sys.argv[1]))
result = json.load(open(sys.argv[2]))
elements = [p["elements"][0] * p["elements"][1] for p in scene["patches"]]
shots = result["shooters"]
distinct = set(shots)
m = result["config"]["samples"]
rays = sum((sum(elements) - elements[s]) * m for s in distinct)
print(f"{len(distinct)} distinct shots of {len(shots)}, {rays} rays")
PY
)"
case "$expected" in *"of 1,"*|"") fail "the scene0 run should shoot more than once: '$expected'";; esac
for mode in first-hit to-the-end; do
  line="$("$floor" "$work/result.json" "$mode")" || fail "embree_floor $mode failed"
  case "$line" in
    *"$expected"*) ;;
    *) fail "embree_floor $mode: '$line', expected '$expected'";;
  esac
  seconds="${line##* }"
  [[ "$seconds" =~ ^[0-9]+\.[0-9]+$ ]] || fail "embree_floor $mode: last word '$seconds' is not the seconds"
done
# Both modes without a mode named: two lines.
[ "$("$floor" "$work/result.json" | wc -l)" = 2 ] || fail "embree_floor without a mode prints both"

"$floor" > /dev/null 2>&1; [ $? = 2 ] || fail "no result file: exit 2 expected"
"$floor" "$work/result.json" sideways > /dev/null 2>&1; [ $? = 2 ] || fail "unknown mode: exit 2 expected"
"$floor" "$work/missing.json" > /dev/null 2>&1; [ $? = 3 ] || fail "unreadable file: exit 3 expected"

[ "$failures" = 0 ] && echo "embree_floor_test: all checks passed"
exit "$failures"
