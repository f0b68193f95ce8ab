#!/usr/bin/env bash
# The seam between the simulated program and the host's speed machinery
# (docs/architecture.md):
#  1. every header in src/host/ marks itself host-side (includes host/host_side.h), and that
#     mark stops a build of the simulated side (compiled with NCUBE_SIMULATED_SIDE);
#  2. no file of the simulated side includes a host header, Embree, OpenMP or host threads;
#  3. whole runs: the default (fast) path and --reference-visibility (the readable
#     definitions alone: the paper's loop or the octree walk, one thread, no cache, no
#     lookahead) give the same result file, byte for byte apart from the host time and the
#     command line, for V = 0 and V > 0, both ray tests, the octree, adaptive subdivision
#     and load balancing. 20 iterations of scene0 and the Cornell box: 10 and 7 of their
#     shots are of a patch shot before (the answer cache's hits), and the Cornell box's
#     elements stop being split at its sixth.
# Called by ctest as: seam_test.sh SIMULATE REPO_ROOT
set -u
simulate="$1"
root="$2"
export NCUBE_ROOT="$root"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

model_folders=(geometry scene counts radiosity visibility machine nodes render util)

# 1. The mark.
for header in "$root"/src/host/*.h; do
  [ "$(basename "$header")" = host_side.h ] && continue
  grep -q '#include "host/host_side.h"' "$header" || fail "$header does not include host/host_side.h"
done
printf '#include "host/host_side.h"\n' > "$work/probe.cpp"
if g++ -std=c++17 -I "$root/src" -DNCUBE_SIMULATED_SIDE -fsyntax-only "$work/probe.cpp" 2>/dev/null; then
  fail "host/host_side.h compiles on the simulated side (NCUBE_SIMULATED_SIDE): the guard is gone"
fi
g++ -std=c++17 -I "$root/src" -fsyntax-only "$work/probe.cpp" || fail "host/host_side.h does not compile on the host side"
grep -q 'NCUBE_SIMULATED_SIDE' "$root/CMakeLists.txt" || fail "CMakeLists.txt does not build ncube_model with NCUBE_SIMULATED_SIDE"

# 2. What the simulated side includes.
for folder in "${model_folders[@]}"; do
  hits=$(grep -rnE '#include +["<](host/|embree|omp\.h|thread>|mutex>|atomic>|condition_variable>|future>)' \
           "$root/src/$folder" || true)
  [ -z "$hits" ] || fail "the simulated side includes host machinery: $hits"
done

# 3. Whole runs.
same_but_host_fields() {  # two result files equal but for the host time and the command line
  /usr/bin/python3 -c 'import json, sys
a, b = (json.load(open(p)) for p in sys.argv[1:3])
for r in (a, b):
    r.pop("host_seconds"); r["provenance"].pop("command_line")
# As printed (not ==, which takes -0.0 for 0.0 and 1 for 1.0).
sys.exit(0 if json.dumps(a, sort_keys=True) == json.dumps(b, sort_keys=True) else 1)' "$1" "$2"
}
without_host_fields() {
  /usr/bin/python3 -c 'import json, sys
r = json.load(open(sys.argv[1])); r.pop("host_seconds"); r["provenance"].pop("command_line")
print(json.dumps(r, indent=1, sort_keys=True))' "$1"
}
# The runs are made in one batch, each forked from build/simulate_server (tests/forked_batch.py:
# about 85 ms of CPU less a run than a new ./simulate), then compared pair by pair.
names=()
check() {  # name, then simulate's arguments (no spaces): the fast path and the reference
  local name="$1"; shift
  local args
  names+=("$name")
  args=$(printf '"%s", ' "$@")
  printf '{"args": [%s"--json", "%s", "--quiet"], "stdout": null, "stderr": "%s"}\n' \
    "$args" "$work/$name-fast.json" "$work/$name-fast.err" >> "$work/cases.jsonl"
  printf '{"args": [%s"--reference-visibility", "--json", "%s", "--quiet"], "stdout": null, "stderr": "%s"}\n' \
    "$args" "$work/$name-reference.json" "$work/$name-reference.err" >> "$work/cases.jsonl"
}
compare() {
  local name="$1"
  [ -s "$work/$name-fast.json" ] && [ -s "$work/$name-reference.json" ] || return
  # One Python start per pair; the two files printed (without_host_fields) only for a diff.
  if ! same_but_host_fields "$work/$name-fast.json" "$work/$name-reference.json"; then
    fail "$name: the fast path and --reference-visibility give different result files"
    diff <(without_host_fields "$work/$name-fast.json") <(without_host_fields "$work/$name-reference.json") | head -6
  fi
}
check scene0-R1-V0 scene0.json --R 1 --V 0 --iterations 20
check scene0-R2-V3 scene0.json --R 2 --V 3 --iterations 20 --threads 2
check scene0-first-blocker scene0.json --R 2 --V 3 --iterations 20 --ray-test first-blocker --threads 2
check scene1-R4-V1 scene1.json --R 4 --V 1 --iterations 4 --samples 16 --threads 2
check scene1-octree scene1.json --R 2 --V 3 --iterations 6 --visibility octree --threads 2
check cornell-subdivide-balance cornell-box.json --R 4 --V 1 --subdivide --balance --iterations 20 --threads 2
check cornell-subdivide-V0 cornell-box.json --R 2 --subdivide --iterations 20 --threads 2
mapfile -t codes < <(/usr/bin/python3 "$root/tests/forked_batch.py" "$simulate" "$work/cases.jsonl")
[ "${#codes[@]}" = $((2 * ${#names[@]})) ] || fail "the batch ran ${#codes[@]} of $((2 * ${#names[@]})) runs"
for k in "${!names[@]}"; do
  name=${names[k]}
  [ "${codes[2 * k]:-none}" = 0 ] || fail "$name: simulate exited ${codes[2 * k]:-none}: $(head -c 300 "$work/$name-fast.err")"
  [ "${codes[2 * k + 1]:-none}" = 0 ] ||
    fail "$name: simulate --reference-visibility exited ${codes[2 * k + 1]:-none}: $(head -c 300 "$work/$name-reference.err")"
  compare "$name"
done

if [ "$failures" -gt 0 ]; then
  echo "$failures failure(s)"
  exit 1
fi
echo "seam: host headers marked and refused on the simulated side; 7 whole runs equal with --reference-visibility"
