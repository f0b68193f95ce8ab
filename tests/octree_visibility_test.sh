#!/usr/bin/env bash
# --visibility octree (section 6) changes how the node programs find blockers, never which:
# the radiosity solution and the shooters are those of brute force, while the counted
# ray-patch tests drop and the octree's work and bytes appear (V = 0: every radiosity
# processor's octree over the whole scene; V > 0: the visibility processors' over their
# shares). Called by ctest as: octree_visibility_test.sh SIMULATE REPO_ROOT
set -u
simulate="$1"
root="$2"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

check() {
  local name="$1"; shift
  for visibility in brute-force octree; do
    "$simulate" "$@" --visibility "$visibility" --json "$work/$name-$visibility.json" --quiet ||
      fail "$name: simulate exited $? with --visibility $visibility"
  done
  /usr/bin/python3 - "$work/$name-brute-force.json" "$work/$name-octree.json" "$name" <<'PY' || fail "$name"
import json, sys
brute, octree = (json.load(open(p)) for p in sys.argv[1:3])
name = sys.argv[3]
problems = []
if brute["config"]["visibility"] != "brute-force" or octree["config"]["visibility"] != "octree":
    problems.append("config.visibility not recorded")
for key in ("patch_radiosity", "shooters"):
    if brute[key] != octree[key]:
        problems.append(key + " differ")
b, o = brute["counts"], octree["counts"]
if not o["ray_patch_tests"] < b["ray_patch_tests"] / 3:
    problems.append("ray-patch tests did not drop: %d against %d" % (o["ray_patch_tests"], b["ray_patch_tests"]))
if b["rays"] != o["rays"] or b["form_factors"] != o["form_factors"]:
    problems.append("rays or form factors differ")
if b["octree_cells_visited"] or b["octree_cells_built"] or not (o["octree_cells_visited"] and o["octree_cells_built"] and o["octree_overlap_tests"]):
    problems.append("octree counts: brute force %s, octree %s" % (b, o))
bigger = [ob["peak_memory_bytes"] > bb["peak_memory_bytes"]
          for bb, ob in zip(brute["nodes"], octree["nodes"])
          if bb["role"] == "visibility" or octree["config"]["V"] == 0]
if not bigger or not all(bigger):
    problems.append("the nodes that test rays do not hold more bytes with the octree")
for p in problems:
    print("FAIL: %s: %s" % (name, p))
print("%s: ray-patch tests %d -> %d, simulated %.1f -> %.1f s" % (name, b["ray_patch_tests"], o["ray_patch_tests"], brute["simulated_seconds"], octree["simulated_seconds"]))
sys.exit(1 if problems else 0)
PY
}

check scene0-R2-V0 "$root/scenes/scene0.json" --R 2 --V 0 --iterations 10
check scene1-R4-V0 "$root/scenes/scene1.json" --R 4 --V 0 --iterations 4
check scene1-R2-V3 "$root/scenes/scene1.json" --R 2 --V 3 --iterations 4

[ "$failures" -eq 0 ] && echo "octree visibility: same solution as brute force"
exit $((failures > 0))
