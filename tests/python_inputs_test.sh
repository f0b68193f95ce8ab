#!/usr/bin/env bash
# The Python scripts' inputs and numbers, bounded before use: exit 2 with one line naming the
# file and the item, never a traceback, a hang or gigabytes of memory, and no output written.
#  - analysis/cycles/compare.py: deep nesting, a NaN luminance (named by its line), a negative or zero area, no
#    patch with a luminance (each against a well-formed pair that compares);
#  - analysis/cycles/cycles_answers.py: a scene nested deeply, a NaN vertex (refused before
#    Blender is looked for);
#  - claims.py and claims_hemicube.py: --jobs 0, -1 and 0x10; claims.py with --sweeps empty;
#  - experiments/sweep --check without a simulator built (the platform's node count estimated
#    from its dimension): 1e9, 1e400, 3.5, -1 and "7" refused before any power is computed.
root="$2"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failed=0
fail() { echo "FAIL: $*"; failed=1; }
expect() {  # CODE WORD COMMAND...: that exit, one line on stderr holding WORD, no traceback
  local want="$1" word="$2" code; shift 2
  timeout 60 "$@" >"$work/out" 2>"$work/err" </dev/null; code=$?
  [ "$code" = "$want" ] || fail "$*: exit $code, not $want: $(head -c 300 "$work/err")"
  if [ "$want" != 0 ]; then
    [ "$(wc -l < "$work/err")" = 1 ] || fail "$*: not one line: $(head -c 600 "$work/err")"
    grep -qF -- "$word" "$work/err" || fail "$*: the message does not name $word: $(cat "$work/err")"
  fi
}
python=/usr/bin/python3

# compare.py: a reference and Cycles' answers of two patches (rows: patch, area, ..., Y, se).
cat > "$work/make.py" <<'PY'
import json, sys
work = sys.argv[1]
def write(name, reference, cycles):
    json.dump(reference, open(f"{work}/{name}-ref.json", "w"))
    json.dump(cycles, open(f"{work}/{name}-cyc.json", "w"))
ref = {"scene_sha256": "ab", "scene_file": "s.json", "patch_luminance": [1.0, 2.0]}
cyc = {"scene_sha256": "ab", "scene_file": "s.json",
       "patches": [[0, 1.0, 0, 0, 0, 0, 0, 0, 1.1, 0.01], [1, 2.0, 0, 0, 0, 0, 0, 0, 2.0, 0.02]]}
write("good", ref, cyc)
write("nan", ref, {**cyc, "patches": [cyc["patches"][0][:8] + [float("nan"), 0.01], cyc["patches"][1]]})
write("negative", ref, {**cyc, "patches": [[0, -1.0] + cyc["patches"][0][2:], cyc["patches"][1]]})
write("zero-area", ref, {**cyc, "patches": [[0, 0.0] + cyc["patches"][0][2:], cyc["patches"][1]]})
write("dark", ref, {**cyc, "patches": [p[:8] + [0.0, 0.0] for p in cyc["patches"]]})
open(f"{work}/deep.json", "w").write('{"a": ' + "[" * 100000 + "]" * 100000 + "}")
scene = json.load(open(sys.argv[2]))
scene["patches"][0]["vertices"][0][0] = float("nan")
json.dump(scene, open(f"{work}/nan-scene.json", "w"))
PY
$python "$work/make.py" "$work" "$root/scenes/scene0.json"
compare="$root/analysis/cycles/compare.py"
expect 0 "" $python "$compare" "$work/good-ref.json" "$work/good-cyc.json"
grep -q "patch RMS 0.0" "$work/out" || fail "compare.py on the good pair: $(cat "$work/out")"
expect 2 "line 1: NaN" $python "$compare" "$work/nan-ref.json" "$work/nan-cyc.json" --json "$work/o.json"
expect 2 "area" $python "$compare" "$work/negative-ref.json" "$work/negative-cyc.json" --json "$work/o.json"
expect 2 "area" $python "$compare" "$work/zero-area-ref.json" "$work/zero-area-cyc.json" --json "$work/o.json"
expect 2 "dark-cyc.json" $python "$compare" "$work/dark-ref.json" "$work/dark-cyc.json" --json "$work/o.json"
expect 2 "nesting" $python "$compare" "$work/deep.json" "$work/good-cyc.json" --json "$work/o.json"
[ ! -e "$work/o.json" ] || fail "compare.py wrote its --json after a refusal"

answers="$root/analysis/cycles/cycles_answers.py"
expect 2 "nesting" $python "$answers" "$work/deep.json" --out "$work/a.json"
expect 2 "patch 0: vertices" $python "$answers" "$work/nan-scene.json" --out "$work/a.json"
[ ! -e "$work/a.json" ] || fail "cycles_answers.py wrote an output after a refusal"

for script in claims claims_hemicube; do
  for jobs in 0 -1 0x10; do
    timeout 60 $python "$root/analysis/$script.py" --jobs "$jobs" --results "$work/none" \
      >/dev/null 2>"$work/err" </dev/null; code=$?
    [ "$code" = 2 ] || fail "$script.py --jobs $jobs: exit $code, not 2: $(head -c 300 "$work/err")"
    grep -q "argument --jobs" "$work/err" || fail "$script.py --jobs $jobs: $(cat "$work/err")"
  done
done

# No sweep file at all: one line, not matplotlib's error about zero columns.
expect 2 "--sweeps" $python "$root/analysis/claims.py" --sweeps --pictures --no-schemes --no-hemicube \
  --results "$work/none" --out "$work/c.md" --figure "$work/c.png"
[ ! -e "$work/c.md" ] && [ ! -e "$work/c.png" ] || fail "claims.py wrote a page without sweeps"

# The sweep's node count estimated without a simulator (a fresh clone): the dimension bounded.
printf 'measure: total_seconds\noptions: {iterations: 1}\ngrid: {scene: [scene0], R: [1], platform: [p.json]}\n' \
  > "$work/s.yaml"
for dimension in 1e9 1e400 3.5 -1 '"7"'; do
  sed -E "s/(\"dimension\"[^}]*\"value\": *)[^,}]*/\1$dimension/" "$root/platforms/ncube2.json" > "$work/p.json"
  NCUBE_SIMULATE="$work/no-simulator" expect 2 "dimension" \
    $python "$root/experiments/sweep" "$work/s.yaml" --check
done
cp "$root/platforms/ncube2.json" "$work/p.json"
NCUBE_SIMULATE="$work/no-simulator" expect 0 "" $python "$root/experiments/sweep" "$work/s.yaml" --check

[ "$failed" = 0 ] && echo "python_inputs_test: passed"
exit "$failed"
