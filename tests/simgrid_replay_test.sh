#!/usr/bin/env bash
# build/simgrid_replay (bench/simgrid_replay.cpp), SimGrid alone on a run's messages, which
# bench/long_runs.py reports as SimGrid's floor beside the run. Checked against the run itself:
#  1. recording (NCUBE_RECORD_ACTIVITIES) changes no result: the result file equals the one
#     written without it, apart from host fields;
#  2. the replay has one actor per node, sends and takes exactly the run's messages (the sum
#     of the result's messages_sent and messages_received), and ends at the run's simulated
#     time to the last digit: a missed or extra execute, put or get would move it;
#  3. with visibility processors and with load balancing (its messages depend on the run);
#  4. bad use exits 2, an unreadable or truncated record exits 3; a record simulate cannot
#     write exits 5 with no result file.
# Called by ctest as: simgrid_replay_test.sh SIMULATE REPO_ROOT
set -u
simulate="$1"
root="$2"
export NCUBE_ROOT="$root"
replay="$(dirname "$simulate")/simgrid_replay"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

check_run() {  # name, then simulate's arguments
  local name="$1"
  shift
  NCUBE_RECORD_ACTIVITIES="$work/$name.act" "$simulate" "$@" --json "$work/$name.json" --quiet \
    || fail "$name: simulate with a record failed"
  "$simulate" "$@" --json "$work/$name-plain.json" --quiet || fail "$name: simulate failed"
  local line verdict
  line="$("$replay" "$root/platforms/ncube2.json" "$work/$name.act")" || fail "$name: replay failed"
  verdict="$(/usr/bin/python3 - "$work/$name.json" "$work/$name-plain.json" "$line" <<'PY'
import json, re, sys
def bad(why):
    print(why)
    sys.exit(1)
def strip(d):
    return {k: v for k, v in d.items() if k not in ("host_seconds", "provenance")}
recorded, plain = (json.load(open(p)) for p in sys.argv[1:3])
if strip(recorded) != strip(plain):
    bad("the record changed the result file")
# "64 actors, E executes, P puts, G gets: ... simulated end T s"
m = re.fullmatch(r"(\d+) actors, \d+ executes, (\d+) puts, (\d+) gets: .* simulated end (\S+) s",
                 sys.argv[3])
if not m:
    bad(f"unreadable replay line '{sys.argv[3]}'")
nodes = recorded["nodes"]
expected = (len(nodes), sum(n["messages_sent"] for n in nodes),
            sum(n["messages_received"] for n in nodes), recorded["simulated_seconds"])
got = (int(m[1]), int(m[2]), int(m[3]), float(m[4]))
if got != expected:
    bad(f"replay (actors, puts, gets, end) {got}, the run's {expected}")
PY
)" || fail "$name: $verdict"
}

check_run scene0-v3 "$root/scenes/scene0.json" --R 2 --V 3 --samples 9
check_run scene1-v0 "$root/scenes/scene1.json" --R 4 --V 0 --iterations 6
check_run scene2-balance "$root/scenes/scene2.json" --R 4 --V 1 --iterations 8 --balance

NCUBE_RECORD_ACTIVITIES="$work/no-such-folder/run.act" "$simulate" "$root/scenes/scene0.json" \
  --json "$work/unwritten.json" --quiet 2>/dev/null
[ $? -eq 2 ] || fail "a record in a missing folder should exit 2 before the run, as --json does"
[ -e "$work/unwritten.json" ] && fail "an unwritable record should leave no result file"

"$replay" >/dev/null 2>&1
[ $? -eq 2 ] || fail "no arguments should exit 2"
"$replay" "$root/platforms/ncube2.json" "$work/missing.act" >/dev/null 2>&1
[ $? -eq 3 ] || fail "a missing record should exit 3"
head -c 100 "$work/scene0-v3.act" > "$work/cut.act"
"$replay" "$root/platforms/ncube2.json" "$work/cut.act" >/dev/null 2>&1
[ $? -eq 3 ] || fail "a truncated record should exit 3"

[ "$failures" -eq 0 ] && echo "simgrid_replay_test: all checks passed"
exit $((failures > 0))
