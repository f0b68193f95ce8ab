#!/usr/bin/env bash
# The actors' stacks on a large platform (issue 37, item 4): --parallelisation shooters with
# R = 1,024 under address-space limits around what the stacks take (1,024 x 8 MiB). SimGrid
# aborts ("Failed to allocate stack", exit 134) when it cannot allocate a stack; the stacks
# are reserved before the node programs are built and each is handed to SimGrid as the block
# its allocation returns (src/simulation/actor_stacks.h), so every limit ends in a clean exit:
# 6 with one line naming the stacks when they do not fit, else a run (exit 0) or, in a window
# above, exit 6 from an allocation while the actors are built. An abort at any limit fails.
# Given back instead (freed just before SimGrid's allocation), the stacks aborted in about
# one run in three at limits 30 to 80 MB above the refusal (tcmalloc lends the freed stack's
# pages to the small allocations of creating the actor), so the limits are the coarse sweep
# 8.6, 8.9, 9.1 and 9.4 GB, and a fine one of 10 limits over the 150 MB above the refusal, found
# from the refusal's count of the stacks that fit. Each run reserves address space, not memory (about
# 350 MB resident).
# Called by ctest as: actor_stacks_test.sh SIMULATE REPO_ROOT
set -u
simulate=$(realpath "$1")
root="$2"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
# 1,090 patches (R <= patches): a light over a floor of 33 x 33 patches, one element each.
/usr/bin/python3 - "$work/grid.json" <<'PY'
import json, sys
patches = [{"vertices": [[0, 2, 0], [1, 2, 0], [1, 2, 1], [0, 2, 1]], "reflectance": [0.5] * 3,
            "emission": [10, 8, 6], "elements": [1, 1]}]
n = 33
for i in range(n):
    for j in range(n):
        x0, z0, x1, z1 = i / n, j / n, (i + 1) / n, (j + 1) / n
        patches.append({"vertices": [[x0, 0, z0], [x0, 0, z1], [x1, 0, z1], [x1, 0, z0]],
                        "reflectance": [0.6, 0.5, 0.4], "elements": [1, 1]})
json.dump({"name": "grid", "patches": patches}, open(sys.argv[1], "w"))
PY
# The runs are forked from build/simulate_server (tests/forked_batch.py: about 85 ms of CPU
# less a run than a new ./simulate, whose own start-up the other script tests try), each under
# its address-space limit as ulimit -v sets it: the first alone (its count of the stacks that
# fit places the fine sweep), the other 13 in one batch, so that every run starts from the
# same process image.
run_batch() {  # run_batch NAME LIMIT...: the exit codes, one a line; the errors in err-NAME-K.txt
  local name=$1 limit k=0
  shift
  : > "$work/cases.jsonl"
  for limit in "$@"; do
    printf '{"args": ["%s", "--parallelisation", "shooters", "--R", "1024", "--V", "0", "--platform", "%s", "--iterations", "2", "--quiet"], "stdout": null, "stderr": "%s", "as_kib": %d}\n' \
      "$work/grid.json" "$root/platforms/ncube2-d10.json" "$work/err-$name-$k.txt" "$limit" >> "$work/cases.jsonl"
    k=$((k + 1))
  done
  /usr/bin/python3 "$root/tests/forked_batch.py" "$simulate" "$work/cases.jsonl"
}
refused=0
check() {  # check LIMIT CODE ERRORS: the run under ulimit -v LIMIT (KiB) ended cleanly
  local err=$3
  case $2 in
    0) ;;
    6) if grep -q "^simulate: the stacks of the simulation's 1024 actors (8.0 MiB each" "$err"; then
         refused=$((refused + 1))
         [ "$(wc -l < "$err")" = 1 ] || fail "ulimit -v $1: more than one line: $(cat "$err")"
       fi ;;
    *) fail "ulimit -v $1: exit $2: $(head -c 300 "$err")" ;;
  esac
}
mapfile -t codes < <(run_batch first 8600000)
check 8600000 "${codes[0]:-none}" "$work/err-first-0.txt"
# The limit where the stacks just fit, from the count that did at 8.6 GB: each stack takes
# 8 MiB and 8 KiB of address space (tcmalloc's pages of 8 KiB).
fitted=$(sed -n 's/.*(\([0-9]*\) did).*/\1/p' "$work/err-first-0.txt")
[ -n "$fitted" ] || fail "ulimit -v 8600000: no count of the stacks that fit: $(head -c 300 "$work/err-first-0.txt")"
# 8.9 and 9.1 GB, then the limit that must run: the stacks' refusal edge lay at about 9.0 GB
# here (2026-11-29; the fine sweep below starts from it), so 8.7 and 8.8 GB showed only the
# refusal that 8.6 GB shows; and the run fits from 9.2 GB on (it ran at 9.2 and 9.25 GB: no
# allocation of it meets a limit above), so 9.3 GB was the run at 9.4 GB again.
edge=$((8600000 + (1024 - ${fitted:-1024}) * 8200))
limits=(8900000 9100000 9400000)
for step in $(seq 1 10); do limits+=($((edge + step * 15000))); done
mapfile -t codes < <(run_batch sweep "${limits[@]}")
[ "${#codes[@]}" = "${#limits[@]}" ] || fail "the batch ran ${#codes[@]} of its ${#limits[@]} runs"
for k in "${!limits[@]}"; do check "${limits[k]}" "${codes[k]:-none}" "$work/err-sweep-$k.txt"; done
[ "${codes[2]:-}" = 0 ] || fail "ulimit -v 9400000: the run does not fit"
[ "$refused" -ge 1 ] || fail "no limit refused with the stacks' line"
[ "$failures" = 0 ] && echo "actor_stacks_test: all checks passed" && exit 0
echo "actor_stacks_test: $failures check(s) failed"
exit 1
