#!/usr/bin/env bash
# What ./simulate says about its trace and its exported scene (docs/cli.md, "--trace" and
# "--export-scene"): trace filters naming nodes or iterations the run does not have are exit 2
# with nothing written (before the run, or after it when the run converged sooner); the
# summary states the trace's size, and past 10 MB a warning names the options that trim it;
# --export-scene alone writes the scene without simulating, and says so. About 20 s on a
# loaded 2-core machine (the warning needs a trace over 10 MB: scene0 on 64 nodes).
# Usage: trace_export_test.sh SIMULATE SOURCE_DIR
simulate=$(realpath "$1")
root=$(realpath "$2")
export NCUBE_ROOT="$root"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

# refused WANTED -- ARGS...: exit 2, one line holding WANTED, no file written.
refused() {
  local wanted="$1"; shift 2
  "$simulate" "$@" --json r.json --trace t.json >stdout 2>stderr
  local got=$?
  [ "$got" -eq 2 ] || fail "simulate $*: exit $got, expected 2 ($(head -c 300 stderr))"
  [ "$(wc -l <stderr)" -eq 1 ] || fail "simulate $*: not one line: $(cat stderr)"
  grep -qF -- "$wanted" stderr || fail "simulate $*: the message does not say '$wanted': $(cat stderr)"
  [ -e r.json ] || [ -e t.json ] && fail "simulate $*: wrote a file"
  rm -f r.json t.json
}

run=(scene0 --R 2 --V 1)   # 4 nodes, 0-3
refused "--trace-nodes names node 4, but the run has 4 nodes (0-3)" -- "${run[@]}" --iterations 2 --trace-nodes 4
refused "--trace-nodes names node 100, but the run has 4 nodes (0-3)" -- "${run[@]}" --iterations 2 --trace-nodes 0-100
refused "--trace-nodes names node 1, but the run has 1 node (0)" -- scene0 --iterations 2 --trace-nodes 0,1
refused "--trace-iterations names iteration 3, but the run stops after 2 (--iterations 2)" -- "${run[@]}" --iterations 2 --trace-iterations 1:3
refused "--trace-iterations names iteration 5, but the run stops after 2" -- "${run[@]}" --iterations 2 --trace-iterations 5:
# Known only once the run has ended: at convergence 0.5, scene0 converges after 1 iteration.
refused "--trace-iterations starts at iteration 40, but the run had 1 iteration (it converged)" -- "${run[@]}" --convergence 0.5 --trace-iterations 40:

# Within the run: accepted, and the summary states the trace's size in decimal MB.
"$simulate" "${run[@]}" --iterations 2 --trace-nodes 0-3 --trace-iterations 0:2 --trace t.json >stdout 2>stderr ||
  fail "a window within the run was refused: $(cat stderr)"
size=$(stat -c %s t.json)
shown=$(awk -v b="$size" 'BEGIN { printf "%.2f MB", b / 1e6 }')
grep -qE "^written +t\.json \(--trace\): $shown\$" stdout || fail "the summary does not state the trace's $shown: $(grep written stdout)"
[ -s stderr ] && fail "a small trace gave a warning: $(cat stderr)"
rm -f t.json

# Over 10 MB (block size 5: about 12 MB in 6 iterations on 64 nodes): the warning.
"$simulate" scene0 --R 8 --V 7 --iterations 6 --block-size 5 --trace big.json >stdout 2>stderr || fail "the large trace's run failed: $(cat stderr)"
size=$(stat -c %s big.json)
[ "$size" -gt 10000000 ] || fail "the large trace is only $size bytes: the warning is not tried"
shown=$(awk -v b="$size" 'BEGIN { printf "%.1f MB", b / 1e6 }')
grep -qE "^written +big\.json \(--trace\): $shown\$" stdout || fail "the summary does not state the trace's $shown: $(grep written stdout)"
grep -qF "simulate: warning: the trace is $shown (over 10.0 MB): --trace-iterations A:B and --trace-nodes LIST keep only those iterations and nodes" stderr ||
  fail "no warning naming the options that trim the trace: $(cat stderr)"
rm -f big.json

# --export-scene alone: the scene, no simulation, and the summary says so.
model="$root/tests/models/cornell-box.obj"
"$simulate" "$model" --R 4 --V 3 --export-scene x.json >stdout 2>stderr || fail "--export-scene alone: $(cat stderr)"
/usr/bin/python3 -c 'import json, sys; sys.exit(not json.load(open("x.json"))["patches"])' ||
  fail "--export-scene alone wrote no scene"
grep -q "^simulation  *none: --export-scene alone writes the scene" stdout || fail "the summary does not say nothing was simulated: $(cat stdout)"
grep -q "^simulated seconds" stdout && fail "--export-scene alone simulated"
grep -qE "^written +x\.json \(--export-scene\)$" stdout || fail "no written line for the scene: $(cat stdout)"
rm -f x.json
"$simulate" "$model" --export-scene x.json --quiet >stdout 2>stderr || fail "--export-scene alone, --quiet: $(cat stderr)"
[ -s stdout ] || [ -s stderr ] && fail "--export-scene --quiet printed: $(cat stdout stderr)"
[ -e x.json ] || fail "--export-scene --quiet wrote no scene"
rm -f x.json
# With an output of a run, the run follows.
"$simulate" "$model" --iterations 1 --export-scene x.json --json r.json >stdout 2>stderr || fail "--export-scene with --json: $(cat stderr)"
grep -q "^simulated seconds" stdout && [ -e r.json ] && [ -e x.json ] || fail "--export-scene with --json did not run: $(cat stdout)"

[ "$failures" -eq 0 ] && echo "trace_export_test: all passed"
exit "$failures"
