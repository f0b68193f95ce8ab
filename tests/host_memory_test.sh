#!/usr/bin/env bash
# The host out of memory during the run is exit 6 with one line and no output, not SimGrid's
# abort (docs/cli.md, exit codes). A run that records its trace (--trace) allocates more as
# it goes, inside the node programs (SimGrid actors; about 1 MB an iteration: the 40
# iterations run here, of scene0's 151 to convergence, grow its resident size from 57 to 97 MB,
# at a third of a whole run's CPU): under an address-space limit (ulimit -v) just below what
# the run needs, an allocation fails in an actor; before, the exception left
# the actor and SimGrid aborted (exit 134, "Uncaught exception std::bad_alloc", temporaries
# left). The limit is found by bisection (the smallest that runs), then a limit every 6 MB in
# the 60 MB below it is tried (10 limits): each ends in exit 0 or 6, one of them in 6, and none leaves a file.
# Lower limits fail where SimGrid allocates the actors' stacks, which SimGrid itself turns into
# an abort: the stacks are reserved first and handed to SimGrid (reserve_actor_stacks,
# src/simulation/actor_stacks.h), so these too are exit 6 (naming the stacks). SimGrid's own
# allocations (xbt_malloc, in the maestro) end the process with xbt's "Memory (c)allocation of
# N bytes failed" and an abort that no code of ours sees: a limit where one of those fails
# first is exit 134 with that message, counted and allowed (docs/cli.md, exit 6), but it must
# leave no file either, and most limits must still be 6.
# THREADS=N runs with N host threads (default 1).
# Usage: bash tests/host_memory_test.sh <path-to-simulate-binary> <repo-root>
set -euo pipefail
simulate="$1"
root="${2:-$(cd "$(dirname "$0")/.." && pwd)}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
export NCUBE_ROOT="$root"

# Exit code of the run under a limit of $1 KiB; its stderr in $work/err.
run() {
  set +e
  (ulimit -v "$1"; "$simulate" "$root/scenes/scene0.json" --R 4 --V 3 --threads "${THREADS:-1}" --quiet \
     --iterations 40 --trace "$work/out/t.trace" --json "$work/out/r.json" 2> "$work/err")
  local code=$?
  set -e
  return $code
}
mkdir "$work/out"
low=100000 high=1000000  # KiB: fails, runs (a run needs about 500 MB of address space)
code=0; run $high || code=$?
[ $code = 0 ] || fail "the run does not run under $high KiB (exit $code): $(head -3 "$work/err")"
while [ $((high - low)) -gt 2000 ]; do
  mid=$(((low + high) / 2))
  code=0; run $mid || code=$?
  rm -rf "$work/out"; mkdir "$work/out"
  if [ $code = 0 ]; then high=$mid; else low=$mid; fi
done
sixes=0 simgrid_aborts=0
for ((limit = high - 3000; limit > high - 60000; limit -= 6000)); do
  code=0; run $limit || code=$?
  if [ $code = 6 ]; then
    sixes=$((sixes + 1))
    [ "$(grep -cv 'tcmalloc: allocation failed' "$work/err")" = 1 ] ||
      fail "under $limit KiB: not one line: $(head -5 "$work/err")"
    grep -q "^simulate: the host ran out of memory\|^simulate: the stacks of the simulation's" "$work/err" || fail "under $limit KiB: $(head -3 "$work/err")"
  elif [ $code = 134 ] && grep -q "\[root/CRITICAL\] Memory c\{0,1\}allocation of [0-9]* bytes failed" "$work/err"; then
    simgrid_aborts=$((simgrid_aborts + 1))
  elif [ $code != 0 ]; then
    fail "under $limit KiB: exit $code: $(grep -v '^  ->' "$work/err" | head -4)"
  fi
  [ $code = 0 ] || [ -z "$(ls -A "$work/out")" ] || fail "under $limit KiB (exit $code): left $(ls "$work/out")"
  rm -rf "$work/out"; mkdir "$work/out"
done
[ $sixes -gt 0 ] || fail "no limit below $high KiB ran out of memory"
[ $simgrid_aborts -lt $sixes ] || fail "$simgrid_aborts limits ended in SimGrid's own abort, only $sixes in exit 6"
echo "ok (runs from $high KiB; $sixes limits below end in exit 6, $simgrid_aborts in SimGrid's own allocation abort)"
