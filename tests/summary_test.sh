#!/usr/bin/env bash
# What ./simulate prints (docs/cli.md, "Output") and the small contracts around it: the summary
# names the platform (a CM-5 run is not taken for an nCube2 one), the number of nodes in the
# right number ("on 1 node"), the visibility and form-factor methods and the parallelisation
# away from their defaults, the elements after subdivision and balancing's moves (both as the
# result file of the same run has them), and every file written; --image writes PNG only;
# --help shows N, X, FILE and the choices, never CLI11's type names.
# Called by ctest as: summary_test.sh SIMULATE REPO_ROOT
set -u
simulate="$1"
root="$2"
export NCUBE_ROOT="$root"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
has() {  # FILE LINE-PATTERN (extended regex, whole line)
  grep -qxE -- "$2" "$1" || fail "$(basename "$1"): no line matching '$2' in: $(cat "$1")"
}
cd "$work"

# One node, the default platform, the paper's methods: no line for what was not chosen.
"$simulate" scene0 --iterations 1 >one.txt 2>&1 || fail "R=1 run"
has one.txt "configuration +R=1 V=0 on 1 node, 64 samples per shooter"
has one.txt "platform +ncube2 \(platforms/ncube2.json, 64 nodes\)"
has one.txt "seconds per iteration [0-9.]+ \(1 iteration, all that ran\)"
grep -qE "^(visibility|form factors|parallelisation|subdivision|load balancing|written) " one.txt \
  && fail "one.txt: a line for an option left at its default: $(cat one.txt)"

# A machine by its name in platforms/machines/, with the octree.
"$simulate" scene0 --R 4 --iterations 2 --platform cm5 --visibility octree >cm5.txt 2>&1 || fail "cm5 run"
has cm5.txt "platform +cm5 \(platforms/machines/cm5.xml, 64 nodes\)"
has cm5.txt "configuration +R=4 V=0 on 4 nodes, 64 samples per shooter"
has cm5.txt "visibility +octree"

# The hemicube under the shooter-centred scheme.
"$simulate" cornell-box --R 2 --iterations 1 --form-factors hemicube --parallelisation shooters \
  >hemicube.txt 2>&1 || fail "hemicube run"
has hemicube.txt "form factors +hemicube"
# The first iteration has one patch with power to shoot (the light): one shot, not "1 shots".
has hemicube.txt "parallelisation +shooters, 1 shot"

# Subdivision and balancing, against the result file of the same run; every file written (a
# 64 x 48 picture: the line is the same at any size, and 800 x 600 is 1.3 s of CPU more).
"$simulate" scene0 --R 4 --iterations 3 --subdivide --balance --balance-threshold 0 \
  --json run.json --image run.png --image-width 64 --image-height 48 --trace run.trace >balanced.txt 2>&1 ||
  fail "balanced run"
read -r at_end moved messages bytes < <(/usr/bin/python3 -c '
import json, sys
r = json.load(open("run.json"))
print(r["elements_at_end"], r["patches_moved"], r["transfers"]["messages"], int(r["transfers"]["payload_bytes"]))')
[ "$moved" -gt 1 ] && [ "$messages" -gt 1 ] || fail "the balanced run moved no patches: the check below checks nothing"
has balanced.txt "subdivision +$at_end elements at the end \(1162 at the start\)"
has balanced.txt "load balancing +$moved patches moved in $messages messages \($bytes bytes\)"
has balanced.txt "written +run.json \(--json\)"
has balanced.txt "written +run.trace \(--trace\): [0-9]+\.[0-9]+ MB"
has balanced.txt "written +run.png \(--image\)"
# The summary goes to stderr when the result file goes to standard output; so do the lines.
"$simulate" scene0 --iterations 1 --json - >stdout.json 2>stderr.txt || fail "--json - run"
has stderr.txt "written +- \(--json\)"
/usr/bin/python3 -c 'import json; json.load(open("stdout.json"))' || fail "--json -: stdout is not the result file alone"

# --image: PNG bytes under a PNG name only.
for name in x.jpg x.jpeg x.webp x.png.bak; do
  "$simulate" scene0 --iterations 1 --image "$name" --json "$name.json" >out.txt 2>err.txt
  code=$?
  [ "$code" -eq 2 ] && [ ! -e "$name" ] && [ ! -e "$name.json" ] && [ "$(wc -l <err.txt)" -eq 1 ] \
    && grep -q "only PNG" err.txt || fail "--image $name: exit $code, $(cat err.txt)"
done
"$simulate" scene0 --iterations 1 --image upper.PNG --image-width 64 --image-height 48 --quiet ||
  fail "--image upper.PNG refused"
[ "$(head -c 8 upper.PNG | od -An -tx1 | tr -d ' \n')" = 89504e470d0a1a0a ] || fail "upper.PNG is not a PNG"

# --help: readable value names, from the option table.
"$simulate" --help >help.txt || fail "--help"
grep -nE "INT|FLOAT|TEXT|NUMBER|:\{|\bUINT\b" help.txt && fail "--help shows CLI11's type names"
has help.txt " +--R N \(default 1\) +radiosity processors"
has help.txt " +--convergence X \(default 0.0001\)"
has help.txt " +--visibility brute-force\|octree \(default brute-force\)"
has help.txt " +--platform FILE \(default platforms/ncube2.json\)"

[ "$failures" -eq 0 ] || { echo "$failures failures"; exit 1; }
echo "summary_test: ok"
