#!/usr/bin/env bash
# Command-line contract of simulate: help, exit codes, no output on bad input, bare scene
# names, determinism of the result file. Called by ctest as: cli_test.sh SIMULATE REPO_ROOT
set -u
simulate="$1"
root="$2"
export NCUBE_ROOT="$root"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

# expect_exit CODE DESCRIPTION -- ARGS...: runs simulate with --json into the work dir and
# checks the exit code, and for a failure that no result file was written.
expect_exit() {
  local code="$1" what="$2"; shift 3
  rm -f "$work/out.json"
  "$simulate" "$@" --json "$work/out.json" >"$work/stdout" 2>"$work/stderr"
  local got=$?
  [ "$got" -eq "$code" ] || fail "$what: exit $got, expected $code ($(head -c 300 "$work/stderr"))"
  if [ "$code" -ne 0 ] && [ -e "$work/out.json" ]; then fail "$what: wrote a result file"; fi
  if [ "$code" -ne 0 ] && [ "$(wc -l <"$work/stderr")" -lt 1 ]; then fail "$what: no message"; fi
}

"$simulate" --help >"$work/help" 2>&1 || fail "--help exits non-zero"
for option in --R --V --samples --iterations --convergence --json --image --platform --cost-model; do
  grep -q -- "$option" "$work/help" || fail "--help does not list $option"
done

# Each bad option, missing file and output-path refusal is also a case of
# tests/robustness/cases.py (exit 2, no result file, one message of at most two lines): an
# unknown option, R 2.5, 0, 010 and 2 with V 2147483647, V -1 and 1.5, samples 20, R 53, block
# size 0, iterations -5, convergence 0 and nan, an empty --image, a missing scene, platform and
# cost model, --json and --trace the same file, a full disk, 16 million elements (exit 3); an
# output onto the scene or in a missing folder is a cell of its threat model. Here the
# messages that must say more.
expect_exit 2 "more nodes than the platform" -- scene0.json --R 8 --V 8
grep -q "72" "$work/stderr" || fail "too many nodes: message does not give R x (V + 1)"
echo '{"parameters": {}}' >"$work/platform.json"
expect_exit 2 "inconsistent platform" -- scene0.json --platform "$work/platform.json"
grep -q "dimension" "$work/stderr" || fail "inconsistent platform: message does not name the parameter"

# Out of memory (section 5: scene3 with R=4, V=15 does not fit): exit 3, and the result
# file says so, naming the node.
# --iterations: if the memory model ever let it fit, the run must end, not hang the suite.
"$simulate" scene3.json --R 4 --V 15 --iterations 1 --json "$work/oom.json" >/dev/null 2>"$work/stderr"
[ $? -eq 3 ] || fail "out of memory: exit code is not 3"
grep -q '"status": "out_of_memory"' "$work/oom.json" || fail "out of memory: status not in result file"
grep -q '"needed_bytes"' "$work/oom.json" || fail "out of memory: needed bytes not reported"
grep -q "radiosity" "$work/stderr" || fail "out of memory: message does not name the role"
echo '{"name": "x", "patches": [' >"$work/broken.json"
expect_exit 2 "malformed scene" -- "$work/broken.json"
grep -q "broken.json" "$work/stderr" || fail "malformed scene: message does not name the file"

# A bare scene name is found in scenes/ from any directory.
(cd "$work" && "$simulate" scene0.json --iterations 2 --quiet) || fail "bare scene name not resolved"

# Same command, same result file (host-time fields aside); a picture is a PNG. The picture is
# 160 x 120 (the result file records the size, so b gives it too): the default 800 x 600 took
# 1.7 of the test's CPU seconds.
small=(--image-width 160 --image-height 120)
"$simulate" scene0.json --iterations 5 "${small[@]}" --json "$work/a.json" --image "$work/a.png" --quiet || fail "run a"
"$simulate" scene0.json --iterations 5 "${small[@]}" --json "$work/b.json" --quiet || fail "run b"
# The same command twice: the same bytes but for host_seconds. Two commands that differ only in
# their outputs: the same result but for the command line recorded in the provenance.
cp "$work/b.json" "$work/b1.json"
"$simulate" scene0.json --iterations 5 "${small[@]}" --json "$work/b.json" --quiet || fail "run b again"
strip() { grep -v '"host_seconds"' "$1"; }
cmp -s <(strip "$work/b1.json") <(strip "$work/b.json") || fail "result files of the same command differ"
strip_command() {
  /usr/bin/python3 -c 'import json, sys; r = json.load(open(sys.argv[1])); del r["host_seconds"]
del r["provenance"]["command_line"]; print(json.dumps(r, indent=1))' "$1"
}
cmp -s <(strip_command "$work/a.json") <(strip_command "$work/b.json") || fail "result files differ"
# Also for a parallel configuration with V + 1 not a power of two, and its trace.
"$simulate" scene0.json --R 5 --V 2 --iterations 3 --json "$work/c.json" --trace "$work/c.trace" --quiet || fail "run c"
"$simulate" scene0.json --R 5 --V 2 --iterations 3 --json "$work/d.json" --quiet || fail "run d"
cmp -s <(strip_command "$work/c.json") <(strip_command "$work/d.json") || fail "parallel result files differ"
grep -q '"traceEvents"' "$work/c.trace" || fail "trace is not a trace-event file"
[ "$(head -c 4 "$work/a.png" | od -An -c | tr -d ' ')" = "211PNG" ] || fail "image is not a PNG"

# Adaptive subdivision with load balancing (sections 4.1, 4.2) moves patches and is just as
# deterministic. Three iterations: 9 patches moved in 3 messages and 1162 elements cut to 2587
# (eight took 1.2 CPU seconds more a run; from the fifth on the runs cost twice as much).
"$simulate" scene0.json --R 8 --subdivide --balance --iterations 3 --json "$work/s1.json" --quiet || fail "run s1"
"$simulate" scene0.json --R 8 --subdivide --balance --iterations 3 --json "$work/s2.json" --quiet || fail "run s2"
cmp -s <(strip_command "$work/s1.json") <(strip_command "$work/s2.json") || fail "subdivision and balancing: result files differ"
/usr/bin/python3 -c 'import json, sys; r = json.load(open(sys.argv[1]))
sys.exit(not (r["patches_moved"] > 0 and r["elements_at_end"] > r["scene"]["elements"]))' "$work/s1.json" ||
  fail "subdivision and balancing: the run cut no element or moved no patch"

# The nCube2 as a SimGrid platform file gives the same result as the JSON platform.
"$simulate" scene0.json --R 8 --V 7 --iterations 2 --json "$work/j.json" --quiet || fail "run json"
"$simulate" scene0.json --R 8 --V 7 --iterations 2 --platform "$root/platforms/ncube2.xml" --json "$work/x.json" --quiet || fail "run xml"
same_result() {
  /usr/bin/python3 -c 'import json, sys; a, b = (json.load(open(f)) for f in sys.argv[1:3])
for r in (a, b): del r["host_seconds"], r["provenance"]
sys.exit(a != b)' "$1" "$2"
}
same_result "$work/j.json" "$work/x.json" || fail "platforms/ncube2.xml and ncube2.json give different results"
grep -q '"simgrid-xml"' "$work/x.json" || fail "the result file does not say the platform was XML"
# --cfg reaches SimGrid, overrides the platform's network model, and the result file says so.
"$simulate" scene0.json --R 8 --V 7 --iterations 2 --cfg=network/model:LV08 --json "$work/l.json" --quiet || fail "run --cfg"
grep -q '"network/model": "LV08"' "$work/l.json" || fail "--cfg=network/model:LV08 not recorded"
same_result "$work/j.json" "$work/l.json" && fail "--cfg=network/model:LV08 changed nothing"
# --log with the project's categories; --version names the code and SimGrid.
"$simulate" scene0.json --R 2 --V 1 --iterations 1 --quiet --log=ncube_messages.thresh:debug 2>"$work/log" || fail "run --log"
grep -q "ncube_messages/DEBUG" "$work/log" || fail "--log=ncube_messages.thresh:debug shows no message"
"$simulate" --version | grep -q "SimGrid 3" || fail "--version does not name SimGrid"
# The summary names its measure of seconds per iteration.
"$simulate" scene0.json --iterations 3 | grep -q "seconds per iteration .*(mean of the first 3 iterations" || fail "summary does not name its measure"

[ "$failures" -eq 0 ] && echo "cli_test: all passed"
exit "$failures"
