#!/usr/bin/env bash
# The Python scripts' inputs and numbers, bounded before use: exit 2 with one line naming the
# file and the item, never a traceback, a hang or gigabytes of memory, and no output written.
#  - analysis/cycles/compare.py: deep nesting, a NaN luminance (named by its line), a negative or zero area, no
#    patch with a luminance (each against a well-formed pair that compares);
#  - analysis/cycles/cycles_answers.py: a scene nested deeply, a NaN vertex (refused before
#    Blender is looked for);
#  - claims.py and claims_hemicube.py: --jobs 0; claims.py with --sweeps empty;
#  - a script whose standard output is closed (compare.py | head -1): exit 141, no traceback;
#  - experiments/sweep --check without a simulator built (the platform's node count estimated
#    from its dimension): 1e9, 1e400, 3.5, -1 and "7" refused before any power is computed.
root=$(cd "$2" && pwd)
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
import hashlib, json, sys
work = sys.argv[1]
def write(name, reference, cycles):
    json.dump(reference, open(f"{work}/{name}-ref.json", "w"))
    json.dump(cycles, open(f"{work}/{name}-cyc.json", "w"))
# The scene the pair names (compare.py reads which patches emit from it): two patches, none emits.
square = {"vertices": [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]], "reflectance": [0.5, 0.5, 0.5]}
text = json.dumps({"name": "s", "patches": [square, square]}).encode()
open(f"{work}/s.json", "wb").write(text)
sha = "sha256:" + hashlib.sha256(text).hexdigest()
ref = {"scene_sha256": sha, "scene_file": "s.json", "patch_luminance": [1.0, 2.0]}
cyc = {"scene_sha256": sha, "scene_file": "s.json",
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
expect 2 "NaN" $python "$answers" "$work/nan-scene.json" --out "$work/a.json"
[ ! -e "$work/a.json" ] || fail "cycles_answers.py wrote an output after a refusal"

# --jobs 0, the defect itself; -1 takes the same check, and 0x10 (with nan and 1e400) is a
# case of the options harness (tests/robustness/options_harness.py: a count given 0x10 must be
# refused, in one line).
for script in claims claims_hemicube; do
  for jobs in 0; do
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

# The reads routed through the gate (ncube.input_file): a FIFO, a NaN and deep nesting are
# refused at once, never a hang or a traceback.
mkfifo "$work/fifo"
printf '{"status": NaN}' > "$work/nan.json"
printf '%s' "$(printf '[%.0s' $(seq 200))" > "$work/deep-plan.json"
timeout 20 $python - "$root/analysis" "$work" <<'PY' || fail "results.read, unknowns' study file: see above"
import json, sys
sys.path.insert(0, sys.argv[1])
work = sys.argv[2]
from ncube import input_file, results
for name in ("fifo", "nan.json", "deep-plan.json", "missing.json"):
    if results.read(f"{work}/{name}") is not None:
        sys.exit(f"results.read({name}) is not None")
    if results.trace_mismatch(f"{work}/{name}") is None:
        sys.exit(f"results.trace_mismatch({name}) is None")
import runpy
unknowns = runpy.run_path(sys.argv[1] + "/unknowns.py", run_name="not_main")
for content in ('{"worlds": 0, "seed": 41}', '{"worlds": NaN, "seed": 41}',
                '{"worlds": 1e400, "seed": 41}', '{"worlds": "32", "seed": 41}', '[32, 41]'):
    open(f"{work}/study.json", "w").write(content)
    try:
        unknowns["read_study"](f"{work}/study.json")
        sys.exit(f"read_study took {content}")
    except input_file.InputFileError as e:
        assert "study.json" in str(e) and "\n" not in str(e), e
try:
    unknowns["read_study"](f"{work}/fifo")
    sys.exit("read_study read a FIFO")
except input_file.InputFileError:
    pass
PY
for plan in fifo nan.json deep-plan.json; do
  (cd "$work" && PYTHONPATH="$root/analysis" expect 2 "$plan" $python -m ncube.summary "$work/$plan" s)
  (cd "$work" && PYTHONPATH="$root/analysis" expect 1 "" $python -m ncube.run_cell "$work/$plan" c.json)
  grep -qF "$plan" "$work/err" && [ "$(wc -l < "$work/err")" = 1 ] \
    || fail "run_cell on a $plan plan: $(head -c 300 "$work/err")"
done

# cycles_answers.py reads what Blender wrote through the gate: a fake Blender that leaves a
# FIFO, a NaN normal or deep nesting as its report ends in exit 7 and one line, and one that
# fails prints one line of its last words, not its log.
cat > "$work/blender" <<'SH'
#!/bin/bash
job="${@: -1}"
case "$FAKE_REPORT" in
  fifo) mkfifo "$job.report.json" ;;
  nan) printf '{"normals": [[[0, 0, NaN]]]}' > "$job.report.json" ;;
  deep) printf '%s' "$(printf '[%.0s' $(seq 200))" > "$job.report.json" ;;
  fail) printf 'line one\nline two\nError: it broke\n'; exit 3 ;;
esac
SH
chmod +x "$work/blender"
printf '{"name": "q", "patches": [{"vertices": [[0,0,0],[1,0,0],[1,1,0],[0,1,0]], "emission": [1,1,1]}]}' \
  > "$work/quad.json"
for report in fifo nan deep fail; do
  FAKE_REPORT=$report expect 7 "$( [ $report = fail ] && echo "it broke" || echo report)" \
    $python "$answers" "$work/quad.json" --out "$work/a.json" --blender "$work/blender" --seeds 2 --texels 2 --samples 1
done
[ ! -e "$work/a.json" ] || fail "cycles_answers.py wrote an output from a bad bake"
for bad in "--samples 100000" "--texels 100000" "--seeds 1" "--bounces 0" "--threads -1"; do
  expect 2 "${bad%% *}" $python "$answers" "$work/quad.json" --out "$work/a.json" --blender "$work/blender" $bad
done

# A closed standard output (`| head -1`) ends a script quietly, exit 141, no traceback: compare.py's
# lines of scene1 into a pipe whose reading end is closed before the script starts.
rc=$(/usr/bin/python3 - "$compare" "$root" "$work/err" <<'PY'
import os, subprocess, sys
compare, root, err = sys.argv[1:]
read_end, write_end = os.pipe()
os.close(read_end)
with open(err, "wb") as stderr:
    print(subprocess.run(["/usr/bin/python3", compare, "--per-patch", root + "/analysis/reference/scene1.json",
                          root + "/analysis/cycles/scene1.json"], stdout=write_end, stderr=stderr).returncode)
PY
)
[[ $rc == 141 && ! -s $work/err ]] || fail "compare.py into a closed pipe: exit $rc, $(head -c 300 "$work/err")"

[ "$failed" = 0 ] && echo "python_inputs_test: passed"
exit "$failed"
