#!/usr/bin/env bash
# Whole runs with --form-factors hemicube (docs/model.md, "The hemicube"):
#  1. the answers do not depend on R: R = 1, 3 and 8 give the same shooters and radiosities
#     to the last bit (every processor draws the same polygons, ties of depth go to the lower
#     patch), at the centre, and R = 1 and 8 at each shooter element's centre (there every
#     processor draws a hemicube per shooter element, so a run's cost grows with R: R = 3's
#     uneven share is the centre's case, R = 8 the elements' own, over 10 iterations: the two
#     lights (36 elements each) and six lit walls (28 to 32 elements), two of them twice; 25
#     iterations at R = 8 cost 4.9 CPU s, 10 cost 2.2);
#  2. the seam: --reference-visibility and two host threads change nothing but host fields;
#  3. the paper's runs do not record the hemicube (no field, no counter), hemicube runs do;
#  4. bad input: one line and exit 2 (V > 0, the rays' options with it, its options without
#     it, an odd or out-of-range N), exit 3 where its buffers do not fit the node.
# Called by ctest as: hemicube_runs_test.sh SIMULATE REPO_ROOT
set -u
simulate="$1"
root="$2"
export NCUBE_ROOT="$root"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

# The runs of sections 1 to 3 are made first, in one batch, each forked from
# build/simulate_server (tests/forked_batch.py: about 85 ms of CPU less a run than a new
# ./simulate); `ran` then checks that each ended in exit 0.
names=()
run() {  # name, then simulate's arguments (no spaces)
  local name="$1"; shift
  names+=("$name")
  printf '{"args": [%s"--json", "%s", "--quiet"], "stdout": null, "stderr": "%s"}\n' \
    "$(printf '"%s", ' "$@")" "$work/$name.json" "$work/$name.err" >> "$work/runs.jsonl"
}
ran() {
  local k
  mapfile -t codes < <(/usr/bin/python3 "$root/tests/forked_batch.py" "$simulate" "$work/runs.jsonl")
  [ "${#codes[@]}" = "${#names[@]}" ] || fail "the batch ran ${#codes[@]} of ${#names[@]} runs"
  for k in "${!names[@]}"; do
    [ "${codes[k]:-none}" = 0 ] || fail "${names[k]}: simulate exited ${codes[k]:-none}: $(head -c 300 "$work/${names[k]}.err")"
  done
}
same() {  # what, file a, file b, keys
  /usr/bin/python3 - "$@" <<'PY' || fail "$1"
import json, sys
what, a, b = sys.argv[1:4]
a, b = json.load(open(a)), json.load(open(b))
keys = sys.argv[4:]
if not keys:
    for r in (a, b):
        r.pop("host_seconds"); r["provenance"].pop("command_line")
    keys = sorted(a)
bad = [k for k in keys if a.get(k) != b.get(k)]
if bad:
    print("%s: %s differ" % (what, ", ".join(bad)))
    sys.exit(1)
PY
}

# 1. R does not change the answers.
for placement in centre elements; do
  Rs="3 8" iterations=25
  # R = 3 at the elements: 2 CPU s, its share shown at the centre
  [ "$placement" = centre ] || Rs=8 iterations=10
  for R in 1 $Rs; do
    run "scene0-$placement-R$R" scene0.json --R "$R" --form-factors hemicube --hemicube-placement "$placement" --iterations "$iterations"
  done
done
run scene1-R1 scene1.json --R 1 --form-factors hemicube --iterations 10
run scene1-R8 scene1.json --R 8 --form-factors hemicube --iterations 10
# 2. The seam.
run cornell-fast cornell-box.json --R 2 --form-factors hemicube --hemicube-resolution 50 --subdivide --iterations 20 --threads 2
run cornell-reference cornell-box.json --R 2 --form-factors hemicube --hemicube-resolution 50 --subdivide --iterations 20 --threads 1 --reference-visibility
# 3. What the result file records.
run paper scene0.json --R 2 --iterations 2
ran

# 1. R does not change the answers.
for placement in centre elements; do
  Rs="3 8"
  [ "$placement" = centre ] || Rs=8
  for R in $Rs; do
    same "scene0 $placement R=$R against R=1" "$work/scene0-$placement-R1.json" "$work/scene0-$placement-R$R.json" patch_radiosity shooters
  done
done
same "scene1 R=8 against R=1" "$work/scene1-R1.json" "$work/scene1-R8.json" patch_radiosity shooters

# 2. The seam.
same "the seam (threads, --reference-visibility)" "$work/cornell-fast.json" "$work/cornell-reference.json"

# 3. What the result file records.
/usr/bin/python3 - "$work/paper.json" "$work/scene0-elements-R8.json" <<'PY' || fail "result-file fields"
import json, sys
paper, hemicube = (json.load(open(p)) for p in sys.argv[1:3])
problems = []
for field in ("form_factors", "hemicube_resolution", "hemicube_placement"):
    if field in paper["config"]:
        problems.append("the paper's run records " + field)
if any(k.startswith("hemicube_") for k in paper["counts"]):
    problems.append("the paper's run has hemicube counters")
c = hemicube["config"]
if (c.get("form_factors"), c.get("hemicube_resolution"), c.get("hemicube_placement")) != ("hemicube", 100, "elements"):
    problems.append("the hemicube run records %s" % c)
counts = hemicube["counts"]
if counts["rays"] or counts["form_factors"] or not counts["hemicube_depth_tests"]:
    problems.append("the hemicube run's counts: %s" % counts)
if counts["hemicube_delta_form_factors"] != 8 * 15000:  # once per node, 1.5 N^2
    problems.append("delta form factors %d, expected 120000 (8 nodes)" % counts["hemicube_delta_form_factors"])
if problems:
    print("; ".join(problems)); sys.exit(1)
PY

# 4. Bad input and limits: the ten cases in one batch, each forked from build/simulate_server
# (tests/forked_batch.py: about 85 ms of CPU less a case than a new ./simulate).
expected=() messages=() arguments=()
refused() {  # expected exit, what the one line must say, simulate's arguments (no spaces)
  expected+=("$1"); messages+=("$2"); shift 2; arguments+=("$*")
}
refused 2 "visibility processors" --form-factors hemicube --V 1
refused 2 "traces no rays" --form-factors hemicube --visibility octree
refused 2 "traces no rays" --form-factors hemicube --ray-test first-blocker
refused 2 "does not cut the shooter" --form-factors hemicube --samples 16
refused 2 "without --form-factors hemicube" --hemicube-resolution 50
refused 2 "without --form-factors hemicube" --hemicube-placement elements
refused 2 "is not even" --form-factors hemicube --hemicube-resolution 51
refused 2 "out of range" --form-factors hemicube --hemicube-resolution 2002
refused 2 "hemicube" --form-factors hemicubes
refused 3 "out of memory" --form-factors hemicube --hemicube-resolution 1000
for k in "${!arguments[@]}"; do
  args=$(printf ', "%s"' ${arguments[k]})
  printf '{"args": ["scene0.json", "--iterations", "1", "--quiet"%s], "stdout": "%s", "stderr": "%s"}\n' \
    "$args" "$work/out-$k" "$work/err-$k"
done > "$work/refusals.jsonl"
mapfile -t codes < <(/usr/bin/python3 "$root/tests/forked_batch.py" "$simulate" "$work/refusals.jsonl")
[ "${#codes[@]}" = "${#arguments[@]}" ] || fail "the batch ran ${#codes[@]} of ${#arguments[@]} cases"
for k in "${!arguments[@]}"; do
  code=${expected[k]} words=${messages[k]} args=${arguments[k]} got=${codes[k]:-none}
  [ "$got" = "$code" ] || fail "$args: exit $got, expected $code"
  grep -q -- "$words" "$work/err-$k" || fail "$args: the message does not say '$words': $(cat "$work/err-$k")"
  [ "$code" -ne 2 ] || [ "$(grep -c 'simulate:' "$work/err-$k")" -eq 1 ] || fail "$args: not one line: $(cat "$work/err-$k")"
done

if [ "$failures" -gt 0 ]; then
  echo "$failures failure(s)"
  exit 1
fi
echo "hemicube runs: the same answers for R = 1, 3, 8; the seam holds; fields for hemicube runs only; bad input refused"
