#!/usr/bin/env bash
# Every option of the sweep tool is bounded and a sweep states its size before expanding it
# (issue 37, item 4; docs/sweeps.md): --cores and --jobs outside their ranges are exit 2 at
# once (--cores 0 used to hang, -1 was taken); a grid of 10^8 cells is refused with its count
# in about a second (it used to end in a MemoryError after 40 s), nothing written.
# Usage: bash tests/sweep_bounds_test.sh <path-to-simulate-binary> <repo-root>
set -u
simulate="$(realpath "$1")"
root="$2"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
cd "$work" || exit 1
sweep() { NCUBE_SIMULATE="$simulate" timeout 30 /usr/bin/python3 "$root/experiments/sweep" "$@" > out.txt 2> err.txt; }
printf "name: small\noptions: {iterations: 1, samples: 4}\ngrid: {scene: [scene0], R: [1]}\n" > small.yaml
# The options refused by the sweep tool's own entry (ncube.runner.main, which
# experiments/sweep calls) in one Python: per option its exit code and message in a file of
# its own; the script itself runs the 10^8-cell grid below.
NCUBE_SIMULATE="$simulate" timeout 60 /usr/bin/python3 - "$root" <<'EOF_PY'
import contextlib, io, sys
sys.path.insert(0, sys.argv[1] + "/analysis")
from ncube import runner
for number, option in enumerate(["--cores 0", "--cores -1", "--cores x", "--cores 1025",
                                 "--jobs 0", "--jobs -5"]):
    err = io.StringIO()
    with contextlib.redirect_stdout(io.StringIO()), contextlib.redirect_stderr(err):
        try:
            code = runner.main(["small.yaml", "--results", "r"] + option.split())
        except SystemExit as end:   # argparse's refusal
            code = end.code
    open(f"code{number}.txt", "w").write(f"{code}\n")
    open(f"err{number}.txt", "w").write(err.getvalue())
EOF_PY
number=0
for option in "--cores 0" "--cores -1" "--cores x" "--cores 1025" "--jobs 0" "--jobs -5"; do
  code=$(cat "code$number.txt" 2>/dev/null)
  [ "$code" = 2 ] || fail "$option: exit $code, expected 2"
  grep -q "argument ${option% *}" "err$number.txt" 2>/dev/null || fail "$option: the message does not name it: $(cat "err$number.txt" 2>/dev/null)"
  number=$((number + 1))
done
[ ! -e r ] || fail "an option refused: the results folder was made"
printf "name: big\ngrid: {scene: [scene0], R: [%s], V: [%s]}\n" "$(seq -s, 1 10000)" "$(seq -s, 0 9999)" > big.yaml
start=$(date +%s)
sweep big.yaml --results r; code=$?
[ "$code" = 2 ] || fail "a grid of 10^8 cells: exit $code, expected 2"
grep -q '100,000,000 cells' err.txt || fail "a grid of 10^8 cells: the count is not said: $(cat err.txt)"
[ $(( $(date +%s) - start )) -le 15 ] || fail "a grid of 10^8 cells took $(( $(date +%s) - start )) s to refuse"
[ ! -e r ] || fail "a grid of 10^8 cells: the results folder was made"
[ "$failures" = 0 ] && echo "sweep_bounds_test: all checks passed" && exit 0
echo "sweep_bounds_test: $failures check(s) failed"
exit 1
