#!/usr/bin/env bash
# --threads shares a run's host work out over host threads; the result file must not depend
# on it: runs with 1 and 2 threads are identical apart from "host_seconds" and the command line (V = 0, V > 0
# with its shared lists of blockers, both ray-test policies, octree visibility, and adaptive
# subdivision with load balancing). Called by ctest as:
# host_threads_test.sh SIMULATE REPO_ROOT
set -u
simulate="$1"
root="$2"
export NCUBE_ROOT="$root"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

# The result without what differs by design: the host time and the command line (which names
# the thread count).
without_host_time() {
  /usr/bin/python3 -c 'import json, sys
r = json.load(open(sys.argv[1])); r.pop("host_seconds"); r["provenance"].pop("command_line")
print(json.dumps(r, indent=1, sort_keys=True))' "$1"
}

# The runs are made in one batch, each forked from build/simulate_server (tests/forked_batch.py:
# about 85 ms of CPU less a run than a new ./simulate), then compared pair by pair.
names=() others=()
check() {  # name, then simulate's arguments (no spaces): a pair of runs, 1 and other_threads
  local name="$1"; shift
  local other="${other_threads:-2}" args
  names+=("$name"); others+=("$other")
  for threads in 1 "$other"; do
    args=$(printf '"%s", ' "$@")
    printf '{"args": [%s"--threads", "%s", "--json", "%s", "--quiet"], "stdout": null, "stderr": "%s"}\n' \
      "$args" "$threads" "$work/$name-$threads.json" "$work/$name-$threads.err" >> "$work/cases.jsonl"
  done
}
compare() {
  local name="$1" other="$2"
  grep -q '"host_seconds"' "$work/$name-1.json" || fail "$name: no host_seconds field to leave out"
  if ! cmp -s <(without_host_time "$work/$name-1.json") <(without_host_time "$work/$name-$other.json"); then
    fail "$name: result files differ between --threads 1 and --threads $other"
    diff <(without_host_time "$work/$name-1.json") <(without_host_time "$work/$name-$other.json") | head -5
  fi
}

check scene1-R1-V0 scene1.json --R 1 --V 0 --samples 64 --iterations 6
check scene1-R2-V3 scene1.json --R 2 --V 3 --samples 64 --iterations 6
check scene1-R2-V3-first-blocker scene1.json --R 2 --V 3 --samples 16 --iterations 4 --ray-test first-blocker
check scene0-R4-V0-first-blocker scene0.json --R 4 --V 0 --samples 64 --iterations 10 --ray-test first-blocker
check scene1-R2-V3-octree scene1.json --R 2 --V 3 --samples 64 --iterations 4 --visibility octree
check scene0-R4-V0-octree scene0.json --R 4 --V 0 --samples 64 --iterations 10 --visibility octree
# Adaptive subdivision and load balancing (sections 4.1, 4.2): children shot at their own
# centres, patches moved between processors.
check scene0-R8-V0-subdivide-balance scene0.json --R 8 --V 0 --iterations 8 --subdivide --balance
check scene0-R4-V1-subdivide-balance scene0.json --R 4 --V 1 --iterations 8 --subdivide --balance
# To convergence (143 shots of 38 of the 52 patches): repeated shots answered and their form
# factors taken from memory, first shots guessed ahead by the host threads computing ahead
# (docs/performance.md); with 3 threads, two of them compute ahead.
check scene0-R2-V3-converge scene0.json --R 2 --V 3 --samples 16
other_threads=3 check scene0-R2-V3-converge-3 scene0.json --R 2 --V 3 --samples 16 --block-size 13

mapfile -t codes < <(/usr/bin/python3 "$root/tests/forked_batch.py" "$simulate" "$work/cases.jsonl")
[ "${#codes[@]}" = $((2 * ${#names[@]})) ] || fail "the batch ran ${#codes[@]} of $((2 * ${#names[@]})) runs"
for k in "${!names[@]}"; do
  name=${names[k]} other=${others[k]}
  [ "${codes[2 * k]:-none}" = 0 ] || fail "$name: simulate exited ${codes[2 * k]:-none} with --threads 1: $(head -c 300 "$work/$name-1.err")"
  [ "${codes[2 * k + 1]:-none}" = 0 ] || fail "$name: simulate exited ${codes[2 * k + 1]:-none} with --threads $other: $(head -c 300 "$work/$name-$other.err")"
  [ "${codes[2 * k]:-none}" = 0 ] && [ "${codes[2 * k + 1]:-none}" = 0 ] && compare "$name" "$other"
done

[ "$failures" -eq 0 ] && echo "host threads: all result files identical" 
exit $((failures > 0))
