#!/usr/bin/env bash
# SimGrid's own tracing (--cfg=tracing:yes, docs/cli.md "SimGrid's tracing") on the project's
# platforms, read back with a real Paje reader (Debian's pajeng, pj_dump):
#  1. the hypercube built in src/machine/hypercube.cpp and the SimGrid XML platform both trace
#     (before the fix the hypercube ended with exit 7, "container loopback-0 already present");
#  2. the trace parses, and holds what the run had: one HOST container per node (node-0 ...
#     node-63), one LINK container per torus link and loopback (64 x 6 x 2 + 64 = 832), one
#     ACTOR container per node program with its send / receive / execute states, the hosts'
#     speed and use (tracing/uncategorized); the last state ends at the run's simulated time;
#  3. tracing moves no simulated second: the result file equals the one without tracing,
#     apart from host fields and the settings listed in it;
#  4. checking the settings (--check-settings --cfg=tracing:yes) writes no trace anywhere.
# Called by ctest as: simgrid_tracing_test.sh SIMULATE REPO_ROOT
set -u
simulate="$1"
root="$2"
export NCUBE_ROOT="$root"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
command -v pj_dump > /dev/null || { echo "FAIL: pj_dump not installed (Debian's pajeng, .ci/install-deps)"; exit 1; }

tracing=(--cfg=tracing:yes --cfg=tracing/actor:yes --cfg=tracing/platform:yes
         --cfg=tracing/uncategorized:yes)

check_trace() {  # name, then simulate's arguments
  local name="$1"
  shift
  "$simulate" "$@" "${tracing[@]}" "--cfg=tracing/filename:$work/$name.trace" \
    --json "$work/$name.json" --quiet 2> "$work/$name.err" \
    || { fail "$name: the traced run failed: $(head -c 300 "$work/$name.err")"; return; }
  "$simulate" "$@" --json "$work/$name-plain.json" --quiet || fail "$name: the plain run failed"
  pj_dump "$work/$name.trace" > "$work/$name.dump" 2> "$work/$name.pj_err" \
    || { fail "$name: pj_dump cannot read the trace: $(head -c 300 "$work/$name.pj_err")"; return; }
  local verdict
  verdict="$(/usr/bin/python3 - "$work/$name.dump" "$work/$name.json" "$work/$name-plain.json" <<'PY'
import collections, json, sys
def bad(why):
    print(why)
    sys.exit(1)
def strip(d):
    return {k: v for k, v in d.items()
            if k not in ("host_seconds", "provenance", "simgrid_config")}
traced, plain = (json.load(open(p)) for p in sys.argv[2:4])
if strip(traced) != strip(plain):
    bad("tracing changed the result file")
rows = [[f.strip() for f in line.split(",")] for line in open(sys.argv[1])]
containers = collections.defaultdict(list)
for r in rows:
    if r[0] == "Container":
        containers[r[2]].append(r[6])
nodes = len(traced["nodes"])
if sorted(containers["HOST"]) != sorted(f"node-{k}" for k in range(64)):
    bad(f"HOST containers are not node-0 ... node-63: {sorted(containers['HOST'])[:5]}")
links = containers["LINK"]
if len(links) != len(set(links)) or len(links) != 64 * 6 * 2 + 64:
    bad(f"{len(links)} LINK containers ({len(set(links))} distinct), expected 832")
if len(containers["ACTOR"]) != nodes:
    bad(f"{len(containers['ACTOR'])} ACTOR containers for {nodes} node programs")
states = [r for r in rows if r[0] == "State" and r[2] == "ACTOR_STATE"]
values = {r[7] for r in states}
if not {"send", "receive", "execute"} <= values:
    bad(f"actor states {sorted(values)} lack send, receive or execute")
if {r[1] for r in states} != set(containers["ACTOR"]):
    bad("not every actor has states")
end = max(float(r[4]) for r in states)
if abs(end - traced["simulated_seconds"]) > 1e-5:
    bad(f"the last actor state ends at {end}, the run at {traced['simulated_seconds']}")
speeds = {r[1] for r in rows if r[0] == "Variable" and r[2] == "speed"}
used = {r[1] for r in rows if r[0] == "Variable" and r[2] == "speed_used"}
if len(speeds) != 64 or not used:
    bad(f"speed traced on {len(speeds)} hosts, speed_used on {len(used)}")
print("ok")
PY
)" || fail "$name: $verdict"
}

check_trace hypercube "$root/scenes/scene0.json" --R 2 --V 1 --iterations 3
check_trace xml "$root/scenes/scene0.json" --R 4 --V 1 --iterations 2 --platform "$root/platforms/ncube2.xml"

mkdir "$work/check" && cd "$work/check" || exit 1
"$simulate" --check-settings --cfg=tracing:yes --cfg=tracing/actor:yes || fail "--check-settings refused tracing"
[ -z "$(ls -A .)" ] || fail "--check-settings wrote $(ls -A .)"

if [ "$failures" -gt 0 ]; then
  echo "$failures failure(s)"
  exit 1
fi
echo "all SimGrid tracing checks passed"
