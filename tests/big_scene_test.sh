#!/usr/bin/env bash
# scene4 (51,200 patches, 76,800 elements; docs/scenes.md) and the nodes' 4 MB: the memory
# story of the paper's section 6 ("scenes, where even the memory for the patches exceeds
# available memory"). Every configuration without visibility processors runs out of memory,
# on the 64-node machine and on the 8,192-node one, because the geometry of all patches
# alone (68 bytes each, platforms/cost_model.json) needs more than a node has; so does the
# single visibility processor of V = 1; R = 8, V = 7 fits and runs.
# Called by ctest as: big_scene_test.sh SIMULATE REPO_ROOT (about 15 s, most of it loading
# the scene four times and one shot of the success case).
set -u
simulate="$1"
root="$2"
export NCUBE_ROOT="$root"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

# Worked out by hand: reserve 786,432 + two shooter records 2 x 88 + 51,200 patches x 68 bytes
# of geometry = 4,268,208 bytes > 4,194,304 (4 MB), before any element.
geometry_alone=4268208

# expect_out_of_memory WHAT NODE ROLE -- ARGS...: exit 3, the result file's status and the
# message name the node, its role and the bytes, which exceed the geometry alone (the result
# files are checked at the end, all in one python3).
cases=0
expect_out_of_memory() {
  local what="$1" node="$2" role="$3"; shift 4
  cases=$((cases + 1))
  local out="$work/oom-$cases.json"
  # One shot of one sample at most, should the configuration (wrongly) fit.
  "$simulate" scene4.json "$@" --iterations 1 --samples 1 --json "$out" \
    >"$work/stdout" 2>"$work/stderr"
  local got=$?
  [ "$got" -eq 3 ] || { fail "$what: exit $got, expected 3 ($(head -c 300 "$work/stderr"))"; return; }
  grep -q "node $node ($role processor) is out of memory: needs [0-9]* bytes, has 4194304" \
    "$work/stderr" || fail "$what: message $(head -c 300 "$work/stderr")"
  printf '%s\t%s\t%s\t%s\n' "$out" "$node" "$role" "$what" >> "$work/oom-cases.tsv"
}

# V = 0 with the most radiosity processors the nCube2 has: each holds all patches' geometry,
# more than its memory whatever R (the bytes needed exceed the geometry alone), so no
# machine of the family runs scene4 without visibility processors.
expect_out_of_memory "R=64, V=0" 0 radiosity -- --R 64
# V = 1: the one visibility processor of each group holds all patches' geometry.
expect_out_of_memory "R=32, V=1" 1 visibility -- --R 32 --V 1
# Too few radiosity processors: R = 4, V = 15 runs out of memory for elements (as scene3 does
# in the paper's section 5): 19,200 elements x 184 bytes on each.
expect_out_of_memory "R=4, V=15" 0 radiosity -- --R 4 --V 15

# R = 8, V = 7 fits and shoots once. With one sample (M = 1) every element but the shooter's
# traces one ray, tested against all other patches: (76,800 - the shooter's elements) x
# (51,200 - 2) ray-patch tests (the receiver's and the shooter's patch are skipped).
"$simulate" scene4.json --R 8 --V 7 --iterations 1 --samples 1 --json "$work/ok.json" \
  >"$work/stdout" 2>"$work/stderr" || fail "R=8, V=7: exit $? ($(head -c 300 "$work/stderr"))"
# The out-of-memory cases' result files, then the run's, in one python3.
touch "$work/oom-cases.tsv"
/usr/bin/python3 - "$work/oom-cases.tsv" "$geometry_alone" "$work/ok.json" "$root/scenes/scene4.json" <<'PY' ||
import json, sys
cases, geometry_alone, ok, scene_file = sys.argv[1:5]
failed = []
for line in open(cases):
    path, node, role, what = line.rstrip("\n").split("\t")
    try:
        result = json.load(open(path))
        oom = result["out_of_memory"]
        assert result["status"] == "out_of_memory", result["status"]
        assert oom["node"] == int(node) and oom["role"] == role, oom
        assert oom["available_bytes"] == 4194304, oom
        assert oom["needed_bytes"] >= float(geometry_alone), oom
        assert result["iterations"] == 0 and result["simulated_seconds"] == 0, result["iterations"]
    except (AssertionError, OSError, ValueError, KeyError) as e:
        failed.append(f"{what}: result file: {e!r}")
try:
    result = json.load(open(ok))
    assert result["status"] == "ok" and result["iterations"] == 1, result["status"]
    shooter = json.load(open(scene_file))["patches"][result["shooters"][0]]
    assert sum(shooter.get("emission", [0, 0, 0])) > 0, "the first shooter is not a light"
    nu, nv = shooter["elements"]
    tests = result["counts"]["ray_patch_tests"]
    assert tests == (76800 - nu * nv) * (51200 - 2), tests
    peaks = [n["peak_memory_bytes"] for n in result["nodes"]]
    assert len(peaks) == 64 and max(peaks) <= 4194304, max(peaks)
    assert result["simulated_seconds"] > 0
except (AssertionError, OSError, ValueError, KeyError, IndexError, TypeError) as e:
    failed.append(f"R=8, V=7: result: {e!r}")
for problem in failed:
    print("FAIL:", problem)
sys.exit(len(failed))
PY
  failures=$((failures + 1))

[ "$failures" -eq 0 ] && echo "big_scene_test: all passed"
exit "$failures"
