#!/usr/bin/env bash
# A platform file never chooses where anything is written (issue 37, item 2; docs/cli.md,
# "Output files"): researchers share platform files as they share models.
#  1. a JSON platform's simgrid_config naming tracing/filename is refused (exit 2, one line
#     naming the file and the setting) and the file it names is left as it was;
#  2. the same for a SimGrid XML platform's <config> tag;
#  3. a platform that turns tracing on by itself writes no file (no simgrid.trace in the
#     current folder, nothing anywhere else the test can see);
#  4. with the trace named on the command line, the platform's tracing settings shape it;
#  5. a sweep cell's cfg that would write a file (tracing/filename, or tracing on with SimGrid's
#     default simgrid.trace) is refused by the sweep tool with one line, nothing run.
# Called by ctest as: platform_outputs_test.sh SIMULATE REPO_ROOT
set -u
simulate="$(realpath "$1")"
root="$2"
export NCUBE_ROOT="$root"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
cd "$work" || exit 1
scene="$root/scenes/scene0.json"
echo precious > victim.txt

/usr/bin/python3 - "$root/platforms/ncube2.json" <<'PY'
import json, sys
base = json.load(open(sys.argv[1]))
for name, extra in (("named", {"tracing": "yes", "tracing/filename": "victim.txt"}),
                    ("on", {"tracing": "yes", "tracing/actor": "yes"})):
    platform = json.loads(json.dumps(base))
    platform["simgrid_config"].update(extra)
    json.dump(platform, open(f"{name}.json", "w"), indent=1)
PY
sed 's|  <config>|  <config>\n    <prop id="tracing" value="yes"/>\n    <prop id="tracing/filename" value="victim.txt"/>|' \
  "$root/platforms/ncube2.xml" > named.xml
grep -q 'tracing/filename' named.xml || fail "the XML platform was not made"

for platform in named.json named.xml; do
  "$simulate" "$scene" --R 1 --iterations 1 --platform "$platform" --quiet > out.txt 2> err.txt
  code=$?
  [ "$code" = 2 ] || fail "$platform: exit $code, expected 2"
  [ "$(wc -l < err.txt)" = 1 ] && grep -q "$platform.*tracing/filename" err.txt \
    || fail "$platform: not one line naming the file and the setting: $(cat err.txt)"
  [ "$(cat victim.txt)" = precious ] || fail "$platform: victim.txt was overwritten"
done

before="$(ls -A | sort)"
"$simulate" "$scene" --R 1 --iterations 1 --platform on.json --quiet 2> err.txt \
  || fail "on.json: exit $?: $(cat err.txt)"
[ "$(ls -A | sort)" = "$before" ] || fail "a platform that turns tracing on wrote: $(ls -A)"

"$simulate" "$scene" --R 1 --iterations 1 --platform on.json --quiet --cfg=tracing:yes \
  --cfg=tracing/filename:"$work/mine.trace" 2> err.txt || fail "named trace: exit $?: $(cat err.txt)"
grep -q "PajeDefineContainerType" mine.trace 2> /dev/null \
  || fail "the trace named on the command line was not written"
grep -q "ACTOR\|actor" mine.trace 2> /dev/null \
  || fail "the platform's tracing/actor did not shape the trace named on the command line"

for cfg in "{'tracing': 'yes', 'tracing/filename': '$work/victim.txt'}" "{'tracing': 'yes'}"; do
  mkdir -p sweep && rm -rf sweep/results
  printf "name: outputs\noptions: {iterations: 1, samples: 4, cfg: %s}\ngrid: {scene: [scene0], R: [1]}\n" \
    "$cfg" > sweep/s.yaml
  NCUBE_SIMULATE="$simulate" /usr/bin/python3 "$root/experiments/sweep" sweep/s.yaml \
    --results sweep/results > out.txt 2> err.txt
  code=$?
  [ "$code" = 2 ] || fail "sweep cfg $cfg: exit $code, expected 2: $(tail -3 err.txt)"
  [ "$(wc -l < err.txt)" = 1 ] && grep -q "key 'cfg'" err.txt \
    || fail "sweep cfg $cfg: not one line naming key 'cfg': $(cat err.txt)"
  [ ! -e sweep/results ] || fail "sweep cfg $cfg: the results folder was made"
  [ "$(cat victim.txt)" = precious ] || fail "sweep cfg $cfg: victim.txt was overwritten"
done

# network_bench: SimGrid's files under the same output rule (its trace onto its own platform
# file replaced it, exit 0).
bench="$(dirname "$simulate")/network_bench"
cp "$root/platforms/ncube2.json" mine.json && cp mine.json mine.orig
"$bench" --platform mine.json --quiet --cfg=tracing:yes --cfg=tracing/filename:mine.json 2> err.txt
code=$?
[ "$code" = 2 ] && grep -q "is the input file" err.txt \
  || fail "network_bench tracing onto its platform: exit $code: $(cat err.txt)"
cmp -s mine.json mine.orig || fail "network_bench overwrote its own platform file"
"$bench" --platform mine.json --quiet --cfg=tracing:yes --cfg=tracing/filename:bench.trace \
  --round-trips 1 --stream-messages 1 --max-bytes 64 2> err.txt || fail "network_bench traced: $(cat err.txt)"
grep -q "PajeDefineContainerType" bench.trace 2> /dev/null || fail "network_bench wrote no trace"

"$bench" --max-bytes 1099511627776 2> err.txt; code=$?
[ "$code" = 2 ] && grep -q "max-bytes" err.txt || fail "network_bench --max-bytes 2^40: exit $code: $(head -c 200 err.txt)"

[ "$failures" = 0 ] && echo "platform_outputs_test: all checks passed" && exit 0
echo "platform_outputs_test: $failures check(s) failed"
exit 1
